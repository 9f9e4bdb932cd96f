//! The options of a simulation: the integration [`Method`], which points to record
//! ([`Output`]), and the tolerances and budgets of [`SimOptions`].

/// The integration method.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Method {
    /// Dormand–Prince 8(5,3) with Hairer's step-size control, initial-step heuristic and
    /// 7th-order dense output. Uses [`SimOptions::rtol`], [`SimOptions::atol`],
    /// [`SimOptions::h_max`], [`SimOptions::h_init`] and [`SimOptions::max_steps`].
    Dop853,
    /// The fixed-step Lie-group (Munthe-Kaas) Runge–Kutta method of order 4 on `ℝᵐ × S²`: the
    /// velocities (and ψ) are advanced by classical RK4 stages, γ only by exact rotations
    /// (Rodrigues), so `|γ|² − 1` stays at round-off level. `step` is the largest step; every
    /// interval between two outputs (or `[0, t_end]`) is cut into equal steps no longer than it.
    LieRk4 {
        /// The (largest) step size, finite and positive.
        step: f64,
    },
    /// Taylor's method of adaptive order (docs/method.md §2c; Jorba & Zou 2005, as in heyoka):
    /// the Taylor coefficients in time of the solution of (8) are computed from the model's
    /// flow tape ([`Lagrangian::flow_tape`](crate::Lagrangian::flow_tape)) by the recurrences
    /// of automatic differentiation, the order is `⌈−ln(ε)/2 + 1⌉` for the tolerance `ε`
    /// (13 at the default `rtol = 1e-10`) and the step comes from the last two coefficients.
    /// Uses [`SimOptions::rtol`], [`SimOptions::atol`], [`SimOptions::rate_atol`],
    /// [`SimOptions::h_max`] and [`SimOptions::max_steps`] (a budget of steps: none is ever
    /// rejected); not [`SimOptions::h_init`]. Output times are evaluated on the step's Taylor
    /// polynomial; [`SimStats::rhs_evaluations`](super::SimStats::rhs_evaluations) counts one
    /// expansion (the recurrences to order p) a step. Faster than DOP853 for errors below about
    /// 2e-10 at t = 1000 on a heavy top, slower above (docs/performance.md).
    ///
    /// For models with a flow tape (`#[derive(Lagrangian)]`, `routh::Model`); a hand-written
    /// model gives [`RouthError::InvalidOption`](crate::RouthError::InvalidOption).
    /// [`simulate_reduced`](super::simulate_reduced) integrates the body's motion (8) this way
    /// and reads Ω and ψ from it in the gauge of (13).
    Taylor,
}

/// Which points the trajectory records.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Output {
    /// `t = 0` and the end of every accepted step (the last one is `t_end`).
    Steps,
    /// Exactly these times, which must be finite, non-decreasing and in `[0, t_end]`. With
    /// [`Method::Dop853`] they are filled in by the dense output (3 more evaluations of the
    /// vector field a step); with [`Method::LieRk4`] the steps are cut to land on them.
    Times(Vec<f64>),
}

/// Options of [`simulate_full`](super::simulate_full) and
/// [`simulate_reduced`](super::simulate_reduced).
///
/// Build with struct-update syntax, e.g. `SimOptions { rtol: 1e-12, ..SimOptions::default() }`.
///
/// # Error control and units
///
/// [`Method::Dop853`] accepts a step when the RMS over the state of `eᵢ/skᵢ` is at most 1, where
/// `eᵢ` is the local error estimate. The weights are taken per 3-vector, by Euclidean length, so
/// that rotating the body frame changes nothing:
///
/// - angular velocity ω (full) or Ω (reduced): `sk = rate_atol + rtol·|ω|`;
/// - γ: `sk = atol + rtol·|γ|`;
/// - ψ (reduced): `sk = atol + rtol·|ψ|`.
///
/// `rtol` has no units. γ and ψ have none either, so neither has `atol`. The angular velocity
/// has the units 1/time, and so does `rate_atol`: the same motion in a unit of time s times
/// smaller (ω s times larger, output times s times larger, `t_end` too) takes the same steps
/// and gives the same γ at the same physical times when `rate_atol` is multiplied by s and the
/// rest is kept. Scaling the inertia, the gyroscopic term, the potential and p_ψ by one factor
/// (the same Lagrangian in other units of energy) changes no state variable and needs no change
/// of the options.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SimOptions {
    /// Relative tolerance of [`Method::Dop853`] and [`Method::Taylor`]. Must be finite and at least
    /// `10·ε ≈ 2.2e-15`. Default `1e-10`.
    ///
    /// It bounds the error of each step, not of the run: the error at time t is proportional to
    /// `rtol` but grows with t, to ~1e2 – 1e3 × `rtol` at t = 1000 on a regular orbit and more
    /// near a separatrix (measured in docs/method.md §2b, "What a tolerance delivers").
    pub rtol: f64,
    /// Absolute tolerance of [`Method::Dop853`] and [`Method::Taylor`] for γ and ψ (dimensionless), and for the angular
    /// velocity unless [`rate_atol`](Self::rate_atol) is given. Finite and positive. Default
    /// `1e-12`.
    pub atol: f64,
    /// Absolute tolerance of [`Method::Dop853`] and [`Method::Taylor`] for the angular velocity (ω or Ω), in the units
    /// of the angular velocity (1/time). `None`: [`atol`](Self::atol). Finite and positive if
    /// given. Default `None`.
    pub rate_atol: Option<f64>,
    /// The integrator. Default [`Method::Dop853`].
    pub method: Method,
    /// Largest step of [`Method::Dop853`] and [`Method::Taylor`] (`None`: unbounded). Must be positive if given.
    pub h_max: Option<f64>,
    /// Initial step of [`Method::Dop853`] (`None`: Hairer's heuristic). Positive if given.
    pub h_init: Option<f64>,
    /// Budget of attempted steps (accepted and rejected); at least 1. Default `100_000`.
    pub max_steps: usize,
    /// Which points are recorded. Default [`Output::Steps`].
    pub output: Output,
    /// Also integrate the attitude of the body, the rotation `R` body → space, as a unit
    /// quaternion (`Ṙ = R[ω]×`, module [`attitude`](super::attitude)), recorded in
    /// [`Trajectory::attitude`](super::Trajectory::attitude) /
    /// [`ReducedTrajectory::attitude`](super::ReducedTrajectory::attitude). Default `false` (no
    /// cost when off).
    ///
    /// With [`Method::LieRk4`] the attitude moves by the same exact rotations as γ, so it stays
    /// a unit quaternion and `γ = Rᵀe₃` holds to round-off. With [`Method::Dop853`] the
    /// quaternion is four more components of the state under the same error control; each
    /// recorded attitude is normalised and turned by the (tolerance-sized) smallest rotation
    /// that makes `Rᵀe₃` equal the direction of the integrated γ, so `γ/|γ| = Rᵀe₃` holds to
    /// round-off there too (|γ| itself drifts at the tolerance, see
    /// [`Trajectory::gamma_norm_error`](super::Trajectory::gamma_norm_error)).
    pub attitude: bool,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions {
            rtol: 1e-10,
            atol: 1e-12,
            rate_atol: None,
            method: Method::Dop853,
            h_max: None,
            h_init: None,
            max_steps: 100_000,
            output: Output::Steps,
            attitude: false,
        }
    }
}

impl SimOptions {
    /// The adaptive method with the given tolerances, other options at their defaults.
    pub fn with_tolerances(rtol: f64, atol: f64) -> Self {
        SimOptions {
            rtol,
            atol,
            ..SimOptions::default()
        }
    }

    /// The Lie-group RK4 method with the given step, other options at their defaults.
    pub fn lie_rk4(step: f64) -> Self {
        SimOptions {
            method: Method::LieRk4 { step },
            ..SimOptions::default()
        }
    }

    /// The same options, also integrating the attitude (see [`SimOptions::attitude`]).
    pub fn with_attitude(mut self) -> Self {
        self.attitude = true;
        self
    }

    /// The same options, recording exactly at `times` (see [`Output::Times`]).
    pub fn at_times(mut self, times: Vec<f64>) -> Self {
        self.output = Output::Times(times);
        self
    }
}
