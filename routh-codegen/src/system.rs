//! `A`, `G`, `C` of (64) as nodes of the graph, from those of the bundle (section 5 in the
//! matrix form of errata E6): the gyroscopic system [`crate::reduce`] derives for
//! `gyroscopic_system` and `bundle_and_system`, and in the same form as
//! `GyroscopicSystem::from_bundle` of routh-core.

use crate::nodes::{M3, V3};
use routh_symbolic::shape::dot3;
use routh_symbolic::{Graph, Id};

/// `G = ½(tr M)[γ]×` (see [`gyroscopic`]) written as `h_i = γ_i·(½ tr M)` and `−h_i`: one
/// multiplication for ½ and one per component, where `g.mul` would pull the constant out of
/// every entry (`0.5·(γ_i tr M)` and `(−0.5)·(γ_i tr M)`, two per component).
fn half_trace_skew(g: &mut Graph, gm: &V3, mx: &M3) -> M3 {
    let tr = g.sum([mx[0][0], mx[1][1], mx[2][2]]);
    let h: V3 = gm.map(|gi| g.mul_scaled(gi, 0.5, tr));
    let n: V3 = h.map(|hi| g.neg(hi));
    let z = g.zero();
    [[z, n[2], h[1]], [h[2], z, n[0]], [n[1], h[0], z]]
}

/// errata E6: `2G = M[γ]× + [γ]×Mᵀ − [∂R/∂Ω]×` and `C = [γ]×ᵀ(μE − H)[γ]×`, μ = (∂R/∂γ, γ); these
/// are the entries printed in section 5 in matrix form.
///
/// G is written in closed form: `M[γ]× + [γ]×Mᵀ = [(tr M)γ − Mᵀγ]×` holds for every 3×3 `M`, and
/// differentiating Theorem 2's identity (17), `(∂R/∂Ω, γ) ≡ p_ψ`, by γ gives `Mᵀγ = −∂R/∂Ω`
/// for every Routh function (at every Ω, so at Ω = 0 too). Hence `2G = (tr M)[γ]×` exactly; the
/// matrix products are not formed; G is `half_trace_skew`, C is `stiffness_sandwich`.
pub fn gyroscopic(g: &mut Graph, gm: &V3, dr_dg: &V3, mx: &M3, h: &M3) -> (M3, M3) {
    let gyro_g = half_trace_skew(g, gm, mx);
    let mu = dot3(g, dr_dg, gm);
    (gyro_g, stiffness_sandwich(g, gm, mu, h))
}

/// `C = [γ]×ᵀ(μE − H)[γ]×` of errata E6, written as `[γ]× N [γ]×` with `N = H − μE` (the two
/// signs cancel: `[γ]×ᵀ = −[γ]×`): `Y = N[γ]×`, then the upper triangle of `[γ]×Y`, mirrored
/// (C is symmetric because H is).
///
/// Every entry is one difference of two products, `a·x − b·y`, with the signs of `[γ]×`
/// absorbed into the order of the operands: no negation is formed (the generic product
/// `[γ]×ᵀ(μE − H)` and `· [γ]×` left two, `−(a + b)`, where both terms of an entry came out
/// negative), N's off-diagonal entries are H's own nodes, and the six entries of C (and the
/// eight of Y they read; `Y₀₀` is not needed) all have the same shape, which is what lets the
/// compiler pair neighbouring entries into two-lane SIMD operations (docs/performance.md).
/// Rows of `[γ]×`: `(0, −γ₂, γ₁)`, `(γ₂, 0, −γ₀)`, `(−γ₁, γ₀, 0)`.
fn stiffness_sandwich(g: &mut Graph, gm: &V3, mu: Id, h: &M3) -> M3 {
    let [g0, g1, g2] = *gm;
    // a·x − b·y.
    let cross = |g: &mut Graph, a: Id, x: Id, b: Id, y: Id| {
        let ax = g.mul(a, x);
        let by = g.mul(b, y);
        g.sub(ax, by)
    };
    let n: M3 = std::array::from_fn(|i| {
        std::array::from_fn(|k| if i == k { g.sub(h[i][i], mu) } else { h[i][k] })
    });
    // Y = N[γ]×: Y_i0 = N_i1 γ₂ − N_i2 γ₁, Y_i1 = N_i2 γ₀ − N_i0 γ₂, Y_i2 = N_i0 γ₁ − N_i1 γ₀.
    let y = |g: &mut Graph, i: usize, k: usize| match k {
        0 => cross(g, n[i][1], g2, n[i][2], g1),
        1 => cross(g, n[i][2], g0, n[i][0], g2),
        _ => cross(g, n[i][0], g1, n[i][1], g0),
    };
    // [γ]×Y: C_0k = γ₁Y_2k − γ₂Y_1k, C_1k = γ₂Y_0k − γ₀Y_2k, C_2k = γ₀Y_1k − γ₁Y_0k.
    let mut c = [[mu; 3]; 3];
    for (i, k) in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)] {
        let (ga, ra, gb, rb) = match i {
            0 => (g1, 2, g2, 1),
            1 => (g2, 0, g0, 2),
            _ => (g0, 1, g1, 0),
        };
        let ya = y(g, ra, k);
        let yb = y(g, rb, k);
        let e = cross(g, ga, ya, gb, yb);
        c[i][k] = e;
        c[k][i] = e;
    }
    c
}
