//! [`stability_atlas`]: the verdict of one steady motion over a grid of two parameters, with
//! boundary curves traced by continuation.

use nalgebra::Vector3;

use super::{AtlasOptions, StabilityAtlas};
use crate::error::RouthError;
use crate::model::Routhian;

/// The stability atlas of the steady motion nearest `gamma_guess` at `(x.0, y.0)`.
pub fn stability_atlas<M: Routhian, F: Fn(f64, f64) -> (M, f64)>(
    family: F,
    gamma_guess: Vector3<f64>,
    x: (f64, f64),
    y: (f64, f64),
    opts: &AtlasOptions,
) -> Result<StabilityAtlas, RouthError> {
    let _ = (&family, gamma_guess, x, y, opts);
    Err(RouthError::InvalidOption {
        what: "stability_atlas",
        reason: "not implemented yet".into(),
    })
}
