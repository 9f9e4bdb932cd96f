//! Simulation checked against things the simulation code did not produce: first integrals
//! (3), (9), |γ| = 1; a closed-form solution (torque-free symmetric top); the reduced motion
//! (13) with (15) against the full motion (8) of the same initial state, including the body's
//! rotation about the vertical reconstructed geometrically from an independently integrated
//! body axis.
//!
//! Models come from `test-models` (hand-written L and R differentiated by num-dual).

use nalgebra::Rotation3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use routh_core::{
    simulate_full, simulate_reduced, Lagrangian, Method, RouthError, Routhian, SimOptions, Vector3,
};
use test_models::{random_tangent, random_unit_vector, Ellipsoid, Gyrostat};

fn asymmetric_top() -> Gyrostat {
    // I = diag(1, 2, 3), centre of mass off every principal axis.
    Gyrostat::heavy_top(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.3, -0.2, 0.5),
        1.0,
        9.81,
    )
}

fn top_initial_state() -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(1.0, -0.5, 2.0),
        Vector3::new(0.3, 0.4, 0.866).normalize(),
    )
}

/// A scale for the energy of a state: kinetic energy plus |potential| bound.
fn energy_scale(model: &Gyrostat, omega: &Vector3<f64>) -> f64 {
    0.5 * omega.dot(&(model.inertia * omega)) + model.mass * model.g * model.com.norm()
}

#[test]
fn heavy_asymmetric_top_keeps_its_integrals() {
    let model = asymmetric_top();
    let (w0, g0) = top_initial_state();
    let opts = SimOptions::with_tolerances(1e-12, 1e-12);
    let tr = simulate_full(&model, w0, g0, 10.0, &opts).expect("simulation");
    assert_eq!(tr.t[0], 0.0);
    assert_eq!(*tr.t.last().expect("points"), 10.0);
    assert!(tr.t.windows(2).all(|w| w[1] > w[0]));
    let e_scale = energy_scale(&model, &w0);
    let p_scale = (model.inertia * w0).norm();
    let e_drift = tr.energy_drift() / e_scale;
    let p_drift = tr.p_psi_drift() / p_scale;
    let g_err = tr.gamma_norm_error();
    eprintln!(
        "DOP853 heavy asymmetric top, t = 10, rtol = atol = 1e-12: {} steps ({} rejected, {} \
         evaluations); relative energy drift {e_drift:.2e}, relative p_psi drift {p_drift:.2e}, \
         max ||γ|² − 1| {g_err:.2e}",
        tr.stats.accepted_steps, tr.stats.rejected_steps, tr.stats.rhs_evaluations
    );
    assert!(e_drift <= 1e-9, "energy drift {e_drift:e}");
    assert!(p_drift <= 1e-9, "p_psi drift {p_drift:e}");
    assert!(g_err <= 1e-9, "|γ|² − 1 = {g_err:e}");
    // The energy is not trivially constant: the motion is a genuine tumble.
    let spread = tr.gamma.iter().map(|g| (g - g0).norm()).fold(0.0, f64::max);
    assert!(spread > 0.5, "γ hardly moved: {spread}");
}

/// The torque-free symmetric top `J = diag(A, A, C)` in closed form. With `m₀ = Jω₀` and
/// `μ = m₀₃(1/C − 1/A)`, `ω = m/A + μe₃`, so the body-to-space rotation is
/// `R(t) = exp(t[m₀/A]×) exp(tμ[e₃]×)` (check: `RᵀṘ = [Rᵀm₀/A + μe₃]× = [ω]×`). Hence
/// `ω(t) = exp(−tμ[e₃]×) ω₀` (ω precesses uniformly about the symmetry axis at
/// `λ = −μ = (C − A)ω₃/A`) and `γ(t) = Rᵀγ₀ = exp(−tμ[e₃]×) exp(−t[m₀/A]×) γ₀`.
struct FreeSymmetricTop {
    a: f64,
    c: f64,
    w0: Vector3<f64>,
    g0: Vector3<f64>,
}

impl FreeSymmetricTop {
    fn model(&self) -> Gyrostat {
        Gyrostat::heavy_top(
            Vector3::new(self.a, self.a, self.c),
            Vector3::zeros(),
            1.0,
            0.0,
        )
    }
    fn exact(&self, t: f64) -> (Vector3<f64>, Vector3<f64>) {
        let m0 = Vector3::new(self.a * self.w0.x, self.a * self.w0.y, self.c * self.w0.z);
        let mu = m0.z * (1.0 / self.c - 1.0 / self.a);
        let spin = Rotation3::from_scaled_axis(Vector3::z() * (-mu * t));
        let precession = Rotation3::from_scaled_axis(m0 * (-t / self.a));
        (spin * self.w0, spin * (precession * self.g0))
    }
}

fn free_symmetric_top() -> FreeSymmetricTop {
    FreeSymmetricTop {
        a: 2.0,
        c: 1.0,
        w0: Vector3::new(0.8, -0.3, 3.0),
        g0: Vector3::new(0.0, 0.6, 0.8),
    }
}

/// Least-squares slope of `ln e` against `ln h`.
fn fitted_order(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (xs, ys): (Vec<f64>, Vec<f64>) = points.iter().map(|(h, e)| (h.ln(), e.ln())).unzip();
    let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

fn show(points: &[(f64, f64)]) -> String {
    points
        .iter()
        .map(|(h, e)| format!("({h:.3e}, {e:.2e})"))
        .collect::<Vec<_>>()
        .join(" ")
}

const ORDER_T_END: f64 = 10.0;

/// The global error at `t_end` of `n` equal steps, against the closed form: `max(|Δω|, |Δγ|)`.
fn global_error(top: &FreeSymmetricTop, opts: &SimOptions, n: usize) -> f64 {
    let tr = simulate_full(&top.model(), top.w0, top.g0, ORDER_T_END, opts).expect("simulation");
    assert_eq!(tr.stats.accepted_steps, n);
    assert_eq!(tr.stats.rejected_steps, 0);
    let (w, g) = top.exact(ORDER_T_END);
    let last = tr.len() - 1;
    (tr.omega[last] - w).amax().max((tr.gamma[last] - g).amax())
}

/// DOP853 has order 8: with fixed steps (`h_init = h_max = h` and tolerances so loose that every
/// step is accepted), the global error at t = 10 against the closed form goes as h⁸.
#[test]
fn dop853_has_order_eight() {
    let top = free_symmetric_top();
    let points: Vec<(f64, f64)> = [40, 56, 80, 112]
        .into_iter()
        .map(|n| {
            let h = ORDER_T_END / n as f64;
            let opts = SimOptions {
                rtol: 1e10,
                atol: 1e10,
                h_init: Some(h),
                h_max: Some(h),
                ..SimOptions::default()
            };
            (h, global_error(&top, &opts, n))
        })
        .collect();
    let order = fitted_order(&points);
    eprintln!(
        "DOP853, fixed steps: (h, error) {}, fitted order {order:.2}",
        show(&points)
    );
    assert!(
        (order - 8.0).abs() < 0.5,
        "order {order}: {}",
        show(&points)
    );
}

/// The Lie RK4 has order 4 and keeps γ on the sphere to round-off at every step size.
#[test]
fn lie_rk4_has_order_four() {
    let top = free_symmetric_top();
    let mut points = vec![];
    for n in [200, 400, 800, 1600] {
        let h = ORDER_T_END / n as f64;
        let opts = SimOptions::lie_rk4(h);
        points.push((h, global_error(&top, &opts, n)));
        let tr =
            simulate_full(&top.model(), top.w0, top.g0, ORDER_T_END, &opts).expect("simulation");
        assert!(tr.gamma_norm_error() < 1e-13, "{:e}", tr.gamma_norm_error());
    }
    let order = fitted_order(&points);
    eprintln!(
        "LieRk4: (h, error) {}, fitted order {order:.2}",
        show(&points)
    );
    assert!(
        (order - 4.0).abs() < 0.5,
        "order {order}: {}",
        show(&points)
    );
}

/// The global error follows the tolerance (torque-free symmetric top, closed form).
#[test]
fn global_error_follows_the_tolerance() {
    let top = free_symmetric_top();
    let t_end = 20.0;
    let mut errors = vec![];
    for tol in [1e-6, 1e-8, 1e-10, 1e-12] {
        let tr = simulate_full(
            &top.model(),
            top.w0,
            top.g0,
            t_end,
            &SimOptions::with_tolerances(tol, tol),
        )
        .expect("simulation");
        let err =
            tr.t.iter()
                .zip(&tr.omega)
                .map(|(&t, w)| (w - top.exact(t).0).amax())
                .fold(0.0, f64::max);
        eprintln!(
            "DOP853 tol {tol:.0e}: {} steps, max |ω − ω_exact| = {err:.2e}",
            tr.len() - 1
        );
        assert!(err < 100.0 * tol, "tol {tol:e}: error {err:e}");
        errors.push(err);
    }
    for w in errors.windows(2) {
        assert!(
            w[1] < w[0] / 10.0,
            "errors do not follow the tolerance: {errors:?}"
        );
    }
}

#[test]
fn lie_method_keeps_gamma_on_the_sphere() {
    let model = asymmetric_top();
    let (w0, g0) = top_initial_state();
    let tr = simulate_full(&model, w0, g0, 10.0, &SimOptions::lie_rk4(1e-3)).expect("simulation");
    assert_eq!(tr.stats.accepted_steps, 10_000);
    assert_eq!(tr.len(), 10_001);
    let g_err = tr.gamma_norm_error();
    let e_drift = tr.energy_drift() / energy_scale(&model, &w0);
    let p_drift = tr.p_psi_drift() / (model.inertia * w0).norm();
    eprintln!(
        "LieRk4 heavy asymmetric top, 10^4 steps of 1e-3: max ||γ|² − 1| {g_err:.2e}, relative \
         energy drift {e_drift:.2e}, relative p_psi drift {p_drift:.2e}"
    );
    assert!(g_err <= 1e-13, "|γ|² − 1 = {g_err:e}");
    assert!(e_drift < 1e-8 && p_drift < 1e-8);

    // The same for the reduced equations (γ is moved by rotations there too).
    let p = model.cyclic_momentum(&w0, &g0);
    let big_omega0 = w0 - g0 * w0.dot(&g0);
    let tr = simulate_reduced(&model, big_omega0, g0, p, 10.0, &SimOptions::lie_rk4(1e-3))
        .expect("simulation");
    let g_err = tr.gamma_norm_error();
    eprintln!("LieRk4 reduced, 10^4 steps: max ||γ|² − 1| {g_err:.2e}");
    assert!(g_err <= 1e-13, "|γ|² − 1 = {g_err:e}");
}

/// Integrates the Poisson equation `dα/dt = α × w(t)` by RK4 with steps of `2δ`, from samples of
/// `w` on a uniform grid of spacing δ (the midpoint of each step is a grid point).
fn poisson_rk4(w: &[Vector3<f64>], delta: f64, alpha0: Vector3<f64>) -> Vec<Vector3<f64>> {
    let h = 2.0 * delta;
    let mut out = vec![alpha0];
    let mut a = alpha0;
    for i in (0..w.len() - 2).step_by(2) {
        let (w0, w1, w2) = (w[i], w[i + 1], w[i + 2]);
        let k1 = a.cross(&w0);
        let k2 = (a + k1 * (h / 2.0)).cross(&w1);
        let k3 = (a + k2 * (h / 2.0)).cross(&w1);
        let k4 = (a + k3 * h).cross(&w2);
        a += (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
        out.push(a);
    }
    out
}

/// Runs the full and the reduced simulation from corresponding states and compares them.
fn reduced_matches_full<M: Routhian>(name: &str, model: &M, seed: u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let g0 = random_unit_vector(&mut rng);
    // A full initial state, its cyclic momentum (9), and the decomposition (7) with Ω₀ ⊥ γ₀.
    let w0 = random_unit_vector(&mut rng) * 2.0;
    let p = model.cyclic_momentum(&w0, &g0);
    let big_omega0 = w0 - g0 * w0.dot(&g0);
    let psi_dot0 = model.psi_dot(&big_omega0, &g0, p);
    // The two states correspond: ω₀ = Ω₀ + ψ̇(Ω₀, γ₀, p)γ₀ by (12).
    assert!((big_omega0 + g0 * psi_dot0 - w0).amax() < 1e-13);

    let t_end: f64 = 10.0;
    let delta: f64 = 1e-3;
    let n = (t_end / delta).round() as usize;
    let times: Vec<f64> = (0..=n).map(|i| i as f64 * delta).collect();
    let opts = SimOptions::with_tolerances(1e-12, 1e-12).at_times(times.clone());
    let full = simulate_full(model, w0, g0, t_end, &opts).expect("full simulation");
    let red = simulate_reduced(model, big_omega0, g0, p, t_end, &opts).expect("reduced");
    assert_eq!(full.t, times);
    assert_eq!(red.t, times);

    // γ(t) and ω(t) = Ω + ψ̇γ agree.
    let gamma_diff = (0..=n)
        .map(|i| (full.gamma[i] - red.gamma[i]).amax())
        .fold(0.0, f64::max);
    let omega_diff = (0..=n)
        .map(|i| (full.omega[i] - red.omega[i]).amax())
        .fold(0.0, f64::max);
    // E' (16) = E (3), (∂R/∂Ω, γ) (17) = p_ψ, Ω·γ stays 0 (gauge, errata E4).
    let e_scale = full.energy[0].abs() + full.omega[0].norm_squared();
    let energy_diff = (0..=n)
        .map(|i| (full.energy[i] - red.energy[i]).abs())
        .fold(0.0, f64::max)
        / e_scale;
    let p_err = red.p_psi_error(p) / (1.0 + p.abs());
    let gauge = red
        .big_omega
        .iter()
        .zip(&red.gamma)
        .map(|(w, g)| w.dot(g).abs())
        .fold(0.0, f64::max);

    // ψ(t) = ∫ ψ̇ dt with ψ̇ = ω·γ (as Ω·γ = 0) from the FULL motion, by Simpson's rule.
    let wg: Vec<f64> = (0..=n).map(|i| full.omega[i].dot(&full.gamma[i])).collect();
    let mut psi_quad = 0.0;
    let mut psi_diff: f64 = 0.0;
    for i in (0..n).step_by(2) {
        psi_quad += (wg[i] + 4.0 * wg[i + 1] + wg[i + 2]) * delta / 3.0;
        psi_diff = psi_diff.max((psi_quad - red.psi[i + 2]).abs());
    }

    // The geometric check: a body axis α, horizontal at t = 0, followed in the full motion
    // (dα/dt = α × ω) and in the reduced motion relative to the rotating frame (dα'/dt = α' × Ω).
    // Since the body frame is rot_z(ψ) ∘ (reduced frame): α = cos ψ α' − sin ψ (γ × α').
    let alpha0 = random_tangent(&mut rng, &g0);
    let alpha_full = poisson_rk4(&full.omega, delta, alpha0);
    let alpha_red = poisson_rk4(&red.big_omega, delta, alpha0);
    let mut alpha_diff: f64 = 0.0;
    for (j, (af, ar)) in alpha_full.iter().zip(&alpha_red).enumerate() {
        let i = 2 * j;
        let (s, c) = red.psi[i].sin_cos();
        let predicted = ar * c - red.gamma[i].cross(ar) * s;
        alpha_diff = alpha_diff.max((af - predicted).amax());
    }
    let psi_range = red.psi.iter().fold(0.0f64, |m, &x| m.max(x.abs()));

    eprintln!(
        "{name}: full {} steps, reduced {} steps; max |γ_full − γ_red| {gamma_diff:.2e}, \
         max |ω_full − (Ω + ψ̇γ)| {omega_diff:.2e}, max |E − E'|/scale {energy_diff:.2e}, \
         max |(∂R/∂Ω, γ) − p|/(1+|p|) {p_err:.2e}, max |Ω·γ| {gauge:.2e}, \
         max |ψ − ∫ω·γ dt| {psi_diff:.2e}, max |α − (cos ψ α' − sin ψ γ×α')| {alpha_diff:.2e} \
         (max |ψ| = {psi_range:.2})",
        full.stats.accepted_steps, red.stats.accepted_steps
    );
    assert!(gamma_diff <= 1e-8, "γ differs by {gamma_diff:e}");
    assert!(omega_diff <= 1e-8, "ω differs by {omega_diff:e}");
    assert!(energy_diff <= 1e-9, "E' − E = {energy_diff:e}");
    assert!(p_err <= 1e-9, "(∂R/∂Ω, γ) − p = {p_err:e}");
    assert!(gauge <= 1e-9, "Ω·γ = {gauge:e}");
    assert!(psi_diff <= 1e-8, "ψ differs from ∫ω·γ by {psi_diff:e}");
    assert!(alpha_diff <= 1e-7, "α differs by {alpha_diff:e}");
    assert!(
        psi_range > 0.5,
        "ψ hardly moved ({psi_range}): the check would be vacuous"
    );
}

#[test]
fn reduced_matches_full_gyrostat() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let model = Gyrostat::random(&mut rng);
    reduced_matches_full("gyrostat (general I, K, B)", &model, 12);
}

#[test]
fn reduced_matches_full_ellipsoid() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let model = Ellipsoid::random(&mut rng);
    reduced_matches_full("ellipsoid on a plane", &model, 22);
}

#[test]
fn reduced_input_errors() {
    let model = asymmetric_top();
    let g0 = Vector3::z();
    let o = SimOptions::default();
    assert!(matches!(
        simulate_reduced(&model, Vector3::zeros(), g0, f64::NAN, 1.0, &o),
        Err(RouthError::NonFinite { what: "p_psi", .. })
    ));
    assert!(matches!(
        simulate_reduced(&model, Vector3::zeros(), g0 * 0.5, 1.0, 1.0, &o),
        Err(RouthError::NonUnitGamma { .. })
    ));
    assert!(matches!(
        simulate_reduced(&model, Vector3::zeros(), g0, 1.0, -1.0, &o),
        Err(RouthError::InvalidOption { what: "t_end", .. })
    ));
    // A model whose vertical moment of inertia vanishes: I = diag(1, 1, 0) at γ = e₃.
    let degenerate = Gyrostat::heavy_top(Vector3::new(1.0, 1.0, 0.0), Vector3::zeros(), 1.0, 1.0);
    assert!(matches!(
        simulate_reduced(&degenerate, Vector3::zeros(), g0, 1.0, 1.0, &o),
        Err(RouthError::DegenerateVerticalInertia { .. })
    ));
    // Method and output options are honoured by the reduced simulation too.
    let opts = SimOptions {
        method: Method::LieRk4 { step: 0.1 },
        ..o
    }
    .at_times(vec![0.0, 0.5, 1.0]);
    let tr = simulate_reduced(&model, Vector3::new(0.1, 0.0, 0.0), g0, 1.0, 1.0, &opts)
        .expect("simulation");
    assert_eq!(tr.t, vec![0.0, 0.5, 1.0]);
    assert_eq!(tr.psi[0], 0.0);
    assert_eq!(tr.stats.accepted_steps, 10);
}
