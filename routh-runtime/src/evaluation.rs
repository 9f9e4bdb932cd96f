//! How a model evaluates its tapes: the answer of `Model::evaluation`, a module below both the
//! model and its kernels.

/// How a [`Model`](crate::Model) evaluates its tapes
/// ([`Model::evaluation`](crate::Model::evaluation)).
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Evaluation {
    /// Compiled to native code by Cranelift (feature `jit`, the default).
    Jit,
    /// By the interpreter ([`crate::kernel::Interpreter`]).
    Interpreter,
    /// By a backend given to [`Model::with_backend`](crate::Model::with_backend).
    Custom,
}
