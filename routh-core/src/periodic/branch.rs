//! [`switch_branch`]: the family of orbits that crosses a family at a branch point
//! (docs/method.md §11), started along the crossing family's tangent and followed both ways as
//! any family (`family.rs`).

use nalgebra::SMatrix;

use super::family::{merge_halves, restart, smallest, Tracer};
use super::shoot::{correct, Problem, Slot, TOP, UNKNOWNS, W};
use super::{OrbitEvent, OrbitEventKind, OrbitFamily, OrbitOptions};
use crate::solve::path::row::LinearRow;
use crate::{RouthError, Routhian};

/// The family of periodic orbits that crosses a family at a [`OrbitEventKind::BranchPoint`]
/// event, followed both ways from the branch point (docs/method.md §11).
///
/// At a branch point the ten rows of the shooting system (the closure, the phase, `E`, `p_ψ`,
/// `|γ|²`) lose one more rank: their null space is a plane holding both families' tangents. In a
/// conservative system the generic branch point of periodic orbits breaks a symmetry (a
/// pitchfork: planar swings of a body with a plane of symmetry meeting the non-planar orbits
/// born from them), and along the crossing family the energy is stationary at the branch point;
/// its tangent is the plane's direction of constant energy, which the first steps follow with a
/// pseudo-arclength row (so that the corrector cannot fall back onto the family it came from).
/// The orbits come from one end of the crossing family to the other through the event's orbit,
/// as [`continue_orbit`](super::continue_orbit) gives them; where the crossing family's energy is
/// not stationary at the event (a branch point without that symmetry) the result is checked and
/// refused rather than guessed.
///
/// Errors: an event that is not a branch point, invalid options, and a crossing family whose
/// first orbit cannot be corrected ([`RouthError::NoConvergence`]).
pub fn switch_branch<M: Routhian>(
    model: &M,
    event: &OrbitEvent,
    opts: &OrbitOptions,
) -> Result<OrbitFamily, RouthError> {
    opts.validate()?;
    if event.kind != OrbitEventKind::BranchPoint {
        return Err(RouthError::InvalidOption {
            what: "event",
            reason: format!(
                "a branch point is needed, got a {} (a period doubling's family is \
                 period_doubled_family's)",
                event.kind
            ),
        });
    }
    let (s, scales) = restart(model, &event.orbit, opts)?;
    // The null vector of the rows with the energy held (its column removed): the crossing
    // family's tangent.
    let top: SMatrix<f64, TOP, { UNKNOWNS - 1 }> = s.tangent_rows().remove_column(7);
    let svd = top.svd(false, true);
    let v_t = svd.v_t.expect("asked for V");
    let values = svd.singular_values.as_slice();
    let imin = smallest(values);
    let largest = values.iter().cloned().fold(0.0, f64::max);
    // At a branch point that null vector is exact (to the event's accuracy); elsewhere the
    // smallest singular value is of the order of the others.
    if values[imin] > 1e-4 * largest {
        return Err(RouthError::InvalidOption {
            what: "event",
            reason: format!(
                "no second family crosses at this orbit with its energy stationary (the rows' \
                 smallest singular value with the energy held is {:.3e} of the largest)",
                values[imin] / largest
            ),
        });
    }
    let mut n = W::zeros();
    for k in 0..UNKNOWNS - 1 {
        n[if k < 7 { k } else { k + 1 }] = v_t[(imin, k)];
    }
    n /= n.norm();
    // Deterministic orientation: the largest component of the state's part positive.
    let lead = (0..6)
        .max_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
        .unwrap_or(0);
    if n[lead] < 0.0 {
        n = -n;
    }
    let x: nalgebra::Vector6<f64> = s.w.fixed_rows::<6>(0).into();
    let tracer = Tracer {
        slot: Slot::Energy(model),
        opts,
        p_psi: event.orbit.p_psi,
        scales,
        bounds: opts.energy_bounds,
        first_period: event.orbit.period,
    };
    let prob = Problem::at(model, &x, event.orbit.p_psi, scales)?;
    let first = |dir: W| -> Result<Option<super::shoot::Solved>, RouthError> {
        let mut h = opts.first_step().max(10.0 * opts.initial_amplitude);
        while h >= opts.min_step {
            let pred = s.w + dir * h;
            let row = LinearRow::through(dir, &pred);
            if let Ok(sol) = correct(Slot::Energy(model), &prob, &row, &pred, opts)? {
                // Kept only if it left along the crossing family: the corrector moved it by
                // little against the step.
                if (sol.w - pred).norm() <= 0.25 * h {
                    return Ok(Some(sol));
                }
            }
            h *= 0.5;
        }
        Ok(None)
    };
    let centre = tracer.node(s.clone(), Some(&n))?;
    let budget = opts.max_orbits.saturating_sub(1);
    let mut halves = Vec::new();
    for (dir, share) in [(n, budget.div_ceil(2)), (-n, budget / 2)] {
        let Some(sol) = first(dir)? else {
            return Err(RouthError::NoConvergence {
                what: "the first orbit of the crossing family",
                iterations: opts.max_iter,
                residual: f64::NAN,
            });
        };
        let start = tracer.node(sol, Some(&dir))?;
        let (mut nodes, events, stop) =
            tracer.trace(start.clone(), share.saturating_sub(1), None)?;
        nodes.insert(0, start);
        halves.push((nodes, events, stop));
    }
    let down = halves.pop().expect("two halves");
    let up = halves.pop().expect("two halves");
    Ok(merge_halves(centre.orbit, up, down))
}
