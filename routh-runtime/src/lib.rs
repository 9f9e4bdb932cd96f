//! `routh::Model`: the language of `#[derive(Lagrangian)]` read at run time.
//!
//! A model is the body of a derive's `#[lagrangian(...)]` attribute (`kinetic = ...`,
//! `linear = ...`, `potential = ...`, `let` items; every function of the derive) and the values
//! of the parameters it uses, given in Rust ([`Model::new`]) or in a TOML file
//! ([`Model::from_toml`], [`Model::from_file`]; docs/models.md). The text goes through the
//! derive's own parser, checks, lowering and reduction, so the errors are the derive's, with
//! their line and column ([`ModelError`]), and the expressions are the ones the derive would
//! generate code for. They are evaluated as tapes ([`routh_tape::Tape`]) that read the parameter
//! values at run time, each compiled to native code by Cranelift the first time it is used
//! (feature `jit`, the default) or evaluated by a register-based interpreter ([`kernel`], [`Model::evaluation`]); a `Model` implements
//! [`Lagrangian`](routh_core::Lagrangian) and [`Routhian`](routh_core::Routhian), so every
//! analysis of `routh` takes it unchanged.
//!
//! ```
//! use routh_runtime::Model;
//! use routh_core::{classify, steady_motions};
//!
//! let src = r#"
//! [model]
//! lagrangian = """
//!     kinetic = 0.5 * omega.dot(inertia * omega),
//!     potential = mgl * gamma.x,
//! """
//! symmetric = ["inertia"]
//! [parameters]
//! inertia = [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 1.0]]
//! mgl = 1
//! "#;
//! // The Kovalevskaya top.
//! let top = Model::from_toml(src)?;
//! for m in steady_motions(&top, 1.0)? {
//!     let report = classify(&top, &m)?;
//!     println!("{:?}: {:?}", m.gamma, report.verdict);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![forbid(unsafe_code)]

mod compile;
mod derived;
mod error;
mod evaluation;
mod hoist;
pub mod kernel;
mod kernels;
mod model;
mod param;
mod results;
mod toml_file;

#[doc(hidden)]
pub use derived::DerivedLatex;
pub use error::ModelError;
pub use evaluation::Evaluation;
pub use model::Model;
pub use param::Param;
