//! The identities that every Routh function satisfies whatever the model: Theorem 2 ((16),
//! (17)), the cyclic momentum (12) and errata E4, E6. Shared by the checks of the num-dual twins
//! (this crate's unit tests) and of the generated code (`tests/routh_identities.rs`).

use nalgebra::Vector3;
use routh_core::Routhian;

/// One identity at one point: `residual ≤ tol · scale` is expected with `tol` of the order of
/// the rounding error.
#[derive(Debug, Clone, Copy)]
pub struct Identity {
    /// The identity, as equation number and formula.
    pub name: &'static str,
    /// `max |lhs − rhs|` over the components.
    pub residual: f64,
    /// `1 + max |rhs|`, or the size of the terms where the rhs is zero.
    pub scale: f64,
}

impl Identity {
    /// Panics with the identity's name unless `residual ≤ tol · scale`.
    pub fn assert_within(&self, tol: f64) {
        assert!(
            self.residual <= tol * self.scale,
            "{}: residual {:e} > {tol:e} × {:e}",
            self.name,
            self.residual,
            self.scale
        );
    }
}

/// The identities of Theorem 2 and errata E4, E6 at `(Ω, γ, p_ψ)` (γ need not be unit).
pub fn reduction_identities<M: Routhian + ?Sized>(
    model: &M,
    w: &Vector3<f64>,
    g: &Vector3<f64>,
    p: f64,
) -> Vec<Identity> {
    let b = model.bundle(w, g, p);
    let omega = w + b.psi_dot * g;
    let energy = model.energy(&omega, g);
    let s = 0.37;
    let gauge = b.routhian + s * p;
    let scalar = |name, lhs: f64, rhs: f64| Identity {
        name,
        residual: (lhs - rhs).abs(),
        scale: 1.0 + rhs.abs(),
    };
    vec![
        scalar("(17) (∂R/∂Ω, γ) = p_ψ", b.dr_domega.dot(g), p),
        scalar(
            "(12) p_ψ of (9) at ω = Ω + ψ̇γ",
            model.cyclic_momentum(&omega, g),
            p,
        ),
        scalar(
            "(16) E' = (∂R/∂Ω, Ω) − R = E",
            b.dr_domega.dot(w) - b.routhian,
            energy,
        ),
        Identity {
            name: "E6 (∂²R/∂Ω∂γ)ᵀγ = −∂R/∂Ω",
            residual: (b.d2r_domega_dgamma.transpose() * g + b.dr_domega).amax(),
            scale: 1.0 + b.dr_domega.amax(),
        },
        Identity {
            name: "E4 ∂²R/∂Ω² γ = 0",
            residual: (b.d2r_domega2 * g).amax(),
            scale: 1.0 + b.d2r_domega2.amax(),
        },
        scalar(
            "E4 gauge R(Ω + sγ) = R(Ω) + s p_ψ",
            model.routhian(&(w + s * g), g, p),
            gauge,
        ),
    ]
}
