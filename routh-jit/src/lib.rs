//! Native code for `routh` tapes at run time: a [Cranelift](https://cranelift.dev) JIT of
//! [`routh_tape::Tape`].
//!
//! [`JitFunction::compile`] turns a tape into one machine-code function
//! `f(inputs: *const f64, params: *const f64, out: *mut f64)`, straight-line, in the tape's
//! children-first order (which is already free of common subexpressions), operations of
//! constants computed at compile time. `inputs` is `[ω₀, ω₁, ω₂, γ₀, γ₁, γ₂, p_ψ]` (`Ω` for the
//! Routh function's tapes) and `params` the tape's parameter values, if it still has parameters
//! ([`Op::Param`](routh_tape::Op::Param) `k` reads `params[k]`), so that one compiled function
//! serves every set of parameter values ([`JitFunction::eval_params`]); [`JitFunction::eval`]
//! takes both in one buffer, the parameters after the inputs. A tape whose parameters are bound
//! ([`Tape::bind`]) has them as constants. Both check the buffers' lengths before every
//! call.
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
mod emit;
mod libcalls;

pub use compile::{is_supported, OptLevel, MAX_PARAMS};
use routh_tape::Tape;
/// The number of inputs before the parameters: `ω` (or `Ω`), `γ`, `p_ψ` (routh-tape's).
pub use routh_tape::INPUTS;

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
        JitFunction::compile_all_with(tapes, OptLevel::default())
    }

    /// [`JitFunction::compile_all`] at optimization level `opt`.
    pub fn compile_all_with(tapes: &[&Tape], opt: OptLevel) -> Result<Vec<JitFunction>, JitError> {
        Ok(compile::compile_all(tapes, opt)?
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
        let ran = match inputs.split_first_chunk::<INPUTS>() {
            Some((x, params)) => self.entry.call(x, params, out),
            None => false,
        };
        if ran {
            Ok(())
        } else {
            Err(self.length_error(inputs.len(), out.len()))
        }
    }

    /// Evaluates the outputs at `inputs = [ω, γ, p_ψ]` with the parameter values `params`
    /// (`Op::Param(k)` reads `params[k]`) into `out`: [`JitFunction::eval`] without copying the
    /// parameters next to the inputs, so that one compiled function serves every set of
    /// parameter values.
    ///
    /// ```
    /// use routh_jit::JitFunction;
    /// use routh_tape::{Op, Output, Tape};
    /// // k · γ₀
    /// let tape = Tape::new(vec![Op::Param(0), Op::Gamma(0), Op::Mul(0, 1)],
    ///     vec![Output { name: "f", slot: 2 }], 1)?;
    /// let f = JitFunction::compile(&tape)?;
    /// let (x, mut out) = ([0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0], [0.0]);
    /// f.eval_params(&x, &[2.0], &mut out)?;
    /// assert_eq!(out[0], 3.0);
    /// f.eval_params(&x, &[4.0], &mut out)?;
    /// assert_eq!(out[0], 6.0);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// Errors: [`JitError::BufferLength`] if `params` is shorter than [`JitFunction::params`]
    /// or `out` shorter than [`JitFunction::outputs`] (nothing is written then).
    #[inline]
    pub fn eval_params(
        &self,
        inputs: &[f64; INPUTS],
        params: &[f64],
        out: &mut [f64],
    ) -> Result<(), JitError> {
        if self.entry.call(inputs, params, out) {
            Ok(())
        } else {
            Err(self.length_error(INPUTS + params.len(), out.len()))
        }
    }

    fn length_error(&self, inputs: usize, outputs: usize) -> JitError {
        JitError::BufferLength {
            inputs,
            outputs,
            want_inputs: self.inputs(),
            want_outputs: self.entry.outputs(),
        }
    }

    /// The number of input values read: [`INPUTS`] plus the tape's parameters.
    pub fn inputs(&self) -> usize {
        INPUTS + self.entry.params()
    }

    /// The number of parameter values read (the tape's [`Tape::num_params`]).
    pub fn params(&self) -> usize {
        self.entry.params()
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

#[cfg(test)]
mod tests {
    use super::*;
    use routh_tape::{Func, Op, Output};

    fn out(name: &'static str, slot: u32) -> Output {
        Output { name, slot }
    }

    #[test]
    fn functions_are_send_sync_and_outlive_their_siblings() {
        fn send_sync<T: Send + Sync + Clone>() {}
        send_sync::<JitFunction>();
        let a = Tape::new(vec![Op::Gamma(0), Op::Neg(0)], vec![out("a", 1)], 0).unwrap();
        let b = Tape::new(vec![Op::PPsi, Op::Mul(0, 0)], vec![out("b", 1)], 0).unwrap();
        let mut both = JitFunction::compile_all(&[&a, &b]).unwrap();
        let g = both.pop().unwrap();
        drop(both);
        // The module lives while one of its functions does, on any thread.
        let y = std::thread::spawn(move || {
            let mut y = [0.0];
            g.eval(&[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0], &mut y)
                .unwrap();
            y[0]
        })
        .join()
        .unwrap();
        assert_eq!(y, 9.0);
    }

    #[test]
    fn short_buffers_are_errors_and_nothing_is_written() {
        let t = Tape::new(
            vec![Op::Param(1), Op::Omega(2), Op::Add(0, 1)],
            vec![out("a", 2), out("b", 0)],
            2,
        )
        .unwrap();
        let f = JitFunction::compile(&t).unwrap();
        assert_eq!((f.inputs(), f.outputs()), (9, 2));
        let mut y = [7.0; 2];
        let e = f.eval(&[0.0; 8], &mut y).unwrap_err();
        assert!(matches!(
            e,
            JitError::BufferLength {
                inputs: 8,
                want_inputs: 9,
                ..
            }
        ));
        assert_eq!(y, [7.0; 2]);
        assert!(f.eval(&[0.0; 9], &mut y[..1]).is_err());
        let x = [0.0, 0.0, 1.5, 0.0, 0.0, 0.0, 0.0, 100.0, 2.0];
        f.eval(&x, &mut y).unwrap();
        assert_eq!(y, [3.5, 2.0]);
        // Longer buffers: the extra values are neither read nor written.
        let mut z = [7.0; 3];
        let mut xs = x.to_vec();
        xs.push(f64::NAN);
        f.eval(&xs, &mut z).unwrap();
        assert_eq!(z, [3.5, 2.0, 7.0]);
    }

    /// `xⁿ` bit for bit as `f64::powi`, for exponents that take every path of the repeated
    /// squaring (zero, one, negative, powers of two, all bits set, the extremes).
    #[test]
    fn powi_is_f64_powi_bit_for_bit() {
        let ns = [
            0,
            1,
            -1,
            2,
            3,
            -3,
            5,
            7,
            8,
            -8,
            13,
            31,
            64,
            -77,
            1000,
            i32::MAX,
            i32::MIN,
            i32::MIN + 1,
        ];
        let xs = [
            1.0000001,
            -0.9999999,
            0.7,
            -1.3,
            3.0f64.sqrt(),
            0.0,
            -0.0,
            f64::INFINITY,
            f64::NAN,
        ];
        for n in ns {
            let t = Tape::new(vec![Op::Gamma(0), Op::Powi(0, n)], vec![out("y", 1)], 0).unwrap();
            let f = JitFunction::compile(&t).unwrap();
            for x in xs {
                let mut y = [0.0];
                f.eval(&[0.0, 0.0, 0.0, x, 0.0, 0.0, 0.0], &mut y).unwrap();
                let want = x.powi(n);
                assert!(
                    y[0].to_bits() == want.to_bits() || (y[0].is_nan() && want.is_nan()),
                    "{x}^{n}: jit {} f64::powi {want}",
                    y[0]
                );
            }
        }
    }

    #[test]
    fn sign_is_the_tape_sign() {
        let t = Tape::new(
            vec![Op::Gamma(0), Op::Func(Func::Sign, 0)],
            vec![out("y", 1)],
            0,
        )
        .unwrap();
        let f = JitFunction::compile(&t).unwrap();
        for x in [
            0.0,
            -0.0,
            2.5,
            -1e-320,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            let mut y = [9.0];
            f.eval(&[0.0, 0.0, 0.0, x, 0.0, 0.0, 0.0], &mut y).unwrap();
            let want = routh_tape::sign(x);
            assert!(
                y[0].to_bits() == want.to_bits() || (y[0].is_nan() && want.is_nan()),
                "sign({x}): jit {} tape {want}",
                y[0]
            );
        }
    }

    /// Negations are carried into the operations that read them (`a + (−x)` as `a − x`, signs
    /// of products, reciprocals and powers by parity): the same bits as the tape's own
    /// evaluation, at signed zeros, infinities and NaN, for negated inputs, negated results and
    /// negated constants, on either side of each operation.
    #[test]
    fn carried_negations_are_the_tape_bit_for_bit() {
        let xs = [
            0.0,
            -0.0,
            1.5,
            -2.25,
            1e-310,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        // γ₀, γ₁, −γ₀, −γ₁, the constant −0.75 and its negation, γ₀·γ₁, −(γ₀·γ₁), γ₀ + γ₁,
        // −(γ₀ + γ₁).
        let leaves = vec![
            Op::Gamma(0),
            Op::Gamma(1),
            Op::Neg(0),
            Op::Neg(1),
            Op::constant(-0.75),
            Op::Neg(4),
            Op::Mul(0, 1),
            Op::Neg(6),
            Op::Add(0, 1),
            Op::Neg(8),
        ];
        let mut binary = Vec::new();
        for a in [0u32, 2, 4, 5, 7] {
            for b in [1u32, 3, 4, 9] {
                binary.push(Op::Add(a, b));
                binary.push(Op::Add(b, a));
                binary.push(Op::Mul(a, b));
                binary.push(Op::Mul(b, a));
            }
        }
        let mut unary = Vec::new();
        for a in [2u32, 3, 5, 7, 9] {
            unary.extend([
                Op::Neg(a),
                Op::Mul(a, a),
                Op::Recip(a),
                Op::Powi(a, 2),
                Op::Powi(a, 3),
                Op::Powi(a, -3),
                Op::Powi(a, -4),
                Op::Powi(a, 0),
                Op::Func(Func::Abs, a),
                Op::Func(Func::Sign, a),
                Op::Func(Func::Sqrt, a),
                Op::Func(Func::Sin, a),
                Op::Powf(a, 1),
            ]);
        }
        let mut cases = Vec::new();
        for op in binary.into_iter().chain(unary) {
            let mut ops = leaves.clone();
            ops.push(op);
            // Negations of the result too, as an output and under a further operation.
            let n = ops.len() as u32;
            ops.push(Op::Neg(n - 1));
            ops.push(Op::Add(n, 0));
            cases.push(ops);
        }
        for ops in cases {
            let n = ops.len() as u32;
            let outputs = (0..n).map(|s| out("y", s)).collect();
            let t = Tape::new(ops, outputs, 0).unwrap();
            let f = JitFunction::compile(&t).unwrap();
            for &a in &xs {
                for &b in &xs {
                    let x = [0.0, 0.0, 0.0, a, b, 0.0, 0.0];
                    let mut got = vec![0.0; n as usize];
                    f.eval(&x, &mut got).unwrap();
                    let mut want = vec![0.0; n as usize];
                    let at = routh_tape::Inputs {
                        omega: [0.0; 3],
                        gamma: [a, b, 0.0],
                        p_psi: 0.0,
                    };
                    t.eval(&at, &[], &mut Vec::new(), &mut want);
                    for (k, (g, w)) in got.iter().zip(&want).enumerate() {
                        assert!(
                            g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan()),
                            "{:?} at γ = ({a}, {b}), slot {k}: jit {g} tape {w}",
                            t.ops()
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn a_tape_with_no_ops_or_outputs_compiles() {
        let t = Tape::new(vec![], vec![], 0).unwrap();
        let f = JitFunction::compile(&t).unwrap();
        f.eval(&[0.0; 7], &mut []).unwrap();
        assert_eq!(f.instructions(), 0);
    }
}
