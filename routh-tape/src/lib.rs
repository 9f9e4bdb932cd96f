//! The typed expression tape of `routh`: the one definition of the DSL's elementary functions
//! ([`Func`], [`sign`]), the scalar trait tapes are evaluated with ([`TapeScalar`]), and the
//! tape itself ([`Tape`]): a straight-line program of typed [`Op`]s over `ω`/`Ω`, `γ`, `p_ψ` and
//! the model's parameters, children first, with named outputs.
//!
//! `#[derive(Lagrangian)]` writes its tapes as `static` data ([`Tape::write_rust`]); the runtime
//! model builds them from the same expression graph. Both hand them out with the parameter
//! values bound ([`CertificationTape`], [`RouthianTape`]), to be evaluated with `f64`, intervals
//! (the certified search) or Taylor jets (higher derivatives of the Routh function).
//!
//! ```
//! use routh_tape::{Func, Inputs, Op, Output, Tape};
//! // sin(γ₀)² + Ω₁
//! let tape = Tape::new(
//!     vec![Op::Gamma(0), Op::Func(Func::Sin, 0), Op::Mul(1, 1), Op::Omega(1), Op::Add(2, 3)],
//!     vec![Output { name: "f", slot: 4 }],
//!     0,
//! ).unwrap();
//! let x = Inputs { omega: [0.0, 1.0, 0.0], gamma: [0.5, 0.0, 0.0], p_psi: 0.0 };
//! let mut out = [0.0];
//! tape.eval(&x, &[], &mut Vec::new(), &mut out);
//! assert_eq!(out[0], 0.5f64.sin().powi(2) + 1.0);
//! ```
#![forbid(unsafe_code)]

mod bound;
mod func;
mod rust;
mod scalar;
mod tape;

pub use bound::{
    CertificationTape, FlowTape, FlowTerms, GradHess, RouthianTape, CERTIFICATION_OUTPUTS,
    FLOW_OUTPUTS, ROUTHIAN_OUTPUT,
};
pub use func::{sign, Func};
pub use rust::RustPaths;
pub use scalar::TapeScalar;
pub use tape::{Inputs, Op, Output, Tape, TapeError, INPUTS};
