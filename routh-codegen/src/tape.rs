//! The certification tape: `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0` as a flat list of operations, for
//! the runtime's interval evaluation (`routh::certify`, docs/method.md §9).
//!
//! The certified search needs enclosures of the gradient and Hessian in γ over boxes of the
//! sphere. Generating a second, generic copy of the code would double what the derive emits; the
//! tape is instead one string literal (one token, whatever the model's size) that the runtime
//! parses once and interprets with intervals. It is the DAG itself, written children first, so
//! the interval evaluation computes every shared subexpression once, like the f64 code.
//!
//! Format: operations separated by `;`, the `k`-th (from 0) defining slot `k`:
//! - `g i` — γ_i; `p` — p_ψ; `f k` — the `k`-th parameter value passed with the tape;
//! - `c HEX` — the constant with these IEEE 754 bits (exact, no decimal rounding);
//! - `+ a b`, `* a b`, `- a` (negation), `/ a` (reciprocal), `^ a n` (integer power), `P a b`
//!   (`a^b`), `F name a` (an elementary function by its `f64` method name, or `sign`);
//!
//! and a last item `o s₁ … s₉`: the slots of `∂R/∂γ` (3) and of the upper triangle of
//! `∂²R/∂γ²` row by row (`00 01 02 11 12 22`).

use crate::lower::{Access, Symbols};
use routh_symbolic::{Graph, Id, Node};
use std::fmt::Write;

/// The tape of `outputs` (gradient then upper Hessian), and the expressions reading the
/// parameters it uses from `self`, in the order of its `f k` operations.
pub fn tape(sym: &Symbols, gradient: &[Id; 3], hessian: &[[Id; 3]; 3]) -> (String, Vec<String>) {
    let g: &Graph = &sym.graph;
    let outputs: Vec<Id> = gradient
        .iter()
        .copied()
        .chain(
            (0..3)
                .flat_map(|i| (i..3).map(move |j| (i, j)))
                .map(|(i, j)| hessian[i][j]),
        )
        .collect();
    let top = outputs.iter().map(|o| o.index()).max().unwrap_or(0);
    // Nodes reachable from the outputs, in id order (children first).
    let mut needed = vec![false; top + 1];
    for o in &outputs {
        needed[o.index()] = true;
    }
    for i in (0..=top).rev() {
        if needed[i] {
            for c in g.node(Id::from_index(i)).children() {
                needed[c.index()] = true;
            }
        }
    }
    let mut slot = vec![usize::MAX; top + 1];
    let mut text = String::new();
    let mut params = Vec::new();
    for (next, i) in (0..=top).filter(|&i| needed[i]).enumerate() {
        let s = |id: Id| slot[id.index()];
        match g.node(Id::from_index(i)) {
            Node::Const(bits) => {
                let _ = write!(text, "c {bits:x}");
            }
            Node::Var(v) => {
                if let Some(k) = sym.gamma.iter().position(|&x| x == v) {
                    let _ = write!(text, "g {k}");
                } else if v == sym.p_psi {
                    text.push('p');
                } else if let Some(p) = sym.params.iter().find(|p| p.var == v) {
                    let f = &p.field;
                    params.push(match p.access {
                        Access::Scalar => format!("self.{f}"),
                        Access::Component(i) => format!("self.{f}[{i}usize]"),
                        Access::Entry(i, j) => format!("self.{f}[({i}usize, {j}usize)]"),
                    });
                    let _ = write!(text, "f {}", params.len() - 1);
                } else {
                    // ω (Ω) is 0 at rest; no other variable reaches these outputs.
                    text.push_str("c 0");
                }
            }
            Node::Add(a, b) => {
                let _ = write!(text, "+ {} {}", s(a), s(b));
            }
            Node::Mul(a, b) => {
                let _ = write!(text, "* {} {}", s(a), s(b));
            }
            Node::Neg(a) => {
                let _ = write!(text, "- {}", s(a));
            }
            Node::Recip(a) => {
                let _ = write!(text, "/ {}", s(a));
            }
            Node::Powi(a, n) => {
                let _ = write!(text, "^ {} {n}", s(a));
            }
            Node::Powf(a, b) => {
                let _ = write!(text, "P {} {}", s(a), s(b));
            }
            Node::Func(f, a) => {
                let _ = write!(text, "F {} {}", f.name(), s(a));
            }
        }
        text.push(';');
        slot[i] = next;
    }
    text.push('o');
    for o in &outputs {
        let _ = write!(text, " {}", slot[o.index()]);
    }
    (text, params)
}
