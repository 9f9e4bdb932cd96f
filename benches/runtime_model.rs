//! `routh::Model` (the DSL read at run time) against the derive's generated code on the same
//! models, in the same run: the model's tapes compiled by the JIT (the default) and interpreted
//! (`Model::interpreted`). One `bundle`, `steady_motions` + `classify`, for the heavy (Lagrange)
//! top, the Kelvin gyrostat and the spheroid on a plane; the bifurcation diagram of the
//! Lagrange top; the bundle tape compiled with its parameters folded in as constants against
//! passed by pointer (what a `Model` does); the time to build a `Model` from text (parse,
//! check, differentiate, reduce, tape: nothing is compiled until a tape is first evaluated),
//! to build it and evaluate a first `bundle` (which compiles the bundle's tape) or a first
//! analysis, and to change one parameter (`set`, `with`: values only). Figures in
//! docs/performance.md.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::{Ellipsoid, Gyrostat, LagrangeTop};
use routh::{
    bifurcation_diagram, classify, steady_motions, ContinuationOptions, Evaluation, Model,
    Routhian, Vector3,
};
use routh_jit::JitFunction;

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

fn bench_pair<D: Routhian>(c: &mut Criterion, name: &str, derived: &D, jit: &Model, p: f64) {
    assert_eq!(jit.evaluation(), Evaluation::Jit);
    let interp = jit.interpreted().expect("interpreter");
    let fast = jit.jit(false).expect("unoptimized JIT");
    let w = Vector3::new(0.3, -0.2, 0.5);
    let g = Vector3::new(0.36, 0.48, 0.8);
    let mut group = c.benchmark_group(format!("runtime_model/{name}"));
    group.bench_function("bundle/derive", |b| {
        b.iter(|| black_box(derived.bundle(black_box(&w), black_box(&g), black_box(p))))
    });
    group.bench_function("bundle/jit", |b| {
        b.iter(|| black_box(jit.bundle(black_box(&w), black_box(&g), black_box(p))))
    });
    group.bench_function("bundle/jit_unoptimized", |b| {
        b.iter(|| black_box(fast.bundle(black_box(&w), black_box(&g), black_box(p))))
    });
    group.bench_function("bundle/interpreter", |b| {
        b.iter(|| black_box(interp.bundle(black_box(&w), black_box(&g), black_box(p))))
    });
    group.bench_function("bundle_and_system/derive", |b| {
        b.iter(|| black_box(derived.bundle_and_system(black_box(&w), black_box(&g), black_box(p))))
    });
    group.bench_function("bundle_and_system/jit", |b| {
        b.iter(|| black_box(jit.bundle_and_system(black_box(&w), black_box(&g), black_box(p))))
    });
    // The bundle's tape alone, called directly: parameters folded in as constants against read
    // from the input buffer at run time (what a Model does).
    let tape = jit.tape("bundle").expect("bundle tape");
    let values = jit.tape_parameters().expect("parameters");
    let folded = JitFunction::compile(&tape.bind(&values).expect("bind")).expect("jit");
    let open = JitFunction::compile(tape).expect("jit");
    let x = [w.x, w.y, w.z, g.x, g.y, g.z, p];
    let mut with_params = x.to_vec();
    with_params.extend_from_slice(&values);
    group.bench_function("bundle_tape/params_folded", |b| {
        let mut out = [0.0; 36];
        b.iter(|| {
            folded.eval(black_box(&x), &mut out).expect("eval");
            black_box(out[0])
        })
    });
    group.bench_function("bundle_tape/params_by_pointer", |b| {
        let mut out = [0.0; 36];
        b.iter(|| {
            open.eval(black_box(&with_params), &mut out).expect("eval");
            black_box(out[0])
        })
    });
    group.sample_size(10);
    group.bench_function("steady+classify/derive", |b| {
        b.iter(|| black_box(analyse(derived, black_box(p))))
    });
    group.bench_function("steady+classify/jit", |b| {
        b.iter(|| black_box(analyse(jit, black_box(p))))
    });
    group.bench_function("steady+classify/jit_unoptimized", |b| {
        b.iter(|| black_box(analyse(&fast, black_box(p))))
    });
    group.bench_function("steady+classify/interpreter", |b| {
        b.iter(|| black_box(analyse(&interp, black_box(p))))
    });
    group.finish();
}

fn bench_runtime_model(c: &mut Criterion) {
    let [(_, top), (_, gyro), (_, ell)] = models();
    bench_pair(c, "heavy_top", &LagrangeTop::example(), &top, 2.2);
    bench_pair(c, "gyrostat", &Gyrostat::kelvin(), &gyro, 3.5);
    bench_pair(c, "ellipsoid", &Ellipsoid::spheroid(), &ell, 5.0);

    // The bifurcation diagram of the Lagrange top over p_ψ ∈ [0, 5], count checks included.
    let opts = ContinuationOptions::default();
    let derived = LagrangeTop::example();
    let interp = top.interpreted().expect("interpreter");
    let fast = top.jit(false).expect("unoptimized JIT");
    let mut group = c.benchmark_group("runtime_model/heavy_top_diagram");
    group.sample_size(10);
    group.bench_function("derive", |b| {
        b.iter(|| bifurcation_diagram(|p| (derived.clone(), p), black_box((0.0, 5.0)), &opts))
    });
    group.bench_function("jit", |b| {
        b.iter(|| bifurcation_diagram(|p| (top.clone(), p), black_box((0.0, 5.0)), &opts))
    });
    group.bench_function("jit_unoptimized", |b| {
        b.iter(|| bifurcation_diagram(|p| (fast.clone(), p), black_box((0.0, 5.0)), &opts))
    });
    group.bench_function("interpreter", |b| {
        b.iter(|| bifurcation_diagram(|p| (interp.clone(), p), black_box((0.0, 5.0)), &opts))
    });
    group.finish();

    let mut group = c.benchmark_group("runtime_model/build");
    group.sample_size(10);
    for (name, m) in models() {
        let text = m.lagrangian_text().to_string();
        let params: Vec<(String, routh::Param)> = m.parameters().to_vec();
        let sym: Vec<&str> = m.symmetric().iter().map(String::as_str).collect();
        let build = || {
            let p: Vec<(&str, routh::Param)> =
                params.iter().map(|(n, v)| (n.as_str(), *v)).collect();
            Model::with_symmetric(black_box(&text), &p, &sym).expect("model")
        };
        group.bench_function(name, |b| b.iter(|| black_box(build())));
        let w = Vector3::new(0.3, -0.2, 0.5);
        let g = Vector3::new(0.36, 0.48, 0.8);
        // Build, then the first bundle: the bundle's tape compiled on the way.
        group.bench_function(format!("{name}/first_bundle"), |b| {
            b.iter(|| {
                let m = build();
                black_box(m.bundle(&w, &g, 2.0))
            })
        });
        // Build, then steady motions and their classification: the tapes they use compiled.
        group.bench_function(format!("{name}/first_analysis"), |b| {
            b.iter(|| black_box(analyse(&build(), 2.0)))
        });
        let (n, v) = params[0].clone();
        group.bench_function(format!("{name}/set/jit"), |b| {
            let mut m = m.clone();
            b.iter(|| m.set(&n, black_box(v)).expect("set"))
        });
        group.bench_function(format!("{name}/with/jit"), |b| {
            b.iter(|| black_box(m.with(&n, black_box(v)).expect("with")))
        });
        group.bench_function(format!("{name}/set/interpreter"), |b| {
            let mut m = m.interpreted().expect("interpreter");
            b.iter(|| m.set(&n, black_box(v)).expect("set"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench_runtime_model);
criterion_main!(benches);
