//! Root finding for tests: an independent one-dimensional solver, so that expected values (e.g.
//! the circles of steady motions of a symmetric top from their closed-form equation) do not come
//! from routh's own code.

/// The roots of `f` between consecutive points of `grid` (ascending or descending): every
/// interval where `f` changes sign (or is zero at its left end) is bisected to full precision.
/// Roots closer than `merge` (relative to their size, absolute below 1) are reported once.
pub fn bracketed_roots(f: impl Fn(f64) -> f64, grid: &[f64], merge: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for w in grid.windows(2) {
        let (mut a, mut b) = (w[0], w[1]);
        let (fa, fb) = (f(a), f(b));
        if fa == 0.0 {
            out.push(a);
            continue;
        }
        if fa * fb > 0.0 {
            continue;
        }
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if f(a) * f(m) <= 0.0 {
                b = m;
            } else {
                a = m;
            }
        }
        out.push(0.5 * (a + b));
    }
    out.dedup_by(|x, y| (*x - *y).abs() <= merge * x.abs().max(1.0));
    out
}
