//! Curves of critical points of the amended potential (circles of steady motions of a symmetric
//! body): tracing them by continuation of the kernel of the restricted form (steps of the crate's
//! predictor–corrector, [`PathOptions::search_curve`]), testing whether a
//! point lies on one, their axes, and the index (winding number of the gradient) of a degenerate
//! isolated point for the Morse self-check.

use nalgebra::{Matrix3, SymmetricEigen, Vector2, Vector3};

use std::convert::Infallible;

use super::*;
use crate::model::Routhian;
use crate::solve::path::{
    sphere_head, Check, Corrected, Outcome, Path, PathOptions, Point, Prediction,
};

/// The unit normal of the least-squares plane through `vertices` (the axis of a circle on the
/// sphere), if there are at least three.
pub(super) fn curve_axis(vertices: &[Vector3<f64>]) -> Option<Vector3<f64>> {
    if vertices.len() < 3 {
        return None;
    }
    let mean: Vector3<f64> = vertices.iter().sum::<Vector3<f64>>() / vertices.len() as f64;
    let cov: Matrix3<f64> = vertices
        .iter()
        .map(|v| (v - mean) * (v - mean).transpose())
        .sum();
    let eig = SymmetricEigen::try_new(cov, f64::EPSILON, 1000)?;
    let k = eig.eigenvalues.imin();
    let n = eig.eigenvectors.column(k).into_owned();
    (n.iter().all(|x| x.is_finite()) && n.norm() > 0.0).then(|| n.normalize())
}

/// A traced curve of non-isolated critical points.
pub(super) struct Curve {
    pub(super) start: Riemannian,
    /// Vertices in order along the curve (the trace may have gone both ways from the start: the
    /// vertices of the second direction then follow those of the first, reversed at the seam).
    pub(super) vertices: Vec<Vector3<f64>>,
    pub(super) closed: bool,
    pub(super) step: f64,
}

impl Curve {
    /// Whether `loc` lies on this curve: degenerate, same level of `U_r` and within `h/2` of the
    /// polyline through the traced vertices (closed when the trace came back to its start).
    pub(super) fn contains(&self, loc: &Riemannian) -> bool {
        // A point of a curve of critical points has a zero eigenvalue; a non-degenerate point
        // close to a small curve (the pole inside a small circle) is not on it.
        if !same_level(&self.start, loc) || !loc.degenerate() {
            return false;
        }
        let n = self.vertices.len();
        let segments = if self.closed { n } else { n.saturating_sub(1) };
        let near = |a: &Vector3<f64>, b: &Vector3<f64>| {
            let ab = b - a;
            let len2 = ab.norm_squared();
            let t = if len2 > 0.0 {
                ((loc.gamma - a).dot(&ab) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (a + t * ab - loc.gamma).norm() <= 0.5 * self.step
        };
        (n == 1 && near(&self.vertices[0], &self.vertices[0]))
            || (0..segments).any(|i| near(&self.vertices[i], &self.vertices[(i + 1) % n]))
    }
}

impl<M: Routhian> Search<'_, M> {
    /// The index of the degenerate isolated critical point `loc`: the winding number of the
    /// gradient on the circle of radius `min(r, INDEX_RADIUS)` around it. `None` when the gradient
    /// vanishes (within round-off) somewhere on the circle or turns too fast to be followed.
    pub(super) fn index(&self, loc: &Riemannian, r: f64) -> Option<i64> {
        let r = r.min(INDEX_RADIUS);
        if r.is_nan() || r <= 0.0 {
            return None;
        }
        let mut total = 0.0;
        let mut first = None;
        let mut last: Option<f64> = None;
        for k in 0..=INDEX_SAMPLES {
            let a = 2.0 * std::f64::consts::PI * (k % INDEX_SAMPLES) as f64 / INDEX_SAMPLES as f64;
            let t = loc.t.basis * Vector2::new(a.cos(), a.sin());
            let g = (loc.gamma * r.cos() + t * r.sin()).normalize();
            let n = self.local(&g)?;
            if n.t.grad_norm <= 4.0 * n.t.grad_floor() {
                return None;
            }
            let w = loc.t.basis.transpose() * n.grad3();
            let angle = w.y.atan2(w.x);
            if let Some(prev) = last {
                let mut d = angle - prev;
                d -= 2.0 * std::f64::consts::PI * (d / (2.0 * std::f64::consts::PI)).round();
                if d.abs() > 0.5 * std::f64::consts::PI {
                    return None;
                }
                total += d;
            } else {
                first = Some(angle);
            }
            last = Some(angle);
        }
        first?;
        let idx = total / (2.0 * std::f64::consts::PI);
        ((idx - idx.round()).abs() < 0.1).then_some(idx.round() as i64)
    }

    /// The next point of a curve from `from` along `dir`, one step of `path` (steps of exactly
    /// its `h`, [`PathOptions::search_curve`]): Newton ([`Search::refine`]) from the prediction,
    /// accepted when converged, degenerate, on the level of `level` and at a distance in
    /// `[h/4, 3h]` from `from`. `Err(true)` when the iteration came back to `from` itself.
    fn continue_from(
        &self,
        path: &mut Path<3>,
        from: &Riemannian,
        dir: &Vector3<f64>,
        level: &Riemannian,
    ) -> Result<Riemannian, bool> {
        let mut back = false;
        let correct = |p: &Prediction<3>| {
            Ok::<_, Infallible>(match self.refine(&p.point, None) {
                Some(Refined::Converged(loc)) => Some(Corrected {
                    point: loc.gamma,
                    iterations: 0,
                    value: loc,
                }),
                _ => None,
            })
        };
        let check = |p: &Point<3, Riemannian>, h: f64| {
            let loc = &p.value;
            if same_point(loc, from) {
                back = true;
                return Check::Shorten;
            }
            let d = (loc.gamma - from.gamma).norm();
            if same_level(loc, level) && loc.degenerate() && d >= 0.25 * h && d <= 3.0 * h {
                Check::Accept
            } else {
                Check::Shorten
            }
        };
        let complete = |c: Corrected<3, Riemannian>| Ok(Some(c.bare()));
        let Ok(step) = path.step(&from.gamma, dir, f64::INFINITY, correct, complete, check);
        match step {
            Outcome::Accepted { point, .. } => Ok(point.value),
            _ => Err(back),
        }
    }

    /// Traces the curve of critical points through the degenerate critical point `start` along
    /// the kernel of `K`; `None` when there is no such curve (a degenerate isolated point).
    pub(super) fn trace(&self, start: &Riemannian) -> Option<Curve> {
        let t0 = start.null_direction();
        let mut h = TRACE_STEP;
        for level in 0..TRACE_LEVELS {
            let mut branches: Vec<Vec<Vector3<f64>>> = Vec::new();
            let mut closed = false;
            let mut returned = 0;
            for sign in [1.0, -1.0] {
                if closed {
                    break;
                }
                let mut path =
                    Path::new(PathOptions::search_curve(h), h).with_retraction(sphere_head);
                let first = match self.continue_from(&mut path, start, &(sign * t0), start) {
                    Ok(first) => first,
                    Err(back) => {
                        returned += usize::from(back);
                        continue;
                    }
                };
                let mut branch = vec![first.gamma];
                let mut prev = start.gamma;
                let mut cur = first;
                for step in 0..MAX_TRACE_STEPS {
                    let mut t = cur.null_direction();
                    if t.dot(&(cur.gamma - prev)) < 0.0 {
                        t = -t;
                    }
                    let Ok(next) = self.continue_from(&mut path, &cur, &t, start) else {
                        break;
                    };
                    branch.push(next.gamma);
                    if step >= 2 && (next.gamma - start.gamma).norm() < 1.5 * h {
                        closed = true;
                        break;
                    }
                    prev = cur.gamma;
                    cur = next;
                }
                branches.push(branch);
            }
            if branches.is_empty() {
                if returned == 2 {
                    // Newton brought both neighbours back to the start: an isolated point.
                    return None;
                }
                h /= 4.0;
                continue;
            }
            // A closed curve resolved by too few vertices (small compared with h): trace it again
            // with a shorter step.
            let count: usize = branches.iter().map(Vec::len).sum();
            if closed && count < MIN_CLOSED_VERTICES && level + 1 < TRACE_LEVELS {
                h /= 4.0;
                continue;
            }
            // A curve of critical points of an analytic U_r is closed (or branches); an open
            // "curve" of a few vertices is the smear of a degenerate isolated point (a pitchfork
            // point, where U_r is quartic along the kernel of K and Newton's method stops at the
            // tolerance a little off it, so its neighbours converge at a distance of that
            // offset): an isolated point.
            if !closed && count < MIN_OPEN_VERTICES {
                return None;
            }
            // Order the vertices along the curve: second branch reversed, start, first branch.
            let mut vertices: Vec<Vector3<f64>> = Vec::new();
            if let Some(back) = branches.get(1) {
                vertices.extend(back.iter().rev().copied());
            }
            vertices.push(start.gamma);
            vertices.extend(branches[0].iter().copied());
            return Some(Curve {
                start: *start,
                vertices,
                closed,
                step: h,
            });
        }
        None
    }
}
