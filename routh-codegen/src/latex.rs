//! The derived formulas in LaTeX and in SymPy's syntax, from the same graph as the generated
//! code: the strings behind `DerivedFormulas::latex()` (printed at run time, on the first call,
//! from the struct's text the derive emits), and what a run-time model built from a [`Model`]
//! returns — both call [`latex_formulas`]; the SymPy strings ([`sympy_formulas`]) are printed
//! for run-time models only, when asked for.

use std::collections::HashMap;

use routh_symbolic::shape::dot3;
use routh_symbolic::{
    matrix_to_latex_named, on_sphere, replace_nodes, sympy_identifiers, to_latex, to_sympy, Graph,
    Id, LatexSymbols, Var, INTERMEDIATES, SYMPY_STATE,
};

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

/// The same formulas in SymPy's syntax, field by field as `routh_core::SympyFormulas`; a matrix
/// as `Matrix([[…], […], […]])`, and the definitions of the named subexpressions `sigmaK` of
/// the formulas too large to write out (in order, each using only the names before it).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SympyText {
    pub lagrangian: String,
    pub psi_dot: String,
    pub routhian: String,
    pub amended_potential: String,
    pub a: String,
    pub g: String,
    pub c: String,
    pub definitions: Vec<(String, String)>,
    /// `(identifier, name)` of every symbol the text may use: the state's (`omega1 … omega3`,
    /// `Omega1 …`, `gamma1 …`, `p_psi`), then the parameters' in order (identifier and name
    /// differ for a name that is not a free Python identifier: `routh_symbolic::sympy_identifiers`).
    pub symbols: Vec<(String, String)>,
}

/// The graph with the formulas simplified on the sphere, and their roots: L, ψ̇, R, U_r, A, G,
/// C (ψ̇ and R printed with `\Omega_i`).
struct Shortened {
    g: Graph,
    plain: LatexSymbols,
    relative: LatexSymbols,
    scalars: [Id; 4],
    matrices: [[[Id; 3]; 3]; 3],
    /// With `named`: the variables standing for γᵀJγ, ψ̇ and μ in `matrices`, and their
    /// definitions (each in terms of the ones before it).
    intermediates: Vec<(Var, Id)>,
}

/// The model's formulas with the functions of γ simplified with `|γ|² = 1` where that shortens
/// their LaTeX ([`routh_symbolic::on_sphere`]).
///
/// With `named`, the matrices are written with the paper's intermediate quantities
/// ([`INTERMEDIATES`]) as variables: γᵀJγ (the denominator of (38), `2T₂` at `ω = γ`), ψ̇ at
/// rest (38) and μ = (∂R/∂γ, γ) at rest, each node replaced where the matrices use it.
fn shortened(model: &Model, fields: &[(String, String)], named: bool) -> Shortened {
    let sym = &model.lowered.sym;
    // A scratch copy: the rewriting adds nodes the generated code must not see.
    let mut g: Graph = sym.graph.clone();
    let plain = LatexSymbols {
        fields: fields.iter().cloned().collect(),
        big_omega: false,
        sympy_names: HashMap::new(),
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
    let scalars = [
        short(&mut g, o.lagrangian, &plain),
        short(&mut g, o.psi_dot, &relative),
        short(&mut g, o.routhian, &relative),
        short(&mut g, o.amended_potential, &plain),
    ];
    let mut matrices = [o.gyro_a, o.gyro_g, o.gyro_c];
    let mut intermediates = Vec::new();
    if named {
        let lowered = &model.lowered;
        let gm = sym.gamma.map(|v| g.var_id(v));
        // The nodes as the reduction built them (hash-consing gives the same ids).
        let on_gamma: HashMap<Var, Id> = sym.omega.iter().copied().zip(gm).collect();
        let t2 = g.substitute(&[lowered.kinetic], &on_gamma)[0];
        let two = g.constant(2.0);
        let gjg = g.mul(two, t2);
        let mu = dot3(&mut g, &o.dr_dgamma_at_rest, &gm);
        let nodes = [gjg, o.psi_dot_at_rest, mu];
        let vars = INTERMEDIATES.map(|(name, _, _)| g.new_var(name));
        let mut map: HashMap<Id, Id> = HashMap::new();
        for (&node, &var) in nodes.iter().zip(&vars) {
            // Each definition in terms of the quantities before it.
            let def = replace_nodes(&mut g, &[node], &map)[0];
            let def = short(&mut g, def, &plain);
            intermediates.push((var, def));
            let v = g.var_id(var);
            map.insert(node, v);
        }
        for m in &mut matrices {
            let flat: Vec<Id> = m.iter().flatten().copied().collect();
            let new = replace_nodes(&mut g, &flat, &map);
            *m = std::array::from_fn(|i| std::array::from_fn(|j| new[3 * i + j]));
        }
    }
    let matrices = matrices.map(|m| m.map(|row| row.map(|id| short(&mut g, id, &plain))));
    Shortened {
        g,
        plain,
        relative,
        scalars,
        matrices,
        intermediates,
    }
}

/// Prints the model's formulas with `fields` as the symbols of its fields (field name → LaTeX;
/// the others print as `\mathit{name}`). Functions of γ are simplified with `|γ|² = 1` where
/// that shortens them ([`routh_symbolic::on_sphere`]); ψ̇ and R are printed with `\Omega_i`.
pub fn latex_formulas(model: &Model, fields: &[(String, String)]) -> LatexText {
    let s = shortened(model, fields, true);
    let g = &s.g;
    let [l, pd, r, ur] = s.scalars;
    let [a, gg, c] = (s.matrices).map(|m| matrix_to_latex_named(g, &m, &s.intermediates, &s.plain));
    LatexText {
        lagrangian: to_latex(g, l, &s.plain),
        psi_dot: to_latex(g, pd, &s.relative),
        routhian: to_latex(g, r, &s.relative),
        amended_potential: to_latex(g, ur, &s.plain),
        a,
        g: gg,
        c,
    }
}

/// The same formulas as [`latex_formulas`] (the same expressions, simplified on the sphere the
/// same way) in SymPy's syntax ([`routh_symbolic::to_sympy`]): `omega1`, `Omega1` (in ψ̇ and R),
/// `gamma1`, `p_psi`, each parameter by its field's name (`inertia_1`, `I_12` for components,
/// from 1), matrices as `Matrix([[…], […], […]])`.
///
/// A parameter whose name is not a free Python identifier (`lambda`, `sin`, `nan`, `Matrix`,
/// `sigma1`) is written under another identifier (`lambda_`), listed in `symbols` with its name
/// ([`sympy_identifiers`]): the text is Python with every symbol bound to its identifier.
pub fn sympy_formulas(model: &Model) -> SympyText {
    let mut s = shortened(model, &[], false);
    let sym = &model.lowered.sym;
    let vars: Vec<&str> = sym.params.iter().map(|p| s.g.var_name(p.var)).collect();
    let params = sympy_identifiers(&vars);
    let renamed: HashMap<String, String> = (vars.iter().zip(&params))
        .map(|(v, (ident, _))| (v.to_string(), ident.clone()))
        .collect();
    s.plain.sympy_names = renamed.clone();
    s.relative.sympy_names = renamed;
    let mut symbols: Vec<(String, String)> = SYMPY_STATE
        .iter()
        .map(|n| (n.to_string(), n.to_string()))
        .collect();
    symbols.extend(params);
    let s = s;
    let g = &s.g;
    let mut definitions = Vec::new();
    let mut one = |roots: &[Id], symbols: &LatexSymbols| {
        let (texts, defs) = to_sympy(g, roots, symbols, definitions.len());
        definitions.extend(defs);
        texts
    };
    let [l, pd, r, ur] = s.scalars;
    let lagrangian = one(&[l], &s.plain).concat();
    let psi_dot = one(&[pd], &s.relative).concat();
    let routhian = one(&[r], &s.relative).concat();
    let amended_potential = one(&[ur], &s.plain).concat();
    let [a, gg, c] = s.matrices.map(|m| {
        let roots: Vec<Id> = m.iter().flatten().copied().collect();
        let cells = one(&roots, &s.plain);
        let rows: Vec<String> = cells
            .chunks(3)
            .map(|row| format!("[{}]", row.join(", ")))
            .collect();
        format!("Matrix([{}])", rows.join(", "))
    });
    SympyText {
        lagrangian,
        psi_dot,
        routhian,
        amended_potential,
        a,
        g: gg,
        c,
        definitions,
        symbols,
    }
}
