//! Families of steady motions: the bifurcation diagram of a Lagrange top (A₁ = 1, C = 1.25,
//! mgl = 1, the derived gyrostat of `derived-models` with K = B = 0) over p_ψ ∈ [0, 5] — every
//! branch, its events located to 1e−10, and the count checks against global searches — and the
//! same diagram without count checks.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::Gyrostat;
use routh::{bifurcation_diagram, ContinuationOptions, Matrix3, Vector3};

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
    group.finish();
}

criterion_group!(benches, bench_families);
criterion_main!(benches);
