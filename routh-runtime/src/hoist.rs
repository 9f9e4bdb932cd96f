//! Parameter-only subexpressions hoisted out of a tape: what folding the parameter values in as
//! constants did, done once per set of values instead of once per compilation.
//!
//! A model's tapes read its parameter values at run time (so that they are compiled once), and
//! then their operations of parameters alone (`m·g·l`, `a₁ − c`, the entries of `diag(I)`, …)
//! would be recomputed at every evaluation. [`split`] cuts a tape in two: `pre`, every
//! operation that depends on parameters and constants only, with an output for each of them
//! that the rest of the tape reads; and `main`, the rest, which reads those outputs as its
//! parameters. A model evaluates `pre` when its values change (`Model::set`, `Model::with`) and
//! `main` at every call. Both are the original operations, in the same order on the same
//! operands, so the results are the same bits as the unsplit tape's.

use routh_tape::{Op, Output, Tape, TapeError};

/// A tape cut in two (see the module documentation).
#[derive(Clone, Debug)]
pub(crate) struct Split {
    /// The parameter-only operations; its outputs are the parameters of `main`.
    pub pre: Tape,
    /// The rest, reading `pre`'s outputs as `Op::Param(k)`.
    pub main: Tape,
}

impl Split {
    /// The parameter values of `main` for the model's values `params`.
    pub fn main_params(&self, params: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.pre.outputs().len()];
        let zero = routh_tape::Inputs {
            omega: [0.0; 3],
            gamma: [0.0; 3],
            p_psi: 0.0,
        };
        self.pre.eval(&zero, params, &mut Vec::new(), &mut out);
        out
    }
}

/// What a slot depends on.
#[derive(Copy, Clone, PartialEq, Eq)]
enum Dep {
    /// Constants only (folded by the JIT and the interpreter).
    Const,
    /// Parameters (and constants), no input.
    Param,
    /// An input.
    Input,
}

/// Cuts `tape` into its parameter-only part and the rest (see the module documentation).
pub(crate) fn split(tape: &Tape) -> Result<Split, TapeError> {
    let ops = tape.ops();
    let mut dep = Vec::with_capacity(ops.len());
    for op in ops {
        let d = match *op {
            Op::Const(_) => Dep::Const,
            Op::Param(_) => Dep::Param,
            Op::Omega(_) | Op::Gamma(_) | Op::PPsi => Dep::Input,
            _ => op
                .operands()
                .map(|a| dep[a as usize])
                .fold(Dep::Const, |acc, d| match (acc, d) {
                    (Dep::Input, _) | (_, Dep::Input) => Dep::Input,
                    (Dep::Param, _) | (_, Dep::Param) => Dep::Param,
                    _ => Dep::Const,
                }),
        };
        dep.push(d);
    }
    // The parameter-only slots `main` reads: operands of its operations, and outputs.
    let mut hoisted = vec![false; ops.len()];
    for (i, op) in ops.iter().enumerate() {
        if dep[i] == Dep::Input {
            for a in op.operands() {
                if dep[a as usize] == Dep::Param {
                    hoisted[a as usize] = true;
                }
            }
        }
    }
    for o in tape.outputs() {
        if dep[o.slot as usize] == Dep::Param {
            hoisted[o.slot as usize] = true;
        }
    }

    // `pre`: every slot that is not an input's, renumbered; an output per hoisted slot.
    let mut pre_ops = Vec::new();
    let mut pre_slot = vec![u32::MAX; ops.len()];
    let mut pre_outputs = Vec::new();
    // `main`: every slot that is not a parameter-only one, or a hoisted one as a parameter.
    let mut main_ops = Vec::new();
    let mut main_slot = vec![u32::MAX; ops.len()];
    for (i, op) in ops.iter().enumerate() {
        if dep[i] != Dep::Input {
            pre_slot[i] = pre_ops.len() as u32;
            pre_ops.push(renumber(op, &pre_slot));
            if hoisted[i] {
                pre_outputs.push(Output {
                    name: "hoisted",
                    slot: pre_slot[i],
                });
            }
        }
        let main_op = match dep[i] {
            Dep::Param if hoisted[i] => Some(Op::Param((pre_outputs.len() - 1) as u32)),
            Dep::Param => None,
            Dep::Const | Dep::Input => Some(renumber(op, &main_slot)),
        };
        if let Some(op) = main_op {
            main_slot[i] = main_ops.len() as u32;
            main_ops.push(op);
        }
    }
    let main_outputs = tape
        .outputs()
        .iter()
        .map(|o| Output {
            name: o.name,
            slot: main_slot[o.slot as usize],
        })
        .collect();
    let hoisted_count = pre_outputs.len() as u32;
    Ok(Split {
        pre: Tape::new(pre_ops, pre_outputs, tape.num_params() as u32)?,
        main: Tape::new(main_ops, main_outputs, hoisted_count)?,
    })
}

/// `op` with its operands renumbered by `slot` (a slot not kept is `u32::MAX`, which
/// `Tape::new` refuses: never, since every operand of a kept operation is kept).
fn renumber(op: &Op, slot: &[u32]) -> Op {
    let s = |a: u32| slot[a as usize];
    match *op {
        Op::Add(a, b) => Op::Add(s(a), s(b)),
        Op::Mul(a, b) => Op::Mul(s(a), s(b)),
        Op::Powf(a, b) => Op::Powf(s(a), s(b)),
        Op::Neg(a) => Op::Neg(s(a)),
        Op::Recip(a) => Op::Recip(s(a)),
        Op::Powi(a, n) => Op::Powi(s(a), n),
        Op::Func(f, a) => Op::Func(f, s(a)),
        leaf => leaf,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use routh_tape::{Func, Inputs};

    /// The split tape gives the unsplit one's bits, and hoists what it should: here
    /// `(k₀·k₁)·γ₀ + sin(k₀)` and an output of parameters only, `k₁²`.
    #[test]
    fn split_equals_unsplit_bit_for_bit() {
        let ops = vec![
            Op::Param(0),
            Op::Param(1),
            Op::Mul(0, 1),
            Op::Gamma(0),
            Op::Mul(2, 3),
            Op::Func(Func::Sin, 0),
            Op::Add(4, 5),
            Op::Mul(1, 1),
            Op::constant(2.0),
            Op::Mul(8, 8),
            Op::Add(6, 9),
        ];
        let outs = vec![
            Output {
                name: "f",
                slot: 10,
            },
            Output { name: "g", slot: 7 },
        ];
        let tape = Tape::new(ops, outs, 2).unwrap();
        let s = split(&tape).unwrap();
        // k₀·k₁, sin k₀ and k₁² are hoisted; k₀ and k₁ alone are read by nothing else.
        assert_eq!(s.pre.outputs().len(), 3);
        assert_eq!(s.main.num_params(), 3);
        assert!(s.main.ops().iter().all(|op| !matches!(op, Op::Func(..))));
        for (k, x) in [
            ([0.3, -1.7], 0.4),
            ([2.5, 1e-3], -3.0),
            ([0.0, -0.0], f64::NAN),
        ] {
            let at = Inputs {
                omega: [0.0; 3],
                gamma: [x, 0.0, 0.0],
                p_psi: 0.0,
            };
            let (mut a, mut b) = ([0.0; 2], [0.0; 2]);
            tape.eval(&at, &k, &mut Vec::new(), &mut a);
            s.main
                .eval(&at, &s.main_params(&k), &mut Vec::new(), &mut b);
            for i in 0..2 {
                assert!(a[i].to_bits() == b[i].to_bits() || (a[i].is_nan() && b[i].is_nan()));
            }
        }
    }

    #[test]
    fn a_tape_without_parameters_is_unchanged() {
        let ops = vec![Op::Gamma(0), Op::constant(3.0), Op::Mul(0, 1)];
        let tape = Tape::new(ops, vec![Output { name: "f", slot: 2 }], 0).unwrap();
        let s = split(&tape).unwrap();
        assert_eq!(s.main.ops(), tape.ops());
        assert_eq!(s.main.num_params(), 0);
    }
}
