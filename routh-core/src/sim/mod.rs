//! Simulation of the full equations (8) and of the reduced equations (13) (docs/method.md §2–3).
//!
//! - [`simulate_full`] integrates (8) for `(ω, γ)` and records the energy (3), the cyclic
//!   momentum (9) and `|γ|²` along the way.
//! - [`simulate_reduced`] integrates (13) for `(Ω, γ)` in the gauge of errata E4, reconstructs
//!   the rotation angle ψ of the rotating frame by (15), and records E' (16), `(∂R/∂Ω, γ)` (17)
//!   and `|γ|²`.
//!
//! Three integrators are offered ([`Method`]): DOP853, an adaptive Runge–Kutta method of order 8
//! with error control and a dense output of order 7 (the default), and RKMK4, a fixed-step
//! Lie-group Runge–Kutta method of order 4 that moves γ by exact rotations and so keeps
//! `|γ| = 1` to round-off over arbitrarily long runs. A third, Taylor's method of adaptive order
//! (module `taylor`), integrates (8) for models with a flow tape (and (13) through (8)). (The crate `ode_solvers` was considered:
//! it depends on another major version of nalgebra and has no fallible right-hand side, so a
//! compact DOP853 is implemented here instead, following Hairer's `dop853.f`.)
//!
//! Layout: `options` holds the options, `results` the trajectory types, `checks` the checks of
//! the inputs, `full` and `reduced` the two drivers; `drive` the integration loop over both
//! methods, `field` the vector fields, `dop853` (with `tableau`) and `lie` the two steppers.

pub mod attitude;
mod checks;
pub(crate) mod dop853;
mod drive;
mod field;
mod full;
mod lie;
mod options;
mod reduced;
mod results;
mod tableau;
mod taylor;

pub use field::{full_vector_field, reduced_vector_field};
pub use full::simulate_full;
pub use options::{Method, Output, SimOptions};
pub use reduced::simulate_reduced;
pub use results::{ReducedTrajectory, SimStats, Trajectory};

#[cfg(test)]
mod tests;
