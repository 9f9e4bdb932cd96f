//! Evaluation of a model's tapes behind one small interface, [`Kernel`]: compiled to native code
//! by Cranelift ([`Jit`], feature `jit`, the default) or interpreted ([`Interpreter`]).
//!
//! With the feature `jit` a [`Model`](crate::Model) compiles all its tapes at once into one
//! block of machine code ([`routh_jit`]); the code computes with the same IEEE operations as
//! the interpreter, so the two give the same bits. Without the feature, or on a host Cranelift
//! does not support, the interpreter evaluates them.
//!
//! The interpreter ([`Interpreter`]) is register based: the tape, its parameters already folded
//! into constants ([`routh_tape::Tape::bind`]), is folded once more (every operation of
//! constants is computed when the kernel is built, as the derive's code would compute it at
//! run time, with the same `f64` operations) and laid out as a register file
//! `[inputs | constants | results]` and a list of instructions, each writing the next result
//! register. An evaluation copies the inputs and constants in and runs the instructions; its
//! working storage is per thread and reused, so an evaluation does not allocate.

use routh_tape::{Func, Op, Tape};
use std::cell::RefCell;
use std::fmt;
use std::sync::Arc;

/// The number of inputs of a kernel: `ω` (or `Ω`), `γ`, `p_ψ`.
pub const INPUTS: usize = 7;

/// One tape, ready to evaluate with `f64`.
pub trait Kernel: Send + Sync + fmt::Debug {
    /// Evaluates the outputs at `inputs = [ω₀, ω₁, ω₂, γ₀, γ₁, γ₂, p_ψ]` (`Ω` for the Routh
    /// function's tapes) into `out` (output `k` to `out[k]`; `out` holds [`Kernel::outputs`]).
    fn eval(&self, inputs: &[f64; INPUTS], out: &mut [f64]);
    /// The number of outputs.
    fn outputs(&self) -> usize;
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

/// The JIT's [`Backend`]: `tape` compiled to native code on its own, or the interpreter if it
/// cannot be (a host Cranelift does not support, or a tape that still has parameters).
/// A [`Model`](crate::Model) compiles its tapes together instead (one block of code), which
/// builds faster.
#[cfg(feature = "jit")]
pub fn jit(tape: &Tape) -> Arc<dyn Kernel> {
    if tape.num_params() > 0 {
        return interpret(tape);
    }
    match routh_jit::JitFunction::compile(tape) {
        Ok(f) => Arc::new(Jit(f)),
        Err(_) => interpret(tape),
    }
}

/// Compiles every tape (none with parameters) into one block of native code; `None` if the JIT
/// cannot (the host is not supported, or Cranelift failed), for the caller to interpret them.
#[cfg(feature = "jit")]
pub(crate) fn jit_all(tapes: &[&Tape], optimize: bool) -> Option<Vec<Arc<dyn Kernel>>> {
    if tapes.iter().any(|t| t.num_params() > 0) {
        return None;
    }
    let level = if optimize {
        routh_jit::OptLevel::Speed
    } else {
        routh_jit::OptLevel::None
    };
    let fns = routh_jit::JitFunction::compile_all_with(tapes, level).ok()?;
    Some(
        fns.into_iter()
            .map(|f| Arc::new(Jit(f)) as Arc<dyn Kernel>)
            .collect(),
    )
}

/// One tape compiled to native code by Cranelift ([`routh_jit::JitFunction`]).
#[cfg(feature = "jit")]
#[derive(Clone, Debug)]
pub struct Jit(pub routh_jit::JitFunction);

#[cfg(feature = "jit")]
impl Kernel for Jit {
    #[inline]
    fn eval(&self, inputs: &[f64; INPUTS], out: &mut [f64]) {
        if self.0.eval(inputs, out).is_err() {
            // `out` is shorter than the outputs: the first ones, through a buffer.
            let mut all = vec![0.0; self.0.outputs()];
            if self.0.eval(inputs, &mut all).is_ok() {
                for (o, x) in out.iter_mut().zip(all) {
                    *o = x;
                }
            }
        }
    }

    fn outputs(&self) -> usize {
        self.0.outputs()
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
    /// The constants, registers `INPUTS..INPUTS + consts.len()`.
    consts: Vec<f64>,
    /// The instructions, writing registers `INPUTS + consts.len()` onwards.
    code: Vec<Ins>,
    /// The register of each output.
    outputs: Vec<u32>,
}

thread_local! {
    static REGISTERS: RefCell<Vec<f64>> = const { RefCell::new(Vec::new()) };
}

impl Interpreter {
    /// The interpreter of `tape`. A parameter still in the tape ([`Op::Param`]) reads NaN.
    pub fn new(tape: &Tape) -> Interpreter {
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
            // a parameter still in the tape reads NaN.
            let folded = match *op {
                Op::Param(_) => Some(f64::NAN),
                _ => op.fold(c),
            };
            let l = match (folded, *op) {
                (Some(x), _) => Loc::Const(x),
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
                (INPUTS + consts.len() - 1) as u32
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
        let base = INPUTS + consts.len();
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
            consts,
            code,
            outputs,
        }
    }

    /// Number of instructions run per evaluation.
    pub fn instructions(&self) -> usize {
        self.code.len()
    }

    fn run(&self, regs: &mut Vec<f64>, inputs: &[f64; INPUTS], out: &mut [f64]) {
        let base = INPUTS + self.consts.len();
        regs.clear();
        regs.extend_from_slice(inputs);
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
        REGISTERS.with(|cell| match cell.try_borrow_mut() {
            Ok(mut regs) => self.run(&mut regs, inputs, out),
            // Re-entered on this thread (cannot happen: `run` calls nothing back): own storage.
            Err(_) => self.run(&mut Vec::new(), inputs, out),
        });
    }

    fn outputs(&self) -> usize {
        self.outputs.len()
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
