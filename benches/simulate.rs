//! Simulation throughput: `routh::simulate_full` (adaptive DOP853 at the default tolerances,
//! rtol = 1e-10, atol = 1e-12) of a heavy asymmetric top over t ∈ [0, 10]. Criterion's
//! throughput is in accepted steps ("elem/s" = steps/s).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use derived_models::AsymmetricTop;
use routh::{simulate_full, SimOptions, Vector3};

const T_END: f64 = 10.0;

fn bench_simulate(c: &mut Criterion) {
    let top = AsymmetricTop {
        inertia: Vector3::new(2.0, 2.5, 1.0),
        com: Vector3::new(0.05, 0.02, 0.5),
        mass: 1.0,
        g: 9.81,
    };
    let omega0 = Vector3::new(0.3, -0.2, 6.0);
    let gamma0 = Vector3::new(0.3, 0.0, 1.0).normalize();
    let opts = SimOptions::default();
    let traj = simulate_full(&top, omega0, gamma0, T_END, &opts).expect("simulation");
    let steps = traj.stats.accepted_steps as u64;
    println!(
        "heavy top, t in [0, {T_END}]: {} accepted steps, {} rejected, {} rhs evaluations; \
         energy drift {:.1e}, p_psi drift {:.1e}, | |gamma|^2 - 1 | {:.1e}",
        traj.stats.accepted_steps,
        traj.stats.rejected_steps,
        traj.stats.rhs_evaluations,
        traj.energy_drift(),
        traj.p_psi_drift(),
        traj.gamma_norm_error(),
    );

    let mut group = c.benchmark_group("simulate_full");
    group.sample_size(20);
    group.throughput(Throughput::Elements(steps));
    group.bench_function("heavy_top_t10", |b| {
        b.iter(|| {
            simulate_full(
                black_box(&top),
                black_box(omega0),
                black_box(gamma0),
                T_END,
                &opts,
            )
            .expect("simulation")
        })
    });
    group.finish();
}

criterion_group!(benches, bench_simulate);
criterion_main!(benches);
