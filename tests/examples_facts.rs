//! The facts the paper's examples (`examples/heavy_top.rs`, `gyrostat.rs`,
//! `ellipsoid_on_plane.rs`, `body_in_fluid.rs`) and `periodic.rs` print, checked against closed
//! forms derived by hand and against simulations, through the models and analyses of the `derived-models` crate:
//! each example declares the same model in its own file (one file a user can copy), and
//! `tests/examples_models.rs` checks that the two declarations are token for token the same.

use derived_models::{
    bisect, classified_steady_motions, instability_threshold, report_at, stability_threshold,
    verdict_at, Ellipsoid, FluidBody, Gyrostat, HeavyBody, Kirchhoff, LagrangeTop,
};
use routh::{simulate_full, Lagrangian, Matrix3, Routhian, SimOptions, Stability, Vector3};

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

// --- heavy_top -------------------------------------------------------------------------------

#[test]
fn maievskii_threshold_found_by_bisection_matches_4_a1_mgl() {
    let top = LagrangeTop::example();
    let formula = top.maievskii_p();
    let found = instability_threshold(&top, Vector3::z(), 0.5 * formula, 1.5 * formula, 1e-13)
        .unwrap()
        .expect("the verdict changes");
    assert!(
        rel(found, formula) < 1e-10,
        "found {found}, formula {formula}"
    );
    // The same for a prolate top (C < A₁), where the sleeping top is never a minimum of U_r.
    let prolate = LagrangeTop {
        a1: 2.0,
        c: 0.7,
        mass: 1.3,
        g: 9.81,
        l: 0.4,
    };
    let f = prolate.maievskii_p();
    let found = instability_threshold(&prolate, Vector3::z(), 0.5 * f, 1.5 * f, 1e-13)
        .unwrap()
        .unwrap();
    assert!(rel(found, f) < 2e-9, "found {found}, formula {f}");
}

#[test]
fn sleeping_top_verdicts_on_either_side_of_the_bounds() {
    let top = LagrangeTop::example();
    let e3 = Vector3::z();
    let pm = top.maievskii_p();
    let ps = top.secular_p().unwrap();
    for (p, expected) in [
        (0.5 * pm, Stability::Unstable),
        (0.999 * pm, Stability::Unstable),
        (1.001 * pm, Stability::GyroscopicallyStabilized),
        (0.999 * ps, Stability::GyroscopicallyStabilized),
        (1.001 * ps, Stability::SecularlyStable),
    ] {
        assert_eq!(verdict_at(&top, e3, p).unwrap(), expected, "p_ψ = {p}");
    }
    // Exactly on the boundary of secular stability the second variation vanishes (errata E8).
    assert_eq!(verdict_at(&top, e3, ps).unwrap(), Stability::Degenerate);
    // Restricted second variation p²(C − A₁)/C² − mgl, twice.
    for p in [1.0, 2.2, 3.0] {
        let k = report_at(&top, e3, p)
            .unwrap()
            .restricted_hessian_eigenvalues;
        let hand = p * p * (top.c - top.a1) / (top.c * top.c) - top.mgl();
        assert!(
            (k[0] - hand).abs() < 1e-9 && (k[1] - hand).abs() < 1e-9,
            "{k:?} vs {hand}"
        );
    }
    // The hanging top is always secularly stable for C > A₁.
    assert_eq!(
        verdict_at(&top, -e3, 1.7).unwrap(),
        Stability::SecularlyStable
    );
}

#[test]
fn tilted_steady_motions_of_the_top_are_the_closed_form_circle() {
    let top = LagrangeTop::example();
    let p = 3.0;
    let rows = classified_steady_motions(&top, p).unwrap();
    assert_eq!(rows.len(), 3, "up, down and one circle");
    let circle = rows.iter().find(|r| !r.motion.isolated).expect("a circle");
    let z = circle.motion.gamma.z;
    let p_closed = top.tilted_family_p(z).unwrap();
    assert!(
        rel(p_closed, p) < 1e-8,
        "z = {z}: closed form gives p = {p_closed}"
    );
    assert_eq!(circle.report.verdict, Stability::Degenerate);
    // Below the bifurcation there is no circle.
    let rows = classified_steady_motions(&top, 2.2).unwrap();
    assert_eq!(rows.len(), 2);
    assert!(rows.iter().all(|r| r.motion.isolated));
}

#[test]
fn perturbed_sleeping_top_falls_below_and_stays_up_above_the_bound() {
    let top = LagrangeTop::example();
    let pm = top.maievskii_p();
    let max_tilt = |factor: f64| {
        let (w0, g0) = top.perturbed_sleeping(factor * pm, 0.01);
        let traj = simulate_full(
            &top,
            w0,
            g0,
            60.0,
            &SimOptions::with_tolerances(1e-10, 1e-12),
        )
        .unwrap();
        assert!((traj.p_psi[0] - factor * pm).abs() < 1e-12);
        traj.gamma
            .iter()
            .map(|g| (g.z / g.norm()).acos().to_degrees())
            .fold(0.0f64, f64::max)
    };
    let below = max_tilt(0.95);
    let above = max_tilt(1.05);
    assert!(
        below > 20.0,
        "below the bound the top should fall: {below}°"
    );
    assert!(
        above < 3.0,
        "above the bound the top should stay up: {above}°"
    );
}

// --- gyrostat --------------------------------------------------------------------------------

#[test]
fn amended_potential_of_the_derive_is_formula_40() {
    for body in [Gyrostat::kelvin(), Gyrostat::coupled()] {
        for p in [-2.0, 0.0, 1.3, 4.0] {
            for g in [
                Vector3::new(0.0, 0.0, 1.0),
                Vector3::new(0.6, 0.0, -0.8),
                Vector3::new(0.36, 0.48, 0.8),
                Vector3::new(-0.5, 0.5, 0.5f64.sqrt()),
            ] {
                let a = body.amended_potential(&g, p);
                let b = body.amended_potential_closed_form(&g, p);
                assert!((a - b).abs() < 1e-12 * (1.0 + b.abs()), "{a} vs {b}");
            }
        }
    }
    assert_eq!(
        Gyrostat::kelvin().amended_potential_formula(),
        "U_r(γ; p_ψ) = ½ (p_ψ − (3.5γ₃))² / (2γ₁² + 2.5γ₂² + 1.5γ₃²) + 0.981γ₃"
    );
    assert_eq!(
        Gyrostat::coupled().amended_potential_formula(),
        "U_r(γ; p_ψ) = ½ (p_ψ − (1γ₁² + 0.4γ₂² + 2γ₃²))² / (2γ₁² + 2.5γ₂² + 1.5γ₃²) + 0.981γ₃"
    );
}

fn kelvin_with_rotor(k3: f64) -> Gyrostat {
    Gyrostat {
        rotor: Vector3::new(0.0, 0.0, k3),
        ..Gyrostat::kelvin()
    }
}

#[test]
fn rotor_threshold_of_the_gyrostat_at_rest_matches_the_formula() {
    let kelvin = Gyrostat::kelvin();
    let e3 = Vector3::z();
    let formula = kelvin.rest_rotor_threshold();
    let found = bisect(0.2 * formula, 3.0 * formula, 1e-13, |k3| {
        Ok(verdict_at(&kelvin_with_rotor(k3), e3, k3)? == Stability::Unstable)
    })
    .unwrap()
    .unwrap();
    assert!(
        rel(found, formula) < 2e-9,
        "found {found}, formula {formula}"
    );
    // At p_ψ = K₃ the upright gyrostat is at rest.
    assert!(kelvin.psi_dot(&Vector3::zeros(), &e3, kelvin.rotor.z).abs() < 1e-15);
    assert_eq!(
        verdict_at(&kelvin, e3, kelvin.rotor.z).unwrap(),
        Stability::GyroscopicallyStabilized
    );
}

#[test]
fn gyrostat_at_rest_stays_up_with_a_strong_rotor_and_falls_with_a_weak_one() {
    let formula = Gyrostat::kelvin().rest_rotor_threshold();
    let max_tilt = |k3: f64| {
        let body = kelvin_with_rotor(k3);
        let g0 = Vector3::new(0.01f64.sin(), 0.0, 0.01f64.cos());
        let traj =
            simulate_full(&body, Vector3::zeros(), g0, 60.0, &SimOptions::default()).unwrap();
        traj.gamma
            .iter()
            .map(|g| (g.z / g.norm()).acos().to_degrees())
            .fold(0.0f64, f64::max)
    };
    let weak = 0.8 * formula;
    let strong = 1.2 * formula;
    assert_eq!(
        verdict_at(&kelvin_with_rotor(weak), Vector3::z(), weak).unwrap(),
        Stability::Unstable
    );
    assert!(max_tilt(weak) > 20.0);
    assert!(max_tilt(strong) < 5.0);
}

// --- ellipsoid_on_plane ----------------------------------------------------------------------

#[test]
fn spheroid_spin_thresholds_match_4_i_mg_l() {
    let body = Ellipsoid::spheroid();
    for sigma in [1.0, -1.0] {
        let gamma = sigma * Vector3::z();
        let formula = body.spheroid_threshold(sigma).unwrap();
        // ℓ = a₃ − σh − a₁²/a₃ with a = (1, 1, 2), h = 0.2.
        let ell = 2.0 - sigma * 0.2 - 0.5;
        assert!((formula * formula - 4.0 * 1.0 * 9.81 * ell).abs() < 1e-9);
        let found = instability_threshold(&body, gamma, 0.5, 40.0, 1e-13)
            .unwrap()
            .unwrap();
        // The same threshold as an event of the branch, located by continuation.
        let event = stability_threshold(&body, gamma, 0.5, 40.0)
            .unwrap()
            .unwrap();
        assert!(
            rel(event, formula) < 1e-9,
            "σ = {sigma}: {event} vs {formula}"
        );
        assert!(
            rel(found, formula) < 2e-9,
            "σ = {sigma}: {found} vs {formula}"
        );
        assert_eq!(
            verdict_at(&body, gamma, 0.99 * formula).unwrap(),
            Stability::Unstable
        );
        assert_eq!(
            verdict_at(&body, gamma, 1.01 * formula).unwrap(),
            Stability::GyroscopicallyStabilized
        );
    }
}

#[test]
fn triaxial_spin_threshold_matches_the_hand_quartic() {
    let body = Ellipsoid::triaxial();
    let formula = body.spin_threshold(1.0).unwrap();
    let found = instability_threshold(&body, Vector3::z(), 0.5, 40.0, 1e-13)
        .unwrap()
        .unwrap();
    let event = stability_threshold(&body, Vector3::z(), 0.5, 40.0)
        .unwrap()
        .unwrap();
    assert!(rel(event, formula) < 1e-9, "{event} vs {formula}");
    assert!(rel(found, formula) < 2e-9, "{found} vs {formula}");
    // The hand second variation kᵢ matches classify's restricted Hessian.
    for sigma in [1.0, -1.0] {
        for p in [0.0, 3.0, 9.0] {
            let eig = report_at(&body, sigma * Vector3::z(), p)
                .unwrap()
                .restricted_hessian_eigenvalues;
            let (k1, k2) = body.pole_hessian(sigma, p);
            let (lo, hi) = (k1.min(k2), k1.max(k2));
            assert!(
                (eig[0] - lo).abs() < 1e-9 * (1.0 + lo.abs()),
                "{eig:?} vs {k1}, {k2}"
            );
            assert!(
                (eig[1] - hi).abs() < 1e-9 * (1.0 + hi.abs()),
                "{eig:?} vs {k1}, {k2}"
            );
        }
    }
    // The spheroid case of the same quartic reduces to 4I mgℓ.
    let sph = Ellipsoid::spheroid();
    for sigma in [1.0, -1.0] {
        let a = sph.spin_threshold(sigma).unwrap();
        let b = sph.spheroid_threshold(sigma).unwrap();
        assert!(rel(a, b) < 1e-9, "{a} vs {b}");
    }
}

#[test]
fn body_at_rest_lies_stably_on_its_flattest_side() {
    // errata E2: U = +m g C₃, the stable rest positions are the minima of C₃.
    let body = Ellipsoid::triaxial();
    let rows = classified_steady_motions(&body, 0.0).unwrap();
    assert_eq!(rows.len(), 6, "the six ends of the principal axes");
    for r in &rows {
        let on_flat_side = r.motion.gamma.x.abs() > 1.0 - 1e-9;
        assert_eq!(
            r.report.verdict == Stability::SecularlyStable,
            on_flat_side,
            "{:?}",
            r.motion.gamma
        );
        if on_flat_side {
            assert!((body.height(&r.motion.gamma) - 0.8).abs() < 1e-9);
        }
    }
}

// --- body_in_fluid ---------------------------------------------------------------------------

#[test]
fn fluid_helper_satisfies_the_errata_e3_identities() {
    for body in [Kirchhoff::body_of_revolution(), Kirchhoff::chiral()] {
        for k in [0.5, 1.0, 2.3] {
            let f = body.parameters(k).unwrap();
            // The matrices A, Λ, Π themselves are not compared with a − bᵀc⁻¹b, kbᵀc⁻¹, k²c⁻¹:
            // that would restate the helper. The identities of (57)–(59) below pin them down.
            let bt = body.b.transpose();
            assert!((f.kinetic - f.kinetic.transpose()).norm() == 0.0);
            let model = FluidBody::from(&f);
            for (w, g) in [
                (Vector3::new(0.3, -0.7, 1.1), Vector3::new(0.48, -0.6, 0.64)),
                (Vector3::new(-1.0, 0.2, 0.0), Vector3::new(0.0, 0.6, -0.8)),
            ] {
                let v = f.velocity(&w, &g);
                let p = f.impulse(&g);
                // p = bω + cv (57), L = T − (p, v) (59 with E3), ∂L/∂ω = ∂T/∂ω, ∂L/∂γ = −kv.
                assert!((body.b * w + body.c * v - p).norm() < 1e-13);
                let t = body.energy(&w, &v);
                assert!((model.lagrangian(&w, &g) - (t - p.dot(&v))).abs() < 1e-13);
                assert!((model.dl_domega(&w, &g) - (body.a * w + bt * v)).norm() < 1e-13);
                assert!((model.dl_dgamma(&w, &g) + k * v).norm() < 1e-13);
                // The energy (3) of L is T; Kirchhoff's (55) is k times the cyclic momentum (9).
                assert!((model.energy(&w, &g) - t).abs() < 1e-13);
                let kirchhoff_55 = (body.a * w + bt * v).dot(&p);
                let p_psi = model.cyclic_momentum(&w, &g);
                assert!((f.kirchhoff_constant(p_psi) - kirchhoff_55).abs() < 1e-13);
                assert!((f.p_psi_from_kirchhoff(kirchhoff_55) - p_psi).abs() < 1e-13);
            }
        }
    }
    // Bad input is an error, not a panic.
    let id = Matrix3::identity();
    assert!(routh::fluid::kirchhoff_lagrangian(id, id * 2.0, id, 1.0).is_err());
    assert!(routh::fluid::kirchhoff_lagrangian(id, id, id, -1.0).is_err());
}

#[test]
fn spinning_body_of_revolution_threshold_matches_the_formula() {
    let body = Kirchhoff::body_of_revolution();
    let e3 = Vector3::z();
    for k in [1.0, 2.5] {
        let f = body.parameters(k).unwrap();
        let model = FluidBody::from(&f);
        let formula = body.axial_threshold(k);
        let found = instability_threshold(&model, e3, 0.2 * formula, 3.0 * formula, 1e-13)
            .unwrap()
            .unwrap();
        let event = stability_threshold(&model, e3, 0.2 * formula, 3.0 * formula)
            .unwrap()
            .unwrap();
        assert!(rel(event, formula) < 1e-9, "k = {k}: {event} vs {formula}");
        assert!(rel(found, formula) < 2e-9, "k = {k}: {found} vs {formula}");
        assert_eq!(
            verdict_at(&model, e3, 0.99 * formula).unwrap(),
            Stability::Unstable
        );
        assert_eq!(
            verdict_at(&model, e3, 1.01 * formula).unwrap(),
            Stability::GyroscopicallyStabilized
        );
    }
    // Without spin: translation along the axis unstable (degree 2, no gyroscopic forces),
    // broadside translation a circle of steady motions (degenerate).
    let f = body.parameters(1.0).unwrap();
    let model = FluidBody::from(&f);
    let rows = classified_steady_motions(&model, 0.0).unwrap();
    assert_eq!(rows.len(), 3);
    for r in rows {
        if r.motion.isolated {
            assert!(r.motion.gamma.z.abs() > 1.0 - 1e-9);
            assert_eq!(r.report.verdict, Stability::Unstable);
            assert_eq!(r.report.degree_of_instability, 2);
        } else {
            assert!(r.motion.gamma.z.abs() < 1e-9);
            assert_eq!(r.report.verdict, Stability::Degenerate);
        }
    }
}

/// `gyrostat`'s energy–momentum diagram of the Kelvin gyrostat: the branches account for every
/// steady motion a global search finds between events, and at every branch point or fold the
/// restricted second variation of the amended potential — computed here from the hand-written
/// num-dual twin of the model, not from the generated code — has a zero eigenvalue.
#[test]
fn kelvin_energy_momentum_diagram_events_are_zeros_of_the_second_variation() {
    let body = Gyrostat::kelvin();
    let twin = test_models::Gyrostat::new(
        body.inertia,
        body.rotor,
        body.coupling,
        body.com,
        body.mass,
        body.g,
    );
    let checked = routh::bifurcation_diagram(
        |p| (body.clone(), p),
        (-6.0, 9.0),
        &routh::ContinuationOptions::default(),
    )
    .unwrap();
    assert!(checked.consistent(), "{:#?}", checked.checks);
    let d = &checked;
    let mut zeros = 0;
    for e in d
        .events
        .iter()
        .filter(|e| e.kind != routh::EventKind::HamiltonianHopf)
    {
        let z = Vector3::zeros();
        let g = e.gamma;
        let grad = twin.dr_dgamma(&z, &g, e.s);
        let hess = twin.d2r_dgamma2(&z, &g, e.s);
        let mu = grad.dot(&g);
        // An orthonormal basis of the tangent plane.
        let a = if g.x.abs() < 0.9 {
            Vector3::x()
        } else {
            Vector3::y()
        };
        let u = (a - a.dot(&g) * g).normalize();
        let v = g.cross(&u);
        let k = |x: &Vector3<f64>, y: &Vector3<f64>| mu * x.dot(y) - x.dot(&(hess * y));
        let (k11, k12, k22) = (k(&u, &u), k(&u, &v), k(&v, &v));
        let det = k11 * k22 - k12 * k12;
        let scale = hess.norm() + grad.norm();
        // det K = κ₁κ₂ with one κ zero: |det| ≤ tol·|K|².
        assert!(
            det.abs() <= 1e-7 * scale * scale,
            "{e}: det K = {det:e} (scale {scale:e})"
        );
        zeros += 1;
    }
    assert!(zeros >= 4, "{:#?}", d.events);
}

/// `body_in_fluid`'s atlas of the motion along the axis over (c₃, p_ψ): the traced
/// Hamiltonian–Hopf curve is the closed form p_ψ² = 4A₁k²(1/c₃ − 1/c₁).
#[test]
fn axial_motion_atlas_curve_is_the_closed_form() {
    let rev = Kirchhoff::body_of_revolution();
    let k = 1.0;
    let body_with = |c3: f64| Kirchhoff {
        c: Matrix3::from_diagonal(&Vector3::new(rev.c[(0, 0)], rev.c[(1, 1)], c3)),
        ..rev
    };
    let atlas = routh::stability_atlas(
        |c3, p| (FluidBody::from(&body_with(c3).parameters(k).unwrap()), p),
        Vector3::z(),
        (0.8, 2.8),
        (0.0, 2.5),
        &routh::AtlasOptions {
            nx: 21,
            ny: 21,
            ..routh::AtlasOptions::default()
        },
    )
    .unwrap();
    let hh: Vec<_> = atlas
        .boundaries
        .iter()
        .filter(|b| b.kind == routh::EventKind::HamiltonianHopf)
        .collect();
    assert!(!hh.is_empty());
    for b in hh {
        assert!(b.points.len() > 10);
        for &(c3, p) in &b.points {
            let exact = body_with(c3).axial_threshold(k);
            assert!(rel(p, exact) < 1e-8, "c₃ = {c3}: {p} vs {exact}");
        }
    }
}

/// `ellipsoid_on_plane`'s atlas of the spheroid spinning on its end over (a₃, p_ψ): the traced
/// Hamiltonian–Hopf curve is the closed form p² = 4I₁mgℓ, ℓ = a₃ − h − a₁²/a₃.
#[test]
fn spheroid_atlas_curve_is_the_closed_form() {
    let base = Ellipsoid::spheroid();
    let with = |a3: f64| {
        let a = Vector3::new(1.0, 1.0, a3);
        Ellipsoid {
            inertia: derived_models::ellipsoid::uniform_inertia(base.mass, &a),
            semi_axes: a,
            ..base.clone()
        }
    };
    let atlas = routh::stability_atlas(
        |a3, p| (with(a3), p),
        Vector3::z(),
        (1.3, 3.0),
        (0.0, 16.0),
        &routh::AtlasOptions {
            nx: 21,
            ny: 21,
            ..routh::AtlasOptions::default()
        },
    )
    .unwrap();
    let mut checked = 0;
    for b in atlas
        .boundaries
        .iter()
        .filter(|b| b.kind == routh::EventKind::HamiltonianHopf)
    {
        for &(a3, p) in &b.points {
            let exact = with(a3).spheroid_threshold(1.0).unwrap();
            assert!(rel(p, exact) < 1e-8, "a₃ = {a3}: {p} vs {exact}");
            checked += 1;
        }
    }
    assert!(checked > 10);
}

// --- periodic --------------------------------------------------------------------------------

/// The options of the example's swing families.
fn swing_options(mgl: f64) -> routh::OrbitOptions {
    routh::OrbitOptions::default()
        .with_energy_bounds(-mgl, 0.999 * mgl)
        .with_max_orbits(400)
        .with_max_step(0.05)
}

/// The swing about e₁ of `J = diag(1, 2, 3)`, `mgl = 1.5` (examples/periodic.rs): a pendulum,
/// periods `4K(m)/ω₀`; stable against out-of-plane perturbations up to the branch point at
/// `E = 0.967866` (amplitude 130.18°), hyperbolic beyond.
#[test]
fn periodic_swing_is_the_pendulum_and_stable_up_to_130_degrees() {
    use derived_models::heavy_body::{elliptic_k, hanging, stability_intervals};
    use routh::{lyapunov_family, OrbitEventKind, OrbitStability};
    let mgl = 1.5;
    let body = HeavyBody::on_axis(1.0, 2.0, 3.0, mgl);
    let hang = hanging(&body).unwrap();
    let f = lyapunov_family(&body, &hang, 0, &swing_options(mgl)).unwrap();
    let w0 = mgl.sqrt();
    for o in &f.orbits {
        let t = 4.0 * elliptic_k(0.5 * (1.0 + o.energy / mgl)) / w0;
        assert!(
            rel(o.period, t) < 1e-7,
            "E = {}: T = {} vs {t}",
            o.energy,
            o.period
        );
        assert!(o.gamma0.x.abs() < 1e-12, "out of the plane γ₁ = 0");
    }
    assert_eq!(f.events.len(), 1, "{:?}", f.events);
    let bp = &f.events[0];
    assert_eq!(bp.kind, OrbitEventKind::BranchPoint);
    assert!((bp.energy - 0.967866).abs() < 1e-5, "{bp}");
    assert!(((-bp.energy / mgl).acos().to_degrees() - 130.18).abs() < 0.01);
    let intervals = stability_intervals(&f);
    let verdicts: Vec<OrbitStability> = intervals.iter().map(|i| i.2).collect();
    assert_eq!(
        verdicts,
        [OrbitStability::Elliptic, OrbitStability::Hyperbolic]
    );
    assert_eq!(intervals[0].1, bp.energy);
}

/// The centre of mass off the axes (`J = diag(1, 3, 6)`, `m g r = (0.4, 0.3, 1.5)`): mode 0
/// doubles its period at `E = −0.936029`, is stable again from `E = 0.406946`, and turns
/// hyperbolic at a branch point at `E = 0.985151`.
#[test]
fn periodic_offaxis_family_doubles_its_period_and_regains_stability() {
    use derived_models::heavy_body::{hanging, stability_intervals};
    use routh::{lyapunov_family, OrbitEventKind, OrbitOptions, OrbitStability};
    let body = HeavyBody {
        inertia: Vector3::new(1.0, 3.0, 6.0),
        mgr: Vector3::new(0.4, 0.3, 1.5),
    };
    let hang = hanging(&body).unwrap();
    let f = lyapunov_family(
        &body,
        &hang,
        0,
        &OrbitOptions::default().with_max_orbits(120),
    )
    .unwrap();
    let events: Vec<(OrbitEventKind, f64)> = f.events.iter().map(|e| (e.kind, e.energy)).collect();
    let expected = [
        (OrbitEventKind::PeriodDoubling, -0.936029),
        (OrbitEventKind::PeriodDoubling, 0.406946),
        (OrbitEventKind::BranchPoint, 0.985151),
    ];
    assert_eq!(events.len(), 3, "{events:?}");
    for ((kind, e), (k, x)) in events.iter().zip(expected) {
        assert_eq!(*kind, k);
        assert!((e - x).abs() < 1e-5, "{kind:?} at {e}, expected {x}");
    }
    let verdicts: Vec<OrbitStability> = stability_intervals(&f).iter().map(|i| i.2).collect();
    assert_eq!(
        verdicts,
        [
            OrbitStability::Elliptic,
            OrbitStability::InverseHyperbolic,
            OrbitStability::Elliptic,
            OrbitStability::Hyperbolic
        ]
    );
}
