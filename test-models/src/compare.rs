//! The comparisons the tests use to say two numbers agree: one place for the rule, so that a
//! test states only its tolerance and its scale.

/// Scalar agreement: `|a − b| ≤ tol · max(scale, 1)` (the scale of the quantity compared, with a
/// floor of 1 so that values near zero are compared absolutely), and both finite.
///
/// ```
/// use test_models::compare::close_to;
/// assert!(close_to(1.0 + 1e-13, 1.0, 1e-12, 1.0));
/// assert!(!close_to(1.0 + 1e-11, 1.0, 1e-12, 1.0));
/// assert!(close_to(1e3 + 1e-10, 1e3, 1e-12, 1e3)); // relative to the scale 1e3
/// assert!(!close_to(f64::NAN, f64::NAN, 1.0, 1.0));
/// assert!(!close_to(f64::INFINITY, 1.0, 1.0, f64::INFINITY)); // an infinite value never agrees
/// ```
pub fn close_to(a: f64, b: f64, tol: f64, scale: f64) -> bool {
    a.is_finite() && b.is_finite() && (a - b).abs() <= tol * scale.max(1.0)
}

/// Normwise relative agreement of two lists: `‖a − b‖∞ ≤ tol · max(‖b‖∞, floor)`, the floor
/// guarding outputs that are exactly zero in the reference, and `a` finite. Returns the relative
/// error `‖a − b‖∞ / max(‖b‖∞, floor)`, or a message with both lists.
///
/// ```
/// use test_models::compare::close;
/// assert!(close(&[1.0, 2.0 + 1e-12], &[1.0, 2.0], 1e-11, 1e-300).is_ok());
/// assert!(close(&[1.0, 2.1], &[1.0, 2.0], 1e-11, 1e-300).is_err());
/// assert!(close(&[f64::NAN], &[1.0], 1.0, 1.0).is_err());
/// ```
pub fn close(a: &[f64], b: &[f64], tol: f64, floor: f64) -> Result<f64, String> {
    let scale = b.iter().fold(floor, |m, x| m.max(x.abs()));
    let err = a
        .iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    if err <= tol * scale && a.iter().all(|x| x.is_finite()) {
        Ok(err / scale)
    } else {
        Err(format!(
            "error {err:e} > {tol:e} × {scale:e}\n  got      {a:?}\n  expected {b:?}"
        ))
    }
}
