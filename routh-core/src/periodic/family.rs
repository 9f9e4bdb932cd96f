//! Families of periodic orbits at fixed `p_ψ` through the energy: [`lyapunov_family`] from an
//! elliptic steady motion, [`continue_orbit`] from any orbit (and, in `doubling.rs`,
//! [`period_doubled_family`](super::period_doubled_family) from a period doubling; docs/method.md §11).
//!
//! The same [`Tracer`] follows the families at a fixed energy through a parameter of the model
//! (`parameter.rs`, [`continue_orbit_in`](super::continue_orbit_in)): the eighth unknown is
//! then the parameter ([`Slot`]), and a fold is where the family turns back in it.
//!
//! Pseudo-arclength in `w = (x₀, T/t_s, E/e_s)` on the crate's one predictor–corrector
//! (`path.rs`, [`PathOptions::orbit_family`]); the tangent is the null vector of the ten rows of
//! the shooting system without the linear row. Between two accepted orbits `a` and `b`:
//! a change of sign of the tangent's energy component is a `Fold`; else of `k − 1` a
//! `BranchPoint`; of `k + 1` a `PeriodDoubling`. Each is located by the crate's one event locator
//! (`locate.rs`) on re-solves along the step, to `|ΔE| ≤ event_tol·max(1, |E|)`.

use nalgebra::{Complex, Matrix6, Vector6};

use super::flow::{field_and_jacobian, join, onto_level, split};
use super::node::{same_family, Node};
use super::shoot::{
    check_guess, correct, correct_at, orbit_of, Problem, Scales, Slot, Solved, UNKNOWNS, W,
};
use super::{OrbitEvent, OrbitFamily, OrbitOptions, OrbitStop, PeriodicOrbit};
use crate::solve::path::row::LinearRow;
use crate::solve::path::{Check, Corrected, Outcome, Path, PathOptions, Point};
use crate::{classify, RouthError, Routhian, Stability, SteadyMotion};

/// The index of the smallest singular value (nalgebra does not promise an order).
pub(super) fn smallest(values: &[f64]) -> usize {
    (0..values.len())
        .min_by(|&a, &b| values[a].total_cmp(&values[b]))
        .unwrap_or(0)
}

/// The unit null vector of the first ten rows of the shooting system (the family's tangent),
/// oriented along `along` when given.
fn tangent_of(s: &Solved, along: Option<&W>) -> W {
    let svd = s.tangent_rows().svd(false, true);
    let v_t = svd.v_t.expect("asked for V");
    let imin = smallest(svd.singular_values.as_slice());
    let mut t: W = v_t.row(imin).transpose();
    t /= t.norm();
    if let Some(a) = along {
        if t.dot(a) < 0.0 {
            t = -t;
        }
    }
    t
}

/// The family's state: what the eighth unknown is (the energy of one model, or the parameter
/// of a family of models at a fixed energy), the options, the scales, the orbits so far.
pub(super) struct Tracer<'a, M: Routhian> {
    pub slot: Slot<'a, M>,
    pub opts: &'a OrbitOptions,
    /// `p_ψ` of a family through the energy (a family in a parameter has the family's).
    pub p_psi: f64,
    pub scales: Scales,
    /// The bounds of the eighth unknown (energies, or parameter values).
    pub bounds: Option<(f64, f64)>,
    pub first_period: f64,
}

impl<M: Routhian> Tracer<'_, M> {
    pub(super) fn problem_at(&self, w: &W) -> Result<Problem, RouthError> {
        let x: Vector6<f64> = w.fixed_rows::<6>(0).into();
        let (model, p) = self.slot.member(w, &self.scales, self.p_psi)?;
        Problem::at(&*model, &x, p, self.scales)
    }

    /// The accepted orbit of `s` with its tangent (oriented along `along`). Errors: a family
    /// whose member at the orbit's parameter is invalid (there was none at the same parameter
    /// in the corrector).
    pub(super) fn node(&self, s: Solved, along: Option<&W>) -> Result<Node, RouthError> {
        self.node_with(s, along, self.opts.nonlinear)
    }

    /// [`Tracer::node`], its twist computed when `twist` is set (NaN otherwise): a re-solve that
    /// locates an event other than a twist zero does not need it.
    pub(super) fn node_with(
        &self,
        s: Solved,
        along: Option<&W>,
        twist: bool,
    ) -> Result<Node, RouthError> {
        let tangent = tangent_of(&s, along);
        let (model, _) = self.slot.member(&s.w, &self.scales, self.p_psi)?;
        let orbit = orbit_of(&*model, &s, &self.scales, self.opts);
        let twist = if twist {
            super::nonlinear::twist_of(
                &*model,
                &orbit,
                &s.shot.monodromy,
                &self.nonlinear_options(),
            )?
        } else {
            f64::NAN
        };
        Ok(Node {
            solved: s,
            tangent,
            orbit,
            twist,
        })
    }

    /// The settings of the twist of the family's orbits: the family's integration tolerances.
    pub(super) fn nonlinear_options(&self) -> super::OrbitNonlinearOptions {
        super::OrbitNonlinearOptions {
            rtol: self.opts.rtol,
            atol: self.opts.atol,
            max_steps: self.opts.max_steps,
            control: self.opts.control.clone(),
            ..Default::default()
        }
    }

    /// Where a node is along the family: its energy (the orbit's, for a family through the
    /// energy) or its parameter.
    pub(super) fn value(&self, n: &Node) -> f64 {
        match self.slot {
            Slot::Energy(_) => n.orbit.energy,
            Slot::Parameter { .. } => self.scales.parameter(&n.solved.w),
        }
    }

    /// Follows the family both ways from the corrected orbit `s`, first towards larger `w₇`,
    /// the budget of orbits shared between the directions: the orbit's node and both halves.
    pub(super) fn both_ways(&self, s: Solved) -> Result<(Node, Half, Half), RouthError> {
        let mut up = self.node(s, None)?;
        if up.tangent[7] < 0.0 {
            up.tangent = -up.tangent;
        }
        let mut down = up.clone();
        down.tangent = -down.tangent;
        let budget = self.opts.max_orbits.saturating_sub(1);
        let traced_up = self.trace(up.clone(), budget.div_ceil(2), None)?;
        let traced_down = self.trace(down, budget / 2, None)?;
        Ok((up, traced_up, traced_down))
    }

    /// The stop at the bound `b` of the eighth unknown.
    fn bound_stop(&self, b: f64) -> OrbitStop {
        match self.slot {
            Slot::Energy(_) => OrbitStop::EnergyBound { energy: b },
            Slot::Parameter { .. } => OrbitStop::ParameterBound { s: b },
        }
    }

    /// The orbit at the bound `bound` (of the energy, or of the parameter), corrected from the
    /// step between `a` and `b` with the eighth unknown fixed there.
    fn at_bound(&self, a: &Node, b: &Node, bound: f64) -> Result<Option<Node>, RouthError> {
        let (ea, eb) = (self.value(a), self.value(b));
        let f = ((bound - ea) / (eb - ea)).clamp(0.0, 1.0);
        let guess = a.solved.w + (b.solved.w - a.solved.w) * f;
        let prob = self.problem_at(&a.solved.w)?;
        let row = self.scales.energy_row(bound);
        Ok(match correct(self.slot, &prob, &row, &guess, self.opts)? {
            Ok(mut s) => {
                // A parameter is put on the bound exactly (the row holds it to round-off; its
                // scale is a power of two, so `(bound/s_s)·s_s` is the bound).
                if let Slot::Parameter { .. } = self.slot {
                    s.w[7] = bound / self.scales.e;
                }
                Some(self.node(s, Some(&a.tangent))?)
            }
            Err(_) => None,
        })
    }

    /// Follows the family from `start` along its tangent until a stop; `budget` orbits at most
    /// (counting none of `start`). `origin`: the steady motion a Lyapunov family starts from.
    pub(super) fn trace(
        &self,
        start: Node,
        budget: usize,
        origin: Option<&Vector6<f64>>,
    ) -> Result<Half, RouthError> {
        let o = self.opts;
        let mut path: Path<UNKNOWNS> = Path::new(
            PathOptions::orbit_family(o.min_step, o.max_step),
            o.first_step(),
        )
        .with_budget(budget.saturating_mul(8).max(16));
        let mut nodes: Vec<Node> = Vec::new();
        let mut events = Vec::new();
        let first_w = start.solved.w;
        let mut cur = start;
        let small = 0.5 * o.initial_amplitude;
        // The caller's cancel flag ends the family with what it has (also when it stops an
        // integration inside a step).
        macro_rules! or_interrupted {
            ($e:expr) => {
                match $e {
                    Err(RouthError::Interrupted) => {
                        return Ok((nodes, events, OrbitStop::Interrupted))
                    }
                    r => r?,
                }
            };
        }
        loop {
            o.control.report(nodes.len(), budget);
            if o.control.is_cancelled() {
                return Ok((nodes, events, OrbitStop::Interrupted));
            }
            if nodes.len() >= budget {
                return Ok((nodes, events, OrbitStop::MaxOrbits));
            }
            let prob = or_interrupted!(self.problem_at(&cur.solved.w));
            let (w, t) = (cur.solved.w, cur.tangent);
            let outcome = or_interrupted!(path.step(
                &w,
                &t,
                f64::INFINITY,
                |pred| {
                    let row = pred
                        .row
                        .unwrap_or_else(|| LinearRow::through(t, &pred.point));
                    Ok::<_, RouthError>(match correct(self.slot, &prob, &row, &pred.point, o)? {
                        Ok(s) => Some(Corrected {
                            point: s.w,
                            iterations: s.iterations,
                            value: s,
                        }),
                        Err(_) => None,
                    })
                },
                |c| {
                    let n = self.node(c.value, Some(&t))?;
                    Ok(Some(Point {
                        point: n.solved.w,
                        tangent: Some(n.tangent),
                        iterations: c.iterations,
                        value: n,
                    }))
                },
                // A step that lands on a family crossing at a branch point is refused (and
                // so shortened until it stays on this one).
                |p, _| {
                    if same_family(&cur, &p.value) {
                        Check::Accept
                    } else {
                        Check::Shorten
                    }
                },
            ));
            if o.control.is_cancelled() {
                // A step cut short by the flag is no stall.
                return Ok((nodes, events, OrbitStop::Interrupted));
            }
            let (next, h) = match outcome {
                Outcome::Accepted { point, h } => (point.value, h),
                Outcome::Stopped(point) => (point.value, path.h()),
                Outcome::Stalled(_) => {
                    return Ok((
                        nodes,
                        events,
                        OrbitStop::Stalled {
                            energy: cur.orbit.energy,
                        },
                    ))
                }
                Outcome::Exhausted => return Ok((nodes, events, OrbitStop::MaxOrbits)),
            };
            // A bound crossed (of the energy, or of the parameter): end exactly on it.
            if let Some((lo, hi)) = self.bounds {
                let e = self.value(&next);
                if e < lo || e > hi {
                    let bound = if e < lo { lo } else { hi };
                    if let Some(end) = or_interrupted!(self.at_bound(&cur, &next, bound)) {
                        let sigma = (end.solved.w - cur.solved.w).norm();
                        let found = or_interrupted!(self.events(&cur, &end, sigma));
                        events.extend(found);
                        nodes.push(end);
                    }
                    return Ok((nodes, events, self.bound_stop(bound)));
                }
            }
            let found = or_interrupted!(self.events(&cur, &next, h));
            events.extend(found);
            nodes.push(next.clone());
            let x: Vector6<f64> = next.solved.w.fixed_rows::<6>(0).into();
            if next.orbit.period > o.max_period_ratio * self.first_period {
                return Ok((
                    nodes,
                    events,
                    OrbitStop::PeriodBound {
                        period: next.orbit.period,
                    },
                ));
            }
            let far_from_origin =
                origin.is_none_or(|xs| (x - xs).norm() > 20.0 * o.initial_amplitude);
            if next.orbit.amplitude < small && far_from_origin {
                return Ok((
                    nodes,
                    events,
                    OrbitStop::ReachedSteadyMotion {
                        gamma: next.orbit.gamma0,
                        energy: next.orbit.energy,
                    },
                ));
            }
            if nodes.len() >= 4 && (next.solved.w - first_w).norm() < 0.5 * h {
                return Ok((nodes, events, OrbitStop::Closed));
            }
            cur = next;
        }
    }
}

/// Refuses a steady motion found on another model (another parameter value): its energy and
/// cyclic momentum must be this model's at its state `xs = (ψ̇γ, γ)`.
fn of_this_model<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    xs: &Vector6<f64>,
) -> Result<(), RouthError> {
    let (w, g) = split(xs);
    let (e, p) = (model.energy(&w, &g), model.cyclic_momentum(&w, &g));
    // NaN is off too.
    let off = |a: f64, b: f64| {
        let d = (a - b).abs();
        d.is_nan() || d > 1e-8 * 1f64.max(a.abs()).max(b.abs())
    };
    if off(e, steady.energy) || off(p, steady.p_psi) {
        return Err(RouthError::InvalidOption {
            what: "steady",
            reason: format!(
                "not a steady motion of this model: at its γ and ψ̇ this model has E = {e}, \
                 p_ψ = {p}, the steady motion says E = {}, p_ψ = {} (found on another model or \
                 parameter value? take it from this model's steady_motions)",
                steady.energy, steady.p_psi
            ),
        });
    }
    Ok(())
}

/// The frequencies `ω₁ ≥ ω₂ > 0` of an elliptic steady motion (`f₂`'s roots `±iω_k`).
fn frequencies<M: Routhian>(model: &M, steady: &SteadyMotion) -> Result<[f64; 2], RouthError> {
    let report = classify(model, steady)?;
    let elliptic = matches!(
        report.verdict,
        Stability::SecularlyStable | Stability::GyroscopicallyStabilized
    );
    let mut w: Vec<f64> = report
        .f2_roots
        .iter()
        .filter(|r| r.im > 0.0)
        .map(|r| r.im)
        .collect();
    if !elliptic || w.len() != 2 {
        return Err(RouthError::InvalidOption {
            what: "steady",
            reason: format!(
                "a Lyapunov family starts at a linearly stable steady motion; this one is {:?}",
                report.verdict
            ),
        });
    }
    w.sort_by(|a, b| b.total_cmp(a));
    Ok([w[0], w[1]])
}

/// A real vector of the plane of the linear mode of `DF(x_s)` with eigenvalue `iω`.
fn mode_vector(a: &Matrix6<f64>, omega: f64) -> Vector6<f64> {
    let m: Matrix6<Complex<f64>> =
        a.map(|v| Complex::new(v, 0.0)) - Matrix6::from_diagonal_element(Complex::new(0.0, omega));
    let svd = m.svd(false, true);
    let v_t = svd.v_t.expect("asked for V");
    let imin = smallest(svd.singular_values.as_slice());
    // The right singular vector is the conjugate of V^H's row.
    let v: Vec<Complex<f64>> = v_t.row(imin).iter().map(|z| z.conj()).collect();
    let re = Vector6::from_fn(|i, _| v[i].re);
    let im = Vector6::from_fn(|i, _| v[i].im);
    let u = if re.norm() >= im.norm() { re } else { im };
    u / u.norm()
}

/// The Lyapunov family of periodic orbits of mode `mode` (0: the faster frequency ω₁, 1: ω₂)
/// born at an elliptic steady motion, followed at the steady motion's `p_ψ` through the energy
/// (docs/method.md §11).
///
/// The first orbit is corrected from the mode's linear orbit at amplitude
/// [`OrbitOptions::initial_amplitude`] (its period near `2π/ω_k`); the family is then followed by
/// pseudo-arclength until an energy bound, the budget of orbits, a period bound, a return onto a
/// steady motion, a closed loop or a stall ([`OrbitFamily::stop`]). Folds, branch points and
/// period doublings are located on the way.
///
/// Errors: a steady motion that is not linearly stable (`classify` must say `SecularlyStable` or
/// `GyroscopicallyStabilized`), `mode > 1`, a resonant start (`ω_j/ω_k` within
/// [`OrbitOptions::resonance_tol`] of an integer: the family is not unique there and is not
/// guessed through), invalid options, and a first orbit that cannot be corrected.
pub fn lyapunov_family<M: Routhian>(
    model: &M,
    steady: &SteadyMotion,
    mode: usize,
    opts: &OrbitOptions,
) -> Result<OrbitFamily, RouthError> {
    opts.validate()?;
    if mode > 1 {
        return Err(RouthError::InvalidOption {
            what: "mode",
            reason: format!("0 (ω₁) or 1 (ω₂), got {mode}"),
        });
    }
    let gamma = crate::validate::unit_gamma("steady.gamma", &steady.gamma)?;
    let xs = join(&(gamma * steady.psi_dot), &gamma);
    of_this_model(model, steady, &xs)?;
    let smallest = 1e-9 * 1f64.max(xs.norm());
    if opts.initial_amplitude < smallest {
        return Err(RouthError::InvalidOption {
            what: "OrbitOptions::initial_amplitude",
            reason: format!(
                "{:e} is too small: the first orbit would not be told from the steady motion \
                 (at least {smallest:e})",
                opts.initial_amplitude
            ),
        });
    }
    let w = frequencies(model, steady)?;
    let (wk, wj) = (w[mode], w[1 - mode]);
    let ratio = wj / wk;
    let n = ratio.round();
    // An axially symmetric body at rest on its axis: 1:1 by the symmetry, mode 0 its swings.
    let swing = super::symmetry::rest_swing(model, steady, mode)?;
    if swing.is_none() && n >= 1.0 && (ratio - n).abs() <= opts.resonance_tol {
        return Err(RouthError::InvalidOption {
            what: "mode",
            reason: format!(
                "resonant start: ω_j/ω_k = {:.6}/{:.6} = {ratio:.6} is within {} of {n}; the \
                 Lyapunov family of this mode is not unique",
                wj, wk, opts.resonance_tol
            ),
        });
    }
    let (_, a) = field_and_jacobian(model, &xs)?;
    let u = swing.unwrap_or_else(|| mode_vector(&a, wk));
    let period = 2.0 * std::f64::consts::PI / wk;
    // Onto the steady motion's level of p_ψ and |γ| = 1: the mode is tangent to both, so the
    // linear orbit leaves them at second order in the amplitude, and at a spinning steady motion
    // (ψ̇ ≠ 0) the energy of a point off the level is off by ψ̇·Δp_ψ, of the same order as the
    // energy above the steady motion: the first orbit's energy would not belong to the level.
    let x0 = onto_level(model, &(xs + u * opts.initial_amplitude), steady.p_psi);
    let (w0, g0) = split(&x0);
    check_guess(model, &w0, &g0, period)?;
    let e0 = model.energy(&w0, &g0);
    if let Some((lo, hi)) = opts.energy_bounds {
        if !(lo <= e0 && e0 <= hi) {
            return Err(RouthError::InvalidOption {
                what: "OrbitOptions::energy_bounds",
                reason: format!(
                    "the family starts at the steady motion's energy {:.12} (its first orbit at \
                     {e0:.12}), outside the bounds ({lo}, {hi})",
                    steady.energy
                ),
            });
        }
    }
    let scales = Scales {
        t: period,
        e: 1f64.max(steady.energy.abs()),
    };
    let tracer = Tracer {
        slot: Slot::Energy(model),
        opts,
        p_psi: steady.p_psi,
        scales,
        bounds: opts.energy_bounds,
        first_period: period,
    };
    let mut prob = Problem::at(model, &x0, steady.p_psi, scales)?;
    if super::symmetry::mode_is_a_turn(&xs, &a, &u) {
        prob.turn = None;
    }
    let row = scales.energy_row(e0);
    let first = match correct(
        Slot::Energy(model),
        &prob,
        &row,
        &scales.pack(&x0, period, e0),
        opts,
    )? {
        Ok(s) => s,
        Err(best) => {
            return Err(RouthError::NoConvergence {
                what: "the first orbit of the Lyapunov family",
                iterations: opts.max_iter,
                residual: best,
            })
        }
    };
    let mut start = tracer.node(first, None)?;
    // Oriented towards larger amplitudes.
    let dx: Vector6<f64> = start.solved.w.fixed_rows::<6>(0) - xs;
    let tx: Vector6<f64> = start.tangent.fixed_rows::<6>(0).into();
    if tx.dot(&dx) < 0.0 {
        start.tangent = -start.tangent;
    }
    let mut orbits = vec![start.orbit.clone()];
    let (nodes, events, stop) =
        tracer.trace(start, opts.max_orbits.saturating_sub(1), Some(&xs))?;
    orbits.extend(nodes.into_iter().map(|n| n.orbit));
    Ok(OrbitFamily {
        orbits,
        events: events.into_iter().map(|(e, _)| e).collect(),
        stop: Some(stop),
    })
}

/// Corrects `orbit` in the family's unknowns (and checks it is an orbit).
pub(super) fn restart<M: Routhian>(
    model: &M,
    orbit: &PeriodicOrbit,
    opts: &OrbitOptions,
) -> Result<(Solved, Scales), RouthError> {
    let x = check_guess(model, &orbit.omega0, &orbit.gamma0, orbit.period)?;
    let e = model.energy(&orbit.omega0, &x.fixed_rows::<3>(3).into());
    let not_an_orbit = |why: String| RouthError::InvalidOption {
        what: "orbit",
        reason: format!(
            "not a periodic orbit of this model: {why}; correct a guess with periodic_orbit first"
        ),
    };
    let de = (e - orbit.energy).abs() / 1f64.max(e.abs());
    if de.is_nan() || de > START_TOL {
        return Err(not_an_orbit(format!(
            "this model gives its start the energy {e} where the orbit says {}",
            orbit.energy
        )));
    }
    let (s, scales, _) = correct_at(model, orbit, e, orbit.p_psi, opts)?;
    let s = match s {
        Ok(s) => s,
        Err(best) => {
            return Err(not_an_orbit(format!(
                "its correction does not converge (residual {best:e} after {} steps)",
                opts.max_iter
            )))
        }
    };
    // The correction of an orbit moves it by its own error (1e−9 by default); one that moves
    // further was not an orbit of this model, and the family would be another orbit's.
    let moved = (s.w.fixed_rows::<6>(0) - x).norm() / 1f64.max(x.norm());
    let dt = (scales.period(&s.w) - orbit.period).abs() / orbit.period;
    if !(moved <= START_TOL && dt <= START_TOL) {
        return Err(not_an_orbit(format!(
            "corrected, its start moves by {moved:.2e} and its period by {dt:.2e} (relative)"
        )));
    }
    Ok((s, scales))
}

/// How far (relative) the correction may move an orbit a family is continued from.
const START_TOL: f64 = 1e-5;

/// Follows the family through `orbit` at its `p_ψ` over `energy_range`, in both directions, by
/// pseudo-arclength (through folds), locating folds, branch points and period doublings
/// (docs/method.md §11). The orbits come from the lower end to the upper end of the part traced
/// (in the order of continuation along the family); [`OrbitFamily::stop`] is `None` when both
/// directions reached the range's ends, else the first other reason.
pub fn continue_orbit<M: Routhian>(
    model: &M,
    orbit: &PeriodicOrbit,
    energy_range: (f64, f64),
    opts: &OrbitOptions,
) -> Result<OrbitFamily, RouthError> {
    opts.validate()?;
    let (lo, hi) = energy_range;
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(RouthError::InvalidOption {
            what: "energy_range",
            reason: format!("need finite lo < hi, got ({lo}, {hi})"),
        });
    }
    if !(lo <= orbit.energy && orbit.energy <= hi) {
        return Err(RouthError::InvalidOption {
            what: "energy_range",
            reason: format!(
                "the orbit's energy {:.12} is outside the range ({lo}, {hi}); a family is \
                 continued from an orbit inside the range",
                orbit.energy
            ),
        });
    }
    let (s, scales) = restart(model, orbit, opts)?;
    let tracer = Tracer {
        slot: Slot::Energy(model),
        opts,
        p_psi: orbit.p_psi,
        scales,
        bounds: Some((lo, hi)),
        first_period: orbit.period,
    };
    let (up, traced_up, traced_down) = tracer.both_ways(s)?;
    Ok(merge_halves(up.orbit, traced_up, traced_down))
}

/// One direction of a family traced from a centre: its orbits, events (each with its place along
/// the family, [`Tracer::value`]) and stop.
pub(super) type Half = (Vec<Node>, Vec<(OrbitEvent, f64)>, OrbitStop);

/// The family through `centre` from the halves traced both ways (`up`, `down`): the orbits from
/// the far end of `down` through `centre` to the far end of `up`, the events in that order (those
/// of `down` with `before` and `after` exchanged), and the stop: `None` when both halves reached
/// a bound (of the energy, or of the parameter), else the first other reason.
pub(super) fn merge_halves(centre: PeriodicOrbit, up: Half, down: Half) -> OrbitFamily {
    merge_along((centre, 0.0), up, down, &|_| 0.0).0
}

/// As [`merge_halves`], with the places along the family of the orbits (`centre.1` the centre's,
/// `value` the others') and of the events, in the same order.
pub(super) fn merge_along(
    centre: (PeriodicOrbit, f64),
    up: Half,
    down: Half,
    value: &dyn Fn(&Node) -> f64,
) -> (OrbitFamily, Vec<f64>, Vec<f64>) {
    let (n_up, ev_up, stop_up) = up;
    let (n_dn, ev_dn, stop_dn) = down;
    let mut places: Vec<f64> = n_dn.iter().rev().map(value).collect();
    places.push(centre.1);
    places.extend(n_up.iter().map(value));
    let mut orbits: Vec<PeriodicOrbit> = n_dn.into_iter().rev().map(|n| n.orbit).collect();
    orbits.push(centre.0);
    orbits.extend(n_up.into_iter().map(|n| n.orbit));
    let mut event_places = Vec::new();
    let mut events: Vec<OrbitEvent> = Vec::new();
    for (e, at) in ev_dn.into_iter().rev() {
        events.push(OrbitEvent {
            before: e.after,
            after: e.before,
            ..e
        });
        event_places.push(at);
    }
    for (e, at) in ev_up {
        events.push(e);
        event_places.push(at);
    }
    let bound = |s: &OrbitStop| {
        matches!(
            s,
            OrbitStop::EnergyBound { .. } | OrbitStop::ParameterBound { .. }
        )
    };
    let stop = if bound(&stop_up) && bound(&stop_dn) {
        None
    } else if !bound(&stop_up) {
        Some(stop_up)
    } else {
        Some(stop_dn)
    };
    (
        OrbitFamily {
            orbits,
            events,
            stop,
        },
        places,
        event_places,
    )
}
