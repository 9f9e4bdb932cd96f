//! Runtime of `routh`: the [`Lagrangian`] and [`Routhian`] traits that generated (or hand-written)
//! models implement, simulation of the full equations (8) and the reduced equations (13), steady
//! motions (31)–(34) and their stability (62)–(64).
//!
//! Equation numbers are those of Bourov & Chevallier, ZAMM 78 (1998) 695–702; where the paper has
//! a misprint the corrected form of `shared/design/ERRATA.md` is implemented and cited (E1–E8).
#![forbid(unsafe_code)]

pub use nalgebra;
pub use nalgebra::{Complex, Matrix3, Vector3};

mod error;
mod model;
mod sim;
mod stability;
mod steady;

pub use error::RouthError;
pub use model::{
    cross_matrix, DerivedFormulas, GyroscopicSystem, Lagrangian, RouthBundle, Routhian,
};
pub use sim::{
    full_vector_field, reduced_vector_field, simulate_full, simulate_reduced, Method, Output,
    ReducedTrajectory, SimOptions, SimStats, Trajectory, SIM_UNIT_GAMMA_TOL,
};
pub use stability::{
    classify, f2_coefficients, Stability, StabilityReport, DOUBLE_ROOT_TOL, UNIT_GAMMA_TOL,
};
pub use steady::{
    steady_motion_near, steady_motions, steady_motions_with, SearchOptions, SteadyMotion,
    GRADIENT_TOL, ZERO_EIGENVALUE_TOL,
};
