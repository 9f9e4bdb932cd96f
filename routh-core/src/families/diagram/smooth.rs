//! Smooth energy curves: after continuation, corrected points are inserted on each branch where
//! its curve `(s, E)` turns too fast to be drawn as a polyline. The points come from the
//! branch's own corrector ([`Ctx::correct`]); only where they go is decided here, by the
//! curvature of the curve, not by the continuation step.

use nalgebra::Vector4;

use super::builder::Builder;
use crate::error::RouthError;
use crate::families::continuation::{meridian_normal, Ctx, Node};
use crate::model::Routhian;
use crate::solve::path::row::LinearRow;

/// Shortest chord that is still split, in plot-normalised coordinates (`s` over the range, `E`
/// over its extent on the diagram): about a fifth of a pixel on a 900-pixel figure.
pub(super) const MIN_CHORD: f64 = 2e-4;
/// Rounds of bisection: a chord is split at most this many times.
const MAX_ROUNDS: usize = 12;

/// The turning angle (radians, in `[0, π]`) between the chords `u` and `v`; `0` when one of them
/// is zero.
fn turn(u: (f64, f64), v: (f64, f64)) -> f64 {
    let cross = u.0 * v.1 - u.1 * v.0;
    let dot = u.0 * v.0 + u.1 * v.1;
    if cross == 0.0 && dot == 0.0 {
        0.0
    } else {
        cross.abs().atan2(dot)
    }
}

/// Whether node `k` (interior) is a turning point in `s`: the energy curve has a cusp there (at
/// a fold `dE/ds` is the same on both sides), where no refinement straightens it.
fn cusp(nodes: &[Node], k: usize) -> bool {
    (nodes[k].s - nodes[k - 1].s) * (nodes[k + 1].s - nodes[k].s) <= 0.0
}

impl<M: Routhian, F: Fn(f64) -> (M, f64)> Ctx<'_, M, F> {
    /// The point of the branch halfway between the consecutive points `a` and `b`: predicted by
    /// the cubic Hermite midpoint in `(γ, σ)` (tangents oriented along the chord), corrected on
    /// the hyperplane through it orthogonal to the chord. `Ok(None)` when the corrector fails or
    /// lands off the arc between them: farther than a quarter of the chord from the prediction,
    /// outside their range of `s`, with its tangent across the chord (another branch crossing
    /// the segment, as at a pitchfork's tip), or with a verdict that is neither `a`'s nor `b`'s.
    pub(super) fn between(&self, a: &Node, b: &Node) -> Result<Option<Node>, RouthError> {
        let len = self.len;
        let (dg, ds) = (b.gamma - a.gamma, (b.s - a.s) / len);
        let l = (dg.norm_squared() + ds * ds).sqrt();
        if l.is_nan() || l <= 0.0 {
            return Ok(None);
        }
        let orient = |n: &Node| {
            let c = (n.tau_g.dot(&dg) + n.tau_s * ds) / l;
            if c >= 0.0 {
                (n.tau_g, n.tau_s, c)
            } else {
                (-n.tau_g, -n.tau_s, -c)
            }
        };
        let (ta_g, ta_s, ca) = orient(a);
        let (tb_g, tb_s, cb) = orient(b);
        let mut g_p = 0.5 * (a.gamma + b.gamma);
        let mut s_p = 0.5 * (a.s + b.s) / len;
        if ca >= 0.7 && cb >= 0.7 {
            g_p += 0.125 * l * (ta_g - tb_g);
            s_p += 0.125 * l * (ta_s - tb_s);
        }
        let g_p = g_p.normalize();
        let a_g = dg / l;
        let row = LinearRow::new(Vector4::new(a_g.x, a_g.y, a_g.z, ds / l), 0.0);
        let circle = meridian_normal(&g_p, &ta_g);
        let Some((g, s, _)) = self.correct(&g_p, s_p, &row, circle)? else {
            return Ok(None);
        };
        let moved = ((g - g_p).norm_squared() + (s / len - s_p).powi(2)).sqrt();
        let slack = 1e-12 * len;
        if moved > 0.25 * l || s < a.s.min(b.s) - slack || s > a.s.max(b.s) + slack {
            return Ok(None);
        }
        let Some(n) = self.node(&g, s, Some((&ta_g, ta_s)))? else {
            return Ok(None);
        };
        let along = (n.tau_g.dot(&dg) + n.tau_s * ds) / l;
        if along < 0.5 || (n.verdict() != a.verdict() && n.verdict() != b.verdict()) {
            return Ok(None);
        }
        Ok(Some(n))
    }
}

/// Splits, round by round, the chords next to every node of `nodes` (but the cusps) where the
/// curve `(s/xs, E/ys)` turns by more than `max_turn`, down to chords of [`MIN_CHORD`].
fn refine<M: Routhian, F: Fn(f64) -> (M, f64)>(
    ctx: &Ctx<'_, M, F>,
    mut nodes: Vec<Node>,
    xs: f64,
    ys: f64,
    max_turn: f64,
) -> Result<Vec<Node>, RouthError> {
    // frozen[k]: the chord (k, k + 1) could not be split.
    let mut frozen = vec![false; nodes.len()];
    for _ in 0..MAX_ROUNDS {
        let q: Vec<(f64, f64)> = nodes
            .iter()
            .map(|n| (n.s / xs, n.point.steady.energy / ys))
            .collect();
        let chord = |k: usize| (q[k + 1].0 - q[k].0, q[k + 1].1 - q[k].1);
        let long = |k: usize| {
            let c = chord(k);
            c.0.hypot(c.1) > MIN_CHORD
        };
        let mut split = vec![false; nodes.len()];
        for k in 1..nodes.len().saturating_sub(1) {
            if cusp(&nodes, k) || turn(chord(k - 1), chord(k)) <= max_turn {
                continue;
            }
            for j in [k - 1, k] {
                split[j] |= !frozen[j] && long(j);
            }
        }
        if !split.iter().any(|s| *s) {
            break;
        }
        let mut next = Vec::with_capacity(2 * nodes.len());
        let mut next_frozen = Vec::with_capacity(2 * nodes.len());
        for k in 0..nodes.len() {
            next.push(nodes[k].clone());
            next_frozen.push(frozen[k]);
            if split[k] {
                match ctx.between(&nodes[k], &nodes[k + 1])? {
                    Some(m) => {
                        next.push(m);
                        next_frozen.push(false);
                    }
                    None => {
                        if let Some(f) = next_frozen.last_mut() {
                            *f = true;
                        }
                    }
                }
            }
        }
        nodes = next;
        frozen = next_frozen;
    }
    Ok(nodes)
}

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Builder<'a, M, F> {
    /// Inserts corrected points on every branch where its energy curve `(s, E)`, in
    /// plot-normalised coordinates (`s` over the range, `E` over its extent on the diagram),
    /// turns by more than [`ContinuationOptions::em_turn_degrees`] between successive chords,
    /// except at the cusps of the curve (its turning points in `s`), down to chords of
    /// [`MIN_CHORD`]. Off when the option is `0`, and on a diagram that stopped early (a budget
    /// ran out: its branches stay as traced, within the budget of steps).
    ///
    /// [`ContinuationOptions::em_turn_degrees`]: crate::ContinuationOptions::em_turn_degrees
    ///
    /// Errors: those of the family and the model at the new points.
    pub(super) fn smooth(&mut self) -> Result<(), RouthError> {
        let max_turn = self.opts.em_turn_degrees.to_radians();
        if max_turn.is_nan() || max_turn <= 0.0 || self.stop.is_some() {
            return Ok(());
        }
        let energies = self
            .branches
            .iter()
            .flat_map(|(nodes, _)| nodes.iter().map(|n| n.point.steady.energy))
            .filter(|e| e.is_finite());
        let (lo, hi) = energies.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
            (lo.min(e), hi.max(e))
        });
        let ys = if hi > lo { hi - lo } else { 1.0 };
        let xs = self.len();
        let branches = std::mem::take(&mut self.branches);
        let mut out = Vec::with_capacity(branches.len());
        for (nodes, isolated) in branches {
            if nodes.len() < 3 {
                out.push((nodes, isolated));
                continue;
            }
            let ctx = self.ctx(isolated, self.scale_at(&nodes[0].gamma, nodes[0].s)?);
            out.push((refine(&ctx, nodes, xs, ys, max_turn)?, isolated));
        }
        self.branches = out;
        Ok(())
    }
}
