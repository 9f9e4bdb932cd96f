//! Krein signatures of the imaginary roots of `f₂` (errata E5): which modes of the linearised
//! reduced system carry positive and which negative energy.
//!
//! On the tangent plane the linearisation is `a ẍ + 2g J ẋ + c x = 0` with `a = PᵀAP` symmetric
//! positive definite, `J = [[0, 1], [−1, 0]]`, `g` the gyroscopic coefficient and `c = PᵀCP`
//! symmetric. Its energy `½ẋᵀaẋ + ½xᵀcx` is conserved (gyroscopic forces do no work), and on the
//! mode `x = Re(u e^{iωt})` of a root `λ = iω` it is proportional to `ω²uᴴau + uᴴcu`. Its sign is
//! the Krein signature of the root. Gyroscopic stabilisation (degree of instability 2) has two
//! pairs of opposite signature; when a pair of each collides on the imaginary axis the roots can
//! leave it (a Hamiltonian–Hopf bifurcation), while roots of equal signature pass each other.

use nalgebra::{Complex, Matrix2};

/// The Krein signature (`+1`, `−1`) of each of `roots`, `0` for a root off the imaginary axis (or
/// at zero, or where the mode cannot be resolved).
pub(crate) fn krein_signatures(
    a: &Matrix2<f64>,
    g: f64,
    c: &Matrix2<f64>,
    roots: &[Complex<f64>; 4],
) -> [i8; 4] {
    let mut out = [0i8; 4];
    for (k, l) in roots.iter().enumerate() {
        if l.im == 0.0 || l.re.abs() > 1e-9 * l.norm() {
            continue;
        }
        let w = l.im;
        // M(iω) = −ω²a + 2iωgJ + c; its null vector u from the row of larger norm.
        let m = |i: usize, j: usize| {
            let skew = match (i, j) {
                (0, 1) => 1.0,
                (1, 0) => -1.0,
                _ => 0.0,
            };
            Complex::new(-w * w * a[(i, j)] + c[(i, j)], 2.0 * w * g * skew)
        };
        let r0 = [m(0, 0), m(0, 1)];
        let r1 = [m(1, 0), m(1, 1)];
        let n = |r: &[Complex<f64>; 2]| r[0].norm() + r[1].norm();
        let r = if n(&r0) >= n(&r1) { r0 } else { r1 };
        let u = [r[1], -r[0]];
        if u[0].norm() + u[1].norm() == 0.0 {
            continue;
        }
        let quad = |q: &Matrix2<f64>| {
            let mut s = Complex::new(0.0, 0.0);
            for i in 0..2 {
                for j in 0..2 {
                    s += u[i].conj() * q[(i, j)] * u[j];
                }
            }
            s.re
        };
        let energy = w * w * quad(a) + quad(c);
        let size = w * w * quad(a).abs() + quad(c).abs();
        if energy.abs() > 1e-9 * size {
            out[k] = if energy > 0.0 { 1 } else { -1 };
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two uncoupled oscillators (g = 0, a = E, c = diag(1, 4)) carry positive energy; the same
    /// with c negative definite and a strong gyroscopic coupling has one mode of each sign.
    #[test]
    fn signatures_of_simple_systems() {
        let a = Matrix2::identity();
        let roots = [
            Complex::new(0.0, -2.0),
            Complex::new(0.0, -1.0),
            Complex::new(0.0, 1.0),
            Complex::new(0.0, 2.0),
        ];
        let s = krein_signatures(&a, 0.0, &Matrix2::new(1.0, 0.0, 0.0, 4.0), &roots);
        assert_eq!(s, [1, 1, 1, 1]);
        // a = E, c = −E, g: f₂ = (λ² − 1)² + 4g²λ² with roots λ = i(±g ± √(g² − 1)).
        let g: f64 = 2.0;
        let d = (g * g - 1.0).sqrt();
        let (w1, w2) = (g - d, g + d);
        let roots = [
            Complex::new(0.0, -w2),
            Complex::new(0.0, -w1),
            Complex::new(0.0, w1),
            Complex::new(0.0, w2),
        ];
        let s = krein_signatures(&a, g, &(-Matrix2::identity()), &roots);
        // The slow and the fast mode have opposite energy.
        assert_eq!(s[2], -s[3]);
        assert!(s.iter().all(|&x| x != 0));
    }
}
