//! Native code for `routh` tapes at run time: a [Cranelift](https://cranelift.dev) JIT of
//! [`routh_tape::Tape`].
//!
//! [`JitFunction::compile`] turns a tape into one machine-code function
//! `f(inputs: *const f64, out: *mut f64)`, straight-line, in the tape's children-first order
//! (which is already free of common subexpressions), operations of constants computed at
//! compile time. `inputs` is `[ω₀, ω₁, ω₂, γ₀, γ₁, γ₂, p_ψ]` (`Ω` for the Routh function's
//! tapes) followed by the tape's parameter values, if it still has parameters
//! ([`Op::Param`](routh_tape::Op::Param) `k` reads `inputs[7 + k]`); a tape whose parameters
//! are bound ([`Tape::bind`]) has them as constants. [`JitFunction::eval`] checks the buffers'
//! lengths before every call.
//!
//! The functions compute what the interpreter of `routh-runtime` and [`Tape::eval`] compute,
//! with the same IEEE operations (squares as `x·x`, `xⁿ` by the same repeated squaring as
//! `f64::powi`, `1/x` as a division, `sqrt` and `abs` natively, the transcendental functions by
//! calls to Rust's own), so the results are bit for bit the same.
//!
//! ```
//! use routh_jit::JitFunction;
//! use routh_tape::{Func, Op, Output, Tape};
//! // sin(γ₀)² + Ω₁
//! let tape = Tape::new(
//!     vec![Op::Gamma(0), Op::Func(Func::Sin, 0), Op::Mul(1, 1), Op::Omega(1), Op::Add(2, 3)],
//!     vec![Output { name: "f", slot: 4 }],
//!     0,
//! )?;
//! let f = JitFunction::compile(&tape)?;
//! let mut out = [0.0];
//! f.eval(&[0.0, 1.0, 0.0, 0.5, 0.0, 0.0, 0.0], &mut out)?;
//! assert_eq!(out[0], 0.5f64.sin().powi(2) + 1.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Only `code` (ownership of the machine code and the call into it) uses `unsafe`; the rest of
//! the crate denies it.
#![deny(unsafe_code)]

#[allow(unsafe_code)]
mod code;
mod compile;
mod libcalls;

pub use compile::{is_supported, INPUTS, MAX_PARAMS};
use routh_tape::Tape;

/// Why a tape could not be compiled or a compiled function not run.
#[derive(Clone, PartialEq, Eq, Debug, thiserror::Error)]
pub enum JitError {
    /// Cranelift does not support this host (or its settings were refused).
    #[error("the JIT does not support this host: {0}")]
    Unsupported(String),
    /// Cranelift failed to compile the function.
    #[error("code generation failed: {0}")]
    Codegen(String),
    /// The tape reads more parameters than [`MAX_PARAMS`].
    #[error("the tape reads {0} parameters, more than the JIT accepts ({MAX_PARAMS})")]
    TooManyParams(usize),
    /// The buffers given to [`JitFunction::eval`] are shorter than the function reads or
    /// writes.
    #[error(
        "buffers too short: {inputs} inputs and {outputs} outputs given, the function reads \
         {want_inputs} and writes {want_outputs}"
    )]
    BufferLength {
        /// The inputs given.
        inputs: usize,
        /// The outputs given.
        outputs: usize,
        /// The inputs read: [`INPUTS`] plus the tape's parameters.
        want_inputs: usize,
        /// The outputs written.
        want_outputs: usize,
    },
}

/// A tape compiled to machine code. Cheap to clone (the code is shared, and freed when the
/// last clone of every function compiled with it is dropped); `Send + Sync`.
#[derive(Clone, Debug)]
pub struct JitFunction {
    entry: code::Entry,
    instructions: usize,
}

impl JitFunction {
    /// Compiles `tape`.
    ///
    /// Errors: [`JitError::Unsupported`] on a host Cranelift does not support,
    /// [`JitError::TooManyParams`], [`JitError::Codegen`] if Cranelift fails.
    pub fn compile(tape: &Tape) -> Result<JitFunction, JitError> {
        let mut all = JitFunction::compile_all(&[tape])?;
        all.pop()
            .ok_or_else(|| JitError::Codegen("no function was compiled".into()))
    }

    /// Compiles several tapes at once, into one block of code (cheaper than one by one: one
    /// module, one finalization); the functions in the order of `tapes`.
    pub fn compile_all(tapes: &[&Tape]) -> Result<Vec<JitFunction>, JitError> {
        Ok(compile::compile_all(tapes)?
            .into_iter()
            .map(|(entry, instructions)| JitFunction {
                entry,
                instructions,
            })
            .collect())
    }

    /// Evaluates the outputs at `inputs` (`[ω, γ, p_ψ]` then the parameters, see the crate
    /// documentation) into `out` (output `k` to `out[k]`; longer buffers are fine, their extra
    /// values are neither read nor written).
    ///
    /// Errors: [`JitError::BufferLength`] if `inputs` is shorter than [`JitFunction::inputs`]
    /// or `out` shorter than [`JitFunction::outputs`] (nothing is written then).
    #[inline]
    pub fn eval(&self, inputs: &[f64], out: &mut [f64]) -> Result<(), JitError> {
        if self.entry.call(inputs, out) {
            Ok(())
        } else {
            Err(JitError::BufferLength {
                inputs: inputs.len(),
                outputs: out.len(),
                want_inputs: self.entry.inputs(),
                want_outputs: self.entry.outputs(),
            })
        }
    }

    /// The number of input values read: [`INPUTS`] plus the tape's parameters.
    pub fn inputs(&self) -> usize {
        self.entry.inputs()
    }

    /// The number of outputs written.
    pub fn outputs(&self) -> usize {
        self.entry.outputs()
    }

    /// The number of operations of the tape left after folding constants (each one or a few
    /// machine instructions, or a call).
    pub fn instructions(&self) -> usize {
        self.instructions
    }
}
