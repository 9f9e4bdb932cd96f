//! `routh::stability_atlas`: the 101 × 101 atlas of the sleeping Lagrange top (A₁ = 1, C = 1.2,
//! the derived gyrostat of `derived-models` with J = diag(1, 1, 1.2), r = e₃) over
//! (mgl, p_ψ) ∈ [0.5, 2] × [0.5, 5], with its two boundary curves (Maievskii's bound and the
//! secular bound), on one thread and on all cores.

use std::hint::black_box;
use std::time::Instant;

use criterion::{criterion_group, criterion_main, Criterion};
use routh::{stability_atlas, stability_atlas_parallel, AtlasOptions, StabilityAtlas, Vector3};

fn atlas(threads: usize) -> StabilityAtlas {
    let opts = AtlasOptions {
        nx: 101,
        ny: 101,
        threads,
        ..AtlasOptions::default()
    };
    let family = |mgl: f64, p: f64| {
        let top = test_models::Gyrostat::lagrange_top(1.0, 1.2, mgl);
        (derived_models::Gyrostat::from(&top), p)
    };
    if threads == 1 {
        stability_atlas(family, Vector3::z(), (0.5, 2.0), (0.5, 5.0), &opts).expect("atlas")
    } else {
        stability_atlas_parallel(family, Vector3::z(), (0.5, 2.0), (0.5, 5.0), &opts)
            .expect("atlas")
    }
}

fn bench_atlas(c: &mut Criterion) {
    let t = Instant::now();
    let a = atlas(0);
    println!(
        "101 × 101 Lagrange-top atlas: {} boundary curves ({} points) in {:.3} s",
        a.boundaries.len(),
        a.boundaries.iter().map(|b| b.points.len()).sum::<usize>(),
        t.elapsed().as_secs_f64()
    );
    for b in &a.boundaries {
        println!("  {}: {} points", b.kind, b.points.len());
    }
    let mut group = c.benchmark_group("atlas");
    group.sample_size(10);
    group.bench_function("lagrange_101x101_threads_1", |b| {
        b.iter(|| atlas(black_box(1)))
    });
    group.bench_function("lagrange_101x101_threads_all", |b| {
        b.iter(|| atlas(black_box(0)))
    });
    group.finish();
}

criterion_group!(benches, bench_atlas);
criterion_main!(benches);
