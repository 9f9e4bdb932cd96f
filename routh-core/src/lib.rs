//! Runtime of `routh`: the [`Lagrangian`] and [`Routhian`] traits that generated (or hand-written)
//! models implement, simulation of the full equations (8) and the reduced equations (13) ([`sim`]),
//! steady motions (31)–(34) ([`steady`]), their stability (62)–(64) ([`stability`]) and families
//! of steady motions through parameters ([`families`]).
//!
//! Equation numbers are those of Bourov & Chevallier, ZAMM 78 (1998) 695–702. Where the paper has
//! a misprint the corrected form is implemented and cited as "errata E1"–"errata E8": the
//! corrections, with their derivations and the tests that check them, are in `docs/errata.md` of
//! the repository; the method as a whole is in `docs/method.md`.
//!
//! The crate root re-exports what a first program uses; the modules hold the rest (options,
//! lower-level functions such as the vector fields).
#![forbid(unsafe_code)]

pub use nalgebra;
pub use nalgebra::{Complex, Matrix3, Vector3};

pub mod certify;
mod circle;
mod classified;
mod control;
mod error;
pub mod export;
pub mod families;
pub mod files;
pub mod fluid;
mod formulas;
mod krein;
mod model;
pub mod nonlinear;
pub mod periodic;
#[cfg(feature = "serde")]
mod serde_support;
pub mod sim;
mod solve;
mod sphere;
pub mod stability;
pub mod steady;
#[doc(hidden)]
pub mod validate;

pub use certify::{steady_motions_certified, Certificate, CertifyOptions};
pub use circle::{classify_circle, classify_circle_with, CircleReport, CircleStability};
pub use classified::{classified_steady_motions, classify_at, stability_threshold, Classified};
pub use control::{Progress, RunControl};
pub use error::RouthError;
#[allow(deprecated)]
pub use families::BranchPoint;
pub use families::{
    bifurcation_diagram, continue_branch, stability_atlas, stability_atlas_parallel, AtlasOptions,
    BifurcationDiagram, BoundaryCurve, Branch, BranchEvent, BranchSample, ContinuationOptions,
    EventKind, NonlinearCurve, NonlinearEventVerdicts, StabilityAtlas, StopReason,
};
pub use formulas::{LatexFormulas, SympyFormulas};
pub use model::{DerivedFormulas, GyroscopicSystem, Lagrangian, RouthBundle, Routhian};
/// What the generated code fills in for the integrators (the equations (8) and (13) with their
/// structure); users do not name them.
#[doc(hidden)]
pub use model::{FullEquations, FullJacobian, RankOneInertia, ReducedEquations};
/// [`nonlinear_stability`] with a jet of the Routh function given by the caller (a hand-written
/// model without a tape); users call [`nonlinear_stability`].
#[doc(hidden)]
pub use nonlinear::nonlinear_stability_from_jet;
pub use nonlinear::{
    nonlinear_stability, NonlinearOptions, NonlinearReport, NonlinearVerdict, Resonance,
};
pub use periodic::{
    axial_symmetry, continue_orbit, continue_orbit_in, lyapunov_family, orbit_chart,
    orbit_crossings, orbit_nonlinear_stability, orbit_path, period_doubled_family, periodic_orbit,
    poincare_section, switch_branch, OrbitChart, OrbitChartCurve, OrbitChartOptions, OrbitEvent,
    OrbitEventKind, OrbitFamily, OrbitNonlinearOptions, OrbitNonlinearReport,
    OrbitNonlinearVerdict, OrbitOptions, OrbitParameterFamily, OrbitResonance, OrbitStability,
    OrbitStop, PeriodicOrbit, PoincareSection, SectionOptions,
};
pub use sim::{simulate_full, simulate_reduced, Method, ReducedTrajectory, SimOptions, Trajectory};
pub use stability::{classify, classify_with, ClassifyOptions, Stability, StabilityReport};
pub use steady::{
    steady_motion_near, steady_motion_search, steady_motions, SearchOptions, SearchResult,
    SteadyMotion,
};
