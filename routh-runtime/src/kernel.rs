//! Evaluation of a model's tapes behind one small interface, [`Kernel`]: compiled to native code
//! by Cranelift ([`Jit`], feature `jit`, the default) or interpreted ([`Interpreter`]).
//!
//! A [`Model`](crate::Model) keeps its tapes unbound: `Op::Param(k)` reads the `k`-th value of
//! a parameter slice passed with the inputs ([`Kernel::eval_params`]), so a tape is compiled
//! once, the first time it is evaluated, and serves every set of parameter values
//! (`Model::set` and `Model::with` change values only). The JIT's code computes with the same
//! IEEE operations as the interpreter, so the two give the same bits. Without the feature, or on
//! a host Cranelift does not support, the interpreter evaluates the tapes.
//!
//! The interpreter ([`Interpreter`]) is register based: the tape is folded (every operation of
//! constants is computed when the kernel is built, as the derive's code would compute it at run
//! time, with the same `f64` operations; operations of parameters are not, their values being
//! known only at evaluation) and laid out as a register file
//! `[inputs | parameters | constants | results]` and a list of instructions, each writing the
//! next result register. An evaluation copies the inputs, parameters and constants in and runs
//! the instructions; its working storage is per thread and reused, so an evaluation does not
//! allocate.

use routh_tape::{Func, Op, Tape};
use std::cell::RefCell;
use std::fmt;
use std::sync::Arc;

/// The number of inputs of a kernel: `ω` (or `Ω`), `γ`, `p_ψ` (one constant with the tape's and
/// the JIT's).
pub use routh_tape::INPUTS;

/// One tape, ready to evaluate with `f64`.
pub trait Kernel: Send + Sync + fmt::Debug {
    /// Evaluates the outputs at `inputs = [ω₀, ω₁, ω₂, γ₀, γ₁, γ₂, p_ψ]` (`Ω` for the Routh
    /// function's tapes) into `out` (output `k` to `out[k]`; `out` holds [`Kernel::outputs`]).
    /// A parameter the tape still reads is NaN.
    fn eval(&self, inputs: &[f64; INPUTS], out: &mut [f64]);
    /// The number of outputs.
    fn outputs(&self) -> usize;
    /// [`Kernel::eval`] with the tape's parameter values: `Op::Param(k)` reads `params[k]`
    /// (NaN past its end). The default ignores `params`: the kernel of a tape whose parameters
    /// are bound (folded in as constants), as a [`Backend`] receives them.
    fn eval_params(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        let _ = params;
        self.eval(inputs, out);
    }
}

/// Builds the kernel of a tape without parameters (all folded into constants): the
/// interpreter's [`interpret`], or a compiled backend's.
pub type Backend = fn(&Tape) -> Arc<dyn Kernel>;

/// The interpreter's [`Backend`].
pub fn interpret(tape: &Tape) -> Arc<dyn Kernel> {
    Arc::new(Interpreter::new(tape))
}

/// Whether models compile their tapes to native code: the feature `jit` is on and Cranelift
/// supports this host.
pub fn jit_supported() -> bool {
    #[cfg(feature = "jit")]
    return routh_jit::is_supported();
    #[cfg(not(feature = "jit"))]
    return false;
}

/// The JIT's [`Backend`]: `tape` compiled to native code on its own (its parameters, if it
/// still has some, read from [`Kernel::eval_params`]'s slice), or the interpreter if it cannot
/// be (a host Cranelift does not support, or Cranelift failed).
#[cfg(feature = "jit")]
pub fn jit(tape: &Tape) -> Arc<dyn Kernel> {
    match routh_jit::JitFunction::compile(tape) {
        Ok(f) => Arc::new(Jit(f)),
        Err(_) => interpret(tape),
    }
}

/// One tape compiled to native code by Cranelift ([`routh_jit::JitFunction`]).
#[cfg(feature = "jit")]
#[derive(Clone, Debug)]
pub struct Jit(pub routh_jit::JitFunction);

#[cfg(feature = "jit")]
impl Jit {
    /// [`Kernel::eval_params`], inlined: the call into the code when the buffers are long
    /// enough (the hot path of a `Model`), else through buffers of the right length.
    #[inline]
    pub fn run(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        if self.0.eval_params(inputs, params, out).is_err() {
            self.run_padded(inputs, params, out);
        }
    }

    /// Missing parameters as NaN, and only the first outputs written to a short `out`.
    #[cold]
    fn run_padded(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        let mut p = params.to_vec();
        p.resize(p.len().max(self.0.params()), f64::NAN);
        let mut all = vec![0.0; self.0.outputs().max(out.len())];
        if self.0.eval_params(inputs, &p, &mut all).is_ok() {
            for (o, x) in out.iter_mut().zip(all) {
                *o = x;
            }
        }
    }
}

#[cfg(feature = "jit")]
impl Kernel for Jit {
    #[inline]
    fn eval(&self, inputs: &[f64; INPUTS], out: &mut [f64]) {
        self.run(inputs, &[], out);
    }

    fn outputs(&self) -> usize {
        self.0.outputs()
    }

    #[inline]
    fn eval_params(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        self.run(inputs, params, out);
    }
}

/// An instruction; the result goes to the next register.
#[derive(Copy, Clone, Debug)]
enum Ins {
    Add(u32, u32),
    Mul(u32, u32),
    Square(u32),
    Neg(u32),
    Recip(u32),
    Powi(u32, i32),
    Powf(u32, u32),
    Func(Func, u32),
}

/// The register-based interpreter of one tape (see the module documentation).
#[derive(Clone, Debug)]
pub struct Interpreter {
    /// The number of parameters, registers `INPUTS..INPUTS + params`.
    params: usize,
    /// The constants, the registers after the parameters.
    consts: Vec<f64>,
    /// The instructions, writing the registers after the constants.
    code: Vec<Ins>,
    /// The register of each output.
    outputs: Vec<u32>,
}

thread_local! {
    static REGISTERS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
}

impl Interpreter {
    /// The interpreter of `tape`; its parameters ([`Op::Param`]) are read from the slice given
    /// to [`Kernel::eval_params`] (NaN for [`Kernel::eval`]).
    pub fn new(tape: &Tape) -> Interpreter {
        let params = tape.num_params();
        // Where each slot of the tape lives: an input, a constant, or a result.
        #[derive(Copy, Clone)]
        enum Loc {
            Input(u32),
            Const(f64),
            Result(usize),
        }
        let mut loc: Vec<Loc> = Vec::with_capacity(tape.len());
        let mut code: Vec<Ins> = Vec::new();
        for op in tape.ops() {
            let c = |s: u32| match loc[s as usize] {
                Loc::Const(x) => Some(x),
                _ => None,
            };
            // Fold operations of constants by the tape's one rule (the JIT folds the same way);
            // a parameter is a register, known at evaluation only.
            let folded = op.fold(c);
            let l = match (folded, *op) {
                (Some(x), _) => Loc::Const(x),
                (None, Op::Param(k)) => Loc::Input((INPUTS + k as usize) as u32),
                (None, Op::Omega(k)) => Loc::Input(u32::from(k)),
                (None, Op::Gamma(k)) => Loc::Input(3 + u32::from(k)),
                (None, Op::PPsi) => Loc::Input(6),
                (None, op) => {
                    // Operands are named by slot for now; registers are assigned below.
                    code.push(match op {
                        Op::Add(a, b) => Ins::Add(a, b),
                        Op::Mul(a, b) if a == b => Ins::Square(a),
                        Op::Mul(a, b) => Ins::Mul(a, b),
                        Op::Neg(a) => Ins::Neg(a),
                        Op::Recip(a) => Ins::Recip(a),
                        Op::Powi(a, n) => Ins::Powi(a, n),
                        Op::Powf(a, b) => Ins::Powf(a, b),
                        Op::Func(f, a) => Ins::Func(f, a),
                        // Leaves are inputs or constants (above).
                        _ => Ins::Neg(0),
                    });
                    Loc::Result(code.len() - 1)
                }
            };
            loc.push(l);
        }
        // Constants that some instruction or output reads, deduplicated by bits.
        let mut consts: Vec<f64> = Vec::new();
        let mut const_reg = std::collections::HashMap::new();
        let mut reg_of_const = |x: f64, consts: &mut Vec<f64>| -> u32 {
            *const_reg.entry(x.to_bits()).or_insert_with(|| {
                consts.push(x);
                (INPUTS + params + consts.len() - 1) as u32
            })
        };
        let mut reg = vec![0u32; loc.len()];
        for (s, l) in loc.iter().enumerate() {
            reg[s] = match *l {
                Loc::Input(i) => i,
                Loc::Const(x) => reg_of_const(x, &mut consts),
                Loc::Result(_) => 0,
            };
        }
        let base = INPUTS + params + consts.len();
        for (s, l) in loc.iter().enumerate() {
            if let Loc::Result(k) = *l {
                reg[s] = (base + k) as u32;
            }
        }
        let r = |s: u32| reg[s as usize];
        let code = code
            .into_iter()
            .map(|ins| match ins {
                Ins::Add(a, b) => Ins::Add(r(a), r(b)),
                Ins::Mul(a, b) => Ins::Mul(r(a), r(b)),
                Ins::Square(a) => Ins::Square(r(a)),
                Ins::Neg(a) => Ins::Neg(r(a)),
                Ins::Recip(a) => Ins::Recip(r(a)),
                Ins::Powi(a, n) => Ins::Powi(r(a), n),
                Ins::Powf(a, b) => Ins::Powf(r(a), r(b)),
                Ins::Func(f, a) => Ins::Func(f, r(a)),
            })
            .collect();
        let outputs = tape.outputs().iter().map(|o| r(o.slot)).collect();
        Interpreter {
            params,
            consts,
            code,
            outputs,
        }
    }

    /// Number of instructions run per evaluation.
    pub fn instructions(&self) -> usize {
        self.code.len()
    }

    fn run(&self, regs: &mut Vec<f64>, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        let base = INPUTS + self.params + self.consts.len();
        regs.clear();
        regs.extend_from_slice(inputs);
        let given = params.len().min(self.params);
        regs.extend_from_slice(&params[..given]);
        regs.resize(INPUTS + self.params, f64::NAN);
        regs.extend_from_slice(&self.consts);
        regs.reserve(self.code.len());
        for ins in &self.code {
            let x = |i: u32| regs[i as usize];
            let y = match *ins {
                Ins::Add(a, b) => x(a) + x(b),
                Ins::Mul(a, b) => x(a) * x(b),
                Ins::Square(a) => x(a).powi(2),
                Ins::Neg(a) => -x(a),
                Ins::Recip(a) => 1.0 / x(a),
                Ins::Powi(a, n) => x(a).powi(n),
                Ins::Powf(a, b) => x(a).powf(x(b)),
                Ins::Func(f, a) => f.apply(x(a)),
            };
            regs.push(y);
        }
        debug_assert_eq!(regs.len(), base + self.code.len());
        for (o, &r) in out.iter_mut().zip(&self.outputs) {
            *o = regs[r as usize];
        }
    }
}

impl Kernel for Interpreter {
    fn eval(&self, inputs: &[f64; INPUTS], out: &mut [f64]) {
        self.eval_params(inputs, &[], out);
    }

    fn outputs(&self) -> usize {
        self.outputs.len()
    }

    fn eval_params(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        REGISTERS.with(|cell| match cell.try_borrow_mut() {
            Ok(mut regs) => self.run(&mut regs, inputs, params, out),
            // Re-entered on this thread (cannot happen: `run` calls nothing back): own storage.
            Err(_) => self.run(&mut Vec::new(), inputs, params, out),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use routh_tape::{Inputs, Output};

    /// The interpreter equals the tape's own generic evaluation bit for bit, including the
    /// folded constant parts.
    #[test]
    fn interpreter_equals_tape_eval() {
        // ((2 · 3) + γ₀) · sin(p_ψ) − Ω₁², and a constant output.
        let ops = vec![
            Op::constant(2.0),
            Op::constant(3.0),
            Op::Mul(0, 1),
            Op::Gamma(0),
            Op::Add(2, 3),
            Op::PPsi,
            Op::Func(Func::Sin, 5),
            Op::Mul(4, 6),
            Op::Omega(1),
            Op::Mul(8, 8),
            Op::Neg(9),
            Op::Add(7, 10),
            Op::Recip(2),
        ];
        let outputs = vec![
            Output {
                name: "f",
                slot: 11,
            },
            Output {
                name: "c",
                slot: 12,
            },
        ];
        let tape = Tape::new(ops, outputs, 0).unwrap();
        let k = Interpreter::new(&tape);
        assert_eq!(k.instructions(), 6);
        let x = [0.1, -0.7, 0.3, 1.5, 2.0, -1.0, 0.9];
        let mut got = [0.0; 2];
        k.eval(&x, &mut got);
        let mut want = [0.0; 2];
        let at = Inputs {
            omega: [x[0], x[1], x[2]],
            gamma: [x[3], x[4], x[5]],
            p_psi: x[6],
        };
        tape.eval(&at, &[], &mut Vec::new(), &mut want);
        assert_eq!(got, want);
        assert_eq!(got[1], 1.0 / 6.0);
    }
}
