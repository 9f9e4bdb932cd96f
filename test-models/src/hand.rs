//! A hand-simplified closed form of every output of the gyrostat's Routh function: the
//! "hand-written bundle" that the benches compare the generated code against (README, “Performance”).
//!
//! For `L = ½ωᵀIω + (K + Bγ)·ω − m g r·γ` with `I` symmetric, write
//! `u = Iγ`, `D = γ·u`, `w = IΩ`, `a = K + Bγ`, `s = p_ψ − w·γ − a·γ`, `ψ̇ = s/D` (38),
//! `v = w + a + Bᵀγ` (so that `∂s/∂γ = −v`, `∂s/∂Ω = −u`, `∂D/∂γ = 2u`) and
//! `q = ∂ψ̇/∂γ = −(v + 2ψ̇u)/D` (while `∂ψ̇/∂Ω = −u/D`). Then, from (39)
//! `R = ½Ω·w + a·Ω − m g r·γ − ½ s ψ̇`:
//!
//! - `∂R/∂Ω = w + a + ψ̇u`, `∂R/∂p_ψ = −ψ̇`,
//! - `∂R/∂γ = BᵀΩ − m g r + ψ̇v + ψ̇²u`,
//! - `∂²R/∂Ω² = I − uuᵀ/D`,
//! - `∂²R/∂Ω_i∂γ_j = B + ψ̇I + uqᵀ`,
//! - `∂²R/∂γ² = −D qqᵀ + ψ̇(B + Bᵀ) + ψ̇²I` (the first term is `−ttᵀ/D` with `t = v + 2ψ̇u`).

use nalgebra::{Matrix3, Vector3};
use routh_core::RouthBundle;

use crate::Gyrostat;

/// Every output of the gyrostat's Routh function at `(Ω, γ, p_ψ)`, written out by hand in
/// plain `f64` arithmetic: one reciprocal of `D = γᵀIγ`, shared products, and only the upper
/// triangles of the symmetric `I`, `∂²R/∂Ω²` and `∂²R/∂γ²`.
///
/// `m.inertia` must be symmetric (only its upper triangle is read). `γ` need not be a unit
/// vector; `γᵀIγ` must be non-zero.
#[inline]
pub fn hand_gyrostat_bundle(
    m: &Gyrostat,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> RouthBundle {
    let (o0, o1, o2) = (big_omega.x, big_omega.y, big_omega.z);
    let (g0, g1, g2) = (gamma.x, gamma.y, gamma.z);

    // Upper triangle of I (symmetric); B in full.
    let i = &m.inertia;
    let (i00, i01, i02, i11, i12, i22) = (
        i[(0, 0)],
        i[(0, 1)],
        i[(0, 2)],
        i[(1, 1)],
        i[(1, 2)],
        i[(2, 2)],
    );
    let b = &m.coupling;
    let (b00, b01, b02) = (b[(0, 0)], b[(0, 1)], b[(0, 2)]);
    let (b10, b11, b12) = (b[(1, 0)], b[(1, 1)], b[(1, 2)]);
    let (b20, b21, b22) = (b[(2, 0)], b[(2, 1)], b[(2, 2)]);

    // u = Iγ, w = IΩ.
    let u0 = i00 * g0 + i01 * g1 + i02 * g2;
    let u1 = i01 * g0 + i11 * g1 + i12 * g2;
    let u2 = i02 * g0 + i12 * g1 + i22 * g2;
    let w0 = i00 * o0 + i01 * o1 + i02 * o2;
    let w1 = i01 * o0 + i11 * o1 + i12 * o2;
    let w2 = i02 * o0 + i12 * o1 + i22 * o2;

    // a = K + Bγ, Bᵀγ, BᵀΩ.
    let a0 = m.rotor.x + b00 * g0 + b01 * g1 + b02 * g2;
    let a1 = m.rotor.y + b10 * g0 + b11 * g1 + b12 * g2;
    let a2 = m.rotor.z + b20 * g0 + b21 * g1 + b22 * g2;
    let btg0 = b00 * g0 + b10 * g1 + b20 * g2;
    let btg1 = b01 * g0 + b11 * g1 + b21 * g2;
    let btg2 = b02 * g0 + b12 * g1 + b22 * g2;
    let bto0 = b00 * o0 + b10 * o1 + b20 * o2;
    let bto1 = b01 * o0 + b11 * o1 + b21 * o2;
    let bto2 = b02 * o0 + b12 * o1 + b22 * o2;

    // D = γᵀIγ and its one reciprocal; s and ψ̇.
    let d = g0 * u0 + g1 * u1 + g2 * u2;
    let inv_d = 1.0 / d;
    let wa0 = w0 + a0;
    let wa1 = w1 + a1;
    let wa2 = w2 + a2;
    let s = p_psi - (wa0 * g0 + wa1 * g1 + wa2 * g2);
    let pd = s * inv_d;
    let pd2 = pd * pd;

    // m g r.
    let mg = m.mass * m.g;
    let (mr0, mr1, mr2) = (mg * m.com.x, mg * m.com.y, mg * m.com.z);

    // R = Ω·(½w + a) − m g r·γ − ½ s ψ̇.
    let routhian = o0 * (0.5 * w0 + a0) + o1 * (0.5 * w1 + a1) + o2 * (0.5 * w2 + a2)
        - (mr0 * g0 + mr1 * g1 + mr2 * g2)
        - 0.5 * s * pd;

    // v = w + a + Bᵀγ; t = v + 2ψ̇u; q = −t/D.
    let v0 = wa0 + btg0;
    let v1 = wa1 + btg1;
    let v2 = wa2 + btg2;
    let pd_u0 = pd * u0;
    let pd_u1 = pd * u1;
    let pd_u2 = pd * u2;
    let t0 = v0 + 2.0 * pd_u0;
    let t1 = v1 + 2.0 * pd_u1;
    let t2 = v2 + 2.0 * pd_u2;
    let q0 = -t0 * inv_d;
    let q1 = -t1 * inv_d;
    let q2 = -t2 * inv_d;

    let dr_domega = Vector3::new(wa0 + pd_u0, wa1 + pd_u1, wa2 + pd_u2);
    // ψ̇v + ψ̇²u = ψ̇(v + ψ̇u).
    let dr_dgamma = Vector3::new(
        bto0 - mr0 + pd * (v0 + pd_u0),
        bto1 - mr1 + pd * (v1 + pd_u1),
        bto2 - mr2 + pd * (v2 + pd_u2),
    );

    // ∂²R/∂Ω² = I − (u/D)uᵀ, symmetric.
    let hu0 = u0 * inv_d;
    let hu1 = u1 * inv_d;
    let hu2 = u2 * inv_d;
    let aa00 = i00 - hu0 * u0;
    let aa01 = i01 - hu0 * u1;
    let aa02 = i02 - hu0 * u2;
    let aa11 = i11 - hu1 * u1;
    let aa12 = i12 - hu1 * u2;
    let aa22 = i22 - hu2 * u2;
    #[rustfmt::skip]
    let d2r_domega2 = Matrix3::new(
        aa00, aa01, aa02,
        aa01, aa11, aa12,
        aa02, aa12, aa22,
    );

    // ∂²R/∂Ω_i∂γ_j = B + ψ̇I + u qᵀ.
    let pi00 = pd * i00;
    let pi01 = pd * i01;
    let pi02 = pd * i02;
    let pi11 = pd * i11;
    let pi12 = pd * i12;
    let pi22 = pd * i22;
    #[rustfmt::skip]
    let d2r_domega_dgamma = Matrix3::new(
        b00 + pi00 + u0 * q0, b01 + pi01 + u0 * q1, b02 + pi02 + u0 * q2,
        b10 + pi01 + u1 * q0, b11 + pi11 + u1 * q1, b12 + pi12 + u1 * q2,
        b20 + pi02 + u2 * q0, b21 + pi12 + u2 * q1, b22 + pi22 + u2 * q2,
    );

    // ∂²R/∂γ² = t qᵀ + ψ̇(B + Bᵀ) + ψ̇²I (t qᵀ = −D q qᵀ), symmetric.
    let cc00 = t0 * q0 + pd * (b00 + b00) + pd2 * i00;
    let cc01 = t0 * q1 + pd * (b01 + b10) + pd2 * i01;
    let cc02 = t0 * q2 + pd * (b02 + b20) + pd2 * i02;
    let cc11 = t1 * q1 + pd * (b11 + b11) + pd2 * i11;
    let cc12 = t1 * q2 + pd * (b12 + b21) + pd2 * i12;
    let cc22 = t2 * q2 + pd * (b22 + b22) + pd2 * i22;
    #[rustfmt::skip]
    let d2r_dgamma2 = Matrix3::new(
        cc00, cc01, cc02,
        cc01, cc11, cc12,
        cc02, cc12, cc22,
    );

    RouthBundle {
        routhian,
        psi_dot: pd,
        dr_domega,
        dr_dgamma,
        dr_dp: -pd,
        d2r_domega2,
        d2r_domega_dgamma,
        d2r_dgamma2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{numdual_bundle, random_unit_vector, random_vector};
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// `‖got − want‖∞ / ‖want‖∞` (absolute when `want` is exactly zero).
    fn rel_err(got: &[f64], want: &[f64]) -> f64 {
        assert!(
            got.iter().all(|x| x.is_finite()),
            "non-finite output {got:?}"
        );
        let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let err = got
            .iter()
            .zip(want)
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
        if scale > 0.0 {
            err / scale
        } else {
            err
        }
    }

    #[test]
    fn hand_bundle_matches_numdual() {
        let mut rng = ChaCha8Rng::seed_from_u64(0x4a4e_d5e7);
        let mut worst = 0.0f64;
        for k in 0..100 {
            // A fresh generic gyrostat at every point (full SPD I, K, general B, r).
            let model = Gyrostat::random(&mut rng);
            let omega = random_vector(&mut rng, 2.0);
            // |γ| ≠ 1 on purpose: R is defined and differentiated on all of ℝ³.
            let gamma = random_unit_vector(&mut rng) * rng.gen_range(0.7..1.3);
            let p = rng.gen_range(-3.0..3.0);
            let got = hand_gyrostat_bundle(&model, &omega, &gamma, p);
            let want = numdual_bundle(&model, &omega, &gamma, p);
            let outputs: [(&str, &[f64], &[f64]); 8] = [
                ("R", &[got.routhian], &[want.routhian]),
                ("psi_dot", &[got.psi_dot], &[want.psi_dot]),
                (
                    "dR/dOmega",
                    got.dr_domega.as_slice(),
                    want.dr_domega.as_slice(),
                ),
                (
                    "dR/dgamma",
                    got.dr_dgamma.as_slice(),
                    want.dr_dgamma.as_slice(),
                ),
                ("dR/dp", &[got.dr_dp], &[want.dr_dp]),
                (
                    "d2R/dOmega2",
                    got.d2r_domega2.as_slice(),
                    want.d2r_domega2.as_slice(),
                ),
                (
                    "d2R/dOmega dgamma",
                    got.d2r_domega_dgamma.as_slice(),
                    want.d2r_domega_dgamma.as_slice(),
                ),
                (
                    "d2R/dgamma2",
                    got.d2r_dgamma2.as_slice(),
                    want.d2r_dgamma2.as_slice(),
                ),
            ];
            for (name, g, w) in outputs {
                let e = rel_err(g, w);
                assert!(
                    e <= 1e-12,
                    "point {k}: {name} relative error {e:e}\n  hand    {g:?}\n  numdual {w:?}"
                );
                worst = worst.max(e);
            }
            // (15) and the symmetry of both Hessian blocks that must be symmetric.
            assert_eq!(got.dr_dp, -got.psi_dot);
            assert_eq!(got.d2r_domega2, got.d2r_domega2.transpose());
            assert_eq!(got.d2r_dgamma2, got.d2r_dgamma2.transpose());
        }
        assert!(worst <= 1e-12, "worst relative error {worst:e}");
    }
}
