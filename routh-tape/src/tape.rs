//! The typed tape: a straight-line program over the inputs `ω`/`Ω`, `γ`, `p_ψ` and the model's
//! parameters, children first, with named outputs.

use crate::{Func, TapeScalar};
use std::borrow::Cow;
use std::fmt;

/// One operation of a [`Tape`]. The `k`-th operation (from 0) defines slot `k`; operands are
/// slots of earlier operations, so the ops are in children-first order and every shared
/// subexpression is computed once.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub enum Op {
    /// The constant with these IEEE 754 bits (exact: no decimal rounding).
    Const(u64),
    /// `ω_i` in the Lagrangian's outputs, `Ω_i` in the Routh function's (`i < 3`).
    Omega(u8),
    /// `γ_i` (`i < 3`).
    Gamma(u8),
    /// The cyclic momentum `p_ψ`.
    PPsi,
    /// The `k`-th parameter value given with the tape (see [`Tape::num_params`]).
    Param(u32),
    /// `a + b`.
    Add(u32, u32),
    /// `a · b`.
    Mul(u32, u32),
    /// `−a`.
    Neg(u32),
    /// `1 / a`.
    Recip(u32),
    /// `a^n`.
    Powi(u32, i32),
    /// `a^b`.
    Powf(u32, u32),
    /// `f(a)`.
    Func(Func, u32),
}

impl Op {
    /// The constant `x`, bit for bit.
    pub const fn constant(x: f64) -> Op {
        Op::Const(x.to_bits())
    }

    /// The operand slots.
    pub fn operands(&self) -> impl Iterator<Item = u32> {
        let (a, b) = match *self {
            Op::Const(_) | Op::Omega(_) | Op::Gamma(_) | Op::PPsi | Op::Param(_) => (None, None),
            Op::Add(a, b) | Op::Mul(a, b) | Op::Powf(a, b) => (Some(a), Some(b)),
            Op::Neg(a) | Op::Recip(a) | Op::Powi(a, _) | Op::Func(_, a) => (Some(a), None),
        };
        a.into_iter().chain(b)
    }

    /// The value of this operation when its operands are known constants (`known(slot)`),
    /// computed with the very `f64` operations of [`Tape::eval`] (`x·x` as `powi(2)`, `1/x` as a
    /// division): the one constant-folding rule of the interpreter and of the JIT, so that both
    /// hold the same bits. `Some` for a constant; `None` for an input, a parameter, or an
    /// operation with an operand that is not known.
    pub fn fold(&self, known: impl Fn(u32) -> Option<f64>) -> Option<f64> {
        let c = known;
        match *self {
            Op::Const(bits) => Some(f64::from_bits(bits)),
            Op::Omega(_) | Op::Gamma(_) | Op::PPsi | Op::Param(_) => None,
            Op::Add(a, b) => c(a).zip(c(b)).map(|(x, y)| x + y),
            Op::Mul(a, b) if a == b => c(a).map(|x| x.powi(2)),
            Op::Mul(a, b) => c(a).zip(c(b)).map(|(x, y)| x * y),
            Op::Neg(a) => c(a).map(|x| -x),
            Op::Recip(a) => c(a).map(TapeScalar::recip),
            Op::Powi(a, n) => c(a).map(|x| x.powi(n)),
            Op::Powf(a, b) => c(a).zip(c(b)).map(|(x, y)| x.powf(y)),
            Op::Func(f, a) => c(a).map(|x| x.func(f)),
        }
    }
}

/// A named output: the slot holding it.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub struct Output {
    /// What the output is, e.g. `"routhian"` or `"d2r_dgamma2[0][1]"`.
    pub name: &'static str,
    /// The slot of the operation computing it.
    pub slot: u32,
}

/// Why a list of ops is not a tape.
#[derive(Clone, PartialEq, Eq, Debug)]
pub enum TapeError {
    /// Op `op` reads slot `operand`, which is not an earlier one.
    NotChildrenFirst {
        /// The index of the op.
        op: usize,
        /// The slot it reads.
        operand: u32,
    },
    /// Op `op` reads `ω_i` or `γ_i` with `i ≥ 3`.
    BadInput {
        /// The index of the op.
        op: usize,
    },
    /// Op `op` reads parameter `k`, and the tape declares fewer.
    BadParam {
        /// The index of the op.
        op: usize,
        /// The parameter read.
        param: u32,
    },
    /// Output `name` names a slot past the end.
    BadOutput {
        /// The name of the output.
        name: &'static str,
    },
    /// The tape was given `got` parameter values and reads `want`.
    ParamCount {
        /// What the tape declares.
        want: usize,
        /// What was given.
        got: usize,
    },
    /// A tape needs an output named `name` and has none (or its outputs are not the expected
    /// ones).
    MissingOutput {
        /// The expected name.
        name: &'static str,
    },
}

impl fmt::Display for TapeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TapeError::NotChildrenFirst { op, operand } => {
                write!(
                    f,
                    "op {op} reads slot {operand}, which is not an earlier op"
                )
            }
            TapeError::BadInput { op } => write!(f, "op {op} reads an input index ≥ 3"),
            TapeError::BadParam { op, param } => {
                write!(
                    f,
                    "op {op} reads parameter {param}, past the declared count"
                )
            }
            TapeError::BadOutput { name } => write!(f, "output `{name}` is past the last op"),
            TapeError::ParamCount { want, got } => {
                write!(f, "the tape reads {want} parameters, {got} were given")
            }
            TapeError::MissingOutput { name } => write!(f, "the tape has no output `{name}`"),
        }
    }
}

impl std::error::Error for TapeError {}

/// The number of scalar inputs of a tape before its parameters: `ω` (or `Ω`), `γ`, `p_ψ` — the
/// length of [`Inputs`] laid out flat as `[ω₀, ω₁, ω₂, γ₀, γ₁, γ₂, p_ψ]`, the layout the
/// interpreter's kernels and the JIT's compiled functions read.
pub const INPUTS: usize = 7;

/// The inputs of a tape: `ω` (or `Ω`), `γ` and `p_ψ`, in any scalar type.
#[derive(Copy, Clone, PartialEq, Debug)]
pub struct Inputs<S> {
    /// `ω` for the Lagrangian's outputs, `Ω` for the Routh function's.
    pub omega: [S; 3],
    /// `γ`.
    pub gamma: [S; 3],
    /// `p_ψ`.
    pub p_psi: S,
}

/// A straight-line program: [`Op`]s in children-first order and named [`Output`]s, reading
/// [`Tape::num_params`] parameter values. Built by `#[derive(Lagrangian)]` as `static` data
/// ([`Tape::from_static`]) or at run time ([`Tape::new`]); always valid (every operand an
/// earlier slot, every input and parameter in range), so evaluation never fails.
///
/// ```
/// use routh_tape::{Inputs, Op, Output, Tape};
/// // γ₀ · p_ψ + 2
/// static OPS: [Op; 5] = [Op::Gamma(0), Op::PPsi, Op::Mul(0, 1), Op::Const(0x4000000000000000), Op::Add(2, 3)];
/// static OUT: [Output; 1] = [Output { name: "f", slot: 4 }];
/// static TAPE: Tape = Tape::from_static(&OPS, &OUT, 0);
/// let x = Inputs { omega: [0.0; 3], gamma: [3.0, 0.0, 0.0], p_psi: 0.5 };
/// let mut slots = Vec::new();
/// let mut out = [0.0];
/// TAPE.eval(&x, &[], &mut slots, &mut out);
/// assert_eq!(out[0], 3.5);
/// ```
#[derive(Clone, PartialEq, Debug)]
pub struct Tape {
    ops: Cow<'static, [Op]>,
    outputs: Cow<'static, [Output]>,
    num_params: u32,
}

/// Checks the tape rules; `const` so that [`Tape::from_static`] checks a `static` tape at
/// compile time.
const fn check(ops: &[Op], outputs: &[Output], num_params: u32) -> Result<(), TapeError> {
    let mut i = 0;
    while i < ops.len() {
        let n = i as u32;
        let (a, b) = match ops[i] {
            Op::Const(_) | Op::PPsi => (None, None),
            Op::Omega(k) | Op::Gamma(k) => {
                if k >= 3 {
                    return Err(TapeError::BadInput { op: i });
                }
                (None, None)
            }
            Op::Param(k) => {
                if k >= num_params {
                    return Err(TapeError::BadParam { op: i, param: k });
                }
                (None, None)
            }
            Op::Add(a, b) | Op::Mul(a, b) | Op::Powf(a, b) => (Some(a), Some(b)),
            Op::Neg(a) | Op::Recip(a) | Op::Powi(a, _) | Op::Func(_, a) => (Some(a), None),
        };
        if let Some(a) = a {
            if a >= n {
                return Err(TapeError::NotChildrenFirst { op: i, operand: a });
            }
        }
        if let Some(b) = b {
            if b >= n {
                return Err(TapeError::NotChildrenFirst { op: i, operand: b });
            }
        }
        i += 1;
    }
    let mut k = 0;
    while k < outputs.len() {
        if outputs[k].slot as usize >= ops.len() {
            return Err(TapeError::BadOutput {
                name: outputs[k].name,
            });
        }
        k += 1;
    }
    Ok(())
}

impl Tape {
    /// A tape of `static` data, as the derive emits it.
    ///
    /// # Panics
    /// If the ops break a rule of [`Tape::new`]: in a `static` or `const` initializer (the only
    /// use the derive makes of it) that is a compile-time error, never a run-time panic.
    pub const fn from_static(
        ops: &'static [Op],
        outputs: &'static [Output],
        num_params: u32,
    ) -> Tape {
        if check(ops, outputs, num_params).is_err() {
            panic!("invalid tape");
        }
        Tape {
            ops: Cow::Borrowed(ops),
            outputs: Cow::Borrowed(outputs),
            num_params,
        }
    }

    /// A tape of ops built at run time, checked: every operand an earlier slot, every `ω_i`,
    /// `γ_i` with `i < 3`, every parameter `< num_params`, every output an existing slot.
    pub fn new(ops: Vec<Op>, outputs: Vec<Output>, num_params: u32) -> Result<Tape, TapeError> {
        check(&ops, &outputs, num_params)?;
        Ok(Tape {
            ops: Cow::Owned(ops),
            outputs: Cow::Owned(outputs),
            num_params,
        })
    }

    /// The operations.
    pub fn ops(&self) -> &[Op] {
        &self.ops
    }

    /// The outputs, in order.
    pub fn outputs(&self) -> &[Output] {
        &self.outputs
    }

    /// The position of the output called `name`.
    pub fn output_index(&self, name: &str) -> Option<usize> {
        self.outputs.iter().position(|o| o.name == name)
    }

    /// How many parameter values the tape reads ([`Op::Param`] `k < num_params`).
    pub fn num_params(&self) -> usize {
        self.num_params as usize
    }

    /// Number of operations.
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// Whether the tape has no operations.
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }

    /// The tape with parameter `k` replaced by the constant `params[k]` (and no parameters
    /// left): what a runtime model evaluates, its parameter values folded in.
    pub fn bind(&self, params: &[f64]) -> Result<Tape, TapeError> {
        if params.len() != self.num_params() {
            return Err(TapeError::ParamCount {
                want: self.num_params(),
                got: params.len(),
            });
        }
        let ops = self
            .ops
            .iter()
            .map(|op| match *op {
                Op::Param(k) => Op::constant(params[k as usize]),
                op => op,
            })
            .collect();
        Tape::new(ops, self.outputs.to_vec(), 0)
    }

    /// Evaluates the tape at `inputs` with parameter values `params` (read as
    /// `S::from_f64(params[k])`), writing output `k` to `out[k]`. `slots` is working storage,
    /// reused between calls (no allocation once it has grown to [`Tape::len`]).
    ///
    /// A `params` shorter than [`Tape::num_params`] reads missing parameters as NaN; an `out`
    /// shorter than the outputs receives the first ones.
    pub fn eval<S: TapeScalar>(
        &self,
        inputs: &Inputs<S>,
        params: &[f64],
        slots: &mut Vec<S>,
        out: &mut [S],
    ) {
        slots.clear();
        slots.reserve(self.ops.len());
        for op in self.ops.iter() {
            // Operands are earlier slots (checked when the tape was made).
            let v = |i: u32| slots[i as usize];
            let x = match *op {
                Op::Const(bits) => S::from_f64(f64::from_bits(bits)),
                Op::Omega(k) => inputs.omega[k as usize],
                Op::Gamma(k) => inputs.gamma[k as usize],
                Op::PPsi => inputs.p_psi,
                Op::Param(k) => S::from_f64(params.get(k as usize).copied().unwrap_or(f64::NAN)),
                Op::Add(a, b) => v(a) + v(b),
                // x·x as a square: the same f64, a tighter enclosure for intervals.
                Op::Mul(a, b) if a == b => v(a).powi(2),
                Op::Mul(a, b) => v(a) * v(b),
                Op::Neg(a) => -v(a),
                Op::Recip(a) => v(a).recip(),
                Op::Powi(a, n) => v(a).powi(n),
                Op::Powf(a, b) => v(a).powf(v(b)),
                Op::Func(f, a) => v(a).func(f),
            };
            slots.push(x);
        }
        for (o, y) in self.outputs.iter().zip(out.iter_mut()) {
            *y = slots[o.slot as usize];
        }
    }
}
