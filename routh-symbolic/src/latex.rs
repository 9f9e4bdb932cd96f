//! A LaTeX printer for the expression DAG, beside the plain-text [`to_infix`](crate::to_infix):
//! the same tree walk, printing sums with their signs, products in normal form (the numeric
//! coefficient first, as a fraction `\frac{p}{q}` when it is one with `q ≤ 12`, then the factors
//! side by side, equal factors as powers), quotients as `\frac{…}{…}`, `x^{1/2}` as `\sqrt{x}`,
//! and brackets `\left( … \right)` only where precedence needs them.
//!
//! Variables print through [`latex_symbol`]: the DSL's `ω₁ γ₁ p_ψ` as `\omega_1`, `\gamma_1`,
//! `p_\psi` (`\Omega_1` in functions of the relative angular velocity Ω), a scalar field `mgl`
//! as `\mathit{mgl}`, the components of a vector field `v` as `\mathit{v}_{1}` and of a matrix
//! field `I` as `\mathit{I}_{11}` (indices from 1), unless the model gives the field a symbol.
//!
//! Terms and factors come in one canonical order (see [`to_latex`]), and [`to_sympy`] prints
//! the same expressions in SymPy's syntax (variables named by [`sympy_symbol`]).
//!
//! [`on_sphere`] rewrites an expression with `|γ|² = 1` where that shortens it (the rule is on
//! the function). A long formula is printed with its common subexpressions named
//! (`… \quad \text{where} \quad \sigma_{1} = …`, see [`to_latex`]); a matrix may name the
//! paper's intermediate quantities instead ([`matrix_to_latex_named`], [`INTERMEDIATES`]).

use std::cell::RefCell;
use std::collections::HashMap;

use crate::graph::{Func, Graph, Id, Node, Var};

/// Largest expression tree printed inline, in nodes of the expanded tree (for a matrix, the
/// total over its entries). A formula whose tree is larger (the expanded tree of a DAG grows
/// fast with sharing: the stiffness matrix `C` of (64) repeats `1/γᵀJγ` and its powers in every
/// entry) is printed with its shared subexpressions named, as
/// `… \quad \text{where} \quad \sigma_{1} = …,\; \sigma_{2} = …` (see [`to_latex`]). 250
/// keeps the short formulas (L, ψ̇, R, U_r of the tops) as they were and names what the long
/// ones repeat. Measured on the paper's models (tests/latex.rs, `--nocapture`): the longest
/// formula went from 208 213 characters (the body in a fluid, before: inline up to 4000 nodes)
/// to 4972 (the body in a fluid), and the gyrostat's `C`, which was too large to print at
/// all, is printed.
const MAX_TREE: u64 = 250;

/// Largest expression tree of a matrix written with named intermediates
/// ([`matrix_to_latex_named`]) printed without `\sigma_{k}`, in nodes over its nine entries
/// and the intermediates' definitions. Larger than [`MAX_TREE`]: the intermediates already
/// name what the entries share, and with them the tops' `A`, `G`, `C` print in full
/// (tests/latex.rs); bounded, as a longer text costs the derive time (printing, and escaping
/// the string literal: at 2250 nodes the ellipsoid's expansion took 2 ms more than at 1000,
/// where the ellipsoids', the gyrostat's and the body in a fluid's `G` and `C` still name
/// `\sigma_{k}`s besides ψ̇, γᵀJγ and μ).
const MAX_TREE_NAMED: u64 = 1000;

/// With named subexpressions, the largest total printed (the main formula and every
/// definition, each named subexpression counting 1 where it is used); beyond it the text says
/// the formula was not printed.
const MAX_NAMED_TOTAL: u64 = 60_000;

/// A subexpression used at least twice is named when it has at least this many nodes (with the
/// named subexpressions inside it counting 1).
const MIN_NAMED_SIZE: u64 = 8;

/// How variables are named in LaTeX: the model's own symbols for its fields, and whether the
/// angular-velocity slots are ω or Ω.
#[derive(Clone, Debug, Default)]
pub struct LatexSymbols {
    /// Field name → LaTeX symbol (e.g. `("inertia", "I")`); the others print as `\mathit{name}`.
    pub fields: HashMap<String, String>,
    /// Print the angular-velocity slots `ω₁ ω₂ ω₃` as `\Omega_1 …` (the Routhian's arguments).
    pub big_omega: bool,
    /// Variable name → its SymPy identifier, in place of [`sympy_symbol`]'s own (the parameters
    /// renamed by [`sympy_identifiers`]; empty: every name as [`sympy_symbol`] makes it).
    pub sympy_names: HashMap<String, String>,
}

/// The syntax a [`Printer`] writes: LaTeX, or SymPy's (Python's) infix syntax.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Style {
    Latex,
    /// LaTeX with the terms of sums in the graph's order: only to measure a formula's length
    /// ([`on_sphere`]; the order does not change the length but by a sign's space), without the
    /// cost of sorting.
    LatexUnsorted,
    Sympy,
}

/// The SymPy name of a variable named as the derive names them: `ω₁ → omega1` (`Omega1` when
/// [`LatexSymbols::big_omega`]), `γ₂ → gamma2`, `p_ψ → p_psi`, a field `name` as `name`, its
/// components `name[i] → name_{i+1}` and `name[(i,j)] → name_{i+1}{j+1}` (from 1, as in the
/// LaTeX: `inertia_3`, `I_12`). The field's own name is kept (not its LaTeX symbol): it is a
/// Python identifier, and it is the name the model's parameters go by everywhere else.
pub fn sympy_symbol(var_name: &str, symbols: &LatexSymbols) -> String {
    if let Some(name) = symbols.sympy_names.get(var_name) {
        return name.clone();
    }
    if let Some(&(_, _, py)) = INTERMEDIATES.iter().find(|(n, _, _)| *n == var_name) {
        return py.to_string();
    }
    if let Some((class, k)) = state_slot(var_name) {
        return match class {
            0 if symbols.big_omega => format!("Omega{}", k + 1),
            0 => format!("omega{}", k + 1),
            1 => format!("gamma{}", k + 1),
            _ => "p_psi".to_string(),
        };
    }
    sympy_param_name(var_name)
}

/// The SymPy name of a parameter's variable: `name`, `name[i] → name_{i+1}`,
/// `name[(i,j)] → name_{i+1}{j+1}`.
fn sympy_param_name(var_name: &str) -> String {
    let (base, index) = match var_name.find('[') {
        Some(at) => (&var_name[..at], Some(&var_name[at..])),
        None => (var_name, None),
    };
    let idx: String = index
        .map(|s| {
            s.chars()
                .filter_map(|c| c.to_digit(10))
                .map(|d| (d + 1).to_string())
                .collect()
        })
        .unwrap_or_default();
    if idx.is_empty() {
        base.to_string()
    } else {
        format!("{base}_{idx}")
    }
}

/// The intermediate quantities the paper names, as variables of that name stand for them in a
/// formula ([`matrix_to_latex_named`]): the name, the LaTeX and the SymPy symbol. `γᵀJγ` is
/// (38)'s denominator `γᵀJ(γ)γ` with `J = ∂²L/∂ω²`, `ψ̇` is ψ̇ at rest (38), `μ = (∂R/∂γ, γ)`
/// at rest (errata E6).
pub const INTERMEDIATES: [(&str, &str, &str); 3] = [
    ("γᵀJγ", "\\gamma^{\\mathsf{T}} J \\gamma", "gJg"),
    ("ψ̇", "\\dot\\psi", "psidot"),
    ("μ", "\\mu", "mu"),
];

/// The names the SymPy text uses besides its symbols: the functions it calls, `Matrix`, the
/// constants `nan` (a formula too large to print) and `oo`, and `Symbol` (which
/// `routh formulas --sympy` imports to define the symbols). No symbol is given one of them as
/// its identifier ([`sympy_identifiers`]).
pub const SYMPY_FUNCTIONS: [&str; 12] = [
    "Matrix", "Symbol", "sqrt", "Abs", "sign", "sin", "cos", "tan", "exp", "log", "nan", "oo",
];

/// Python's keywords (`keyword.kwlist`): not identifiers.
const PYTHON_KEYWORDS: [&str; 35] = [
    "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class", "continue",
    "def", "del", "elif", "else", "except", "finally", "for", "from", "global", "if", "import",
    "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try", "while",
    "with", "yield",
];

/// The state's SymPy names, in the order of [`sympy_identifiers`]' list.
pub const SYMPY_STATE: [&str; 10] = [
    "omega1", "omega2", "omega3", "Omega1", "Omega2", "Omega3", "gamma1", "gamma2", "gamma3",
    "p_psi",
];

/// Whether `s` may be a symbol's identifier in the SymPy text: an ASCII Python identifier, not
/// a keyword, a name of [`SYMPY_FUNCTIONS`] or a state's name, not `sigmaK` (the named
/// subexpressions).
fn free_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    let ascii_ident = matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_');
    let sigma = s
        .strip_prefix("sigma")
        .is_some_and(|k| !k.is_empty() && k.bytes().all(|b| b.is_ascii_digit()));
    ascii_ident
        && !sigma
        && !PYTHON_KEYWORDS.contains(&s)
        && !SYMPY_FUNCTIONS.contains(&s)
        && !SYMPY_STATE.contains(&s)
}

/// The SymPy identifiers and names of a model's parameters, given the names of their variables
/// in order (`mgl`, `inertia[0]`, `inertia[(0,2)]`): `(identifier, name)` for each, so that any
/// parameter name round-trips through the text. The name is the one [`sympy_symbol`] gives
/// (`mgl`, `inertia_1`, `inertia_13`), the display name of the `sympy.Symbol`; where two would
/// be the same (a parameter `omega1`, a scalar `com_1` beside a vector `com`), the scalar keeps
/// it before a component and the state before both, and the other gets `_` appended until it is
/// no one's. The identifier, the name in the text, is the name when it is a free one (an ASCII
/// Python identifier, not a keyword, not a function or constant the text uses, not a state's
/// name, not `sigmaK`): `lambda`, `sin`, `nan` or `α` is renamed, to the name with its other
/// characters written `_<hex>` and `_` appended until it is free and no one else's (`lambda_`,
/// `_3b1`). Whatever the names, the identifiers are distinct and so are the names.
pub fn sympy_identifiers(var_names: &[&str]) -> Vec<(String, String)> {
    let natural: Vec<String> = var_names.iter().map(|v| sympy_param_name(v)).collect();
    // Names: the state's, then the scalars', then the components', each its own when free.
    let mut names: Vec<Option<String>> = vec![None; natural.len()];
    let mut taken: std::collections::HashSet<String> =
        SYMPY_STATE.iter().map(|s| s.to_string()).collect();
    for scalars in [true, false] {
        for (i, v) in var_names.iter().enumerate() {
            if v.contains('[') != scalars && taken.insert(natural[i].clone()) {
                names[i] = Some(natural[i].clone());
            }
        }
    }
    let names: Vec<String> = names
        .into_iter()
        .zip(&natural)
        .map(|(name, n)| {
            name.unwrap_or_else(|| {
                let mut n = format!("{n}_");
                while !taken.insert(n.clone()) {
                    n.push('_');
                }
                n
            })
        })
        .collect();
    // Identifiers: every free name is kept, then the others renamed.
    let mut idents: Vec<Option<String>> = vec![None; names.len()];
    let mut used = std::collections::HashSet::new();
    for (i, n) in names.iter().enumerate() {
        if free_identifier(n) && used.insert(n.clone()) {
            idents[i] = Some(n.clone());
        }
    }
    idents
        .into_iter()
        .zip(&names)
        .map(|(ident, name)| {
            let ident = ident.unwrap_or_else(|| {
                let mut id: String = name
                    .chars()
                    .map(|c| {
                        if c.is_ascii_alphanumeric() || c == '_' {
                            c.to_string()
                        } else {
                            format!("_{:x}", u32::from(c))
                        }
                    })
                    .collect();
                if id.starts_with(|c: char| c.is_ascii_digit()) {
                    id.insert(0, '_');
                }
                id.push('_');
                while !(free_identifier(&id) && used.insert(id.clone())) {
                    id.push('_');
                }
                id
            });
            (ident, name.clone())
        })
        .collect()
}

/// A state variable's place: `(0, k)` for `ω_{k+1}`, `(1, k)` for `γ_{k+1}`, `(2, 0)` for `p_ψ`;
/// `None` for a parameter.
fn state_slot(var_name: &str) -> Option<(u8, u8)> {
    if var_name == "p_ψ" {
        return Some((2, 0));
    }
    let mut chars = var_name.chars();
    let (first, last) = (chars.next()?, chars.next()?);
    if chars.next().is_some() {
        return None;
    }
    let k = match last {
        '₁' => 0,
        '₂' => 1,
        '₃' => 2,
        _ => return None,
    };
    match first {
        'ω' => Some((0, k)),
        'γ' => Some((1, k)),
        _ => None,
    }
}

/// The LaTeX symbol of a variable named as the derive names them: `ω₁`, `γ₂`, `p_ψ`, a field
/// `name`, `name[i]` or `name[(i,j)]` (see the module documentation).
pub fn latex_symbol(var_name: &str, symbols: &LatexSymbols) -> String {
    let sub = |c: char| match c {
        '₁' => Some(1),
        '₂' => Some(2),
        '₃' => Some(3),
        _ => None,
    };
    let mut chars = var_name.chars();
    if let (Some(first), Some(last), 2) = (chars.next(), chars.next(), var_name.chars().count()) {
        if let Some(k) = sub(last) {
            match first {
                'ω' if symbols.big_omega => return format!("\\Omega_{k}"),
                'ω' => return format!("\\omega_{k}"),
                'γ' => return format!("\\gamma_{k}"),
                _ => {}
            }
        }
    }
    if var_name == "p_ψ" {
        return "p_\\psi".to_string();
    }
    if let Some(&(_, tex, _)) = INTERMEDIATES.iter().find(|(n, _, _)| *n == var_name) {
        return tex.to_string();
    }
    let (base, index) = match var_name.find('[') {
        Some(at) => (&var_name[..at], Some(&var_name[at..])),
        None => (var_name, None),
    };
    let base_tex = match symbols.fields.get(base) {
        Some(s) => s.clone(),
        None => format!("\\mathit{{{}}}", base.replace('_', "\\_")),
    };
    let digits: Vec<usize> = index
        .map(|s| {
            s.chars()
                .filter_map(|c| c.to_digit(10))
                .map(|d| d as usize + 1)
                .collect()
        })
        .unwrap_or_default();
    if digits.is_empty() {
        base_tex
    } else {
        let idx: String = digits.iter().map(|d| d.to_string()).collect();
        // A symbol with its own sub- or superscript (`r_c`) in braces: `{r_c}_{1}`, not the
        // double subscript `r_c_{1}` LaTeX refuses.
        if base_tex.contains(['_', '^']) {
            format!("{{{base_tex}}}_{{{idx}}}")
        } else {
            format!("{base_tex}_{{{idx}}}")
        }
    }
}

/// The expression `root` in LaTeX (see the module documentation).
///
/// Terms and factors come in a canonical order (see [`to_sympy`], which shares it): in a
/// product the number first, then the parameters (in the order of the model's fields), then
/// `ω₁ ω₂ ω₃`, `γ₁ γ₂ γ₃`, `p_ψ`, then anything else (sums in brackets, functions); a sum by
/// decreasing degree in the state variables (ω or Ω, γ, p_ψ), terms of equal degree by their
/// exponents of `ω₁ … γ₃ p_ψ` in that order (`ω₁² + ω₁ω₂ + ω₂²`), then by their parameters, and
/// a leading negative term after the first positive one (`1 - \gamma_3^{2}`, as SymPy prints).
///
/// A formula whose expanded tree has more than `MAX_TREE` (250) nodes (a matrix: in all) is
/// printed with its common subexpressions named: each subexpression used at least twice and of
/// at least `MIN_NAMED_SIZE` (8) nodes becomes `\sigma_{k}`, defined after the formula, inner
/// ones first, as in
///
/// ```text
/// \frac{\sigma_{2}}{\sigma_{1}} \quad \text{where} \quad \sigma_{1} = …,\; \sigma_{2} = …
/// ```
///
/// (a definition uses only the names before it). Beyond `MAX_NAMED_TOTAL` nodes even so, the
/// text says that the formula was not printed.
pub fn to_latex(g: &Graph, root: Id, symbols: &LatexSymbols) -> String {
    let (main, defs) = print_roots(g, &[root], symbols, Style::Latex, 0, MAX_TREE);
    format!("{}{}", main.concat(), where_clause(&defs))
}

/// The length of [`to_latex`] of `root` (but for the order of terms, which costs time to find
/// and changes the length by a space at most).
fn latex_len(g: &Graph, root: Id, symbols: &LatexSymbols) -> usize {
    let (main, defs) = print_roots(g, &[root], symbols, Style::LatexUnsorted, 0, MAX_TREE);
    main.concat().len() + where_clause(&defs).len()
}

/// A 3×3 matrix of expressions as `\begin{pmatrix} … \end{pmatrix}`; when named
/// subexpressions are needed (see [`to_latex`]) they are shared by the entries and defined after
/// the matrix.
pub fn matrix_to_latex(g: &Graph, m: &[[Id; 3]; 3], symbols: &LatexSymbols) -> String {
    let roots: Vec<Id> = m.iter().flatten().copied().collect();
    let (cells, defs) = print_roots(g, &roots, symbols, Style::Latex, 0, MAX_TREE);
    let rows: Vec<String> = cells.chunks(3).map(|row| row.join(" & ")).collect();
    format!(
        "\\begin{{pmatrix}} {} \\end{{pmatrix}}{}",
        rows.join(" \\\\ "),
        where_clause(&defs)
    )
}

/// ` \quad \text{where} \quad σ₁ = …,\; σ₂ = …` of LaTeX definitions (empty without any).
fn where_clause(defs: &[(String, String)]) -> String {
    if defs.is_empty() {
        return String::new();
    }
    let defs: Vec<String> = defs.iter().map(|(n, d)| format!("{n} = {d}")).collect();
    format!(" \\quad \\text{{where}} \\quad {}", defs.join(",\\; "))
}

/// The expressions `roots` in SymPy's syntax (Python's infix: `*`, `/`, `**`, `sqrt(…)`,
/// `Abs`, `sign`, `sin` … `log`, rationals as `1/2`), in the canonical order of [`to_latex`],
/// variables named by [`sympy_symbol`] (`omega1`, `gamma3`, `p_psi`, `inertia_1`, `I_12`).
///
/// Written out in full up to `MAX_TREE_SYMPY` (20 000) nodes of expanded tree in all; beyond
/// that with their common subexpressions named `sigma{k}` (k from `first + 1`), which the second
/// element defines, inner ones first, each with only the names before it (so that
/// `sympify(definition, locals=…)` in order, then the roots, rebuilds the expressions).
pub fn to_sympy(
    g: &Graph,
    roots: &[Id],
    symbols: &LatexSymbols,
    first: usize,
) -> (Vec<String>, Vec<(String, String)>) {
    print_roots(g, roots, symbols, Style::Sympy, first, MAX_TREE_SYMPY)
}

/// A 3×3 matrix as [`matrix_to_latex`], its entries written with the intermediate quantities
/// `named` — `(variable, definition)`, the variables named as in [`INTERMEDIATES`] and standing
/// for their definitions in the entries (and in the later definitions) — and those defined
/// after the matrix, `\quad \text{where} \quad \gamma^{\mathsf{T}} J \gamma = …,\; \dot\psi = …`.
/// Only the quantities the matrix uses are defined. The entries are printed in full up to
/// `9 MAX_TREE` nodes in all (250 an entry); beyond it, with named common subexpressions
/// `\sigma_{k}` as [`to_latex`]. The definitions come in an order where each uses only the
/// ones before it.
pub fn matrix_to_latex_named(
    g: &Graph,
    m: &[[Id; 3]; 3],
    named: &[(Var, Id)],
    symbols: &LatexSymbols,
) -> String {
    let mut roots: Vec<Id> = m.iter().flatten().copied().collect();
    roots.extend(named.iter().map(|&(_, d)| d));
    let (texts, sigmas) = print_roots(g, &roots, symbols, Style::Latex, 0, MAX_TREE_NAMED);
    let (cells, values) = texts.split_at(9);
    let rows: Vec<String> = cells.chunks(3).map(|row| row.join(" & ")).collect();
    let mut defs: Vec<(String, String)> = (named.iter().zip(values))
        .map(|(&(v, _), t)| (latex_symbol(g.var_name(v), symbols), t.clone()))
        .collect();
    defs.extend(sigmas);
    // Only the definitions the matrix uses, directly or through another.
    let mut used = vec![false; defs.len()];
    let mut text = cells.concat();
    loop {
        let mut more = false;
        for (k, (name, value)) in defs.iter().enumerate() {
            if !used[k] && text.contains(name.as_str()) {
                used[k] = true;
                more = true;
                text.push_str(value);
            }
        }
        if !more {
            break;
        }
    }
    let mut left: Vec<(String, String)> = (defs.into_iter().zip(used))
        .filter_map(|(d, u)| u.then_some(d))
        .collect();
    // Each definition after the ones it uses.
    let mut ordered = Vec::with_capacity(left.len());
    while !left.is_empty() {
        let k = (0..left.len())
            .find(|&k| {
                (left.iter().enumerate())
                    .all(|(j, (name, _))| j == k || !left[k].1.contains(name.as_str()))
            })
            .unwrap_or(0);
        ordered.push(left.remove(k));
    }
    format!(
        "\\begin{{pmatrix}} {} \\end{{pmatrix}}{}",
        rows.join(" \\\\ "),
        where_clause(&ordered)
    )
}

/// `roots` with every node of `map`'s keys replaced by its value, rebuilt through the
/// simplifying constructors (children first; the replaced node's own children are not
/// visited).
pub fn replace_nodes(g: &mut Graph, roots: &[Id], map: &HashMap<Id, Id>) -> Vec<Id> {
    let Some(last) = roots.iter().map(|r| r.index()).max() else {
        return Vec::new();
    };
    let mut seen = vec![false; last + 1];
    let mut stack: Vec<Id> = Vec::new();
    for &r in roots {
        if !seen[r.index()] {
            seen[r.index()] = true;
            stack.push(r);
        }
    }
    while let Some(id) = stack.pop() {
        if map.contains_key(&id) {
            continue;
        }
        for c in g.node(id).children() {
            if !seen[c.index()] {
                seen[c.index()] = true;
                stack.push(c);
            }
        }
    }
    let mut image: Vec<Id> = (0..=last).map(Id::from_index).collect();
    for idx in (0..=last).filter(|&i| seen[i]) {
        let id = Id::from_index(idx);
        if let Some(&to) = map.get(&id) {
            image[idx] = to;
            continue;
        }
        let node = g.node(id);
        if node.children().all(|c| image[c.index()] == c) {
            continue;
        }
        let m = |x: Id| image[x.index()];
        image[idx] = match node {
            Node::Const(_) | Node::Var(_) => id,
            Node::Add(a, b) => g.add(m(a), m(b)),
            Node::Mul(a, b) => g.mul(m(a), m(b)),
            Node::Neg(a) => g.neg(m(a)),
            Node::Recip(a) => g.recip(m(a)),
            Node::Powi(a, n) => g.powi(m(a), n),
            Node::Powf(a, b) => g.powf(m(a), m(b)),
            Node::Func(f, a) => g.func(f, m(a)),
        };
    }
    roots.iter().map(|r| image[r.index()]).collect()
}

/// The name of the `k`-th (from 1) named subexpression.
fn definition_name(k: usize, style: Style) -> String {
    match style {
        Style::Latex | Style::LatexUnsorted => format!("\\sigma_{{{k}}}"),
        Style::Sympy => format!("sigma{k}"),
    }
}

/// Largest expanded tree (in all the roots) printed in full in SymPy's syntax.
const MAX_TREE_SYMPY: u64 = 20_000;

/// The text of each of `roots` and the definitions of their named subexpressions (none when
/// the roots are small enough to print inline), names numbered from `first + 1`.
fn print_roots(
    g: &Graph,
    roots: &[Id],
    symbols: &LatexSymbols,
    style: Style,
    first: usize,
    inline: u64,
) -> (Vec<String>, Vec<(String, String)>) {
    let Some(last) = roots.iter().map(|r| r.index()).max() else {
        return (Vec::new(), Vec::new());
    };
    // Uses of each node reachable from the roots (edges of the DAG, and the roots themselves),
    // and the reachable nodes in index order: the walks below visit only those (the graph
    // holds every output of the model; a formula reaches a small part of it).
    let mut uses = vec![0u32; last + 1];
    let mut seen = vec![false; last + 1];
    let mut stack: Vec<Id> = Vec::new();
    for &r in roots {
        uses[r.index()] += 1;
        if !seen[r.index()] {
            seen[r.index()] = true;
            stack.push(r);
        }
    }
    while let Some(id) = stack.pop() {
        for c in g.node(id).children() {
            uses[c.index()] += 1;
            if !seen[c.index()] {
                seen[c.index()] = true;
                stack.push(c);
            }
        }
    }
    let reachable: Vec<usize> = (0..=last).filter(|&i| seen[i]).collect();
    let mut size = vec![0u64; last + 1];
    for &i in &reachable {
        size[i] = g.nodes()[i]
            .children()
            .fold(1u64, |acc, c| acc.saturating_add(size[c.index()]));
    }
    let none: [usize; 0] = [];
    let vars = RefCell::new(Vec::new());
    let degrees = RefCell::new(Vec::new());
    // Inline when small: a matrix by the total of its entries (its entries share the same
    // subexpressions, e.g. γᵀJγ in each entry of G).
    let total_size = (roots.iter().map(|r| size[r.index()])).fold(0u64, u64::saturating_add);
    if total_size <= inline {
        let p = Printer {
            g,
            symbols,
            style,
            first,
            named: &none,
            expanding: None,
            vars: &vars,
            degrees: &degrees,
        };
        let texts = roots
            .iter()
            .map(|&r| {
                let mut s = String::new();
                p.expr(r, &mut s, 0);
                s
            })
            .collect();
        return (texts, Vec::new());
    }
    // Bottom up (children have smaller indices): the size with named children counting 1, and
    // the names.
    let mut reduced = vec![0u64; last + 1];
    // `named[i]` = k of `\sigma_{k}` for a named node, 0 for the others (dense: the printer
    // asks for every node it visits).
    let mut named: Vec<usize> = vec![0; last + 1];
    let mut order: Vec<Id> = Vec::new();
    for &i in &reachable {
        let id = Id::from_index(i);
        let node = g.node(id);
        reduced[i] = node.children().fold(1u64, |acc, c| {
            acc.saturating_add(if named[c.index()] != 0 {
                1
            } else {
                reduced[c.index()]
            })
        });
        let leaf = matches!(node, Node::Const(_) | Node::Var(_));
        if !leaf && uses[i] >= 2 && reduced[i] >= MIN_NAMED_SIZE {
            order.push(id);
            named[i] = order.len();
        }
    }
    let total =
        (order.iter().chain(roots).map(|id| reduced[id.index()])).fold(0u64, u64::saturating_add);
    if total > MAX_NAMED_TOTAL {
        let text = match style {
            Style::Latex | Style::LatexUnsorted => {
                format!("\\text{{(a formula of more than {MAX_NAMED_TOTAL} terms, not printed)}}")
            }
            Style::Sympy => "nan".to_string(),
        };
        return (vec![text; roots.len()], Vec::new());
    }
    let print = |id: Id, expanding: Option<Id>| {
        let p = Printer {
            g,
            symbols,
            style,
            first,
            named: &named,
            expanding,
            vars: &vars,
            degrees: &degrees,
        };
        let mut s = String::new();
        p.expr(id, &mut s, 0);
        s
    };
    let texts = roots.iter().map(|&r| print(r, None)).collect();
    let defs = order
        .iter()
        .enumerate()
        .map(|(k, &id)| (definition_name(first + k + 1, style), print(id, Some(id))))
        .collect();
    (texts, defs)
}

/// `f` rewritten with `|γ|² = 1` where that shortens it. The rule: each candidate replaces
/// every power `γᵢⁿ` (n ≥ 2) of one component by `(1 − γⱼ² − γₖ²) γᵢⁿ⁻²`, for i = 1, 2, 3,
/// and lets the simplifying constructors collect like terms (so `A(γ₁² + γ₂²) + Cγ₃²` becomes
/// `A + (C − A)γ₃²` with i = 1, 2 folded in two rounds); a candidate is kept when its printed
/// LaTeX is strictly shorter than the current one, and rounds repeat (at most 3) while one is.
/// The result equals `f` wherever `|γ| = 1`, not elsewhere.
pub fn on_sphere(g: &mut Graph, f: Id, gamma: [Var; 3], symbols: &LatexSymbols) -> Id {
    let mut best = f;
    let mut best_len = latex_len(g, best, symbols);
    for _ in 0..3 {
        let mut improved = false;
        for i in 0..3 {
            let cand = replace_square(g, best, gamma, i);
            if cand == best {
                continue;
            }
            let len = latex_len(g, cand, symbols);
            if len < best_len {
                best = cand;
                best_len = len;
                improved = true;
            }
        }
        if !improved {
            break;
        }
    }
    best
}

/// `f` with `γᵢⁿ → (1 − γⱼ² − γₖ²)γᵢⁿ⁻²` (n ≥ 2), rebuilt through the constructors.
fn replace_square(g: &mut Graph, f: Id, gamma: [Var; 3], i: usize) -> Id {
    let gi = g.var_id(gamma[i]);
    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
    let (gj, gk) = (g.var_id(gamma[j]), g.var_id(gamma[k]));
    let one = g.one();
    let (sj, sk) = (g.powi(gj, 2), g.powi(gk, 2));
    let s = g.add(sj, sk);
    let rest = g.sub(one, s);
    // Only the nodes `f` reaches, in index order (children first): the graph holds every
    // output of the model, and rebuilding all of it for each candidate of each formula was
    // most of what the derive cost (docs/performance.md, "Expansion cost").
    let mut seen = vec![false; f.index() + 1];
    seen[f.index()] = true;
    let mut stack = vec![f];
    let mut squares = false;
    while let Some(id) = stack.pop() {
        let node = g.node(id);
        squares |= matches!(node, Node::Powi(a, n) if a == gi && n >= 2);
        for c in node.children() {
            if !seen[c.index()] {
                seen[c.index()] = true;
                stack.push(c);
            }
        }
    }
    if !squares {
        return f;
    }
    // The image of each node (itself until rebuilt), by index.
    let mut map: Vec<Id> = (0..=f.index()).map(Id::from_index).collect();
    for idx in (0..=f.index()).filter(|&i| seen[i]) {
        let id = Id::from_index(idx);
        let node = g.node(id);
        let m = |x: Id, map: &[Id]| map[x.index()];
        // A node other than a sum whose children are their own images is its own image (as
        // in `Graph::substitute`).
        let same = match node {
            Node::Const(_) | Node::Var(_) | Node::Add(..) => false,
            Node::Powi(a, n) if a == gi && n >= 2 => false,
            Node::Mul(a, b) | Node::Powf(a, b) => map[a.index()] == a && map[b.index()] == b,
            Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Func(_, a) => {
                map[a.index()] == a
            }
        };
        if same {
            continue;
        }
        let new = match node {
            Node::Const(_) | Node::Var(_) => id,
            Node::Add(a, b) => {
                let (a, b) = (m(a, &map), m(b, &map));
                g.add(a, b)
            }
            Node::Mul(a, b) => {
                let (a, b) = (m(a, &map), m(b, &map));
                g.mul(a, b)
            }
            Node::Neg(a) => {
                let a = m(a, &map);
                g.neg(a)
            }
            Node::Recip(a) => {
                let a = m(a, &map);
                g.recip(a)
            }
            Node::Powi(a, n) if a == gi && n >= 2 => {
                let p = g.powi(gi, n - 2);
                g.mul(rest, p)
            }
            Node::Powi(a, n) => {
                let a = m(a, &map);
                g.powi(a, n)
            }
            Node::Powf(a, b) => {
                let (a, b) = (m(a, &map), m(b, &map));
                g.powf(a, b)
            }
            Node::Func(fu, a) => {
                let a = m(a, &map);
                g.func(fu, a)
            }
        };
        map[idx] = new;
    }
    map[f.index()]
}

/// `c` as `(p, q)` with `c = p/q`, `1 ≤ q ≤ 12`, when it is such a fraction exactly.
fn fraction(c: f64) -> Option<(i64, i64)> {
    (1..=12).find_map(|q| {
        let p = c * q as f64;
        (p.round() == p && p.abs() < 1e6).then_some((p as i64, q))
    })
}

/// A non-negative constant in LaTeX: an integer, `\frac{p}{q}`, or the decimal.
fn number(c: f64) -> String {
    match fraction(c) {
        Some((p, 1)) => format!("{p}"),
        Some((p, q)) => format!("\\frac{{{p}}}{{{q}}}"),
        None => format!("{c}"),
    }
}

/// "Not yet computed" in [`Printer::degrees`].
const UNKNOWN: i32 = i32::MIN;

struct Printer<'a> {
    g: &'a Graph,
    symbols: &'a LatexSymbols,
    style: Style,
    /// The number of the named subexpressions before these (their names go on from `first + 1`).
    first: usize,
    /// Named subexpressions: `named[i]` = k of `\sigma_{k}` for node i, 0 if not named.
    named: &'a [usize],
    /// The named subexpression whose definition is being printed (expanded, not named).
    expanding: Option<Id>,
    /// The symbol of each variable printed so far, by variable index ([`latex_symbol`] once
    /// per variable, not once per occurrence).
    vars: &'a RefCell<Vec<Option<String>>>,
    /// The degree in the state variables of each node met so far (for the order of terms),
    /// [`UNKNOWN`] for the others.
    degrees: &'a RefCell<Vec<i32>>,
}

/// The place of a term in a sum: decreasing degree, then decreasing exponents of
/// `ω₁ ω₂ ω₃ γ₁ γ₂ γ₃ p_ψ`, then the parameters by index (see [`to_latex`]).
type TermKey = (
    std::cmp::Reverse<i32>,
    std::cmp::Reverse<[i32; 7]>,
    Vec<(u32, i32)>,
);

impl Printer<'_> {
    /// The name `id` prints as, if it is a named subexpression (other than the one being
    /// defined).
    fn name_of(&self, id: Id) -> Option<String> {
        self.is_named(id)
            .then(|| definition_name(self.first + self.named[id.index()], self.style))
    }

    /// Whether `id` prints as a name ([`Printer::name_of`] without forming the name).
    fn is_named(&self, id: Id) -> bool {
        Some(id) != self.expanding && self.named.get(id.index()).is_some_and(|&k| k != 0)
    }

    fn latex(&self) -> bool {
        self.style != Style::Sympy
    }

    /// `(…)` around `text`.
    fn bracket(&self, text: &str) -> String {
        if self.latex() {
            format!("\\left({text}\\right)")
        } else {
            format!("({text})")
        }
    }

    /// The degree of `id` in the state variables (ω, γ, p_ψ): a sum's the largest of its
    /// terms', a quotient's the difference, a function's 0.
    fn degree(&self, id: Id) -> i32 {
        if let Some(&d) = self.degrees.borrow().get(id.index()) {
            if d != UNKNOWN {
                return d;
            }
        }
        let g = self.g;
        let d = match g.node(id) {
            Node::Const(_) | Node::Func(..) => 0,
            Node::Var(v) => i32::from(state_slot(g.var_name(v)).is_some()),
            Node::Add(a, b) => self.degree(a).max(self.degree(b)),
            Node::Mul(a, b) => self.degree(a).saturating_add(self.degree(b)),
            Node::Neg(a) => self.degree(a),
            Node::Recip(a) => -self.degree(a),
            Node::Powi(a, n) => self.degree(a).saturating_mul(n),
            Node::Powf(a, e) if g.as_const(e) == Some(0.5) => self.degree(a) / 2,
            Node::Powf(..) => 0,
        };
        // Grown on demand (most printing never asks: one term, or no sorting).
        let mut degrees = self.degrees.borrow_mut();
        if degrees.len() <= id.index() {
            degrees.resize(id.index() + 1, UNKNOWN);
        }
        degrees[id.index()] = d;
        d
    }

    /// The sort key of the term `t` of a sum.
    fn term_key(&self, t: Id) -> TermKey {
        /// The exponents of the state variables and the parameters of a product; a sum among
        /// its factors (`A₁(ω₁² + ω₂²)`) counts by the largest exponents of its terms, one
        /// level deep (`inner`).
        fn walk(
            p: &Printer,
            id: Id,
            n: i32,
            inner: bool,
            exps: &mut [i32; 7],
            params: &mut Vec<(u32, i32)>,
        ) {
            if p.is_named(id) {
                return;
            }
            match p.g.node(id) {
                Node::Mul(a, b) => {
                    walk(p, a, n, inner, exps, params);
                    walk(p, b, n, inner, exps, params);
                }
                Node::Neg(a) => walk(p, a, n, inner, exps, params),
                Node::Powi(a, m) if p.g.as_var(a).is_some() => {
                    walk(p, a, n * m, inner, exps, params)
                }
                Node::Var(v) => match state_slot(p.g.var_name(v)) {
                    Some((class, k)) => exps[usize::from(class * 3 + k).min(6)] += n,
                    None => params.push((v.index() as u32, -n)),
                },
                Node::Add(..) if !inner && n > 0 => {
                    let mut stack = vec![id];
                    let mut most = [0; 7];
                    while let Some(t) = stack.pop() {
                        match p.g.node(t) {
                            Node::Add(a, b) if !p.is_named(t) => stack.extend([a, b]),
                            _ => {
                                let mut e = [0; 7];
                                walk(p, t, 1, true, &mut e, &mut Vec::new());
                                for k in 0..7 {
                                    most[k] = most[k].max(e[k]);
                                }
                            }
                        }
                    }
                    for k in 0..7 {
                        exps[k] += n * most[k];
                    }
                }
                _ => {}
            }
        }
        let (mut exps, mut params) = ([0; 7], Vec::new());
        walk(self, t, 1, false, &mut exps, &mut params);
        params.sort_unstable();
        (
            std::cmp::Reverse(self.degree(t)),
            std::cmp::Reverse(exps),
            params,
        )
    }

    /// Binding strength: 1 sums, 2 products, 3 unary minus, 4 powers, 5 atoms.
    fn expr(&self, id: Id, out: &mut String, parent: u8) {
        if let Some(name) = self.name_of(id) {
            out.push_str(&name);
            return;
        }
        let g = self.g;
        let latex = self.latex();
        let (prec, text) = match g.node(id) {
            Node::Add(..) => (1, self.sum(id, false)),
            Node::Mul(..) | Node::Recip(_) => {
                let (negative, body, _) = self.product(id);
                if negative {
                    (3, format!("-{body}"))
                } else {
                    (2, body)
                }
            }
            Node::Neg(x) if matches!(g.node(x), Node::Add(..)) => (1, self.sum(x, true)),
            Node::Neg(x) if matches!(g.node(x), Node::Mul(..) | Node::Recip(_)) => {
                let (negative, body, _) = self.product(x);
                if negative {
                    (2, body)
                } else {
                    (3, format!("-{body}"))
                }
            }
            Node::Neg(x) => {
                let mut t = String::from("-");
                self.expr(x, &mut t, 3);
                (3, t)
            }
            Node::Const(b) => {
                let c = f64::from_bits(b);
                let (text, rational) = self.number(c.abs());
                if c < 0.0 {
                    (3, format!("-{text}"))
                } else if rational && !latex {
                    (2, text)
                } else {
                    (5, text)
                }
            }
            Node::Var(v) => {
                let mut vars = self.vars.borrow_mut();
                if vars.len() <= v.index() {
                    vars.resize(v.index() + 1, None);
                }
                let sym = vars[v.index()].get_or_insert_with(|| match self.style {
                    Style::Latex | Style::LatexUnsorted => {
                        latex_symbol(g.var_name(v), self.symbols)
                    }
                    Style::Sympy => sympy_symbol(g.var_name(v), self.symbols),
                });
                // A symbol of several letters (γᵀJγ) in brackets as a power's base.
                if parent >= 4 && sym.contains(' ') {
                    let sym = self.bracket(sym);
                    out.push_str(&sym);
                } else if parent >= 4 && latex && sym.contains('^') {
                    // `{x^*}^{2}`, not the double superscript `x^*^{2}`.
                    out.push_str(&format!("{{{sym}}}"));
                } else {
                    out.push_str(sym);
                }
                return;
            }
            Node::Powi(x, n) if n < 0 => {
                let mut t = String::new();
                self.power(x, -n, &mut t);
                if latex {
                    (5, format!("\\frac{{1}}{{{t}}}"))
                } else {
                    (2, format!("1/{t}"))
                }
            }
            Node::Powi(x, n) => {
                let mut t = String::new();
                self.power(x, n, &mut t);
                (4, t)
            }
            Node::Powf(x, e) if g.as_const(e) == Some(0.5) => {
                let mut t = String::new();
                self.expr(x, &mut t, 0);
                if latex {
                    (5, format!("\\sqrt{{{t}}}"))
                } else {
                    (5, format!("sqrt({t})"))
                }
            }
            Node::Powf(x, e) => {
                let (mut t, mut u) = (String::new(), String::new());
                self.expr(x, &mut t, 5);
                self.expr(e, &mut u, 0);
                if latex {
                    (4, format!("{t}^{{{u}}}"))
                } else {
                    (4, format!("{t}**({u})"))
                }
            }
            Node::Func(f, x) => {
                let mut t = String::new();
                self.expr(x, &mut t, 0);
                let s = match (latex, f) {
                    (true, Func::Sqrt) => format!("\\sqrt{{{t}}}"),
                    (true, Func::Abs) => format!("\\left|{t}\\right|"),
                    (true, Func::Sign) => format!("\\operatorname{{sgn}}\\left({t}\\right)"),
                    (true, _) => format!("\\{}\\left({t}\\right)", f.name()),
                    (false, Func::Sqrt) => format!("sqrt({t})"),
                    (false, Func::Abs) => format!("Abs({t})"),
                    (false, Func::Sign) => format!("sign({t})"),
                    (false, Func::Ln) => format!("log({t})"),
                    (false, _) => format!("{}({t})", f.name()),
                };
                (5, s)
            }
        };
        if prec < parent {
            out.push_str(&self.bracket(&text));
        } else {
            out.push_str(&text);
        }
    }

    /// A non-negative constant, and whether it is written as a quotient.
    fn number(&self, c: f64) -> (String, bool) {
        if self.latex() {
            let text = number(c);
            let quotient = text.starts_with("\\frac");
            return (text, quotient);
        }
        match fraction(c) {
            // Not Python's `NaN`/`inf` (Rust's `{:?}`): SymPy's names, never a symbol's.
            _ if c.is_nan() => ("nan".to_string(), false),
            _ if c.is_infinite() => ("oo".to_string(), false),
            Some((p, 1)) => (format!("{p}"), false),
            Some((p, q)) => (format!("{p}/{q}"), true),
            None => (format!("{c:?}"), false),
        }
    }

    /// The place of a factor in a product's normal form: parameters 0 (by index), ω or Ω 1,
    /// γ 2, `p_ψ` 3 (by index), anything else 4 (a power by its base).
    fn rank(&self, f: Id) -> (u8, u32) {
        match self.g.node(f) {
            Node::Var(v) => match state_slot(self.g.var_name(v)) {
                Some((class, k)) => (1 + class, u32::from(k)),
                None => (0, v.index() as u32),
            },
            Node::Powi(x, n) if n > 0 && self.g.as_var(x).is_some() => self.rank(x),
            _ => (4, 0),
        }
    }

    /// `x^{n}` (`x**n`) with the base bracketed unless it is an atom.
    fn power(&self, x: Id, n: i32, out: &mut String) {
        self.expr(x, out, 5);
        if self.latex() {
            out.push_str(&format!("^{{{n}}}"));
        } else {
            out.push_str(&format!("**{n}"));
        }
    }

    /// The terms of a sum (negated if `negate`), each with its sign, in the canonical order.
    fn sum(&self, id: Id, negate: bool) -> String {
        // Nested sums and negated sums are flattened into one list of signed terms.
        fn terms(p: &Printer, id: Id, flip: bool, acc: &mut Vec<(Id, bool)>) {
            if p.is_named(id) {
                acc.push((id, flip));
                return;
            }
            match p.g.node(id) {
                Node::Add(a, b) => {
                    terms(p, a, flip, acc);
                    terms(p, b, flip, acc);
                }
                Node::Neg(x) if matches!(p.g.node(x), Node::Add(..)) => terms(p, x, !flip, acc),
                _ => acc.push((id, flip)),
            }
        }
        let mut ts = Vec::new();
        terms(self, id, negate, &mut ts);
        // Like terms collected: each term as its coefficient times its other factors, the
        // coefficients of equal factors (hash-consing makes equal subexpressions one node)
        // added, and a term whose coefficient adds up to 0 dropped (`1 - γ₃² - 1 + 1` is
        // `1 - γ₃²`, `A₁ψ̇ + A₁ψ̇` is `2 A₁ψ̇`). Groups in the order of their first term.
        type Group = (f64, Vec<Id>, Vec<Id>, Id);
        let mut groups: Vec<Group> = Vec::new();
        let mut index: HashMap<(Vec<Id>, Vec<Id>), usize> = HashMap::new();
        for (t, flip) in ts {
            let (mut coef, mut num, mut den) = (if flip { -1.0 } else { 1.0 }, vec![], vec![]);
            self.factors(t, &mut coef, &mut num, &mut den);
            let (mut kn, mut kd) = (num.clone(), den.clone());
            kn.sort_unstable();
            kd.sort_unstable();
            match index.entry((kn, kd)) {
                std::collections::hash_map::Entry::Occupied(e) => groups[*e.get()].0 += coef,
                std::collections::hash_map::Entry::Vacant(e) => {
                    e.insert(groups.len());
                    groups.push((coef, num, den, t));
                }
            }
        }
        groups.retain(|g| g.0 != 0.0);
        if groups.is_empty() {
            return "0".to_string();
        }
        let sorted = self.style != Style::LatexUnsorted && groups.len() > 1;
        let mut printed: Vec<(TermKey, bool, String)> = groups
            .into_iter()
            .map(|(coef, num, den, t)| {
                let (negative, body, _) = self.product_of(coef, &num, &den);
                let key = if sorted {
                    self.term_key(t)
                } else {
                    Default::default()
                };
                (key, negative, body)
            })
            .collect();
        // Stable: terms of equal keys keep the order of the graph.
        if sorted {
            printed.sort_by(|a, b| a.0.cmp(&b.0));
        }
        // A leading minus after the first positive term, as SymPy prints `1 - x**2`.
        if sorted && printed.first().is_some_and(|t| t.1) {
            if let Some(k) = printed.iter().position(|t| !t.1) {
                let t = printed.remove(k);
                printed.insert(0, t);
            }
        }
        let mut out = String::new();
        for (k, (_, negative, body)) in printed.into_iter().enumerate() {
            match (k, negative) {
                (0, true) => out.push('-'),
                (0, false) => {}
                (_, true) => out.push_str(" - "),
                (_, false) => out.push_str(" + "),
            }
            out.push_str(&body);
        }
        out
    }

    /// A product as `(negative, text, quotient)`: the coefficient first, factors side by side
    /// (joined by `*` in SymPy's syntax), a denominator as `\frac` (`(…)/(…)`).
    fn product(&self, id: Id) -> (bool, String, bool) {
        let (mut coef, mut num, mut den) = (1.0, Vec::new(), Vec::new());
        self.factors(id, &mut coef, &mut num, &mut den);
        self.product_of(coef, &num, &den)
    }

    /// The factors of `id` (a product, or any term): the numeric coefficient multiplied into
    /// `coef`, the other factors of the numerator and of the denominator pushed.
    fn factors(&self, id: Id, coef: &mut f64, num: &mut Vec<Id>, den: &mut Vec<Id>) {
        if self.is_named(id) {
            num.push(id);
            return;
        }
        match self.g.node(id) {
            Node::Mul(a, b) => {
                self.factors(a, coef, num, den);
                self.factors(b, coef, num, den);
            }
            Node::Neg(x) => {
                *coef = -*coef;
                self.factors(x, coef, num, den);
            }
            Node::Const(b) => *coef *= f64::from_bits(b),
            Node::Recip(x) => den.push(x),
            // A negative integer power goes to the denominator as itself (printed
            // `x^{|n|}` by `join`).
            Node::Powi(_, n) if n < 0 => den.push(id),
            _ => num.push(id),
        }
    }

    /// The product `coef · num / den` as [`Printer::product`] prints it.
    fn product_of(&self, coef: f64, num: &[Id], den: &[Id]) -> (bool, String, bool) {
        let g = self.g;
        let latex = self.latex();
        let sep = if latex { " " } else { "*" };
        // Normal form: the parameters, then the angular velocity, γ, p_ψ, then the rest; a
        // lone factor (a whole numerator or denominator) without brackets. Returns the text
        // and whether it is one factor.
        let join = |ids: &[Id], bare: bool| {
            let mut t = String::new();
            let mut seen: Vec<Id> = Vec::new();
            for &f in ids {
                if !seen.contains(&f) {
                    seen.push(f);
                }
            }
            seen.sort_by_key(|&f| self.rank(f));
            let alone = bare && seen.len() == 1;
            for (k, &f) in seen.iter().enumerate() {
                if k > 0 {
                    t.push_str(sep);
                }
                let n = ids.iter().filter(|&&x| x == f).count() as i32;
                match g.node(f) {
                    _ if self.is_named(f) && n > 1 => self.power(f, n, &mut t),
                    Node::Powi(x, m) if m < 0 && !self.is_named(f) => self.power(x, -m * n, &mut t),
                    _ if n > 1 => self.power(f, n, &mut t),
                    // In SymPy's syntax a factor of a quotient binds like a power.
                    _ if !latex => self.expr(f, &mut t, 4),
                    _ => self.expr(f, &mut t, if alone { 0 } else { 3 }),
                }
            }
            (t, alone || (!latex && seen.len() == 1))
        };
        let a = coef.abs();
        let negative = coef < 0.0;
        if den.is_empty() {
            let text = match (a == 1.0, num.is_empty()) {
                (_, true) => return (negative, self.number(a).0, false),
                (true, false) => join(num, false).0,
                (false, false) => format!("{}{sep}{}", self.number(a).0, join(num, false).0),
            };
            return (negative, text, false);
        }
        // With a denominator: a rational coefficient p/q goes into the fraction.
        let (p, q) = match fraction(a) {
            Some((p, q)) => (number(p as f64), (q != 1).then(|| q.to_string())),
            None => (self.number(a).0, None),
        };
        let (top, top_one) = match (p.as_str(), num.is_empty()) {
            (_, true) => (p.clone(), true),
            ("1", false) => join(num, true),
            (_, false) => (format!("{p}{sep}{}", join(num, false).0), false),
        };
        let (bottom, bottom_one) = match q {
            Some(q) => (format!("{q}{sep}{}", join(den, false).0), false),
            None => join(den, true),
        };
        if latex {
            return (negative, format!("\\frac{{{top}}}{{{bottom}}}"), true);
        }
        let wrap = |s: String, one: bool| if one { s } else { format!("({s})") };
        let text = format!("{}/{}", wrap(top, top_one), wrap(bottom, bottom_one));
        (negative, text, true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A graph with the parameters `mass g l` and `inertia[0..3]` (declared in that order),
    /// then `ω₁ ω₂ ω₃ γ₁ γ₂ γ₃ p_ψ`.
    fn top() -> (Graph, Vec<Id>) {
        let mut g = Graph::new();
        let names = [
            "mass",
            "g",
            "l",
            "inertia[0]",
            "inertia[1]",
            "inertia[2]",
            "ω₁",
            "ω₂",
            "ω₃",
            "γ₁",
            "γ₂",
            "γ₃",
            "p_ψ",
        ];
        let ids = names.iter().map(|n| g.var(*n)).collect();
        (g, ids)
    }

    fn symbols() -> LatexSymbols {
        LatexSymbols {
            fields: [("inertia".to_string(), "I".to_string())]
                .into_iter()
                .collect(),
            big_omega: false,
            sympy_names: HashMap::new(),
        }
    }

    fn both(g: &Graph, f: Id) -> (String, String) {
        let s = symbols();
        (to_latex(g, f, &s), to_sympy(g, &[f], &s, 0).0.concat())
    }

    /// `½(I₃ω₃² + I₁ω₁² + I₂ω₂²) − l g m γ₃`, built in a scrambled order, prints in the
    /// canonical one: by degree, then ω₁ before ω₂ before ω₃; parameters before variables, in
    /// the order of the fields.
    #[test]
    fn terms_and_factors_in_canonical_order() {
        let (mut g, v) = top();
        let [m, gr, l, i1, i2, i3, w1, w2, w3, _, _, g3, _] = v[..] else {
            unreachable!()
        };
        let sq = |g: &mut Graph, i, w| {
            let w2 = g.powi(w, 2);
            g.mul(i, w2)
        };
        let t3 = sq(&mut g, i3, w3);
        let t1 = sq(&mut g, i1, w1);
        let t2 = sq(&mut g, i2, w2);
        let s = g.add(t3, t1);
        let s = g.add(s, t2);
        let half = g.constant(0.5);
        let kinetic = g.mul(half, s);
        let p = g.mul(l, g3);
        let p = g.mul(gr, p);
        let p = g.mul(p, m);
        let lag = g.sub(kinetic, p);
        let (tex, py) = both(&g, lag);
        assert_eq!(
            tex,
            "\\frac{1}{2} \\left(I_{1} \\omega_1^{2} + I_{2} \\omega_2^{2} + I_{3} \\omega_3^{2}\\right) \
             - \\mathit{mass} \\mathit{g} \\mathit{l} \\gamma_3"
        );
        assert_eq!(
            py,
            "1/2*(inertia_1*omega1**2 + inertia_2*omega2**2 + inertia_3*omega3**2) - mass*g*l*gamma3"
        );
        // Expanded: degree 2 before degree 1, ω before γ.
        let k1 = g.mul(half, t1);
        let k3 = g.mul(half, t3);
        let f = g.add(p, k3);
        let f = g.add(f, k1);
        let (tex, py) = both(&g, f);
        assert_eq!(
            tex,
            "\\frac{1}{2} I_{1} \\omega_1^{2} + \\frac{1}{2} I_{3} \\omega_3^{2} \
             + \\mathit{mass} \\mathit{g} \\mathit{l} \\gamma_3"
        );
        assert_eq!(
            py,
            "1/2*inertia_1*omega1**2 + 1/2*inertia_3*omega3**2 + mass*g*l*gamma3"
        );
    }

    /// Mixed monomials: `ω₁² + ω₁ω₂ + ω₂²` whatever the order built; a leading negative term
    /// goes after the first positive one; a constant last.
    #[test]
    fn graded_order_and_signs() {
        let (mut g, v) = top();
        let [_, _, _, _, _, _, w1, w2, _, g1, g2, g3, p] = v[..] else {
            unreachable!()
        };
        let a = g.powi(w2, 2);
        let b = g.mul(w1, w2);
        let c = g.powi(w1, 2);
        let s = g.add(a, b);
        let s = g.add(s, c);
        assert_eq!(both(&g, s).1, "omega1**2 + omega1*omega2 + omega2**2");
        // A bracketed sum counts by its leading term: m(ω₁² + ω₂²) before l ω₃².
        let [m, _, l, _, _, _, _, _, w3, ..] = v[..] else {
            unreachable!()
        };
        let w12 = g.add(a, c);
        let t12 = g.mul(m, w12);
        let c3 = g.powi(w3, 2);
        let t3 = g.mul(l, c3);
        let k = g.add(t3, t12);
        assert_eq!(both(&g, k).1, "mass*(omega1**2 + omega2**2) + l*omega3**2");
        // 1 − γ₁² − γ₂² (as on_sphere writes γ₃²), and γ₃ + p_ψ²/(2γ₃) (of equal degree,
        // γ₃ first by its exponents).
        let one = g.one();
        let s1 = g.powi(g1, 2);
        let s2 = g.powi(g2, 2);
        let s = g.add(s1, s2);
        let rest = g.sub(one, s);
        assert_eq!(
            both(&g, rest),
            (
                "1 - \\gamma_1^{2} - \\gamma_2^{2}".to_string(),
                "1 - gamma1**2 - gamma2**2".to_string()
            )
        );
        let neg = g.neg(s);
        assert_eq!(both(&g, neg).1, "-gamma1**2 - gamma2**2");
        let p2 = g.powi(p, 2);
        let two = g.constant(2.0);
        let d = g.mul(two, g3);
        let q = g.div(p2, d);
        let f = g.add(g3, q);
        assert_eq!(
            both(&g, f),
            (
                "\\gamma_3 + \\frac{p_\\psi^{2}}{2 \\gamma_3}".to_string(),
                "gamma3 + p_psi**2/(2*gamma3)".to_string()
            )
        );
        let r = g.func(Func::Sqrt, rest);
        let f = g.div(p, r);
        assert_eq!(both(&g, f).1, "p_psi/sqrt(1 - gamma1**2 - gamma2**2)");
    }

    /// A matrix with a named intermediate: the entries use `\mu` and its definition follows,
    /// and a quantity the matrix does not use is not defined.
    #[test]
    fn matrix_with_named_intermediates() {
        let (mut g, v) = top();
        let [m, _, _, _, _, _, _, _, _, g1, g2, g3, p] = v[..] else {
            unreachable!()
        };
        let s1 = g.powi(g1, 2);
        let s2 = g.powi(g2, 2);
        let s = g.add(s1, s2);
        let mu = g.mul(m, s);
        let e11 = g.mul(mu, g3);
        let e22 = g.powi(mu, 2);
        let zero = g.zero();
        let unused = g.mul(p, g3);
        let [v_psi, v_mu] = ["ψ̇", "μ"].map(|n| g.new_var(n));
        let map: HashMap<Id, Id> = [(mu, g.var_id(v_mu))].into_iter().collect();
        let new = replace_nodes(&mut g, &[e11, e22], &map);
        let mat = [
            [new[0], zero, zero],
            [zero, new[1], zero],
            [zero, zero, zero],
        ];
        let tex = matrix_to_latex_named(&g, &mat, &[(v_psi, unused), (v_mu, mu)], &symbols());
        assert_eq!(
            tex,
            "\\begin{pmatrix} \\mu \\gamma_3 & 0 & 0 \\\\ 0 & \\mu^{2} & 0 \\\\ 0 & 0 & 0 \\end{pmatrix} \
             \\quad \\text{where} \\quad \\mu = \\mathit{mass} \\left(\\gamma_1^{2} + \\gamma_2^{2}\\right)"
        );
    }

    /// A field's symbol with a subscript of its own is wrapped before its index (issue 47: the
    /// gyrostat's `r_c_{1}` was a "Double subscript" error), a superscript before a power.
    #[test]
    fn symbols_with_subscripts_are_wrapped() {
        let s = LatexSymbols {
            fields: [
                ("com", "r_c"),
                ("c0", "c_0"),
                ("x", "x^*"),
                ("inertia", "I"),
            ]
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .into_iter()
            .collect(),
            ..LatexSymbols::default()
        };
        assert_eq!(latex_symbol("com[0]", &s), "{r_c}_{1}");
        assert_eq!(latex_symbol("c0[2]", &s), "{c_0}_{3}");
        assert_eq!(latex_symbol("inertia[(0,1)]", &s), "I_{12}");
        assert_eq!(latex_symbol("com", &s), "r_c");
        let mut g = Graph::new();
        let x = g.var("x");
        let x2 = g.powi(x, 2);
        assert_eq!(to_latex(&g, x2, &s), "{x^*}^{2}");
    }

    /// Like terms are collected and constants added up: `A₁ψ̇ − 2A₁ψ̇γ₁² + A₁ψ̇` prints as
    /// `2 A₁ ψ̇ − 2 A₁ ψ̇ γ₁²`, `1 − γ₃² − 1 + 1` as `1 − γ₃²` (issue 47: G of the heavy top had
    /// `A_1 \dot\psi … + A_1 \dot\psi`, the SymPy text `1 - gamma3**2 - 1 + 1`).
    #[test]
    fn like_terms_are_collected() {
        let (mut g, v) = top();
        let [_, _, _, i1, _, _, _, _, _, g1, _, g3, p] = v[..] else {
            unreachable!()
        };
        // (a + γ₁) + (a − 2aγ₁²) − γ₁, the like terms in different sums (as in G's
        // `A_1 \dot\psi - … + A_1 \dot\psi`): the constructors keep them apart.
        let a = g.mul(i1, p);
        let two = g.constant(2.0);
        let s1 = g.powi(g1, 2);
        let b = g.mul(a, s1);
        let b = g.mul(two, b);
        // The same product associated the other way: another node.
        let a2 = g.mul(p, i1);
        let u = g.add(a, g1);
        let v = g.sub(a2, b);
        let f = g.add(u, v);
        let f = g.sub(f, g1);
        let (tex, py) = both(&g, f);
        assert_eq!(tex, "2 I_{1} p_\\psi - 2 I_{1} \\gamma_1^{2} p_\\psi");
        assert_eq!(py, "2*inertia_1*p_psi - 2*inertia_1*gamma1**2*p_psi");
        // (1 − γ₃²) + (γ₁ − 1) + (1 − γ₁): constants from different sums.
        let one = g.one();
        let s3 = g.powi(g3, 2);
        let c1 = g.sub(one, s3);
        let c2 = g.sub(g1, one);
        let c3 = g.sub(one, g1);
        let d = g.add(c1, c2);
        let d = g.add(d, c3);
        assert_eq!(both(&g, d).1, "1 - gamma3**2");
    }

    /// Named subexpressions in SymPy's syntax: numbered from `first + 1`, defined in order.
    #[test]
    fn sympy_names_and_symbols() {
        let s = LatexSymbols::default();
        assert_eq!(sympy_symbol("ω₂", &s), "omega2");
        let big = LatexSymbols {
            big_omega: true,
            ..LatexSymbols::default()
        };
        assert_eq!(sympy_symbol("ω₂", &big), "Omega2");
        assert_eq!(sympy_symbol("γ₃", &s), "gamma3");
        assert_eq!(sympy_symbol("p_ψ", &s), "p_psi");
        assert_eq!(sympy_symbol("mgl", &s), "mgl");
        assert_eq!(sympy_symbol("com[2]", &s), "com_3");
        assert_eq!(sympy_symbol("inertia[(0,2)]", &s), "inertia_13");
        assert_eq!(definition_name(3, Style::Sympy), "sigma3");
    }

    /// A NaN or infinite constant is SymPy's `nan` or `oo` (not Rust's `NaN`, `inf`: names
    /// SymPy would take for symbols).
    #[test]
    fn non_finite_constants_in_sympy() {
        let (mut g, ids) = top();
        let inf = g.constant(f64::INFINITY);
        let nan = g.constant(f64::NAN);
        let a = g.mul(inf, ids[0]);
        let b = g.mul(nan, ids[1]);
        let s = LatexSymbols::default();
        assert_eq!(to_sympy(&g, &[a], &s, 0).0.concat(), "oo*mass");
        assert_eq!(to_sympy(&g, &[b], &s, 0).0.concat(), "nan*g");
    }

    /// Every parameter gets a free identifier and a name of its own: keywords, the text's
    /// functions and constants, `sigmaK`, non-ASCII names are renamed (the name kept); a name
    /// that is the state's or another's gets `_` (a scalar before a component); an identifier
    /// taken by a parameter as it is is not given to another.
    #[test]
    fn sympy_identifiers_are_free_and_distinct() {
        let vars = [
            "lambda", "sin", "nan", "Matrix", "sigma12", "α", "mgl", "omega1", "com[0]", "com[1]",
            "com_1", "lambda_", "I[(0,1)]", "r#type",
        ];
        let got = sympy_identifiers(&vars);
        let want = [
            ("lambda__", "lambda"),
            ("sin_", "sin"),
            ("nan_", "nan"),
            ("Matrix_", "Matrix"),
            ("sigma12_", "sigma12"),
            ("_3b1_", "α"),
            ("mgl", "mgl"),
            ("omega1_", "omega1_"),
            ("com_1_", "com_1_"),
            ("com_2", "com_2"),
            ("com_1", "com_1"),
            ("lambda_", "lambda_"),
            ("I_12", "I_12"),
            ("r_23type_", "r#type"),
        ];
        let got: Vec<(&str, &str)> = got.iter().map(|(i, n)| (i.as_str(), n.as_str())).collect();
        assert_eq!(got, want);
        let mut with = LatexSymbols::default();
        with.sympy_names.insert("sin".into(), "sin_".into());
        assert_eq!(sympy_symbol("sin", &with), "sin_");
        assert_eq!(sympy_symbol("γ₃", &with), "gamma3");
    }
}
