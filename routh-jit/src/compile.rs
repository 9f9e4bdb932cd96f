//! From a tape to Cranelift IR and machine code (no `unsafe` here: the call into the code is in
//! `crate::code`).
//!
//! Each tape becomes one function `f(inputs: *const f64, params: *const f64, out: *mut f64)`
//! (`inputs` = `[ω, γ, p_ψ]`, `params` the tape's parameter values), its body written by
//! `crate::emit`; the tapes given together are compiled into one module, by Cranelift at
//! `opt_level` `speed` (or `none`).

use crate::code::{Code, Entry};
use crate::{emit, libcalls, JitError};
use cranelift_codegen::ir::{types, AbiParam};
use cranelift_codegen::isa::OwnedTargetIsa;
use cranelift_codegen::settings::{self, Configurable};
use cranelift_frontend::FunctionBuilderContext;
use cranelift_jit::{JITBuilder, JITModule};
use cranelift_module::{FuncId, Linkage, Module};
use routh_tape::{Func, Tape};
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
        let count = emit::body(&mut ctx.func, &mut fctx, &mut module, &imports, tape)?;
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
