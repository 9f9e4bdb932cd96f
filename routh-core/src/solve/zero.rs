//! The one zero test of routh-core (docs/method.md §5): whether an eigenvalue of the restricted
//! second variation `K` (62)–(63), a tangential gradient (33) or a determinant is zero, decided
//! relative to a *local tangential scale* — never against an absolute number.
//!
//! Two transformations must change no verdict and no count (README, "What is guaranteed"):
//!
//! - multiplying the Lagrangian by a constant `c` (`J → cJ`, `a → c·a`, `U → cU`, with
//!   `p_ψ → c·p_ψ`), which multiplies `R(0, γ, p_ψ)` and all its derivatives by `c`;
//! - adding `k|γ|²` to `U`, a constant on the sphere, which adds the radial vector `−2kγ` to
//!   `∂R/∂γ` and `−2kE` to `∂²R/∂γ²`, so `μ = (∂R/∂γ, γ)` by `−2k`.
//!
//! Every scale here is linear under the first and invariant under the second: the tangential
//! gradient `g`, `K = Pᵀ(μE − ∂²R/∂γ²)P`, and [`tangential_scale`], the size of the whole
//! matrix `∂²R/∂γ² − μE` (of which `−K` is the tangential block), which does not vanish at a
//! degenerate critical point where `K` does. Round-off floors, on the other hand, are relative
//! to the *raw* derivatives (the size of the terms whose difference is computed), as in
//! [`crate::sphere::Tangential`].
//!
//! Users: the search's [`Tangential::zero_tol`](crate::sphere::Tangential) (relative to `‖K‖`,
//! floored at round-off), the defining equations of families (`families/equations.rs`: the
//! residual scale of the corrector and the atlas's test functions) and the diagram's tests of
//! `Node::eig` (eigenvalues of `K` divided by the tangential scale at the start of their branch).

use nalgebra::{Matrix3, Vector3};

use crate::solve::norm::stable_norm;

/// A threshold: a quantity is zero when its modulus is at most [`ZeroTest::tol`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ZeroTest {
    /// `max(rel · scale, floor)`.
    pub tol: f64,
}

impl ZeroTest {
    /// Zero relative to `scale`: `|x| ≤ rel · scale`.
    #[inline(always)]
    pub(crate) fn relative(rel: f64, scale: f64) -> Self {
        ZeroTest { tol: rel * scale }
    }

    /// Zero relative to `scale`, never below the round-off `floor`: `|x| ≤ max(rel · scale,
    /// floor)`.
    #[inline(always)]
    pub(crate) fn with_floor(rel: f64, scale: f64, floor: f64) -> Self {
        ZeroTest {
            tol: (rel * scale).max(floor),
        }
    }

    /// Whether `x` is zero.
    #[inline(always)]
    pub(crate) fn is_zero(&self, x: f64) -> bool {
        x.abs() <= self.tol
    }

    /// How many of `xs` are zero.
    #[inline(always)]
    pub(crate) fn count(&self, xs: &[f64]) -> usize {
        xs.iter().filter(|&&x| self.is_zero(x)).count()
    }
}

/// An eigenvalue of `K` relative to the tangential scale of its branch is zero below this in a
/// bifurcation diagram (a point of a circle of steady motions, a degenerate seed).
pub(crate) const EIGEN_REL: f64 = 1e-6;

/// Both eigenvalues of `K` below this relative to the branch's scale: a double zero (a symmetric
/// body where a circle of steady motions is born), which makes a zero of `K` a branch point.
pub(crate) const DOUBLE_REL: f64 = 1e-8;

/// Both eigenvalues of `K` below this relative to the branch's scale, next to the axis of a
/// branch of circles (where the circles shrink to the pole).
pub(crate) const AXIS_REL: f64 = 1e-5;

/// The local tangential scale of the amended potential at a unit γ, from `∇U_r = −∂R/∂γ` and
/// `H = −∂²R/∂γ²` (both at `Ω = 0`): `max(|(E − γγᵀ)∇U_r|, ‖H − (γ·∇U_r)E‖_F)`.
///
/// `H − (γ·∇U_r)E = −(∂²R/∂γ² − μE)`: its tangential block is `K` (62)–(63); unlike `‖H‖` it is
/// unchanged by adding `k|γ|²` to `U` and, unlike `‖K‖`, it does not vanish where `K` does (a
/// branch point, the birth of a circle). Both terms scale linearly with the Lagrangian. Zero
/// only where the second derivatives are a multiple of `E` (a potential constant on the sphere)
/// and the gradient is radial.
pub(crate) fn tangential_scale(
    gamma: &Vector3<f64>,
    grad: &Vector3<f64>,
    hess: &Matrix3<f64>,
) -> f64 {
    let radial = gamma.dot(grad);
    let t = grad - gamma * radial;
    let shifted = hess - Matrix3::from_diagonal_element(radial);
    // The derivatives are finite (checked by the callers); `stable_norm` neither over- nor
    // underflows (p_ψ = 1e±150).
    stable_norm(t.as_slice()).max(stable_norm(shifted.as_slice()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `U_r = ½γᵀAγ + b·γ` plus `k|γ|²`, scaled by `c`: the scale is `c` times that of the
    /// unshifted, unscaled potential, and vanishes for a constant on the sphere.
    #[test]
    fn tangential_scale_is_invariant_under_a_shift_and_linear_in_units() {
        let a = Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.0, 0.4, -0.1, 0.4, -0.5);
        let b = Vector3::new(0.2, -0.7, 0.4);
        let g = Vector3::new(0.3, -0.5, 0.8).normalize();
        let at = |c: f64, k: f64| {
            let grad = c * (a * g + b) + 2.0 * k * g;
            let hess = c * a + Matrix3::from_diagonal_element(2.0 * k);
            tangential_scale(&g, &grad, &hess)
        };
        let base = at(1.0, 0.0);
        assert!(base > 0.1, "{base}");
        for (c, k) in [(1.0, 1e6), (1e-3, -1e3), (1e3, 7.0), (1.0, -1e9)] {
            let s = at(c, k);
            let want = c * base;
            // The shift cancels up to round-off of its own size, 2|k|·ε·(a few).
            assert!(
                (s - want).abs() <= 1e-12 * want + 1e-14 * k.abs(),
                "c = {c}, k = {k}: {s} vs {want}"
            );
        }
        // A constant on the sphere: U = k|γ|² alone.
        let k = 3.0;
        let flat = tangential_scale(&g, &(2.0 * k * g), &Matrix3::from_diagonal_element(2.0 * k));
        assert!(flat <= 1e-14, "{flat}");
    }

    #[test]
    fn thresholds() {
        let z = ZeroTest::with_floor(1e-6, 2.0, 1e-3);
        assert!(z.is_zero(-1e-3) && !z.is_zero(1.1e-3));
        assert_eq!(ZeroTest::relative(1e-6, 2.0).count(&[1e-6, -2e-6, 3e-6]), 2);
    }
}
