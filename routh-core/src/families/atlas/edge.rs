//! The start of a boundary curve on an edge of the grid whose end nodes differ in verdict:
//! the test function located along the edge by the crate's event locator ([`crate::solve::locate`]),
//! then projected onto the curve (see the module docs of [`super`], "The boundary curves").

use nalgebra::{Vector3, Vector4};

use super::super::equations::restricted_eigen;
use super::curve::{CurvePoint, Test};
use super::grid::Node;
use super::Ctx;
use crate::model::Routhian;
use crate::solve::locate::{locate, End, Stop};
use crate::sphere::local::Local;
use crate::sphere::{sym2_eigen, tangent_basis};

const LOCATE_MAX_ITER: usize = 80;

/// Which zero the search on an edge looks for.
#[derive(Debug, Clone, Copy)]
pub(super) enum Seed {
    /// The motion is lost beyond this edge.
    Fold,
    /// The `k`-th eigenvalue (ascending) of `K` changes sign.
    Zero(usize),
    /// The discriminant of `f₂` changes sign with degree 2 on both ends.
    Hopf,
}

impl<M: Routhian, F: Fn(f64, f64) -> (M, f64)> Ctx<'_, M, F> {
    /// The start of a curve on the edge from node `a` to node `b`: the test function and the
    /// point, projected onto the curve.
    pub(super) fn locate(
        &self,
        pa: (f64, f64),
        na: &Node,
        pb: (f64, f64),
        nb: Option<&Node>,
        seed: Seed,
    ) -> Option<(Test, CurvePoint)> {
        let point = |s: f64| {
            if s == 1.0 {
                pb
            } else {
                (pa.0 + s * (pb.0 - pa.0), pa.1 + s * (pb.1 - pa.1))
            }
        };
        let (test, s0, g0) = match seed {
            Seed::Fold => {
                let f = self.follow(pa, &na.gamma, pb);
                if f.reached.is_some() {
                    return None;
                }
                let (s, g) = f.last;
                let (x, y) = point(s);
                let (m, p) = self.member(x, y).ok()?;
                let l = Local::at(&m, &g, p).ok()?;
                (Test::Zero(restricted_eigen(&l).1), s, g)
            }
            Seed::Zero(_) | Seed::Hopf => {
                let nb = nb?;
                let test = match seed {
                    Seed::Zero(k) => {
                        let (m, p) = self.member(pa.0, pa.1).ok()?;
                        let l = Local::at(&m, &na.gamma, p).ok()?;
                        let e = sym2_eigen(&l.restricted());
                        Test::Zero(tangent_basis(&na.gamma) * e.vectors[k])
                    }
                    _ => Test::Hopf,
                };
                let tau = |s: f64, g: &Vector3<f64>| {
                    let (x, y) = point(s);
                    self.tau(&test, g, x, y).ok().map(|t| t.0)
                };
                let (fa, fb) = (tau(0.0, &na.gamma)?, tau(1.0, &nb.gamma)?);
                if fa * fb > 0.0 || (fa == 0.0 && fb == 0.0) {
                    return None;
                }
                // τ(s) along the edge, γ(s) by continuation from the nearer end of the bracket
                // (else the other).
                let end = End::new;
                let found = locate(
                    end(0.0, fa, na.gamma),
                    end(1.0, fb, nb.gamma),
                    LOCATE_MAX_ITER,
                    |s, lo, hi| {
                        let (near, far) = if s - lo.at <= hi.at - s {
                            (lo, hi)
                        } else {
                            (hi, lo)
                        };
                        let g = self
                            .follow(point(near.at), &near.point, point(s))
                            .reached
                            .or_else(|| self.follow(point(far.at), &far.point, point(s)).reached);
                        Ok::<_, ()>(g.and_then(|g| Some((tau(s, &g)?, g))))
                    },
                    |lo, hi| {
                        lo.value.abs().min(hi.value.abs()) <= 1e-3 * self.opts.curve_tol
                            || hi.at - lo.at <= 1e-12
                    },
                )
                .ok()?;
                if found.stop == Stop::SolveFailed {
                    return None;
                }
                (test, found.best.at, found.best.point)
            }
        };
        let (x, y) = point(s0);
        let (u, v) = self.scale_xy(x, y);
        let basis = tangent_basis(&g0);
        let (w, e, _) = self.correct(&test, &g0, &basis, Vector4::new(0.0, 0.0, u, v), None)?;
        let test = match test {
            Test::Zero(_) => Test::Zero(e.pick),
            t => t,
        };
        Some((
            test,
            CurvePoint {
                gamma: e.gamma,
                u: w[2],
                v: w[3],
            },
        ))
    }
}
