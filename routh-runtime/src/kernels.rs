//! The kernels of a model's tapes, each built the first time its tape is evaluated and shared by
//! every clone of the model and every copy made by `Model::with` (one `Arc<Kernels>`).
//!
//! Building a model parses, checks and reduces its text and makes its tapes; it compiles none.
//! An analysis pays for the tapes it evaluates, once (a `OnceLock` per tape). The JIT's and the
//! interpreter's kernels read the parameter values from a slice passed with the inputs, so they
//! serve every set of values; a custom [`Backend`] receives the tapes with the values bound,
//! and its kernels are made again for new values.

use crate::compile::{Compiled, TAPES};
use crate::evaluation::Evaluation;
use crate::kernel::{Backend, Interpreter, Kernel, INPUTS};
use std::fmt;
use std::sync::{Arc, OnceLock};

/// How the kernels are made.
#[derive(Clone)]
pub(crate) enum Maker {
    /// By the JIT (Cranelift), `optimize`d or not; by the interpreter if a tape fails to
    /// compile.
    #[cfg(feature = "jit")]
    Jit { optimize: bool },
    /// By the interpreter.
    Interpreter,
    /// By a custom backend, from the tapes with these parameter values bound.
    Custom {
        backend: Backend,
        values: Arc<[f64]>,
    },
}

/// One tape's evaluator: an enum, so that the hot path is a direct call (no `dyn` for the JIT
/// and the interpreter).
enum Runner {
    #[cfg(feature = "jit")]
    Jit(crate::kernel::Jit),
    Interpreter(Interpreter),
    Custom(Arc<dyn Kernel>),
}

impl Runner {
    #[inline]
    fn run(&self, inputs: &[f64; INPUTS], params: &[f64], out: &mut [f64]) {
        match self {
            #[cfg(feature = "jit")]
            Runner::Jit(f) => f.run(inputs, params, out),
            Runner::Interpreter(i) => i.eval_params(inputs, params, out),
            Runner::Custom(k) => k.eval_params(inputs, params, out),
        }
    }
}

/// The kernels of one model's tapes, made on first use.
pub(crate) struct Kernels {
    compiled: Arc<Compiled>,
    maker: Maker,
    evaluation: Evaluation,
    cells: [OnceLock<Runner>; TAPES],
}

impl fmt::Debug for Kernels {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let made = self.cells.iter().filter(|c| c.get().is_some()).count();
        f.debug_struct("Kernels")
            .field("evaluation", &self.evaluation)
            .field("made", &made)
            .finish_non_exhaustive()
    }
}

impl Kernels {
    /// The kernels of `compiled`'s tapes, none made yet. The JIT is used where the feature
    /// `jit` is on and Cranelift supports the host, else the interpreter.
    pub(crate) fn new(compiled: Arc<Compiled>, maker: Maker) -> Kernels {
        let (maker, evaluation) = match maker {
            #[cfg(feature = "jit")]
            Maker::Jit { .. } if !routh_jit::is_supported() => {
                (Maker::Interpreter, Evaluation::Interpreter)
            }
            #[cfg(feature = "jit")]
            m @ Maker::Jit { .. } => (m, Evaluation::Jit),
            m @ Maker::Interpreter => (m, Evaluation::Interpreter),
            m @ Maker::Custom { .. } => (m, Evaluation::Custom),
        };
        Kernels {
            compiled,
            maker,
            evaluation,
            cells: std::array::from_fn(|_| OnceLock::new()),
        }
    }

    /// How the tapes are evaluated.
    pub(crate) fn evaluation(&self) -> Evaluation {
        self.evaluation
    }

    /// The maker, for a model whose parameter values change (a custom backend's kernels are
    /// made again from the new values).
    pub(crate) fn maker(&self) -> &Maker {
        &self.maker
    }

    /// The number of kernels made so far.
    pub(crate) fn made(&self) -> usize {
        self.cells.iter().filter(|c| c.get().is_some()).count()
    }

    /// Evaluates tape `which` (an index of [`crate::compile::index`]) at `inputs` with the
    /// parameter values `params` (the tape's hoisted values, [`crate::hoist::Split::main_params`];
    /// ignored by a custom backend, whose tapes are bound), making its kernel first if it is
    /// the first evaluation.
    #[inline]
    pub(crate) fn eval(
        &self,
        which: usize,
        inputs: &[f64; INPUTS],
        params: &[f64],
        out: &mut [f64],
    ) {
        if let Some(cell) = self.cells.get(which) {
            cell.get_or_init(|| self.make(which))
                .run(inputs, params, out);
        }
    }

    #[cold]
    fn make(&self, which: usize) -> Runner {
        // `which` indexes `cells`, which has one cell per tape: never the empty tape.
        static EMPTY: routh_tape::Tape = routh_tape::Tape::from_static(&[], &[], 0);
        let fields = self.compiled.tapes.fields();
        let unbound = fields.get(which).copied().unwrap_or(&EMPTY);
        // The JIT and the interpreter evaluate the tape without its parameter-only part
        // (computed once per set of values: `Model::hoisted`).
        let tape = self.compiled.split.get(which).map_or(&EMPTY, |s| &s.main);
        match &self.maker {
            #[cfg(feature = "jit")]
            Maker::Jit { optimize } => {
                let level = if *optimize {
                    routh_jit::OptLevel::Speed
                } else {
                    routh_jit::OptLevel::None
                };
                match routh_jit::JitFunction::compile_all_with(&[tape], level) {
                    Ok(mut f) if f.len() == 1 => match f.pop() {
                        Some(f) => Runner::Jit(crate::kernel::Jit(f)),
                        None => Runner::Interpreter(Interpreter::new(tape)),
                    },
                    _ => Runner::Interpreter(Interpreter::new(tape)),
                }
            }
            Maker::Interpreter => Runner::Interpreter(Interpreter::new(tape)),
            Maker::Custom { backend, values } => match unbound.bind(values) {
                Ok(bound) => Runner::Custom(backend(&bound)),
                // Cannot happen (the values are the tapes' own): the tape interpreted.
                Err(_) => Runner::Interpreter(Interpreter::new(unbound)),
            },
        }
    }
}
