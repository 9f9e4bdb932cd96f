//! The defining equations of a boundary curve of the atlas — `P_bᵀt(γ(ξ); x, y) = 0` (33) and
//! the test function `τ` (an eigenvalue of `K` (62)–(63), or the discriminant of `f₂`, errata
//! E5) — their Jacobian in `(ξ, u, v)` and the Gauss–Newton corrector onto them (see the module
//! docs of [`super`], "The boundary curves").

use std::convert::Infallible;

use nalgebra::{Matrix3x2, Matrix3x4, Matrix4, Vector2, Vector3, Vector4};

use super::super::equations::{chart, chart_eval, relative_discriminant};
use super::Ctx;
use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::newton::{Linearised, Newton};
use crate::solve::path::row::LinearRow;
use crate::sphere::local::Local;
use crate::sphere::{sym2_eigen, tangent_basis};

const XI_FD: f64 = 1e-6;
/// Singular values of the curve Jacobian below this fraction of the largest span its null space.
const NULL_CUT: f64 = 1e-8;

/// A test function whose zeros are a boundary curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Test {
    /// The eigenvalue of `K` (relative to the local scale) whose eigenvector is nearest the
    /// reference (a tangent vector of ℝ³).
    Zero(Vector3<f64>),
    /// The relative discriminant of `f₂`.
    Hopf,
}

/// A point of a curve: γ (the centre of the chart, ξ = 0) and the scaled parameters.
#[derive(Debug, Clone, Copy)]
pub(super) struct CurvePoint {
    pub(super) gamma: Vector3<f64>,
    pub(super) u: f64,
    pub(super) v: f64,
}

/// The curve equations at one point, in the chart around `base`.
pub(super) struct Ext {
    pub(super) gamma: Vector3<f64>,
    /// `(P_bᵀt / scale, τ)`.
    pub(super) g: Vector3<f64>,
    /// Its Jacobian in `(ξ₁, ξ₂, u, v)`.
    pub(super) jac: Matrix3x4<f64>,
    /// The eigenvector picked by a [`Test::Zero`] (zero for [`Test::Hopf`]).
    pub(super) pick: Vector3<f64>,
}

/// The null vector of the 3×4 `jac` nearest the reference `r` (normalised, oriented along `r`).
pub(super) fn null_tangent(jac: &Matrix3x4<f64>, r: &Vector4<f64>) -> Option<Vector4<f64>> {
    if !jac.iter().all(|v| v.is_finite()) {
        return None;
    }
    let mut m = Matrix4::zeros();
    m.fixed_view_mut::<3, 4>(0, 0).copy_from(jac);
    let svd = m.svd(false, true);
    let vt = svd.v_t?;
    let smax = svd.singular_values[0];
    let mut t = Vector4::zeros();
    for i in 0..4 {
        if i == 3 || svd.singular_values[i] <= NULL_CUT * smax {
            let v = vt.row(i).transpose();
            t += v * v.dot(r);
        }
    }
    if t.norm() <= 1e-6 * r.norm() {
        // The reference is orthogonal to the null space: take the last singular vector.
        t = vt.row(3).transpose();
        if t.dot(r) < 0.0 {
            t = -t;
        }
    }
    let n = t.norm();
    (n > 0.0 && n.is_finite()).then(|| t / n)
}

/// The fold indicator of a zero-eigenvalue curve at a point: `|ℓᵀ ∂F/∂(u, v)|` with `ℓ` the left
/// null vector of `∂F/∂ξ` (both relative to the local scale). Non-zero at a fold (the parameters
/// push the motion out of the null direction: it ceases to exist on one side), zero at a branch
/// point (where `∂F/∂(u, v)` lies in the range of `∂F/∂ξ`).
pub(super) fn fold_indicator(e: &Ext) -> f64 {
    let fxi = e.jac.fixed_view::<2, 2>(0, 0).into_owned();
    let fp = e.jac.fixed_view::<2, 2>(0, 2).into_owned();
    if !fxi.iter().chain(fp.iter()).all(|v| v.is_finite()) {
        return 0.0;
    }
    let svd = fxi.svd(true, false);
    let Some(u) = svd.u else { return 0.0 };
    let k = usize::from(svd.singular_values[1] < svd.singular_values[0]);
    (fp.transpose() * u.column(k)).norm()
}

impl<M: Routhian, F: Fn(f64, f64) -> (M, f64)> Ctx<'_, M, F> {
    /// The test function at γ and `(x, y)`, and the picked eigenvector.
    pub(super) fn tau(
        &self,
        test: &Test,
        gamma: &Vector3<f64>,
        x: f64,
        y: f64,
    ) -> Result<(f64, Vector3<f64>), RouthError> {
        let (m, p) = self.member(x, y)?;
        match test {
            Test::Zero(r) => {
                let l = Local::at(&m, gamma, p)?;
                let e = sym2_eigen(&l.restricted());
                let pb = tangent_basis(gamma);
                let v = [pb * e.vectors[0], pb * e.vectors[1]];
                let i = usize::from(v[1].dot(r).abs() > v[0].dot(r).abs());
                let scale = l.scale();
                Ok((e.values[i] / scale, v[i]))
            }
            Test::Hopf => Ok((relative_discriminant(&m, gamma, p)?, Vector3::zeros())),
        }
    }

    /// The curve equations and their Jacobian at `(ξ, u, v)` in the chart around `base`.
    pub(super) fn ext(
        &self,
        test: &Test,
        base: &Vector3<f64>,
        basis: &Matrix3x2<f64>,
        w: &Vector4<f64>,
    ) -> Result<Ext, RouthError> {
        let xi = Vector2::new(w[0], w[1]);
        let (x, y) = self.unscale(w[2], w[3]);
        let ce = chart_eval(&|s| (self.family)(s, y), base, basis, &xi, x, self.hx)?;
        let scale = ce.local.scale();
        if !(scale > 0.0 && scale.is_finite()) {
            return Err(RouthError::NoConvergence {
                what: "boundary curve (zero local scale)",
                iterations: 0,
                residual: f64::NAN,
            });
        }
        let ty = |yy: f64| -> Result<Vector2<f64>, RouthError> {
            let (m, p) = self.member(x, yy)?;
            Ok(basis.transpose() * Local::at(&m, &ce.gamma, p)?.tangential())
        };
        let fy = (ty(y + self.hy)? - ty(y - self.hy)?) / (2.0 * self.hy);
        let (t0, pick) = self.tau(test, &ce.gamma, x, y)?;
        let mut dtau = [0.0; 4];
        for (k, d) in dtau.iter_mut().enumerate().take(2) {
            let mut e = Vector2::zeros();
            e[k] = XI_FD;
            let gp = chart(base, basis, &(xi + e)).0;
            let gm = chart(base, basis, &(xi - e)).0;
            *d = (self.tau(test, &gp, x, y)?.0 - self.tau(test, &gm, x, y)?.0) / (2.0 * XI_FD);
        }
        dtau[2] = (self.tau(test, &ce.gamma, x + self.hx, y)?.0
            - self.tau(test, &ce.gamma, x - self.hx, y)?.0)
            / (2.0 * self.hx)
            * self.lx();
        dtau[3] = (self.tau(test, &ce.gamma, x, y + self.hy)?.0
            - self.tau(test, &ce.gamma, x, y - self.hy)?.0)
            / (2.0 * self.hy)
            * self.ly();
        let j = &ce.jac;
        let (lx, ly) = (self.lx(), self.ly());
        let jac = Matrix3x4::new(
            j[(0, 0)] / scale,
            j[(0, 1)] / scale,
            j[(0, 2)] * lx / scale,
            fy.x * ly / scale,
            j[(1, 0)] / scale,
            j[(1, 1)] / scale,
            j[(1, 2)] * lx / scale,
            fy.y * ly / scale,
            dtau[0],
            dtau[1],
            dtau[2],
            dtau[3],
        );
        Ok(Ext {
            gamma: ce.gamma,
            g: Vector3::new(ce.f.x / scale, ce.f.y / scale, t0),
            jac,
            pick,
        })
    }

    /// Gauss–Newton with minimum-norm steps ([`Newton::curve`]) on the curve equations, plus the
    /// linear equation `row` (`n·w = c`) if given, from `w0` in the chart around `base`.
    pub(super) fn correct(
        &self,
        test: &Test,
        base: &Vector3<f64>,
        basis: &Matrix3x2<f64>,
        w0: Vector4<f64>,
        row: Option<LinearRow<4>>,
    ) -> Option<(Vector4<f64>, Ext, usize)> {
        // The residual is the largest of the three equations (each relative to its own scale).
        let eval = |w: &Vector4<f64>| -> Result<Option<(Ext, Linearised)>, Infallible> {
            let Ok(e) = self.ext(test, base, basis, w) else {
                return Ok(None);
            };
            let mut jac = Matrix4::zeros();
            jac.fixed_view_mut::<3, 4>(0, 0).copy_from(&e.jac);
            let mut l = Linearised::new(Vector4::new(e.g.x, e.g.y, e.g.z, 0.0), jac, 0.0);
            l.residual = e.g.amax();
            Ok(Some((e, l)))
        };
        let start = eval(&w0).ok()??;
        let out = Newton::curve(self.opts.curve_tol)
            .solve(
                w0,
                row.as_slice(),
                start,
                |p| p.1,
                |_, w, _| eval(w),
                |_| false,
            )
            .ok()?;
        out.ok().map(|s| (s.w, s.point.0, s.iterations))
    }
}
