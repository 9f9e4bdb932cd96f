//! The chart's curves continued in `(x, h)` (docs/method.md §12.4), by local parameterisation
//! (Rheinboldt): from an event found on the family at one `x` of the grid, the curve of its kind
//! is followed both ways, each step fixing the coordinate along which the curve advances most
//! (in units of the chart's ranges) and locating the event along the family in the other:
//! - a step in `x`: at the new `x`, a regular orbit of the family (the *anchor*, never the event
//!   itself, which may be a branch point where the fixed-energy system is singular) is corrected
//!   at its predicted energy, the family is followed from it over a window about the predicted
//!   `h` (`continue_orbit`) and the event of the curve's kind nearest the prediction is the next
//!   point;
//! - a step in `h`, where the curve is steep or turns back in `x`: at the energy
//!   `E = Eₛ(x̂) + h` of the predicted `x̂`, the family through the anchor is followed in the
//!   parameter (`continue_orbit_in`) over a window about `x̂`, and the event nearest `x̂` is the
//!   next point.
//!
//! Both are the crate's one corrector, path follower and event locator, so every point is an
//! event located to `event_tol` like the families' own. The step follows the secant predictor's
//! error, and the steps in `x` land on every `x` of the grid, so that an event of the grid's
//! families on a traced curve is recognised and does not start a second curve.

use nalgebra::Vector3;

use super::super::shoot::orbit_near;
use super::super::{
    continue_orbit, continue_orbit_in, OrbitEvent, OrbitEventKind, OrbitFamily, OrbitOptions,
};
use super::OrbitChartCurve;
use crate::{steady_motion_near, PeriodicOrbit, RouthError, Routhian, SteadyMotion};

/// A point of a curve: the event's `(x, h)`, the steady motion there and the anchor with its `h`.
#[derive(Clone)]
pub(super) struct Point {
    pub x: f64,
    pub h: f64,
    pub steady_gamma: Vector3<f64>,
    pub anchor: PeriodicOrbit,
    pub anchor_h: f64,
}

/// What every curve of one chart shares.
pub(super) struct Tracing<'a, F> {
    pub family: &'a F,
    /// The grid of `x`, increasing.
    pub xs: &'a [f64],
    /// The chart's range of `h`.
    pub h_range: (f64, f64),
    /// The widest search window about the prediction, a fraction of the chart's ranges.
    pub join_tol: f64,
    pub opts: &'a OrbitOptions,
}

/// The regular orbit of `fam` nearest the event `ev` in energy (the events lie between accepted
/// orbits, which are regular points of the family), with its index.
pub(super) fn anchor_of(fam: &OrbitFamily, ev: &OrbitEvent) -> Option<(usize, PeriodicOrbit)> {
    fam.orbits
        .iter()
        .enumerate()
        .filter(|(_, o)| !o.degenerate)
        .min_by(|a, b| {
            (a.1.energy - ev.energy)
                .abs()
                .total_cmp(&(b.1.energy - ev.energy).abs())
        })
        .map(|(i, o)| (i, o.clone()))
}

/// A step of the curve: which coordinate is fixed, and where.
#[derive(Clone, Copy)]
enum Fixed {
    X(f64),
    H(f64),
}

impl<F> Tracing<'_, F> {
    fn x_span(&self) -> f64 {
        self.xs[self.xs.len() - 1] - self.xs[0]
    }

    fn h_span(&self) -> f64 {
        self.h_range.1 - self.h_range.0
    }

    /// `(x, h)` in units of the chart's ranges.
    fn scaled(&self, x: f64, h: f64) -> (f64, f64) {
        (x / self.x_span(), h / self.h_span())
    }

    /// The next `x` of the grid beyond `x` in the direction `dir`, if any.
    fn next_grid(&self, x: f64, dir: f64) -> Option<f64> {
        let tiny = 1e-9 * self.x_span();
        if dir > 0.0 {
            self.xs.iter().copied().find(|&g| g > x + tiny)
        } else {
            self.xs.iter().rev().copied().find(|&g| g < x - tiny)
        }
    }

    /// Whether the seed `(x, h)` lies on one of `curves` of `kind`: a point at the same `x` of
    /// the grid within `1e−4` of the range of `h`, or a segment across `x` within `2e−3`.
    pub fn covered(
        &self,
        curves: &[OrbitChartCurve],
        kind: OrbitEventKind,
        x: f64,
        h: f64,
    ) -> bool {
        let (tx, th) = (1e-9 * self.x_span(), self.h_span());
        curves.iter().filter(|c| c.kind == kind).any(|c| {
            c.points
                .iter()
                .any(|q| (q[0] - x).abs() <= tx && (q[1] - h).abs() <= 1e-4 * th)
                || c.points.windows(2).any(|w| {
                    let (a, b) = (w[0], w[1]);
                    (a[0] - x) * (b[0] - x) < 0.0 && {
                        let at = a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
                        (at - h).abs() <= 2e-3 * th
                    }
                })
        })
    }
}

impl<M: Routhian, F: Fn(f64) -> (M, f64)> Tracing<'_, F> {
    /// The curve of `kind` through `seed`, followed both ways: its points in the order of the
    /// curve. Errors: cancellation only (a step that fails ends the curve there).
    pub fn curve(&self, kind: OrbitEventKind, seed: Point) -> Result<OrbitChartCurve, RouthError> {
        let down = self.follow(kind, &seed, -1.0)?;
        let up = self.follow(kind, &seed, 1.0)?;
        let points = down
            .iter()
            .rev()
            .chain(std::iter::once(&seed))
            .chain(&up)
            .map(|p| [p.x, p.h])
            .collect();
        Ok(OrbitChartCurve { kind, points })
    }

    /// The points beyond `seed`, first in the direction `dir` of `x`. The step, in units of the
    /// chart's ranges, is at most the grid's spacing, halved where a step fails (down to 1/256
    /// of it, where the curve ends: it left the chart) and adapted to the secant predictor's
    /// error against 1/500; it is a step in `x` where the curve advances more in `x` than in
    /// `h`, else a step in `h`.
    fn follow(
        &self,
        kind: OrbitEventKind,
        seed: &Point,
        dir: f64,
    ) -> Result<Vec<Point>, RouthError> {
        let spacing = 1.0 / (self.xs.len() - 1) as f64;
        let (ds_max, ds_min, tol) = (spacing, spacing / 256.0, 2e-3);
        let budget = 32 * self.xs.len();
        let mut out = Vec::new();
        let mut p = seed.clone();
        // The unit tangent in scaled coordinates, known after the first step.
        let mut tangent: Option<(f64, f64)> = None;
        let mut ds = ds_max;
        let mut window = self.join_tol;
        while out.len() < budget {
            if self.opts.control.is_cancelled() {
                return Err(RouthError::Interrupted);
            }
            let (t, along_x) = match tangent {
                None => ((dir, 0.0), true),
                Some(t) => (t, t.0.abs() >= t.1.abs()),
            };
            let (x_span, h_span) = (self.x_span(), self.h_span());
            let fixed = if along_x {
                let sx = t.0.signum();
                let Some(grid) = self.next_grid(p.x, sx) else {
                    break;
                };
                let mut x1 = p.x + sx * ds * x_span;
                if (x1 - grid) * sx >= -1e-9 * x_span {
                    x1 = grid;
                }
                Fixed::X(x1)
            } else {
                let h1 = p.h + t.1.signum() * ds * h_span;
                if !(self.h_range.0..=self.h_range.1).contains(&h1) {
                    break;
                }
                Fixed::H(h1)
            };
            // The secant prediction.
            let pred = match (fixed, tangent) {
                (Fixed::X(x1), Some(t)) => (x1, p.h + t.1 / t.0 * (x1 - p.x) / x_span * h_span),
                (Fixed::X(x1), None) => (x1, p.h),
                (Fixed::H(h1), Some(t)) => (p.x + t.0 / t.1 * (h1 - p.h) / h_span * x_span, h1),
                (Fixed::H(h1), None) => (p.x, h1),
            };
            let found = match fixed {
                Fixed::X(x1) => self.step_in_x(kind, &p, x1, pred.1, window * h_span)?,
                Fixed::H(h1) => self.step_in_h(kind, &p, h1, pred.0, window * x_span)?,
            };
            let used = {
                let (a, b) = (self.scaled(p.x, p.h), self.scaled(pred.0, pred.1));
                ((b.0 - a.0).powi(2) + (b.1 - a.1).powi(2)).sqrt()
            };
            match found {
                Some(q) => {
                    let (a, b, c) = (
                        self.scaled(p.x, p.h),
                        self.scaled(q.x, q.h),
                        self.scaled(pred.0, pred.1),
                    );
                    let err = ((b.0 - c.0).powi(2) + (b.1 - c.1).powi(2)).sqrt();
                    let chord = (b.0 - a.0, b.1 - a.1);
                    let len = (chord.0 * chord.0 + chord.1 * chord.1).sqrt();
                    if len.is_nan() || len <= 0.0 {
                        break;
                    }
                    ds = match tangent {
                        Some(_) => {
                            used.max(ds_min) * (tol / err.max(1e-300)).sqrt().clamp(0.3, 2.0)
                        }
                        None => ds,
                    }
                    .clamp(ds_min, ds_max);
                    // The next window: a few times this prediction's error, within the widest.
                    window = (4.0 * err).max(5e-3).min(self.join_tol);
                    tangent = Some((chord.0 / len, chord.1 / len));
                    out.push(q.clone());
                    p = q;
                }
                None => {
                    ds /= 2.0;
                    window = self.join_tol;
                    if ds < ds_min {
                        break;
                    }
                }
            }
        }
        Ok(out)
    }

    /// The steady motion at `x` near the one at `p`, with the model.
    fn steady_at(&self, p: &Point, x: f64) -> Option<(M, f64, SteadyMotion)> {
        let (model, p_psi) = (self.family)(x);
        let s = steady_motion_near(&model, p.steady_gamma, p_psi).ok()?;
        Some((model, p_psi, s))
    }

    /// The options of the local families: the chart's, the nonlinear events only for the
    /// kinds that need them.
    fn local(&self, kind: OrbitEventKind) -> OrbitOptions {
        OrbitOptions {
            nonlinear: matches!(
                kind,
                OrbitEventKind::ThirdOrderResonance
                    | OrbitEventKind::FourthOrderResonance
                    | OrbitEventKind::TwistDegenerate
            ),
            control: self.opts.control.cancel_only(),
            ..self.opts.clone()
        }
    }

    /// The event of `kind` at `x1` nearest `h_pred` (`None`: none found, or the steady motion,
    /// the anchor or the family failed there).
    fn step_in_x(
        &self,
        kind: OrbitEventKind,
        p: &Point,
        x1: f64,
        h_pred: f64,
        window: f64,
    ) -> Result<Option<Point>, RouthError> {
        let Some((model, p_psi, s)) = self.steady_at(p, x1) else {
            return Ok(None);
        };
        let h_anchor = p.anchor_h + (h_pred - p.h);
        let lo = (h_pred.min(h_anchor) - window).max(self.h_range.0);
        let hi = (h_pred.max(h_anchor) + window).min(self.h_range.1);
        if !(lo < hi && lo <= h_anchor && h_anchor <= hi) {
            return Ok(None);
        }
        let local = self.local(kind);
        let Some(anchor) = soft(orbit_near(
            &model,
            &p.anchor,
            s.energy + h_anchor,
            p_psi,
            &local,
        ))?
        .flatten() else {
            return Ok(None);
        };
        let Some(fam) = soft(continue_orbit(
            &model,
            &anchor,
            (s.energy + lo, s.energy + hi),
            &local,
        ))?
        else {
            return Ok(None);
        };
        let target = s.energy + h_pred;
        let Some(ev) = nearest(
            fam.events.iter().filter(|e| e.kind == kind),
            |e| e.energy,
            target,
        ) else {
            return Ok(None);
        };
        let Some((_, anchor)) = anchor_of(&fam, ev) else {
            return Ok(None);
        };
        Ok(Some(Point {
            x: x1,
            h: ev.energy - s.energy,
            steady_gamma: s.gamma,
            anchor_h: anchor.energy - s.energy,
            anchor,
        }))
    }

    /// The event of `kind` at `h = h1` nearest `x_pred`, located along the family in the
    /// parameter at the energy `Eₛ(x_pred) + h1` (`None`: none found, or a failure there).
    fn step_in_h(
        &self,
        kind: OrbitEventKind,
        p: &Point,
        h1: f64,
        x_pred: f64,
        window: f64,
    ) -> Result<Option<Point>, RouthError> {
        let (x_lo, x_hi) = (self.xs[0], self.xs[self.xs.len() - 1]);
        if !(x_lo..=x_hi).contains(&x_pred) {
            return Ok(None);
        }
        let Some((model, p_psi, s)) = self.steady_at(p, x_pred) else {
            return Ok(None);
        };
        let energy = s.energy + h1;
        let local = self.local(kind);
        let guess_e = s.energy + p.anchor_h + (h1 - p.h);
        // The anchor at the predicted x, then moved to the fixed energy (it may sit next to
        // the event: corrected first where it is regular).
        let Some(anchor) = soft(orbit_near(&model, &p.anchor, guess_e, p_psi, &local))?.flatten()
        else {
            return Ok(None);
        };
        let Some(anchor) = soft(orbit_near(&model, &anchor, energy, p_psi, &local))?.flatten()
        else {
            return Ok(None);
        };
        let range = ((x_pred - window).max(x_lo), (x_pred + window).min(x_hi));
        if range.0 >= range.1 {
            return Ok(None);
        }
        let Some(fam) = soft(continue_orbit_in(
            self.family,
            &anchor,
            x_pred,
            range,
            &local,
        ))?
        else {
            return Ok(None);
        };
        let events = fam.family.events.iter().zip(&fam.event_parameter);
        let Some((ev, &x_ev)) = nearest(events.filter(|e| e.0.kind == kind), |e| *e.1, x_pred)
        else {
            return Ok(None);
        };
        let Some((j, anchor)) = anchor_of(&fam.family, ev) else {
            return Ok(None);
        };
        let Some((_, _, s_ev)) = self.steady_at(p, x_ev) else {
            return Ok(None);
        };
        let x_anchor = fam.parameter.get(j).copied().unwrap_or(x_ev);
        let es_anchor = self
            .steady_at(p, x_anchor)
            .map_or(s_ev.energy, |t| t.2.energy);
        Ok(Some(Point {
            x: x_ev,
            h: energy - s_ev.energy,
            steady_gamma: s_ev.gamma,
            anchor_h: anchor.energy - es_anchor,
            anchor,
        }))
    }
}

/// The item of `items` whose `key` is nearest `target`.
fn nearest<T>(items: impl Iterator<Item = T>, key: impl Fn(&T) -> f64, target: f64) -> Option<T> {
    items.min_by(|a, b| (key(a) - target).abs().total_cmp(&(key(b) - target).abs()))
}

/// A local computation's result, its failure `None` (the step fails) except a cancellation.
fn soft<T>(r: Result<T, RouthError>) -> Result<Option<T>, RouthError> {
    match r {
        Ok(v) => Ok(Some(v)),
        Err(RouthError::Interrupted) => Err(RouthError::Interrupted),
        Err(_) => Ok(None),
    }
}
