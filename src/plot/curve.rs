//! Curves smooth at print resolution: a polyline of samples along a curve is drawn through a
//! cubic Hermite interpolant of its points (in fractional pixels, corners kept), and dashes are
//! laid along its arc length in one pattern from end to end, so that a dashed line over a few
//! samples neither shows their corners nor restarts its pattern at each one.

/// A point in fractional pixels.
pub(super) type PxF = (f64, f64);
/// A point in whole pixels.
pub(super) type Px = (i32, i32);

/// Points closer than this (pixels) to the last one kept are dropped before interpolating: a
/// dense branch has many points per pixel, whose rounding noise would otherwise show.
const MIN_GAP: f64 = 1.5;
/// The longest straight piece of the interpolant where the curve bends (pixels).
const PIECE: f64 = 2.5;
/// A turn sharper than this (radians) at a sample is a corner (a cusp of the energy–momentum
/// diagram, say), kept as it is.
const CORNER: f64 = 1.0;

fn sub(a: PxF, b: PxF) -> PxF {
    (a.0 - b.0, a.1 - b.1)
}

fn norm(a: PxF) -> f64 {
    a.0.hypot(a.1)
}

/// The angle between two directions, in `[0, π]`.
fn turn(a: PxF, b: PxF) -> f64 {
    let (na, nb) = (norm(a), norm(b));
    if na == 0.0 || nb == 0.0 {
        return 0.0;
    }
    ((a.0 * b.0 + a.1 * b.1) / (na * nb))
        .clamp(-1.0, 1.0)
        .acos()
}

/// The points thinned to at least [`MIN_GAP`] apart (the last always kept).
fn thin(pts: &[PxF]) -> Vec<PxF> {
    let mut out: Vec<PxF> = Vec::with_capacity(pts.len());
    for (i, &p) in pts.iter().enumerate() {
        let last = i + 1 == pts.len();
        match out.last() {
            Some(&q) if norm(sub(p, q)) < MIN_GAP => {
                if last && out.len() > 1 {
                    *out.last_mut().expect("non-empty") = p;
                } else if last {
                    out.push(p);
                }
            }
            _ => out.push(p),
        }
    }
    out
}

/// The polyline through `pts` with each segment replaced by a cubic Hermite arc whose tangents
/// are the central differences of the samples (one-sided at the ends and at corners), cut into
/// pieces of at most [`PIECE`] pixels where the curve bends. Straight runs stay two points.
pub(super) fn smooth(pts: &[PxF]) -> Vec<PxF> {
    let p = thin(pts);
    let n = p.len();
    if n < 3 {
        return p;
    }
    // The unit tangent at each sample.
    let unit = |v: PxF| {
        let l = norm(v);
        if l > 0.0 {
            (v.0 / l, v.1 / l)
        } else {
            (0.0, 0.0)
        }
    };
    let corner =
        |i: usize| i > 0 && i + 1 < n && turn(sub(p[i], p[i - 1]), sub(p[i + 1], p[i])) > CORNER;
    let central = |i: usize| unit(sub(p[i + 1], p[i - 1]));
    // At an end, the tangent of the parabola through the first (last) three samples: the chord's
    // direction mirrored about the neighbour's tangent.
    let end = |chord: PxF, next: PxF| unit((2.0 * chord.0 - next.0, 2.0 * chord.1 - next.1));
    let tangent_out = |i: usize| {
        let chord = unit(sub(p[i + 1], p[i]));
        if i == 0 && !corner(1) {
            end(chord, central(1))
        } else if i == 0 || corner(i) {
            chord
        } else {
            central(i)
        }
    };
    let tangent_in = |i: usize| {
        let chord = unit(sub(p[i], p[i - 1]));
        if i + 1 == n && !corner(n - 2) {
            end(chord, central(n - 2))
        } else if i + 1 == n || corner(i) {
            chord
        } else {
            central(i)
        }
    };
    let mut out = vec![p[0]];
    for i in 0..n - 1 {
        let (a, b) = (p[i], p[i + 1]);
        let len = norm(sub(b, a));
        let (ta, tb) = (tangent_out(i), tangent_in(i + 1));
        let chord = unit(sub(b, a));
        let bend = turn(ta, chord).max(turn(chord, tb));
        let pieces = if bend < 0.01 {
            1
        } else {
            ((len / PIECE).ceil() as usize).clamp(1, 64)
        };
        for k in 1..=pieces {
            let t = k as f64 / pieces as f64;
            let (t2, t3) = (t * t, t * t * t);
            let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
            let h10 = t3 - 2.0 * t2 + t;
            let h01 = -2.0 * t3 + 3.0 * t2;
            let h11 = t3 - t2;
            out.push((
                h00 * a.0 + h10 * len * ta.0 + h01 * b.0 + h11 * len * tb.0,
                h00 * a.1 + h10 * len * ta.1 + h01 * b.1 + h11 * len * tb.1,
            ));
        }
    }
    out
}

/// The dashes of a dash-`dash`, gap-`gap` pattern laid along the polyline from its start, each
/// dash a polyline of its own (following the curve round its bends).
pub(super) fn dashes(pts: &[PxF], dash: f64, gap: f64) -> Vec<Vec<PxF>> {
    let mut out = Vec::new();
    if pts.len() < 2 || dash <= 0.0 {
        return out;
    }
    let period = dash + gap.max(0.0);
    let mut phase = 0.0f64; // arc length into the current period
    let mut cur: Vec<PxF> = vec![pts[0]];
    for w in pts.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = norm(sub(b, a));
        let mut done = 0.0f64;
        while done < len {
            let on = phase < dash;
            let to_switch = if on { dash - phase } else { period - phase };
            let step = to_switch.min(len - done);
            done += step;
            phase += step;
            let t = done / len;
            let q = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if on {
                cur.push(q);
            }
            if phase >= dash && on {
                if cur.len() >= 2 {
                    out.push(std::mem::take(&mut cur));
                }
                cur.clear();
            }
            if phase >= period {
                phase -= period;
                cur = vec![q];
            }
        }
    }
    if phase < dash && cur.len() >= 2 {
        out.push(cur);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_sampled_coarsely_is_drawn_close_to_the_circle() {
        // 12 samples of a circle of radius 100: the chords stray 3.4 px from it, the
        // interpolant much less.
        let r = 100.0;
        let pts: Vec<PxF> = (0..=12)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 24.0;
                (r * a.cos(), r * a.sin())
            })
            .collect();
        let s = smooth(&pts);
        assert!(s.len() > 100, "{}", s.len());
        let worst = s.iter().map(|p| (norm(*p) - r).abs()).fold(0.0, f64::max);
        assert!(worst < 0.5, "{worst}");
        // Every piece short.
        assert!(s.windows(2).all(|w| norm(sub(w[1], w[0])) <= PIECE + 1e-9));
    }

    #[test]
    fn corners_and_straight_lines_stay_as_they_are() {
        let cusp = [
            (0.0, 0.0),
            (50.0, 0.0),
            (100.0, 0.0),
            (50.0, 5.0),
            (0.0, 10.0),
        ];
        let s = smooth(&cusp);
        assert!(s.contains(&(100.0, 0.0)));
        // No point beyond the cusp.
        assert!(s.iter().all(|p| p.0 <= 100.0 + 1e-9), "{s:?}");
        assert_eq!(smooth(&[(0.0, 0.0), (10.0, 0.0), (20.0, 0.0)]).len(), 3);
    }

    #[test]
    fn dashes_run_on_across_the_samples() {
        // A line of 100 px in 7 unequal pieces, dash 9 gap 6: dashes start every 15 px.
        let xs = [0.0, 3.0, 17.0, 18.0, 40.0, 61.0, 88.0, 100.0];
        let pts: Vec<PxF> = xs.iter().map(|&x| (x, 0.0)).collect();
        let d = dashes(&pts, 9.0, 6.0);
        assert_eq!(d.len(), 7);
        for (k, dash) in d.iter().enumerate() {
            let (a, b) = (dash[0].0, dash[dash.len() - 1].0);
            assert!((a - 15.0 * k as f64).abs() < 1e-9, "{k}: {a}");
            assert!((b - a - 9.0).abs() < 1e-9 || b == 100.0, "{k}: {a} {b}");
        }
    }
}
