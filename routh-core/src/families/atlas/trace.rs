//! The boundary curves of the atlas followed by pseudo-arclength continuation from their starts
//! on the grid edges (the crate's predictor–corrector, [`PathOptions::atlas_boundary`]), with
//! their kind (see the module docs of [`super`], "The boundary curves").

use nalgebra::{Vector2, Vector4};

use super::super::equations::chart;
use super::super::{BoundaryCurve, EventKind, StopReason};
use super::curve::{fold_indicator, null_tangent, CurvePoint, Ext, Test};
use super::edge::Seed;
use super::grid::Node;
use super::Ctx;
use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::path::row::LinearRow;
use crate::solve::path::{Check, Corrected, Outcome, Path, PathOptions, Point, Prediction};
use crate::sphere::tangent_basis;

/// A zero-eigenvalue curve is a fold where [`fold_indicator`] exceeds this.
const FOLD_INDICATOR: f64 = 1e-6;
/// Starts closer than this (unit square) to a traced curve of the same class are skipped.
const DEDUP: f64 = 2e-3;

/// A traced curve: whether it is a Hamiltonian–Hopf curve, its points in the unit square, and
/// the number of them where the fold indicator is non-zero.
pub(super) type Traced = (bool, Vec<(f64, f64)>, usize);

/// Distance from `p` to the segment `[a, b]` of the plane.
pub(super) fn segment_distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

impl<M: Routhian, F: Fn(f64, f64) -> (M, f64)> Ctx<'_, M, F> {
    /// Follows a curve from `start` along `t0` (in the chart around `start.gamma`), with at most
    /// `budget` points: the points after the start, and whether it closed.
    ///
    /// When the budget is spent before the curve leaves the rectangle, closes or ends, the curve
    /// ends there and [`StopReason::MaxCurvePoints`] is recorded.
    pub(super) fn trace(
        &self,
        test0: Test,
        start: CurvePoint,
        t0: Vector4<f64>,
        budget: usize,
    ) -> Result<(Vec<(CurvePoint, f64)>, bool), RouthError> {
        let h_max = self.opts.curve_step * std::f64::consts::SQRT_2;
        let mut path = Path::new(PathOptions::atlas_boundary(h_max), h_max);
        let mut test = test0;
        let mut pts = Vec::new();
        let mut cur = start;
        let mut t = t0;
        let mut travelled = 0.0;
        let inside = |u: f64, v: f64| (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v);
        loop {
            if pts.len() >= budget {
                // The budget ends this curve, not the atlas: the atlas comes back with
                // `stop` saying where.
                let (x, y) = self.unscale(cur.u, cur.v);
                self.stopped(StopReason::MaxCurvePoints {
                    x,
                    y,
                    gamma: cur.gamma,
                });
                return Ok((pts, false));
            }
            let basis = tangent_basis(&cur.gamma);
            let w = Vector4::new(0.0, 0.0, cur.u, cur.v);
            // In the chart around the current point: the corrector on the test's equations and
            // the row of the path, the tangent from the null vector of the extended Jacobian.
            let correct = |p: &Prediction<4>| {
                Ok::<_, RouthError>(self.correct(&test, &cur.gamma, &basis, p.point, p.row).map(
                    |(wc, e, it)| Corrected {
                        point: wc,
                        iterations: it,
                        value: e,
                    },
                ))
            };
            let complete = |c: Corrected<4, Ext>| {
                Ok(null_tangent(&c.value.jac, &t).map(|tn| Point {
                    tangent: Some(tn),
                    ..c.bare()
                }))
            };
            let accepted = path.step(&w, &t, f64::INFINITY, correct, complete, |_, _| {
                Check::Accept
            })?;
            let Outcome::Accepted { point, .. } = accepted else {
                // A cusp, a crossing or the end of the motion: the curve ends here.
                return Ok((pts, false));
            };
            let (wc, e, tn) = (point.point, point.value, point.tangent.unwrap_or(t));
            if !inside(wc[2], wc[3]) {
                // Solve the exit point on the edge of the square crossed first.
                let mut best: Option<(f64, usize, f64)> = None;
                for (k, from, to) in [(2, w[2], wc[2]), (3, w[3], wc[3])] {
                    for bound in [0.0, 1.0] {
                        if (to - bound) * (from - bound) < 0.0 || (to != bound && from == bound) {
                            let lam = (bound - from) / (to - from);
                            if best.is_none_or(|b| lam < b.0) {
                                best = Some((lam, k, bound));
                            }
                        }
                    }
                }
                if let Some((lam, k, bound)) = best {
                    let guess = w + (wc - w) * lam;
                    let row = LinearRow::fixed(k, bound);
                    if let Some((we, ee, _)) =
                        self.correct(&test, &cur.gamma, &basis, guess, Some(row))
                    {
                        let (mut u, mut v) = (we[2], we[3]);
                        if k == 2 {
                            u = bound;
                        } else {
                            v = bound;
                        }
                        if inside(u, v) {
                            let point = CurvePoint {
                                gamma: ee.gamma,
                                u,
                                v,
                            };
                            pts.push((point, fold_indicator(&ee)));
                        }
                    }
                }
                return Ok((pts, false));
            }
            // Accept; move the chart to the new point and carry the tangent over.
            let xi = Vector2::new(wc[0], wc[1]);
            let dg = chart(&cur.gamma, &basis, &xi).1;
            let nb = tangent_basis(&e.gamma);
            let txi = nb.transpose() * (dg * Vector2::new(tn[0], tn[1]));
            let tnew = Vector4::new(txi.x, txi.y, tn[2], tn[3]);
            t = tnew / tnew.norm();
            travelled += (wc - w).norm();
            cur = CurvePoint {
                gamma: e.gamma,
                u: wc[2],
                v: wc[3],
            };
            if let Test::Zero(_) = test {
                test = Test::Zero(e.pick);
            }
            pts.push((cur, fold_indicator(&e)));
            let h = path.h();
            let back = (cur.u - start.u).hypot(cur.v - start.v);
            if travelled > 4.0 * h_max && back < h && (cur.gamma - start.gamma).norm() < 0.1 {
                let beta = pts[0].1;
                pts.push((start, beta));
                return Ok((pts, true));
            }
        }
    }

    /// All boundary curves from the grid.
    ///
    /// Errors: those of [`Ctx::trace`].
    pub(super) fn boundaries(
        &self,
        xs: &[f64],
        ys: &[f64],
        rows: &[Vec<Option<Node>>],
    ) -> Result<Vec<BoundaryCurve>, RouthError> {
        let (nx, ny) = (xs.len(), ys.len());
        let mut edges = Vec::new();
        for j in 0..ny {
            for i in 0..nx - 1 {
                edges.push(((i, j), (i + 1, j)));
            }
        }
        for i in 0..nx {
            for j in 0..ny - 1 {
                edges.push(((i, j), (i, j + 1)));
            }
        }
        // (kind is Hopf, scaled points, started at a fold).
        // (kind is Hopf, scaled points, number of points where the fold indicator is non-zero).
        let mut curves: Vec<Traced> = Vec::new();
        let budget = self.opts.max_curve_points;
        for (a, b) in edges {
            let na = rows[a.1][a.0].as_ref();
            let nb = rows[b.1][b.0].as_ref();
            let (pa, pb) = ((xs[a.0], ys[a.1]), (xs[b.0], ys[b.1]));
            let mut seeds: Vec<(f64, f64, &Node, Option<&Node>, Seed)> = Vec::new();
            match (na, nb) {
                (Some(n), None) => seeds.push((pa.0, pa.1, n, None, Seed::Fold)),
                (None, Some(n)) => seeds.push((pb.0, pb.1, n, None, Seed::Fold)),
                (Some(n1), Some(n2)) if n1.report.verdict != n2.report.verdict => {
                    let (k1, k2) = (
                        n1.report.restricted_hessian_eigenvalues,
                        n2.report.restricted_hessian_eigenvalues,
                    );
                    for k in 0..2 {
                        if k1[k] * k2[k] <= 0.0 && !(k1[k] == 0.0 && k2[k] == 0.0) {
                            seeds.push((pa.0, pa.1, n1, Some(n2), Seed::Zero(k)));
                        }
                    }
                    if k1[1] < 0.0 && k2[1] < 0.0 && n1.disc * n2.disc <= 0.0 {
                        seeds.push((pa.0, pa.1, n1, Some(n2), Seed::Hopf));
                    }
                }
                _ => {}
            }
            for (x0, y0, n1, n2, seed) in seeds {
                let to = if (x0, y0) == pa { pb } else { pa };
                let Some((test, start)) = self.locate((x0, y0), n1, to, n2, seed) else {
                    continue;
                };
                let hopf = test == Test::Hopf;
                let near = curves.iter().any(|(h, pts, _)| {
                    *h == hopf
                        && pts
                            .windows(2)
                            .any(|s| segment_distance((start.u, start.v), s[0], s[1]) <= DEDUP)
                        || *h == hopf
                            && pts.len() == 1
                            && (pts[0].0 - start.u).hypot(pts[0].1 - start.v) <= DEDUP
                });
                if near {
                    continue;
                }
                let basis = tangent_basis(&start.gamma);
                let w = Vector4::new(0.0, 0.0, start.u, start.v);
                let Ok(e) = self.ext(&test, &start.gamma, &basis, &w) else {
                    continue;
                };
                let r = Vector4::new(0.0, 0.0, -e.jac[(2, 3)], e.jac[(2, 2)]);
                let r = if r.norm() > 0.0 {
                    r
                } else {
                    Vector4::new(0.0, 0.0, 1.0, 0.0)
                };
                let Some(t0) = null_tangent(&e.jac, &r) else {
                    continue;
                };
                let (fwd, closed) = self.trace(test, start, t0, budget.saturating_sub(1))?;
                let back = if closed {
                    Vec::new()
                } else {
                    self.trace(test, start, -t0, budget.saturating_sub(1 + fwd.len()))?
                        .0
                };
                let mut all: Vec<(CurvePoint, f64)> = back.into_iter().rev().collect();
                all.push((start, fold_indicator(&e)));
                all.extend(fwd);
                let folds = all.iter().filter(|p| p.1 > FOLD_INDICATOR).count();
                let pts = all.iter().map(|(p, _)| (p.u, p.v)).collect();
                curves.push((hopf, pts, folds));
            }
        }
        Ok(curves
            .into_iter()
            .map(|(hopf, pts, folds)| {
                let kind = if hopf {
                    EventKind::HamiltonianHopf
                } else if 2 * folds > pts.len() {
                    EventKind::Fold
                } else {
                    EventKind::BranchPoint
                };
                BoundaryCurve {
                    kind,
                    points: pts.iter().map(|&(u, v)| self.unscale(u, v)).collect(),
                }
            })
            .collect())
    }
}
