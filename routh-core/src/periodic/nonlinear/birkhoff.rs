//! The Birkhoff normal form to order three of an area-preserving map of the plane at an elliptic
//! fixed point (docs/method.md §12.2).
//!
//! In canonical coordinates `ξ` (`Ω = dξ₁∧dξ₂`) the linear part `L` (`det L = 1`,
//! `|tr L| < 2`) is conjugated by a symplectic `S` to the rotation by `φ` counter-clockwise;
//! with `z = w₁ − i w₂` (`w = S⁻¹ξ`) the map reads `z ↦ λz + Σ a_{jk} zʲz̄ᵏ + Σ b_{jk} zʲz̄ᵏ`,
//! `λ = e^{2πiρ}`: `arg z` grows clockwise (the fixed sense), and `ρ = −φ/2π mod 1`. The
//! quadratic terms are removed by `z = w + h(w, w̄)`, `h_{jk} = a_{jk}/(λʲλ̄ᵏ − λ)` (the term
//! `z̄²` is resonant at `λ³ = 1`); the coefficient `c` of `w²w̄` of the conjugated map then
//! gives `w ↦ λw(1 + (c/λ)|w|²) + …`: invariant circles of area `A = π|w|²` turn by
//! `2πρ + Im(c/λ)|w|²`, so `τ = dρ/dA = Im(c/λ)/(2π²)`. `Re(c/λ) = 0` for an area-preserving
//! map, a check of the jets. At `λ⁴ = 1` the coefficient `d` of `w̄³` is resonant, and the
//! orbit is stable when `|c| > |d|`, unstable when `|c| < |d|` (Markeev).

use nalgebra::{Complex, Matrix2};
use std::f64::consts::PI;

use super::jet::{index, CJet, MapJet, EXPS};

/// What the normal form gives.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Birkhoff {
    /// `ρ ∈ [0, 1)`.
    pub rotation_number: f64,
    /// `τ = dρ/dA`.
    pub twist: f64,
    /// `|Re(c/λ)|/|c/λ|`: 0 for an area-preserving map.
    pub area_defect: f64,
    /// `|a₀₂|`, the resonant quadratic coefficient at order three.
    pub third_resonant: f64,
    /// The scale of the quadratic terms (`max |a_{jk}|`).
    pub quadratic_scale: f64,
    /// `|c|` and `|d|` for the fourth-order criterion.
    pub fourth: (f64, f64),
    /// The scale `|Im(c/λ)|` is compared with: the cubic terms plus the products of the
    /// quadratic terms and the homological solution.
    pub twist_scale: f64,
}

/// The normal form of `p` (jets in canonical coordinates, `p(0) = 0`); `None` unless the linear
/// part is elliptic. `skip_third`: leave the term `z̄²` in place (at a third-order resonance).
pub(crate) fn birkhoff(p: &[MapJet; 2], skip_third: bool) -> Option<Birkhoff> {
    let l = Matrix2::new(
        p[0].coeff(1, 0),
        p[0].coeff(0, 1),
        p[1].coeff(1, 0),
        p[1].coeff(0, 1),
    );
    let det = l.determinant();
    // Normalised to det 1 (the jets' round-off), as the map is symplectic.
    let cosphi = 0.5 * l.trace() / det.abs().sqrt();
    if cosphi.is_nan() || cosphi.abs() >= 1.0 {
        return None;
    }
    let mut sinphi = (1.0 - cosphi * cosphi).sqrt();
    let mut kmat = (l / det.abs().sqrt() - Matrix2::identity() * cosphi) / sinphi;
    // S = [u, Ku] with u = e₁ has det K₂₁: choose the sign of φ so that it is positive.
    if kmat[(1, 0)] < 0.0 {
        sinphi = -sinphi;
        kmat = -kmat;
    }
    let sdet = kmat[(1, 0)];
    if sdet.is_nan() || sdet <= 0.0 {
        return None;
    }
    let s = Matrix2::new(1.0, kmat[(0, 0)], 0.0, kmat[(1, 0)]) / sdet.sqrt();
    let sinv = s.try_inverse()?;
    let phi = sinphi.atan2(cosphi);
    let rho = (-phi / (2.0 * PI)).rem_euclid(1.0);
    // The map in w = S⁻¹ξ: q(w) = S⁻¹ p(S w).
    let (w1, w2) = (MapJet::variable(0), MapJet::variable(1));
    let xi = [
        w1.scale(s[(0, 0)]) + w2.scale(s[(0, 1)]),
        w1.scale(s[(1, 0)]) + w2.scale(s[(1, 1)]),
    ];
    let pw = [
        p[0].substitute(&xi[0], &xi[1]),
        p[1].substitute(&xi[0], &xi[1]),
    ];
    let q = [
        pw[0].scale(sinv[(0, 0)]) + pw[1].scale(sinv[(0, 1)]),
        pw[0].scale(sinv[(1, 0)]) + pw[1].scale(sinv[(1, 1)]),
    ];
    // In z = w₁ − i w₂: w₁ = (z + z̄)/2, w₂ = i(z − z̄)/2.
    let z = CJet::variable(0);
    let zb = CJet::variable(1);
    let half = Complex::new(0.5, 0.0);
    let cw1 = (z + zb).scale(half);
    let cw2 = (z - zb).scale(Complex::new(0.0, 0.5));
    let real = |m: &MapJet| CJet {
        c: std::array::from_fn(|k| Complex::new(m.c[k], 0.0)),
    };
    let q1 = real(&q[0]).substitute(&cw1, &cw2);
    let q2 = real(&q[1]).substitute(&cw1, &cw2);
    let f = q1 - q2.scale(Complex::new(0.0, 1.0));
    let lambda = Complex::new(phi.cos(), -phi.sin());
    // Remove the quadratic terms.
    let mut h = CJet::constant(Complex::new(0.0, 0.0));
    let mut quadratic_scale = 0.0f64;
    let mut hsum = 0.0;
    for (kk, &(j, k)) in EXPS.iter().enumerate() {
        if j + k != 2 {
            continue;
        }
        let a = f.c[kk];
        quadratic_scale = quadratic_scale.max(a.norm());
        if skip_third && (j, k) == (0, 2) {
            continue;
        }
        let den = lambda.powu(j.into()) * lambda.conj().powu(k.into()) - lambda;
        h.c[kk] = a / den;
        hsum += h.c[kk].norm();
    }
    let third_resonant = f.coeff(0, 2).norm();
    let phi_map = z + h; // z = w + h(w, w̄)
    let fz = f.substitute(&phi_map, &phi_map.conj());
    // Φ⁻¹(u) = u − h(Φ⁻¹(u)) to order three.
    let mut inv = z;
    for _ in 0..3 {
        inv = z - h.substitute(&inv, &inv.conj());
    }
    let g = inv.substitute(&fz, &fz.conj());
    let c = g.c[index(2, 1)] / lambda;
    let d = g.c[index(0, 3)] / lambda;
    let cubic: f64 = EXPS
        .iter()
        .zip(&f.c)
        .filter(|((j, k), _)| j + k == 3)
        .map(|(_, a)| a.norm())
        .sum();
    let twist_scale = cubic + quadratic_scale * hsum;
    Some(Birkhoff {
        rotation_number: rho,
        twist: c.im / (2.0 * PI * PI),
        area_defect: if c.norm() > 0.0 {
            c.re.abs() / c.norm()
        } else {
            0.0
        },
        third_resonant,
        quadratic_scale,
        fourth: (c.norm(), d.norm()),
        twist_scale,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::periodic::nonlinear::jet::Series;

    /// The time-1 map of `H = ω I + β I²` (`I = (q² + p²)/2`), which turns clockwise by
    /// `ω + 2βI` with area `A = 2πI`: `ρ = (ω + 2βI)/2π`, `τ = β/(2π²)`. The map is written
    /// as its Taylor expansion to order three in `(q, p)`, then conjugated by a shear and a
    /// near-identity symplectic change of coordinates that adds quadratic terms.
    #[test]
    fn twist_of_a_twist_map_in_disguise() {
        let (om, beta) = (2.0_f64, 0.37_f64);
        let (q, p) = (MapJet::variable(0), MapJet::variable(1));
        // Exact flow: angle θ = ω + β(q² + p²), (q, p) ↦ R_cw(θ)(q, p).
        let theta = Series::constant(om) + (q * q + p * p).scale(beta);
        let (c, s) = (
            routh_tape::TapeScalar::func(theta, routh_tape::Func::Cos),
            routh_tape::TapeScalar::func(theta, routh_tape::Func::Sin),
        );
        let m = [q * c + p * s, p * c - q * s];
        let b = birkhoff(&m, false).unwrap();
        assert!((b.rotation_number - om / (2.0 * PI)).abs() < 1e-14);
        assert!(
            (b.twist - beta / (2.0 * PI * PI)).abs() < 1e-13,
            "{}",
            b.twist
        );
        // Conjugate by the symplectic Φ(q, p) = (q + εp², p) then a linear shear: ψ⁻¹∘m∘ψ.
        let eps = 0.3;
        let shear = 0.8;
        // ψ(x, y) = (x + ε(y + shear·x)²... built as the composition of two symplectic maps:
        // A(x, y) = (x, y + shear x), B(x, y) = (x + ε y², y).
        let a = |u: &[MapJet; 2]| [u[0], u[1] + u[0].scale(shear)];
        let a_inv = |u: &[MapJet; 2]| [u[0], u[1] - u[0].scale(shear)];
        let bmap = |u: &[MapJet; 2]| [u[0] + (u[1] * u[1]).scale(eps), u[1]];
        let b_inv = |u: &[MapJet; 2]| [u[0] - (u[1] * u[1]).scale(eps), u[1]];
        let apply = |f: &[MapJet; 2], u: &[MapJet; 2]| {
            [f[0].substitute(&u[0], &u[1]), f[1].substitute(&u[0], &u[1])]
        };
        let id = [q, p];
        let psi = bmap(&a(&id));
        let psi_inv = a_inv(&b_inv(&id));
        let conj = apply(&psi_inv, &apply(&m, &psi));
        let b2 = birkhoff(&conj, false).unwrap();
        assert!((b2.rotation_number - om / (2.0 * PI)).abs() < 1e-13);
        assert!(
            (b2.twist - beta / (2.0 * PI * PI)).abs() < 1e-12,
            "{} vs {}",
            b2.twist,
            beta / (2.0 * PI * PI)
        );
        assert!(b2.area_defect < 1e-12);
    }
}
