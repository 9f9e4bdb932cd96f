//! Geometry of the unit sphere of verticals γ: a tangent basis of γ^⊥ (63), the restricted
//! second variation (62)–(63), the closed-form 2×2 symmetric eigen-decomposition, the local scale
//! of the amended potential and a Fibonacci grid of starting points. The Newton corrector on the
//! sphere is an engine of its own, [`crate::solve::newton`].

pub(crate) mod local;

use crate::solve::norm::stable_norm;
use crate::solve::zero::ZeroTest;
use std::borrow::Cow;
use std::sync::OnceLock;

use nalgebra::{Matrix2, Matrix3, Matrix3x2, Vector2, Vector3};

/// A 3×2 orthonormal basis `P = [u v]` of γ^⊥ with `(u, v, γ)` right-handed; γ must be a unit
/// vector.
pub(crate) fn tangent_basis(gamma: &Vector3<f64>) -> Matrix3x2<f64> {
    let a = gamma.abs();
    let e = if a.x <= a.y && a.x <= a.z {
        Vector3::x()
    } else if a.y <= a.z {
        Vector3::y()
    } else {
        Vector3::z()
    };
    let u = (e - e.dot(gamma) * gamma).normalize();
    let v = gamma.cross(&u);
    Matrix3x2::from_columns(&[u, v])
}

/// Round-off floor, relative to the raw scale `max(|∂R/∂γ|, ‖∂²R/∂γ²‖_F)`, under which the
/// tangential quantities `g` and `K` are indistinguishable from zero. They are differences of
/// terms of the raw size (the radial parts cancel exactly in `K`, not in floating point), so their
/// round-off is a few `ε` of it; `1024 ε ≈ 2.3e−13` leaves a wide margin for round-off inside the
/// model.
pub(crate) const ROUND: f64 = 1024.0 * f64::EPSILON;

/// The realistic round-off of the tangential gradient relative to `|∂R/∂γ|` (a few ulps), used
/// to estimate how precisely a converged critical point is located.
pub(crate) const NOISE: f64 = 16.0 * f64::EPSILON;

/// The tangential (Riemannian) quantities of the amended potential `U_r = −R(0, γ, p_ψ)` at a
/// unit γ, with the scales the tests of the search and of `classify` are relative to.
///
/// Everything here except the round-off floors is invariant under adding `c|γ|²` to `U` (which
/// changes `∂R/∂γ` by a radial vector and `∂²R/∂γ²` by `2cE`, and `μE − ∂²R/∂γ²` not at all) and
/// scales linearly when the model is multiplied by a constant.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tangential {
    /// `P`: orthonormal basis of γ^⊥.
    pub basis: Matrix3x2<f64>,
    /// Riemannian gradient `Pᵀ(−∂R/∂γ)` of `U_r`.
    pub grad: Vector2<f64>,
    /// `|g|`.
    pub grad_norm: f64,
    /// Eigenvalues (ascending) of the restricted second variation `K = Pᵀ(μE − ∂²R/∂γ²)P`
    /// (62)–(63).
    pub values: [f64; 2],
    /// Orthonormal eigenvectors of `K`.
    pub vectors: [Vector2<f64>; 2],
    /// `‖K‖_F`: the scale of the restricted form itself.
    pub knorm: f64,
    /// `|∂R/∂γ|` (radial part included): the size of the terms whose difference is `g`.
    pub raw_grad: f64,
    /// `max(|∂R/∂γ|, ‖∂²R/∂γ²‖_F)`: the size of the terms whose difference is `K`.
    pub raw: f64,
    /// The threshold under which an eigenvalue of `K` is zero: `rel · ‖K‖_F` (`rel` the relative
    /// zero-eigenvalue tolerance), never below the round-off floor [`ROUND`]` ·
    /// max(|μ|, ‖PᵀHP‖_F, 64ε‖H‖_F)` — the size of the terms `K = μE − PᵀHP` is the difference
    /// of (H = ∂²R/∂γ²).
    pub zero_tol: f64,
    /// The Newton step `−K⁻¹g` in the tangent plane (radians), with the eigenvalues of `K` below
    /// `zero_tol` replaced by that threshold (and a component of `g` within round-off along them
    /// dropped): an estimate of the distance to the nearest critical point that is never small
    /// where `g` is not zero but `K` is (a flat region).
    pub step: Vector2<f64>,
    /// `|step|` (`+∞` if it is not finite).
    pub step_len: f64,
    /// The residual of (33) as a distance on the sphere: 0 when `|g|` is within round-off
    /// ([`Self::grad_floor`]), otherwise the smaller of `step_len` and the second-order estimate
    /// `√(2|g|/raw)` (which matters only at degenerate points, where `K` vanishes). Invariant
    /// under multiplying the model by a constant; `step_len` is also invariant under adding
    /// `c|γ|²` to `U`.
    pub residual: f64,
}

impl Tangential {
    /// The tangential quantities at the unit vector γ; `rel` is the relative tolerance for a zero
    /// eigenvalue of `K`.
    #[inline(always)]
    pub(crate) fn new(
        gamma: &Vector3<f64>,
        dr_dgamma: &Vector3<f64>,
        d2r_dgamma2: &Matrix3<f64>,
        rel: f64,
    ) -> Self {
        Self::with_basis(gamma, tangent_basis(gamma), dr_dgamma, d2r_dgamma2, rel)
    }

    /// [`Self::new`] with the basis `tangent_basis(gamma)` computed by the caller (before the
    /// model is evaluated, so that its square root and divisions overlap with the model).
    #[inline(always)]
    pub(crate) fn with_basis(
        gamma: &Vector3<f64>,
        basis: Matrix3x2<f64>,
        dr_dgamma: &Vector3<f64>,
        d2r_dgamma2: &Matrix3<f64>,
        rel: f64,
    ) -> Self {
        let mu = dr_dgamma.dot(gamma);
        let (hess, pth) = restricted_parts(&basis, mu, d2r_dgamma2);
        let e = sym2_eigen(&hess);
        let raw_grad = norm3(dr_dgamma.x, dr_dgamma.y, dr_dgamma.z);
        let h2: f64 = d2r_dgamma2.iter().map(|x| x * x).sum();
        let k2 = hess[(0, 0)].powi(2) + 2.0 * hess[(0, 1)].powi(2) + hess[(1, 1)].powi(2);
        let (hnorm, knorm) = if h2.is_normal() || h2 == 0.0 {
            (h2.sqrt(), k2.sqrt())
        } else {
            // Entries beyond 1e154 (p_ψ = 1e150 in units of the inertia) or below 1e−154.
            (
                stable_norm(d2r_dgamma2.as_slice()),
                stable_norm(hess.as_slice()),
            )
        };
        let raw = raw_grad.max(hnorm);
        let (u, v) = (basis.column(0), basis.column(1));
        let grad = Vector2::new(-u.dot(dr_dgamma), -v.dot(dr_dgamma));
        let grad_norm = norm3(grad.x, grad.y, 0.0);
        // The round-off of K = μE − PᵀHP is a few ulps of the two terms it is the difference
        // of (with c|γ|² added to U both carry 2c, and so does the floor), plus the error of the
        // basis P (orthonormal to γ within ε) times H: not the radial part of H, which K never
        // sees — at a higher-order point with a large radial Hessian (U = (1 + γ₃)² at −e₃) a
        // floor of ε‖H‖ would call K = 0 long before the point is reached.
        let pth = pth.unwrap_or_else(|| hnorm_tangential(&basis, d2r_dgamma2));
        let k_terms = mu.abs().max(pth).max(64.0 * f64::EPSILON * hnorm);
        let zero_tol = ZeroTest::with_floor(rel, knorm, ROUND * k_terms).tol;
        let gf = ROUND * raw_grad;
        let mut step = Vector2::zeros();
        for i in 0..2 {
            let v = e.vectors[i];
            let gi = grad.dot(&v);
            let k = e.values[i];
            let c = if k.abs() > zero_tol {
                -gi / k
            } else if gi.abs() <= gf {
                0.0
            } else if zero_tol > 0.0 {
                -gi / zero_tol
            } else {
                // K = 0 and ∂R/∂γ = 0 exactly, but g ≠ 0: cannot happen (|g| ≤ |∂R/∂γ|).
                f64::INFINITY
            };
            step += c * v;
        }
        let step_len = match step.norm() {
            l if l.is_finite() => l,
            _ => f64::INFINITY,
        };
        // At a degenerate critical point (K → 0, e.g. a branch point located exactly) the
        // Newton step overestimates the distance: there |g| grows quadratically with it, with a
        // coefficient of the size of the third derivatives, bounded by `raw`. The smaller of the
        // two estimates is the distance.
        let quadratic = if raw > 0.0 {
            (2.0 * grad_norm / raw).sqrt()
        } else {
            f64::INFINITY
        };
        let residual = if grad_norm <= gf {
            0.0
        } else {
            step_len.min(quadratic)
        };
        Tangential {
            basis,
            grad,
            grad_norm,
            values: e.values,
            vectors: e.vectors,
            knorm,
            raw_grad,
            raw,
            zero_tol,
            step,
            step_len,
            residual,
        }
    }

    /// The threshold under which the gradient is zero within round-off: [`ROUND`]` · |∂R/∂γ|`.
    pub(crate) fn grad_floor(&self) -> f64 {
        ROUND * self.raw_grad
    }

    /// Number of eigenvalues of `K` that are zero within [`Self::zero_tol`].
    pub(crate) fn zero_count(&self) -> usize {
        self.zero_test().count(&self.values)
    }

    /// The zero test of the eigenvalues of `K`: `|k| ≤` [`Self::zero_tol`].
    #[inline(always)]
    pub(crate) fn zero_test(&self) -> ZeroTest {
        ZeroTest { tol: self.zero_tol }
    }
}

/// `‖PᵀHP‖_F`, the tangential block of a symmetric 3×3 `H`, without overflow.
fn hnorm_tangential(basis: &Matrix3x2<f64>, h: &Matrix3<f64>) -> f64 {
    let scale = h.amax();
    if scale == 0.0 || !scale.is_finite() {
        return scale;
    }
    let t = basis.transpose() * (h / scale) * basis;
    scale * t.norm()
}

/// `|(x, y, z)|` without the cost of scaling when no overflow or underflow is possible.
#[inline]
fn norm3(x: f64, y: f64, z: f64) -> f64 {
    let s = x * x + y * y + z * z;
    if s.is_normal() || s == 0.0 && x == 0.0 && y == 0.0 && z == 0.0 {
        s.sqrt()
    } else {
        stable_norm(&[x, y, z])
    }
}

/// `|v|` of a 2-vector: the same value as [`stable_norm`], without its loop when `|v|²` is a
/// normal number.
#[inline]
fn norm2(v: &Vector2<f64>) -> f64 {
    let s = v.x * v.x + v.y * v.y;
    if s.is_normal() {
        s.sqrt()
    } else {
        stable_norm(v.as_slice())
    }
}

/// The restricted second variation `Pᵀ(μE − ∂²R/∂γ²)P` (62)–(63), symmetrised.
pub(crate) fn restricted_hessian(
    p: &Matrix3x2<f64>,
    mu: f64,
    d2r_dgamma2: &Matrix3<f64>,
) -> Matrix2<f64> {
    restricted_parts(p, mu, d2r_dgamma2).0
}

/// [`restricted_hessian`] and `‖PᵀHP‖_F` (`H = ∂²R/∂γ²`) from the same products, the norm `None`
/// when its sum of squares is not a normal number (then [`hnorm_tangential`] scales).
#[inline]
fn restricted_parts(
    p: &Matrix3x2<f64>,
    mu: f64,
    d2r_dgamma2: &Matrix3<f64>,
) -> (Matrix2<f64>, Option<f64>) {
    // Written out (no 3×3 temporaries): K_ij = μ δ_ij − p_iᵀ H p_j, symmetrised.
    let u = Vector3::new(p[(0, 0)], p[(1, 0)], p[(2, 0)]);
    let v = Vector3::new(p[(0, 1)], p[(1, 1)], p[(2, 1)]);
    let hu = d2r_dgamma2 * u;
    let hv = d2r_dgamma2 * v;
    let (uhu, uhv, vhu, vhv) = (u.dot(&hu), u.dot(&hv), v.dot(&hu), v.dot(&hv));
    let k01 = -0.5 * (uhv + vhu);
    let k = Matrix2::new(mu - uhu, k01, k01, mu - vhv);
    let s = uhu * uhu + uhv * uhv + vhu * vhu + vhv * vhv;
    let zero = uhu == 0.0 && uhv == 0.0 && vhu == 0.0 && vhv == 0.0;
    (k, (s.is_normal() || zero).then(|| s.sqrt()))
}

/// Eigen-decomposition of a symmetric 2×2 matrix, eigenvalues ascending.
pub(crate) struct Eigen2 {
    pub values: [f64; 2],
    pub vectors: [Vector2<f64>; 2],
}

/// Closed-form eigen-decomposition of the symmetric 2×2 matrix `k` (reads the upper triangle).
#[inline(always)]
pub(crate) fn sym2_eigen(k: &Matrix2<f64>) -> Eigen2 {
    let (a, b, c) = (k[(0, 0)], k[(0, 1)], k[(1, 1)]);
    let m = 0.5 * (a + c);
    let h = 0.5 * (a - c);
    let d2 = h * h + b * b;
    let d = if d2.is_normal() || (h == 0.0 && b == 0.0) {
        d2.sqrt()
    } else {
        h.hypot(b)
    };
    // The eigenvalue of larger magnitude by the direct formula, the other from the determinant
    // when that avoids cancellation.
    let (lo, hi) = if d == 0.0 {
        (m, m)
    } else {
        let big = if m >= 0.0 { m + d } else { m - d };
        let det = a * c - b * b;
        let small = if big == 0.0 {
            m - d
        } else if det.is_finite() {
            det / big
        } else {
            // Entries beyond 1e154: divide first.
            (a / big) * c - (b / big) * b
        };
        if m >= 0.0 {
            (small, big)
        } else {
            (big, small)
        }
    };
    let vec_for = |lam: f64| {
        let v1 = Vector2::new(b, lam - a);
        let v2 = Vector2::new(lam - c, b);
        let (n1, n2) = (norm2(&v1), norm2(&v2));
        let (v, n) = if n1 >= n2 { (v1, n1) } else { (v2, n2) };
        if n > 0.0 && n.is_finite() {
            v / n
        } else {
            Vector2::new(1.0, 0.0)
        }
    };
    let v_lo = if d == 0.0 {
        Vector2::new(1.0, 0.0)
    } else {
        vec_for(lo)
    };
    let v_hi = Vector2::new(-v_lo.y, v_lo.x);
    Eigen2 {
        values: [lo, hi],
        vectors: [v_lo, v_hi],
    }
}

/// `n` points of the Fibonacci (golden-angle) lattice on the unit sphere.
pub(crate) fn fibonacci_sphere(n: usize) -> Vec<Vector3<f64>> {
    let golden = std::f64::consts::PI * (3.0 - 5.0f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / n as f64;
            let r = (1.0 - z * z).max(0.0).sqrt();
            let phi = golden * i as f64;
            Vector3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
}

/// The default number of starts of the search of steady motions (`SearchOptions::starts`),
/// the size of the grid [`fibonacci_grid`] caches.
pub(crate) const DEFAULT_STARTS: usize = 400;

/// [`fibonacci_sphere`]`(n)`; the grids of the default search of steady motions and of its
/// refinement (4 times finer) are computed once per process.
pub(crate) fn fibonacci_grid(n: usize) -> Cow<'static, [Vector3<f64>]> {
    static DEFAULT: OnceLock<Vec<Vector3<f64>>> = OnceLock::new();
    static FINE: OnceLock<Vec<Vector3<f64>>> = OnceLock::new();
    let cache = if n == DEFAULT_STARTS {
        &DEFAULT
    } else if n == 4 * DEFAULT_STARTS {
        &FINE
    } else {
        return Cow::Owned(fibonacci_sphere(n));
    };
    Cow::Borrowed(cache.get_or_init(|| fibonacci_sphere(n)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tangent_basis_is_orthonormal_and_right_handed() {
        for g in fibonacci_sphere(50) {
            let p = tangent_basis(&g);
            let (u, v) = (p.column(0).into_owned(), p.column(1).into_owned());
            assert!((u.norm() - 1.0).abs() < 1e-14 && (v.norm() - 1.0).abs() < 1e-14);
            assert!(u.dot(&v).abs() < 1e-14 && u.dot(&g).abs() < 1e-14);
            assert!((u.cross(&v) - g).norm() < 1e-14);
        }
    }

    #[test]
    fn cached_grids_are_the_fibonacci_grids() {
        let n = DEFAULT_STARTS;
        for m in [n, 4 * n, 7] {
            assert_eq!(*fibonacci_grid(m), *fibonacci_sphere(m));
        }
    }

    #[test]
    fn sym2_eigen_matches_definition() {
        for (a, b, c) in [
            (1.0, 0.0, 1.0),
            (2.0, 1.0, -3.0),
            (1e8, 1.0, 1e8 + 1e-3),
            (0.0, 0.0, 5.0),
        ] {
            let k = Matrix2::new(a, b, b, c);
            let e = sym2_eigen(&k);
            assert!(e.values[0] <= e.values[1]);
            for i in 0..2 {
                let r = k * e.vectors[i] - e.values[i] * e.vectors[i];
                assert!(r.norm() <= 1e-9 * (1.0 + k.norm()), "{a} {b} {c}: {r}");
            }
        }
    }
}
