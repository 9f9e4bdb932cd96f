//! Lowering of the DSL's `syn::Expr`s to nodes of a [`routh_symbolic::Graph`], with every error
//! spanned at the user's tokens.

use crate::attr::{FieldKind, Input, Item, Term};
use crate::ctxt::Ctxt;
use routh_symbolic::{shape, Func, Graph, Id, Value, Var};
use std::collections::HashMap;

/// How a scalar input slot is read from the model struct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// `self.field`
    Scalar,
    /// `self.field[i]`
    Component(usize),
    /// `self.field[(i, j)]`
    Entry(usize, usize),
}

/// A scalar parameter read from a field.
#[derive(Clone, Debug)]
pub struct Param {
    /// The variable standing for the parameter in the graph.
    pub var: Var,
    pub field: syn::Ident,
    pub access: Access,
}

/// The symbols of a model: the graph, the variables ω (also used for Ω), γ and p_ψ, and the
/// parameters. Their nodes are [`Symbols::ids`].
pub struct Symbols {
    pub graph: Graph,
    pub omega: [Var; 3],
    pub gamma: [Var; 3],
    pub p_psi: Var,
    pub params: Vec<Param>,
}

impl Symbols {
    /// The nodes of three variables (of ω or γ), to build expressions with.
    pub fn ids(&self, vars: [Var; 3]) -> [Id; 3] {
        vars.map(|v| self.graph.var_id(v))
    }
}

/// A lowered model: `L = kinetic + linear − potential`.
pub struct Lowered {
    pub sym: Symbols,
    pub kinetic: Id,
    pub linear: Id,
    pub potential: Id,
    /// The `crate = "..."` path, if given.
    pub krate: Option<syn::Path>,
}

/// A name in scope: a value, or a `let` whose definition failed (uses stay silent).
#[derive(Clone, Copy)]
enum Binding {
    Value(Value),
    /// A name whose definition already produced an error: uses stay silent.
    Poisoned,
    /// A field marked `#[lagrangian(skip)]`.
    Skipped,
}

/// Deepest nesting of expressions lowered (deeper input is an error, not a stack overflow).
const MAX_DEPTH: usize = 200;

struct Lowerer<'a> {
    cx: &'a Ctxt,
    g: Graph,
    names: HashMap<String, Binding>,
    /// `let` names defined later in the attribute, for a better message.
    later_lets: Vec<String>,
    gamma: [Id; 3],
    field_names: Vec<String>,
    depth: usize,
}

/// Lowers every item. Returns `None` if any error was recorded.
pub fn lower(cx: &Ctxt, input: &Input) -> Option<Lowered> {
    let mut g = Graph::new();
    let omega = ["ω₁", "ω₂", "ω₃"].map(|name| g.new_var(name));
    let gamma = ["γ₁", "γ₂", "γ₃"].map(|name| g.new_var(name));
    let p_psi = g.new_var("p_ψ");
    let [omega_ids, gamma_ids] = [omega, gamma].map(|vs| vs.map(|v| g.var_id(v)));
    let mut names = HashMap::new();
    names.insert(
        "omega".to_string(),
        Binding::Value(Value::Vector(omega_ids)),
    );
    names.insert(
        "gamma".to_string(),
        Binding::Value(Value::Vector(gamma_ids)),
    );
    let mut params = vec![];
    let mut field_names = vec![];
    for f in input.fields {
        let name = f.ident.to_string();
        if crate::check::RESERVED.contains(&name.as_str()) {
            // Reported by `check::fields_do_not_shadow_variables`; the DSL's meaning stays.
            continue;
        }
        let Some(kind) = f.kind.filter(|_| !f.skip) else {
            // Skipped, or of a type already reported: uses say so or stay silent.
            names.insert(
                name,
                if f.skip {
                    Binding::Skipped
                } else {
                    Binding::Poisoned
                },
            );
            continue;
        };
        field_names.push(name.clone());
        let mut slot = |g: &mut Graph, label: String, access: Access| {
            let var = g.new_var(label);
            params.push(Param {
                var,
                field: f.ident.clone(),
                access,
            });
            g.var_id(var)
        };
        let value = match kind {
            FieldKind::Scalar => Value::Scalar(slot(&mut g, name.clone(), Access::Scalar)),
            FieldKind::Vector => Value::Vector(std::array::from_fn(|i| {
                slot(&mut g, format!("{name}[{i}]"), Access::Component(i))
            })),
            FieldKind::Matrix if f.symmetric.is_some() => {
                // One slot per entry of the upper triangle, shared by its mirror image.
                let upper: Vec<(usize, usize, Id)> = (0..3)
                    .flat_map(|i| (i..3).map(move |j| (i, j)))
                    .map(|(i, j)| {
                        (
                            i,
                            j,
                            slot(&mut g, format!("{name}[({i},{j})]"), Access::Entry(i, j)),
                        )
                    })
                    .collect();
                let at = |i: usize, j: usize| {
                    let (a, b) = (i.min(j), i.max(j));
                    upper.iter().find(|e| e.0 == a && e.1 == b).map(|e| e.2)
                };
                let z = g.zero();
                Value::Matrix(std::array::from_fn(|i| {
                    std::array::from_fn(|j| at(i, j).unwrap_or(z))
                }))
            }
            FieldKind::Matrix => Value::Matrix(std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    slot(&mut g, format!("{name}[({i},{j})]"), Access::Entry(i, j))
                })
            })),
        };
        names.insert(name, Binding::Value(value));
    }
    let later_lets = input
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Let { name, .. } => Some(name.to_string()),
            _ => None,
        })
        .collect();
    let mut l = Lowerer {
        cx,
        g,
        names,
        later_lets,
        gamma: gamma_ids,
        field_names,
        depth: 0,
    };
    // In source order, so that errors come out in a stable order.
    let mut terms: Vec<(&'static str, Id, &syn::Expr)> = Vec::new();
    let mut krate = None;
    for item in &input.items {
        match item {
            Item::Let { name, expr } => {
                let s = name.to_string();
                l.later_lets.retain(|n| *n != s);
                let b = match l.expr(expr) {
                    Some(v) => Binding::Value(v),
                    None => Binding::Poisoned,
                };
                l.names.entry(s).or_insert(b);
            }
            Item::Term { term, expr, .. } => {
                let Some(v) = l.expr(expr) else { continue };
                match v {
                    Value::Scalar(s) => {
                        if !terms.iter().any(|t| t.0 == term.name()) {
                            terms.push((term.name(), s, expr));
                        }
                    }
                    other => cx.error_spanned_by(
                        expr,
                        format!(
                            "`{}` must be a scalar, found {}",
                            term.name(),
                            other.shape()
                        ),
                    ),
                }
            }
            Item::Crate { path, .. } => krate = Some(path.clone()),
            Item::Failed { name: Some(name) } => {
                l.later_lets.retain(|n| name != n);
                l.names.entry(name.to_string()).or_insert(Binding::Poisoned);
            }
            Item::Failed { name: None } => {}
        }
    }
    let mut g = l.g;
    let zero = g.zero();
    let find = |t: Term| terms.iter().find(|x| x.0 == t.name()).map(|x| x.1);
    let kinetic = find(Term::Kinetic);
    let linear = find(Term::Linear).unwrap_or(zero);
    let potential = find(Term::Potential).unwrap_or(zero);
    let sym = Symbols {
        graph: g,
        omega,
        gamma,
        p_psi,
        params,
    };
    for (name, id, expr) in &terms {
        crate::check::term_degree(cx, &sym.graph, name, *id, expr, &sym.omega);
    }
    if cx.has_errors() {
        return None;
    }
    Some(Lowered {
        kinetic: kinetic?,
        linear,
        potential,
        sym,
        krate,
    })
}

fn int_lit(e: &syn::Expr) -> Option<i64> {
    match e {
        syn::Expr::Lit(syn::ExprLit {
            lit: syn::Lit::Int(i),
            ..
        }) => i.base10_parse().ok(),
        syn::Expr::Unary(syn::ExprUnary {
            op: syn::UnOp::Neg(_),
            expr,
            ..
        }) => int_lit(expr).map(|v| -v),
        syn::Expr::Paren(p) => int_lit(&p.expr),
        syn::Expr::Group(p) => int_lit(&p.expr),
        _ => None,
    }
}

fn strip_ref(e: &syn::Expr) -> &syn::Expr {
    match e {
        syn::Expr::Reference(r) if r.mutability.is_none() => strip_ref(&r.expr),
        _ => e,
    }
}

const METHODS: &str = "dot, cross, norm, norm_squared, transpose, component_mul, trace, sqrt, powi, powf, sin, cos, tan, exp, ln, recip, abs";

impl Lowerer<'_> {
    fn err(&self, tokens: impl quote::ToTokens, msg: impl std::fmt::Display) -> Option<Value> {
        self.cx.error_spanned_by(tokens, msg);
        None
    }

    fn shaped(
        &self,
        tokens: impl quote::ToTokens,
        r: Result<Value, shape::ShapeError>,
    ) -> Option<Value> {
        match r {
            Ok(v) => Some(v),
            Err(e) => self.err(tokens, e),
        }
    }

    fn name(&self, ident: &syn::Ident) -> Option<Value> {
        let s = ident.to_string();
        match self.names.get(&s) {
            Some(Binding::Value(v)) => Some(*v),
            Some(Binding::Poisoned) => None,
            Some(Binding::Skipped) => self.err(
                ident,
                format!("field `{s}` is marked `#[lagrangian(skip)]`; remove the attribute to use it in the Lagrangian"),
            ),
            None if self.later_lets.contains(&s) => self.err(
                ident,
                format!("`{s}` is used before its `let`; move the `let {s} = ...` item first"),
            ),
            None => {
                let known: Vec<&str> = self.field_names.iter().map(String::as_str).collect();
                self.err(
                    ident,
                    format!("unknown name `{s}`: the Lagrangian can use `omega`, `gamma`, the fields of type f64, Vector3<f64> or Matrix3<f64> ({}) and earlier `let` names", if known.is_empty() { "none".to_string() } else { known.join(", ") }),
                )
            }
        }
    }

    fn expr(&mut self, e: &syn::Expr) -> Option<Value> {
        if self.depth >= MAX_DEPTH {
            if self.depth == MAX_DEPTH {
                self.depth += 1;
                self.cx.error_spanned_by(e, format!("expression nested more than {MAX_DEPTH} levels deep; split it with `let` items"));
            }
            return None;
        }
        self.depth += 1;
        let v = self.expr_inner(e);
        self.depth -= 1;
        v
    }

    fn expr_inner(&mut self, e: &syn::Expr) -> Option<Value> {
        use syn::Expr as E;
        match e {
            E::Lit(lit) => {
                let (digits, suffix, what) = match &lit.lit {
                    syn::Lit::Float(f) => (f.base10_digits().to_string(), f.suffix().to_string(), "a float"),
                    syn::Lit::Int(i) => (i.base10_digits().to_string(), i.suffix().to_string(), "an integer"),
                    _ => return self.err(e, "only numeric literals can appear in a Lagrangian"),
                };
                if !(suffix.is_empty() || suffix == "f64") {
                    return self.err(e, format!("{what} literal with suffix `{suffix}`: numbers in a Lagrangian are `f64`; drop the suffix"));
                }
                match digits.parse::<f64>() {
                    Ok(v) if v.is_finite() => Some(Value::Scalar(self.g.constant(v))),
                    _ => self.err(e, "this literal is out of the range of `f64`"),
                }
            }
            E::Path(p) if p.qself.is_none() && p.path.get_ident().is_some() => {
                self.name(p.path.get_ident()?)
            }
            E::Paren(p) => self.expr(&p.expr),
            E::Group(p) => self.expr(&p.expr),
            E::Reference(_) => self.expr(strip_ref(e)),
            E::Unary(u) => match u.op {
                syn::UnOp::Neg(_) => {
                    let v = self.expr(&u.expr)?;
                    Some(shape::neg(&mut self.g, &v))
                }
                _ => self.err(e, "unsupported unary operator: only `-` is allowed"),
            },
            E::Binary(_) => self.binary_chain(e),
            E::MethodCall(m) => self.method(e, m),
            E::Field(f) => {
                // `self.name` is the field `name`; `v.x`, `v.y`, `v.z` are components.
                if let (E::Path(base), syn::Member::Named(n)) = (&*f.base, &f.member) {
                    if base.path.is_ident("self") {
                        if !self.field_names.contains(&n.to_string()) && !matches!(self.names.get(&n.to_string()), Some(Binding::Skipped | Binding::Poisoned)) {
                            return self.err(n, format!("`self.{n}` is not a field the Lagrangian can use"));
                        }
                        return self.name(n);
                    }
                }
                let base = self.expr(&f.base)?;
                let i = match &f.member {
                    syn::Member::Named(n) if n == "x" => 0,
                    syn::Member::Named(n) if n == "y" => 1,
                    syn::Member::Named(n) if n == "z" => 2,
                    _ => return self.err(&f.member, "unknown component: use `.x`, `.y`, `.z` or `[i]`"),
                };
                self.shaped(e, shape::component(&base, i))
            }
            E::Index(ix) => {
                let base = self.expr(&ix.expr)?;
                match strip_ref(&ix.index) {
                    E::Tuple(t) if t.elems.len() == 2 => {
                        let (i, j) = (int_lit(&t.elems[0]), int_lit(&t.elems[1]));
                        match (i, j) {
                            (Some(i), Some(j)) if (0..3).contains(&i) && (0..3).contains(&j) => {
                                self.shaped(e, shape::entry(&base, i as usize, j as usize))
                            }
                            _ => self.err(&ix.index, "matrix indices must be integer literals 0, 1 or 2: `m[(i, j)]`"),
                        }
                    }
                    E::Tuple(_) => self.err(&ix.index, "a matrix is indexed by two integer literals: `m[(i, j)]`"),
                    _ if base.shape() == routh_symbolic::Shape::Matrix => {
                        self.err(&ix.index, "a matrix is indexed by a pair: `m[(i, j)]`")
                    }
                    idx => match int_lit(idx) {
                        Some(i) if (0..3).contains(&i) => self.shaped(e, shape::component(&base, i as usize)),
                        _ => self.err(&ix.index, "a vector index must be an integer literal 0, 1 or 2"),
                    },
                }
            }
            E::Call(c) => self.call(e, c),
            _ => self.err(
                e,
                "unsupported expression: a Lagrangian is built from literals, names, `+ - * /`, unary `-`, methods, components, `diag`, `skew` and `grad`",
            ),
        }
    }

    /// A chain of binary operators `((a ∘ b) ∘ c) ∘ …`, as a flat sum or product parses (left
    /// deep), lowered by a loop over its left operands: a flat sum of any length costs no stack
    /// and no nesting depth; only the right operands (the terms) are lowered recursively.
    fn binary_chain(&mut self, e: &syn::Expr) -> Option<Value> {
        let mut spine: Vec<&syn::ExprBinary> = Vec::new();
        let mut first = e;
        while let syn::Expr::Binary(b) = first {
            spine.push(b);
            first = &b.left;
        }
        let mut acc = self.expr(first);
        for b in spine.into_iter().rev() {
            // Every term is lowered, so that every mistake in the chain is reported.
            let r = self.expr(&b.right);
            acc = match (acc, r) {
                (Some(l), Some(r)) => {
                    let res = match b.op {
                        syn::BinOp::Add(_) => shape::add(&mut self.g, &l, &r),
                        syn::BinOp::Sub(_) => shape::sub(&mut self.g, &l, &r),
                        syn::BinOp::Mul(_) => shape::mul(&mut self.g, &l, &r),
                        syn::BinOp::Div(_) => shape::div(&mut self.g, &l, &r),
                        _ => {
                            self.err(
                                b.op,
                                "unsupported operator: the Lagrangian uses `+`, `-`, `*` and `/`",
                            );
                            acc = None;
                            continue;
                        }
                    };
                    self.shaped(b, res)
                }
                _ => None,
            };
        }
        acc
    }

    fn arity(
        &self,
        tokens: impl quote::ToTokens,
        name: &str,
        got: usize,
        want: usize,
    ) -> Option<()> {
        if got == want {
            Some(())
        } else {
            self.cx.error_spanned_by(
                tokens,
                format!(
                    "`{name}` takes {want} argument{}, found {got}",
                    if want == 1 { "" } else { "s" }
                ),
            );
            None
        }
    }

    fn method(&mut self, e: &syn::Expr, m: &syn::ExprMethodCall) -> Option<Value> {
        let name = m.method.to_string();
        if let Some(t) = &m.turbofish {
            return self.err(t, "type arguments are not supported here");
        }
        let recv = self.expr(&m.receiver);
        let args: Vec<&syn::Expr> = m.args.iter().map(strip_ref).collect();
        let n = args.len();
        let r = match name.as_str() {
            "dot" | "cross" | "component_mul" => {
                self.arity(&m.method, &name, n, 1)?;
                let a = self.expr(args[0]);
                let (recv, a) = (recv?, a?);
                let g = &mut self.g;
                match name.as_str() {
                    "dot" => shape::dot(g, &recv, &a),
                    "cross" => shape::cross(g, &recv, &a),
                    _ => shape::component_mul(g, &recv, &a),
                }
            }
            "norm" | "norm_squared" | "transpose" | "trace" | "recip" => {
                self.arity(&m.method, &name, n, 0)?;
                let recv = recv?;
                let g = &mut self.g;
                match name.as_str() {
                    "norm" => shape::norm(g, &recv),
                    "norm_squared" => shape::norm_squared(g, &recv),
                    "transpose" => shape::transpose(g, &recv),
                    "trace" => shape::trace(g, &recv),
                    _ => shape::scalar_func(g, &name, &recv, Graph::recip),
                }
            }
            // The elementary functions: the one list is `routh_tape::Func`.
            _ if Func::from_name(&name).is_some_and(Func::is_dsl_method) => {
                self.arity(&m.method, &name, n, 0)?;
                let recv = recv?;
                let f = Func::from_name(&name)?;
                let g = &mut self.g;
                shape::scalar_func(g, &name, &recv, move |g: &mut Graph, s: Id| g.func(f, s))
            }
            "powi" => {
                self.arity(&m.method, &name, n, 1)?;
                let Some(k) = int_lit(args[0]).filter(|k| k.abs() <= 64) else {
                    return self.err(
                        args[0],
                        "`powi` takes an integer literal exponent between -64 and 64",
                    );
                };
                let recv = recv?;
                shape::scalar_func(&mut self.g, &name, &recv, |g, s| g.powi(s, k as i32))
            }
            "powf" => {
                self.arity(&m.method, &name, n, 1)?;
                let a = self.expr(args[0]);
                let (recv, a) = (recv?, a?);
                let g = &mut self.g;
                match a.scalar("the exponent of `powf`") {
                    Ok(x) => shape::scalar_func(g, &name, &recv, |g, s| g.powf(s, x)),
                    Err(err) => Err(err),
                }
            }
            _ => {
                return self.err(
                    &m.method,
                    format!("unsupported method `{name}`: the Lagrangian can use {METHODS}"),
                )
            }
        };
        self.shaped(e, r)
    }

    fn call(&mut self, e: &syn::Expr, c: &syn::ExprCall) -> Option<Value> {
        let syn::Expr::Path(p) = &*c.func else {
            return self.err(
                &c.func,
                "unsupported call: the functions are `diag(v)`, `skew(v)` and `grad(EXPR, gamma)`",
            );
        };
        let Some(f) = p.path.get_ident() else {
            return self.err(
                &c.func,
                "unsupported call: the functions are `diag(v)`, `skew(v)` and `grad(EXPR, gamma)`",
            );
        };
        let name = f.to_string();
        let args: Vec<&syn::Expr> = c.args.iter().map(strip_ref).collect();
        match name.as_str() {
            "diag" | "skew" => {
                self.arity(f, &name, args.len(), 1)?;
                let v = self.expr(args[0])?;
                let r = if name == "diag" { shape::diag(&mut self.g, &v) } else { shape::skew(&mut self.g, &v) };
                self.shaped(e, r)
            }
            "grad" => {
                self.arity(f, &name, args.len(), 2)?;
                let is_gamma = matches!(args[1], syn::Expr::Path(p) if p.path.is_ident("gamma"));
                let v = self.expr(args[0]);
                if !is_gamma {
                    return self.err(args[1], "`grad` differentiates with respect to `gamma` only: `grad(EXPR, gamma)`");
                }
                let v = v?;
                let gamma = self.gamma;
                let r = shape::grad(&mut self.g, &v, &gamma);
                self.shaped(e, r)
            }
            _ if METHODS.split(", ").any(|m| m == name) => self.err(
                f,
                format!("`{name}` is a method here: write `x.{name}(..)`; the functions are `diag(v)`, `skew(v)` and `grad(EXPR, gamma)`"),
            ),
            _ => self.err(f, format!("unknown function `{name}`: the functions are `diag(v)`, `skew(v)` and `grad(EXPR, gamma)`")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The error message's list of methods names every elementary function a text may call
    /// (the functions themselves are `routh_tape::Func`, the one list).
    #[test]
    fn methods_list_every_dsl_function() {
        for f in Func::ALL.into_iter().filter(|f| f.is_dsl_method()) {
            assert!(METHODS.split(", ").any(|m| m == f.name()), "{}", f.name());
        }
    }
}
