//! Simulation cost per unit of simulated time, for the heavy asymmetric top and the ellipsoid on
//! a plane over t ∈ [0, 10]: `simulate_full` and `simulate_reduced` (generated code, our DOP853)
//! beside the `ode_solvers` crate's Dop853 (Hairer's controller, same order) on three right-hand
//! sides: the generated full equations (8) (`full_vector_field`, the equations `simulate_full`
//! integrates), the generated reduced equations (13) with ψ (15) (`reduced_vector_field`, those
//! of `simulate_reduced`), and the baseline, the full equations written by hand in closed form.
//! The first two separate the integrators (same equations, same right-hand side); the baseline
//! adds the cost of the generated right-hand side against an expert's. For the reduced problem
//! the fair baseline is the same equations (13) by hand, two ways: through the hand-written (8)
//! (Routh's reduction is exact: `Ω̇ = ω̇ − γ(γ·ω̇)/|γ|² − ψ̇γ̇` at `ω = Ω + ψ̇γ`), for both bodies,
//! and in closed form from R (39) for the top; a last line compares `simulate_reduced` with the
//! faster of them.
//!
//! Printed before the criterion timings, for each model, with ratios to the baseline:
//!
//! 1. at rtol = 1e-10, atol = 1e-12 for all: right-hand-side evaluations, wall time per unit
//!    simulated time and the final error;
//! 2. at equal final error: for each solver the loosest tolerance on a grid (rtol = 10^(−7−j/8),
//!    atol = rtol/100) from which on every tighter grid tolerance keeps the final error at or
//!    below a common target, the baseline's error at rtol = 1e-10; the same figures for the runs
//!    so chosen.
//!
//! The final error is `max(|ω(T) − ω_ref|∞ / |ω_ref|∞, |γ(T) − γ_ref|∞)` against `simulate_full`
//! at rtol = 1e-14, atol = 1e-16 (the baseline at the same tolerances is printed beside it as a
//! check of the reference). For the reduced equations ω is the reconstructed `Ω + ψ̇γ`.
//!
//! Wall times are the fastest of 150 interleaved rounds (every solver runs a ~0.5 ms batch in
//! each round, in turn): on a shared machine a batch is slowed by whatever else runs, never sped
//! up, and interleaving spreads slow periods over all solvers alike. Every solver records every
//! step (`ode_solvers` with `OutputType::Sparse`, `simulate_*` with `Output::Steps`, which also
//! records the integrals).
//!
//! The hand-written right-hand sides: the Euler–Poisson equations for the top, and for the
//! ellipsoid the full equations (8) with the derivatives of its Lagrangian worked out by hand and
//! `J = I + m v vᵀ` inverted by Sherman–Morrison (its inertia is diagonal). Both are checked
//! against `full_vector_field` of the generated model before anything is timed.
//! `simulate_full` evaluates the generated derivatives; for the ellipsoid the derive has found
//! `J = I + m v vᵀ` in the kinetic energy as written (docs/method.md §2a), so it too solves by
//! Sherman–Morrison, from one factorisation of `I` per simulation (for any `I`, not only a
//! diagonal one).

mod common;

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use ode_solvers::{Dop853, OutputType, SVector as OdeVector, System};
use rand::Rng;
use routh::{simulate_full, simulate_reduced, Lagrangian, Routhian, SimOptions, Vector3};
use routh_core::sim::{full_vector_field, reduced_vector_field};

use derived_models::{AsymmetricTop as HeavyTop, DiagonalEllipsoid};

const T_END: f64 = 10.0;
const RTOL: f64 = 1e-10;

type State = OdeVector<f64, 6>;
type State7 = OdeVector<f64, 7>;

fn split(y: &State) -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(y[0], y[1], y[2]),
        Vector3::new(y[3], y[4], y[5]),
    )
}

fn join(dy: &mut State, a: &Vector3<f64>, b: &Vector3<f64>) {
    for i in 0..3 {
        dy[i] = a[i];
        dy[3 + i] = b[i];
    }
}

/// The heavy top by hand: `Iω̇ = Iω × ω + m g γ × r`, `γ̇ = γ × ω`.
#[derive(Clone)]
struct TopRhs(HeavyTop);

impl HandRhs for TopRhs {
    fn rates(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let m = &self.0;
        let iw = m.inertia.component_mul(w);
        let torque = iw.cross(w) + g.cross(&m.com) * (m.mass * m.g);
        (torque.component_div(&m.inertia), g.cross(w))
    }
    fn inertia(&self) -> Vector3<f64> {
        self.0.inertia
    }
    fn reduced_closed_form(&self, o: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Option<Rates7> {
        Some(self.reduced_closed(o, g, p))
    }
}

impl TopRhs {
    /// The reduced equations (13) of the top in closed form, written from its Routh function
    /// `R = ½Ω·IΩ − m g r·γ − ½q²/s` (39) with `w = Iγ`, `c = IΩ`, `s = γ·w`, `ρ = 1/s`,
    /// `q = p_ψ − c·γ`, `u = qρ = ψ̇`: `∂R/∂Ω = c + uw`, `∂R/∂γ = u(c + uw) − m g r`,
    /// `M = uI − w zᵀ` with `z = ρ(c + 2uw)`, and `Ω̇ = J⁻¹b` projected on γ^⊥ (the gauge).
    fn reduced_closed(&self, o: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Rates7 {
        let m = &self.0;
        let i = &m.inertia;
        let w = i.component_mul(g);
        let c = i.component_mul(o);
        let rho = 1.0 / g.dot(&w);
        let r_gamma = 1.0 / g.norm_squared();
        let u = (p - c.dot(g)) * rho;
        let uw = w * u;
        let dr_do = c + uw;
        let dr_dg = dr_do * u - m.com * (m.mass * m.g);
        let g_dot = g.cross(o);
        let z = (dr_do + uw) * rho;
        let m_gd = i.component_mul(&g_dot) * u - w * z.dot(&g_dot);
        let b = dr_do.cross(o) + dr_dg.cross(g) - m_gd;
        let y = b.component_div(i);
        (y - g * (g.dot(&y) * r_gamma), g_dot, u)
    }
}

/// `(Ω̇, γ̇, ψ̇)` of the reduced equations (13) with (15).
type Rates7 = (Vector3<f64>, Vector3<f64>, f64);

/// The ellipsoid on a plane by hand. With `D = diag(a²)`, `s = √(γᵀDγ)`, the height gradient
/// `n = Dγ/s − c₀`, its Jacobian `N = D/s − DγγᵀD/s³`, `v = n × γ` and `u = v·ω`:
/// `L = ½ωᵀIω + ½m u² − m g (s − c₀·γ)`, so
/// `∂L/∂ω = Iω + m u v`, `J = I + m v vᵀ`, `∂u/∂γ = ω × n + N(γ × ω)`,
/// `∂L/∂γ = m u ∂u/∂γ − m g n`, and `(∂²L/∂ω∂γ) x = m v (∂u/∂γ·x) + m u (n × x − γ × Nx)`.
#[derive(Clone)]
struct EllipsoidRhs(DiagonalEllipsoid);

impl HandRhs for EllipsoidRhs {
    fn rates(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let e = &self.0;
        let (i, m) = (&e.inertia, e.mass);
        let d = e.semi_axes.component_mul(&e.semi_axes);
        let dg = d.component_mul(g);
        let s = g.dot(&dg).sqrt();
        let n = dg / s - e.offset;
        // N x = D x / s − Dγ (Dγ·x) / s³.
        let big_n = |x: &Vector3<f64>| d.component_mul(x) / s - dg * (dg.dot(x) / (s * s * s));
        let v = n.cross(g);
        let u = v.dot(w);
        let g_dot = g.cross(w);
        let du_dg = w.cross(&n) + big_n(&g_dot);
        let dl_dw = i.component_mul(w) + v * (m * u);
        let dl_dg = du_dg * (m * u) - n * (m * e.g);
        let mixed =
            v * (m * du_dg.dot(&g_dot)) + (n.cross(&g_dot) - g.cross(&big_n(&g_dot))) * (m * u);
        let rhs = dl_dw.cross(w) + dl_dg.cross(g) - mixed;
        // (I + m v vᵀ)⁻¹ by Sherman–Morrison.
        let (ir, iv) = (rhs.component_div(i), v.component_div(i));
        let w_dot = ir - iv * (m * v.dot(&ir) / (1.0 + m * v.dot(&iv)));
        (w_dot, g_dot)
    }
    fn inertia(&self) -> Vector3<f64> {
        self.0.inertia
    }
}

/// A closed-form right-hand side of (8) for `ode_solvers`, and of (13) from it.
trait HandRhs: Clone {
    fn rates(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>);

    /// The diagonal inertia I: for both bodies `γᵀJγ = γᵀIγ` and `(∂L/∂ω(Ω), γ) = IΩ·γ`
    /// (the ellipsoid's `v = n × γ` is orthogonal to γ), so ψ̇ of (38) is
    /// `(p_ψ − IΩ·γ)/(γᵀIγ)`.
    fn inertia(&self) -> Vector3<f64>;

    /// The reduced equations (13) in the gauge `Ω̇·γ = 0` through the full ones (Routh's
    /// reduction is exact): with `ω = Ω + ψ̇γ` (7), `ω̇ = Ω̇ + ψ̈γ + ψ̇γ̇` and `γ̇ ⊥ γ`, so
    /// `Ω̇ = ω̇ − γ(γ·ω̇)/|γ|² − ψ̇γ̇`. The cheapest correct (13) an expert writes by hand.
    fn reduced_via_full(&self, o: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Rates7 {
        let i = self.inertia();
        let psi_dot = (p - i.component_mul(o).dot(g)) / i.component_mul(g).dot(g);
        let (w_dot, g_dot) = self.rates(&(o + g * psi_dot), g);
        let o_dot = w_dot - g * (g.dot(&w_dot) / g.norm_squared()) - g_dot * psi_dot;
        (o_dot, g_dot, psi_dot)
    }

    /// (13) written out in closed form, where there is one.
    fn reduced_closed_form(&self, _o: &Vector3<f64>, _g: &Vector3<f64>, _p: f64) -> Option<Rates7> {
        None
    }
}

/// A hand-written reduced right-hand side for `ode_solvers`: through (8), or in closed form.
struct HandReduced<H>(H, f64, bool);

impl<H: HandRhs> System<f64, State7> for HandReduced<H> {
    fn system(&self, _t: f64, y: &State7, dy: &mut State7) {
        let (o, g) = (
            Vector3::new(y[0], y[1], y[2]),
            Vector3::new(y[3], y[4], y[5]),
        );
        let (a, b, psi_dot) = if self.2 {
            self.0
                .reduced_closed_form(&o, &g, self.1)
                .expect("closed form")
        } else {
            self.0.reduced_via_full(&o, &g, self.1)
        };
        for i in 0..3 {
            dy[i] = a[i];
            dy[3 + i] = b[i];
        }
        dy[6] = psi_dot;
    }
}

struct Ode<H>(H);

impl<H: HandRhs> System<f64, State> for Ode<H> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        let (w, g) = split(y);
        let (a, b) = self.0.rates(&w, &g);
        join(dy, &a, &b);
    }
}

/// The generated model's full equations (8) through `full_vector_field`, for `ode_solvers`.
struct GeneratedFull<'a, M>(&'a M);

impl<M: Lagrangian> System<f64, State> for GeneratedFull<'_, M> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        let (w, g) = split(y);
        let (a, b) = full_vector_field(self.0, &w, &g).expect("vector field");
        join(dy, &a, &b);
    }
}

/// The generated model's reduced equations (13) with ψ (15) through `reduced_vector_field`.
struct GeneratedReduced<'a, M>(&'a M, f64);

impl<M: Routhian> System<f64, State7> for GeneratedReduced<'_, M> {
    fn system(&self, _t: f64, y: &State7, dy: &mut State7) {
        let (w, g) = (
            Vector3::new(y[0], y[1], y[2]),
            Vector3::new(y[3], y[4], y[5]),
        );
        let (a, b, psi_dot) = reduced_vector_field(self.0, &w, &g, self.1).expect("vector field");
        for i in 0..3 {
            dy[i] = a[i];
            dy[3 + i] = b[i];
        }
        dy[6] = psi_dot;
    }
}

/// The final state and the evaluations of one run.
#[derive(Debug, Clone, Copy)]
struct End {
    omega: Vector3<f64>,
    gamma: Vector3<f64>,
    evals: usize,
}

/// `ode_solvers`' Dop853 with Hairer's default controller, output at every step (as
/// `simulate_*` records every step). Returns the final state and the evaluations.
fn ode_solvers_run<const N: usize, S: System<f64, OdeVector<f64, N>>>(
    system: S,
    y0: OdeVector<f64, N>,
    rtol: f64,
) -> (OdeVector<f64, N>, usize) {
    let mut solver = Dop853::from_param(
        system,
        0.0,
        T_END,
        T_END,
        y0,
        rtol,
        rtol / 100.0,
        0.9,
        0.0,
        0.333,
        6.0,
        T_END,
        0.0,
        1_000_000,
        1000,
        OutputType::Sparse,
    );
    let stats = solver.integrate().expect("ode_solvers");
    let y = *solver.results().get().1.last().expect("output");
    (y, stats.num_eval as usize)
}

/// The three solvers on one model and initial state.
struct Problem<'a, M, H> {
    name: &'a str,
    model: &'a M,
    hand: H,
    w0: Vector3<f64>,
    g0: Vector3<f64>,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Solver {
    Full,
    Reduced,
    /// `ode_solvers` on the generated full equations: same equations as `Full`.
    OdeFull,
    /// `ode_solvers` on the generated reduced equations: same equations as `Reduced`.
    OdeReduced,
    /// `ode_solvers` on the hand-written reduced equations through the full ones.
    OdeHandReduced,
    /// `ode_solvers` on the hand-written reduced equations in closed form (the top).
    OdeHandReducedClosed,
    /// `ode_solvers` on the hand-written full equations: the baseline.
    OdeHand,
}

/// The baseline last.
const SOLVERS: [Solver; 7] = [
    Solver::Full,
    Solver::Reduced,
    Solver::OdeFull,
    Solver::OdeReduced,
    Solver::OdeHandReduced,
    Solver::OdeHandReducedClosed,
    Solver::OdeHand,
];

impl Solver {
    fn label(self) -> &'static str {
        match self {
            Solver::Full => "simulate_full                 ",
            Solver::Reduced => "simulate_reduced              ",
            Solver::OdeFull => "ode_solvers, generated (8)    ",
            Solver::OdeReduced => "ode_solvers, generated (13)   ",
            Solver::OdeHandReduced => "ode_solvers, hand (13) via (8)",
            Solver::OdeHandReducedClosed => "ode_solvers, hand (13) closed ",
            Solver::OdeHand => "ode_solvers, hand-written (8) ",
        }
    }
}

impl<M: Routhian, H: HandRhs> Problem<'_, M, H> {
    fn opts(rtol: f64) -> SimOptions {
        SimOptions::with_tolerances(rtol, rtol / 100.0)
    }

    fn run(&self, solver: Solver, rtol: f64) -> End {
        let (w0, g0) = (self.w0, self.g0);
        match solver {
            Solver::Full => {
                let tr = simulate_full(self.model, w0, g0, T_END, &Self::opts(rtol)).expect("full");
                End {
                    omega: *tr.omega.last().expect("points"),
                    gamma: *tr.gamma.last().expect("points"),
                    evals: tr.stats.rhs_evaluations,
                }
            }
            Solver::Reduced => {
                let p = self.model.cyclic_momentum(&w0, &g0);
                let big_omega0 = w0 - g0 * w0.dot(&g0);
                let tr = simulate_reduced(self.model, big_omega0, g0, p, T_END, &Self::opts(rtol))
                    .expect("reduced");
                End {
                    omega: *tr.omega.last().expect("points"),
                    gamma: *tr.gamma.last().expect("points"),
                    evals: tr.stats.rhs_evaluations,
                }
            }
            Solver::OdeFull | Solver::OdeHand => {
                let y0 = State::from_column_slice(&[w0.x, w0.y, w0.z, g0.x, g0.y, g0.z]);
                let (y, evals) = if solver == Solver::OdeFull {
                    ode_solvers_run(GeneratedFull(self.model), y0, rtol)
                } else {
                    ode_solvers_run(Ode(self.hand.clone()), y0, rtol)
                };
                let (omega, gamma) = split(&y);
                End {
                    omega,
                    gamma,
                    evals,
                }
            }
            Solver::OdeReduced | Solver::OdeHandReduced | Solver::OdeHandReducedClosed => {
                let p = self.model.cyclic_momentum(&w0, &g0);
                let o = w0 - g0 * w0.dot(&g0);
                let y0 = State7::from_column_slice(&[o.x, o.y, o.z, g0.x, g0.y, g0.z, 0.0]);
                let (y, evals) = match solver {
                    Solver::OdeReduced => {
                        ode_solvers_run(GeneratedReduced(self.model, p), y0, rtol)
                    }
                    _ => {
                        let closed = solver == Solver::OdeHandReducedClosed;
                        ode_solvers_run(HandReduced(self.hand.clone(), p, closed), y0, rtol)
                    }
                };
                let (o, gamma) = (
                    Vector3::new(y[0], y[1], y[2]),
                    Vector3::new(y[3], y[4], y[5]),
                );
                End {
                    omega: o + gamma * self.model.psi_dot(&o, &gamma, p),
                    gamma,
                    evals,
                }
            }
        }
    }

    /// One run, kept from being optimised away (for timing).
    fn run_only(&self, solver: Solver, rtol: f64) {
        let (w0, g0) = (self.w0, self.g0);
        match solver {
            Solver::Full => {
                black_box(simulate_full(
                    black_box(self.model),
                    w0,
                    g0,
                    T_END,
                    &Self::opts(rtol),
                ))
                .expect("full");
            }
            Solver::Reduced => {
                let p = self.model.cyclic_momentum(&w0, &g0);
                let big_omega0 = w0 - g0 * w0.dot(&g0);
                let r = simulate_reduced(
                    black_box(self.model),
                    big_omega0,
                    g0,
                    p,
                    T_END,
                    &Self::opts(rtol),
                );
                black_box(r).expect("reduced");
            }
            _ => {
                black_box(self.run(solver, rtol));
            }
        }
    }
}

const ROUNDS: usize = 150;

/// Seconds per call of each closure: every round runs a batch of each in turn (batch sizes
/// calibrated to ~0.5 ms); returns per-closure per-round times.
fn interleaved(fs: &mut [&mut dyn FnMut()]) -> Vec<Vec<f64>> {
    let batch: Vec<usize> = fs
        .iter_mut()
        .map(|f| {
            let start = Instant::now();
            let mut n = 0usize;
            while start.elapsed().as_secs_f64() < 0.0005 {
                f();
                n += 1;
            }
            n.max(1)
        })
        .collect();
    let mut times = vec![Vec::with_capacity(ROUNDS); fs.len()];
    for _ in 0..ROUNDS {
        for (i, f) in fs.iter_mut().enumerate() {
            let start = Instant::now();
            for _ in 0..batch[i] {
                f();
            }
            times[i].push(start.elapsed().as_secs_f64() / batch[i] as f64);
        }
    }
    times
}

/// Prints one table: each solver at its rtol, with evaluations and time, and their ratios to the
/// last entry (the baseline), and the final error.
fn table<M: Routhian, H: HandRhs>(
    problem: &Problem<'_, M, H>,
    picks: &[(Solver, f64)],
    err: &dyn Fn(&End) -> f64,
) {
    let ends: Vec<End> = picks.iter().map(|&(s, r)| problem.run(s, r)).collect();
    let mut runs: Vec<Box<dyn FnMut() + '_>> = picks
        .iter()
        .map(|&(s, r)| Box::new(move || problem.run_only(s, r)) as Box<dyn FnMut()>)
        .collect();
    let mut refs: Vec<&mut dyn FnMut()> = runs
        .iter_mut()
        .map(|b| &mut **b as &mut dyn FnMut())
        .collect();
    let times = interleaved(&mut refs);
    let ode = picks.len() - 1;
    let fastest = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
    for (i, &(solver, rtol)) in picks.iter().enumerate() {
        println!(
            "    {} rtol {rtol:7.1e}: {:6} rhs evaluations ({:.2}×), {:7.2} µs per unit time \
             ({:.2}×), final error {:.1e}",
            solver.label(),
            ends[i].evals,
            ends[i].evals as f64 / ends[ode].evals as f64,
            fastest(&times[i]) / T_END * 1e6,
            fastest(&times[i]) / fastest(&times[ode]),
            err(&ends[i]),
        );
    }
    // `simulate_reduced` against the faster hand-written (13): the same equations by hand.
    let at = |s: Solver| picks.iter().position(|&(x, _)| x == s);
    let hand13 = [Solver::OdeHandReduced, Solver::OdeHandReducedClosed]
        .into_iter()
        .filter_map(at)
        .min_by(|&a, &b| fastest(&times[a]).total_cmp(&fastest(&times[b])));
    if let (Some(r), Some(h)) = (at(Solver::Reduced), hand13) {
        println!(
            "    simulate_reduced / {}: {:.2}× the evaluations, {:.2}× the wall time",
            picks[h].0.label().trim_end(),
            ends[r].evals as f64 / ends[h].evals as f64,
            fastest(&times[r]) / fastest(&times[h]),
        );
    }
}

/// Prints both comparisons for one model and registers its criterion benches.
fn compare<M: Routhian, H: HandRhs>(c: &mut Criterion, problem: &Problem<'_, M, H>) {
    let name = problem.name;
    // The hand-written right-hand side is the generated model's.
    let mut rng = common::rng(7);
    for _ in 0..100 {
        let w = test_models::random_vector(&mut rng, 2.0);
        let g = test_models::random_unit_vector(&mut rng);
        let (a, b) = problem.hand.rates(&w, &g);
        let (x, y) = full_vector_field(problem.model, &w, &g).expect("field");
        let scale = x.amax().max(y.amax()).max(1.0);
        let diff = (a - x).amax().max((b - y).amax());
        assert!(
            diff < 1e-12 * scale,
            "{name}: hand-written rhs differs by {diff:e}"
        );
        // The hand-written (13), both ways, against the generated one on a level p_ψ.
        let p = rng.gen_range(-3.0..3.0);
        let (x, y, z) = reduced_vector_field(problem.model, &w, &g, p).expect("field");
        let mut hands = vec![problem.hand.reduced_via_full(&w, &g, p)];
        hands.extend(problem.hand.reduced_closed_form(&w, &g, p));
        for (a, b, c) in hands {
            let scale = x.amax().max(y.amax()).max(z.abs()).max(1.0);
            let diff = (a - x).amax().max((b - y).amax()).max((c - z).abs());
            assert!(
                diff < 1e-12 * scale,
                "{name}: hand-written (13) differs by {diff:e}"
            );
        }
    }
    let solvers: Vec<Solver> = SOLVERS
        .into_iter()
        .filter(|&s| {
            s != Solver::OdeHandReducedClosed
                || (problem.hand)
                    .reduced_closed_form(&problem.w0, &problem.g0, 1.0)
                    .is_some()
        })
        .collect();

    let reference = problem.run(Solver::Full, 1e-14);
    let err = |e: &End| {
        ((e.omega - reference.omega).amax() / reference.omega.amax())
            .max((e.gamma - reference.gamma).amax())
    };
    let check = problem.run(Solver::OdeHand, 1e-14);
    println!(
        "{name}, t in [0, {T_END}]; ratios to ode_solvers on the hand-written right-hand side; \
         final errors against simulate_full at rtol 1e-14 (ode_solvers at rtol 1e-14 is {:.1e} \
         from it):",
        err(&check)
    );

    println!("  at the same tolerances (atol = rtol/100):");
    let same: Vec<(Solver, f64)> = solvers.iter().map(|&s| (s, RTOL)).collect();
    table(problem, &same, &err);

    // Equal final error: the loosest grid tolerance from which on all tighter ones meet it.
    let target = err(&problem.run(Solver::OdeHand, RTOL));
    let grid: Vec<f64> = (0..=48)
        .map(|j| 10f64.powf(-7.0 - j as f64 / 8.0))
        .collect();
    let pick = |solver: Solver| {
        let errors: Vec<f64> = grid.iter().map(|&r| err(&problem.run(solver, r))).collect();
        let from = (0..grid.len())
            .find(|&i| errors[i..].iter().all(|&e| e <= target))
            .expect("the tightest grid tolerance meets the target");
        (solver, grid[from])
    };
    println!(
        "  at equal final error (≤ {target:.1e}, the baseline's at rtol {RTOL:e}; each at the \
         loosest rtol of a grid, 8 per decade, from which on its error stays below that):"
    );
    let equal: Vec<(Solver, f64)> = solvers.iter().map(|&s| pick(s)).collect();
    table(problem, &equal, &err);

    let mut group = c.benchmark_group(format!("simulate_{name}"));
    group.sample_size(20);
    for (solver, id) in [
        (Solver::Full, "simulate_full"),
        (Solver::Reduced, "simulate_reduced"),
        (Solver::OdeHand, "ode_solvers_hand_written"),
    ] {
        group.bench_function(id, |b| b.iter(|| problem.run_only(solver, RTOL)));
    }
    group.finish();
}

fn bench_simulate(c: &mut Criterion) {
    let w0 = Vector3::new(1.0, -0.5, 2.0);
    let g0 = Vector3::new(0.3, 0.4, 0.866).normalize();

    let top = HeavyTop {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        com: Vector3::new(0.3, -0.2, 0.5),
        mass: 1.0,
        g: 9.81,
    };
    let problem = Problem {
        name: "heavy_top",
        model: &top,
        hand: TopRhs(top.clone()),
        w0,
        g0,
    };
    compare(c, &problem);

    let (ellipsoid, _twin) = common::m2(&mut common::rng(2));
    let problem = Problem {
        name: "ellipsoid",
        model: &ellipsoid,
        hand: EllipsoidRhs(ellipsoid.clone()),
        w0,
        g0,
    };
    compare(c, &problem);
}

criterion_group!(benches, bench_simulate);
criterion_main!(benches);
