//! The analyses the examples run and print, shared with `tests/examples_facts.rs`.

pub use routh::{
    classified_steady_motions, classify_at as report_at, stability_threshold, Classified,
};
use routh::{RouthError, Routhian, Stability, Vector3};

/// The verdict of [`report_at`].
pub fn verdict_at<M: Routhian>(
    model: &M,
    gamma: Vector3<f64>,
    p_psi: f64,
) -> Result<Stability, RouthError> {
    Ok(report_at(model, gamma, p_psi)?.verdict)
}

/// Bisection for the point where the predicate `pred` changes value between `lo` and `hi`
/// (`pred(lo) != pred(hi)` is required, otherwise `None`). Stops when the bracket is shorter than
/// `rel_tol · |hi|`; returns the midpoint of the final bracket.
pub fn bisect<F>(
    mut lo: f64,
    mut hi: f64,
    rel_tol: f64,
    mut pred: F,
) -> Result<Option<f64>, RouthError>
where
    F: FnMut(f64) -> Result<bool, RouthError>,
{
    let at_lo = pred(lo)?;
    if pred(hi)? == at_lo {
        return Ok(None);
    }
    while (hi - lo).abs() > rel_tol * hi.abs().max(lo.abs()) {
        let mid = 0.5 * (lo + hi);
        if pred(mid)? == at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(0.5 * (lo + hi)))
}

/// The `p_ψ` in `[lo, hi]` where the verdict of the steady motion at the fixed critical point
/// `gamma` switches between `Unstable` and stable (secularly or gyroscopically), by bisection
/// on "is the verdict `Unstable`" to the relative tolerance `rel_tol`.
pub fn instability_threshold<M: Routhian>(
    model: &M,
    gamma: Vector3<f64>,
    lo: f64,
    hi: f64,
    rel_tol: f64,
) -> Result<Option<f64>, RouthError> {
    bisect(lo, hi, rel_tol, |p| {
        Ok(verdict_at(model, gamma, p)? == Stability::Unstable)
    })
}
