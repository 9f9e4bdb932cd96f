//! Geometry of the unit sphere of verticals γ: a tangent basis of γ^⊥ (63), the restricted
//! second variation (62)–(63), the closed-form 2×2 symmetric eigen-decomposition, the local scale
//! of the amended potential and a Fibonacci grid of starting points.

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

/// The local scale `max(|∂R/∂γ|, ‖∂²R/∂γ²‖_F)` (see [`steady_motions`]).
pub(crate) fn local_scale(dr_dgamma: &Vector3<f64>, d2r_dgamma2: &Matrix3<f64>) -> f64 {
    dr_dgamma.norm().max(d2r_dgamma2.norm())
}

/// The restricted second variation `Pᵀ(μE − ∂²R/∂γ²)P` (62)–(63), symmetrised.
pub(crate) fn restricted_hessian(
    p: &Matrix3x2<f64>,
    mu: f64,
    d2r_dgamma2: &Matrix3<f64>,
) -> Matrix2<f64> {
    let k = p.transpose() * (Matrix3::from_diagonal_element(mu) - d2r_dgamma2) * p;
    0.5 * (k + k.transpose())
}

/// Eigen-decomposition of a symmetric 2×2 matrix, eigenvalues ascending.
pub(crate) struct Eigen2 {
    pub values: [f64; 2],
    pub vectors: [Vector2<f64>; 2],
}

/// Closed-form eigen-decomposition of the symmetric 2×2 matrix `k` (reads the upper triangle).
pub(crate) fn sym2_eigen(k: &Matrix2<f64>) -> Eigen2 {
    let (a, b, c) = (k[(0, 0)], k[(0, 1)], k[(1, 1)]);
    let m = 0.5 * (a + c);
    let d = (0.5 * (a - c)).hypot(b);
    // The eigenvalue of larger magnitude by the direct formula, the other from the determinant
    // when that avoids cancellation.
    let (lo, hi) = if d == 0.0 {
        (m, m)
    } else {
        let big = if m >= 0.0 { m + d } else { m - d };
        let det = a * c - b * b;
        let small = if big != 0.0 { det / big } else { m - d };
        if m >= 0.0 {
            (small, big)
        } else {
            (big, small)
        }
    };
    let vec_for = |lam: f64| {
        let v1 = Vector2::new(b, lam - a);
        let v2 = Vector2::new(lam - c, b);
        let v = if v1.norm() >= v2.norm() { v1 } else { v2 };
        let n = v.norm();
        if n > 0.0 {
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
