//! The checks of a simulation's inputs and records: `t_end` and the options, γ₀, an initial state
//! too large for the vector field, a recorded quantity that overflowed.

use nalgebra::Vector3;

use super::{Method, Output, SimOptions};
use crate::validate::{check_finite, unit_gamma};
use crate::RouthError;

pub(super) fn check_unit_gamma(gamma: &Vector3<f64>) -> Result<(), RouthError> {
    unit_gamma("gamma0", gamma).map(|_| ())
}

pub(super) fn invalid(what: &'static str, reason: impl Into<String>) -> RouthError {
    RouthError::InvalidOption {
        what,
        reason: reason.into(),
    }
}

/// The model's flow tape, which [`Method::Taylor`](super::Method::Taylor) integrates; an error
/// naming the method for a model without one.
pub(super) fn flow_tape<M: crate::Lagrangian + ?Sized>(
    model: &M,
) -> Result<routh_tape::FlowTape, RouthError> {
    model.flow_tape().ok_or_else(|| {
        invalid(
            "method",
            "Method::Taylor needs the model's flow tape (a #[derive(Lagrangian)] model or \
             routh::Model); this model has none: use Method::Dop853",
        )
    })
}

/// Checks `t_end` and every option.
pub(super) fn validate(opts: &SimOptions, t_end: f64) -> Result<(), RouthError> {
    check_finite("t_end", &[t_end])?;
    if t_end < 0.0 {
        return Err(invalid("t_end", format!("must be ≥ 0 (got {t_end})")));
    }
    check_finite("rtol", &[opts.rtol])?;
    check_finite("atol", &[opts.atol])?;
    if opts.rtol < 10.0 * f64::EPSILON {
        return Err(invalid(
            "rtol",
            format!("must be ≥ 10ε ≈ 2.2e-15 (got {:e})", opts.rtol),
        ));
    }
    if opts.atol <= 0.0 {
        return Err(invalid(
            "atol",
            format!("must be > 0 (got {:e})", opts.atol),
        ));
    }
    if let Some(a) = opts.rate_atol {
        check_finite("rate_atol", &[a])?;
        if a <= 0.0 {
            return Err(invalid("rate_atol", format!("must be > 0 (got {a:e})")));
        }
    }
    if let Method::LieRk4 { step } = opts.method {
        check_finite("step", &[step])?;
        if step <= 0.0 {
            return Err(invalid("step", format!("must be > 0 (got {step:e})")));
        }
    }
    if let Some(h) = opts.h_max {
        if h.is_nan() {
            return Err(RouthError::NonFinite {
                what: "h_max",
                value: h,
            });
        }
        if h <= 0.0 {
            return Err(invalid("h_max", format!("must be > 0 (got {h:e})")));
        }
    }
    if let Some(h) = opts.h_init {
        check_finite("h_init", &[h])?;
        if h <= 0.0 {
            return Err(invalid("h_init", format!("must be > 0 (got {h:e})")));
        }
    }
    if opts.max_steps == 0 {
        return Err(invalid("max_steps", "must be ≥ 1"));
    }
    if let Output::Times(ts) = &opts.output {
        check_finite("output time", ts)?;
        if let Some(&t) = ts.iter().find(|&&t| !(0.0..=t_end).contains(&t)) {
            return Err(invalid(
                "output",
                format!("time {t} outside [0, t_end = {t_end}]"),
            ));
        }
        if ts.windows(2).any(|w| w[1] < w[0]) {
            return Err(invalid("output", "times must be non-decreasing"));
        }
    }
    Ok(())
}

pub(super) fn all_finite(v: &Vector3<f64>) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// A finite input so large that the vector field overflows at the initial state.
pub(super) fn too_large(what: &'static str, size: f64, equations: &str) -> RouthError {
    invalid(
        what,
        format!(
            "|{what}| = {size:e} is too large for this model: the vector field of {equations} \
             overflows f64 at the initial state"
        ),
    )
}

/// `Err(NonFiniteState)` at the first recorded time where one of `columns` is not finite: the
/// integrators check the state, not the quantities recorded from it (energy, ψ̇, …), which can
/// overflow for a finite state (e.g. ω ≈ 1e200 after a fixed-step run went unstable). Found by
/// tests/runtime_properties.rs.
pub(super) fn non_finite_record(t: &[f64], columns: &[&[f64]]) -> Result<(), RouthError> {
    let bad = (0..t.len()).find(|&i| columns.iter().any(|c| !c[i].is_finite()));
    match bad {
        Some(i) => Err(RouthError::NonFiniteState { t: t[i] }),
        None => Ok(()),
    }
}
