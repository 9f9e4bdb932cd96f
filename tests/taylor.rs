//! `Method::Taylor` (Taylor's method on the derive's flow tape) against DOP853 on models the
//! derive wrote: the heavy asymmetric top `J = (1, 1.6, 2.3)` with its centre of mass off the
//! axes, and the ellipsoid on a plane (`J` depends on γ; the tape has square roots, powers and
//! reciprocals). The references are DOP853 runs at rtol = 1e-14 (an independent integrator on
//! the generated `f64` code, not on the tape) and the first integrals (3), (9), |γ|².
//! `routh::Model` built from the same text integrates the same way, and `simulate_reduced` by
//! Taylor's method (through the body's motion) agrees with DOP853 on (13).

use derived_models::{AsymmetricTop, Ellipsoid};
use routh::{
    simulate_full, simulate_reduced, Matrix3, Method, Model, RouthError, SimOptions, Trajectory,
    Vector3,
};

fn top() -> AsymmetricTop {
    AsymmetricTop {
        inertia: Vector3::new(1.0, 1.6, 2.3),
        com: Vector3::new(0.1, -0.05, 0.4),
        mass: 1.0,
        g: 1.0,
    }
}

fn ellipsoid() -> Ellipsoid {
    Ellipsoid {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 1.3, 0.8)),
        semi_axes: Vector3::new(0.9, 1.1, 0.6),
        offset: Vector3::new(0.05, 0.02, -0.1),
        mass: 1.0,
        g: 1.0,
    }
}

fn start() -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(0.5, -0.3, 1.2),
        Vector3::new(0.3, 0.2, 0.9).normalize(),
    )
}

fn taylor(rtol: f64) -> SimOptions {
    SimOptions {
        method: Method::Taylor,
        max_steps: 1_000_000,
        ..SimOptions::with_tolerances(rtol, rtol)
    }
}

/// `max_i |a(tᵢ) − b(tᵢ)|` over ω and γ of two runs recorded at the same times.
fn distance(a: &Trajectory, b: &Trajectory) -> f64 {
    assert_eq!(a.t, b.t);
    let w = a.omega.iter().zip(&b.omega).map(|(x, y)| (x - y).amax());
    let g = a.gamma.iter().zip(&b.gamma).map(|(x, y)| (x - y).amax());
    w.chain(g).fold(0.0, f64::max)
}

#[test]
fn taylor_follows_dop853_on_the_heavy_asymmetric_top_and_the_ellipsoid() {
    let (w0, g0) = start();
    let times: Vec<f64> = (0..=400).map(|i| 0.25 * i as f64).collect();
    let reference = SimOptions {
        max_steps: 1_000_000,
        ..SimOptions::with_tolerances(1e-14, 1e-16)
    }
    .at_times(times.clone());
    type Run = Box<dyn Fn(&SimOptions) -> Result<Trajectory, RouthError>>;
    let runs: [(&str, Run); 2] = [
        (
            "top",
            Box::new(move |o: &SimOptions| simulate_full(&top(), w0, g0, 100.0, o)),
        ),
        (
            "ellipsoid",
            Box::new(move |o: &SimOptions| simulate_full(&ellipsoid(), w0, g0, 100.0, o)),
        ),
    ];
    for (name, run) in runs {
        let r = run(&reference).unwrap();
        // The reference's own error, gauged by DOP853 one decade looser.
        let looser = SimOptions {
            max_steps: 1_000_000,
            ..SimOptions::with_tolerances(1e-13, 1e-15)
        };
        let d_ref = distance(&run(&looser.at_times(times.clone())).unwrap(), &r);
        eprintln!("{name}: |DOP853(1e-13) − DOP853(1e-14)| ≤ {d_ref:.2e} on t ≤ 100");
        for rtol in [1e-8, 1e-11, 1e-14] {
            let t = run(&taylor(rtol).at_times(times.clone())).unwrap();
            let d = distance(&t, &r);
            let steps = run(&taylor(rtol)).unwrap();
            eprintln!(
                "{name} rtol {rtol:.0e}: {} steps, |Taylor − DOP853(1e-14)| ≤ {d:.2e} on t ≤ 100, \
                 energy drift {:.2e}, p_ψ drift {:.2e}, | |γ|² − 1 | ≤ {:.2e}",
                steps.stats.accepted_steps,
                steps.energy_drift(),
                steps.p_psi_drift(),
                steps.gamma_norm_error()
            );
            // Measured (x86-64): at rtol 1e-8, 1e-11, 1e-14 the distance is 8.5e-10, 1.3e-12,
            // 3.8e-13 (top; the reference's gauge 2.9e-12) and 2.8e-8, 2.1e-11, 8.6e-12
            // (ellipsoid; gauge 7.3e-11: at 1e-14 the distance is the reference's error); the
            // integrals drift by at most ~30·rtol. Bounds: 100·rtol plus twice the gauge.
            assert!(
                d < 100.0 * rtol + 2.0 * d_ref,
                "{name} rtol {rtol:e}: distance {d:e} (gauge {d_ref:e})"
            );
            for (what, drift) in [
                ("energy", steps.energy_drift()),
                ("p_psi", steps.p_psi_drift()),
                ("|γ|²", steps.gamma_norm_error()),
            ] {
                assert!(drift < 100.0 * rtol + 1e-13, "{name} {what}: {drift:e}");
            }
        }
    }
}

#[test]
fn dense_output_is_the_step_polynomial() {
    // Output times inside the steps, evaluated on the Taylor polynomial, against DOP853 at
    // 1e-14 at the same times: as accurate as the step ends.
    let (w0, g0) = start();
    let times: Vec<f64> = (0..=136).map(|i| 0.0731 * i as f64).collect();
    let t = simulate_full(&top(), w0, g0, 10.0, &taylor(1e-13).at_times(times.clone())).unwrap();
    let r = simulate_full(
        &top(),
        w0,
        g0,
        10.0,
        &SimOptions::with_tolerances(1e-14, 1e-16).at_times(times),
    )
    .unwrap();
    let d = distance(&t, &r);
    assert!(d < 1e-12, "dense output off by {d:e}");
}

#[test]
fn runtime_model_integrates_as_the_derive() {
    const TEXT: &str = "kinetic = 0.5 * omega.dot(diag(inertia) * omega),
        potential = mass * g * com.dot(gamma),";
    let d = top();
    let p = [
        ("inertia", d.inertia.into()),
        ("com", d.com.into()),
        ("mass", d.mass.into()),
        ("g", d.g.into()),
    ];
    let m = Model::new(TEXT, &p).unwrap();
    let (w0, g0) = start();
    let a = simulate_full(&d, w0, g0, 50.0, &taylor(1e-12)).unwrap();
    let b = simulate_full(&m, w0, g0, 50.0, &taylor(1e-12)).unwrap();
    // The same steps (the step size is read from the coefficients, which agree to rounding)
    // and the same states to rounding.
    assert_eq!(a.t.len(), b.t.len());
    let dt =
        a.t.iter()
            .zip(&b.t)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
    let dx = distance(
        &a,
        &Trajectory {
            t: a.t.clone(),
            ..b.clone()
        },
    );
    eprintln!(
        "Model vs derive: {} steps, |Δt| ≤ {dt:.1e}, |Δx| ≤ {dx:.1e}",
        a.t.len()
    );
    assert!(dt < 1e-12 && dx < 1e-11, "Δt {dt:e}, Δx {dx:e}");
}

#[test]
fn taylor_needs_a_flow_tape_and_the_full_equations() {
    let (w0, g0) = start();
    // A hand-written model has no flow tape.
    let hand = test_models::HeavyTop::lagrange(2.0, 1.0, 1.0);
    let e = simulate_full(&hand, w0, g0, 1.0, &taylor(1e-10)).unwrap_err();
    assert!(
        matches!(e, RouthError::InvalidOption { what: "method", .. }),
        "{e}"
    );
    let e = simulate_reduced(&hand, w0, g0, 0.5, 1.0, &taylor(1e-10)).unwrap_err();
    assert!(
        matches!(e, RouthError::InvalidOption { what: "method", .. }),
        "{e}"
    );
}

#[test]
fn reduced_equations_by_taylor_agree_with_dop853() {
    // simulate_reduced by Taylor's method (the body's motion on the flow tape, Ω and ψ read in
    // the gauge Ω·γ = Ω₀·γ₀) against DOP853 on the reduced equations (13) themselves; Ω₀ with
    // a component along γ₀, so that the gauge is not Ω·γ = 0.
    let (_, g0) = start();
    let big0 = Vector3::new(0.4, -0.2, 0.3);
    let p = 0.8;
    let times: Vec<f64> = (0..=200).map(|i| 0.25 * i as f64).collect();
    let m = ellipsoid();
    let t = simulate_reduced(
        &m,
        big0,
        g0,
        p,
        50.0,
        &taylor(1e-12).at_times(times.clone()),
    )
    .unwrap();
    let d = simulate_reduced(
        &m,
        big0,
        g0,
        p,
        50.0,
        &SimOptions::with_tolerances(1e-14, 1e-16).at_times(times),
    )
    .unwrap();
    let dist = |a: &[Vector3<f64>], b: &[Vector3<f64>]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).amax())
            .fold(0.0, f64::max)
    };
    let d_big = dist(&t.big_omega, &d.big_omega);
    let d_gamma = dist(&t.gamma, &d.gamma);
    let d_omega = dist(&t.omega, &d.omega);
    let d_psi = t
        .psi
        .iter()
        .zip(&d.psi)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    eprintln!(
        "reduced, ellipsoid, t ≤ 50: |ΔΩ| {d_big:.1e}, |Δγ| {d_gamma:.1e}, |Δω| {d_omega:.1e}, \
         |Δψ| {d_psi:.1e}; ψ(50) = {:.3}, energy drift {:.1e}, p_ψ error {:.1e}",
        t.psi.last().unwrap(),
        t.energy_drift(),
        t.p_psi_error(p)
    );
    let worst = d_big.max(d_gamma).max(d_omega).max(d_psi);
    // Measured: |ΔΩ| 4.7e-13, |Δγ| 3.5e-13, |Δω| 3.9e-13, |Δψ| 9.3e-13 (ψ(50) = 30.2); the
    // bound is 100× that.
    assert!(worst < 1e-10, "Taylor and DOP853 differ by {worst:e}");
    assert!(t.energy_drift() < 1e-11 && t.p_psi_error(p) < 1e-11);
    // The gauge is kept.
    let s = big0.dot(&g0);
    for (w, g) in t.big_omega.iter().zip(&t.gamma) {
        assert!((w.dot(g) - s).abs() < 1e-12);
    }
}

#[test]
fn taylor_moves_the_attitude_with_gamma() {
    // γ = Rᵀe₃ at every recorded point, and the attitude agrees with DOP853's.
    let (w0, g0) = start();
    let t = simulate_full(&top(), w0, g0, 20.0, &taylor(1e-12).with_attitude()).unwrap();
    for (q, g) in t.attitude.iter().zip(&t.gamma) {
        let e3 = q.inverse_transform_vector(&Vector3::z());
        assert!((e3 - g.normalize()).norm() < 1e-14);
    }
    let d = simulate_full(
        &top(),
        w0,
        g0,
        20.0,
        &SimOptions::with_tolerances(1e-13, 1e-15).with_attitude(),
    )
    .unwrap();
    let (qa, qb) = (t.attitude.last().unwrap(), d.attitude.last().unwrap());
    assert!(qa.angle_to(qb) < 1e-9, "{}", qa.angle_to(qb));
}
