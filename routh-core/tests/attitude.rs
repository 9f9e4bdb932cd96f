//! The attitude integrated with `SimOptions::attitude`, checked against what the simulation did
//! not produce: `γ = Rᵀe₃` (γ is integrated by its own equation), an independent RK4 integration
//! of Euler's equations with `Ṙ = R[ω]×` on the 3×3 matrix, the Lagrange top's nutation bounds
//! from the roots of its cubic (closed form of the first integrals), and the precession rate of a
//! steady motion.

use nalgebra::{Matrix3, UnitQuaternion};
use routh_core::{
    simulate_full, simulate_reduced, steady::steady_motions, Lagrangian, SimOptions, Vector3,
};
use test_models::Gyrostat;

fn asymmetric_top() -> Gyrostat {
    Gyrostat::heavy_top(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.3, -0.2, 0.5),
        1.0,
        9.81,
    )
}

fn state() -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(1.0, -0.5, 2.0),
        Vector3::new(0.3, 0.4, 0.866).normalize(),
    )
}

fn gamma_of(q: &UnitQuaternion<f64>) -> Vector3<f64> {
    q.inverse_transform_vector(&Vector3::z())
}

/// `max |γ/|γ| − Rᵀe₃|` and `max | |q| − 1 |` (with the adaptive method |γ| itself drifts at
/// the tolerance; its direction is what the attitude must reproduce).
fn consistency(gamma: &[Vector3<f64>], att: &[UnitQuaternion<f64>]) -> (f64, f64) {
    assert_eq!(gamma.len(), att.len());
    let g = (gamma.iter().zip(att))
        .map(|(g, q)| (g.normalize() - gamma_of(q)).amax())
        .fold(0.0, f64::max);
    let n = att
        .iter()
        .map(|q| (q.quaternion().norm() - 1.0).abs())
        .fold(0.0, f64::max);
    (g, n)
}

#[test]
fn attitude_is_off_by_default_and_empty() {
    let (w, g) = state();
    let tr = simulate_full(&asymmetric_top(), w, g, 1.0, &SimOptions::default()).unwrap();
    assert!(tr.attitude.is_empty() && tr.euler_angles().is_empty());
}

#[test]
fn gamma_is_r_transpose_e3_at_every_step() {
    let model = asymmetric_top();
    let (w, g) = state();
    for opts in [
        SimOptions::default().with_attitude(),
        SimOptions::lie_rk4(1e-3).with_attitude(),
        SimOptions::default()
            .with_attitude()
            .at_times((0..=100).map(|i| 0.05 * i as f64).collect()),
    ] {
        let tr = simulate_full(&model, w, g, 5.0, &opts).unwrap();
        let (dg, dn) = consistency(&tr.gamma, &tr.attitude);
        eprintln!(
            "full {:?}: max|γ − Rᵀe₃| = {dg:.1e}, max||q| − 1| = {dn:.1e}",
            opts.method
        );
        assert!(dg < 1e-13, "{dg:e}");
        assert!(dn < 1e-13, "{dn:e}");
        let p = model.cyclic_momentum(&w, &g);
        let big0 = w - g * w.dot(&g);
        let rt = simulate_reduced(&model, big0, g, p, 5.0, &opts).unwrap();
        let (dg, dn) = consistency(&rt.gamma, &rt.attitude);
        eprintln!(
            "reduced {:?}: max|γ − Rᵀe₃| = {dg:.1e}, max||q| − 1| = {dn:.1e}",
            opts.method
        );
        assert!(dg < 1e-13, "{dg:e}");
        assert!(dn < 1e-13, "{dn:e}");
    }
}

/// The Lie method's quaternion stays unit to round-off over a long run (no renormalisation).
#[test]
fn lie_quaternion_stays_unit() {
    let (w, g) = state();
    let tr = simulate_full(
        &asymmetric_top(),
        w,
        g,
        200.0,
        &SimOptions {
            max_steps: 1_000_000,
            ..SimOptions::lie_rk4(2e-3)
        }
        .with_attitude(),
    )
    .unwrap();
    let (dg, dn) = consistency(&tr.gamma, &tr.attitude);
    eprintln!("LieRk4, 100 000 steps: max|γ − Rᵀe₃| = {dg:.1e}, max||q| − 1| = {dn:.1e}");
    assert!(dn < 1e-12 && dg < 1e-12, "{dn:e} {dg:e}");
}

/// Euler's equations of the heavy top `I ω̇ = Iω × ω + m g γ × r` with `Ṙ = R[ω]×`, `γ = Rᵀe₃`,
/// integrated by classical RK4 on `(ω, R)` (R as a plain 3×3 matrix): independent of routh.
fn reference(
    model: &Gyrostat,
    w0: Vector3<f64>,
    r0: Matrix3<f64>,
    t: f64,
    n: usize,
) -> Matrix3<f64> {
    let inv = model.inertia.try_inverse().unwrap();
    let mg = model.mass * model.g;
    let f = |w: &Vector3<f64>, r: &Matrix3<f64>| {
        let gamma = r.transpose() * Vector3::z();
        let iw = model.inertia * w;
        let wd = inv * (iw.cross(w) + gamma.cross(&model.com) * mg);
        (wd, r * w.cross_matrix())
    };
    let h = t / n as f64;
    let (mut w, mut r) = (w0, r0);
    for _ in 0..n {
        let (a1, b1) = f(&w, &r);
        let (a2, b2) = f(&(w + a1 * (h / 2.0)), &(r + b1 * (h / 2.0)));
        let (a3, b3) = f(&(w + a2 * (h / 2.0)), &(r + b2 * (h / 2.0)));
        let (a4, b4) = f(&(w + a3 * h), &(r + b3 * h));
        w += (a1 + a2 * 2.0 + a3 * 2.0 + a4) * (h / 6.0);
        r += (b1 + b2 * 2.0 + b3 * 2.0 + b4) * (h / 6.0);
    }
    r
}

#[test]
fn attitude_matches_an_independent_integration() {
    let model = asymmetric_top();
    let (w, g) = state();
    let t_end = 3.0;
    let times = vec![0.0, 1.0, 2.0, 3.0];
    for opts in [
        SimOptions::with_tolerances(1e-12, 1e-13).with_attitude(),
        SimOptions::lie_rk4(5e-4).with_attitude(),
    ] {
        let opts = opts.at_times(times.clone());
        let tr = simulate_full(&model, w, g, t_end, &opts).unwrap();
        let r0 = tr.attitude[0].to_rotation_matrix().into_inner();
        assert!((r0.transpose() * Vector3::z() - g).amax() < 1e-15);
        for (i, &t) in times.iter().enumerate().skip(1) {
            let want = reference(&model, w, r0, t, 20_000 * i);
            let got = tr.attitude[i].to_rotation_matrix().into_inner();
            let err = (got - want).amax();
            eprintln!("{:?}, t = {t}: max|R − R_ref| = {err:.1e}", opts.method);
            assert!(err < 1e-9, "{err:e}");
        }
        // The reduced system, reconstructed by (15), gives the same attitude.
        let p = model.cyclic_momentum(&w, &g);
        let big0 = w - g * w.dot(&g);
        let rt = simulate_reduced(&model, big0, g, p, t_end, &opts).unwrap();
        for (i, &t) in times.iter().enumerate().skip(1) {
            let want = reference(&model, w, r0, t, 20_000 * i);
            let got = rt.attitude[i].to_rotation_matrix().into_inner();
            let err = (got - want).amax();
            eprintln!(
                "reduced {:?}, t = {t}: max|R − R_ref| = {err:.1e}",
                opts.method
            );
            assert!(err < 1e-8, "{err:e}");
        }
    }
}

/// Roots of the Lagrange top's cubic `f(u) = (1 − u²)·2(E' − mgl u)/A − ((L_z − L₃u)/A)²`,
/// `u = cos θ`, `u̇² = f(u)` (E' = E − ½Cω₃², L_z, L₃ = Cω₃ the integrals), in [−1, 1]: the
/// turning points of the nutation, by bisection between the sign changes of f.
fn nutation_bounds(a: f64, e1: f64, mgl: f64, lz: f64, l3: f64) -> (f64, f64) {
    let f = |u: f64| (1.0 - u * u) * 2.0 * (e1 - mgl * u) / a - ((lz - l3 * u) / a).powi(2);
    let n = 20_000;
    let mut roots = Vec::new();
    for k in 0..n {
        let (mut lo, mut hi) = (
            -1.0 + 2.0 * k as f64 / n as f64,
            -1.0 + 2.0 * (k + 1) as f64 / n as f64,
        );
        if f(lo) * f(hi) <= 0.0 && f(lo) != f(hi) {
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if f(lo) * f(mid) <= 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            roots.push(0.5 * (lo + hi));
        }
    }
    assert_eq!(roots.len(), 2, "{roots:?}");
    (roots[0], roots[1])
}

#[test]
fn lagrange_top_nutates_between_the_roots_of_its_cubic() {
    let (a, c, mgl) = (2.0, 1.0, 1.5);
    let top = Gyrostat::lagrange_top(a, c, mgl);
    let gamma0 = Vector3::new(0.0, 0.6, 0.8);
    let omega0 = Vector3::new(0.4, -0.2, 4.0);
    let e = 0.5 * omega0.dot(&(top.inertia * omega0)) + mgl * gamma0.z;
    let l3 = c * omega0.z;
    let lz = (top.inertia * omega0).dot(&gamma0);
    let e1 = e - 0.5 * c * omega0.z * omega0.z;
    let (u1, u2) = nutation_bounds(a, e1, mgl, lz, l3);
    let (theta_max, theta_min) = (u1.acos(), u2.acos());
    let t_end = 20.0;
    let times: Vec<f64> = (0..=20_000).map(|i| t_end * i as f64 / 20_000.0).collect();
    for opts in [
        SimOptions::with_tolerances(1e-12, 1e-13),
        SimOptions::lie_rk4(1e-3),
    ] {
        let opts = opts.with_attitude().at_times(times.clone());
        let tr = simulate_full(&top, omega0, gamma0, t_end, &opts).unwrap();
        let th: Vec<f64> = tr.euler_angles().iter().map(|e| e[1]).collect();
        let lo = th.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = th.iter().cloned().fold(0.0, f64::max);
        eprintln!(
            "{:?}: θ ∈ [{lo:.9}, {hi:.9}], cubic: [{theta_min:.9}, {theta_max:.9}]",
            opts.method
        );
        assert!((lo - theta_min).abs() < 1e-6, "{lo} vs {theta_min}");
        assert!((hi - theta_max).abs() < 1e-6, "{hi} vs {theta_max}");
    }
}

/// A steady motion is a regular precession: the Euler angle ψ grows at the steady motion's ψ̇,
/// θ and φ stay put. Checked on the full and on the reduced simulation (where the gauge ψ and
/// the Euler ψ then differ by a constant).
#[test]
fn steady_motion_precesses_at_its_psi_dot() {
    let model = asymmetric_top();
    let p_psi = 6.0;
    let motions = steady_motions(&model, p_psi).unwrap();
    assert!(!motions.is_empty());
    let t_end = 2.0;
    let times: Vec<f64> = (0..=20).map(|i| t_end * i as f64 / 20.0).collect();
    for s in &motions {
        let opts = SimOptions::with_tolerances(1e-12, 1e-13)
            .with_attitude()
            .at_times(times.clone());
        let tr = simulate_full(&model, s.gamma * s.psi_dot, s.gamma, t_end, &opts).unwrap();
        let rt = simulate_reduced(&model, Vector3::zeros(), s.gamma, p_psi, t_end, &opts).unwrap();
        for (k, eul) in [tr.euler_angles(), rt.euler_angles()].iter().enumerate() {
            for (e, &t) in eul.iter().zip(&times) {
                let psi = eul[0][0] + s.psi_dot * t;
                // Unstable motions drift away from the steady one: only short times.
                assert!(
                    (e[0] - psi).abs() < 1e-6,
                    "{k}: ψ {} vs {psi} at t = {t}",
                    e[0]
                );
                assert!((e[1] - eul[0][1]).abs() < 1e-6);
            }
        }
        // Reduced: the gauge ψ is ψ̇ t too.
        assert!((rt.psi.last().unwrap() - s.psi_dot * t_end).abs() < 1e-8);
        eprintln!("steady γ = {:?}: ψ̇ = {:.6}", s.gamma.as_slice(), s.psi_dot);
    }
}

/// The three classic apex loci of a heavy symmetric top, started at rest in θ at θ₀ with the
/// precession rate ψ̇₀: the classical criterion compares `u' = L_z/L₃` (where ψ̇ = 0) with the
/// nutation range `[u₁, u₂]` of `u = cos θ` from the cubic — inside: looping, at the turning
/// point `u₂`: cuspidal, outside: wavy. The simulation's ψ̇ must say the same.
#[test]
fn apex_loci_follow_the_classical_criterion() {
    use routh_core::sim::attitude::{classify_apex_locus, ApexLocus};
    let (a, c, mgl) = (1.0, 0.6, 1.0);
    let top = Gyrostat::lagrange_top(a, c, mgl);
    let (theta0, spin) = (0.5f64, 6.0);
    let slow = mgl / (c * spin); // the slow precession rate of a fast top
    for (psi_dot0, want) in [
        (-slow, ApexLocus::Looping),
        (0.0, ApexLocus::Cuspidal),
        (0.6 * slow, ApexLocus::Wavy),
    ] {
        // Body frame of Euler angles (ψ, θ, φ = 0): γ = (0, sin θ, cos θ); ω = ψ̇γ + spin-part.
        let gamma0 = Vector3::new(0.0, theta0.sin(), theta0.cos());
        // ω₃ = ψ̇ cos θ + φ̇ with φ̇ chosen for the given spin ω₃; ω₁ = θ̇ = 0, ω₂ = ψ̇ sin θ.
        let omega0 = Vector3::new(0.0, psi_dot0 * theta0.sin(), spin);
        let l3 = c * spin;
        let lz = (top.inertia * omega0).dot(&gamma0);
        let e = 0.5 * omega0.dot(&(top.inertia * omega0)) + mgl * gamma0.z;
        let (u1, u2) = nutation_bounds(a, e - 0.5 * c * spin * spin, mgl, lz, l3);
        let u_prime = lz / l3;
        let criterion = if (u_prime - u2).abs() < 1e-9 || (u_prime - u1).abs() < 1e-9 {
            ApexLocus::Cuspidal
        } else if u_prime > u1 && u_prime < u2 {
            ApexLocus::Looping
        } else {
            ApexLocus::Wavy
        };
        assert_eq!(criterion, want, "u' = {u_prime}, [{u1}, {u2}]");
        let t_end = 6.0;
        let times: Vec<f64> = (0..=6000).map(|i| t_end * i as f64 / 6000.0).collect();
        let opts = SimOptions::with_tolerances(1e-11, 1e-12)
            .with_attitude()
            .at_times(times.clone());
        let tr = simulate_full(&top, omega0, gamma0, t_end, &opts).unwrap();
        let got = classify_apex_locus(&tr.t, &tr.euler_angles(), 0.02).unwrap();
        eprintln!("ψ̇₀ = {psi_dot0:+.4}: u' = {u_prime:.5} in [{u1:.5}, {u2:.5}]? → {got}");
        assert_eq!(got, criterion);
    }
}
