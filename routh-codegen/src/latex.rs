//! The derived formulas in LaTeX, from the same graph as the generated code: the strings behind
//! `DerivedFormulas::latex()` (emitted as consts by the derive), and what a run-time model built
//! from a [`Model`] returns — both call [`latex_formulas`].

use std::collections::HashMap;

use routh_symbolic::{matrix_to_latex, on_sphere, to_latex, Graph, Id, LatexSymbols};

use crate::Model;

/// The LaTeX of L, ψ̇ (38), R (14), U_r (34) and A, G, C (64) at Ω = 0, field by field as
/// `routh_core::LatexFormulas` (this crate does not depend on routh-core).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LatexText {
    pub lagrangian: String,
    pub psi_dot: String,
    pub routhian: String,
    pub amended_potential: String,
    pub a: String,
    pub g: String,
    pub c: String,
}

/// Prints the model's formulas with `fields` as the symbols of its fields (field name → LaTeX;
/// the others print as `\mathit{name}`). Functions of γ are simplified with `|γ|² = 1` where
/// that shortens them ([`routh_symbolic::on_sphere`]); ψ̇ and R are printed with `\Omega_i`.
pub fn latex_formulas(model: &Model, fields: &[(String, String)]) -> LatexText {
    let sym = &model.lowered.sym;
    // A scratch copy: the rewriting adds nodes the generated code must not see.
    let mut g: Graph = sym.graph.clone();
    let plain = LatexSymbols {
        fields: fields.iter().cloned().collect(),
        big_omega: false,
    };
    let relative = LatexSymbols {
        big_omega: true,
        ..plain.clone()
    };
    let o = &model.outputs;
    // `on_sphere` of each node once: a symmetric A or C has each off-diagonal entry twice.
    let mut shortened: HashMap<(Id, bool), Id> = HashMap::new();
    let mut short = |g: &mut Graph, id: Id, s: &LatexSymbols| {
        *(shortened.entry((id, s.big_omega))).or_insert_with(|| on_sphere(g, id, sym.gamma, s))
    };
    let mut one = |g: &mut Graph, id: Id, s: &LatexSymbols| {
        let id = short(g, id, s);
        to_latex(g, id, s)
    };
    let lagrangian = one(&mut g, o.lagrangian, &plain);
    let psi_dot = one(&mut g, o.psi_dot, &relative);
    let routhian = one(&mut g, o.routhian, &relative);
    let amended_potential = one(&mut g, o.amended_potential, &plain);
    let mut matrix = |g: &mut Graph, m: &[[Id; 3]; 3]| {
        let m = m.map(|row| row.map(|id| short(g, id, &plain)));
        matrix_to_latex(g, &m, &plain)
    };
    let a = matrix(&mut g, &o.gyro_a);
    let gg = matrix(&mut g, &o.gyro_g);
    let c = matrix(&mut g, &o.gyro_c);
    LatexText {
        lagrangian,
        psi_dot,
        routhian,
        amended_potential,
        a,
        g: gg,
        c,
    }
}
