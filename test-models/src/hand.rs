//! A hand-simplified closed form of every output of the gyrostat's Routh function: the
//! "hand-written bundle" that the benches compare the generated code against (docs/performance.md).
//!
//! For `L = ½ωᵀIω + (K + Bγ)·ω − m g r·γ` with `I` symmetric, write
//!
//! - `w = Iγ`, `s = γᵀIγ = γ·w`, `ρ = 1/s` (the one division);
//! - `c = IΩ + a` with `a = K + Bγ` (so `∂L/∂ω(Ω) = c`);
//! - `q = p_ψ − c·γ` and `u = qρ = ψ̇` (38);
//! - `h = c + Bᵀγ` (so `∂q/∂γ = −h`, `∂q/∂Ω = −w`, `∂s/∂γ = 2w`);
//! - `t = h + 2uw` and `z = ρt` (so `∂u/∂γ = −z`, `∂u/∂Ω = −ρw`);
//! - `P = B + uI`.
//!
//! Then, from (39) `R = ½Ω·IΩ + a·Ω − m g r·γ − ½ q²/s`:
//!
//! - `R = ½(Ω·(c + a) − q u) − m g r·γ`, `∂R/∂p_ψ = −u`;
//! - `∂R/∂Ω = c + uw`;
//! - `∂R/∂γ = BᵀΩ − m g r + u(h + uw)`;
//! - `∂²R/∂Ω² = I − (ρw)wᵀ`;
//! - `∂²R/∂Ω_i∂γ_j = P − (ρw)tᵀ` (`= B + uI − wtᵀ/s`);
//! - `∂²R/∂γ² = u(P + Bᵀ) − t zᵀ` (`= u(B + Bᵀ) + u²I − ttᵀ/s`; symmetric, because
//!   `P + Bᵀ = B + Bᵀ + uI`).
//!
//! Every block reuses `w`, `ρw`, `c`, `u`, `uw`, `t`, `z` and `P`; only the upper triangles of
//! the symmetric `I`, `∂²R/∂Ω²` and `∂²R/∂γ²` are formed. Everything after the division waits
//! for it, so that part is written for a short critical path rather than for the fewest
//! operations: `h` is formed before `u` is known, and `t = h + u(2w)` is one multiplication and
//! one addition after `u` (three more operations than `(h + uw) + uw`, which would reuse the
//! sum `∂R/∂γ` needs but is three dependent steps); `∂²R/∂Ω∂γ` reads `t` rather than `z = ρt`.
//!
//! A, G, C of (64) are written inline, from the locals above, as an expert would
//! ([`hand_gyrostat_bundle_and_system`]): `A = ∂²R/∂Ω²` is the block already formed;
//! differentiating (17), `(∂R/∂Ω, γ) ≡ p_ψ`, by γ gives `Mᵀγ = −∂R/∂Ω` (`M = ∂²R/∂Ω∂γ`), and
//! `M[γ]× + [γ]×Mᵀ = [(tr M)γ − Mᵀγ]×` for any `M`, so `2G = (tr M)[γ]×` with the trace read
//! off the diagonal locals of `M`; and since `[γ]×ᵀ = −[γ]×`,
//! `C = [γ]×ᵀ(μE − ∂²R/∂γ²)[γ]× = [γ]× N [γ]×` with `N = ∂²R/∂γ² − μE`, `μ = (∂R/∂γ, γ)`: the
//! off-diagonal entries of `N` are the Hessian's own locals (no negation, no symmetrisation),
//! and the sandwich skips the zeros of `[γ]×` and forms only the upper triangle of `C`.
//! [`hand_gyrostat_system`] is the composed path instead: the bundle, then
//! [`GyroscopicSystem::from_bundle`].

use nalgebra::{Matrix3, Vector3};
use routh_core::{GyroscopicSystem, RouthBundle};

use crate::Gyrostat;

/// Every output of the gyrostat's Routh function at `(Ω, γ, p_ψ)`, written out by hand in
/// plain `f64` arithmetic (see the module documentation for the formulas): one reciprocal of
/// `s = γᵀIγ`, shared products across the blocks, and only the upper triangles of the symmetric
/// `I`, `∂²R/∂Ω²` and `∂²R/∂γ²`.
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
    // Inlined, the unused A, G, C are dead code and are not computed.
    hand_gyrostat_bundle_and_system(m, big_omega, gamma, p_psi).0
}

/// Every output of the gyrostat's Routh function at `(Ω, γ, p_ψ)` and A, G, C of (64) formed
/// from them, in one body written by hand (see the module documentation): the expert's
/// counterpart of the generated `Routhian::bundle_and_system`. Same conditions as
/// [`hand_gyrostat_bundle`].
///
/// `#[inline(always)]`, as the generated code is inlined: so that the bench compares equal
/// call paths, and so that [`hand_gyrostat_bundle`], which keeps only the bundle, does not
/// compute A, G, C.
#[inline(always)]
pub fn hand_gyrostat_bundle_and_system(
    m: &Gyrostat,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> (RouthBundle, GyroscopicSystem) {
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

    // w = Iγ, s = γ·w and its one reciprocal.
    let w0 = i00 * g0 + i01 * g1 + i02 * g2;
    let w1 = i01 * g0 + i11 * g1 + i12 * g2;
    let w2 = i02 * g0 + i12 * g1 + i22 * g2;
    let s = g0 * w0 + g1 * w1 + g2 * w2;
    let rho = 1.0 / s;

    // a = K + Bγ, c = IΩ + a.
    let a0 = m.rotor.x + (b00 * g0 + b01 * g1 + b02 * g2);
    let a1 = m.rotor.y + (b10 * g0 + b11 * g1 + b12 * g2);
    let a2 = m.rotor.z + (b20 * g0 + b21 * g1 + b22 * g2);
    let c0 = (i00 * o0 + i01 * o1 + i02 * o2) + a0;
    let c1 = (i01 * o0 + i11 * o1 + i12 * o2) + a1;
    let c2 = (i02 * o0 + i12 * o1 + i22 * o2) + a2;

    // q = p_ψ − c·γ, u = ψ̇ = q/s, uw.
    let q = p_psi - (c0 * g0 + c1 * g1 + c2 * g2);
    let u = q * rho;
    let uw0 = u * w0;
    let uw1 = u * w1;
    let uw2 = u * w2;

    // m g r.
    let mg = m.mass * m.g;
    let (mr0, mr1, mr2) = (mg * m.com.x, mg * m.com.y, mg * m.com.z);

    // R = ½(Ω·(c + a) − q u) − m g r·γ.
    let routhian = 0.5 * (o0 * (c0 + a0) + o1 * (c1 + a1) + o2 * (c2 + a2) - q * u)
        - (mr0 * g0 + mr1 * g1 + mr2 * g2);

    let dr_domega = Vector3::new(c0 + uw0, c1 + uw1, c2 + uw2);

    // h = c + Bᵀγ (formed while ρ is being computed), h + uw; ∂R/∂γ = BᵀΩ − m g r + u(h + uw).
    let h0 = c0 + (b00 * g0 + b10 * g1 + b20 * g2);
    let h1 = c1 + (b01 * g0 + b11 * g1 + b21 * g2);
    let h2 = c2 + (b02 * g0 + b12 * g1 + b22 * g2);
    let hu0 = h0 + uw0;
    let hu1 = h1 + uw1;
    let hu2 = h2 + uw2;
    let dr_dgamma = Vector3::new(
        (b00 * o0 + b10 * o1 + b20 * o2) - mr0 + u * hu0,
        (b01 * o0 + b11 * o1 + b21 * o2) - mr1 + u * hu1,
        (b02 * o0 + b12 * o1 + b22 * o2) - mr2 + u * hu2,
    );

    // ∂²R/∂Ω² = I − (ρw)wᵀ, symmetric.
    let rw0 = rho * w0;
    let rw1 = rho * w1;
    let rw2 = rho * w2;
    let aa00 = i00 - rw0 * w0;
    let aa01 = i01 - rw0 * w1;
    let aa02 = i02 - rw0 * w2;
    let aa11 = i11 - rw1 * w1;
    let aa12 = i12 - rw1 * w2;
    let aa22 = i22 - rw2 * w2;
    #[rustfmt::skip]
    let d2r_domega2 = Matrix3::new(
        aa00, aa01, aa02,
        aa01, aa11, aa12,
        aa02, aa12, aa22,
    );

    // t = h + u(2w), z = ρt: 2w is ready long before u, which waits for the division, so this
    // is one multiplication and one addition after u where (h + uw) + uw is three steps.
    let t0 = h0 + u * (w0 + w0);
    let t1 = h1 + u * (w1 + w1);
    let t2 = h2 + u * (w2 + w2);
    let z0 = rho * t0;
    let z1 = rho * t1;
    let z2 = rho * t2;

    // P = B + uI; ∂²R/∂Ω_i∂γ_j = P − (ρw)tᵀ.
    let ui00 = u * i00;
    let ui01 = u * i01;
    let ui02 = u * i02;
    let ui11 = u * i11;
    let ui12 = u * i12;
    let ui22 = u * i22;
    let (p00, p01, p02) = (b00 + ui00, b01 + ui01, b02 + ui02);
    let (p10, p11, p12) = (b10 + ui01, b11 + ui11, b12 + ui12);
    let (p20, p21, p22) = (b20 + ui02, b21 + ui12, b22 + ui22);
    #[rustfmt::skip]
    let d2r_domega_dgamma = Matrix3::new(
        p00 - rw0 * t0, p01 - rw0 * t1, p02 - rw0 * t2,
        p10 - rw1 * t0, p11 - rw1 * t1, p12 - rw1 * t2,
        p20 - rw2 * t0, p21 - rw2 * t1, p22 - rw2 * t2,
    );

    // ∂²R/∂γ² = u(P + Bᵀ) − t zᵀ, symmetric.
    let cc00 = u * (p00 + b00) - t0 * z0;
    let cc01 = u * (p01 + b10) - t0 * z1;
    let cc02 = u * (p02 + b20) - t0 * z2;
    let cc11 = u * (p11 + b11) - t1 * z1;
    let cc12 = u * (p12 + b21) - t1 * z2;
    let cc22 = u * (p22 + b22) - t2 * z2;
    #[rustfmt::skip]
    let d2r_dgamma2 = Matrix3::new(
        cc00, cc01, cc02,
        cc01, cc11, cc12,
        cc02, cc12, cc22,
    );

    // 2G = (tr M)[γ]×, the trace from the diagonal of ∂²R/∂Ω∂γ.
    let half_tr = 0.5 * ((p00 - rw0 * t0) + (p11 - rw1 * t1) + (p22 - rw2 * t2));
    let (hg0, hg1, hg2) = (half_tr * g0, half_tr * g1, half_tr * g2);
    #[rustfmt::skip]
    let g = Matrix3::new(
        0.0, -hg2, hg1,
        hg2, 0.0, -hg0,
        -hg1, hg0, 0.0,
    );

    // C = [γ]× N [γ]×, N = ∂²R/∂γ² − μE, μ = (∂R/∂γ, γ): Y = N[γ]× (Y₀₀ is not read), then
    // the upper triangle of [γ]×Y. Rows of [γ]×: (0, −g2, g1), (g2, 0, −g0), (−g1, g0, 0).
    let mu = dr_dgamma.x * g0 + dr_dgamma.y * g1 + dr_dgamma.z * g2;
    let (n00, n11, n22) = (cc00 - mu, cc11 - mu, cc22 - mu);
    let y01 = cc02 * g0 - n00 * g2;
    let y02 = n00 * g1 - cc01 * g0;
    let y10 = n11 * g2 - cc12 * g1;
    let y11 = cc12 * g0 - cc01 * g2;
    let y12 = cc01 * g1 - n11 * g0;
    let y20 = cc12 * g2 - n22 * g1;
    let y21 = n22 * g0 - cc02 * g2;
    let y22 = cc02 * g1 - cc12 * g0;
    let k00 = g1 * y20 - g2 * y10;
    let k01 = g1 * y21 - g2 * y11;
    let k02 = g1 * y22 - g2 * y12;
    let k11 = g2 * y01 - g0 * y21;
    let k12 = g2 * y02 - g0 * y22;
    let k22 = g0 * y12 - g1 * y02;
    #[rustfmt::skip]
    let c = Matrix3::new(
        k00, k01, k02,
        k01, k11, k12,
        k02, k12, k22,
    );

    let bundle = RouthBundle {
        routhian,
        psi_dot: u,
        dr_domega,
        dr_dgamma,
        dr_dp: -u,
        d2r_domega2,
        d2r_domega_dgamma,
        d2r_dgamma2,
    };
    let system = GyroscopicSystem {
        a: d2r_domega2,
        g,
        c,
    };
    (bundle, system)
}

/// Every output of the gyrostat at `(Ω, γ, p_ψ)` and A, G, C of (64) there through the composed
/// path: the hand-written bundle, then [`GyroscopicSystem::from_bundle`] (what the default
/// `Routhian::bundle_and_system` does for a hand-written model).
#[inline]
pub fn hand_gyrostat_system(
    m: &Gyrostat,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> (RouthBundle, GyroscopicSystem) {
    let bundle = hand_gyrostat_bundle(m, big_omega, gamma, p_psi);
    let system = GyroscopicSystem::from_bundle(&bundle, gamma);
    (bundle, system)
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
            // A, G, C written inline against the matrix products of errata E6 on the num-dual
            // bundle (not the closed forms either side uses): 2G = M[γ]× + [γ]×Mᵀ − [∂R/∂Ω]×,
            // C = [γ]×ᵀ(μE − ∂²R/∂γ²)[γ]×.
            let (bundle, sys) = hand_gyrostat_bundle_and_system(&model, &omega, &gamma, p);
            assert_eq!(bundle, got);
            let gx = gamma.cross_matrix();
            let mx = want.d2r_domega_dgamma;
            let want_g = 0.5 * (mx * gx + gx * mx.transpose() - want.dr_domega.cross_matrix());
            let mu = want.dr_dgamma.dot(&gamma);
            let want_c =
                gx.transpose() * (Matrix3::from_diagonal_element(mu) - want.d2r_dgamma2) * gx;
            let systems: [(&str, &[f64], &[f64]); 3] = [
                ("A", sys.a.as_slice(), want.d2r_domega2.as_slice()),
                ("G", sys.g.as_slice(), want_g.as_slice()),
                ("C", sys.c.as_slice(), want_c.as_slice()),
            ];
            // The composed path (hand bundle, then from_bundle) gives the same to round-off.
            let (bundle2, composed) = hand_gyrostat_system(&model, &omega, &gamma, p);
            assert_eq!(bundle2, got);
            for (name, fused, comp) in [("G", &sys.g, &composed.g), ("C", &sys.c, &composed.c)] {
                let e = rel_err(fused.as_slice(), comp.as_slice());
                assert!(e <= 1e-13, "point {k}: fused {name} vs from_bundle: {e:e}");
            }
            assert_eq!(sys.a, composed.a);
            for (name, g, w) in outputs.into_iter().chain(systems) {
                let e = rel_err(g, w);
                assert!(
                    e <= 1e-12,
                    "point {k}: {name} relative error {e:e}\n  hand    {g:?}\n  numdual {w:?}"
                );
                worst = worst.max(e);
            }
            // ∂R/∂p_ψ (15) against R itself: R is a quadratic polynomial in p_ψ ((39): p_ψ enters
            // only through −½(p_ψ − q)²/s), so the central difference with any step h is exact
            // but for the round-off of the two values of R, a few ε·|R|/h.
            let h = 0.5;
            let r_plus = hand_gyrostat_bundle(&model, &omega, &gamma, p + h).routhian;
            let r_minus = hand_gyrostat_bundle(&model, &omega, &gamma, p - h).routhian;
            let fd = (r_plus - r_minus) / (2.0 * h);
            let round_off = 16.0 * f64::EPSILON * (r_plus.abs() + r_minus.abs()) / (2.0 * h);
            assert!(
                (got.dr_dp - fd).abs() <= round_off.max(1e-14 * fd.abs()),
                "point {k}: dR/dp = {} vs central difference {fd}",
                got.dr_dp
            );
            // The symmetry of both Hessian blocks that must be symmetric.
            assert_eq!(got.d2r_domega2, got.d2r_domega2.transpose());
            assert_eq!(got.d2r_dgamma2, got.d2r_dgamma2.transpose());
            assert_eq!(sys.c, sys.c.transpose());
            assert_eq!(sys.g, -sys.g.transpose());
        }
        assert!(worst <= 1e-12, "worst relative error {worst:e}");
    }
}
