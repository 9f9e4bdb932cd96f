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
//! [`on_sphere`] rewrites an expression with `|γ|² = 1` where that shortens it (the rule is on
//! the function). A long formula is printed with its common subexpressions named
//! (`… \quad \text{where} \quad \sigma_{1} = …`, see [`to_latex`]).

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
        format!("{base_tex}_{{{idx}}}")
    }
}

/// The expression `root` in LaTeX (see the module documentation).
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
    let (main, defs) = print_roots(g, &[root], symbols);
    format!("{}{defs}", main.concat())
}

/// A 3×3 matrix of expressions as `\begin{pmatrix} … \end{pmatrix}`; when named
/// subexpressions are needed (see [`to_latex`]) they are shared by the entries and defined after
/// the matrix.
pub fn matrix_to_latex(g: &Graph, m: &[[Id; 3]; 3], symbols: &LatexSymbols) -> String {
    let roots: Vec<Id> = m.iter().flatten().copied().collect();
    let (cells, defs) = print_roots(g, &roots, symbols);
    let rows: Vec<String> = cells.chunks(3).map(|row| row.join(" & ")).collect();
    format!(
        "\\begin{{pmatrix}} {} \\end{{pmatrix}}{defs}",
        rows.join(" \\\\ ")
    )
}

/// The name of the `k`-th (from 1) named subexpression.
fn definition_name(k: usize) -> String {
    format!("\\sigma_{{{k}}}")
}

/// The LaTeX of each of `roots` and the `where` clause of their named subexpressions (empty
/// when every root is small enough to print inline).
fn print_roots(g: &Graph, roots: &[Id], symbols: &LatexSymbols) -> (Vec<String>, String) {
    let Some(last) = roots.iter().map(|r| r.index()).max() else {
        return (Vec::new(), String::new());
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
    // Inline when small: a matrix by the total of its entries (its entries share the same
    // subexpressions, e.g. γᵀJγ in each entry of G).
    let total_size = (roots.iter().map(|r| size[r.index()])).fold(0u64, u64::saturating_add);
    if total_size <= MAX_TREE {
        let p = Printer {
            g,
            symbols,
            named: &none,
            expanding: None,
            vars: &vars,
        };
        let texts = roots
            .iter()
            .map(|&r| {
                let mut s = String::new();
                p.expr(r, &mut s, 0);
                s
            })
            .collect();
        return (texts, String::new());
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
        let text =
            format!("\\text{{(a formula of more than {MAX_NAMED_TOTAL} terms, not printed)}}");
        return (vec![text; roots.len()], String::new());
    }
    let print = |id: Id, expanding: Option<Id>| {
        let p = Printer {
            g,
            symbols,
            named: &named,
            expanding,
            vars: &vars,
        };
        let mut s = String::new();
        p.expr(id, &mut s, 0);
        s
    };
    let texts = roots.iter().map(|&r| print(r, None)).collect();
    let defs: Vec<String> = order
        .iter()
        .enumerate()
        .map(|(k, &id)| format!("{} = {}", definition_name(k + 1), print(id, Some(id))))
        .collect();
    let clause = if defs.is_empty() {
        String::new()
    } else {
        format!(" \\quad \\text{{where}} \\quad {}", defs.join(",\\; "))
    };
    (texts, clause)
}

/// `f` rewritten with `|γ|² = 1` where that shortens it. The rule: each candidate replaces
/// every power `γᵢⁿ` (n ≥ 2) of one component by `(1 − γⱼ² − γₖ²) γᵢⁿ⁻²`, for i = 1, 2, 3,
/// and lets the simplifying constructors collect like terms (so `A(γ₁² + γ₂²) + Cγ₃²` becomes
/// `A + (C − A)γ₃²` with i = 1, 2 folded in two rounds); a candidate is kept when its printed
/// LaTeX is strictly shorter than the current one, and rounds repeat (at most 3) while one is.
/// The result equals `f` wherever `|γ| = 1`, not elsewhere.
pub fn on_sphere(g: &mut Graph, f: Id, gamma: [Var; 3], symbols: &LatexSymbols) -> Id {
    let mut best = f;
    let mut best_len = to_latex(g, best, symbols).len();
    for _ in 0..3 {
        let mut improved = false;
        for i in 0..3 {
            let cand = replace_square(g, best, gamma, i);
            if cand == best {
                continue;
            }
            let len = to_latex(g, cand, symbols).len();
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

struct Printer<'a> {
    g: &'a Graph,
    symbols: &'a LatexSymbols,
    /// Named subexpressions: `named[i]` = k of `\sigma_{k}` for node i, 0 if not named.
    named: &'a [usize],
    /// The named subexpression whose definition is being printed (expanded, not named).
    expanding: Option<Id>,
    /// The symbol of each variable printed so far, by variable index ([`latex_symbol`] once
    /// per variable, not once per occurrence).
    vars: &'a RefCell<Vec<Option<String>>>,
}

impl Printer<'_> {
    /// The name `id` prints as, if it is a named subexpression (other than the one being
    /// defined).
    fn name_of(&self, id: Id) -> Option<String> {
        self.is_named(id)
            .then(|| definition_name(self.named[id.index()]))
    }

    /// Whether `id` prints as a name ([`Printer::name_of`] without forming the name).
    fn is_named(&self, id: Id) -> bool {
        Some(id) != self.expanding && self.named.get(id.index()).is_some_and(|&k| k != 0)
    }

    /// Binding strength: 1 sums, 2 products, 3 unary minus, 4 powers, 5 atoms.
    fn expr(&self, id: Id, out: &mut String, parent: u8) {
        if let Some(name) = self.name_of(id) {
            out.push_str(&name);
            return;
        }
        let g = self.g;
        let (prec, text) = match g.node(id) {
            Node::Add(..) => (1, self.sum(id, false)),
            Node::Mul(..) | Node::Recip(_) => {
                let (negative, body) = self.product(id);
                if negative {
                    (3, format!("-{body}"))
                } else {
                    (2, body)
                }
            }
            Node::Neg(x) if matches!(g.node(x), Node::Add(..)) => (1, self.sum(x, true)),
            Node::Neg(x) if matches!(g.node(x), Node::Mul(..) | Node::Recip(_)) => {
                let (negative, body) = self.product(x);
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
                if c < 0.0 {
                    (3, format!("-{}", number(-c)))
                } else {
                    (5, number(c))
                }
            }
            Node::Var(v) => {
                let mut vars = self.vars.borrow_mut();
                if vars.len() <= v.index() {
                    vars.resize(v.index() + 1, None);
                }
                let sym = vars[v.index()]
                    .get_or_insert_with(|| latex_symbol(g.var_name(v), self.symbols));
                out.push_str(sym);
                return;
            }
            Node::Powi(x, n) if n < 0 => {
                let mut t = String::new();
                self.power(x, -n, &mut t);
                (5, format!("\\frac{{1}}{{{t}}}"))
            }
            Node::Powi(x, n) => {
                let mut t = String::new();
                self.power(x, n, &mut t);
                (4, t)
            }
            Node::Powf(x, e) if g.as_const(e) == Some(0.5) => {
                let mut t = String::new();
                self.expr(x, &mut t, 0);
                (5, format!("\\sqrt{{{t}}}"))
            }
            Node::Powf(x, e) => {
                let (mut t, mut u) = (String::new(), String::new());
                self.expr(x, &mut t, 5);
                self.expr(e, &mut u, 0);
                (4, format!("{t}^{{{u}}}"))
            }
            Node::Func(f, x) => {
                let mut t = String::new();
                self.expr(x, &mut t, 0);
                let s = match f {
                    Func::Sqrt => format!("\\sqrt{{{t}}}"),
                    Func::Abs => format!("\\left|{t}\\right|"),
                    Func::Sign => format!("\\operatorname{{sgn}}\\left({t}\\right)"),
                    Func::Sin | Func::Cos | Func::Tan | Func::Exp | Func::Ln => {
                        format!("\\{}\\left({t}\\right)", f.name())
                    }
                };
                (5, s)
            }
        };
        if prec < parent {
            out.push_str("\\left(");
            out.push_str(&text);
            out.push_str("\\right)");
        } else {
            out.push_str(&text);
        }
    }

    /// The place of a factor in a product's normal form: parameters 0, `p_ψ` 1, ω or Ω 2, γ 3,
    /// anything else 4 (a power by its base).
    fn rank(&self, f: Id) -> u8 {
        match self.g.node(f) {
            Node::Var(v) => {
                let name = self.g.var_name(v);
                if name == "p_ψ" {
                    1
                } else if name.starts_with('ω') {
                    2
                } else if name.starts_with('γ') {
                    3
                } else {
                    0
                }
            }
            Node::Powi(x, n) if n > 0 => self.rank(x),
            _ => 4,
        }
    }

    /// `x^{n}` with the base bracketed unless it is an atom.
    fn power(&self, x: Id, n: i32, out: &mut String) {
        self.expr(x, out, 5);
        out.push_str(&format!("^{{{n}}}"));
    }

    /// The terms of a sum (negated if `negate`), each with its sign.
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
        let g = self.g;
        let mut ts = Vec::new();
        terms(self, id, negate, &mut ts);
        let mut out = String::new();
        for (k, (t, negate)) in ts.into_iter().enumerate() {
            let mut body = String::new();
            let negative = match g.node(t) {
                _ if self.is_named(t) => {
                    self.expr(t, &mut body, 2);
                    false
                }
                Node::Neg(x) => {
                    self.expr(x, &mut body, 2);
                    true
                }
                Node::Const(b) if f64::from_bits(b) < 0.0 => {
                    body = number(-f64::from_bits(b));
                    true
                }
                Node::Mul(..) | Node::Recip(_) => {
                    let (negative, text) = self.product(t);
                    body = text;
                    negative
                }
                _ => {
                    self.expr(t, &mut body, 2);
                    false
                }
            };
            match (k, negative != negate) {
                (0, true) => out.push('-'),
                (0, false) => {}
                (_, true) => out.push_str(" - "),
                (_, false) => out.push_str(" + "),
            }
            out.push_str(&body);
        }
        out
    }

    /// A product as `(negative, text)`: the coefficient first, factors side by side, a
    /// denominator as `\frac`.
    fn product(&self, id: Id) -> (bool, String) {
        fn factors(p: &Printer, id: Id, coef: &mut f64, num: &mut Vec<Id>, den: &mut Vec<Id>) {
            if p.is_named(id) {
                num.push(id);
                return;
            }
            match p.g.node(id) {
                Node::Mul(a, b) => {
                    factors(p, a, coef, num, den);
                    factors(p, b, coef, num, den);
                }
                Node::Neg(x) => {
                    *coef = -*coef;
                    factors(p, x, coef, num, den);
                }
                Node::Const(b) => *coef *= f64::from_bits(b),
                Node::Recip(x) => den.push(x),
                // A negative integer power goes to the denominator as itself (printed
                // `x^{|n|}` by `join`).
                Node::Powi(_, n) if n < 0 => den.push(id),
                _ => num.push(id),
            }
        }
        let g = self.g;
        let (mut coef, mut num, mut den) = (1.0, Vec::new(), Vec::new());
        factors(self, id, &mut coef, &mut num, &mut den);
        // Normal form: the parameters, then p_ψ, the angular velocity, γ, then the rest; a
        // lone factor (a whole numerator or denominator) without brackets.
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
                    t.push(' ');
                }
                let n = ids.iter().filter(|&&x| x == f).count() as i32;
                match g.node(f) {
                    _ if self.is_named(f) && n > 1 => self.power(f, n, &mut t),
                    Node::Powi(x, m) if m < 0 && !self.is_named(f) => self.power(x, -m * n, &mut t),
                    _ if n > 1 => self.power(f, n, &mut t),
                    _ => self.expr(f, &mut t, if alone { 0 } else { 3 }),
                }
            }
            t
        };
        let a = coef.abs();
        let negative = coef < 0.0;
        if den.is_empty() {
            let text = match (a == 1.0, num.is_empty()) {
                (_, true) => number(a),
                (true, false) => join(&num, false),
                (false, false) => format!("{} {}", number(a), join(&num, false)),
            };
            return (negative, text);
        }
        // With a denominator: a rational coefficient p/q goes into the fraction.
        let (p, q) = match fraction(a) {
            Some((p, q)) => (number(p as f64), (q != 1).then(|| q.to_string())),
            None => (number(a), None),
        };
        let top = match (p.as_str(), num.is_empty()) {
            (_, true) => p.clone(),
            ("1", false) => join(&num, true),
            (_, false) => format!("{p} {}", join(&num, false)),
        };
        let bottom = match q {
            Some(q) => format!("{q} {}", join(&den, false)),
            None => join(&den, true),
        };
        (negative, format!("\\frac{{{top}}}{{{bottom}}}"))
    }
}
