//! The shooting corrector of periodic orbits and [`periodic_orbit`] (docs/method.md §11).
//!
//! Unknowns `w = (x₀, T/t_s, E/e_s, Δφ) ∈ ℝ⁹` (`t_s`, `e_s` scales of the family, so that a
//! pseudo-arclength in `w` weighs the period and the energy like the state; `Δφ` the body turn
//! of an axially symmetric body, docs/method.md §11a). Along a family in a parameter
//! ([`Slot::Parameter`]) the eighth unknown is the parameter `s/s_s` instead, the energy row holds
//! the family's fixed energy and the momentum row its `p_ψ(s)` (docs/method.md §11, "Families in
//! a parameter"). Rows: `S_Δφ φ_T(x₀) − x₀` (6), the phase
//! `F̂_ref·(x₀ − x_ref)`, `E(x₀) − E`, `p_ψ(x₀) − p_ψ`, `(|γ₀|² − 1)/2` (the gradient rows scaled
//! to unit length), the gauge `ξ̂_ref·(x₀ − x_ref)` and `p_φ(x₀) − p_φ` on an axially symmetric
//! body (else `Δφ = 0` and an empty row), and one linear row (the energy fixed, or the
//! continuation's). The 13 × 9 system is consistent and of full column rank at a regular
//! orbit; each step is its minimum-norm least-squares solution (SVD, singular values below
//! `1e−12` of the largest dropped), the step in `T` limited to a third of the period.
//!
//! This is a second Newton next to the sphere's fixed-size 4 × 4 one (`solve::newton`), kept
//! apart deliberately: its unknowns are eight, its residual is a flow, and its stop rule is on
//! the flow's integration tolerance (docs/architecture.md).

use std::ops::Deref;

use nalgebra::{SMatrix, SVector, Vector3, Vector6};

use super::flow::{field, flow_end, integrals, join, onto_level, precession, shoot, split, Shot};
use super::symmetry::{self, Turn};
use super::{OrbitOptions, OrbitStability, PeriodicOrbit};
use crate::sim::dop853::{self, Accepted, Config};
use crate::solve::locate::{estimated_distance, illinois, End};
use crate::solve::path::row::LinearRow;
use crate::validate::{check_finite, unit_gamma};
use crate::{Lagrangian, RouthError};

/// The number of unknowns, `w = (x₀, T/t_s, E/e_s, Δφ)`.
pub(crate) const UNKNOWNS: usize = 9;
/// The rows without the linear row (the family's tangent is their null vector).
pub(crate) const TOP: usize = 12;
pub(crate) type W = SVector<f64, UNKNOWNS>;
type Jac = SMatrix<f64, { TOP + 1 }, UNKNOWNS>;
/// The index of the body turn `Δφ` in `w`.
pub(crate) const TURN: usize = 8;

/// The scales of the period and of the eighth unknown (the energy, or the parameter of a
/// [`Slot::Parameter`] family) in the unknowns.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Scales {
    pub t: f64,
    pub e: f64,
}

impl Scales {
    pub fn pack(&self, x: &Vector6<f64>, t: f64, e: f64) -> W {
        let mut w = W::zeros();
        w.fixed_rows_mut::<6>(0).copy_from(x);
        w[6] = t / self.t;
        w[7] = e / self.e;
        w
    }
    /// As [`Scales::pack`] with the body turn `Δφ` (docs/method.md §11a).
    pub fn pack_turned(&self, x: &Vector6<f64>, t: f64, e: f64, body_turn: f64) -> W {
        let mut w = self.pack(x, t, e);
        w[TURN] = body_turn;
        w
    }
    pub fn period(&self, w: &W) -> f64 {
        w[6] * self.t
    }
    pub fn energy(&self, w: &W) -> f64 {
        w[7] * self.e
    }
    /// The parameter `s = w₇·s_s` of a [`Slot::Parameter`] family (the same unknown as the
    /// energy of [`Scales::energy`]).
    pub fn parameter(&self, w: &W) -> f64 {
        w[7] * self.e
    }
    /// The linear row closing the system with the energy fixed at `e`: `w₇ = e/e_s` (or the
    /// continuation's pseudo-arclength row, [`LinearRow::through`]).
    pub fn energy_row(&self, e: f64) -> LinearRow<UNKNOWNS> {
        LinearRow::fixed(7, e / self.e)
    }
}

/// What the eighth unknown `w₇` is, and where the model of a point `w` comes from.
pub(crate) enum Slot<'a, M> {
    /// The energy `E = w₇·e_s` of one model (`p_ψ` the problem's): the families through the
    /// energy and [`periodic_orbit`].
    Energy(&'a M),
    /// The parameter `s = w₇·s_s` of a family `s ↦ (model, p_ψ)` at the fixed energy `energy`
    /// (docs/method.md §11, "Families in a parameter"): the energy row holds `E(x₀; model(s))`
    /// at `energy`, the momentum row `p_ψ(x₀; model(s))` at `p_ψ(s)`, and the column of `s` is
    /// a central difference of the residual in `s`.
    Parameter {
        family: &'a dyn Fn(f64) -> (M, f64),
        energy: f64,
    },
}

impl<M> Clone for Slot<'_, M> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<M> Copy for Slot<'_, M> {}

/// A model: the slot's own, or a member of the family made at a parameter value.
pub(crate) enum Member<'a, M> {
    Borrowed(&'a M),
    Owned(M),
}

impl<M> Deref for Member<'_, M> {
    type Target = M;
    fn deref(&self) -> &M {
        match self {
            Member::Borrowed(m) => m,
            Member::Owned(m) => m,
        }
    }
}

/// Wraps an error with the parameter value where it happened (as the diagrams do).
pub(crate) fn at_parameter(s: f64, e: RouthError) -> RouthError {
    match e {
        RouthError::AtParameter { .. } => e,
        e => RouthError::AtParameter {
            s,
            source: Box::new(e),
        },
    }
}

/// The member of `family` at `s`: the model and a finite `p_ψ` (else an error at `s`).
pub(crate) fn member_at<M>(
    family: &dyn Fn(f64) -> (M, f64),
    s: f64,
) -> Result<(M, f64), RouthError> {
    let (m, p) = family(s);
    check_finite("p_psi returned by the family", &[p]).map_err(|e| at_parameter(s, e))?;
    Ok((m, p))
}

impl<'a, M> Slot<'a, M> {
    /// The model and `p_ψ` at `w`: the slot's model with `p_psi` (the problem's), or the
    /// family's member at `s = w₇·s_s`.
    pub fn member(
        &self,
        w: &W,
        scales: &Scales,
        p_psi: f64,
    ) -> Result<(Member<'a, M>, f64), RouthError> {
        match *self {
            Slot::Energy(m) => Ok((Member::Borrowed(m), p_psi)),
            Slot::Parameter { family, .. } => {
                let (m, p) = member_at(family, scales.parameter(w))?;
                Ok((Member::Owned(m), p))
            }
        }
    }
}

/// What the corrector needs besides the row: the momentum and the phase condition's plane.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Problem {
    pub p_psi: f64,
    pub x_ref: Vector6<f64>,
    /// `F(x_ref)/|F(x_ref)|`.
    pub f_ref: Vector6<f64>,
    pub scales: Scales,
    /// The gauge and the momentum about `e₃` of an axially symmetric body (`None`: `Δφ = 0`).
    pub turn: Option<Turn>,
    /// The Gauss–Newton step drops the singular values below this fraction of the largest
    /// (1e−12; larger at a branch point, whose second null direction is the crossing family's).
    pub cut: f64,
}

impl Problem {
    /// The phase plane through `x` (an orbit's point, not a steady motion).
    pub fn at<M: Lagrangian + ?Sized>(
        model: &M,
        x: &Vector6<f64>,
        p_psi: f64,
        scales: Scales,
    ) -> Result<Self, RouthError> {
        let f = field(model, x)?;
        Ok(Problem {
            p_psi,
            x_ref: *x,
            f_ref: f / f.norm(),
            scales,
            turn: symmetry::turn_at(model, x)?,
            cut: 1e-12,
        })
    }
}

/// A corrected orbit: the unknowns, the flow over its period and the system's Jacobian there.
#[derive(Clone)]
pub(crate) struct Solved {
    pub w: W,
    pub shot: ShotSummary,
    pub jac: Jac,
    pub iterations: usize,
}

impl Solved {
    /// The rows of the system without the linear row, whose null vector is the family's
    /// tangent.
    pub fn tangent_rows(&self) -> SMatrix<f64, TOP, UNKNOWNS> {
        self.jac.fixed_rows::<TOP>(0).into()
    }
}

/// What is kept of the last integration.
#[derive(Clone)]
pub(crate) struct ShotSummary {
    pub trace: f64,
    pub precession: f64,
    pub reach: f64,
    pub monodromy: nalgebra::Matrix6<f64>,
}

type Residual = SVector<f64, { TOP + 1 }>;

/// The residual and Jacobian of the system at `w`, with the flow and the model there (see
/// [`Slot`]). On an axially symmetric body (`prob.turn`) the shot's monodromy and turn are
/// returned modulo the body turn `β = w₈`: `S_β Φ(T)` and `R(T)·Rot(e₃, −β)` (docs/method.md
/// §11a). Along a family in a parameter the column of `s` is the central difference of the
/// residual between `s ± δ`, `δ = 1e−6·max(1, |s|)`, the models from the family (the family is
/// a closure, not a formula, as for the steady motions' families).
fn linearise<'a, M: Lagrangian>(
    slot: &Slot<'a, M>,
    prob: &Problem,
    row: &LinearRow<UNKNOWNS>,
    w: &W,
    opts: &OrbitOptions,
) -> Result<(Residual, Jac, Shot, Member<'a, M>, f64), RouthError> {
    let t = prob.scales.period(w);
    if !(t.is_finite() && t > 0.0) {
        return Err(RouthError::NoConvergence {
            what: "periodic orbit (the period left (0, ∞))",
            iterations: 0,
            residual: f64::NAN,
        });
    }
    let (model, p) = slot.member(w, &prob.scales, prob.p_psi)?;
    match *slot {
        Slot::Energy(_) => {
            let target = prob.scales.energy(w);
            let (r, j, s) = system(&*model, p, (target, true), prob, row, w, opts)?;
            Ok((r, j, s, model, p))
        }
        Slot::Parameter { family, energy } => {
            let (r, mut j, s) = system(&*model, p, (energy, false), prob, row, w, opts)?;
            let s0 = prob.scales.parameter(w);
            let ds = 1e-6 * s0.abs().max(1.0);
            let (sp, sm) = (s0 + ds, s0 - ds);
            // The sides need the residual only: a state-only integration of the flow (no
            // variational equations, no attitude).
            let x: Vector6<f64> = w.fixed_rows::<6>(0).into();
            let t = prob.scales.period(w);
            let side = |s: f64| -> Result<Residual, RouthError> {
                let (m, p) = member_at(family, s)?;
                let end = flow_end(&m, &x, t, opts)?;
                Ok(residual(&m, p, energy, prob, row, w, &end))
            };
            let (rp, rm) = (side(sp)?, side(sm)?);
            for i in 0..TOP {
                j[(i, 7)] = (rp[i] - rm[i]) / (sp - sm) * prob.scales.e;
            }
            Ok((r, j, s, model, p))
        }
    }
}

/// The rows of the system at `w` for one model at momentum `p_psi` with the energy row at
/// `energy`, from `end = φ_T(x₀)` (the shot's end, or a state-only integration's).
fn residual<M: Lagrangian + ?Sized>(
    model: &M,
    p_psi: f64,
    energy: f64,
    prob: &Problem,
    row: &LinearRow<UNKNOWNS>,
    w: &W,
    end: &Vector6<f64>,
) -> Residual {
    let x: Vector6<f64> = w.fixed_rows::<6>(0).into();
    let (e, de, p, dp) = integrals(model, &x);
    let (_, g) = split(&x);
    let mut r = Residual::zeros();
    // Periodicity modulo the body turn: S_β φ_T(x₀) − x₀; β = 0 without the symmetry.
    let beta = if prob.turn.is_some() { w[TURN] } else { 0.0 };
    let gap = symmetry::act(beta, end) - x;
    for i in 0..6 {
        r[i] = gap[i];
    }
    r[6] = prob.f_ref.dot(&(x - prob.x_ref));
    r[7] = (e - energy) / de.norm().max(f64::MIN_POSITIVE);
    r[8] = (p - p_psi) / dp.norm().max(f64::MIN_POSITIVE);
    r[9] = 0.5 * (g.norm_squared() - 1.0);
    // The gauge ξ̂_ref·(x₀ − x_ref) = 0 (the phase of the turn) and p_φ(x₀) = p_φ; without the
    // symmetry β = 0 and an empty row.
    match &prob.turn {
        Some(turn) => {
            let (pf, dpf) = symmetry::body_momentum(model, &x);
            r[10] = turn.xi_ref.dot(&(x - prob.x_ref));
            r[11] = (pf - turn.p_phi) / dpf.norm().max(f64::MIN_POSITIVE);
        }
        None => r[10] = w[TURN],
    }
    r[TOP] = row.residual(w);
    r
}

/// The rows of [`linearise`] for one model at momentum `p_psi` and their Jacobian, the energy
/// row at `energy.0` (and its column that of an unknown energy `w₇·e_s` when `energy.1`; else
/// empty).
fn system<M: Lagrangian + ?Sized>(
    model: &M,
    p_psi: f64,
    energy: (f64, bool),
    prob: &Problem,
    row: &LinearRow<UNKNOWNS>,
    w: &W,
    opts: &OrbitOptions,
) -> Result<(Residual, Jac, Shot), RouthError> {
    let x: Vector6<f64> = w.fixed_rows::<6>(0).into();
    let t = prob.scales.period(w);
    let mut s = shoot(model, &x, t, opts)?;
    let r = residual(model, p_psi, energy.0, prob, row, w, &s.end);
    let f_end = field(model, &s.end)?;
    let (_, de, _, dp) = integrals(model, &x);
    let (_, g) = split(&x);
    let (ne, np) = (
        de.norm().max(f64::MIN_POSITIVE),
        dp.norm().max(f64::MIN_POSITIVE),
    );
    let mut j = Jac::zeros();
    // ∂/∂x₀ = S_βΦ − I, ∂/∂T = S_β F(φ_T(x₀)) and ∂/∂β = ξ(S_β φ_T(x₀)).
    let beta = if prob.turn.is_some() { w[TURN] } else { 0.0 };
    let (end, f_end) = (symmetry::act(beta, &s.end), symmetry::act(beta, &f_end));
    if prob.turn.is_some() {
        let r3 = symmetry::rot(beta);
        let mut sb = nalgebra::Matrix6::zeros();
        sb.fixed_view_mut::<3, 3>(0, 0).copy_from(&r3);
        sb.fixed_view_mut::<3, 3>(3, 3).copy_from(&r3);
        s.monodromy = sb * s.monodromy;
        s.turn = symmetry::less_body_turn(&s.turn, beta);
        let xi = symmetry::generator(&end);
        for i in 0..6 {
            j[(i, TURN)] = xi[i];
        }
    }
    for i in 0..6 {
        for k in 0..6 {
            j[(i, k)] = s.monodromy[(i, k)] - if i == k { 1.0 } else { 0.0 };
        }
        j[(i, 6)] = f_end[i] * prob.scales.t;
    }
    for k in 0..6 {
        j[(6, k)] = prob.f_ref[k];
        j[(7, k)] = de[k] / ne;
        j[(8, k)] = dp[k] / np;
    }
    if energy.1 {
        j[(7, 7)] = -prob.scales.e / ne;
    }
    for k in 0..3 {
        j[(9, 3 + k)] = g[k];
    }
    match &prob.turn {
        Some(turn) => {
            let (_, dpf) = symmetry::body_momentum(model, &x);
            let npf = dpf.norm().max(f64::MIN_POSITIVE);
            for k in 0..6 {
                j[(10, k)] = turn.xi_ref[k];
                j[(11, k)] = dpf[k] / npf;
            }
        }
        None => j[(10, TURN)] = 1.0,
    }
    for k in 0..UNKNOWNS {
        j[(TOP, k)] = row.normal[k];
    }
    Ok((r, j, s))
}

/// Corrects `w` to an orbit (`Ok(None)`: no convergence within `max_iter` steps, or the period
/// left `(0, ∞)`; integration failures are errors).
pub(crate) fn correct<M: Lagrangian>(
    slot: Slot<'_, M>,
    prob: &Problem,
    row: &LinearRow<UNKNOWNS>,
    w0: &W,
    opts: &OrbitOptions,
) -> Result<Result<Solved, f64>, RouthError> {
    let mut w = *w0;
    let mut best = f64::INFINITY;
    for it in 0..=opts.max_iter {
        let t = prob.scales.period(&w);
        if !(t.is_finite() && t > 0.0) {
            return Ok(Err(best));
        }
        let (r, j, s, model, p) = match linearise(&slot, prob, row, &w, opts) {
            Ok(v) => v,
            Err(RouthError::TooManySteps { .. })
            | Err(RouthError::StepSizeUnderflow { .. })
            | Err(RouthError::NonFiniteState { .. }) => return Ok(Err(best)),
            Err(e) => {
                return Err(match slot {
                    Slot::Energy(_) => e,
                    Slot::Parameter { .. } => at_parameter(prob.scales.parameter(&w), e),
                })
            }
        };
        let x: Vector6<f64> = w.fixed_rows::<6>(0).into();
        let scale = 1f64.max(x.norm());
        let res = r.amax() / scale;
        best = best.min(res);
        if !res.is_finite() {
            return Ok(Err(best));
        }
        // The guess itself is accepted only when its gap is small against the orbit's own size
        // (a relative test): the linear orbit of a Lyapunov family at amplitude a closes to
        // O(a²) in absolute terms, below any absolute tolerance, and one Gauss–Newton step
        // gives the period its nonlinear correction.
        let relative = it > 0 || r.fixed_rows::<6>(0).amax() <= opts.newton_tol * s.reach;
        if res <= opts.newton_tol && relative {
            // Onto the level of p_ψ and |γ| = 1 exactly (the rows hold them to newton_tol):
            // a move of the order of round-off, which the closure does not see.
            let xl = onto_level(&*model, &x, p);
            let (_, gn) = split(&xl);
            let mut w = w;
            w.fixed_rows_mut::<6>(0).copy_from(&xl);
            let trace = s.monodromy.trace();
            return Ok(Ok(Solved {
                w,
                shot: ShotSummary {
                    trace,
                    precession: precession(&s.turn, &gn),
                    reach: s.reach,
                    monodromy: s.monodromy,
                },
                jac: j,
                iterations: it,
            }));
        }
        if it == opts.max_iter {
            break;
        }
        let svd = j.svd(true, true);
        let cut = prob.cut * svd.singular_values.max();
        let Ok(step) = svd.solve(&r, cut) else {
            return Ok(Err(best));
        };
        let mut step = -step;
        let dt = step[6].abs() * prob.scales.t;
        if dt > t / 3.0 {
            step *= t / 3.0 / dt;
        }
        w += step;
    }
    Ok(Err(best))
}

/// What [`correct_at`] gives: the correction (`Err(best residual)` when it does not converge),
/// the scales and the guess's state.
pub(crate) type Corrected = (Result<Solved, f64>, Scales, Vector6<f64>);

/// One correction of `guess` (an orbit of this model, or of a neighbouring model or energy) in
/// the family's unknowns with the energy fixed at `energy` and the momentum at `p_psi`: the
/// result (`Err(best residual)` when it does not converge), the scales and the guess's state.
pub(crate) fn correct_at<M: Lagrangian>(
    model: &M,
    guess: &PeriodicOrbit,
    energy: f64,
    p_psi: f64,
    opts: &OrbitOptions,
) -> Result<Corrected, RouthError> {
    let x = check_guess(model, &guess.omega0, &guess.gamma0, guess.period)?;
    let scales = Scales {
        t: guess.period,
        e: 1f64.max(energy.abs()),
    };
    let prob = Problem::at(model, &x, p_psi, scales)?;
    let row = scales.energy_row(energy);
    let w = scales.pack_turned(&x, guess.period, energy, guess.body_turn);
    Ok((
        correct(Slot::Energy(model), &prob, &row, &w, opts)?,
        scales,
        x,
    ))
}

/// The orbit of `model` at the energy `energy` and the momentum `p_psi` corrected from `guess`
/// ([`correct_at`]; the chart's curves, `chart/curves.rs`). `None` when it does not converge or
/// lands on a steady motion; the model's own errors are errors.
pub(crate) fn orbit_near<M: Lagrangian>(
    model: &M,
    guess: &PeriodicOrbit,
    energy: f64,
    p_psi: f64,
    opts: &OrbitOptions,
) -> Result<Option<PeriodicOrbit>, RouthError> {
    let (s, scales, x) = correct_at(model, guess, energy, p_psi, opts)?;
    Ok(match s {
        Ok(s) if s.shot.reach > 1e-8 * 1f64.max(x.norm()) => {
            Some(orbit_of(model, &s, &scales, opts))
        }
        _ => None,
    })
}

/// The orbit of a solved system. On an axially symmetric body the body turn is `w₈` (else 0),
/// and an orbit that is not a relative equilibrium of the two turns is degenerate: `k = 1`,
/// `μ = 1/μ = 1`, `Parabolic` (docs/method.md §11a; the monodromy modulo the turn has every
/// multiplier 1 there, which the tests check against finite differences of `simulate_full`).
pub(crate) fn orbit_of<M: Lagrangian + ?Sized>(
    model: &M,
    s: &Solved,
    scales: &Scales,
    opts: &OrbitOptions,
) -> PeriodicOrbit {
    let x: Vector6<f64> = s.w.fixed_rows::<6>(0).into();
    let (omega0, gamma0) = split(&x);
    // An integration failure here (there was none over the same state in the corrector) keeps
    // the ordinary reading.
    let degenerate = matches!(symmetry::turn_at(model, &x), Ok(Some(_)));
    let body_turn = if symmetry::axial_symmetry(model) {
        symmetry::wrap(s.w[TURN])
    } else {
        0.0
    };
    let k = if degenerate {
        1.0
    } else {
        0.5 * (s.shot.trace - 4.0)
    };
    PeriodicOrbit {
        omega0,
        gamma0,
        period: scales.period(&s.w),
        energy: model.energy(&omega0, &gamma0),
        p_psi: model.cyclic_momentum(&omega0, &gamma0),
        precession: s.shot.precession,
        body_turn,
        multipliers: PeriodicOrbit::multipliers_from_index(k),
        stability_index: k,
        stability: OrbitStability::from_index(k, opts.parabolic_tol),
        degenerate,
        amplitude: s.shot.reach,
    }
}

/// The upward crossings `(t, |S_β x(t) − x_ref|, β)` of the phase plane `F̂_ref·(x − x_ref) = 0`
/// by the flow from `x_ref`, for `from < t < to` (upwards as at `t = 0`, where the test's
/// derivative is `|F| > 0`), each located by the crate's one locator on the dense output. On an
/// axially symmetric body (`prob.turn`) the state is first turned about `e₃` onto `x_ref`
/// ([`symmetry::align`]) by `β`, so that returns modulo the body turn count (docs/method.md
/// §11a; else `β = 0`).
fn plane_returns<M: Lagrangian + ?Sized>(
    model: &M,
    prob: &Problem,
    from: f64,
    to: f64,
    opts: &OrbitOptions,
) -> Vec<(f64, f64, f64)> {
    let (rtol, atol) = (opts.rtol.max(1e-10), opts.atol.max(1e-12));
    let weights = dop853::componentwise(rtol, atol);
    let cfg = Config {
        weights: &weights,
        h_max: f64::INFINITY,
        h_init: None,
        max_steps: opts.max_steps,
        dense: true,
        control: Some(&opts.control),
    };
    let turned = |x: &Vector6<f64>| -> (Vector6<f64>, f64) {
        match prob.turn {
            Some(_) => {
                let b = symmetry::align(x, &prob.x_ref);
                (symmetry::act(b, x), b)
            }
            None => (*x, 0.0),
        }
    };
    let g = |x: &Vector6<f64>| prob.f_ref.dot(&(turned(x).0 - prob.x_ref));
    let mut prev = (0.0, 0.0);
    let mut returns: Vec<(f64, f64, f64)> = Vec::new();
    let rhs = |_t: f64, x: &Vector6<f64>| field(model, x);
    let _ = dop853::integrate(rhs, 0.0, prob.x_ref, to, &cfg, |s: &Accepted<'_, 6>| {
        let now = (s.t, g(s.y));
        if prev.1 < 0.0 && now.1 >= 0.0 && s.t > from {
            if let Some(d) = s.dense {
                let z = illinois(
                    End::new(prev.0, prev.1, ()),
                    End::new(now.0, now.1, ()),
                    100,
                    |t| Ok::<_, RouthError>(Some((g(&d.eval(t)), ()))),
                    |lo, hi| estimated_distance(lo, hi) <= 1e-12 * hi.at,
                )?;
                if z.at > from && z.at < to {
                    let (y, b) = turned(&d.eval(z.at));
                    returns.push((z.at, (y - prob.x_ref).norm(), b));
                }
            }
        }
        prev = now;
        Ok(())
    });
    returns
}

/// The time of the guess's closest return through its own phase plane within `(T/2, 4T)` of the
/// period guessed, the earliest crossing about as near to `x_ref` as the nearest. A user's period
/// guess is often off by tens of per cent (a pendulum's period doubles near the separatrix);
/// Newton's basin in `T` is narrower. Returns the time and the body turn there (0 without the
/// axial symmetry). `None`: no return (then the guess is used as it is).
fn return_time<M: Lagrangian + ?Sized>(
    model: &M,
    prob: &Problem,
    period: f64,
    opts: &OrbitOptions,
) -> Option<(f64, f64)> {
    let returns = plane_returns(model, prob, 0.5 * period, 4.0 * period, opts);
    // The earliest return about as close as the closest: on an orbit the returns after 2T, 3T
    // are as close as the first (to round-off), and the first is the period.
    let closest = returns.iter().map(|r| r.1).fold(f64::INFINITY, f64::min);
    let near = 2.0 * closest + 1e-8 * 1f64.max(prob.x_ref.norm());
    returns.iter().find(|r| r.1 <= near).map(|r| (r.0, r.2))
}

/// The orbit's minimal period, when a corrected orbit of period `T` is one of period `T/n`
/// traversed `n ≥ 2` times: its earliest return onto its starting point within `(0, T)` (to
/// `min(1e−6·max(1, |x₀|), 1e−3·amplitude)`; a near miss of a different orbit is farther by the
/// orbit's own size). `None`: `T` is minimal.
fn shorter_period<M: Lagrangian + ?Sized>(
    model: &M,
    prob: &Problem,
    period: f64,
    amplitude: f64,
    opts: &OrbitOptions,
) -> Option<(f64, f64)> {
    let close = (1e-6 * 1f64.max(prob.x_ref.norm())).min(1e-3 * amplitude);
    plane_returns(model, prob, 1e-3 * period, (1.0 - 1e-3) * period, opts)
        .into_iter()
        .find(|r| r.1 <= close)
        .map(|r| (r.0, r.2))
}

/// Checks a guess: finite, `|γ| = 1`, `T > 0`, and not a steady motion (a point that moves by
/// less than `1e−8·max(1, |x|)` over `T`). Returns `x` with γ normalised.
pub(crate) fn check_guess<M: Lagrangian + ?Sized>(
    model: &M,
    omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    period: f64,
) -> Result<Vector6<f64>, RouthError> {
    check_finite("omega_guess", omega.as_slice())?;
    let gamma = unit_gamma("gamma_guess", gamma)?;
    check_finite("period_guess", &[period])?;
    if period <= 0.0 {
        return Err(RouthError::InvalidOption {
            what: "period_guess",
            reason: format!("the period must be positive, got {period}"),
        });
    }
    crate::validate::check_kinetic(model, &gamma)?;
    let x = join(omega, &gamma);
    let f = field(model, &x)?;
    check_finite("the vector field at the guess", f.as_slice())?;
    // Largest components, not lengths (whose squares overflow at |ω| = 1e200).
    let scale = 1f64.max(x.amax());
    let moved = f.amax() * period;
    if moved <= 1e-8 * scale {
        // A state that does not move at all is a steady motion; one that moves, but by almost
        // nothing over the period asked, was given too short a period.
        if f.amax() <= 1e-10 * scale {
            return Err(RouthError::InvalidOption {
                what: "omega_guess, gamma_guess",
                reason: "the guess is a steady motion (the state does not move); start a family \
                         of periodic orbits from it with lyapunov_family"
                    .into(),
            });
        }
        return Err(RouthError::InvalidOption {
            what: "period_guess",
            reason: format!(
                "{period:e} is too short: the state moves by {moved:e} over it, nothing beside \
                 its size {scale:e}"
            ),
        });
    }
    Ok(x)
}

/// Corrects a guess to a periodic orbit of the full equations (8) with the energy (3) and the
/// cyclic momentum (9) of the guess, and gives its period, precession `Δψ` over one period, Floquet
/// multipliers and stability (docs/method.md §11).
///
/// The guess need not lie on the orbit's phase: the corrected `(ω₀, γ₀)` is the orbit's point
/// on the plane through the guess normal to the flow there.
///
/// Errors: a non-finite guess, a non-unit γ, `T ≤ 0`, a guess that is a steady motion
/// ([`RouthError::InvalidOption`]), invalid options, and [`RouthError::NoConvergence`] when the
/// corrector does not converge within [`OrbitOptions::max_iter`] steps.
///
/// ```
/// use routh_core::{periodic_orbit, Matrix3, OrbitOptions, Vector3};
/// use test_models::HeavyTop;
/// // A heavy body J = diag(1, 2, 3), centre of mass on its third axis (U = γ₃): swings about the
/// // first axis are a pendulum with ω₀² = mgl/A = 1. Small swings of 0.05 rad:
/// let body = HeavyTop { j: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)), mgr: Vector3::z() };
/// let a = 0.05f64;
/// let gamma = Vector3::new(0.0, a.sin(), -a.cos());
/// let orbit = periodic_orbit(&body, Vector3::zeros(), gamma, 6.0, &OrbitOptions::default())?;
/// // T ≈ 2π(1 + a²/16), the pendulum's first correction; no precession.
/// let t0 = 2.0 * std::f64::consts::PI;
/// assert!((orbit.period - t0 * (1.0 + a * a / 16.0)).abs() < 1e-5);
/// assert!(orbit.precession.abs() < 1e-9);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn periodic_orbit<M: crate::Routhian>(
    model: &M,
    omega_guess: Vector3<f64>,
    gamma_guess: Vector3<f64>,
    period_guess: f64,
    opts: &OrbitOptions,
) -> Result<PeriodicOrbit, RouthError> {
    opts.validate()?;
    let x = check_guess(model, &omega_guess, &gamma_guess, period_guess)?;
    let (w, g) = split(&x);
    let e = model.energy(&w, &g);
    let p = model.cyclic_momentum(&w, &g);
    check_finite("energy of the guess", &[e, p])?;
    let scales = Scales {
        t: period_guess,
        e: 1f64.max(e.abs()),
    };
    let prob = Problem::at(model, &x, p, scales)?;
    let row = scales.energy_row(e);
    let (t0, b0) = return_time(model, &prob, period_guess, opts).unwrap_or((period_guess, 0.0));
    let w0 = scales.pack_turned(&x, t0, e, b0);
    let s = match correct(Slot::Energy(model), &prob, &row, &w0, opts)? {
        Ok(s) => s,
        Err(best) => {
            return Err(RouthError::NoConvergence {
                what: "periodic orbit",
                iterations: opts.max_iter,
                residual: best,
            })
        }
    };
    if s.shot.reach <= 1e-8 * 1f64.max(x.norm()) {
        return Err(RouthError::NoConvergence {
            what: "periodic orbit (the guess converged to a steady motion)",
            iterations: s.iterations,
            residual: 0.0,
        });
    }
    // A guess near a multiple of the period converges to the orbit traversed several times:
    // corrected again at its minimal period.
    let t = scales.period(&s.w);
    let x1: Vector6<f64> = s.w.fixed_rows::<6>(0).into();
    let at = Problem::at(model, &x1, p, scales)?;
    if let Some((t_min, b)) = shorter_period(model, &at, t, s.shot.reach, opts) {
        let w = scales.pack_turned(&x1, t_min, e, b);
        if let Ok(m) = correct(Slot::Energy(model), &at, &row, &w, opts)? {
            return Ok(orbit_of(model, &m, &scales, opts));
        }
    }
    Ok(orbit_of(model, &s, &scales, opts))
}
