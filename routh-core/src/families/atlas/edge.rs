//! The start of a boundary curve on an edge of the grid whose end nodes differ in verdict:
//! the test function bracketed by regula falsi (Illinois) along the edge, then projected onto
//! the curve (see the module docs of [`super`], "The boundary curves").

use nalgebra::{Vector3, Vector4};

use super::super::equations::{restricted_eigen, Local};
use super::curve::{CurvePoint, Test};
use super::grid::Node;
use super::Ctx;
use crate::model::Routhian;
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
                let (mut sa, mut ga, mut fa): (f64, _, _) = (0.0, na.gamma, tau(0.0, &na.gamma)?);
                let (mut sb, mut gb, mut fb) = (1.0, nb.gamma, tau(1.0, &nb.gamma)?);
                if fa * fb > 0.0 || (fa == 0.0 && fb == 0.0) {
                    return None;
                }
                // Illinois on τ(s) along the edge, γ(s) by continuation from the bracket.
                let (mut sc, mut gc) = if fa.abs() <= fb.abs() {
                    (sa, ga)
                } else {
                    (sb, gb)
                };
                for _ in 0..LOCATE_MAX_ITER {
                    if fa == 0.0 {
                        (sc, gc) = (sa, ga);
                        break;
                    }
                    if fb == 0.0 {
                        (sc, gc) = (sb, gb);
                        break;
                    }
                    if (sb - sa).abs() <= 1e-12 {
                        break;
                    }
                    let mut s = (sa * fb - sb * fa) / (fb - fa);
                    if !(s.is_finite() && s > sa.min(sb) && s < sa.max(sb)) {
                        s = 0.5 * (sa + sb);
                    }
                    let g = self
                        .follow(point(sb), &gb, point(s))
                        .reached
                        .or_else(|| self.follow(point(sa), &ga, point(s)).reached)?;
                    let f = tau(s, &g)?;
                    (sc, gc) = (s, g);
                    if f.abs() <= 1e-3 * self.opts.curve_tol {
                        break;
                    }
                    if f * fb < 0.0 {
                        (sa, ga, fa) = (sb, gb, fb);
                    } else {
                        fa /= 2.0;
                    }
                    (sb, gb, fb) = (s, g, f);
                }
                (test, sc, gc)
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
