//! Steady motions and their stability: `routh::steady_motions` (global search of the critical
//! points of the amended potential on S²) followed by `routh::classify` of every motion found,
//! for a generic asymmetric gyrostat (derived model M1 of `derived-models`) at p_ψ = 3.

mod common;

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use routh::{classify, steady_motions, StabilityReport, SteadyMotion};

const P_PSI: f64 = 3.0;

fn analyse(model: &derived_models::Gyrostat, p_psi: f64) -> Vec<(SteadyMotion, StabilityReport)> {
    let motions = steady_motions(model, p_psi).expect("steady motions");
    motions
        .into_iter()
        .map(|s| {
            let report = classify(model, &s).expect("classify");
            (s, report)
        })
        .collect()
}

fn bench_steady(c: &mut Criterion) {
    let (model, _) = common::m1(&mut common::rng(0x57EAD));
    let found = analyse(&model, P_PSI);
    println!(
        "generic gyrostat at p_psi = {P_PSI}: {} steady motions",
        found.len()
    );
    for (s, r) in &found {
        println!(
            "  gamma = [{:+.4}, {:+.4}, {:+.4}]  psi_dot = {:+.4}  U_r = {:+.4}  {:?}",
            s.gamma.x, s.gamma.y, s.gamma.z, s.psi_dot, s.amended_potential, r.verdict
        );
    }
    let motions: Vec<SteadyMotion> = found.into_iter().map(|(s, _)| s).collect();

    let mut group = c.benchmark_group("steady");
    group.sample_size(20);
    group.bench_function("steady_motions+classify", |b| {
        b.iter(|| analyse(black_box(&model), black_box(P_PSI)))
    });
    group.bench_function("classify_only", |b| {
        b.iter(|| {
            motions
                .iter()
                .map(|s| classify(black_box(&model), s).expect("classify"))
                .collect::<Vec<_>>()
        })
    });
    group.finish();
}

criterion_group!(benches, bench_steady);
criterion_main!(benches);
