//! The grid of the atlas: the steady motion followed from node to node by a tangent predictor
//! and Newton's method on the sphere (natural-parameter steps of the crate's predictor–corrector,
//! [`PathOptions::grid_segment`]), and its verdict at every node (see the module docs of
//! [`super`], "The grid").

use std::convert::Infallible;

use nalgebra::{Matrix2, Matrix3x2, Matrix4, Vector2, Vector3, Vector4};

use super::super::equations::{chart, chart_eval, relative_discriminant};
use super::{at_xy, Ctx, PINV_CUT};
use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::newton::{Linearised, Newton};
use crate::solve::path::{Check, Corrected, Outcome, Path, PathOptions, Point, Prediction};
use crate::sphere::local::Local;
use crate::sphere::{sym2_eigen, tangent_basis};
use crate::stability::{classify_with, StabilityReport};
use crate::steady::SteadyMotion;

/// Central-difference step in the segment parameter of the grid continuation.
const SEGMENT_DS: f64 = 1e-6;
/// Jump detection: `|ξ − ξ_pred| ≤ JUMP_RATIO·|ξ_pred| + JUMP_FLOOR`.
const JUMP_RATIO: f64 = 0.3;
const JUMP_FLOOR: f64 = 1e-4;
/// Jump detection: eigenvalues of `K` move by at most this fraction of the local scale per step.
const EIGEN_JUMP: f64 = 0.3;
/// A continuation that stalls where an eigenvalue of `K` is below this fraction of the size of the
/// derivatives ended at a fold; elsewhere the motion was lost.
const FOLD_EIGEN: f64 = 1e-3;

/// A grid node where the motion was found.
#[derive(Debug, Clone)]
pub(super) struct Node {
    pub(super) gamma: Vector3<f64>,
    pub(super) report: StabilityReport,
    /// [`relative_discriminant`] of `f₂` there.
    pub(super) disc: f64,
}

/// The result of following the motion along a segment.
pub(super) struct Follow {
    /// γ at the end of the segment, if reached.
    pub(super) reached: Option<Vector3<f64>>,
    /// The last point reached: the segment parameter and γ.
    pub(super) last: (f64, Vector3<f64>),
}

/// Minimum-norm solution of `j·d = b`, singular values `≤ cut` taken as zero (the tangent
/// predictor of [`Ctx::follow`]).
pub(super) fn pinv_solve2(j: &Matrix2<f64>, b: &Vector2<f64>, cut: f64) -> Option<Vector2<f64>> {
    if !j.iter().all(|v| v.is_finite()) || !b.iter().all(|v| v.is_finite()) {
        return None;
    }
    let svd = j.svd(true, true);
    svd.solve(b, cut)
        .ok()
        .filter(|d| d.iter().all(|v| v.is_finite()))
}

impl<M: Routhian, F: Fn(f64, f64) -> (M, f64)> Ctx<'_, M, F> {
    /// Newton's method on the sphere ([`Newton::grid`]) for the member `(m, p)`, in the chart
    /// around `base`, from `xi0`. `None` if it does not converge.
    pub(super) fn newton(
        m: &M,
        p: f64,
        base: &Vector3<f64>,
        basis: &Matrix3x2<f64>,
        xi0: Vector2<f64>,
    ) -> Option<(Vector2<f64>, Local)> {
        // `P_bᵀt` and its Jacobian relative to the local scale.
        let eval = |w: &Vector4<f64>| -> Result<Option<(Local, Linearised)>, Infallible> {
            let (g, dg) = chart(base, basis, &Vector2::new(w[0], w[1]));
            let Ok(l) = Local::at(m, &g, p) else {
                return Ok(None);
            };
            let scale = l.scale();
            if !(scale > 0.0 && scale.is_finite()) {
                return Ok(None);
            }
            let f = basis.transpose() * l.tangential() / scale;
            let j = basis.transpose() * l.dt_dgamma() * dg / scale;
            let mut jac = Matrix4::zeros();
            jac.fixed_view_mut::<2, 2>(0, 0).copy_from(&j);
            let lin = Linearised::new(Vector4::new(f.x, f.y, 0.0, 0.0), jac, 0.0);
            Ok(Some((l, lin)))
        };
        let w0 = Vector4::new(xi0.x, xi0.y, 0.0, 0.0);
        let start = eval(&w0).ok()??;
        let out = Newton::grid()
            .solve(w0, &[], start, |p| p.1, |_, w, _| eval(w), |_| false)
            .ok()?;
        out.ok().map(|s| (Vector2::new(s.w[0], s.w[1]), s.point.0))
    }

    /// Follows the motion from `γ_a` at `a` to `b` along the segment.
    pub(super) fn follow(&self, a: (f64, f64), gamma_a: &Vector3<f64>, b: (f64, f64)) -> Follow {
        let seg = |s: f64| {
            if s == 1.0 {
                (self.family)(b.0, b.1)
            } else {
                (self.family)(a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1))
            }
        };
        let mut s = 0.0;
        let mut gamma = *gamma_a;
        let mut path = Path::new(PathOptions::grid_segment(2), 1.0);
        let lost = |s: f64, gamma: Vector3<f64>| Follow {
            reached: None,
            last: (s, gamma),
        };
        while s < 1.0 {
            // The point is (ξ, s) in the chart around γ, the tangent (dξ/ds, 1).
            let basis = tangent_basis(&gamma);
            let Ok(ce) = chart_eval(&seg, &gamma, &basis, &Vector2::zeros(), s, SEGMENT_DS) else {
                return lost(s, gamma);
            };
            let scale = ce.local.scale();
            let kappa0 = sym2_eigen(&ce.local.restricted()).values;
            let jxi = ce.jac.fixed_view::<2, 2>(0, 0).into_owned();
            let js = ce.jac.column(2).into_owned();
            let Some(dxi) = pinv_solve2(&jxi, &(-js), PINV_CUT * scale) else {
                return lost(s, gamma);
            };
            // Newton at the predicted s (exactly the end of the segment on the last step).
            let correct = |p: &Prediction<3>| {
                let s1 = if p.at_limit { 1.0 } else { p.point[2] };
                let pred = Vector2::new(p.point[0], p.point[1]);
                let (m, mp) = seg(s1);
                let newton = mp
                    .is_finite()
                    .then(|| Self::newton(&m, mp, &gamma, &basis, pred));
                Ok::<_, Infallible>(newton.flatten().map(|(xi, l)| Corrected {
                    point: Vector3::new(xi.x, xi.y, s1),
                    iterations: 0,
                    value: (pred, l),
                }))
            };
            // Jumps: ξ within `JUMP_RATIO` of its predicted move, the eigenvalues of K within
            // `EIGEN_JUMP` of the local scale of their values at the start of the step.
            let check = |p: &Point<3, (Vector2<f64>, Local)>, _| {
                let (pred, l) = &p.value;
                let xi = Vector2::new(p.point[0], p.point[1]);
                let kappa1 = sym2_eigen(&l.restricted()).values;
                let near = (xi - pred).norm() <= JUMP_RATIO * pred.norm() + JUMP_FLOOR;
                let smooth = (0..2)
                    .all(|i| (kappa1[i] - kappa0[i]).abs() <= EIGEN_JUMP * scale.max(l.scale()));
                if near && smooth {
                    Check::Accept
                } else {
                    Check::Shorten
                }
            };
            let t = Vector3::new(dxi.x, dxi.y, 1.0);
            let w = Vector3::new(0.0, 0.0, s);
            let Ok(step) = path.step(&w, &t, 1.0 - s, correct, |c| Ok(Some(c.bare())), check);
            let Outcome::Accepted { point, .. } = step else {
                return lost(s, gamma);
            };
            s = point.point[2];
            gamma = point.value.1.gamma;
        }
        Follow {
            reached: Some(gamma),
            last: (1.0, gamma),
        }
    }

    /// The record and verdict at a node where the motion is at `gamma`.
    pub(super) fn node(&self, x: f64, y: f64, gamma: Vector3<f64>) -> Result<Node, RouthError> {
        let (m, p) = self.member(x, y)?;
        let steady = SteadyMotion::at(&m, gamma, p, true).map_err(|e| at_xy(x, y, e))?;
        let report = classify_with(&m, &steady, &self.opts.classify).map_err(|e| at_xy(x, y, e))?;
        let disc = relative_discriminant(&m, &steady.gamma, p).map_err(|e| at_xy(x, y, e))?;
        Ok(Node {
            gamma: steady.gamma,
            report,
            disc,
        })
    }

    /// Whether the motion, lost by [`Ctx::follow`] at `last` on the segment from `a` to `b`,
    /// ended at a fold (the restricted second variation has an eigenvalue below `1e−3` of the
    /// size of the derivatives there: the motion ceases to exist) rather than being lost (its
    /// continuation would jump to another motion or stalls for another reason).
    pub(super) fn lost_at(&self, a: (f64, f64), b: (f64, f64), last: (f64, Vector3<f64>)) -> bool {
        let (s, gamma) = last;
        let (m, p) = (self.family)(a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1));
        match Local::at(&m, &gamma, p) {
            Ok(l) => {
                let k = sym2_eigen(&l.restricted()).values;
                k[0].abs().min(k[1].abs()) > FOLD_EIGEN * l.scale()
            }
            Err(_) => true,
        }
    }

    /// Follows the motion along the line of nodes `xs` at ordinate `y` from the node `i0`, where
    /// it is at `first`, both ways. Returns the nodes and, for each node without the motion,
    /// whether it was lost (see [`Ctx::lost_at`]); `lost0` is that flag for every node when
    /// `first` is `None`.
    pub(super) fn row(
        &self,
        xs: &[f64],
        y: f64,
        i0: usize,
        first: Option<Vector3<f64>>,
        lost0: bool,
    ) -> Result<Line, RouthError> {
        // A cancelled atlas skips its remaining rows (and returns Interrupted).
        self.opts.control.check()?;
        let done = self
            .rows_done
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        self.opts.control.report(done, self.opts.ny);
        let mut out: Vec<Option<Node>> = vec![None; xs.len()];
        let mut lost = vec![false; xs.len()];
        let Some(g0) = first else {
            return Ok((out, vec![lost0; xs.len()]));
        };
        out[i0] = Some(self.node(xs[i0], y, g0)?);
        let order: [Vec<usize>; 2] = [(i0 + 1..xs.len()).collect(), (0..i0).rev().collect()];
        for dir in order {
            let mut gone: Option<bool> = None;
            for i in dir {
                if let Some(l) = gone {
                    lost[i] = l;
                    continue;
                }
                self.member(xs[i], y)?;
                let k = if i > i0 { i - 1 } else { i + 1 };
                let Some(g) = out[k].as_ref().map(|n| n.gamma) else {
                    continue;
                };
                let f = self.follow((xs[k], y), &g, (xs[i], y));
                match f.reached {
                    Some(g) => out[i] = Some(self.node(xs[i], y, g)?),
                    None => {
                        let l = self.lost_at((xs[k], y), (xs[i], y), f.last);
                        lost[i] = l;
                        gone = Some(l);
                    }
                }
            }
        }
        Ok((out, lost))
    }
}

/// The nodes of one line of the grid and, where the motion is missing, whether it was lost.
pub(super) type Line = (Vec<Option<Node>>, Vec<bool>);
