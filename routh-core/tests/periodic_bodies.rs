//! Periodic orbits of the bodies a dynamicist tries first (docs/method.md §11–§11a), each checked
//! against what routh does not compute: spinning tops' first orbits closed by `simulate_full`,
//! the symmetric body's planar swings against the pendulum's `4K(m)/ω₀`, the Lagrange top's
//! nutations against the quadrature of its cubic (period, Δψ, Δφ), the minimal period and the
//! first orbit's nonlinear period against the elliptic integral, and the ranges' errors.

use crate::common::{closure_gap, elliptic_k, heavy_body as body, HeavyTop};
use routh_core::{
    axial_symmetry, continue_orbit, lyapunov_family, orbit_crossings, orbit_path,
    period_doubled_family, periodic_orbit, steady_motions, Matrix3, OrbitEvent, OrbitEventKind,
    OrbitOptions, SectionOptions, SteadyMotion, Vector3,
};
use std::f64::consts::PI;

fn steady_at(m: &HeavyTop, p_psi: f64, gamma3: f64) -> SteadyMotion {
    steady_motions(m, p_psi)
        .unwrap()
        .into_iter()
        .find(|s| (s.gamma.z - gamma3).abs() < 1e-6)
        .expect("the steady motion on the axis")
}

fn wrap(a: f64) -> f64 {
    let r = a.rem_euclid(2.0 * PI);
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}

/// (2) Spinning steady motions: the first orbit of both Lyapunov families converges with the
/// default tolerances at amplitudes 1e−4 … 1e−2 from the README's sleeping Lagrange top (A = 1,
/// C = 1.25, mgl = 1, p_ψ = 3) and from upright asymmetric tops (secularly and gyroscopically
/// stable), closes under `simulate_full`, keeps p_ψ, and its period tends to the linear one as
/// the amplitude squared.
#[test]
fn spinning_tops_start_their_families() {
    let cases = [
        (HeavyTop::lagrange(1.0, 1.25, 1.0), 3.0),
        (body(1.0, 1.3, 2.0, 1.0), 4.0),
        (body(1.0, 1.3, 0.6, 1.0), 4.0),
    ];
    for (m, p_psi) in cases {
        let s = steady_at(&m, p_psi, 1.0);
        for mode in 0..2 {
            let mut periods = Vec::new();
            for amp in [1e-4, 1e-3, 1e-2] {
                let opts = OrbitOptions {
                    initial_amplitude: amp,
                    max_orbits: 6,
                    ..OrbitOptions::default()
                };
                let f = lyapunov_family(&m, &s, mode, &opts)
                    .unwrap_or_else(|e| panic!("p_ψ = {p_psi}, mode {mode}, amplitude {amp}: {e}"));
                assert_eq!(f.orbits.len(), 6, "the family goes on: {:?}", f.stop);
                for o in &f.orbits {
                    // The corrector stops at newton_tol (1e−9) times max(1, |x₀|) per row; a
                    // spinning top's |ω| is 2.4–4.
                    let gap = closure_gap(&m, o) / o.omega0.norm().max(1.0);
                    assert!(gap < 1e-8, "mode {mode}, amplitude {amp}: gap {gap:e}");
                    assert!(
                        (o.p_psi - p_psi).abs() <= 1e-11 * p_psi,
                        "p_ψ = {}",
                        o.p_psi
                    );
                }
                periods.push(f.orbits[0].period);
            }
            // T(a) = T₀ + c a² + …: the differences scale by 100 per decade of amplitude.
            let (d1, d2) = (periods[1] - periods[0], periods[2] - periods[1]);
            let ratio = d2 / d1;
            assert!(
                (ratio / 100.0 - 1.0).abs() < 0.05,
                "p_ψ = {p_psi}, mode {mode}: periods {periods:?}"
            );
        }
    }
}

/// (3) The axial symmetry is read off the model: the Lagrange top has it; Kovalevskaya's body
/// (A₁ = A₂, centre of mass off the axis) and a body 1e−8 off A₁ = A₂ have not.
#[test]
fn axial_symmetry_is_detected() {
    assert!(axial_symmetry(&HeavyTop::lagrange(1.0, 0.6, 2.0)));
    let kovalevskaya = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 1.0)),
        mgr: Vector3::new(1.0, 0.0, 0.0),
    };
    assert!(!axial_symmetry(&kovalevskaya));
    assert!(!axial_symmetry(&body(1.0, 1.0 + 1e-8, 0.6, 2.0)));
    assert!(!axial_symmetry(&body(1.0, 1.6, 2.3, 1.0)));
}

/// (3) The hanging symmetric body at p_ψ = 0: its Lyapunov family (mode 0) is its planar swings,
/// each a pendulum of period `4K(sin²(θ₀/2))/ω₀`, `ω₀ = √(mgl/A)`, in one vertical plane, with no
/// precession and no body turn, reported degenerate (the body is integrable) with no events;
/// mode 1 is the same family, an error that says so.
#[test]
fn the_symmetric_body_swings_in_planes() {
    let (a, c, mgl) = (1.0, 0.6, 2.0);
    let m = HeavyTop::lagrange(a, c, mgl);
    let s = steady_at(&m, 0.0, -1.0);
    let opts = OrbitOptions {
        max_orbits: 60,
        energy_bounds: Some((-mgl, 1.5)),
        ..OrbitOptions::default()
    };
    let f = lyapunov_family(&m, &s, 0, &opts).unwrap();
    assert!(
        f.orbits.len() >= 20,
        "{} orbits, {:?}",
        f.orbits.len(),
        f.stop
    );
    assert!(f.events.is_empty(), "spurious events: {:?}", f.events);
    let w0 = (mgl / a).sqrt();
    for o in &f.orbits {
        let theta0 = (-o.energy / mgl).acos();
        let exact = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / w0;
        assert!(
            (o.period - exact).abs() <= 1e-8 * exact,
            "E = {}: T = {} vs 4K/ω₀ = {exact}",
            o.energy,
            o.period
        );
        assert!(o.degenerate && o.stability_index == 1.0);
        assert!(o.precession.abs() < 1e-8 && o.body_turn.abs() < 1e-8);
        assert!(closure_gap(&m, o) < 1e-8);
        // One vertical plane: ω is normal to it, γ in it.
        assert!(o.omega0.dot(&o.gamma0).abs() < 1e-9 && o.omega0.z.abs() < 1e-9);
    }
    assert!(lyapunov_family(&m, &s, 1, &opts).is_err());
}

/// The Lagrange top's nutation between the roots `u₁ < u₂` of its cubic
/// `u̇² = f(u) = (1 − u²)(2/A)(E − p_φ²/2C − mgl u) − ((p_ψ − p_φ u)/A)²` (u = cos θ = γ₃):
/// the period `2∫du/√f`, `Δψ = 2∫ψ̇ du/√f` with `ψ̇ = (p_ψ − p_φu)/(A(1 − u²))` and
/// `Δφ = 2∫(p_φ/C − ψ̇u) du/√f`, by `u = u₁ + (u₂ − u₁)sin²s` (which removes the endpoint
/// singularities: `du/√f = 2 ds/√(c₃(u₃ − u))`) and composite Simpson over `s ∈ [0, π/2]`.
fn nutation_by_quadrature(
    (a, c, mgl): (f64, f64, f64),
    u0: f64,
    psi_dot0: f64,
    phi_dot0: f64,
) -> (f64, f64, f64) {
    let p_phi = c * (phi_dot0 + psi_dot0 * u0);
    let p_psi = a * (1.0 - u0 * u0) * psi_dot0 + p_phi * u0;
    let e = 0.5 * a * psi_dot0 * psi_dot0 * (1.0 - u0 * u0) + p_phi * p_phi / (2.0 * c) + mgl * u0;
    let ep = e - p_phi * p_phi / (2.0 * c);
    let c3 = 2.0 * mgl / a;
    let c2 = -2.0 * ep / a - p_phi * p_phi / (a * a);
    let c1 = -2.0 * mgl / a + 2.0 * p_psi * p_phi / (a * a);
    // Deflated by the known root u0: f = (u − u0)(c3 u² + q1 u + q0).
    let q1 = c2 + c3 * u0;
    let q0 = c1 + q1 * u0;
    let disc = (q1 * q1 - 4.0 * c3 * q0).sqrt();
    let (r1, r2) = ((-q1 - disc) / (2.0 * c3), (-q1 + disc) / (2.0 * c3));
    let mut roots = [u0, r1, r2];
    roots.sort_by(|x, y| x.total_cmp(y));
    let (u1, u2, u3) = (roots[0], roots[1], roots[2]);
    assert!(u1 >= -1.0 && u2 <= 1.0 && u3 > 1.0, "{roots:?}");
    let n = 4000;
    let h = 0.5 * PI / n as f64;
    let (mut t, mut dpsi, mut dphi) = (0.0, 0.0, 0.0);
    for i in 0..=n {
        let s = i as f64 * h;
        let w = if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        let u = u1 + (u2 - u1) * s.sin().powi(2);
        let dt = 2.0 / (c3 * (u3 - u)).sqrt();
        let psi_dot = (p_psi - p_phi * u) / (a * (1.0 - u * u));
        t += w * dt;
        dpsi += w * psi_dot * dt;
        dphi += w * (p_phi / c - psi_dot * u) * dt;
    }
    let k = 2.0 * h / 3.0;
    (k * t, k * dpsi, k * dphi)
}

/// (3) Nutations of the Lagrange top (A = 1, C = 1.25, mgl = 1) corrected from a guess 5 % off
/// the period: period, precession Δψ and body turn Δφ as the quadrature of the cubic gives
/// them, reported degenerate; continued upwards in energy, every orbit degenerate and no event.
#[test]
fn lagrange_nutations_match_the_quadrature() {
    let (a, c, mgl) = (1.0, 1.25, 1.0);
    let m = HeavyTop::lagrange(a, c, mgl);
    for (theta0, psi_dot0, phi_dot0) in [(0.5f64, 0.3, 2.0), (1.2, -0.4, 3.5), (2.0, 0.8, 1.0)] {
        let (t, dpsi, dphi) = nutation_by_quadrature((a, c, mgl), theta0.cos(), psi_dot0, phi_dot0);
        let gamma = Vector3::new(0.0, theta0.sin(), theta0.cos());
        let omega = gamma * psi_dot0 + Vector3::z() * phi_dot0;
        let o = periodic_orbit(&m, omega, gamma, 1.05 * t, &OrbitOptions::default()).unwrap();
        assert!(
            (o.period - t).abs() <= 1e-9 * t,
            "θ₀ = {theta0}: T = {} vs quadrature {t}",
            o.period
        );
        assert!(
            wrap(o.precession - dpsi).abs() <= 1e-8,
            "θ₀ = {theta0}: Δψ = {} vs quadrature {}",
            o.precession,
            wrap(dpsi)
        );
        assert!(
            wrap(o.body_turn - dphi).abs() <= 1e-8,
            "θ₀ = {theta0}: Δφ = {} vs quadrature {}",
            o.body_turn,
            wrap(dphi)
        );
        assert!(o.degenerate, "a nutation is not isolated");
        assert!(closure_gap(&m, &o) < 1e-8);
        let f = continue_orbit(
            &m,
            &o,
            // Upwards: below, the nutation shrinks onto the regular precession of the same
            // momenta, where the family folds back onto itself.
            (o.energy - 1e-9, o.energy + 0.05),
            &OrbitOptions {
                max_orbits: 40,
                ..OrbitOptions::default()
            },
        )
        .unwrap();
        assert!(f.orbits.len() >= 5, "{:?}", f.stop);
        assert!(f.events.is_empty(), "spurious events: {:?}", f.events);
        for q in &f.orbits {
            assert!(q.degenerate);
            assert!(closure_gap(&m, q) < 1e-8);
        }
    }
}

/// (4) The minimal period: a guess near 2T or 3T of a planar swing gives the orbit of period T
/// (the pendulum's `4K/ω₀`), not the orbit traversed twice or three times.
#[test]
fn the_minimal_period_is_reported() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let w0 = 1.5f64.sqrt();
    let theta0 = 1.0f64;
    let exact = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / w0;
    let gamma = Vector3::new(0.0, theta0.sin(), -theta0.cos());
    for n in [2.0, 3.0] {
        let o = periodic_orbit(
            &m,
            Vector3::zeros(),
            gamma,
            n * exact * 1.01,
            &OrbitOptions::default(),
        )
        .unwrap();
        assert!(
            (o.period - exact).abs() <= 1e-8 * exact,
            "guess {n}T: T = {} vs {exact}",
            o.period
        );
    }
}

/// (4) The first orbit of a family is corrected with a relative stop test: its period is the
/// nonlinear `4K(m)/ω₀` of its amplitude to 1e−9, not the linear `2π/ω₀` (4e−8 apart at
/// amplitude 1e−3).
#[test]
fn the_first_orbit_has_its_nonlinear_period() {
    let (a, mgl) = (1.0, 1.5);
    let m = body(a, 2.0, 3.0, mgl);
    let s = steady_at(&m, 0.0, -1.0);
    for mode in 0..2 {
        let f = lyapunov_family(
            &m,
            &s,
            mode,
            &OrbitOptions {
                max_orbits: 2,
                ..OrbitOptions::default()
            },
        )
        .unwrap();
        let o = &f.orbits[0];
        // The swing's axis: the one ω is about.
        let axis = if o.omega0.x.abs() + o.gamma0.y.abs() > o.omega0.y.abs() + o.gamma0.x.abs() {
            0
        } else {
            1
        };
        let j = [1.0, 2.0, 3.0][axis];
        let theta0 = (-o.energy / mgl).acos();
        let exact = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / (mgl / j).sqrt();
        let linear = 2.0 * PI / (mgl / j).sqrt();
        assert!(
            (o.period - exact).abs() <= 1e-9 * exact,
            "mode {mode}: T = {} vs 4K/ω₀ = {exact} (linear {linear})",
            o.period
        );
    }
}

/// (4) Starts outside the range asked for are errors that say so, not an orbit "at the bound".
#[test]
fn starts_outside_the_range_are_errors() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let s = steady_at(&m, 0.0, -1.0);
    let err = lyapunov_family(
        &m,
        &s,
        0,
        &OrbitOptions {
            energy_bounds: Some((5.0, 6.0)),
            ..OrbitOptions::default()
        },
    )
    .unwrap_err();
    assert!(err.to_string().contains("outside"), "{err}");
    let theta0 = 0.8f64;
    let o = periodic_orbit(
        &m,
        Vector3::zeros(),
        Vector3::new(0.0, theta0.sin(), -theta0.cos()),
        5.0,
        &OrbitOptions::default(),
    )
    .unwrap();
    let err = continue_orbit(&m, &o, (5.0, 6.0), &OrbitOptions::default()).unwrap_err();
    assert!(err.to_string().contains("outside"), "{err}");
}

/// Hostile inputs of the orbit functions are errors that say so, not hangs or allocations:
/// a path of 10¹² samples, the crossings of an "orbit" of period 1e300 (ends on the step budget),
/// and a period doubling whose orbit is not at k = −1 (an edited event).
#[test]
fn hostile_orbit_inputs_are_errors() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let theta0 = 0.8f64;
    let o = periodic_orbit(
        &m,
        Vector3::zeros(),
        Vector3::new(0.0, theta0.sin(), -theta0.cos()),
        5.0,
        &OrbitOptions::default(),
    )
    .unwrap();
    let err = orbit_path(&m, &o, 1_000_000_000_000).unwrap_err();
    assert!(err.to_string().contains("samples"), "{err}");
    let mut long = o.clone();
    long.period = 1e300;
    assert!(orbit_crossings(&m, &long, &SectionOptions::default().with_size(1, 5)).is_err());
    let event = OrbitEvent {
        kind: OrbitEventKind::PeriodDoubling,
        energy: o.energy,
        orbit: o.clone(),
        before: o.stability,
        after: o.stability,
    };
    let err = period_doubled_family(&m, &event, &OrbitOptions::default()).unwrap_err();
    assert!(err.to_string().contains("not −1"), "{err}");
}
