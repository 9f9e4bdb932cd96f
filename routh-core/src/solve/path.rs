//! The one predictor–corrector of the crate: a step along a curve `{F = 0}` in ℝᴺ from a point
//! `w` with its tangent `t` (docs/method.md §5 "The search", §6b "Continuation", "Atlases").
//!
//! - **Predictor**: `w + h·t`, passed through the caller's retraction (the normalisation of γ
//!   where the point lives on the sphere).
//! - **Stepping**: what `h` measures and the [`LinearRow`] the corrector adds to `F = 0`:
//!   pseudo-arclength `t·(w − w_pred) = 0` ([`Stepping::Arclength`], `h` an arclength), a fixed
//!   parameter `w_k = w_pred,k` ([`Stepping::Parameter`], natural-parameter stepping, `h` a step
//!   in `w_k`), or no row ([`Stepping::Free`]: the curve is a set of solutions of a square system
//!   and the corrector slides to the nearest one).
//! - **Corrector**: a closure of the caller (each analysis's own equations, solved by the one
//!   Newton corrector, `solve::newton`), then a second closure that completes an accepted point
//!   (its tangent, its test functions).
//! - **Acceptance**: the distance from the prediction at most `max_move·h + move_floor` (a larger
//!   move is a jump to another curve), the cosine between consecutive tangents at least
//!   `min_cos`, and the caller's check (jumps of its test functions, events sharing a step).
//! - **Step control**: halve on any failure, down to `h_min` (then [`Outcome::Stalled`]); after an
//!   easy convergence grow (capped at `h_max`), after a hard one shrink.
//!
//! The five curves of the crate use it: the families of periodic orbits
//! (`periodic/family.rs`, [`PathOptions::orbit_family`]), the search's circles of critical points
//! (`steady/search/curves.rs`, [`PathOptions::search_curve`]), the branches of the bifurcation
//! diagram (`families/continuation.rs`, `families/diagram/trace.rs`, [`PathOptions::diagram`]),
//! the atlas's boundary curves (`families/atlas/trace.rs`, [`PathOptions::atlas_boundary`]) and
//! the atlas grid's segments (`families/atlas/grid.rs`, [`PathOptions::grid_segment`]). Each keeps
//! its own equations, events and ends.

pub(crate) mod row;

use nalgebra::SVector;

use row::LinearRow;

/// How a step is parametrised, and so which linear row closes the corrector's system (see the
/// module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Stepping {
    /// Pseudo-arclength `t·(w − w_pred) = 0`; `h` is an arclength along the unit tangent.
    Arclength,
    /// Natural parameter: `w_k = w_pred,k`; `h` is a step in `w_k` and the predictor is
    /// `w + h·t/|t_k|` (the tangent need not be unit; it cannot pass a fold, where `t_k = 0`).
    Parameter(usize),
    /// No row: the corrector solves a square system from the prediction.
    Free,
}

/// Settings of the predictor–corrector; a named constructor per user.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PathOptions {
    pub stepping: Stepping,
    /// Below this step the curve cannot be continued ([`Outcome::Stalled`]).
    pub h_min: f64,
    /// Largest step.
    pub h_max: f64,
    /// A corrected point is accepted only within `max_move·h + move_floor` of the prediction.
    pub max_move: f64,
    pub move_floor: f64,
    /// Smallest cosine between the tangents at consecutive points (`−∞`: not checked) …
    pub min_cos: f64,
    /// … waived for steps `h ≤ relax·h_min` (where the step cannot usefully shrink further).
    pub relax: f64,
    /// After a convergence in at most `easy` iterations: `h ← min(grow·h, h_max)`.
    pub grow: f64,
    pub easy: usize,
    /// After a convergence in at least `hard` iterations: `h ← max(ease·h, h_min)`.
    pub ease: f64,
    pub hard: usize,
}

impl PathOptions {
    /// The branches of the bifurcation diagram: pseudo-arclength in `(γ, σ)` between `min_step`
    /// and `max_step` (`ContinuationOptions`), a jump beyond `h/2` rejected, tangents turning by
    /// more than `acos 0.97 ≈ 14°` rejected unless the step is already below `4·min_step`; grown
    /// by 1.5 after at most 2 Newton iterations, shrunk by 0.7 after 6 or more.
    pub fn diagram(min_step: f64, max_step: f64) -> Self {
        PathOptions {
            stepping: Stepping::Arclength,
            h_min: min_step,
            h_max: max_step,
            max_move: 0.5,
            move_floor: 1e-9,
            min_cos: 0.97,
            relax: 4.0,
            grow: 1.5,
            easy: 2,
            ease: 0.7,
            hard: 6,
        }
    }

    /// The boundary curves of the atlas: pseudo-arclength in `(ξ, u, v)` with steps between
    /// `1e−4·h_max` and `h_max`, a jump beyond `h/2` rejected, tangents turning by more than
    /// `acos 0.8 ≈ 37°` rejected; grown by 1.5 after at most 3 iterations.
    pub fn atlas_boundary(h_max: f64) -> Self {
        PathOptions {
            stepping: Stepping::Arclength,
            h_min: 1e-4 * h_max,
            h_max,
            max_move: 0.5,
            move_floor: 0.0,
            min_cos: 0.8,
            relax: 0.0,
            grow: 1.5,
            easy: 3,
            ease: 1.0,
            hard: usize::MAX,
        }
    }

    /// A segment of the atlas grid: natural-parameter stepping in the segment parameter `w_k`
    /// (steps from `1e−6` to the whole segment, doubled after every success); jumps are the
    /// caller's check (relative to the predicted move in ξ, and the eigenvalues of `K`).
    pub fn grid_segment(k: usize) -> Self {
        PathOptions {
            stepping: Stepping::Parameter(k),
            h_min: 1e-6,
            h_max: 1.0,
            max_move: f64::INFINITY,
            move_floor: 0.0,
            min_cos: f64::NEG_INFINITY,
            relax: 0.0,
            grow: 2.0,
            easy: usize::MAX,
            ease: 1.0,
            hard: usize::MAX,
        }
    }

    /// A family of periodic orbits (`periodic/family.rs`): pseudo-arclength in `(x₀, T/t_s,
    /// E/e_s)` between `min_step` and `max_step` (`OrbitOptions`), a jump beyond `h/2` rejected,
    /// tangents turning by more than `acos 0.9 ≈ 26°` rejected unless the step is already below
    /// `4·min_step`; grown by 1.5 after at most 3 Gauss–Newton steps, shrunk by 0.7 after 7.
    pub fn orbit_family(min_step: f64, max_step: f64) -> Self {
        PathOptions {
            stepping: Stepping::Arclength,
            h_min: min_step,
            h_max: max_step,
            max_move: 0.5,
            move_floor: 1e-9,
            min_cos: 0.9,
            relax: 4.0,
            grow: 1.5,
            easy: 3,
            ease: 0.7,
            hard: 7,
        }
    }

    /// A curve of critical points in the search: steps of exactly `h` on the sphere (a failure
    /// ends the direction; the search retries the whole curve with a shorter step), no row
    /// (Newton at fixed `p_ψ` from the prediction); the distance window and the level are the
    /// caller's check.
    pub fn search_curve(h: f64) -> Self {
        PathOptions {
            stepping: Stepping::Free,
            h_min: h,
            h_max: h,
            max_move: f64::INFINITY,
            move_floor: 0.0,
            min_cos: f64::NEG_INFINITY,
            relax: 0.0,
            grow: 1.0,
            easy: 0,
            ease: 1.0,
            hard: usize::MAX,
        }
    }
}

/// What the corrector is given: the predicted point and the row of its system.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Prediction<const N: usize> {
    /// The predicted point `w_pred` (retracted).
    pub point: SVector<f64, N>,
    /// The row `a·(w − w_pred) = 0` through it, as `a·w = a·w_pred` (`None` for
    /// [`Stepping::Free`]).
    pub row: Option<LinearRow<N>>,
    /// Whether the step was cut to the caller's limit (the end of the curve's domain).
    pub at_limit: bool,
}

/// A point the corrector converged to, with the caller's data.
#[derive(Debug, Clone)]
pub(crate) struct Corrected<const N: usize, X> {
    pub point: SVector<f64, N>,
    /// Newton iterations (drives the step control).
    pub iterations: usize,
    pub value: X,
}

impl<const N: usize, X> Corrected<N, X> {
    /// The point as accepted, with no tangent (no cosine check).
    pub fn bare(self) -> Point<N, X> {
        Point {
            point: self.point,
            tangent: None,
            iterations: self.iterations,
            value: self.value,
        }
    }
}

/// A completed point: its tangent (if the caller computes one) and the caller's data.
#[derive(Debug, Clone)]
pub(crate) struct Point<const N: usize, Y> {
    pub point: SVector<f64, N>,
    pub tangent: Option<SVector<f64, N>>,
    pub iterations: usize,
    pub value: Y,
}

/// Why an attempt was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Failure {
    /// The corrector (or the completion) did not converge.
    Corrector,
    /// The corrected point is too far from the prediction.
    Moved,
    /// No tangent where the cosine is checked, or a predictor along `t_k = 0`.
    Tangent,
    /// The tangent turned too fast.
    Turned,
    /// The caller's check asked for a shorter step.
    Check,
}

/// The caller's verdict on a point that passed the engine's tests.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Check {
    Accept,
    /// Reject and halve the step.
    Shorten,
    /// End the curve here ([`Outcome::Stopped`]).
    Stop,
}

/// The result of [`Path::step`].
#[derive(Debug, Clone)]
pub(crate) enum Outcome<const N: usize, Y> {
    /// A point accepted with step `h` (the step for the next one is [`Path::h`]).
    Accepted { point: Point<N, Y>, h: f64 },
    /// The caller's check ended the curve at this point.
    Stopped(Point<N, Y>),
    /// Every step down to `h_min` failed; the last failure.
    Stalled(Failure),
    /// The budget of attempts is spent.
    Exhausted,
}

/// The state of a traced curve: the step, the retraction, the attempts made.
#[derive(Debug, Clone)]
pub(crate) struct Path<const N: usize> {
    opts: PathOptions,
    h: f64,
    retract: fn(SVector<f64, N>) -> SVector<f64, N>,
    attempts: usize,
    budget: usize,
}

/// The retraction of a point whose first three coordinates are a unit vector γ: normalise them.
pub(crate) fn sphere_head<const N: usize>(mut w: SVector<f64, N>) -> SVector<f64, N> {
    let g = w.fixed_rows::<3>(0).normalize();
    w.fixed_rows_mut::<3>(0).copy_from(&g);
    w
}

impl<const N: usize> Path<N> {
    /// A curve stepped with `opts`, starting with step `h0`, in flat coordinates and with no
    /// budget.
    pub fn new(opts: PathOptions, h0: f64) -> Self {
        Path {
            opts,
            h: h0,
            retract: |w| w,
            attempts: 0,
            budget: usize::MAX,
        }
    }

    /// With the retraction `retract` applied to every prediction.
    pub fn with_retraction(mut self, retract: fn(SVector<f64, N>) -> SVector<f64, N>) -> Self {
        self.retract = retract;
        self
    }

    /// With at most `budget` attempts (accepted or not) over the whole curve.
    pub fn with_budget(mut self, budget: usize) -> Self {
        self.budget = budget;
        self
    }

    /// The step of the next attempt.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// The attempts made so far.
    pub fn attempts(&self) -> usize {
        self.attempts
    }

    /// One prediction and correction from `w` along `t` with step `h` (no step control, no
    /// cosine or caller check): the corrected point if it is within the distance bound of the
    /// prediction. `at_limit` is passed to the corrector.
    pub fn attempt<X, E>(
        &self,
        w: &SVector<f64, N>,
        t: &SVector<f64, N>,
        h: f64,
        at_limit: bool,
        correct: &mut impl FnMut(&Prediction<N>) -> Result<Option<Corrected<N, X>>, E>,
    ) -> Result<Result<Corrected<N, X>, Failure>, E> {
        let (raw, normal) = match self.opts.stepping {
            Stepping::Arclength => (w + t * h, Some(*t)),
            Stepping::Parameter(k) => {
                if t[k] == 0.0 || !t[k].is_finite() {
                    return Ok(Err(Failure::Tangent));
                }
                let mut e = SVector::zeros();
                e[k] = 1.0;
                (w + t * (h / t[k].abs()), Some(e))
            }
            Stepping::Free => (w + t * h, None),
        };
        let point = (self.retract)(raw);
        let pred = Prediction {
            point,
            row: normal.map(|a| LinearRow::through(a, &point)),
            at_limit,
        };
        let Some(c) = correct(&pred)? else {
            return Ok(Err(Failure::Corrector));
        };
        if (c.point - pred.point).norm() > self.opts.max_move * h + self.opts.move_floor {
            return Ok(Err(Failure::Moved));
        }
        Ok(Ok(c))
    }

    /// The next point from `w` along `t`: attempts with the current step (cut to `limit`, the
    /// distance to the end of the curve's domain or the caller's longest step from `w`), halved
    /// after every failure, until one passes the corrector, the distance bound, `complete` (which
    /// gives the point's tangent), the tangent cosine and `check`; then the step for the next
    /// point is adapted.
    pub fn step<X, Y, E>(
        &mut self,
        w: &SVector<f64, N>,
        t: &SVector<f64, N>,
        limit: f64,
        mut correct: impl FnMut(&Prediction<N>) -> Result<Option<Corrected<N, X>>, E>,
        mut complete: impl FnMut(Corrected<N, X>) -> Result<Option<Point<N, Y>>, E>,
        mut check: impl FnMut(&Point<N, Y>, f64) -> Check,
    ) -> Result<Outcome<N, Y>, E> {
        let o = self.opts;
        loop {
            if self.attempts >= self.budget {
                return Ok(Outcome::Exhausted);
            }
            self.attempts += 1;
            let at_limit = self.h >= limit;
            let h = if at_limit { limit } else { self.h };
            let failure = match self.attempt(w, t, h, at_limit, &mut correct)? {
                Err(f) => f,
                Ok(c) => match complete(c)? {
                    None => Failure::Corrector,
                    Some(p) => {
                        let waived = h <= o.relax * o.h_min || o.min_cos == f64::NEG_INFINITY;
                        match p.tangent {
                            None if !waived => Failure::Tangent,
                            Some(tn) if !waived && turned(tn.dot(t), o.min_cos) => Failure::Turned,
                            _ => match check(&p, h) {
                                Check::Accept => {
                                    self.h = if p.iterations <= o.easy {
                                        (o.grow * h).min(o.h_max)
                                    } else if p.iterations >= o.hard {
                                        (o.ease * h).max(o.h_min)
                                    } else {
                                        h
                                    };
                                    return Ok(Outcome::Accepted { point: p, h });
                                }
                                Check::Stop => return Ok(Outcome::Stopped(p)),
                                Check::Shorten => Failure::Check,
                            },
                        }
                    }
                },
            };
            self.h = 0.5 * h;
            if self.h < o.h_min {
                return Ok(Outcome::Stalled(failure));
            }
        }
    }
}

/// Whether a cosine between consecutive tangents is below `min` (or not a number).
fn turned(cos: f64, min: f64) -> bool {
    cos.is_nan() || cos < min
}

#[cfg(test)]
mod tests;
