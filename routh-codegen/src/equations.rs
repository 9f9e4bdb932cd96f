//! The right sides of the equations of motion as nodes: the full equations (8) and the reduced
//! equations (13), each solved for the angular acceleration (docs/method.md §2–§3), so that the
//! derive can emit the whole vector field a simulation evaluates as one straight-line body
//! (`Lagrangian::full_equations`, `Routhian::reduced_equations`).
//!
//! Both have the same shape, `∂F/∂w × w + ∂F/∂γ × γ − (∂²F/∂w∂γ)(γ × w)` with `F = L, w = ω`
//! or `F = R, w = Ω` (the ω slots of the graph stand for Ω in every Routhian output). Built on
//! the DAG, the products share the nodes the derivatives already have, and terms that cancel
//! exactly (such as `n·(γ × γ)`) vanish by hash-consing instead of in floating point.

use crate::lower::Symbols;
use crate::reduce::{Outputs, M3, V3};
use routh_symbolic::{op_counts, Graph, Id, Var};
use std::collections::HashMap;

/// The right sides, one node per component.
pub struct Equations {
    /// `∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)` of (8).
    pub full: V3,
    /// `∂R/∂Ω × Ω + ∂R/∂γ × γ − (∂²R/∂Ω∂γ)(γ × Ω)` of (13).
    pub reduced: V3,
}

/// The right sides of (8) and (13) for the model's outputs.
///
/// The term `(∂²F/∂w∂γ)(γ × w)` is formed in two exactly equal ways, and the one that makes the
/// shorter method body (with the inertia J it returns beside it) is kept: as the product of the
/// 3×3 matrix the derivatives already have with `γ̇ = γ × w`, or as the derivative of `∂F/∂w`
/// along `γ̇`, `d/dε ∂F/∂w(w, γ + εγ̇)` at `ε = 0`, which never forms the matrix (for the
/// ellipsoid on a plane, whose mixed block is long, this is the shorter).
pub fn equations(sym: &mut Symbols, o: &Outputs) -> Equations {
    let (w, gm) = (sym.ids(sym.omega), sym.ids(sym.gamma));
    let gamma_vars = sym.gamma;
    let g = &mut sym.graph;
    let gamma_dot = cross(g, &gm, &w);
    let j = flat(&o.d2l_domega2);
    let shortest = |g: &mut Graph, p: &V3, f: &V3, m: &M3| {
        let product = matrix_times(g, m, &gamma_dot);
        let by_matrix = right_side(g, p, f, &product, &w, &gm);
        let along = derivative_along(g, p, gamma_vars, &gm, &gamma_dot);
        let by_derivative = right_side(g, p, f, &along, &w, &gm);
        let cost = |g: &Graph, r: &V3| {
            let mut ids = j.clone();
            ids.extend(r);
            op_counts(g, &ids).total()
        };
        if cost(g, &by_derivative) < cost(g, &by_matrix) {
            by_derivative
        } else {
            by_matrix
        }
    };
    let full = shortest(g, &o.dl_domega, &o.dl_dgamma, &o.d2l_domega_dgamma);
    let reduced = shortest(g, &o.dr_domega, &o.dr_dgamma, &o.d2r_domega_dgamma);
    Equations { full, reduced }
}

fn flat(m: &M3) -> Vec<Id> {
    m.iter().flatten().copied().collect()
}

/// `m x`.
fn matrix_times(g: &mut Graph, m: &M3, x: &V3) -> V3 {
    std::array::from_fn(|i| {
        let products: Vec<Id> = (0..3).map(|j| g.mul(m[i][j], x[j])).collect();
        g.sum(products)
    })
}

/// `(∂p/∂γ) x`: the derivative of `p` along `x`, `d/dε p(γ + εx)` at `ε = 0`.
fn derivative_along(g: &mut Graph, p: &V3, gamma_vars: [Var; 3], gm: &V3, x: &V3) -> V3 {
    let eps_var = g.new_var("ε");
    let eps = g.var_id(eps_var);
    let shift: HashMap<Var, Id> = (0..3)
        .map(|k| {
            let t = g.mul(eps, x[k]);
            (gamma_vars[k], g.add(gm[k], t))
        })
        .collect();
    let shifted = g.substitute(p, &shift);
    let d: Vec<Id> = shifted.iter().map(|&s| g.diff(s, eps_var)).collect();
    let zero = g.zero();
    let at_zero: HashMap<Var, Id> = [(eps_var, zero)].into_iter().collect();
    let d0 = g.substitute(&d, &at_zero);
    [d0[0], d0[1], d0[2]]
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
