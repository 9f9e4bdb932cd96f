//! `routh::Model` (the DSL read at run time, tapes evaluated by the interpreter) against the
//! derive's generated code on the same models: one `bundle`, and `steady_motions` + `classify`,
//! for the heavy (Lagrange) top, the Kelvin gyrostat and the spheroid on a plane; and the time
//! to build a `Model` from text (parse, check, differentiate, reduce, tape, bind). Figures in
//! docs/performance.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::{Ellipsoid, Gyrostat, LagrangeTop};
use routh::{classify, steady_motions, Model, Routhian, Vector3};

fn models() -> [(&'static str, Model); 3] {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/models/");
    let load = |f: &str| Model::from_file(format!("{dir}{f}")).expect("example model");
    [
        ("heavy_top", load("heavy_top.toml")),
        ("gyrostat", load("gyrostat.toml")),
        ("ellipsoid", load("ellipsoid.toml")),
    ]
}

fn analyse<M: Routhian>(model: &M, p: f64) -> Vec<routh::StabilityReport> {
    let motions = steady_motions(model, p).expect("steady motions");
    motions
        .iter()
        .map(|s| classify(model, s).expect("classify"))
        .collect()
}

fn bench_pair<D: Routhian>(c: &mut Criterion, name: &str, derived: &D, runtime: &Model, p: f64) {
    let w = Vector3::new(0.3, -0.2, 0.5);
    let g = Vector3::new(0.36, 0.48, 0.8);
    let mut group = c.benchmark_group(format!("runtime_model/{name}"));
    group.bench_function("bundle/derive", |b| {
        b.iter(|| black_box(derived.bundle(black_box(&w), black_box(&g), black_box(p))))
    });
    group.bench_function("bundle/runtime", |b| {
        b.iter(|| black_box(runtime.bundle(black_box(&w), black_box(&g), black_box(p))))
    });
    group.sample_size(10);
    group.bench_function("steady+classify/derive", |b| {
        b.iter(|| black_box(analyse(derived, black_box(p))))
    });
    group.bench_function("steady+classify/runtime", |b| {
        b.iter(|| black_box(analyse(runtime, black_box(p))))
    });
    group.finish();
}

fn bench_runtime_model(c: &mut Criterion) {
    let [(_, top), (_, gyro), (_, ell)] = models();
    bench_pair(c, "heavy_top", &LagrangeTop::example(), &top, 2.2);
    bench_pair(c, "gyrostat", &Gyrostat::kelvin(), &gyro, 3.5);
    bench_pair(c, "ellipsoid", &Ellipsoid::spheroid(), &ell, 5.0);

    let mut group = c.benchmark_group("runtime_model/build");
    group.sample_size(10);
    for (name, m) in models() {
        let text = m.lagrangian_text().to_string();
        let params: Vec<(String, routh::Param)> = m.parameters().to_vec();
        let sym: Vec<&str> = m.symmetric().iter().map(String::as_str).collect();
        group.bench_function(name, |b| {
            b.iter(|| {
                let p: Vec<(&str, routh::Param)> =
                    params.iter().map(|(n, v)| (n.as_str(), *v)).collect();
                black_box(Model::with_symmetric(black_box(&text), &p, &sym).expect("model"))
            })
        });
        group.bench_function(format!("{name}/set"), |b| {
            let mut m = m.clone();
            let (n, v) = params[0].clone();
            b.iter(|| m.set(&n, black_box(v)).expect("set"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_runtime_model);
criterion_main!(benches);
