//! The one overflow- and underflow-safe Euclidean norm of the crate, used by the input checks,
//! the search on the sphere and the integrators' error weights.

/// The Euclidean norm of `xs` without overflow or underflow: the plain `√Σx²` when that sum is a
/// normal number (then the same value as nalgebra's `norm`), otherwise scaled by the largest
/// magnitude. NaN if an entry is NaN, `+∞` if one is infinite.
#[inline]
pub(crate) fn stable_norm(xs: &[f64]) -> f64 {
    let s: f64 = xs.iter().map(|x| x * x).sum();
    if s.is_normal() {
        return s.sqrt();
    }
    let m = xs.iter().fold(0.0f64, |m, x| {
        if x.is_nan() || x.abs() > m {
            x.abs()
        } else {
            m
        }
    });
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * xs.iter().map(|x| (x / m).powi(2)).sum::<f64>().sqrt()
}

#[cfg(test)]
mod tests {
    use super::stable_norm;

    /// Extremes where `√Σx²` over- or underflows: the scaled form must still give the norm
    /// (checked against the exact values `√2·10³⁰⁰` and `5·10⁻³¹⁰`).
    #[test]
    fn stable_norm_survives_extremes() {
        assert!((stable_norm(&[1e300, 1e300, 0.0]) / (1e300 * 2f64.sqrt()) - 1.0).abs() < 1e-15);
        assert!((stable_norm(&[3e-310, 4e-310, 0.0]) / 5e-310 - 1.0).abs() < 1e-6);
        assert_eq!(stable_norm(&[0.0; 3]), 0.0);
        assert!(stable_norm(&[f64::NAN, 1.0]).is_nan());
        assert_eq!(stable_norm(&[f64::INFINITY, 1.0]), f64::INFINITY);
        // In range it is the plain formula, bit for bit.
        assert_eq!(stable_norm(&[3.0, 4.0]), 5.0);
    }
}
