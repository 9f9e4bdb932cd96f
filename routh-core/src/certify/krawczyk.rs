//! The tests of a chart box: exclusion by the natural and mean-value enclosures, the Krawczyk
//! operator for existence and uniqueness, and the tightening of a certified enclosure.

use super::chart::{ChartBox, Evaluator, Face};
use super::interval::Interval;

/// What one Krawczyk step found on a box.
pub(super) enum Verdict {
    /// No steady motion in the box.
    Excluded,
    /// Exactly one, inside the given sub-box.
    Unique(Interval, Interval),
    /// Not decided at this size; the Krawczyk contraction estimate `‖I − Y F'(X)‖∞` (∞ when it
    /// could not be formed). It halves with the box near a regular zero and stays large near a
    /// circle of zeros, where `F'` is singular.
    Split(f64),
}

pub(super) fn excludes_zero(x: Interval) -> bool {
    x.lo > 0.0 || x.hi < 0.0
}

/// `x` widened by 5% of its width on each side.
pub(super) fn inflate(x: Interval) -> Interval {
    let e = 0.05 * x.width();
    Interval::new((x.lo - e).next_down(), (x.hi + e).next_up())
}

/// One test of a box: exclusion by the natural and mean-value enclosures, then Krawczyk. The
/// tests run on the box widened by 5%: a steady motion on the edge of a box (the centre of a
/// face, on the first split, is one) can never map into the interior of that box, but it does
/// into the interior of the wider one. A verdict on the wider box holds for the box.
pub(super) fn test_box(ev: &mut Evaluator<'_>, b: &ChartBox) -> Verdict {
    let b = &ChartBox {
        face: b.face,
        u: inflate(b.u),
        v: inflate(b.v),
    };
    let field = ev.field(b, true);
    if field.f.iter().any(|&x| excludes_zero(x)) {
        return Verdict::Excluded;
    }
    let Some(df) = field.df else {
        return Verdict::Split(f64::INFINITY);
    };
    if df.iter().flatten().any(|x| !x.is_bounded()) {
        return Verdict::Split(f64::INFINITY);
    }
    let (mu, mv) = (b.u.mid(), b.v.mid());
    let centre = ChartBox {
        face: b.face,
        u: Interval::point(mu),
        v: Interval::point(mv),
    };
    let fm = ev.field(&centre, false).f;
    if fm.iter().any(|x| !x.is_bounded()) {
        return Verdict::Split(f64::INFINITY);
    }
    let d = [b.u - centre.u, b.v - centre.v];
    // Mean-value form: F(X) ⊆ F(m) + F'(X)(X − m).
    for i in 0..2 {
        let mv_form = fm[i] + df[i][0] * d[0] + df[i][1] * d[1];
        if excludes_zero(mv_form) {
            return Verdict::Excluded;
        }
    }
    // Y ≈ F'(m)⁻¹ from the midpoints (any real matrix keeps Krawczyk valid).
    let m = [
        [df[0][0].mid(), df[0][1].mid()],
        [df[1][0].mid(), df[1][1].mid()],
    ];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let scale = m.iter().flatten().fold(0.0f64, |s, x| s.max(x.abs()));
    if !det.is_finite() || det.abs() <= 1e-14 * scale * scale {
        return Verdict::Split(f64::INFINITY);
    }
    let y = [
        [m[1][1] / det, -m[0][1] / det],
        [-m[1][0] / det, m[0][0] / det],
    ];
    let yp = |i: usize, j: usize| Interval::point(y[i][j]);
    let mut k = [centre.u, centre.v];
    let mut q = 0.0f64;
    for (i, ki) in k.iter_mut().enumerate() {
        let yf = yp(i, 0) * fm[0] + yp(i, 1) * fm[1];
        let mut acc = *ki - yf;
        let mut row = 0.0;
        for j in 0..2 {
            // (I − Y F'(X))_ij
            let ydf = yp(i, 0) * df[0][j] + yp(i, 1) * df[1][j];
            let e = if i == j {
                Interval::point(1.0)
            } else {
                Interval::point(0.0)
            };
            let c = e - ydf;
            row += c.mag();
            acc = acc + c * d[j];
        }
        q = q.max(row);
        *ki = acc;
    }
    let x = [b.u, b.v];
    if k[0].intersect(x[0]).is_none() || k[1].intersect(x[1]).is_none() {
        return Verdict::Excluded;
    }
    if k[0].interior_of(x[0]) && k[1].interior_of(x[1]) {
        return Verdict::Unique(k[0], k[1]);
    }
    Verdict::Split(q)
}

/// Widest enclosure (per component of γ) of a certified motion; a motion that cannot be
/// enclosed tighter is reported undecided.
pub(super) const MAX_ENCLOSURE: f64 = 1e-10;

/// A tight enclosure of the zero certified unique in `unique` (found in `k`): Newton's method
/// in floating point from the centre of `k`, then Krawczyk on boxes of half-width `1e−14` to
/// `1e−11` around the Newton point; the first one certified (it lies in `unique`, so it holds
/// the same zero) is the enclosure. `None` when Newton leaves `unique` or no small box is
/// certified.
pub(super) fn tighten(
    ev: &mut Evaluator<'_>,
    face: Face,
    unique: (Interval, Interval),
    k: (Interval, Interval),
) -> Option<(Interval, Interval)> {
    let (mut u, mut v) = (k.0.mid(), k.1.mid());
    for _ in 0..40 {
        let at = ChartBox {
            face,
            u: Interval::point(u),
            v: Interval::point(v),
        };
        let field = ev.field(&at, true);
        let df = field.df?;
        let (f0, f1) = (field.f[0].mid(), field.f[1].mid());
        let m = [
            [df[0][0].mid(), df[0][1].mid()],
            [df[1][0].mid(), df[1][1].mid()],
        ];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        if !(det.is_finite() && det != 0.0) {
            return None;
        }
        let du = (m[1][1] * f0 - m[0][1] * f1) / det;
        let dv = (-m[1][0] * f0 + m[0][0] * f1) / det;
        if !(du.is_finite() && dv.is_finite()) {
            return None;
        }
        u -= du;
        v -= dv;
        if !(unique.0.lo <= u && u <= unique.0.hi && unique.1.lo <= v && v <= unique.1.hi) {
            return None;
        }
        if du.abs().max(dv.abs()) <= 1e-16 * (1.0 + u.abs().max(v.abs())) {
            break;
        }
    }
    for r in [1e-14, 1e-13, 1e-12, 1e-11] {
        let small = ChartBox {
            face,
            u: Interval::new(u - r, u + r),
            v: Interval::new(v - r, v + r),
        };
        // The box the test really uses is 5% wider; it must lie in the uniqueness box.
        let wide = (inflate(small.u), inflate(small.v));
        if !(wide.0.interior_of(unique.0) && wide.1.interior_of(unique.1)) {
            return None;
        }
        if let Verdict::Unique(ku, kv) = test_box(ev, &small) {
            if let (Some(a), Some(b)) = (ku.intersect(wide.0), kv.intersect(wide.1)) {
                return Some((a, b));
            }
        }
    }
    None
}

/// Shrinks the enclosure of a certified zero by Krawczyk steps (every zero of the box stays in
/// `K ∩ X`).
pub(super) fn refine(
    ev: &mut Evaluator<'_>,
    face: Face,
    mut x: (Interval, Interval),
    iterations: usize,
) -> (Interval, Interval) {
    for _ in 0..iterations {
        let b = ChartBox {
            face,
            u: x.0,
            v: x.1,
        };
        let before = x.0.width() + x.1.width();
        match test_box(ev, &b) {
            Verdict::Unique(ku, kv) => match (ku.intersect(x.0), kv.intersect(x.1)) {
                (Some(u), Some(v)) => x = (u, v),
                _ => break,
            },
            _ => break,
        }
        if x.0.width() + x.1.width() >= 0.5 * before {
            break;
        }
    }
    x
}
