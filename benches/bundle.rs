//! Generated `bundle_and_system` vs the expert's hand-written one vs num-dual Hessians of the
//! same R (docs/performance.md).
//!
//! Every measured function evaluates all the outputs a caller of the analysis uses at one point:
//! the bundle (R, ψ̇, ∂R/∂Ω, ∂R/∂γ, ∂R/∂p_ψ and the three Hessian blocks) and A, G, C of (64)
//! formed from it. One iteration is one evaluation, cycling through 64 precomputed random
//! points, so criterion's time per iteration is ns/eval.
//!
//! - `M1_gyrostat/{generated,hand,generated_composed,hand_composed,numdual}`: gyrostat with full
//!   symmetric I, K, general B, U = m g r·γ. `generated` is the derived `bundle_and_system` (one
//!   straight-line body); `hand` is `test_models::hand_gyrostat_bundle_and_system` (every output
//!   written out by hand, A, G, C inline from its locals: the expert baseline);
//!   `*_composed` are the same bundles followed by `GyroscopicSystem::from_bundle` (the path
//!   every caller took before `bundle_and_system`, and the default for hand-written models);
//!   `numdual` is `test_models::numdual_bundle` (one second-order num-dual Hessian over (Ω, γ))
//!   then `from_bundle`.
//! - `M2_ellipsoid/{generated,generated_composed,numdual}`: heavy ellipsoid on a plane with
//!   diagonal I.
//!
//! After criterion, `same-run ratios` times every variant again in this process (interleaved,
//! median of 301 samples) and prints the ratios.

mod common;

use std::hint::black_box;
use std::time::Instant;

use common::Point;
use criterion::{criterion_group, BenchmarkGroup, Criterion};
use routh::{GyroscopicSystem, RouthBundle, Routhian};
use test_models::{hand_gyrostat_bundle_and_system, hand_gyrostat_system, numdual_bundle};

const N_POINTS: usize = 64;

type Output = (RouthBundle, GyroscopicSystem);

/// `bundle` then `GyroscopicSystem::from_bundle`.
#[inline(always)]
fn with_system(bundle: RouthBundle, pt: &Point) -> Output {
    let system = GyroscopicSystem::from_bundle(&bundle, &pt.gamma);
    (bundle, system)
}

struct Setup {
    pts: Vec<Point>,
    m1: derived_models::Gyrostat,
    m1_twin: test_models::Gyrostat,
    m2: derived_models::DiagonalEllipsoid,
    m2_twin: test_models::Ellipsoid,
}

impl Setup {
    fn new() -> Self {
        let mut rng = common::rng(0xB0D1E5);
        let (m1, m1_twin) = common::m1(&mut rng);
        let (m2, m2_twin) = common::m2(&mut rng);
        let pts = common::points(&mut rng, N_POINTS);
        let s = Setup {
            pts,
            m1,
            m1_twin,
            m2,
            m2_twin,
        };
        s.check();
        s
    }

    fn m1_generated(&self, pt: &Point) -> Output {
        self.m1
            .bundle_and_system(&pt.big_omega, &pt.gamma, pt.p_psi)
    }
    fn m1_hand(&self, pt: &Point) -> Output {
        hand_gyrostat_bundle_and_system(&self.m1_twin, &pt.big_omega, &pt.gamma, pt.p_psi)
    }
    fn m1_generated_composed(&self, pt: &Point) -> Output {
        with_system(self.m1.bundle(&pt.big_omega, &pt.gamma, pt.p_psi), pt)
    }
    fn m1_hand_composed(&self, pt: &Point) -> Output {
        hand_gyrostat_system(&self.m1_twin, &pt.big_omega, &pt.gamma, pt.p_psi)
    }
    fn m1_numdual(&self, pt: &Point) -> Output {
        with_system(
            numdual_bundle(&self.m1_twin, &pt.big_omega, &pt.gamma, pt.p_psi),
            pt,
        )
    }
    fn m2_generated(&self, pt: &Point) -> Output {
        self.m2
            .bundle_and_system(&pt.big_omega, &pt.gamma, pt.p_psi)
    }
    fn m2_generated_composed(&self, pt: &Point) -> Output {
        with_system(self.m2.bundle(&pt.big_omega, &pt.gamma, pt.p_psi), pt)
    }
    fn m2_numdual(&self, pt: &Point) -> Output {
        with_system(
            numdual_bundle(&self.m2_twin, &pt.big_omega, &pt.gamma, pt.p_psi),
            pt,
        )
    }

    /// The variants agree (so that the benches compare equal work).
    fn check(&self) {
        fn flat((b, s): &Output) -> Vec<f64> {
            let mut v = vec![b.routhian, b.psi_dot, b.dr_dp];
            for x in [&b.dr_domega, &b.dr_dgamma] {
                v.extend(x.iter());
            }
            for x in [
                &b.d2r_domega2,
                &b.d2r_domega_dgamma,
                &b.d2r_dgamma2,
                &s.a,
                &s.g,
                &s.c,
            ] {
                v.extend(x.iter());
            }
            v
        }
        fn assert_close(what: &str, a: &Output, b: &Output) {
            // ‖a − b‖∞ ≤ 1e−10 · max(‖b‖∞, 1), and a finite.
            test_models::compare::close(&flat(a), &flat(b), 1e-10, 1.0)
                .unwrap_or_else(|e| panic!("{what}: {e}"));
        }
        for pt in &self.pts {
            let m1 = self.m1_numdual(pt);
            assert_close("M1 generated", &self.m1_generated(pt), &m1);
            assert_close("M1 hand", &self.m1_hand(pt), &m1);
            assert_close(
                "M1 generated composed",
                &self.m1_generated_composed(pt),
                &m1,
            );
            assert_close("M1 hand composed", &self.m1_hand_composed(pt), &m1);
            let m2 = self.m2_numdual(pt);
            assert_close("M2 generated", &self.m2_generated(pt), &m2);
            assert_close(
                "M2 generated composed",
                &self.m2_generated_composed(pt),
                &m2,
            );
        }
    }
}

/// One measured function: the bundle and A, G, C of one model at one point.
type Eval = fn(&Setup, &Point) -> Output;
type Variant = (&'static str, Eval);

const M1_VARIANTS: [Variant; 5] = [
    ("generated", Setup::m1_generated),
    ("hand", Setup::m1_hand),
    ("generated_composed", Setup::m1_generated_composed),
    ("hand_composed", Setup::m1_hand_composed),
    ("numdual", Setup::m1_numdual),
];
const M2_VARIANTS: [Variant; 3] = [
    ("generated", Setup::m2_generated),
    ("generated_composed", Setup::m2_generated_composed),
    ("numdual", Setup::m2_numdual),
];

fn bench_variant<M: criterion::measurement::Measurement>(
    group: &mut BenchmarkGroup<'_, M>,
    setup: &Setup,
    (name, f): Variant,
) {
    group.bench_function(name, |b| {
        let mut k = 0usize;
        b.iter(|| {
            let pt = &setup.pts[k % N_POINTS];
            k = k.wrapping_add(1);
            f(setup, black_box(pt))
        })
    });
}

fn bench_bundle(c: &mut Criterion) {
    let setup = Setup::new();
    let mut group = c.benchmark_group("M1_gyrostat");
    for v in M1_VARIANTS {
        bench_variant(&mut group, &setup, v);
    }
    group.finish();
    let mut group = c.benchmark_group("M2_ellipsoid");
    for v in M2_VARIANTS {
        bench_variant(&mut group, &setup, v);
    }
    group.finish();
}

/// ns/eval of every variant, timed in this process. Every sample is a whole number of sweeps
/// over the 64 points lasting about 200 µs for every variant (so that preemption by other
/// processes, which the shared 2-core machine sees a lot of, hits all variants alike), and the
/// variants are interleaved sample by sample. Prints the median and the minimum over 301
/// samples, and the ratios of both.
fn same_run_ratios() {
    const SAMPLES: usize = 301;
    const SAMPLE_NS: f64 = 200_000.0;
    let setup = Setup::new();
    let variants: Vec<(String, Eval)> = M1_VARIANTS
        .iter()
        .map(|(n, f)| (format!("M1 {n}"), *f))
        .chain(M2_VARIANTS.iter().map(|(n, f)| (format!("M2 {n}"), *f)))
        .collect();
    let time = |f: Eval, sweeps: usize| {
        let start = Instant::now();
        for _ in 0..sweeps {
            for pt in &setup.pts {
                black_box(f(&setup, black_box(pt)));
            }
        }
        start.elapsed().as_nanos() as f64 / (sweeps * N_POINTS) as f64
    };
    // Calibration (also the warm-up): the fastest of 20 single sweeps.
    let sweeps: Vec<usize> = variants
        .iter()
        .map(|(_, f)| {
            let ns = (0..20).map(|_| time(*f, 1)).fold(f64::INFINITY, f64::min);
            ((SAMPLE_NS / (ns * N_POINTS as f64)).round() as usize).max(1)
        })
        .collect();
    let mut samples = vec![Vec::with_capacity(SAMPLES); variants.len()];
    for _ in 0..SAMPLES {
        for (i, (_, f)) in variants.iter().enumerate() {
            samples[i].push(time(*f, sweeps[i]));
        }
    }
    for v in &mut samples {
        v.sort_by(f64::total_cmp);
    }
    let med: Vec<f64> = samples.iter().map(|v| v[v.len() / 2]).collect();
    let min: Vec<f64> = samples.iter().map(|v| v[0]).collect();
    let idx = |name: &str| variants.iter().position(|(n, _)| n == name).unwrap();
    println!();
    println!(
        "same-run ratios ({SAMPLES} interleaved samples of ~{:.0} us each; \
         ns per bundle + A, G, C):",
        SAMPLE_NS / 1e3
    );
    println!("  {:<24} {:>10} {:>10}", "", "median", "min");
    for (i, (name, _)) in variants.iter().enumerate() {
        println!("  {name:<24} {:>10.1} {:>10.1}", med[i], min[i]);
    }
    for (label, num, den) in [
        (
            "M1 generated / hand                  ",
            "M1 generated",
            "M1 hand",
        ),
        (
            "M1 generated composed / hand         ",
            "M1 generated_composed",
            "M1 hand",
        ),
        (
            "M1 hand composed / hand              ",
            "M1 hand_composed",
            "M1 hand",
        ),
        (
            "M2 generated composed / generated    ",
            "M2 generated_composed",
            "M2 generated",
        ),
        (
            "M2 num-dual / generated              ",
            "M2 numdual",
            "M2 generated",
        ),
        (
            "M1 num-dual / generated              ",
            "M1 numdual",
            "M1 generated",
        ),
    ] {
        let (n, d) = (idx(num), idx(den));
        println!(
            "  {label} = {:8.3} (median)  {:8.3} (min)",
            med[n] / med[d],
            min[n] / min[d]
        );
    }
}

criterion_group!(benches, bench_bundle);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // Only when benchmarking (`cargo bench`), not in `cargo test --benches`.
    if std::env::args().any(|a| a == "--bench") {
        same_run_ratios();
    }
}
