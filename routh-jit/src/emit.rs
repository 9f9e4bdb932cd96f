//! The body of one compiled tape: Cranelift IR for its operations (no `unsafe` here).
//!
//! One basic block of straight-line SSA, in the tape's children-first order (already free of
//! common subexpressions); Cranelift's e-graph pass then places each pure value where it is
//! first needed. Operations of constants are computed here, with the very `f64` operations the
//! interpreter of `routh-runtime` folds them with, so both hold the same constants; each
//! constant is made once. The inputs and parameters are loaded once each, as pure values. The
//! operations are `fadd`, `fsub` (for `a + (−x)`), `fmul` (`x·x` for a square), `fdiv` (`1/x`),
//! `sqrt`, `fabs`; a negation is carried to the operations that read it and costs nothing there
//! (see [`Val`]), else it is an `xor` of the sign bit; `xⁿ` by repeated squaring inline, in the
//! order of `f64::powi` (compiler-builtins' `__powidf2`): the same products, so the same bits;
//! `sign` inline, exactly as [`routh_tape::sign`]; `sin`, `cos`, `tan`, `exp`, `ln` and `powf`
//! as calls to the Rust wrappers of `crate::libcalls`.

use crate::{libcalls, JitError};
use cranelift_codegen::ir::condcodes::FloatCC;
use cranelift_codegen::ir::{types, FuncRef, InstBuilder, MemFlagsData, Value};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::JITModule;
use cranelift_module::{FuncId, Module};
use routh_tape::INPUTS;
use routh_tape::{Func, Op, Tape};
use std::collections::HashMap;

fn codegen(e: impl std::fmt::Display) -> JitError {
    JitError::Codegen(e.to_string())
}

/// A tape's value at a slot: a constant (folded), or an SSA value or its negation.
///
/// A negation is carried, not computed, to the operations that read it, where it is free:
/// `a + (−x)` is `a − x`, `(−a)·x` is `−(a·x)`, `1/(−a)` is `−(1/a)`, `(−a)ⁿ` is `±aⁿ` by the
/// parity of `n`, `|−a|` is `|a|`, all exactly (IEEE 754 rounds symmetrically). Only the
/// functions, `xʸ`, the outputs and `(−a) + (−b)` (not `−(a + b)` at `a = 0`, `b = −0`)
/// compute it, as an `xor` of the sign bit.
#[derive(Copy, Clone)]
enum Val {
    Const(f64),
    Ssa { v: Value, neg: bool },
}

/// Emits the operations of one tape, carrying negations (see [`Val`]).
struct Emit<'a, 'b> {
    b: FunctionBuilder<'b>,
    /// Each constant once (by bits).
    consts: HashMap<u64, Value>,
    /// Each negation computed once.
    negated: HashMap<Value, Value>,
    /// The values of the leaves, loaded where first read.
    leaves: HashMap<usize, Value>,
    inputs: Value,
    params: Value,
    flags: MemFlagsData,
    module: &'a mut JITModule,
    imports: &'a HashMap<&'static str, FuncId>,
    refs: HashMap<&'static str, FuncRef>,
}

impl Emit<'_, '_> {
    fn constant(&mut self, x: f64) -> Value {
        let b = &mut self.b;
        *self
            .consts
            .entry(x.to_bits())
            .or_insert_with(|| b.ins().f64const(x))
    }

    /// The value of `v`, its negation computed if it is carried.
    fn value(&mut self, v: Val) -> Value {
        match v {
            Val::Const(x) => self.constant(x),
            Val::Ssa { v, neg: false } => v,
            Val::Ssa { v, neg: true } => {
                if let Some(&n) = self.negated.get(&v) {
                    return n;
                }
                // `−x` flips the sign bit: an `xor` with `−0.0`, a constant made once (Cranelift
                // makes the mask anew for each `fneg`).
                let mask = self.constant(-0.0);
                let n = self.b.ins().bxor(v, mask);
                self.negated.insert(v, n);
                n
            }
        }
    }

    /// Input `k` of the inputs (`k < INPUTS`) or, `param`, of the parameters (`k <
    /// MAX_PARAMS`): the offset fits an i32.
    fn load(&mut self, param: bool, k: usize) -> Value {
        let key = if param { INPUTS + k } else { k };
        let base = if param { self.params } else { self.inputs };
        // The inputs are not written while the function runs (the outputs go to a buffer
        // borrowed uniquely, `crate::code::Entry::call`): a load is a pure value, which
        // Cranelift places where it is used.
        let flags = self.flags.with_readonly().with_can_move();
        let b = &mut self.b;
        *self
            .leaves
            .entry(key)
            .or_insert_with(|| b.ins().load(types::F64, flags, base, (8 * k) as i32))
    }

    fn call(&mut self, name: &'static str, args: &[Value]) -> Result<Value, JitError> {
        let fref = match self.refs.get(name) {
            Some(r) => *r,
            None => {
                let id = *self
                    .imports
                    .get(name)
                    .ok_or_else(|| codegen(format!("no import {name}")))?;
                let r = self.module.declare_func_in_func(id, self.b.func);
                self.refs.insert(name, r);
                r
            }
        };
        let inst = self.b.ins().call(fref, args);
        self.b
            .inst_results(inst)
            .first()
            .copied()
            .ok_or_else(|| codegen(format!("{name} returned nothing")))
    }

    /// `op` on the operand values `x` and `y` (`y` for the binary operations).
    fn op(&mut self, op: &Op, x: Val, y: Val) -> Result<Val, JitError> {
        let ssa = |v: Value, neg: bool| Val::Ssa { v, neg };
        Ok(match *op {
            Op::Omega(k) => ssa(self.load(false, usize::from(k)), false),
            Op::Gamma(k) => ssa(self.load(false, 3 + usize::from(k)), false),
            Op::PPsi => ssa(self.load(false, 6), false),
            Op::Param(k) => ssa(self.load(true, k as usize), false),
            // Leaves that are constants are folded before.
            Op::Const(bits) => Val::Const(f64::from_bits(bits)),
            Op::Neg(_) => match x {
                Val::Const(c) => Val::Const(-c),
                Val::Ssa { v, neg } => ssa(v, !neg),
            },
            Op::Add(..) => match (x, y) {
                // x + (−y) = x − y; (−x) + y = y − x.
                (Val::Ssa { v: a, neg: true }, Val::Ssa { v: c, neg: false })
                | (Val::Ssa { v: c, neg: false }, Val::Ssa { v: a, neg: true }) => {
                    ssa(self.b.ins().fsub(c, a), false)
                }
                (Val::Ssa { v: a, neg: true }, Val::Const(c))
                | (Val::Const(c), Val::Ssa { v: a, neg: true }) => {
                    let c = self.constant(c);
                    ssa(self.b.ins().fsub(c, a), false)
                }
                // (−x) + (−y) is not −(x + y) at x = 0, y = −0: one negation computed.
                (Val::Ssa { neg: true, .. }, Val::Ssa { v: c, neg: true }) => {
                    let a = self.value(x);
                    ssa(self.b.ins().fsub(a, c), false)
                }
                _ => {
                    let (a, c) = (self.value(x), self.value(y));
                    ssa(self.b.ins().fadd(a, c), false)
                }
            },
            Op::Mul(a, c) if a == c => {
                let v = self.value(strip(x));
                ssa(self.b.ins().fmul(v, v), false)
            }
            Op::Mul(..) => match (x, y) {
                // c·(−v) = (−c)·v.
                (Val::Const(c), Val::Ssa { v, neg }) | (Val::Ssa { v, neg }, Val::Const(c)) => {
                    let c = self.constant(if neg { -c } else { c });
                    let (l, r) = if matches!(x, Val::Const(_)) {
                        (c, v)
                    } else {
                        (v, c)
                    };
                    ssa(self.b.ins().fmul(l, r), false)
                }
                (Val::Ssa { v: a, neg: n }, Val::Ssa { v: c, neg: m }) => {
                    ssa(self.b.ins().fmul(a, c), n != m)
                }
                (Val::Const(_), Val::Const(_)) => {
                    let (a, c) = (self.value(x), self.value(y));
                    ssa(self.b.ins().fmul(a, c), false)
                }
            },
            Op::Recip(_) => {
                let (neg, a) = (negated(x), self.value(strip(x)));
                let one = self.constant(1.0);
                ssa(self.b.ins().fdiv(one, a), neg)
            }
            Op::Powi(_, n) => {
                let (neg, a) = (negated(x), self.value(strip(x)));
                ssa(powi(self, a, n), neg && n % 2 != 0)
            }
            Op::Powf(..) => {
                let (a, c) = (self.value(x), self.value(y));
                ssa(self.call(libcalls::POWF, &[a, c])?, false)
            }
            Op::Func(Func::Abs, _) => {
                let a = self.value(strip(x));
                ssa(self.b.ins().fabs(a), false)
            }
            Op::Func(f, _) => {
                let a = self.value(x);
                let y = match f {
                    Func::Sqrt => self.b.ins().sqrt(a),
                    Func::Sign => sign(self, a),
                    f => {
                        let name = libcalls::unary(f)
                            .ok_or_else(|| codegen(format!("no wrapper for {}", f.name())))?;
                        self.call(name, &[a])?
                    }
                };
                ssa(y, false)
            }
        })
    }
}

/// Whether `v` is a carried negation.
fn negated(v: Val) -> bool {
    matches!(v, Val::Ssa { neg: true, .. })
}

/// `v` without its carried negation.
fn strip(v: Val) -> Val {
    match v {
        Val::Ssa { v, .. } => Val::Ssa { v, neg: false },
        c => c,
    }
}

/// Writes the body of `tape` into `func`; the number of instructions of the tape kept (not
/// folded).
pub(crate) fn body(
    func: &mut cranelift_codegen::ir::Function,
    fctx: &mut FunctionBuilderContext,
    module: &mut JITModule,
    imports: &HashMap<&'static str, FuncId>,
    tape: &Tape,
) -> Result<usize, JitError> {
    let ops = tape.ops();
    let mut b = FunctionBuilder::new(func, fctx);
    let block = b.create_block();
    b.append_block_params_for_function_params(block);
    b.switch_to_block(block);
    b.seal_block(block);
    let (inputs, params, out) = match b.block_params(block) {
        [i, p, o] => (*i, *p, *o),
        _ => return Err(codegen("the function does not take three pointers")),
    };
    let mut e = Emit {
        b,
        consts: HashMap::new(),
        negated: HashMap::new(),
        leaves: HashMap::new(),
        inputs,
        params,
        // Reads and writes of the caller's buffers: aligned, in bounds (checked before every
        // call), never trapping.
        flags: MemFlagsData::trusted(),
        module,
        imports,
        refs: HashMap::new(),
    };
    let mut slots: Vec<Val> = Vec::with_capacity(ops.len());
    let mut kept = 0;
    for op in ops {
        let c = |s: u32| match slots.get(s as usize) {
            Some(Val::Const(x)) => Some(*x),
            _ => None,
        };
        // Operations of constants, folded by the tape's one rule (as the interpreter folds
        // them).
        if let Some(x) = op.fold(c) {
            slots.push(Val::Const(x));
            continue;
        }
        kept += 1;
        let mut operands = op.operands().map(|a| slots.get(a as usize).copied());
        let mut next = || match operands.next() {
            Some(Some(v)) => Ok(v),
            Some(None) => Err(codegen("an operand after its user")),
            None => Ok(Val::Const(0.0)),
        };
        let (x, y) = (next()?, next()?);
        let v = e.op(op, x, y)?;
        slots.push(v);
    }
    for (k, o) in tape.outputs().iter().enumerate() {
        let v = *slots
            .get(o.slot as usize)
            .ok_or_else(|| codegen("an output past the end"))?;
        let y = e.value(v);
        let offset = i32::try_from(8 * k).map_err(|_| codegen("too many outputs"))?;
        e.b.ins().store(e.flags, y, out, offset);
    }
    e.b.ins().return_(&[]);
    let config = e.module.target_config();
    e.b.finalize(config);
    Ok(kept)
}

/// `xⁿ` as `f64::powi` computes it (compiler-builtins' `__powidf2`, and LLVM's expansion of a
/// constant exponent): the product of the squares `x^(2^i)` of the set bits of `|n|`, lowest
/// first, then `1/·` for `n < 0`; `x⁰ = 1`.
fn powi(em: &mut Emit, x: Value, n: i32) -> Value {
    let mut e = n.unsigned_abs();
    let mut acc: Option<Value> = None;
    let mut square = x;
    while e != 0 {
        if e & 1 == 1 {
            acc = Some(match acc {
                None => square,
                Some(r) => em.b.ins().fmul(r, square),
            });
        }
        e >>= 1;
        if e != 0 {
            square = em.b.ins().fmul(square, square);
        }
    }
    let r = match acc {
        Some(r) => r,
        None => return em.constant(1.0),
    };
    if n < 0 {
        let one = em.constant(1.0);
        em.b.ins().fdiv(one, r)
    } else {
        r
    }
}

/// [`routh_tape::sign`]: `0` at `±0`, NaN at NaN, else `copysign(1, x)` (`f64::signum`).
fn sign(e: &mut Emit, x: Value) -> Value {
    let zero = e.constant(0.0);
    let one = e.constant(1.0);
    let nan = e.constant(f64::NAN);
    let b = &mut e.b;
    let signum = b.ins().fcopysign(one, x);
    let is_nan = b.ins().fcmp(FloatCC::Unordered, x, x);
    let signum = b.ins().select(is_nan, nan, signum);
    let is_zero = b.ins().fcmp(FloatCC::Equal, x, zero);
    b.ins().select(is_zero, zero, signum)
}
