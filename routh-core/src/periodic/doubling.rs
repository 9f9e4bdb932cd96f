//! [`period_doubled_family`]: the family of orbits of twice the period born at a period doubling
//! of a family (docs/method.md §11), started along the monodromy's eigenvector for −1 and then
//! followed as any family (`family.rs`).

use nalgebra::{SMatrix, Vector6};

use super::family::{restart, smallest, Tracer};
use super::shoot::{correct, Problem, Scales, Slot, W};
use super::{OrbitEvent, OrbitEventKind, OrbitFamily, OrbitOptions};
use crate::solve::path::row::LinearRow;
use crate::{RouthError, Routhian};

/// The family of orbits of twice the period born at a [`OrbitEventKind::PeriodDoubling`] event,
/// followed away from it (docs/method.md §11): the branch leaves the doubly traversed orbit along
/// the eigenvector of the monodromy for the multiplier −1, which the first step's pseudo-arclength
/// row follows (so that the corrector cannot fall back onto the orbit traversed twice).
///
/// Errors: an event that is not a period doubling, and a first orbit that cannot be corrected.
pub fn period_doubled_family<M: Routhian>(
    model: &M,
    event: &OrbitEvent,
    opts: &OrbitOptions,
) -> Result<OrbitFamily, RouthError> {
    opts.validate()?;
    if event.kind != OrbitEventKind::PeriodDoubling {
        return Err(RouthError::InvalidOption {
            what: "event",
            reason: format!("a period doubling is needed, got a {}", event.kind),
        });
    }
    let (s, scales) = restart(model, &event.orbit, opts)?;
    // The event's orbit must be at k = −1 (an event edited, or taken from another model, is
    // not a period doubling: the null vector below would be a guess).
    let k = 0.5 * (s.shot.trace - 4.0);
    if (k + 1.0).abs() > 1e-6 {
        return Err(RouthError::InvalidOption {
            what: "event",
            reason: format!(
                "its orbit has the stability index k = {k:.9}, not −1: not a period doubling of \
                 this model"
            ),
        });
    }
    // The eigenvector of Φ(T) for −1: the null vector of Φ + I restricted by the constraints
    // (the rows of E, p_ψ and |γ|² keep it on the level set).
    let mut m = SMatrix::<f64, 9, 6>::zeros();
    let phi = s.shot.monodromy;
    for i in 0..6 {
        for k in 0..6 {
            m[(i, k)] = phi[(i, k)] + if i == k { 1.0 } else { 0.0 };
        }
    }
    for k in 0..6 {
        m[(6, k)] = s.jac[(7, k)];
        m[(7, k)] = s.jac[(8, k)];
        m[(8, k)] = s.jac[(9, k)];
    }
    let svd = m.svd(false, true);
    let v_t = svd.v_t.expect("asked for V");
    let imin = smallest(svd.singular_values.as_slice());
    let v: Vector6<f64> = v_t.row(imin).transpose();
    let doubled = Scales {
        t: 2.0 * event.orbit.period,
        e: scales.e,
    };
    let x: Vector6<f64> = s.w.fixed_rows::<6>(0).into();
    let e = event.orbit.energy;
    let w_pd = doubled.pack(&x, 2.0 * event.orbit.period, e);
    let mut n = W::zeros();
    n.fixed_rows_mut::<6>(0).copy_from(&(v / v.norm()));
    let tracer = Tracer {
        slot: Slot::Energy(model),
        opts,
        p_psi: event.orbit.p_psi,
        scales: doubled,
        bounds: opts.energy_bounds,
        first_period: doubled.t,
    };
    let prob = Problem::at(model, &x, event.orbit.p_psi, doubled)?;
    let mut h = opts.first_step().max(10.0 * opts.initial_amplitude);
    let mut first = None;
    while h >= opts.min_step {
        let pred = w_pd + n * h;
        let row = LinearRow::through(n, &pred);
        if let Ok(sol) = correct(Slot::Energy(model), &prob, &row, &pred, opts)? {
            first = Some(sol);
            break;
        }
        h *= 0.5;
    }
    let Some(first) = first else {
        return Err(RouthError::NoConvergence {
            what: "the first orbit of the period-doubled family",
            iterations: opts.max_iter,
            residual: f64::NAN,
        });
    };
    let mut start = tracer.node(first, None)?;
    let away: Vector6<f64> = start.solved.w.fixed_rows::<6>(0) - x;
    let tx: Vector6<f64> = start.tangent.fixed_rows::<6>(0).into();
    if tx.dot(&away) < 0.0 {
        start.tangent = -start.tangent;
    }
    let mut orbits = vec![start.orbit.clone()];
    let (nodes, events, stop) = tracer.trace(start, opts.max_orbits.saturating_sub(1), None)?;
    orbits.extend(nodes.into_iter().map(|n| n.orbit));
    Ok(OrbitFamily {
        orbits,
        events: events.into_iter().map(|(e, _)| e).collect(),
        stop: Some(stop),
    })
}
