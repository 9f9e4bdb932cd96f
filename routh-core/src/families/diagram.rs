//! [`bifurcation_diagram`] and [`continue_branch`].

use nalgebra::Vector3;

use super::{BifurcationDiagram, ContinuationOptions};
use crate::error::RouthError;
use crate::model::Routhian;

/// Every branch of steady motions of `family` over `range`.
pub fn bifurcation_diagram<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: F,
    range: (f64, f64),
    opts: &ContinuationOptions,
) -> Result<BifurcationDiagram, RouthError> {
    let _ = (&family, range, opts);
    Err(RouthError::InvalidOption {
        what: "bifurcation_diagram",
        reason: "not implemented yet".into(),
    })
}

/// The branch through the steady motion nearest `gamma_guess` at `s0`.
pub fn continue_branch<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: F,
    gamma_guess: Vector3<f64>,
    s0: f64,
    range: (f64, f64),
    opts: &ContinuationOptions,
) -> Result<BifurcationDiagram, RouthError> {
    let _ = (&family, gamma_guess, s0, range, opts);
    Err(RouthError::InvalidOption {
        what: "continue_branch",
        reason: "not implemented yet".into(),
    })
}
