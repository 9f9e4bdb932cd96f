//! Families of steady motions: the bifurcation diagram of a Lagrange top (A₁ = 1, C = 1.25,
//! mgl = 1, the derived gyrostat of `derived-models` with K = B = 0) over p_ψ ∈ [0, 5] — every
//! branch, its events located to 1e−10, and the count checks against global searches — and the
//! same diagram without count checks — and the cost of `ContinuationOptions::nonlinear`: the
//! diagram of an oblate asymmetric top (I = diag(1, 1.2, 1.25), mgl = 1) over p_ψ ∈ [1.9, 2.6]
//! with and without the nonlinear events, and their same-run ratio (the contract: at most 5).

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::Gyrostat;
use routh::{bifurcation_diagram, ContinuationOptions, Matrix3, NonlinearOptions, Vector3};

fn lagrange_top() -> Gyrostat {
    Gyrostat {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 1.25)),
        rotor: Vector3::zeros(),
        coupling: Matrix3::zeros(),
        com: Vector3::z(),
        mass: 1.0,
        g: 1.0,
    }
}

/// An oblate asymmetric top: gyroscopically stabilised over part of [1.9, 2.6], with nonlinear
/// events there.
fn oblate_asymmetric_top() -> Gyrostat {
    Gyrostat {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 1.2, 1.25)),
        ..lagrange_top()
    }
}

/// The same-run ratio of the diagram with `ContinuationOptions::nonlinear` to the diagram
/// without it, runs alternated (so that both see the same load), over at least `min` each.
fn nonlinear_ratio(top: &Gyrostat, plain: &ContinuationOptions, nl: &ContinuationOptions) {
    let range = (1.9, 2.6);
    let (mut t_plain, mut t_nl, mut n) = (Duration::ZERO, Duration::ZERO, 0);
    while n < 5 || t_plain + t_nl < Duration::from_secs(4) {
        let t = Instant::now();
        black_box(bifurcation_diagram(|p| (top.clone(), p), range, plain).expect("diagram"));
        t_plain += t.elapsed();
        let t = Instant::now();
        black_box(bifurcation_diagram(|p| (top.clone(), p), range, nl).expect("diagram"));
        t_nl += t.elapsed();
        n += 1;
    }
    println!(
        "oblate asymmetric top over p in [1.9, 2.6], {n} runs each: {:.2} ms without, {:.2} ms \
         with nonlinear events; ratio {:.2}",
        1e3 * t_plain.as_secs_f64() / n as f64,
        1e3 * t_nl.as_secs_f64() / n as f64,
        t_nl.as_secs_f64() / t_plain.as_secs_f64()
    );
}

fn bench_families(c: &mut Criterion) {
    let top = lagrange_top();
    let opts = ContinuationOptions::default();
    let d = bifurcation_diagram(|p| (top.clone(), p), (0.0, 5.0), &opts).expect("diagram");
    println!(
        "Lagrange top over p in [0, 5]: {} branches, {} points",
        d.branches.len(),
        d.branches.iter().map(|b| b.points.len()).sum::<usize>()
    );
    for e in &d.events {
        println!("  {e}");
    }
    let unchecked = ContinuationOptions {
        verify_counts: false,
        ..ContinuationOptions::default()
    };
    let mut group = c.benchmark_group("families");
    group.sample_size(10);
    group.bench_function("lagrange_top_diagram", |b| {
        b.iter(|| bifurcation_diagram(|p| (top.clone(), p), black_box((0.0, 5.0)), &opts))
    });
    group.bench_function("lagrange_top_diagram_without_count_checks", |b| {
        b.iter(|| bifurcation_diagram(|p| (top.clone(), p), black_box((0.0, 5.0)), &unchecked))
    });
    let oblate = oblate_asymmetric_top();
    // The defaults (count checks on), as a user would build either diagram.
    let plain = ContinuationOptions::default();
    let nl = ContinuationOptions {
        nonlinear: Some(NonlinearOptions::default()),
        ..ContinuationOptions::default()
    };
    let d = bifurcation_diagram(|p| (oblate.clone(), p), (1.9, 2.6), &nl).expect("diagram");
    println!("Oblate asymmetric top over p in [1.9, 2.6], nonlinear events:");
    for e in &d.events {
        println!("  {e}");
    }
    nonlinear_ratio(&oblate, &plain, &nl);
    group.bench_function("oblate_asymmetric_top_diagram", |b| {
        b.iter(|| bifurcation_diagram(|p| (oblate.clone(), p), black_box((1.9, 2.6)), &plain))
    });
    group.bench_function("oblate_asymmetric_top_diagram_with_nonlinear", |b| {
        b.iter(|| bifurcation_diagram(|p| (oblate.clone(), p), black_box((1.9, 2.6)), &nl))
    });
    group.finish();
}

criterion_group!(benches, bench_families);
criterion_main!(benches);
