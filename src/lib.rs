//! # routh
//!
//! Routh reduction for rigid-body dynamics (Bourov & Chevallier, ZAMM 78 (1998) 695–702).
//!
//! Write a body's Lagrangian `L(ω, γ) = ½ ωᵀJ(γ)ω + a(γ)·ω − U(γ)` declaratively on a struct;
//! `#[derive(Lagrangian)]` differentiates it symbolically at build time and emits straight-line
//! code for `L`, its derivatives, the Routh function `R` of (14) with its gradients and Hessians,
//! and the matrices `A`, `G`, `C` of (64). The runtime ([`routh_core`]) simulates the body in full
//! (8) or reduced (13) form, finds its steady motions (33) and classifies their stability
//! (sections 4–5, with the corrections of `docs/errata.md`).
//!
//! ```
//! use routh::{Lagrangian, Matrix3, Vector3};
//!
//! /// A heavy symmetric (Lagrange) top.
//! #[derive(Lagrangian)]
//! #[lagrangian(
//!     kinetic = 0.5 * omega.dot(diag(inertia) * omega),
//!     potential = mgl * gamma.z,
//! )]
//! struct Top { inertia: Vector3<f64>, mgl: f64 }
//!
//! let top = Top { inertia: Vector3::new(2.0, 2.0, 1.0), mgl: 1.0 };
//! let gamma = Vector3::new(0.0, 0.0, 1.0);
//! let omega = Vector3::new(0.0, 0.0, 3.0);
//! // Energy (3): ½·C·r² + m g l
//! assert!((routh::Lagrangian::energy(&top, &omega, &gamma) - 5.5).abs() < 1e-12);
//! let _ = Matrix3::<f64>::identity();
//! ```
//!
//! A search finds steady motions; [`certify::steady_motions_certified`] proves by interval
//! arithmetic that the ones it returns are all of them (or names the regions it could not
//! decide, such as the tube around a circle of steady motions):
//!
//! ```
//! use routh::certify::{steady_motions_certified, CertifyOptions};
//! use routh::{Lagrangian, Vector3};
//!
//! /// A heavy asymmetric top (centre of mass on the third axis).
//! #[derive(Lagrangian)]
//! #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
//! struct Asymmetric { inertia: Vector3<f64>, mgl: f64 }
//!
//! let top = Asymmetric { inertia: Vector3::new(1.0, 2.0, 3.0), mgl: 1.0 };
//! let cert = steady_motions_certified(&top, 0.5, &CertifyOptions::default()).unwrap();
//! assert!(cert.complete);
//! assert_eq!(cert.motions.len(), 2); // the sleeping and the hanging top, and nothing else
//! println!("{cert}");
//! ```
#![forbid(unsafe_code)]

pub use routh_core::*;
pub use routh_macros::Lagrangian;
/// Models read at run time: the derive's language as text or TOML (`routh::Model`,
/// docs/models.md).
pub use routh_runtime::{Evaluation, Model, ModelError, Param};

#[cfg(feature = "serde")]
pub mod options;

/// What most programs use, in one import: `use routh::prelude::*;`.
///
/// The derive and the model traits, the vector types, the analyses of a single model
/// (steady motions, their stability, simulations) and of families (diagrams, atlases), with
/// their options and results.
pub mod prelude {
    pub use crate::{
        bifurcation_diagram, classified_steady_motions, classify, classify_at, classify_circle,
        continue_branch, nonlinear_stability, simulate_full, simulate_reduced, stability_atlas,
        steady_motions, steady_motions_certified, AtlasOptions, BifurcationDiagram,
        CircleStability, Classified, ContinuationOptions, Lagrangian, Matrix3, Model, ModelError,
        NonlinearOptions, NonlinearReport, NonlinearVerdict, Param, RouthError, Routhian,
        SimOptions, Stability, StabilityReport, SteadyMotion, Vector3,
    };
}

/// The README's examples, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
#[cfg(feature = "plot")]
pub mod plot;
pub mod style;

/// Paths used by the code that `#[derive(Lagrangian)]` generates. Not a public API.
#[doc(hidden)]
pub mod __private {
    pub use core::primitive::f64;
    pub use core::primitive::i32;
    pub use routh_core::nalgebra::{Matrix3, Vector3};
    pub use routh_core::{
        DerivedFormulas, FullEquations, FullJacobian, GyroscopicSystem, Lagrangian, RankOneInertia,
        ReducedEquations, RouthBundle, Routhian,
    };
    pub use routh_tape::{CertificationTape, FlowTape, Func, Op, Output, RouthianTape, Tape};

    /// What `Lagrangian::constant_inertia` returns.
    pub type MaybeMatrix3 = core::option::Option<Matrix3<f64>>;
    /// The `rank_one` field of `FullEquations` and `ReducedEquations`.
    pub type MaybeRankOne = core::option::Option<RankOneInertia>;

    /// What `Routhian::certification_tape` returns.
    pub type MaybeTape = core::option::Option<CertificationTape>;
    /// What `Routhian::routh_tape` returns.
    pub type MaybeRouthianTape = core::option::Option<RouthianTape>;
    /// What `Lagrangian::flow_tape` returns.
    pub type MaybeFlowTape = core::option::Option<FlowTape>;

    /// `sign(x)` with `sign(0) = 0`: the derivative of `abs` (the one definition, in
    /// `routh-tape`).
    pub use routh_tape::sign;

    /// What the derive's `DerivedFormulas::latex` returns, and the struct's text it prints
    /// the formulas from on the first call.
    pub use routh_core::LatexFormulas;
    pub use routh_runtime::DerivedLatex;
}
