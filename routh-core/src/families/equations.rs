//! The defining equations of families of steady motions, shared by the continuation of branches
//! and the stability atlas.
//!
//! A point of a family is `(γ, s)` with γ on the unit sphere and `s` the parameter. It is a
//! steady motion when the tangential gradient of the amended potential vanishes (33):
//! `t(γ, s) = (E − γγᵀ)∇U_r = 0`, `∇U_r = −∂R/∂γ` at `Ω = 0` (errata: γ is differentiated as a free
//! vector). Near a base point `γ_b` we use the chart `γ(ξ) = (γ_b + P_b ξ)/|γ_b + P_b ξ|`,
//! `ξ ∈ ℝ²`, `P_b` an orthonormal basis of `γ_b^⊥`, and the two equations `F(ξ, s) = P_bᵀ t = 0`.
//! Their Jacobian in ξ is exact (from the model's Hessian in γ):
//! `∂t/∂γ · δγ = (E − γγᵀ)H δγ − (γ·∇U_r) δγ − γ (∇U_rᵀ δγ)`, `H = −∂²R/∂γ²`,
//! `∂γ/∂ξ = (E − γγᵀ)P_b/|γ_b + P_b ξ|`; the derivative in `s` is a central difference (the
//! family is a closure, not a formula).
//!
//! Test functions, whose zeros are the events:
//! - the eigenvalues of the restricted second variation `K = Pᵀ(μE − ∂²R/∂γ²)P` (62)–(63) (at a
//!   steady motion `∂t/∂γ` restricted to the tangent plane is exactly `K`);
//! - the discriminant of `f₂` in `λ²`, `c₂² − 4c₄c₀`, relative to `c₂² + 4|c₄c₀|` (errata E5).

use nalgebra::{Matrix2x3, Matrix3, Matrix3x2, Vector2, Vector3};

use crate::error::RouthError;
use crate::model::Routhian;
use crate::sphere::local::Local;
use crate::sphere::{sym2_eigen, tangent_basis};
use crate::stability::f2_coefficients_scaled;
use crate::validate::check_finite;

/// The family member at `s`, with errors that name `s`.
pub(crate) fn member<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: &F,
    s: f64,
) -> Result<(M, f64), RouthError> {
    let (m, p) = family(s);
    check_finite("p_psi returned by the family", &[p]).map_err(|e| at(s, e))?;
    Ok((m, p))
}

/// Wraps an error with the parameter value where it happened.
pub(crate) fn at(s: f64, e: RouthError) -> RouthError {
    match e {
        RouthError::AtParameter { .. } => e,
        e => RouthError::AtParameter {
            s,
            source: Box::new(e),
        },
    }
}

/// The chart `γ(ξ)` around `base` with basis `basis`, and `∂γ/∂ξ`.
pub(crate) fn chart(
    base: &Vector3<f64>,
    basis: &Matrix3x2<f64>,
    xi: &Vector2<f64>,
) -> (Vector3<f64>, Matrix3x2<f64>) {
    let v = base + basis * xi;
    let n = v.norm();
    let g = v / n;
    let proj = Matrix3::identity() - g * g.transpose();
    (g, proj * basis / n)
}

/// `F(ξ, s) = P_bᵀ t(γ(ξ), s)` and its Jacobian `[∂F/∂ξ | ∂F/∂s]` (2×3) in the chart around
/// `base`. `ds` is the step of the central difference in `s`.
pub(crate) struct ChartEval {
    pub gamma: Vector3<f64>,
    pub f: Vector2<f64>,
    pub jac: Matrix2x3<f64>,
    pub local: Local,
}

pub(crate) fn chart_eval<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: &F,
    base: &Vector3<f64>,
    basis: &Matrix3x2<f64>,
    xi: &Vector2<f64>,
    s: f64,
    ds: f64,
) -> Result<ChartEval, RouthError> {
    let (gamma, dg) = chart(base, basis, xi);
    let (m, p) = member(family, s)?;
    let local = Local::at(&m, &gamma, p).map_err(|e| at(s, e))?;
    let f = basis.transpose() * local.tangential();
    let jxi = basis.transpose() * local.dt_dgamma() * dg;
    let side = |s1: f64| -> Result<Vector2<f64>, RouthError> {
        let (m1, p1) = member(family, s1)?;
        let l1 = Local::at(&m1, &gamma, p1).map_err(|e| at(s1, e))?;
        Ok(basis.transpose() * l1.tangential())
    };
    let js = (side(s + ds)? - side(s - ds)?) / (2.0 * ds);
    let jac = Matrix2x3::new(
        jxi[(0, 0)],
        jxi[(0, 1)],
        js.x,
        jxi[(1, 0)],
        jxi[(1, 1)],
        js.y,
    );
    Ok(ChartEval {
        gamma,
        f,
        jac,
        local,
    })
}

/// The eigenvalues (ascending) and the eigenvector (in ℝ³, tangent) of the eigenvalue of
/// smallest magnitude of `K` at `local`.
pub(crate) fn restricted_eigen(local: &Local) -> ([f64; 2], Vector3<f64>) {
    let e = sym2_eigen(&local.restricted());
    let i = usize::from(e.values[1].abs() < e.values[0].abs());
    (e.values, tangent_basis(&local.gamma) * e.vectors[i])
}

/// The discriminant of `f₂` in `λ²`, `c₂² − 4c₄c₀`, relative to `c₂² + 4|c₄c₀|` (in `[−1, 1]`).
pub(crate) fn relative_discriminant<M: Routhian>(
    model: &M,
    gamma: &Vector3<f64>,
    p: f64,
) -> Result<f64, RouthError> {
    // The scaled coefficients have the same ratios and never overflow (p_ψ = 1e±150).
    let ([c4, c2, c0], _) = f2_coefficients_scaled(model, gamma, p)?;
    let big = c2.abs().max(c4.abs()).max(c0.abs());
    if big == 0.0 {
        return Ok(0.0);
    }
    let (c4, c2, c0) = (c4 / big, c2 / big, c0 / big);
    let scale = c2 * c2 + 4.0 * (c4 * c0).abs();
    Ok(if scale > 0.0 {
        (c2 * c2 - 4.0 * c4 * c0) / scale
    } else {
        0.0
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Lagrangian;

    /// U_r = ½p²/(γᵀJγ) + mgl γ₃ for J = diag(a, b, c), written as R by hand.
    struct Top {
        j: Vector3<f64>,
        mgl: f64,
    }
    impl Lagrangian for Top {
        fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
            0.5 * w.dot(&self.j.component_mul(w)) - self.mgl * g.z
        }
        fn dl_domega(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
            self.j.component_mul(w)
        }
        fn dl_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
            Vector3::new(0.0, 0.0, -self.mgl)
        }
        fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> {
            Matrix3::from_diagonal(&self.j)
        }
        fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
            Matrix3::zeros()
        }
    }
    impl Routhian for Top {
        fn routhian(&self, _: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
            -self.mgl * g.z - 0.5 * p * p / g.dot(&self.j.component_mul(g))
        }
        fn dr_domega(&self, _: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
            (p / g.dot(&self.j.component_mul(g))) * self.j.component_mul(g)
        }
        fn dr_dgamma(&self, _: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
            let n = g.dot(&self.j.component_mul(g));
            Vector3::new(0.0, 0.0, -self.mgl) + (p * p / (n * n)) * self.j.component_mul(g)
        }
        fn d2r_domega2(&self, _: &Vector3<f64>, _: &Vector3<f64>, _: f64) -> Matrix3<f64> {
            Matrix3::zeros()
        }
        fn d2r_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>, _: f64) -> Matrix3<f64> {
            Matrix3::zeros()
        }
        fn d2r_dgamma2(&self, _: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
            let n = g.dot(&self.j.component_mul(g));
            let jg = self.j.component_mul(g);
            (p * p / (n * n)) * Matrix3::from_diagonal(&self.j)
                - (4.0 * p * p / (n * n * n)) * jg * jg.transpose()
        }
    }

    #[test]
    fn chart_jacobian_matches_finite_differences() {
        let family = |s: f64| {
            (
                Top {
                    j: Vector3::new(1.0, 1.3, 1.7),
                    mgl: s,
                },
                2.0,
            )
        };
        let base = Vector3::new(0.3, -0.4, 0.8).normalize();
        let basis = tangent_basis(&base);
        let xi = Vector2::new(0.05, -0.02);
        let e = chart_eval(&family, &base, &basis, &xi, 0.9, 1e-5).unwrap();
        let h = 1e-6;
        for k in 0..3 {
            let (mut xp, mut xm, mut sp, mut sm) = (xi, xi, 0.9, 0.9);
            if k < 2 {
                xp[k] += h;
                xm[k] -= h;
            } else {
                sp += h;
                sm -= h;
            }
            let fp = chart_eval(&family, &base, &basis, &xp, sp, 1e-5).unwrap().f;
            let fm = chart_eval(&family, &base, &basis, &xm, sm, 1e-5).unwrap().f;
            let fd = (fp - fm) / (2.0 * h);
            for i in 0..2 {
                assert!(
                    (fd[i] - e.jac[(i, k)]).abs() < 1e-7,
                    "∂F{i}/∂x{k}: fd {} vs {}",
                    fd[i],
                    e.jac[(i, k)]
                );
            }
        }
    }

    #[test]
    fn restricted_form_is_the_tangent_jacobian_at_a_critical_point() {
        // γ = e₃ is critical for every p; K must equal P_bᵀ ∂t/∂γ P_b there.
        let top = Top {
            j: Vector3::new(1.0, 1.3, 1.7),
            mgl: 1.0,
        };
        let l = Local::at(&top, &Vector3::z(), 2.5).unwrap();
        let p = tangent_basis(&Vector3::z());
        let k = p.transpose() * l.dt_dgamma() * p;
        assert!((k - l.restricted()).norm() < 1e-12 * l.restricted().norm());
    }
}
