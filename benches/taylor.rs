//! Taylor's method (`Method::Taylor`) against DOP853 (`Method::Dop853`) at matched accuracy, in
//! the same run: `simulate_full` of the heavy asymmetric top `J = (1, 1.6, 2.3)` (the derived
//! `AsymmetricTop`, centre of mass off the axes) over t ∈ [0, 1000], recording every step.
//!
//! Printed before the criterion timings: for each method and tolerance `rtol = atol = tol` on a
//! grid 1e-8 … 1e-14 (half decades), the number of steps, the wall time (the fastest of
//! interleaved rounds) and the error at t = 1000, `max(|Δω|∞/|ω|∞, |Δγ|∞)` against a reference
//! run (Taylor at rtol = 3e-15; its distance to DOP853 at 3e-15 is printed as a check). Then, at
//! matched accuracy, each method's time at the other's achieved error, interpolated log-log on
//! the other's (error, time) curve, and the ratio Taylor/DOP853.
//!
//! Run with `cargo bench --bench taylor` (add `-- --quick` for short criterion timings).

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::AsymmetricTop;
use routh::{simulate_full, Method, SimOptions, Trajectory, Vector3};

const T_END: f64 = 1000.0;

fn top() -> AsymmetricTop {
    AsymmetricTop {
        inertia: Vector3::new(1.0, 1.6, 2.3),
        com: Vector3::new(0.1, -0.05, 0.4),
        mass: 1.0,
        g: 1.0,
    }
}

/// A regular start: spinning fast about the axis of the largest moment, tilted.
fn start() -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(0.5, -0.3, 3.0),
        Vector3::new(0.3, 0.2, 0.9).normalize(),
    )
}

fn opts(method: Method, tol: f64) -> SimOptions {
    SimOptions {
        method,
        max_steps: 10_000_000,
        ..SimOptions::with_tolerances(tol, tol)
    }
}

fn run(method: Method, tol: f64) -> Trajectory {
    let (w0, g0) = start();
    simulate_full(&top(), w0, g0, T_END, &opts(method, tol)).expect("simulation")
}

fn error(tr: &Trajectory, w_ref: &Vector3<f64>, g_ref: &Vector3<f64>) -> f64 {
    let (w, g) = (tr.omega.last().unwrap(), tr.gamma.last().unwrap());
    ((w - w_ref).amax() / w_ref.amax()).max((g - g_ref).amax())
}

/// `y` at `x` on the piecewise-linear curve through `pts` in log-log (`None` outside).
fn interpolate(pts: &[(f64, f64)], x: f64) -> Option<f64> {
    let mut pts: Vec<(f64, f64)> = pts.iter().map(|&(a, b)| (a.ln(), b.ln())).collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let x = x.ln();
    pts.windows(2).find_map(|w| {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        (x0 <= x && x <= x1 && x1 > x0).then(|| (y0 + (y1 - y0) * (x - x0) / (x1 - x0)).exp())
    })
}

fn table() {
    let reference = run(Method::Taylor, 3e-15);
    let (w_ref, g_ref) = (
        *reference.omega.last().unwrap(),
        *reference.gamma.last().unwrap(),
    );
    let check = run(Method::Dop853, 3e-15);
    println!(
        "reference: Taylor rtol 3e-15, {} steps; DOP853 at 3e-15 differs by {:.1e}",
        reference.stats.accepted_steps,
        error(&check, &w_ref, &g_ref)
    );
    let tols: Vec<f64> = (0..=12)
        .map(|j| 10f64.powf(-8.0 - 0.5 * j as f64))
        .collect();
    let methods = [("Taylor", Method::Taylor), ("DOP853", Method::Dop853)];
    // Fastest of interleaved rounds.
    let rounds = 5;
    let mut best = vec![vec![f64::INFINITY; tols.len()]; 2];
    let mut results: Vec<Vec<(usize, f64)>> = vec![Vec::new(); 2];
    for round in 0..rounds {
        for (m, &(_, method)) in methods.iter().enumerate() {
            for (i, &tol) in tols.iter().enumerate() {
                let t0 = Instant::now();
                let tr = black_box(run(method, tol));
                let dt = t0.elapsed().as_secs_f64();
                best[m][i] = best[m][i].min(dt);
                if round == 0 {
                    results[m].push((tr.stats.accepted_steps, error(&tr, &w_ref, &g_ref)));
                }
            }
        }
    }
    println!("| tol | method | steps | error at t = 1000 | time (ms) |");
    println!("|---|---|---|---|---|");
    for (i, tol) in tols.iter().enumerate() {
        for (m, (name, _)) in methods.iter().enumerate() {
            let (steps, err) = results[m][i];
            println!(
                "| {tol:.1e} | {name} | {steps} | {err:.2e} | {:.3} |",
                best[m][i] * 1e3
            );
        }
    }
    let curve = |m: usize| -> Vec<(f64, f64)> {
        (0..tols.len())
            .map(|i| (results[m][i].1, best[m][i]))
            .collect()
    };
    let (taylor, dop) = (curve(0), curve(1));
    println!();
    println!("| error | Taylor (ms) | DOP853 (ms) | Taylor / DOP853 | at the error of |");
    println!("|---|---|---|---|---|");
    for (own, other, name) in [(&taylor, &dop, "Taylor"), (&dop, &taylor, "DOP853")] {
        for &(err, time) in own {
            if let Some(t_other) = interpolate(other, err) {
                let (tt, td) = if name == "Taylor" {
                    (time, t_other)
                } else {
                    (t_other, time)
                };
                println!(
                    "| {err:.2e} | {:.3} | {:.3} | {:.2} | {name} |",
                    tt * 1e3,
                    td * 1e3,
                    tt / td
                );
            }
        }
    }
}

fn bench(c: &mut Criterion) {
    table();
    let mut g = c.benchmark_group("simulate_full t = 1000, heavy asymmetric top");
    g.sample_size(10);
    for tol in [1e-8, 1e-10, 1e-12, 1e-14] {
        g.bench_function(format!("Taylor tol {tol:.0e}"), |b| {
            b.iter(|| run(Method::Taylor, black_box(tol)))
        });
        g.bench_function(format!("DOP853 tol {tol:.0e}"), |b| {
            b.iter(|| run(Method::Dop853, black_box(tol)))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
