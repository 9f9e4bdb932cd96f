//! A rigid body in an ideal fluid (paper Example 3), brought to the form (8) of this crate.
//!
//! Kirchhoff's equations (52) for a body in an unbounded ideal fluid at rest at infinity, with
//! no external forces, are written for the angular velocity ω and the linear velocity v of a
//! body point with the kinetic energy (53) of body and fluid,
//!
//! ```text
//! T(ω, v) = ½((aω, ω) + 2(bω, v) + (cv, v)),     p = ∂T/∂v = bω + cv   (57).
//! ```
//!
//! The impulse `p` is constant in space, so in the body frame `ṗ = p × ω` and `|p| = k` (56).
//! The partial Legendre transform in v, with the missing `−(p, v)` of (59) restored (errata E3),
//!
//! ```text
//! L(ω, p) = T − (p, v) = ½((Aω, ω) + 2(Bω, p) + (Cp, p)),   A = a − bᵀc⁻¹b,  B = c⁻¹b,  C = −c⁻¹,
//! ```
//!
//! and the substitution `p = kγ` (61) give a Lagrangian of the form this crate handles, with γ
//! the body-frame unit vector along the impulse (the role the vertical plays elsewhere):
//!
//! ```text
//! L(ω, γ) = ½(Aω, ω) + k(bᵀc⁻¹γ, ω) − ½k²(c⁻¹γ, γ),
//! ```
//!
//! i.e. kinetic matrix `A`, gyroscopic (linear) term `(Λγ, ω)` with `Λ = k bᵀc⁻¹`, and potential
//! `U(γ) = ½(Πγ, γ)` with `Π = k²c⁻¹` (`L` contains `−U`). The equations (8) with this `L` are
//! Kirchhoff's equations (52): `∂L/∂ω = aω + bᵀv = ∂T/∂ω` and `∂L/∂γ × γ = −kv × γ = p × v`.
//!
//! The cyclic momentum (9) of this `L`, `p_ψ = (∂L/∂ω, γ) = (∂T/∂ω, p)/k`, is **not** the
//! constant written `p_ψ` in (55): that one is `(∂T/∂ω, ∂T/∂v) = k·p_ψ` (errata E7). See
//! [`FluidParameters::kirchhoff_constant`].
//!
//! ```
//! use routh_core::fluid::kirchhoff_lagrangian;
//! use routh_core::{Matrix3, Vector3};
//!
//! let a = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.4));
//! let b = Matrix3::new(0.1, 0.0, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.2);
//! let c = Matrix3::from_diagonal(&Vector3::new(3.0, 3.0, 1.5));
//! let f = kirchhoff_lagrangian(a, b, c, 2.0)?;
//! let c_inv = c.try_inverse().unwrap();
//! assert!((f.kinetic - (a - b.transpose() * c_inv * b)).norm() < 1e-12);
//! assert!((f.linear - 2.0 * b.transpose() * c_inv).norm() < 1e-12);
//! assert!((f.potential - 4.0 * c_inv).norm() < 1e-12);
//!
//! // L(ω, γ) = T(ω, v) − (p, v) with p = kγ and v = c⁻¹(p − bω) (58).
//! let (w, g) = (Vector3::new(0.3, -0.2, 0.5), Vector3::new(0.6, 0.0, 0.8));
//! let v = f.velocity(&w, &g);
//! let t = 0.5 * (w.dot(&(a * w)) + 2.0 * v.dot(&(b * w)) + v.dot(&(c * v)));
//! assert!((f.lagrangian(&w, &g) - (t - 2.0 * g.dot(&v))).abs() < 1e-12);
//! # Ok::<(), routh_core::RouthError>(())
//! ```

use crate::error::RouthError;
use nalgebra::{Matrix3, SymmetricEigen, Vector3};

/// The matrices of the Lagrangian `L(ω, γ) = ½(Aω, ω) + (Λγ, ω) − ½(Πγ, γ)` of a body in an
/// ideal fluid with impulse of magnitude `k` (errata E3; see the [module documentation](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct FluidParameters {
    /// `A = a − bᵀc⁻¹b`: the kinetic matrix, `½(Aω, ω)` (symmetric positive definite).
    pub kinetic: Matrix3<f64>,
    /// `Λ = k bᵀc⁻¹`: the linear (gyroscopic) term is `(Λγ, ω) = k (bᵀc⁻¹γ)·ω`.
    pub linear: Matrix3<f64>,
    /// `Π = k² c⁻¹`: the potential is `U(γ) = ½(Πγ, γ) = ½k²(c⁻¹γ, γ)`, and `L` contains `−U`.
    pub potential: Matrix3<f64>,
    /// The magnitude `k = |p| > 0` of the impulse (56).
    pub k: f64,
    /// The coupling matrix `b` of (53), kept to reconstruct the linear velocity.
    pub b: Matrix3<f64>,
    /// `c⁻¹`, kept to reconstruct the linear velocity.
    pub c_inv: Matrix3<f64>,
}

impl FluidParameters {
    /// The body-frame linear velocity (58), `v = c⁻¹(kγ − bω)`, of the state `(ω, γ)`.
    pub fn velocity(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector3<f64> {
        self.c_inv * (self.k * gamma - self.b * omega)
    }

    /// The body-frame impulse `p = kγ` (61).
    pub fn impulse(&self, gamma: &Vector3<f64>) -> Vector3<f64> {
        self.k * gamma
    }

    /// `L(ω, γ) = ½(Aω, ω) + (Λγ, ω) − ½(Πγ, γ)`.
    pub fn lagrangian(&self, omega: &Vector3<f64>, gamma: &Vector3<f64>) -> f64 {
        0.5 * omega.dot(&(self.kinetic * omega)) + (self.linear * gamma).dot(omega)
            - 0.5 * gamma.dot(&(self.potential * gamma))
    }

    /// Kirchhoff's constant (55), `(∂T/∂ω, ∂T/∂v) = k·p_ψ`, from the cyclic momentum
    /// `p_ψ = (∂L/∂ω, γ)` (9) of the reduced Lagrangian (errata E7: keep the two apart).
    pub fn kirchhoff_constant(&self, p_psi: f64) -> f64 {
        self.k * p_psi
    }

    /// The cyclic momentum (9) of the reduced Lagrangian from Kirchhoff's constant (55).
    pub fn p_psi_from_kirchhoff(&self, kirchhoff_constant: f64) -> f64 {
        kirchhoff_constant / self.k
    }
}

/// The rejection of the input `what` for `reason`.
fn invalid(what: &'static str, reason: String) -> RouthError {
    RouthError::InvalidModel { what, reason }
}

/// Relative asymmetry above which `a` or `c` is rejected.
const SYMMETRY_TOL: f64 = 1e-12;

fn check_symmetric(what: &'static str, m: &Matrix3<f64>) -> Result<(), RouthError> {
    let norm = m.norm();
    let asymmetry = if norm > 0.0 {
        (m - m.transpose()).norm() / norm
    } else {
        0.0
    };
    if asymmetry > SYMMETRY_TOL {
        return Err(invalid(
            what,
            format!("{what} is not symmetric (relative asymmetry {asymmetry:e})"),
        ));
    }
    Ok(())
}

fn not_positive_definite(what: &'static str, min_eigenvalue: f64) -> RouthError {
    invalid(
        what,
        format!("{what} is not positive definite (smallest eigenvalue {min_eigenvalue:e})"),
    )
}

fn check_positive_definite(what: &'static str, m: &Matrix3<f64>) -> Result<(), RouthError> {
    let min_eigenvalue = SymmetricEigen::new(*m).eigenvalues.min();
    // Relative to the largest entry, so that round-off cannot pass off a singular form.
    if min_eigenvalue.is_nan() || min_eigenvalue <= 1e-14 * m.amax() {
        return Err(not_positive_definite(what, min_eigenvalue));
    }
    Ok(())
}

/// The Lagrangian of a body in an ideal fluid with impulse magnitude `k`, in the form (8) of this
/// crate (errata E3): from the matrices `a`, `b`, `c` of the kinetic energy (53),
/// `T = ½((aω, ω) + 2(bω, v) + (cv, v))`, returns `A = a − bᵀc⁻¹b` (kinetic), `Λ = k bᵀc⁻¹`
/// (linear term `(Λγ, ω)`) and `Π = k²c⁻¹` (potential `½(Πγ, γ)`).
///
/// Declare a model with these as fields, e.g.
/// `kinetic = 0.5 * omega.dot(a_kin * omega), linear = (lin * gamma).dot(omega),
/// potential = 0.5 * gamma.dot(pot * gamma)`.
///
/// Errors: [`RouthError::NonFinite`] for a non-finite entry; [`RouthError::InvalidModel`] naming
/// the input for `a` or `c` not symmetric (relative tolerance `1e−12`), `c` or the kinetic form
/// `T` not positive definite (checked as `c > 0` and `A > 0`, its Schur complement), `k ≤ 0`.
pub fn kirchhoff_lagrangian(
    a: Matrix3<f64>,
    b: Matrix3<f64>,
    c: Matrix3<f64>,
    k: f64,
) -> Result<FluidParameters, RouthError> {
    for (what, m) in [("a", &a), ("b", &b), ("c", &c)] {
        if let Some(&value) = m.iter().find(|x| !x.is_finite()) {
            return Err(RouthError::NonFinite { what, value });
        }
    }
    if !k.is_finite() {
        return Err(RouthError::NonFinite {
            what: "k",
            value: k,
        });
    }
    if k <= 0.0 {
        return Err(invalid(
            "k",
            format!("the impulse magnitude k = {k} must be positive (56)"),
        ));
    }
    check_symmetric("a", &a)?;
    check_symmetric("c", &c)?;
    check_positive_definite("c", &c)?;
    let c_inv = c
        .cholesky()
        .map(|ch| ch.inverse())
        .ok_or_else(|| not_positive_definite("c", SymmetricEigen::new(c).eigenvalues.min()))?;
    let c_inv = 0.5 * (c_inv + c_inv.transpose());
    let kinetic = a - b.transpose() * c_inv * b;
    let kinetic = 0.5 * (kinetic + kinetic.transpose());
    check_positive_definite("the kinetic form T (A = a − bᵀc⁻¹b)", &kinetic)?;
    Ok(FluidParameters {
        kinetic,
        linear: k * b.transpose() * c_inv,
        potential: k * k * c_inv,
        k,
        b,
        c_inv,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_input() {
        let id = Matrix3::identity();
        let invalid = |r: Result<FluidParameters, RouthError>, input: &str, why: &str| match r {
            Err(RouthError::InvalidModel { what, reason }) => what == input && reason.contains(why),
            _ => false,
        };
        assert!(invalid(
            kirchhoff_lagrangian(id, id * 0.1, id, 0.0),
            "k",
            "must be positive"
        ));
        assert!(matches!(
            kirchhoff_lagrangian(id, id * f64::NAN, id, 1.0),
            Err(RouthError::NonFinite { what: "b", value }) if value.is_nan()
        ));
        let skew = Matrix3::new(1.0, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert!(invalid(
            kirchhoff_lagrangian(skew, id, id, 1.0),
            "a",
            "not symmetric"
        ));
        assert!(invalid(
            kirchhoff_lagrangian(id, id * 0.1, -id, 1.0),
            "c",
            "not positive definite"
        ));
        // b too strong: T is indefinite although a and c are positive definite.
        assert!(matches!(
            kirchhoff_lagrangian(id, id * 2.0, id, 1.0),
            Err(RouthError::InvalidModel { reason, .. }) if reason.contains("not positive definite")
        ));
    }
}
