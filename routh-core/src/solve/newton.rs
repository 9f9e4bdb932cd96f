//! The one Newton corrector of routh-core (docs/method.md §5, docs/architecture.md "Engines"):
//! the search's damped Newton on the sphere, the continuation's pseudo-arclength
//! corrector, the atlas grid's Newton at a fixed member and the atlas curves' Gauss–Newton are all
//! [`Newton::solve`] with different [`Newton`] settings.
//!
//! The unknowns are `w ∈ ℝ⁴`: the chart coordinates `ξ₁, ξ₂` of γ on the sphere, then up to two
//! parameters (unused trailing entries stay 0). The caller evaluates its equations at an iterate
//! and returns them [`Linearised`] (residual rows scaled by the local tangential scale, their
//! Jacobian, the round-off floor); the engine adds up to two [`LinearRow`]s `n·w = c`, solves for
//! the minimum-norm step (SVD of the fixed 4×4, singular values below a relative cut dropped, no
//! allocation; closed form when the Jacobian is a symmetric 2×2), optionally damps it
//! (Levenberg–Marquardt, a step accepted only if it decreases the residual) and stops by one rule:
//!
//! - converged when every linear row is within [`ROW_TOL`] and the residual is within
//!   [`Newton::tol`] — never below the caller's round-off floor ([`ZeroTest::with_floor`]) — or
//!   within [`Newton::loose_tol`] once the iteration no longer gains at that scale (the last step
//!   at round-off, [`ROUND_STEP`], or the previous residual already within `loose_tol`: linear
//!   convergence at a degenerate point, or a residual at its round-off plateau);
//! - otherwise a [`Stop`] that says why, with the last iterate and the best residual reached.

use nalgebra::{Matrix4, Vector2, Vector4};

use crate::solve::norm::stable_norm;
use crate::solve::path::row::LinearRow;
use crate::solve::zero::ZeroTest;

/// A linear row `n·w = c` is satisfied when `|n·w − c|` is at most this.
pub(crate) const ROW_TOL: f64 = 1e-13;
/// A step this short is at round-off: the looser tolerance applies.
pub(crate) const ROUND_STEP: f64 = 1e-13;
/// Largest number of Levenberg–Marquardt retries (λ growing tenfold) within one iteration.
const MAX_LM_RETRIES: usize = 14;
/// The relative cut of the atlas (singular values below it relative to the largest are zero).
const ATLAS_CUT: f64 = 1e-10;
/// The relative cut of the continuation's corrector.
const CONTINUATION_CUT: f64 = 1e-12;

/// The settings of one corrector. Named constructors give those of the four users.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Newton {
    /// Largest number of steps (the residual is tested `max_iter + 1` times).
    pub max_iter: usize,
    /// Longest step `|Δw|`: without damping a longer step stops the iteration
    /// ([`Why::StepTooLong`]); with damping it is shortened to this length.
    pub max_step: f64,
    /// Converged when the residual is at most this (and the linear rows within [`ROW_TOL`]).
    pub tol: f64,
    /// … or at most this once the iteration no longer gains (see the module docs).
    pub loose_tol: f64,
    /// Singular values of the Jacobian at most `cut` times the largest (or at most
    /// [`Linearised::zero`]) are zero: the step has no component along them.
    pub cut: f64,
    /// Levenberg–Marquardt damping with accept-only-if-the-residual-decreases (the global search,
    /// from far away); without it, plain minimum-norm Gauss–Newton steps (local correctors).
    pub damping: bool,
}

impl Newton {
    /// The search of steady motions (`Search::refine`): damped, steps shortened to 0.5 rad, the
    /// residual being the length of the Newton step (rad), converged at `gradient_tol / 100` or at
    /// `gradient_tol` once convergence is only linear (a degenerate critical point).
    pub(crate) fn search(max_iter: usize, gradient_tol: f64) -> Self {
        Newton {
            max_iter,
            max_step: 0.5,
            tol: 1e-2 * gradient_tol,
            loose_tol: gradient_tol,
            cut: 0.0,
            damping: true,
        }
    }

    /// The continuation's corrector (`families::continuation::Ctx::correct`): 15 steps (16
    /// evaluations, `CORRECTOR_MAX_ITER`), the
    /// residual `|F|/scale` within `newton_tol`, or `100·newton_tol` once the steps are at
    /// round-off. The chart bound `|ξ| ≤ 0.5` is the caller's (its evaluation refuses beyond).
    pub(crate) fn continuation(newton_tol: f64) -> Self {
        Newton {
            max_iter: 15,
            max_step: f64::INFINITY,
            tol: newton_tol,
            loose_tol: 100.0 * newton_tol,
            cut: CONTINUATION_CUT,
            damping: false,
        }
    }

    /// The atlas grid's Newton at a fixed member: polished to `1e−14`, accepted at `1e−11` one
    /// step later; steps of at most 0.5 rad; 11 steps.
    pub(crate) fn grid() -> Self {
        Newton {
            max_iter: 11,
            max_step: 0.5,
            tol: 1e-14,
            loose_tol: 1e-11,
            cut: ATLAS_CUT,
            damping: false,
        }
    }

    /// The atlas curves' Gauss–Newton on `(ξ, u, v)`: converged at `curve_tol / 100`, or at
    /// `curve_tol` once the steps are at round-off; corrections of at most 0.25; 10 steps.
    pub(crate) fn curve(curve_tol: f64) -> Self {
        Newton {
            max_iter: 10,
            max_step: 0.25,
            tol: 1e-2 * curve_tol,
            loose_tol: curve_tol,
            cut: ATLAS_CUT,
            damping: false,
        }
    }
}

/// The Jacobian of the residual rows with respect to `w`.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Jacobian {
    /// A 4×4 matrix (unused rows and columns zero).
    General(Matrix4<f64>),
    /// A symmetric 2×2 matrix (rows and unknowns 0 and 1) by its eigen-decomposition: the
    /// restricted second variation `K` (62)–(63) of the search, where the residual is the
    /// Riemannian gradient. Solved in closed form.
    Symmetric2 {
        values: [f64; 2],
        vectors: [Vector2<f64>; 2],
    },
}

impl Jacobian {
    fn matrix(&self) -> Matrix4<f64> {
        match self {
            Jacobian::General(m) => *m,
            Jacobian::Symmetric2 { values, vectors } => {
                let mut m = Matrix4::zeros();
                for (k, v) in values.iter().zip(vectors) {
                    for (i, j) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
                        m[(i, j)] += k * v[i] * v[j];
                    }
                }
                m
            }
        }
    }
}

/// The caller's equations at one iterate.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Linearised {
    /// The residual rows `F(w)`, relative to the local scale (unused rows 0; the last
    /// `rows.len()` rows are left to the [`LinearRow`]s).
    pub rows: Vector4<f64>,
    /// `∂F/∂w`.
    pub jac: Jacobian,
    /// The round-off of `rows` (same units): with damping, a component of the residual along a
    /// zero singular value within it is noise and is not corrected (it would slide along a curve
    /// of solutions).
    pub noise: f64,
    /// Singular values of the Jacobian at most this are zero (the caller's zero test).
    pub zero: f64,
    /// The residual compared with [`Newton::tol`]: `|rows|` by default, or the caller's distance
    /// to the solution (the search: the length of the Newton step on the sphere).
    pub residual: f64,
    /// The round-off floor of `residual`: the tolerances are never below it.
    pub floor: f64,
}

impl Linearised {
    /// Rows and Jacobian with round-off floor `floor` (of the rows and of the residual `|rows|`).
    pub(crate) fn new(rows: Vector4<f64>, jac: Matrix4<f64>, floor: f64) -> Self {
        Linearised {
            rows,
            jac: Jacobian::General(jac),
            noise: floor,
            zero: 0.0,
            residual: norm4(&rows),
            floor,
        }
    }
}

/// A converged iterate.
#[derive(Debug, Clone)]
pub(crate) struct Solved<P> {
    /// The caller's point there.
    pub point: P,
    /// The unknowns there.
    pub w: Vector4<f64>,
    /// Steps taken.
    pub iterations: usize,
}

/// Why the corrector stopped short of convergence.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Why {
    /// Without damping, a step longer than [`Newton::max_step`] (the iteration diverges).
    StepTooLong,
    /// Every direction that would reduce the residual has a zero singular value.
    Singular,
    /// A non-finite residual, Jacobian or step, or the caller refused the next iterate.
    NonFinite,
    /// [`Newton::max_iter`] steps without convergence.
    MaxIterations,
    /// With damping, no step decreased the residual (a local minimum of `|F|`).
    NoDecrease,
    /// The caller's hook stopped the iteration (the search's early capture).
    Interrupted,
}

/// The end of an iteration that did not converge.
#[derive(Debug, Clone)]
pub(crate) struct Stop<P> {
    pub why: Why,
    /// The last accepted iterate.
    pub last: P,
    /// The smallest [`Linearised::residual`] of every iterate evaluated.
    pub best_residual: f64,
}

impl Newton {
    /// Newton's method from the evaluated iterate `start` at unknowns `w0`, with the linear `rows`
    /// (at most two). `lin` gives the equations at an iterate; `next(p, w, d)` evaluates the
    /// iterate at `w = w(p) + d` (`Ok(None)` where it cannot: outside the chart, non-finite);
    /// `interrupt(p)` is asked before every step and stops the iteration when it returns `true`.
    /// Errors of `next` are returned as they are.
    #[inline]
    pub(crate) fn solve<P, E>(
        &self,
        w0: Vector4<f64>,
        rows: &[LinearRow<4>],
        start: P,
        lin: impl Fn(&P) -> Linearised,
        mut next: impl FnMut(&P, &Vector4<f64>, &Vector4<f64>) -> Result<Option<P>, E>,
        mut interrupt: impl FnMut(&P) -> bool,
    ) -> Result<Result<Solved<P>, Stop<P>>, E> {
        let rows = &rows[..rows.len().min(2)];
        let mut w = w0;
        let mut cur = start;
        let mut l = lin(&cur);
        let mut best = l.residual;
        let mut prev = f64::INFINITY;
        let mut last_step = f64::INFINITY;
        let mut lambda = 0.0f64;
        let stop = |why, last, best| {
            Ok(Err(Stop {
                why,
                last,
                best_residual: best,
            }))
        };
        for it in 0..=self.max_iter {
            if !(l.residual.is_finite() && l.rows.iter().all(|v| v.is_finite())) {
                return stop(Why::NonFinite, cur, best);
            }
            let mut rhs = l.rows;
            let first = 4 - rows.len();
            for (k, r) in rows.iter().enumerate() {
                rhs[first + k] = r.residual(&w);
            }
            if self.converged(&l, &rhs, first, prev, last_step) {
                return Ok(Ok(Solved {
                    point: cur,
                    w,
                    iterations: it,
                }));
            }
            if it == self.max_iter {
                return stop(Why::MaxIterations, cur, best);
            }
            if interrupt(&cur) {
                return stop(Why::Interrupted, cur, best);
            }
            prev = l.residual;
            let Some(sys) = System::new(&l, rows, rhs, self.cut) else {
                return stop(Why::NonFinite, cur, best);
            };
            if !self.damping {
                let d = sys.step(0.0, None);
                last_step = d.norm();
                if !last_step.is_finite() {
                    return stop(Why::NonFinite, cur, best);
                }
                if last_step == 0.0 {
                    return stop(Why::Singular, cur, best);
                }
                if last_step > self.max_step {
                    return stop(Why::StepTooLong, cur, best);
                }
                match next(&cur, &(w + d), &d)? {
                    Some(n) => {
                        w += d;
                        cur = n;
                        l = lin(&cur);
                        best = best.min(l.residual);
                    }
                    None => return stop(Why::NonFinite, cur, best),
                }
                continue;
            }
            // Levenberg–Marquardt: λ relative to the square of the largest singular value (the
            // system is solved in units of it, so that J² neither overflows nor underflows).
            let norm = norm4(&l.rows);
            let tries = if norm <= l.noise { 1 } else { MAX_LM_RETRIES };
            let smax2: f64 = if sys.smax > 0.0 { 1.0 } else { 0.0 };
            let lambda_min = (l.zero / sys.unit).powi(2);
            let (mut accepted, mut any) = (false, false);
            for _ in 0..tries {
                let mut d = sys.step(lambda, Some(l.noise));
                let len = d.norm();
                if len.is_finite() && len > 0.0 {
                    any = true;
                    if len > self.max_step {
                        d *= self.max_step / len;
                    }
                    if let Some(n) = next(&cur, &(w + d), &d)? {
                        let ln = lin(&n);
                        if norm4(&ln.rows) < norm {
                            best = best.min(ln.residual);
                            last_step = d.norm();
                            (w, cur, l, accepted) = (w + d, n, ln, true);
                            break;
                        }
                    }
                }
                let grown = if lambda == 0.0 {
                    (1e-6 * smax2).max(lambda_min)
                } else {
                    lambda * 10.0
                };
                if grown <= lambda || !grown.is_finite() {
                    break;
                }
                lambda = grown;
            }
            if !accepted {
                let why = if any { Why::NoDecrease } else { Why::Singular };
                return stop(why, cur, best);
            }
            lambda = if lambda <= 1e-6 * smax2 {
                0.0
            } else {
                lambda / 10.0
            };
        }
        stop(Why::MaxIterations, cur, best)
    }

    /// The one convergence rule (module docs); `rhs[first..]` are the linear rows' residuals.
    #[inline(always)]
    fn converged(
        &self,
        l: &Linearised,
        rhs: &Vector4<f64>,
        first: usize,
        prev: f64,
        last_step: f64,
    ) -> bool {
        if rhs.iter().skip(first).any(|r| r.abs() > ROW_TOL) {
            return false;
        }
        let tight = ZeroTest::with_floor(self.tol, 1.0, l.floor);
        let loose = ZeroTest::with_floor(self.loose_tol, 1.0, l.floor);
        tight.is_zero(l.residual)
            || (loose.is_zero(l.residual) && (last_step <= ROUND_STEP || loose.is_zero(prev)))
    }
}

/// The linear system of one step: the first `n` singular triplets of the Jacobian (with the
/// linear rows), in units of its largest singular value.
struct System {
    n: usize,
    /// Singular values / `unit` (signed eigenvalues for [`Jacobian::Symmetric2`]).
    s: [f64; 4],
    /// Components of the right-hand side along the left singular vectors, / `unit`.
    c: [f64; 4],
    /// Right singular vectors.
    v: [Vector4<f64>; 4],
    /// Singular values at most this (/ `unit`) are zero.
    cut: f64,
    /// The largest singular value / `unit` (1, or 0 for a zero Jacobian).
    smax: f64,
    unit: f64,
}

impl System {
    /// `None` when the Jacobian or the right-hand side is not finite.
    #[inline(always)]
    fn new(l: &Linearised, rows: &[LinearRow<4>], rhs: Vector4<f64>, cut: f64) -> Option<System> {
        if !rhs.iter().all(|v| v.is_finite()) {
            return None;
        }
        match (&l.jac, rows.is_empty()) {
            (Jacobian::Symmetric2 { values, vectors }, true) => {
                let kmax = values[0].abs().max(values[1].abs());
                if !kmax.is_finite() {
                    return None;
                }
                let unit = if kmax > 0.0 { kmax } else { 1.0 };
                let r = Vector2::new(rhs[0], rhs[1]);
                let pad = |x: &Vector2<f64>| Vector4::new(x.x, x.y, 0.0, 0.0);
                // u = sign(k)·v: the sign goes with the value, so that s·c = k·(v·r).
                Some(System {
                    n: 2,
                    s: [values[0] / unit, values[1] / unit, 0.0, 0.0],
                    c: [
                        vectors[0].dot(&r) / unit,
                        vectors[1].dot(&r) / unit,
                        0.0,
                        0.0,
                    ],
                    v: [
                        pad(&vectors[0]),
                        pad(&vectors[1]),
                        Vector4::zeros(),
                        Vector4::zeros(),
                    ],
                    cut: (cut * kmax).max(l.zero) / unit,
                    smax: kmax / unit,
                    unit,
                })
            }
            _ => Self::general(l, rows, rhs, cut),
        }
    }

    /// The SVD of the padded 4×4 (rows of the caller, then the linear rows).
    fn general(
        l: &Linearised,
        rows: &[LinearRow<4>],
        rhs: Vector4<f64>,
        cut: f64,
    ) -> Option<System> {
        let mut m = l.jac.matrix();
        let first = 4 - rows.len();
        for (k, r) in rows.iter().enumerate() {
            m.set_row(first + k, &r.normal.transpose());
        }
        let a = m.amax();
        if !a.is_finite() {
            return None;
        }
        let scale = if a > 0.0 { a } else { 1.0 };
        let svd = (m / scale).svd(true, true);
        let (u, vt) = (svd.u?, svd.v_t?);
        let sv = svd.singular_values;
        let smax = sv.max();
        let unit = if smax > 0.0 { smax * scale } else { scale };
        let r = rhs / unit;
        let mut out = System {
            n: 4,
            s: [0.0; 4],
            c: [0.0; 4],
            v: [Vector4::zeros(); 4],
            cut: (cut * smax * scale).max(l.zero) / unit,
            smax: smax * scale / unit,
            unit,
        };
        for i in 0..4 {
            out.s[i] = sv[i] * scale / unit;
            out.c[i] = u.column(i).dot(&r);
            out.v[i] = vt.row(i).transpose();
        }
        Some(out)
    }

    /// The step `−(JᵀJ + λ)⁺Jᵀr` (λ relative to `unit²`). A direction whose singular value is
    /// below the cut is dropped — with `noise` (damped steps), only when the residual's
    /// component along it is within the noise (a component above it is corrected, damped).
    #[inline(always)]
    fn step(&self, lambda: f64, noise: Option<f64>) -> Vector4<f64> {
        let mut d = Vector4::zeros();
        for i in 0..self.n {
            let (s, c) = (self.s[i], self.c[i]);
            if s.abs() <= self.cut && noise.is_none_or(|n| (c * self.unit).abs() <= n) {
                continue;
            }
            let den = s * s + lambda;
            if den > 0.0 {
                d -= (s * c / den) * self.v[i];
            }
        }
        d
    }
}

/// `|x|` of a 4-vector without overflow or underflow, and without the cost of scaling when none
/// is possible.
#[inline(always)]
pub(crate) fn norm4(x: &Vector4<f64>) -> f64 {
    let s = x.norm_squared();
    if s.is_normal() || s == 0.0 && x.iter().all(|v| *v == 0.0) {
        s.sqrt()
    } else {
        stable_norm(x.as_slice())
    }
}

#[cfg(test)]
mod tests;
