//! Periodic motions: relative periodic orbits of the full equations (8), their Floquet
//! stability, their families through the energy, and Poincaré sections (docs/method.md §11).
//!
//! The body-frame equations (8) in `x = (ω, γ)` are the body's motion reduced by the rotation
//! about the vertical: `p_ψ` (9) and `|γ|²` are their Casimirs, and on a level of `p_ψ` they are
//! a Hamiltonian system of two degrees of freedom (the reduced system (13)). A periodic orbit of
//! (8), `x(T) = x(0)`, is a relative periodic orbit of the body: after one period its attitude
//! returns up to a turn `Δψ` about the vertical ([`PeriodicOrbit::precession`]).
//!
//! - **Monodromy.** `Φ(T)`, the derivative of the flow of (8) over one period, integrated with the
//!   orbit from the variational equations `Φ' = DF(x)Φ`, `DF` from
//!   [`Lagrangian::full_jacobian`](crate::Lagrangian::full_jacobian) (the derive's and the
//!   run-time models' exact derivatives). Its eigenvalues are `1, 1, 1, 1` (the flow, the
//!   energy, the two Casimirs) and a pair `μ, 1/μ`, so `tr Φ = 4 + μ + 1/μ` and the stability
//!   index is `k = (tr Φ − 4)/2`: `|k| < 1` elliptic, `k > 1` hyperbolic, `k < −1` inverse
//!   hyperbolic, `k = ±1` parabolic (within [`OrbitOptions::parabolic_tol`]).
//! - **Corrector.** Shooting: `(x₀, T)` (and `E` along a family) solve `φ_T(x₀) = x₀`, a phase
//!   condition `F(x_ref)·(x₀ − x_ref) = 0`, `E(x₀) = E`, `p_ψ(x₀) = p_ψ`, `|γ₀|² = 1` and one
//!   linear row (the energy, or the pseudo-arclength row of the continuation), an overdetermined
//!   but consistent system solved by minimum-norm Gauss–Newton steps (SVD).
//! - **Families** ([`lyapunov_family`], [`continue_orbit`]): pseudo-arclength in `(x₀, T, E)` on
//!   the crate's one predictor–corrector, events located on the crate's one event locator; and
//!   at a fixed energy through a parameter of the model ([`continue_orbit_in`]), on the same
//!   corrector, predictor–corrector and locator with the parameter in place of the energy.
//! - **Sections** ([`poincare_section`]): many orbits at one `(p_ψ, E)` crossing a plane through
//!   the vertical's body coordinates, in parallel (rayon).
//!
//! Families of steady motions, through `p_ψ` or a parameter, are in [`crate::families`]; both
//! kinds of family are followed by the same engines (docs/architecture.md, "Engines").

mod branch;
mod chart;
mod doubling;
mod events;
mod family;
mod flow;
mod node;
mod nonlinear;
mod parameter;
mod section;
mod shoot;
mod symmetry;

use std::fmt;

use nalgebra::{Complex, Vector3};

pub use branch::switch_branch;
pub use chart::{orbit_chart, OrbitChart, OrbitChartCurve, OrbitChartOptions};
pub use doubling::period_doubled_family;
pub use family::{continue_orbit, lyapunov_family};
pub use flow::orbit_path;
pub use nonlinear::{
    orbit_nonlinear_stability, OrbitNonlinearOptions, OrbitNonlinearReport, OrbitNonlinearVerdict,
    OrbitResonance,
};
/// The section and chart of the nonlinear test, chosen (for the tests of its invariance).
#[doc(hidden)]
pub use nonlinear::{orbit_nonlinear_stability_in, orbit_symplectic_form, SectionChart};
pub use parameter::{continue_orbit_in, OrbitParameterFamily};
pub use section::{
    orbit_crossings, poincare_section, PoincareSection, SectionOptions, SectionOrbit,
};
pub use shoot::periodic_orbit;
pub use symmetry::axial_symmetry;

use crate::RouthError;

/// The smallest relative tolerance of the integration and the corrector (100 roundoffs).
const MIN_TOL: f64 = 100.0 * f64::EPSILON;

/// Settings of the periodic-orbit analyses ([`periodic_orbit`], [`lyapunov_family`],
/// [`continue_orbit`]). `Default` gives tolerances for about 9 correct digits of the period and
/// the multipliers.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitOptions {
    /// Relative tolerance of the integration of the orbit and its variational equations.
    pub rtol: f64,
    /// Absolute tolerance of the same.
    pub atol: f64,
    /// The corrector has converged when the residual of `φ_T(x₀) = x₀` and of the other rows is
    /// at most this (relative to `max(1, |x₀|)`).
    pub newton_tol: f64,
    /// Largest number of Gauss–Newton steps of one correction.
    pub max_iter: usize,
    /// `|k ∓ 1|` at most this is `Parabolic`.
    pub parabolic_tol: f64,
    /// The energies a family stays within (both ends included); `None`: no bound.
    pub energy_bounds: Option<(f64, f64)>,
    /// Largest number of orbits of a family (a budget: the family then ends with
    /// [`OrbitStop::MaxOrbits`], never an error).
    pub max_orbits: usize,
    /// A family ends ([`OrbitStop::PeriodBound`]) once the period exceeds this many times the
    /// period of its first orbit (a family approaching a homoclinic orbit has periods growing
    /// without bound).
    pub max_period_ratio: f64,
    /// First step of the continuation (pseudo-arclength in `(x₀, T/T₀, E)`; at most
    /// `max_step`, whichever is set).
    pub initial_step: f64,
    /// Largest step.
    pub max_step: f64,
    /// Smallest step: below it the family ends ([`OrbitStop::Stalled`]).
    pub min_step: f64,
    /// The distance `|x₀ − x_s|` of the first orbit of a Lyapunov family from its steady motion.
    pub initial_amplitude: f64,
    /// A Lyapunov family does not start from a mode `k` whose other frequency is within this of
    /// an integer multiple of `ω_k` (`|ω_j/ω_k − n| ≤ resonance_tol`, n ≥ 1): a resonant start.
    pub resonance_tol: f64,
    /// Events are located to `|ΔE| ≤ event_tol·max(1, |E|)`.
    pub event_tol: f64,
    /// Budget of integration steps per period.
    pub max_steps: usize,
    /// Along families, also locate where the twist of the Poincaré map vanishes and where it
    /// meets the resonances of order three (`k = −1/2`) and four (`k = 0`)
    /// ([`OrbitEventKind::TwistDegenerate`] …; [`orbit_nonlinear_stability`]). Default `false`.
    #[cfg_attr(feature = "serde", serde(default))]
    pub nonlinear: bool,
    /// Cancellation and progress (not a setting: not serialised, not compared).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub control: crate::RunControl,
}

impl Default for OrbitOptions {
    fn default() -> Self {
        OrbitOptions {
            rtol: 1e-11,
            atol: 1e-12,
            newton_tol: 1e-9,
            max_iter: 12,
            parabolic_tol: 1e-6,
            energy_bounds: None,
            max_orbits: 100,
            max_period_ratio: 20.0,
            initial_step: 0.02,
            max_step: 0.1,
            min_step: 1e-7,
            initial_amplitude: 1e-3,
            resonance_tol: 1e-3,
            event_tol: 1e-9,
            max_steps: 100_000,
            nonlinear: false,
            control: crate::RunControl::default(),
        }
    }
}

impl OrbitOptions {
    /// With the family kept within `lo ≤ E ≤ hi`.
    pub fn with_energy_bounds(mut self, lo: f64, hi: f64) -> Self {
        self.energy_bounds = Some((lo, hi));
        self
    }

    /// With at most `n` orbits in a family.
    pub fn with_max_orbits(mut self, n: usize) -> Self {
        self.max_orbits = n;
        self
    }

    /// With the largest continuation step `h` (and the first step at most `h`).
    pub fn with_max_step(mut self, h: f64) -> Self {
        self.max_step = h;
        self.initial_step = self.initial_step.min(h);
        self
    }

    /// The first step: `initial_step`, at most `max_step`.
    pub(crate) fn first_step(&self) -> f64 {
        self.initial_step.min(self.max_step)
    }

    pub(crate) fn validate(&self) -> Result<(), RouthError> {
        let positive = [
            ("OrbitOptions::rtol", self.rtol),
            ("OrbitOptions::atol", self.atol),
            ("OrbitOptions::newton_tol", self.newton_tol),
            ("OrbitOptions::parabolic_tol", self.parabolic_tol),
            ("OrbitOptions::max_period_ratio", self.max_period_ratio),
            ("OrbitOptions::initial_step", self.initial_step),
            ("OrbitOptions::max_step", self.max_step),
            ("OrbitOptions::min_step", self.min_step),
            ("OrbitOptions::initial_amplitude", self.initial_amplitude),
            ("OrbitOptions::resonance_tol", self.resonance_tol),
            ("OrbitOptions::event_tol", self.event_tol),
        ];
        for (what, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return Err(RouthError::InvalidOption {
                    what,
                    reason: format!("must be positive and finite, got {v}"),
                });
            }
        }
        if self.rtol >= 1.0 {
            return Err(RouthError::InvalidOption {
                what: "OrbitOptions::rtol",
                reason: format!("must be below 1, got {}", self.rtol),
            });
        }
        // Below a hundred roundoffs no integration or correction can deliver the tolerance: the
        // corrector would end in "no convergence" instead.
        for (what, v) in [
            ("OrbitOptions::rtol", self.rtol),
            ("OrbitOptions::newton_tol", self.newton_tol),
        ] {
            if v < MIN_TOL {
                return Err(RouthError::InvalidOption {
                    what,
                    reason: format!(
                        "{v:e} is below what double precision delivers: at least {MIN_TOL:e}"
                    ),
                });
            }
        }
        if self.min_step > self.max_step {
            return Err(RouthError::InvalidOption {
                what: "OrbitOptions::min_step",
                reason: format!("{} exceeds max_step = {}", self.min_step, self.max_step),
            });
        }
        if let Some((lo, hi)) = self.energy_bounds {
            if !(lo.is_finite() && hi.is_finite() && lo < hi) {
                return Err(RouthError::InvalidOption {
                    what: "OrbitOptions::energy_bounds",
                    reason: format!("need finite lo < hi, got ({lo}, {hi})"),
                });
            }
        }
        if self.max_iter == 0 || self.max_orbits == 0 || self.max_steps == 0 {
            return Err(RouthError::InvalidOption {
                what: "OrbitOptions::max_iter/max_orbits/max_steps",
                reason: "must be at least 1".into(),
            });
        }
        Ok(())
    }
}

/// The linear stability of a periodic orbit from its stability index `k = (μ + 1/μ)/2`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OrbitStability {
    /// `|k| < 1`: `μ, 1/μ` on the unit circle, linearly stable.
    Elliptic,
    /// `k = ±1` within the tolerance: a double multiplier `±1` (a fold, a branch point or a
    /// period doubling of the family).
    Parabolic,
    /// `k > 1`: real positive multipliers `μ > 1 > 1/μ`, unstable.
    Hyperbolic,
    /// `k < −1`: real negative multipliers, unstable (after a period doubling).
    InverseHyperbolic,
}

impl OrbitStability {
    /// The stability of an orbit with index `k`, `Parabolic` within `tol` of ±1.
    pub fn from_index(k: f64, tol: f64) -> Self {
        if (k - 1.0).abs() <= tol || (k + 1.0).abs() <= tol {
            OrbitStability::Parabolic
        } else if k > 1.0 {
            OrbitStability::Hyperbolic
        } else if k < -1.0 {
            OrbitStability::InverseHyperbolic
        } else {
            OrbitStability::Elliptic
        }
    }

    /// The lower-case name (`"elliptic"`, `"parabolic"`, `"hyperbolic"`, `"inverse_hyperbolic"`).
    pub fn as_str(&self) -> &'static str {
        match self {
            OrbitStability::Elliptic => "elliptic",
            OrbitStability::Parabolic => "parabolic",
            OrbitStability::Hyperbolic => "hyperbolic",
            OrbitStability::InverseHyperbolic => "inverse_hyperbolic",
        }
    }
}

impl fmt::Display for OrbitStability {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A periodic orbit of the full equations (8): a relative periodic orbit of the body.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PeriodicOrbit {
    /// `ω` at a point of the orbit.
    pub omega0: Vector3<f64>,
    /// `γ` at the same point, `|γ₀| = 1`.
    pub gamma0: Vector3<f64>,
    /// The period `T > 0`.
    pub period: f64,
    /// The energy (3).
    pub energy: f64,
    /// The cyclic momentum (9).
    pub p_psi: f64,
    /// `Δψ ∈ (−π, π]`: `R(T) = Rot(e_z, Δψ)·R(0)·Rot(e₃, Δφ)` (`R` body → space), the turn
    /// about the upward vertical after one period.
    pub precession: f64,
    /// `Δφ ∈ (−π, π]`, the turn about the body axis `e₃` in the same identity: on an axially
    /// symmetric body ([`axial_symmetry`]) the orbit is periodic modulo it,
    /// `x(T) = (Rot(e₃, −Δφ)ω₀, Rot(e₃, −Δφ)γ₀)`; exactly 0 on any other body (docs/method.md
    /// §11a).
    #[cfg_attr(feature = "serde", serde(default))]
    pub body_turn: f64,
    /// `μ, 1/μ`: `|μ₀| ≥ 1`, and `Im μ₀ ≥ 0` on the unit circle.
    pub multipliers: [Complex<f64>; 2],
    /// `k = (μ + 1/μ)/2 = (tr Φ(T) − 4)/2`.
    pub stability_index: f64,
    /// The verdict from `k`.
    pub stability: OrbitStability,
    /// The orbit is not isolated on its energy level: a relative periodic orbit of an axially
    /// symmetric body that is not a relative equilibrium of the two turns (a nutation, a planar
    /// swing). The reduced system is then integrable (the momentum about `e₃` is a further
    /// integral), the monodromy modulo the body turn has every multiplier 1, and the orbit is
    /// reported with `k = 1`, `μ = 1/μ = 1` and `Parabolic` by that theorem (docs/method.md §11a);
    /// families of such orbits report no branch points or period doublings (`k` never crosses ±1).
    #[cfg_attr(feature = "serde", serde(default))]
    pub degenerate: bool,
    /// Half the largest distance between points of the orbit in `(ω, γ)` (0 at a steady motion).
    pub amplitude: f64,
}

impl PeriodicOrbit {
    /// The multipliers `μ, 1/μ` from the stability index `k` (see [`PeriodicOrbit::multipliers`]).
    pub fn multipliers_from_index(k: f64) -> [Complex<f64>; 2] {
        if k.abs() <= 1.0 {
            let s = (1.0 - k * k).max(0.0).sqrt();
            [Complex::new(k, s), Complex::new(k, -s)]
        } else {
            let s = (k * k - 1.0).sqrt();
            let mu = if k > 0.0 { k + s } else { k - s };
            [Complex::new(mu, 0.0), Complex::new(1.0 / mu, 0.0)]
        }
    }
}

impl fmt::Display for PeriodicOrbit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "periodic orbit: T = {:.10}, E = {:.10}, p_ψ = {}, Δψ = {:.6}, Δφ = {:.6}, k = {:.8} ({}{}), ω₀ = ({:.6}, {:.6}, {:.6}), γ₀ = ({:.6}, {:.6}, {:.6})",
            self.period,
            self.energy,
            self.p_psi,
            self.precession,
            self.body_turn,
            self.stability_index,
            self.stability,
            if self.degenerate { ", degenerate" } else { "" },
            self.omega0.x,
            self.omega0.y,
            self.omega0.z,
            self.gamma0.x,
            self.gamma0.y,
            self.gamma0.z
        )
    }
}

/// What happens along a family of periodic orbits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OrbitEventKind {
    /// The energy turns back along the family (`dE/ds = 0`); `k = 1` there.
    Fold,
    /// `k = 1` without a fold: another family of orbits of the same period crosses.
    BranchPoint,
    /// `k = −1`: a family of orbits of twice the period is born.
    PeriodDoubling,
    /// The twist of the Poincaré map vanishes (`τ = 0`, a true zero of `τ` along the family;
    /// located with [`OrbitOptions::nonlinear`]): Moser's theorem does not apply there.
    TwistDegenerate,
    /// `k = −1/2`: the resonance of order three (with [`OrbitOptions::nonlinear`]).
    ThirdOrderResonance,
    /// `k = 0`: the resonance of order four (with [`OrbitOptions::nonlinear`]).
    FourthOrderResonance,
}

impl OrbitEventKind {
    /// The lower-case name (`"fold"`, `"branch_point"`, `"period_doubling"`).
    pub fn as_str(&self) -> &'static str {
        match self {
            OrbitEventKind::Fold => "fold",
            OrbitEventKind::BranchPoint => "branch_point",
            OrbitEventKind::PeriodDoubling => "period_doubling",
            OrbitEventKind::TwistDegenerate => "twist_degenerate",
            OrbitEventKind::ThirdOrderResonance => "third_order_resonance",
            OrbitEventKind::FourthOrderResonance => "fourth_order_resonance",
        }
    }
}

impl fmt::Display for OrbitEventKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// An event of a family, located by solving `k(E) = ±1` (or `dE/ds = 0`).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitEvent {
    /// What happens.
    pub kind: OrbitEventKind,
    /// The energy where it happens.
    pub energy: f64,
    /// The orbit there.
    pub orbit: PeriodicOrbit,
    /// The stability just before (in the family's order).
    pub before: OrbitStability,
    /// The stability just after.
    pub after: OrbitStability,
}

impl fmt::Display for OrbitEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} at E = {:.12} (T = {:.10}): {} -> {}",
            self.kind, self.energy, self.orbit.period, self.before, self.after
        )
    }
}

/// Why a family of periodic orbits ended.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OrbitStop {
    /// It reached an end of [`OrbitOptions::energy_bounds`] (or of `continue_orbit`'s range).
    EnergyBound {
        /// The bound reached.
        energy: f64,
    },
    /// [`OrbitOptions::max_orbits`] orbits were computed.
    MaxOrbits,
    /// The period passed [`OrbitOptions::max_period_ratio`] times the first period.
    PeriodBound {
        /// The last period.
        period: f64,
    },
    /// The family returned to its first orbit: it is closed.
    Closed,
    /// The orbits shrank onto a steady motion (the other end of the family).
    ReachedSteadyMotion {
        /// Where.
        gamma: Vector3<f64>,
        /// Its energy.
        energy: f64,
    },
    /// No step down to [`OrbitOptions::min_step`] could be corrected.
    Stalled {
        /// The energy of the last orbit.
        energy: f64,
    },
    /// A family in a parameter ([`continue_orbit_in`]) reached an end of its parameter range
    /// (its last orbit corrected onto it).
    ParameterBound {
        /// The end reached.
        s: f64,
    },
    /// The caller stopped it ([`OrbitOptions::control`]'s cancel flag: Ctrl-C); the orbits
    /// computed before are kept.
    Interrupted,
}

impl fmt::Display for OrbitStop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OrbitStop::EnergyBound { energy } => write!(f, "reached the energy bound {energy}"),
            OrbitStop::MaxOrbits => f.write_str("the budget of orbits is spent"),
            OrbitStop::PeriodBound { period } => {
                write!(f, "the period grew past its bound (T = {period})")
            }
            OrbitStop::Closed => f.write_str("the family closed on its first orbit"),
            OrbitStop::ReachedSteadyMotion { gamma, energy } => write!(
                f,
                "the orbits shrank onto the steady motion γ = ({:.6}, {:.6}, {:.6}) at E = {energy}",
                gamma.x, gamma.y, gamma.z
            ),
            OrbitStop::Stalled { energy } => {
                write!(f, "the continuation stalled at E = {energy}")
            }
            OrbitStop::ParameterBound { s } => write!(f, "reached the parameter bound s = {s}"),
            OrbitStop::Interrupted => f.write_str("interrupted by the caller"),
        }
    }
}

/// A family of periodic orbits at one `p_ψ`, in the order of continuation.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitFamily {
    /// The orbits, in the order of continuation.
    pub orbits: Vec<PeriodicOrbit>,
    /// Folds, branch points and period doublings, in the same order.
    pub events: Vec<OrbitEvent>,
    /// Why the family ended (`None`: it reached the end it was asked for).
    pub stop: Option<OrbitStop>,
}
