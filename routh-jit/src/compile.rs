//! From a tape to Cranelift IR and machine code (no `unsafe` here: the call into the code is in
//! `crate::code`).
//!
//! Each tape becomes one function `f(inputs: *const f64, params: *const f64, out: *mut f64)`
//! (`inputs` = `[ω, γ, p_ψ]`, `params` the tape's parameter values): one basic block of
//! straight-line SSA, in the tape's children-first order (already free of common
//! subexpressions). Operations of constants are computed here, with the very `f64` operations
//! the interpreter of `routh-runtime` folds them with, so both hold the same constants. The
//! operations are `fadd`, `fmul` (`x·x` for a square), `fneg`, `fdiv` (`1/x`), `sqrt`, `fabs`;
//! `xⁿ` by repeated squaring inline, in the order of `f64::powi` (compiler-builtins'
//! `__powidf2`): the same products, so the same bits; `sign` inline, exactly as
//! [`routh_tape::sign`]; `sin`, `cos`, `tan`, `exp`, `ln` and `powf` as calls to the Rust
//! wrappers of `crate::libcalls`.

use crate::code::{Code, Entry};
use crate::{libcalls, JitError};
use cranelift_codegen::ir::condcodes::FloatCC;
use cranelift_codegen::ir::{types, AbiParam, FuncRef, InstBuilder, MemFlagsData, Value};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::{FunctionBuilder, FunctionBuilderContext};
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{FuncId, Linkage, Module};
use routh_tape::{Func, Op, Tape};
use std::collections::HashMap;
use std::sync::OnceLock;

/// The most parameters a tape compiled with its parameters unbound may read.
pub const MAX_PARAMS: usize = 1 << 20;

/// How hard Cranelift optimizes.
#[derive(Copy, Clone, PartialEq, Eq, Debug, Default)]
pub enum OptLevel {
    /// No optimization passes and the single-pass register allocator: the fastest to compile,
    /// the slowest code.
    None,
    /// Cranelift's `speed` (e-graph rewrites, GVN, LICM; the default).
    #[default]
    Speed,
}

/// The host's instruction set, detected once per optimization level.
fn isa(opt: OptLevel) -> Result<OwnedTargetIsa, JitError> {
    static SPEED: OnceLock<Result<OwnedTargetIsa, String>> = OnceLock::new();
    static NONE: OnceLock<Result<OwnedTargetIsa, String>> = OnceLock::new();
    let (cell, level) = match opt {
        OptLevel::Speed => (&SPEED, "speed"),
        OptLevel::None => (&NONE, "none"),
    };
    cell.get_or_init(|| {
        let mut flags = settings::builder();
        let set = |flags: &mut settings::Builder, name: &str, value: &str| {
            flags
                .set(name, value)
                .map_err(|e| format!("setting {name}={value}: {e}"))
        };
        // The JIT needs absolute, non-colocated calls (cranelift-jit's requirement).
        set(&mut flags, "use_colocated_libcalls", "false")?;
        set(&mut flags, "is_pic", "false")?;
        set(&mut flags, "opt_level", level)?;
        let regalloc = match opt {
            OptLevel::Speed => "backtracking",
            OptLevel::None => "single_pass",
        };
        set(&mut flags, "regalloc_algorithm", regalloc)?;
        // The code never unwinds (the wrappers it calls cannot), and nothing walks its frames.
        set(&mut flags, "unwind_info", "false")?;
        // Check the IR in debug builds (the tests); skip it in release builds.
        let verify = if cfg!(debug_assertions) {
            "true"
        } else {
            "false"
        };
        set(&mut flags, "enable_verifier", verify)?;
        let builder = cranelift_native::builder().map_err(str::to_string)?;
        builder
            .finish(settings::Flags::new(flags))
            .map_err(|e| e.to_string())
    })
    .clone()
    .map_err(JitError::Unsupported)
}

/// Whether Cranelift supports this host (its instruction set could be set up).
pub fn is_supported() -> bool {
    isa(OptLevel::default()).is_ok()
}

fn codegen(e: impl std::fmt::Display) -> JitError {
    JitError::Codegen(e.to_string())
}

/// A tape's value at a slot: a constant (folded) or an SSA value.
#[derive(Copy, Clone)]
enum Val {
    Const(f64),
    Ssa(Value),
}

/// Compiles every tape into one module; the entries in the order of `tapes`, each with the
/// number of operations it executes.
pub(crate) fn compile_all(tapes: &[&Tape], opt: OptLevel) -> Result<Vec<(Entry, usize)>, JitError> {
    let isa = isa(opt)?;
    let mut builder = JITBuilder::with_isa(isa, cranelift_module::default_libcall_names());
    builder.symbols(libcalls::symbols());
    let mut module = JITModule::new(builder);
    let ptr = module.target_config().pointer_type();
    let mut sig = module.make_signature();
    sig.params.push(AbiParam::new(ptr));
    sig.params.push(AbiParam::new(ptr));
    sig.params.push(AbiParam::new(ptr));

    let mut unary = module.make_signature();
    unary.params.push(AbiParam::new(types::F64));
    unary.returns.push(AbiParam::new(types::F64));
    let mut binary = unary.clone();
    binary.params.push(AbiParam::new(types::F64));
    let mut imports: HashMap<&'static str, FuncId> = HashMap::new();
    for f in Func::ALL {
        if let Some(name) = libcalls::unary(f) {
            let id = module
                .declare_function(name, Linkage::Import, &unary)
                .map_err(codegen)?;
            imports.insert(name, id);
        }
    }
    let id = module
        .declare_function(libcalls::POWF, Linkage::Import, &binary)
        .map_err(codegen)?;
    imports.insert(libcalls::POWF, id);

    let mut ctx = module.make_context();
    let mut fctx = FunctionBuilderContext::new();
    let mut made: Vec<(FuncId, usize, usize, usize)> = Vec::with_capacity(tapes.len());
    for (k, tape) in tapes.iter().enumerate() {
        if tape.num_params() > MAX_PARAMS {
            return Err(JitError::TooManyParams(tape.num_params()));
        }
        ctx.func.signature = sig.clone();
        let count = body(&mut ctx.func, &mut fctx, &mut module, &imports, tape)?;
        let id = module
            .declare_function(&format!("tape{k}"), Linkage::Local, &sig)
            .map_err(codegen)?;
        module.define_function(id, &mut ctx).map_err(codegen)?;
        module.clear_context(&mut ctx);
        made.push((id, tape.num_params(), tape.outputs().len(), count));
    }
    module.finalize_definitions().map_err(codegen)?;
    let code = Code::new(module);
    Ok(made
        .into_iter()
        .map(|(id, params, outputs, count)| (code.entry(id, params, outputs), count))
        .collect())
}

/// Writes the body of `tape` into `func`; the number of instructions of the tape kept (not
/// folded).
fn body(
    func: &mut cranelift_codegen::ir::Function,
    fctx: &mut FunctionBuilderContext,
    module: &mut JITModule,
    imports: &HashMap<&'static str, FuncId>,
    tape: &Tape,
) -> Result<usize, JitError> {
    let mut b = FunctionBuilder::new(func, fctx);
    let block = b.create_block();
    b.append_block_params_for_function_params(block);
    b.switch_to_block(block);
    b.seal_block(block);
    let (inputs, params, out) = match b.block_params(block) {
        [i, p, o] => (*i, *p, *o),
        _ => return Err(codegen("the function does not take three pointers")),
    };
    // Reads of the caller's buffers: aligned, in bounds (checked before every call), never
    // trapping.
    let flags = MemFlagsData::trusted();
    let mut refs: HashMap<&'static str, FuncRef> = HashMap::new();
    let mut call = |b: &mut FunctionBuilder, name: &'static str, args: &[Value]| {
        let fref = match refs.get(name) {
            Some(r) => *r,
            None => {
                let id = *imports
                    .get(name)
                    .ok_or_else(|| codegen(format!("no import {name}")))?;
                let r = module.declare_func_in_func(id, b.func);
                refs.insert(name, r);
                r
            }
        };
        let inst = b.ins().call(fref, args);
        b.inst_results(inst)
            .first()
            .copied()
            .ok_or_else(|| codegen(format!("{name} returned nothing")))
    };
    let mut slots: Vec<Val> = Vec::with_capacity(tape.len());
    let mut count = 0;
    for op in tape.ops() {
        let c = |s: u32| match slots[s as usize] {
            Val::Const(x) => Some(x),
            Val::Ssa(_) => None,
        };
        // Operations of constants, folded by the tape's one rule (as the interpreter folds them);
        // a parameter is read from the input buffer.
        let folded = op.fold(c);
        if let Some(x) = folded {
            slots.push(Val::Const(x));
            continue;
        }
        let v = |b: &mut FunctionBuilder, s: u32| match slots[s as usize] {
            Val::Const(x) => b.ins().f64const(x),
            Val::Ssa(v) => v,
        };
        // k < INPUTS, or k < MAX_PARAMS for a parameter: the offset fits an i32.
        let load = |b: &mut FunctionBuilder, k: usize| {
            b.ins().load(types::F64, flags, inputs, (8 * k) as i32)
        };
        let load_param = |b: &mut FunctionBuilder, k: usize| {
            b.ins().load(types::F64, flags, params, (8 * k) as i32)
        };
        count += 1;
        let y = match *op {
            Op::Omega(k) => load(&mut b, usize::from(k)),
            Op::Gamma(k) => load(&mut b, 3 + usize::from(k)),
            Op::PPsi => load(&mut b, 6),
            Op::Param(k) => load_param(&mut b, k as usize),
            Op::Add(a, x) => {
                let (a, x) = (v(&mut b, a), v(&mut b, x));
                b.ins().fadd(a, x)
            }
            Op::Mul(a, x) => {
                let (a, x) = (v(&mut b, a), v(&mut b, x));
                b.ins().fmul(a, x)
            }
            Op::Neg(a) => {
                let a = v(&mut b, a);
                b.ins().fneg(a)
            }
            Op::Recip(a) => {
                let a = v(&mut b, a);
                let one = b.ins().f64const(1.0);
                b.ins().fdiv(one, a)
            }
            Op::Powi(a, n) => {
                let a = v(&mut b, a);
                powi(&mut b, a, n)
            }
            Op::Powf(a, x) => {
                let (a, x) = (v(&mut b, a), v(&mut b, x));
                call(&mut b, libcalls::POWF, &[a, x])?
            }
            Op::Func(f, a) => {
                let a = v(&mut b, a);
                match f {
                    Func::Sqrt => b.ins().sqrt(a),
                    Func::Abs => b.ins().fabs(a),
                    Func::Sign => sign(&mut b, a),
                    f => {
                        let name = libcalls::unary(f)
                            .ok_or_else(|| codegen(format!("no wrapper for {}", f.name())))?;
                        call(&mut b, name, &[a])?
                    }
                }
            }
            // Leaves that are constants were folded above.
            Op::Const(bits) => b.ins().f64const(f64::from_bits(bits)),
        };
        slots.push(Val::Ssa(y));
    }
    for (k, o) in tape.outputs().iter().enumerate() {
        let y = match slots[o.slot as usize] {
            Val::Const(x) => b.ins().f64const(x),
            Val::Ssa(v) => v,
        };
        let offset = i32::try_from(8 * k).map_err(|_| codegen("too many outputs"))?;
        b.ins().store(flags, y, out, offset);
    }
    b.ins().return_(&[]);
    b.finalize(module.target_config());
    Ok(count)
}

/// `xⁿ` as `f64::powi` computes it (compiler-builtins' `__powidf2`, and LLVM's expansion of a
/// constant exponent): the product of the squares `x^(2^i)` of the set bits of `|n|`, lowest
/// first, then `1/·` for `n < 0`; `x⁰ = 1`.
fn powi(b: &mut FunctionBuilder, x: Value, n: i32) -> Value {
    let mut e = n.unsigned_abs();
    let mut acc: Option<Value> = None;
    let mut square = x;
    while e != 0 {
        if e & 1 == 1 {
            acc = Some(match acc {
                None => square,
                Some(r) => b.ins().fmul(r, square),
            });
        }
        e >>= 1;
        if e != 0 {
            square = b.ins().fmul(square, square);
        }
    }
    let r = match acc {
        Some(r) => r,
        None => return b.ins().f64const(1.0),
    };
    if n < 0 {
        let one = b.ins().f64const(1.0);
        b.ins().fdiv(one, r)
    } else {
        r
    }
}

/// [`routh_tape::sign`]: `0` at `±0`, NaN at NaN, else `copysign(1, x)` (`f64::signum`).
fn sign(b: &mut FunctionBuilder, x: Value) -> Value {
    let zero = b.ins().f64const(0.0);
    let one = b.ins().f64const(1.0);
    let nan = b.ins().f64const(f64::NAN);
    let signum = b.ins().fcopysign(one, x);
    let is_nan = b.ins().fcmp(FloatCC::Unordered, x, x);
    let signum = b.ins().select(is_nan, nan, signum);
    let is_zero = b.ins().fcmp(FloatCC::Equal, x, zero);
    b.ins().select(is_zero, zero, signum)
}
