//! Simulation cost at rtol = 1e-10 (atol = 1e-12), per unit of simulated time: `simulate_full`
//! and `simulate_reduced` (generated code) beside the `ode_solvers` crate's Dop853 on a
//! right-hand side written for it, for the heavy asymmetric top and the ellipsoid on a plane.
//!
//! Printed once before the timings: right-hand-side evaluations, wall time per unit simulated
//! time, their ratios to `ode_solvers`, and the final error of γ against a tight reference
//! (`simulate_full` at rtol = 1e-14). For the top, the `ode_solvers` right-hand side is the
//! Euler–Poisson equations written by hand; for the ellipsoid (configuration-dependent J) it is
//! `full_vector_field` of the hand-written num-dual twin from `test-models`.

mod common;

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use ode_solvers::{Dop853, OutputType, SVector as OdeVector, System};
use routh::{simulate_full, simulate_reduced, Lagrangian, Routhian, SimOptions, Vector3};

use derived_models::AsymmetricTop as HeavyTop;

const T_END: f64 = 10.0;
const RTOL: f64 = 1e-10;
const ATOL: f64 = 1e-12;

type State = OdeVector<f64, 6>;

/// The heavy top by hand: `Iω̇ = Iω × ω + m g γ × r`, `γ̇ = γ × ω`.
struct TopRhs(HeavyTop);

impl System<f64, State> for TopRhs {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        let m = &self.0;
        let (w, g) = (
            Vector3::new(y[0], y[1], y[2]),
            Vector3::new(y[3], y[4], y[5]),
        );
        let iw = m.inertia.component_mul(&w);
        let torque = iw.cross(&w) + g.cross(&m.com) * (m.mass * m.g);
        let w_dot = torque.component_div(&m.inertia);
        let g_dot = g.cross(&w);
        for i in 0..3 {
            dy[i] = w_dot[i];
            dy[3 + i] = g_dot[i];
        }
    }
}

/// Any model through `full_vector_field` (used for the ellipsoid's num-dual twin).
struct FieldRhs<M>(M);

impl<M: Lagrangian> System<f64, State> for FieldRhs<M> {
    fn system(&self, _t: f64, y: &State, dy: &mut State) {
        let (w, g) = (
            Vector3::new(y[0], y[1], y[2]),
            Vector3::new(y[3], y[4], y[5]),
        );
        let (w_dot, g_dot) =
            routh_core::sim::full_vector_field(&self.0, &w, &g).expect("vector field");
        for i in 0..3 {
            dy[i] = w_dot[i];
            dy[3 + i] = g_dot[i];
        }
    }
}

/// `(γ(T_END), rhs evaluations)` from `ode_solvers`' Dop853.
fn ode_solvers_run<S: System<f64, State>>(
    rhs: S,
    w0: Vector3<f64>,
    g0: Vector3<f64>,
) -> (Vector3<f64>, usize) {
    let y0 = State::from_column_slice(&[w0.x, w0.y, w0.z, g0.x, g0.y, g0.z]);
    // Sparse output (the end of every step), Hairer's default controller parameters.
    let mut solver = Dop853::from_param(
        rhs,
        0.0,
        T_END,
        T_END,
        y0,
        RTOL,
        ATOL,
        0.9,
        0.0,
        0.333,
        6.0,
        T_END,
        0.0,
        100_000,
        1000,
        OutputType::Sparse,
    );
    let stats = solver.integrate().expect("ode_solvers");
    let y = solver
        .results()
        .get()
        .1
        .last()
        .expect("output")
        .clone_owned();
    (Vector3::new(y[3], y[4], y[5]), stats.num_eval as usize)
}

/// Mean wall time of `f` over enough repetitions to take ~0.2 s, in seconds.
fn wall_time(mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    let mut n = 0u32;
    while start.elapsed().as_secs_f64() < 0.2 || n < 3 {
        f();
        n += 1;
    }
    start.elapsed().as_secs_f64() / n as f64
}

/// Prints the comparison for one model and registers its criterion benches.
fn compare<M, S>(
    c: &mut Criterion,
    name: &str,
    model: &M,
    rhs: impl Fn() -> S,
    w0: Vector3<f64>,
    g0: Vector3<f64>,
) where
    M: Routhian,
    S: System<f64, State>,
{
    let opts = SimOptions::with_tolerances(RTOL, ATOL);
    let tight = SimOptions::with_tolerances(1e-14, 1e-16);
    let reference = *simulate_full(model, w0, g0, T_END, &tight)
        .expect("reference")
        .gamma
        .last()
        .expect("points");
    let p = model.cyclic_momentum(&w0, &g0);
    let big_omega0 = w0 - g0 * w0.dot(&g0);

    let full = simulate_full(model, w0, g0, T_END, &opts).expect("full");
    let red = simulate_reduced(model, big_omega0, g0, p, T_END, &opts).expect("reduced");
    let (ode_gamma, ode_evals) = ode_solvers_run(rhs(), w0, g0);
    let t_full = wall_time(|| {
        black_box(simulate_full(model, w0, g0, T_END, &opts).expect("full"));
    }) / T_END;
    let t_red = wall_time(|| {
        black_box(simulate_reduced(model, big_omega0, g0, p, T_END, &opts).expect("reduced"));
    }) / T_END;
    let t_ode = wall_time(|| {
        black_box(ode_solvers_run(rhs(), w0, g0));
    }) / T_END;
    let err = |g: &Vector3<f64>| (g - reference).amax();
    let last = |v: &[Vector3<f64>]| *v.last().expect("points");
    println!("{name}, t in [0, {T_END}], rtol {RTOL:e}, atol {ATOL:e}:");
    for (what, evals, t, e) in [
        (
            "simulate_full   ",
            full.stats.rhs_evaluations,
            t_full,
            err(&last(&full.gamma)),
        ),
        (
            "simulate_reduced",
            red.stats.rhs_evaluations,
            t_red,
            err(&last(&red.gamma)),
        ),
        ("ode_solvers     ", ode_evals, t_ode, err(&ode_gamma)),
    ] {
        println!(
            "  {what}: {evals:6} rhs evaluations ({:.2}× ode_solvers), {:8.2} µs per unit time \
             ({:.2}× ode_solvers), |γ(T) − γ_ref| {e:.1e}",
            evals as f64 / ode_evals as f64,
            t * 1e6,
            t / t_ode,
        );
    }

    let mut group = c.benchmark_group(format!("simulate_{name}"));
    group.sample_size(20);
    group.bench_function("simulate_full", |b| {
        b.iter(|| simulate_full(black_box(model), w0, g0, T_END, &opts).expect("full"))
    });
    group.bench_function("simulate_reduced", |b| {
        b.iter(|| {
            simulate_reduced(black_box(model), big_omega0, g0, p, T_END, &opts).expect("reduced")
        })
    });
    group.bench_function("ode_solvers_dop853", |b| {
        b.iter(|| ode_solvers_run(rhs(), black_box(w0), g0))
    });
    group.finish();
}

fn bench_simulate(c: &mut Criterion) {
    let top = HeavyTop {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        com: Vector3::new(0.3, -0.2, 0.5),
        mass: 1.0,
        g: 9.81,
    };
    let w0 = Vector3::new(1.0, -0.5, 2.0);
    let g0 = Vector3::new(0.3, 0.4, 0.866).normalize();
    compare(c, "heavy_top", &top, || TopRhs(top.clone()), w0, g0);

    let (ellipsoid, twin) = common::m2(&mut common::rng(2));
    compare(
        c,
        "ellipsoid",
        &ellipsoid,
        || FieldRhs(twin.clone()),
        w0,
        g0,
    );
}

criterion_group!(benches, bench_simulate);
criterion_main!(benches);
