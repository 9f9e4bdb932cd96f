//! [`continue_orbit_in`]: a family of periodic orbits at a fixed energy through a parameter of
//! the model, the closure `s ↦ (model, p_ψ)` as for the families of steady motions
//! (docs/method.md §11, "Families in a parameter").
//!
//! The same corrector, path follower and event locator as the families through the energy
//! (`shoot.rs`, `family.rs`): the eighth unknown is `s/s_s` in place of `E/e_s`
//! ([`Slot::Parameter`]), the energy row holds `E(x₀; model(s))` at the family's energy and the
//! momentum row `p_ψ(x₀; model(s))` at `p_ψ(s)`; folds (the family turning back in `s`), branch
//! points and period doublings are found and located as there.

use nalgebra::Vector6;

use super::family::{merge_along, Tracer};
use super::flow::split;
use super::shoot::{check_guess, correct, member_at, Problem, Scales, Slot};
use super::{OrbitFamily, OrbitOptions, PeriodicOrbit};
use crate::validate::check_finite;
use crate::{RouthError, Routhian};

/// A family of periodic orbits at one energy through a parameter `s` of the model
/// ([`continue_orbit_in`]): the orbits with their parameter values, the events with theirs.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitParameterFamily {
    /// `s` of each orbit of [`OrbitParameterFamily::family`], in the same order.
    pub parameter: Vec<f64>,
    /// `s` of each event of [`OrbitParameterFamily::family`], in the same order.
    pub event_parameter: Vec<f64>,
    /// The orbits (each at the fixed energy, with `p_ψ(s)`), the folds (where the family turns
    /// back in `s`), branch points and period doublings, and why the family ended (`None`: both
    /// ends of the range reached; else [`OrbitStop`](super::OrbitStop)).
    pub family: OrbitFamily,
}

/// Follows the family of periodic orbits through `orbit` at its energy as the model varies with
/// a parameter: `family(s)` gives the model and `p_ψ` at `s`, as for
/// [`bifurcation_diagram`](crate::bifurcation_diagram), and `orbit` is an orbit of `family(s0)`
/// at its `p_ψ` (docs/method.md §11, "Families in a parameter").
///
/// The family is followed both ways within `range` by pseudo-arclength in `(x₀, T, s)` (through
/// folds, where it turns back in `s`) on the same corrector, predictor–corrector and event
/// locator as [`continue_orbit`](super::continue_orbit), with the parameter in place of the
/// energy: the energy stays that of `orbit`, `p_ψ` follows `family(s).1`, and the column of `s`
/// in the corrector's Jacobian is a central difference in `s` (models from the closure). Folds,
/// branch points (`k = 1` without a fold) and period doublings (`k = −1`) are located as along
/// the energy, their `s` in [`OrbitParameterFamily::event_parameter`]. The orbits come from the
/// lower end of the part traced to the upper end, in the order of continuation; a family ends at
/// an end of `range` (its last orbit corrected onto it, [`OrbitStop::ParameterBound`]), its
/// budget of orbits, a period bound, a return onto a steady motion, a closed loop or a stall, as
/// [`continue_orbit`](super::continue_orbit) does (a stall reports the fixed energy; the
/// last entry of [`OrbitParameterFamily::parameter`] on that side says where).
/// [`OrbitOptions::energy_bounds`] is not used (the energy is fixed).
///
/// Errors ([`RouthError`], never a panic): an empty or non-finite `range`, `s0` outside it,
/// invalid options, an `orbit` that is not one of `family(s0)` at `p_ψ = family(s0).1` (its
/// `p_ψ` or energy there off by more than `1e−6` of their size, or its correction moving it by
/// more than `1e−6` of its size or period: [`RouthError::InvalidOption`]; not closing at all:
/// [`RouthError::NoConvergence`]), and a family whose model at some `s` is invalid (a mass matrix
/// that is not positive definite, a non-finite `p_ψ`): [`RouthError::AtParameter`] at that `s`.
///
/// [`OrbitStop::ParameterBound`]: super::OrbitStop::ParameterBound
///
/// ```
/// use routh_core::{continue_orbit_in, periodic_orbit, Matrix3, OrbitOptions, Vector3};
/// use test_models::HeavyTop;
/// // J = diag(a, 2, 3), centre of mass on e₃ (mgl = 1): the planar swing about e₁ of amplitude
/// // 0.5 rad at its energy E = −cos 0.5, as the moment a about e₁ goes from 1 to 1.2.
/// let body = |a: f64| HeavyTop {
///     j: Matrix3::from_diagonal(&Vector3::new(a, 2.0, 3.0)),
///     mgr: Vector3::z(),
/// };
/// let gamma = Vector3::new(0.0, 0.5f64.sin(), -0.5f64.cos());
/// let opts = OrbitOptions::default();
/// let orbit = periodic_orbit(&body(1.0), Vector3::zeros(), gamma, 6.5, &opts)?;
/// let f = continue_orbit_in(|a| (body(a), 0.0), &orbit, 1.0, (1.0, 1.2), &opts)?;
/// assert_eq!(f.family.stop, None);
/// // A pendulum of length ∝ a: the period grows as √a at a fixed amplitude.
/// let last = f.family.orbits.last().unwrap();
/// assert!((f.parameter.last().unwrap() - 1.2).abs() < 1e-9);
/// assert!((last.period - orbit.period * 1.2f64.sqrt()).abs() < 1e-7);
/// assert!((last.energy - orbit.energy).abs() < 1e-9);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn continue_orbit_in<M: Routhian, F: Fn(f64) -> (M, f64)>(
    family: F,
    orbit: &PeriodicOrbit,
    s0: f64,
    range: (f64, f64),
    opts: &OrbitOptions,
) -> Result<OrbitParameterFamily, RouthError> {
    opts.validate()?;
    let (lo, hi) = range;
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(RouthError::InvalidOption {
            what: "range",
            reason: format!("need finite lo < hi, got ({lo}, {hi})"),
        });
    }
    if !(s0.is_finite() && lo <= s0 && s0 <= hi) {
        return Err(RouthError::InvalidOption {
            what: "s0",
            reason: format!(
                "the orbit's parameter {s0} is outside the range ({lo}, {hi}); a family is \
                 continued from an orbit inside the range"
            ),
        });
    }
    let fam: &dyn Fn(f64) -> (M, f64) = &family;
    let (m0, p0) = member_at(fam, s0)?;
    let x = check_guess(&m0, &orbit.omega0, &orbit.gamma0, orbit.period)?;
    let (w, g) = split(&x);
    let (e0, p) = (m0.energy(&w, &g), m0.cyclic_momentum(&w, &g));
    check_finite("energy and p_psi of the orbit", &[e0, p])?;
    let near = |a: f64, b: f64| (a - b).abs() <= 1e-6 * b.abs().max(1.0);
    if !near(p, p0) || !near(orbit.energy, e0) {
        return Err(RouthError::InvalidOption {
            what: "orbit",
            reason: format!(
                "not an orbit of family(s0) at s0 = {s0} with p_ψ = {p0}: there its p_ψ is {p} \
                 and its energy {e0} (the orbit says E = {})",
                orbit.energy
            ),
        });
    }
    // The scale of s: max(1, |s0|) rounded up to a power of two, so that w₇ = s/s_s and back
    // are exact (an end of the range is reached exactly).
    let scales = Scales {
        t: orbit.period,
        e: 2f64.powi(1f64.max(s0.abs()).log2().ceil().min(1023.0) as i32),
    };
    let slot = Slot::Parameter {
        family: fam,
        energy: e0,
    };
    let prob = Problem::at(&m0, &x, p0, scales)?;
    let row = scales.energy_row(s0);
    let w0 = scales.pack_turned(&x, orbit.period, s0, orbit.body_turn);
    let s = match correct(slot, &prob, &row, &w0, opts)? {
        Ok(s) => s,
        Err(best) => {
            return Err(RouthError::NoConvergence {
                what: "the starting orbit (not a periodic orbit of family(s0))",
                iterations: opts.max_iter,
                residual: best,
            })
        }
    };
    let moved = (Vector6::from(s.w.fixed_rows::<6>(0)) - x).norm();
    let t = scales.period(&s.w);
    if moved > 1e-6 * 1f64.max(x.norm()) || (t - orbit.period).abs() > 1e-6 * orbit.period {
        return Err(RouthError::InvalidOption {
            what: "orbit",
            reason: format!(
                "not an orbit of family(s0) at s0 = {s0}: corrected there it moves by {moved:.3e} \
                 and its period from {} to {t}",
                orbit.period
            ),
        });
    }
    let tracer = Tracer {
        slot,
        opts,
        p_psi: p0,
        scales,
        bounds: Some(range),
        first_period: orbit.period,
    };
    let (up, traced_up, traced_down) = tracer.both_ways(s)?;
    let centre = (up.orbit.clone(), tracer.value(&up));
    let (family, parameter, event_parameter) =
        merge_along(centre, traced_up, traced_down, &|n| tracer.value(n));
    Ok(OrbitParameterFamily {
        parameter,
        event_parameter,
        family,
    })
}
