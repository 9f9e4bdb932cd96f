//! Emission of straight-line bodies, as Rust source text ([`crate::methods`] wraps them into
//! the generated methods).
//!
//! Each body is straight-line code: the inputs it needs are read into `__v*` locals, then the
//! nodes its outputs need are written in latency order ([`crate::order`]; children before
//! parents, so every shared subexpression is computed once) as `let __t* = ...;`. A negation feeding only a
//! sum is written as a subtraction, a reciprocal used once as a division, and small integer
//! powers as products. No allocation, no `unsafe`.
//!
//! The methods are written as text, not with `quote!`: a model's methods are tens of thousands
//! of tokens, and building them one by one is most of what the derive costs a user, whose build
//! runs the generator unoptimised (`crate::expand_with` lexes the text in one go, in the
//! compiler when it runs as a proc macro). Nothing in the text comes from the user's tokens but
//! field names, and every path in it is one of the aliases [`crate::expand_with`] declares
//! next to the impls, through `<crate>::__private` ([`ALIASES`]), so that the text never names
//! the crate path (whose tokens carry the user's span for errors).

use crate::lower::{Access, Symbols};
use routh_symbolic::{Func, Graph, Id, Node, Plan, Var};
use std::cell::Cell;
use std::fmt::Write;

/// The names the text uses for the types of `<crate>::__private`, declared as type aliases in
/// the `const _` block around the impls: `(alias, item of __private)`.
pub const ALIASES: [(&str, &str); 21] = [
    ("__F64", "f64"),
    ("__Vector3", "Vector3"),
    ("__Matrix3", "Matrix3"),
    ("__RouthBundle", "RouthBundle"),
    ("__GyroscopicSystem", "GyroscopicSystem"),
    ("__FullEquations", "FullEquations"),
    ("__FullJacobian", "FullJacobian"),
    ("__ReducedEquations", "ReducedEquations"),
    ("__Op", "Op"),
    ("__Output", "Output"),
    ("__Tape", "Tape"),
    ("__Func", "Func"),
    ("__CertificationTape", "CertificationTape"),
    ("__RouthianTape", "RouthianTape"),
    ("__MaybeTape", "MaybeTape"),
    ("__MaybeRouthianTape", "MaybeRouthianTape"),
    ("__FlowTape", "FlowTape"),
    ("__MaybeFlowTape", "MaybeFlowTape"),
    ("__MaybeMatrix3", "MaybeMatrix3"),
    ("__RankOneInertia", "RankOneInertia"),
    ("__MaybeRankOne", "MaybeRankOne"),
];

/// The function the text calls for `sign(x)`, declared next to the aliases when used (see
/// [`Emitter::uses_sign`]) as a wrapper of `<crate>::__private::sign`.
pub const SIGN: &str = "__sign";

/// How a variable is read in one method.
#[derive(Clone, Copy)]
pub enum Inputs {
    /// `(omega, gamma)` of the Lagrangian methods.
    Lagrangian,
    /// `(big_omega, gamma, p_psi)` of the Routhian methods.
    Routhian,
}

/// Writes the methods of the impls.
pub struct Emitter<'a> {
    sym: &'a Symbols,
    /// How each variable is read from `self` (`self.field`, `self.field[i]`, ...), by
    /// variable index; empty for ω, γ, p_ψ and the reduction's own variables.
    params: Vec<String>,
    /// Whether a method calls [`SIGN`].
    sign: Cell<bool>,
}

/// A literal `c` as the derive writes it: `0.5f64`, `(-2f64)`, `__F64::NAN`.
fn lit(out: &mut String, c: f64) {
    if c.is_nan() {
        out.push_str("__F64::NAN");
    } else if c.is_infinite() {
        out.push_str(if c > 0.0 {
            "__F64::INFINITY"
        } else {
            "(-__F64::INFINITY)"
        });
    } else if c < 0.0 {
        let _ = write!(out, "(-{}f64)", -c);
    } else {
        let _ = write!(out, "{c}f64");
    }
}

/// `__t<id>`.
fn local(out: &mut String, id: Id) {
    name(out, b't', id.index());
}

/// `__v<var>`: the local an input is read into.
fn input_local(out: &mut String, v: Var) {
    name(out, b'v', v.index());
}

/// `__<letter><n>`, formed by hand in one buffer and written in one piece: the names of locals
/// are most of the text, and `write!` (or a `push` per digit) costs several times as much
/// unoptimised.
fn name(out: &mut String, letter: u8, mut n: usize) {
    let mut buf = [b'_'; 24];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    i -= 1;
    buf[i] = letter;
    // `buf[i - 2..i]` is `__` already.
    if let Ok(s) = std::str::from_utf8(&buf[i - 2..]) {
        out.push_str(s);
    }
}

impl<'a> Emitter<'a> {
    /// An emitter for the model's symbols.
    pub fn new(sym: &'a Symbols) -> Self {
        let mut params = vec![String::new(); sym.graph.num_vars()];
        for p in &sym.params {
            let f = &p.field;
            params[p.var.index()] = match p.access {
                Access::Scalar => format!("self.{f}"),
                Access::Component(i) => format!("self.{f}[{i}usize]"),
                Access::Entry(i, j) => format!("self.{f}[({i}usize, {j}usize)]"),
            };
        }
        Emitter {
            sym,
            params,
            sign: Cell::new(false),
        }
    }

    /// Whether a method written so far calls [`SIGN`].
    pub fn uses_sign(&self) -> bool {
        self.sign.get()
    }

    fn g(&self) -> &Graph {
        &self.sym.graph
    }

    /// Reads variable `var` from the method's arguments or from `self`.
    fn input(&self, out: &mut String, var: Var, inputs: Inputs) {
        let s = self.sym;
        let idx = |vars: &[Var; 3]| vars.iter().position(|&x| x == var);
        if let Some(i) = idx(&s.omega) {
            let _ = match inputs {
                Inputs::Lagrangian => write!(out, "__omega[{i}usize]"),
                Inputs::Routhian => write!(out, "__big_omega[{i}usize]"),
            };
        } else if let Some(i) = idx(&s.gamma) {
            let _ = write!(out, "__gamma[{i}usize]");
        } else if s.p_psi == var {
            out.push_str("__p_psi");
        } else {
            match self.params.get(var.index()).filter(|p| !p.is_empty()) {
                Some(p) => out.push_str(p),
                // Every variable is ω, γ, p_ψ or a parameter.
                None => out.push_str("0.0f64"),
            }
        }
    }

    /// Names the value of `id` (a literal, an input local or a node local).
    fn operand(&self, out: &mut String, id: Id) {
        match self.g().node(id) {
            Node::Const(b) => lit(out, f64::from_bits(b)),
            Node::Var(v) => input_local(out, v),
            _ => local(out, id),
        }
    }

    /// `a <op> b`.
    fn binary(&self, out: &mut String, a: Id, op: &str, b: Id) {
        self.operand(out, a);
        out.push_str(op);
        self.operand(out, b);
    }

    /// `a <op> b` for a commutative `op`, the operand computed later (the larger id) first.
    ///
    /// The order is free for the value but not for the machine code: x86's SSE arithmetic
    /// overwrites its first operand (`addsd x, y` is `x += y`), and LLVM's SLP vectoriser and
    /// instruction selection largely keep the order they are given. The value computed last is
    /// the one most likely to die at this use (an input or an early shared value is usually
    /// read again later), so putting it first lets the instruction overwrite it in place where
    /// the other order needs a register copy. Measured on the bench models (docs/performance.md,
    /// 2026-11-26): the gyrostat's `bundle_and_system` compiles to 501 instructions instead of
    /// 521, and its `bundle` then `from_bundle` runs 6 % faster; the ellipsoid's runs 2–3 % slower.
    fn commutative(&self, out: &mut String, a: Id, op: &str, b: Id, rank: &[u32]) {
        let rank_of = |x: Id| rank.get(x.index()).map_or(0, |&r| r);
        let (ra, rb) = (rank_of(a), rank_of(b));
        let a_first = ra > rb || (ra == rb && a.index() > b.index());
        let (first, second) = if a_first { (a, b) } else { (b, a) };
        self.binary(out, first, op, second);
    }

    /// The right side of statement `id`; `rank[i]` is 1 + the position of statement `i` in
    /// the body (0 for leaves), which decides the order of commutative operands.
    fn expr(&self, out: &mut String, id: Id, plan: &Plan, rank: &[u32]) {
        let g = self.g();
        match g.node(id) {
            Node::Add(a, b) => match (plan.folds(g, id, a), plan.folds(g, id, b)) {
                (_, Some(x)) => self.binary(out, a, " - ", x),
                (Some(x), _) => self.binary(out, b, " - ", x),
                _ => self.commutative(out, a, " + ", b, rank),
            },
            Node::Mul(a, b) => match (plan.folds(g, id, a), plan.folds(g, id, b)) {
                (_, Some(x)) => self.binary(out, a, " / ", x),
                (Some(x), _) => self.binary(out, b, " / ", x),
                _ => self.commutative(out, a, " * ", b, rank),
            },
            Node::Neg(a) => {
                out.push('-');
                self.operand(out, a);
            }
            Node::Recip(a) => {
                out.push_str("1.0f64 / ");
                self.operand(out, a);
            }
            Node::Powi(a, n) => match n {
                2 => self.binary(out, a, " * ", a),
                3 => {
                    self.binary(out, a, " * ", a);
                    out.push_str(" * ");
                    self.operand(out, a);
                }
                _ => {
                    self.operand(out, a);
                    let _ = write!(out, ".powi({n}i32)");
                }
            },
            Node::Powf(a, b) => {
                self.operand(out, a);
                out.push_str(".powf(");
                self.operand(out, b);
                out.push(')');
            }
            Node::Func(Func::Sign, a) => {
                self.sign.set(true);
                out.push_str(SIGN);
                out.push('(');
                self.operand(out, a);
                out.push(')');
            }
            Node::Func(f, a) => {
                self.operand(out, a);
                out.push('.');
                out.push_str(f.name());
                out.push_str("()");
            }
            Node::Const(_) | Node::Var(_) => self.operand(out, id),
        }
    }

    /// Writes the statements computing `outputs`; returns the text naming each output.
    pub fn body(&self, out: &mut String, outputs: &[Id], inputs: Inputs) -> Vec<String> {
        self.body_in_parts(out, &[outputs], inputs, |_, _, _| {})
            .into_iter()
            .flatten()
            .collect()
    }

    /// [`Emitter::body`] for outputs given in parts, with `close(out, k, names)` called as soon
    /// as the statements of part `k` are written (before those that only later parts need):
    /// one plan, so every shared value is still computed once, but a caller can assemble part
    /// `k` (a struct literal into a local) there, so that its values need not stay live through
    /// the statements of the parts after it. Returns the names of each part's outputs.
    pub fn body_in_parts(
        &self,
        out: &mut String,
        parts: &[&[Id]],
        inputs: Inputs,
        mut close: impl FnMut(&mut String, usize, &[String]),
    ) -> Vec<Vec<String>> {
        let g = self.g();
        let all: Vec<Id> = parts.iter().flat_map(|p| p.iter().copied()).collect();
        let plan = Plan::new(g, &all);
        // Inputs first (only those read), then the nodes in order.
        let nodes = g.nodes();
        for &id in &plan.emitted {
            if let Node::Var(v) = nodes[id.index()] {
                out.push_str("let ");
                input_local(out, v);
                out.push_str(": __F64 = ");
                self.input(out, v, inputs);
                out.push_str(";\n");
            }
        }
        // Statements are untyped: every operand is an input local declared `__F64`, a literal
        // suffixed `f64` or an earlier statement, so each type is inferred, and the text has two
        // tokens fewer per statement (lexing this text is most of what expansion costs).
        // The statements each part needs (and no earlier part did) are written before the
        // part is closed, in latency order (`crate::order`).
        let groups = crate::order::latency_order(g, &plan, parts);
        let mut rank = vec![0u32; plan.emit.len()];
        for (k, id) in groups.iter().flatten().enumerate() {
            rank[id.index()] = k as u32 + 1;
        }
        let mut names = Vec::with_capacity(parts.len());
        for (k, part) in parts.iter().enumerate() {
            for &id in groups.get(k).into_iter().flatten() {
                out.push_str("let ");
                local(out, id);
                out.push_str(" = ");
                self.expr(out, id, &plan, &rank);
                out.push_str(";\n");
            }
            let part_names: Vec<String> = part
                .iter()
                .map(|&o| {
                    let mut s = String::new();
                    self.operand(&mut s, o);
                    s
                })
                .collect();
            close(out, k, &part_names);
            names.push(part_names);
        }
        names
    }
}
