//! The right sides of the equations of motion as nodes: the full equations (8) and the reduced
//! equations (13), each solved for the angular acceleration (docs/method.md §2–§3), so that the
//! derive can emit the whole vector field a simulation evaluates as one straight-line body
//! (`Lagrangian::full_equations`, `Routhian::reduced_equations`).
//!
//! Both have the same shape, `∂F/∂w × w + ∂F/∂γ × γ − (∂²F/∂w∂γ)(γ × w)` with `F = L, w = ω`
//! or `F = R, w = Ω` (the ω slots of the graph stand for Ω in every Routhian output). Built on
//! the DAG, the products share the nodes the derivatives already have, and terms that cancel
//! exactly (such as `n·(γ × γ)`) vanish by hash-consing instead of in floating point.

use crate::layout::JacobianTerms;
use crate::lower::Symbols;
use crate::nodes::{M3, V3};
use crate::reduce::Outputs;
use routh_symbolic::{Graph, Id, Var};

/// The right sides, one node per component.
pub struct Equations {
    /// `∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)` of (8).
    pub full: V3,
    /// `∂R/∂Ω × Ω + ∂R/∂γ × γ − (∂²R/∂Ω∂γ)(γ × Ω)` of (13).
    pub reduced: V3,
    /// `J`, the right side of (8) and their derivatives in `(ω, γ)`, for
    /// `Lagrangian::full_jacobian`.
    pub jacobian: JacobianTerms<Id>,
}

/// The right sides of (8) and (13) for the model's outputs.
///
/// The mixed term `(∂²F/∂w∂γ)(γ × w)` is the product of the 3×3 matrix the derivatives already
/// have with `γ̇ = γ × w`. (Forming it instead as the derivative of `∂F/∂w` along `γ̇`,
/// `d/dε ∂F/∂w(w, γ + εγ̇)` at `ε = 0`, and keeping the shorter, was tried: 6% fewer operations
/// for the top's (13), 1% for the ellipsoid's (8), none for the gyrostat, at 6 ms more of
/// expansion in an unoptimised build of the generator, which is what a user pays.)
pub fn equations(sym: &mut Symbols, o: &Outputs) -> Equations {
    let (w, gm) = (sym.ids(sym.omega), sym.ids(sym.gamma));
    let g = &mut sym.graph;
    let gamma_dot = cross(g, &gm, &w);
    let side = |g: &mut Graph, p: &V3, f: &V3, m: &M3| {
        let product = matrix_times(g, m, &gamma_dot);
        right_side(g, p, f, &product, &w, &gm)
    };
    let full = side(g, &o.dl_domega, &o.dl_dgamma, &o.d2l_domega_dgamma);
    let reduced = side(g, &o.dr_domega, &o.dr_dgamma, &o.d2r_domega_dgamma);
    let jacobian = jacobian(g, &full, &o.d2l_domega2, sym.omega, sym.gamma);
    Equations {
        full,
        reduced,
        jacobian,
    }
}

/// `J`, `f` and their first derivatives: the nodes of `f` (the right side of (8)) and of `J`
/// differentiated by the ω and γ variables ([`Graph::diff`], memoised per variable, so the
/// derivatives share the nodes that the outputs' own derivatives already made). `J` is free of
/// ω; each `∂J/∂γ_k` is symmetric, its upper triangle mirrored.
fn jacobian(g: &mut Graph, f: &V3, j: &M3, w: [Var; 3], gm: [Var; 3]) -> JacobianTerms<Id> {
    let by = |g: &mut Graph, x: [Var; 3]| f.map(|fi| x.map(|v| g.diff(fi, v)));
    let dright_domega = by(g, w);
    let dright_dgamma = by(g, gm);
    let dinertia_dgamma = gm.map(|v| {
        let mut d = [[j[0][0]; 3]; 3];
        for r in 0..3 {
            for c in r..3 {
                d[r][c] = g.diff(j[r][c], v);
                d[c][r] = d[r][c];
            }
        }
        d
    });
    JacobianTerms {
        inertia: *j,
        right_side: *f,
        dright_domega,
        dright_dgamma,
        dinertia_dgamma,
    }
}

/// `m x`.
fn matrix_times(g: &mut Graph, m: &M3, x: &V3) -> V3 {
    std::array::from_fn(|i| {
        let products: Vec<Id> = (0..3).map(|j| g.mul(m[i][j], x[j])).collect();
        g.sum(products)
    })
}

/// `a × b`.
fn cross(g: &mut Graph, a: &V3, b: &V3) -> V3 {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let x = g.mul(a[j], b[k]);
        let y = g.mul(a[k], b[j]);
        g.sub(x, y)
    })
}

/// `p × w + f × γ − mixed`, with `mixed = (∂p/∂γ)(γ × w)`.
fn right_side(g: &mut Graph, p: &V3, f: &V3, mixed: &V3, w: &V3, gm: &V3) -> V3 {
    let pw = cross(g, p, w);
    let fg = cross(g, f, gm);
    std::array::from_fn(|i| {
        let s = g.add(pw[i], fg[i]);
        g.sub(s, mixed[i])
    })
}
