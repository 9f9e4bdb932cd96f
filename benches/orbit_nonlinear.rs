//! Orbital stability beyond linear (docs/method.md §12), same-run ratios:
//! `orbit_nonlinear_stability` against one `periodic_orbit` correction of the same orbit; a
//! Lyapunov family of 40 orbits with and without `OrbitOptions::nonlinear` (the twist of every
//! orbit and the nonlinear events); an `orbit_chart` of 40 parameter values of the 1 : 4 : 1
//! body of examples/models/body_141.toml.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::AsymmetricTop;
use routh::{
    lyapunov_family, orbit_chart, orbit_nonlinear_stability, periodic_orbit, steady_motions, Model,
    OrbitChartOptions, OrbitNonlinearOptions, OrbitOptions, Routhian, SteadyMotion, Vector3,
};

fn top() -> AsymmetricTop {
    AsymmetricTop {
        inertia: Vector3::new(1.0, 3.0, 6.0),
        com: Vector3::new(0.4, 0.3, 1.5),
        mass: 1.0,
        g: 1.0,
    }
}

fn hanging<M: Routhian>(m: &M) -> SteadyMotion {
    steady_motions(m, 0.0)
        .expect("steady motions")
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .expect("a hanging position")
}

fn bench_orbit_nonlinear(c: &mut Criterion) {
    let m = top();
    let s = hanging(&m);
    let opts = OrbitOptions::default().with_max_orbits(40);
    let fam = lyapunov_family(&m, &s, 0, &opts).expect("family");
    let o = fam
        .orbits
        .iter()
        .rev()
        .find(|o| o.stability == routh::OrbitStability::Elliptic)
        .expect("an elliptic orbit")
        .clone();
    let mut group = c.benchmark_group("orbit_nonlinear");
    group.sample_size(10);
    group.bench_function("orbit_nonlinear_stability", |b| {
        b.iter(|| orbit_nonlinear_stability(&m, black_box(&o), &OrbitNonlinearOptions::default()))
    });
    group.bench_function("periodic_orbit_same_orbit", |b| {
        b.iter(|| {
            periodic_orbit(
                &m,
                black_box(o.omega0),
                o.gamma0,
                o.period,
                &OrbitOptions::default(),
            )
        })
    });
    group.bench_function("family_40_linear", |b| {
        b.iter(|| lyapunov_family(&m, black_box(&s), 0, &opts))
    });
    let nonlinear = OrbitOptions {
        nonlinear: true,
        ..opts.clone()
    };
    group.bench_function("family_40_nonlinear", |b| {
        b.iter(|| lyapunov_family(&m, black_box(&s), 0, &nonlinear))
    });
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/models/body_141.toml");
    let body = Model::from_file(path).expect("example model");
    let chart_opts = OrbitChartOptions {
        nx: 40,
        ..OrbitChartOptions::default()
    };
    group.bench_function("orbit_chart_40", |b| {
        b.iter(|| {
            orbit_chart(
                |x| (body.with("alpha", x).expect("alpha"), 0.0),
                -Vector3::z(),
                0,
                (0.2, 1.4),
                (0.0, 1.9),
                &chart_opts,
            )
        })
    });
    group.finish();
}

criterion_group!(benches, bench_orbit_nonlinear);
criterion_main!(benches);
