//! The model's tapes (`routh_tape::Tape`): the outputs of the expression DAG as typed
//! straight-line programs, for what the derive emits as `static` data (the certification tape
//! of `∂R/∂γ`, `∂²R/∂γ²` at `Ω = 0` and the tape of `R` itself) and for the runtime model, which
//! evaluates one tape per generated method.
//!
//! Inputs: `ω` (which stands for `Ω` in the Routh function's outputs) is [`Op::Omega`], `γ` is
//! [`Op::Gamma`], `p_ψ` is [`Op::PPsi`], and the `k`-th scalar parameter of
//! [`Symbols::params`] is `Op::Param(k)`: every tape of a model reads the same parameter list,
//! in that order ([`param_reads`] writes how the derive reads it from `self`).

use crate::lower::{Access, Symbols};
use crate::reduce::Outputs;
use routh_symbolic::{Id, Var};
use routh_tape::{Op, Tape, TapeError, CERTIFICATION_OUTPUTS, FLOW_OUTPUTS, ROUTHIAN_OUTPUT};

/// The tape computing `outputs` (name, node) of the model's graph.
pub fn tape(sym: &Symbols, outputs: &[(&'static str, Id)]) -> Result<Tape, TapeError> {
    let input = |v: Var| -> Op {
        let idx = |vars: &[Var; 3]| vars.iter().position(|&x| x == v);
        if let Some(i) = idx(&sym.omega) {
            Op::Omega(i as u8)
        } else if let Some(i) = idx(&sym.gamma) {
            Op::Gamma(i as u8)
        } else if v == sym.p_psi {
            Op::PPsi
        } else if let Some(k) = sym.params.iter().position(|p| p.var == v) {
            Op::Param(k as u32)
        } else {
            // Every variable is ω, γ, p_ψ or a parameter (as in the emitted code).
            Op::constant(0.0)
        }
    };
    sym.graph.to_tape(outputs, &input, sym.params.len() as u32)
}

/// The certification tape: `∂R/∂γ` then the upper triangle of `∂²R/∂γ²`, at `Ω = 0`, named as
/// [`CERTIFICATION_OUTPUTS`].
pub fn certification(sym: &Symbols, o: &Outputs) -> Result<Tape, TapeError> {
    let g = &o.dr_dgamma_at_rest;
    let h = &o.d2r_dgamma2_at_rest;
    let ids = [
        g[0], g[1], g[2], h[0][0], h[0][1], h[0][2], h[1][1], h[1][2], h[2][2],
    ];
    let outs: Vec<_> = CERTIFICATION_OUTPUTS.into_iter().zip(ids).collect();
    tape(sym, &outs)
}

/// The tape of the Routh function `R(Ω, γ, p_ψ)` (14) itself, general in all its arguments,
/// named [`ROUTHIAN_OUTPUT`].
pub fn routhian(sym: &Symbols, o: &Outputs) -> Result<Tape, TapeError> {
    tape(sym, &[(ROUTHIAN_OUTPUT, o.routhian)])
}

/// The tape of `L(ω, γ)` and the derivatives the full equations (8) are made of, named as
/// [`FLOW_OUTPUTS`]: what jets of the flow of (8) evaluate.
pub fn flow(sym: &Symbols, o: &Outputs) -> Result<Tape, TapeError> {
    let j = &o.d2l_domega2;
    let n = &o.d2l_domega_dgamma;
    let ids = [
        o.lagrangian,
        o.dl_domega[0],
        o.dl_domega[1],
        o.dl_domega[2],
        o.dl_dgamma[0],
        o.dl_dgamma[1],
        o.dl_dgamma[2],
        j[0][0],
        j[0][1],
        j[0][2],
        j[1][1],
        j[1][2],
        j[2][2],
        n[0][0],
        n[0][1],
        n[0][2],
        n[1][0],
        n[1][1],
        n[1][2],
        n[2][0],
        n[2][1],
        n[2][2],
    ];
    let outs: Vec<_> = FLOW_OUTPUTS.into_iter().zip(ids).collect();
    tape(sym, &outs)
}

/// How the derive reads the parameters from `self`, in the order of `Op::Param(k)`.
pub fn param_reads(sym: &Symbols) -> Vec<String> {
    sym.params
        .iter()
        .map(|p| {
            let f = &p.field;
            match p.access {
                Access::Scalar => format!("self.{f}"),
                Access::Component(i) => format!("self.{f}[{i}usize]"),
                Access::Entry(i, j) => format!("self.{f}[({i}usize, {j}usize)]"),
            }
        })
        .collect()
}
