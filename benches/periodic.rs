//! Periodic orbits (docs/method.md §11, figures in docs/performance.md): a Lyapunov family of
//! 100 orbits with their multipliers on the derive's asymmetric heavy top and on the same model
//! read at run time (`routh::Model`, JIT), one orbit corrected by `periodic_orbit` against a
//! straightforward baseline (single shooting whose monodromy is built by finite differences of
//! `simulate_full`, six extra integrations per Newton step), and a Poincaré section of 50 orbits
//! × 200 crossings.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use derived_models::AsymmetricTop;
use routh::nalgebra::{SMatrix, SVector, Vector6};
use routh::{
    lyapunov_family, periodic_orbit, poincare_section, simulate_full, steady_motions, Lagrangian,
    Model, OrbitOptions, PeriodicOrbit, Routhian, SectionOptions, SimOptions, SteadyMotion,
    Vector3,
};

fn top() -> AsymmetricTop {
    AsymmetricTop {
        inertia: Vector3::new(1.0, 3.0, 6.0),
        com: Vector3::new(0.4, 0.3, 1.5),
        mass: 1.0,
        g: 1.0,
    }
}

fn runtime_top() -> Model {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/models/asymmetric_top.toml"
    );
    Model::from_file(path).expect("example model")
}

fn hanging<M: Routhian>(m: &M) -> SteadyMotion {
    steady_motions(m, 0.0)
        .expect("steady motions")
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .expect("a hanging position")
}

/// The baseline: Newton on `(x₀, T)` for `φ_T(x₀) = x₀` with the phase, energy, momentum and
/// `|γ|` rows, the monodromy by central differences of `simulate_full` (step 1e−6), least squares
/// by SVD. What one writes with an integrator and no derivatives of the vector field.
fn fd_shooting<M: Lagrangian>(m: &M, w0: Vector3<f64>, g0: Vector3<f64>, t0: f64) -> f64 {
    let opts = SimOptions::with_tolerances(1e-11, 1e-12);
    let flow = |x: &Vector6<f64>, t: f64| -> Vector6<f64> {
        let w = Vector3::new(x[0], x[1], x[2]);
        let g = Vector3::new(x[3], x[4], x[5]);
        let tr = simulate_full(m, w, g.normalize(), t, &opts).expect("flow");
        let n = tr.t.len() - 1;
        let (w, g) = (tr.omega[n], tr.gamma[n]);
        Vector6::new(w.x, w.y, w.z, g.x, g.y, g.z)
    };
    let state = |w: &Vector3<f64>, g: &Vector3<f64>| Vector6::new(w.x, w.y, w.z, g.x, g.y, g.z);
    let field = |x: &Vector6<f64>| -> Vector6<f64> {
        let w = Vector3::new(x[0], x[1], x[2]);
        let g = Vector3::new(x[3], x[4], x[5]);
        let (a, b) = routh::sim::full_vector_field(m, &w, &g).expect("field");
        Vector6::new(a.x, a.y, a.z, b.x, b.y, b.z)
    };
    let grad = |f: &dyn Fn(&Vector3<f64>, &Vector3<f64>) -> f64, x: &Vector6<f64>| {
        let h = 1e-7;
        Vector6::from_fn(|i, _| {
            let (mut p, mut q) = (*x, *x);
            p[i] += h;
            q[i] -= h;
            let s = |y: &Vector6<f64>| {
                f(
                    &Vector3::new(y[0], y[1], y[2]),
                    &Vector3::new(y[3], y[4], y[5]),
                )
            };
            (s(&p) - s(&q)) / (2.0 * h)
        })
    };
    let x_ref = state(&w0, &g0);
    let f_ref = field(&x_ref).normalize();
    let (e0, p0) = (m.energy(&w0, &g0), m.cyclic_momentum(&w0, &g0));
    let mut x = x_ref;
    let mut t = t0;
    for _ in 0..12 {
        let end = flow(&x, t);
        let mut r = SVector::<f64, 10>::zeros();
        let mut j = SMatrix::<f64, 10, 7>::zeros();
        for i in 0..6 {
            r[i] = end[i] - x[i];
        }
        let w = Vector3::new(x[0], x[1], x[2]);
        let g = Vector3::new(x[3], x[4], x[5]);
        r[6] = f_ref.dot(&(x - x_ref));
        r[7] = m.energy(&w, &g) - e0;
        r[8] = m.cyclic_momentum(&w, &g) - p0;
        r[9] = 0.5 * (g.norm_squared() - 1.0);
        if r.amax() < 1e-9 {
            break;
        }
        let h = 1e-6;
        for k in 0..6 {
            let (mut p, mut q) = (x, x);
            p[k] += h;
            q[k] -= h;
            let col = (flow(&p, t) - flow(&q, t)) / (2.0 * h);
            for i in 0..6 {
                j[(i, k)] = col[i] - if i == k { 1.0 } else { 0.0 };
            }
        }
        let fe = field(&end);
        for i in 0..6 {
            j[(i, 6)] = fe[i];
        }
        let de = grad(&|w, g| m.energy(w, g), &x);
        let dp = grad(&|w, g| m.cyclic_momentum(w, g), &x);
        for k in 0..6 {
            j[(6, k)] = f_ref[k];
            j[(7, k)] = de[k];
            j[(8, k)] = dp[k];
        }
        for k in 0..3 {
            j[(9, 3 + k)] = g[k];
        }
        let step = j.svd(true, true).solve(&r, 1e-12).expect("svd");
        for k in 0..6 {
            x[k] -= step[k];
        }
        t -= step[6];
    }
    t
}

fn bench_periodic(c: &mut Criterion) {
    let derived = top();
    let runtime = runtime_top();
    let s = hanging(&derived);
    let opts = OrbitOptions::default().with_max_orbits(100);
    let fam = lyapunov_family(&derived, &s, 0, &opts).expect("family");
    println!(
        "asymmetric top, mode 0 at the hanging position: {} orbits, {} events, stop {:?}",
        fam.orbits.len(),
        fam.events.len(),
        fam.stop
    );
    let rt = lyapunov_family(&runtime, &hanging(&runtime), 0, &opts).expect("family");
    let worst = fam
        .orbits
        .iter()
        .zip(&rt.orbits)
        .map(|(a, b)| (a.period - b.period).abs() / a.period)
        .fold(0.0, f64::max);
    println!(
        "run-time model: {} orbits, largest relative period difference {worst:e}",
        rt.orbits.len()
    );
    let o: &PeriodicOrbit = &fam.orbits[30];
    let tb = fd_shooting(&derived, o.omega0, o.gamma0, o.period * 1.01);
    println!(
        "one orbit: T = {} (periodic_orbit), {tb} (finite-difference shooting)",
        o.period
    );

    let mut group = c.benchmark_group("periodic");
    group.sample_size(10);
    group.bench_function("lyapunov_family_100_derive", |b| {
        b.iter(|| lyapunov_family(&derived, black_box(&s), 0, &opts))
    });
    let srt = hanging(&runtime);
    group.bench_function("lyapunov_family_100_runtime", |b| {
        b.iter(|| lyapunov_family(&runtime, black_box(&srt), 0, &opts))
    });
    let one = OrbitOptions::default();
    group.bench_function("one_orbit_periodic_orbit", |b| {
        b.iter(|| {
            periodic_orbit(
                &derived,
                o.omega0,
                o.gamma0,
                black_box(o.period * 1.01),
                &one,
            )
        })
    });
    group.bench_function("one_orbit_fd_shooting_baseline", |b| {
        b.iter(|| fd_shooting(&derived, o.omega0, o.gamma0, black_box(o.period * 1.01)))
    });
    let sec = SectionOptions::default().with_size(50, 200);
    let e = fam.orbits[20].energy;
    group.bench_function("poincare_section_50x200", |b| {
        b.iter(|| poincare_section(&derived, 0.0, black_box(e), &sec))
    });
    group.finish();
}

criterion_group!(benches, bench_periodic);
criterion_main!(benches);
