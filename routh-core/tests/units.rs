//! Units and symmetries of the simulation (docs/method.md §2): the same motion written in other units, in
//! a rotated body frame, or run backwards in time, must give the same trajectory and the same
//! work, for the full equations (8) and for the reduced equations (13) in the gauge of E4.
//!
//! How each change of units maps solutions, for `L = ½ωᵀJω + a(γ)·ω − U(γ)`:
//!
//! - `J → kJ, a → ka, U → kU` multiplies L by k: the same equations. ω, Ω, γ, ψ are unchanged,
//!   `p_ψ → k p_ψ`, the energy → k·E.
//! - Time `t → t/s` (everything s times faster): `ω̃(t) = s ω(st)`, `γ̃(t) = γ(st)`. The action
//!   `∫ L̃(ω̃, γ̃) dt` is proportional to the old one when `a → s a, U → s² U` (J unchanged), so
//!   `p_ψ → s p_ψ`. The angular velocities carry the unit 1/time, so their absolute tolerance
//!   [`SimOptions::rate_atol`] scales by s; γ and ψ are dimensionless and keep theirs.
//! - Lengths `ℓ` (ellipsoid semi-axes and offset, a top's centre of mass) with inertia `∝ ℓ²`:
//!   `J → ℓ²J`, `U → ℓU`, that is the two above with `k = ℓ²`, `s = ℓ^{−1/2}`.
//! - A rotation Q of the body frame: `J → QJQᵀ`, `a(γ) → Q a(Qᵀγ)`, `U(γ) → U(Qᵀγ)`; then
//!   `γ̃ = Qγ`, `ω̃ = Qω`, `Ω̃ = QΩ`, and p_ψ, ψ, the energy are unchanged.
//! - Time reversal: `a → −a` with `ω → −ω` gives `p_ψ → −p_ψ` and the motion run backwards,
//!   `γ̃(t) = γ(T − t)`.

use nalgebra::{Matrix3, Rotation3, Vector3};
use routh_core::{
    simulate_full, simulate_reduced, Lagrangian, ReducedTrajectory, RouthError, Routhian,
    SimOptions,
};
use test_models::Ellipsoid;

/// A hand-written gyrostat `L = ½ωᵀJω + (K + Bγ)·ω − c·γ` with its Routh function (39) and every
/// derivative in closed form (J constant and symmetric positive definite).
#[derive(Debug, Clone)]
struct Gyro {
    j: Matrix3<f64>,
    k: Vector3<f64>,
    b: Matrix3<f64>,
    c: Vector3<f64>,
}

/// The quantities of (38)–(39) at `(Ω, γ, p)`: `a`, `d = p − q`, `r = d/(γᵀJγ)` (= ψ̇),
/// `∂q/∂γ` and `∂r/∂γ`.
struct Parts {
    a: Vector3<f64>,
    d: f64,
    r: f64,
    gq: Vector3<f64>,
    dr: Vector3<f64>,
}

impl Gyro {
    fn parts(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Parts {
        let a = self.k + self.b * g;
        let jg = self.j * g;
        let n = g.dot(&jg);
        let q = (self.j * w).dot(g) + a.dot(g);
        let d = p - q;
        let r = d / n;
        let gq = self.j * w + a + self.b.transpose() * g;
        let dr = -(gq + jg * (2.0 * r)) / n;
        Parts { a, d, r, gq, dr }
    }

    /// Scaled units: `J → kJ`, `a → k s a`, `U → k s² U` (see the module docs).
    fn scaled(&self, k: f64, s: f64) -> Self {
        Gyro {
            j: self.j * k,
            k: self.k * (k * s),
            b: self.b * (k * s),
            c: self.c * (k * s * s),
        }
    }

    /// The same body in a frame rotated by Q.
    fn rotated(&self, q: &Matrix3<f64>) -> Self {
        Gyro {
            j: q * self.j * q.transpose(),
            k: q * self.k,
            b: q * self.b * q.transpose(),
            c: q * self.c,
        }
    }

    /// The gyroscopic terms reversed.
    fn reversed(&self) -> Self {
        Gyro {
            k: -self.k,
            b: -self.b,
            ..self.clone()
        }
    }
}

impl Lagrangian for Gyro {
    fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
        0.5 * w.dot(&(self.j * w)) + (self.k + self.b * g).dot(w) - self.c.dot(g)
    }
    fn dl_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
        self.j * w + self.k + self.b * g
    }
    fn dl_dgamma(&self, w: &Vector3<f64>, _: &Vector3<f64>) -> Vector3<f64> {
        self.b.transpose() * w - self.c
    }
    fn d2l_domega2(&self, _: &Vector3<f64>) -> Matrix3<f64> {
        self.j
    }
    fn d2l_domega_dgamma(&self, _: &Vector3<f64>, _: &Vector3<f64>) -> Matrix3<f64> {
        self.b
    }
}

impl Routhian for Gyro {
    fn routhian(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> f64 {
        let s = self.parts(w, g, p);
        0.5 * w.dot(&(self.j * w)) + s.a.dot(w) - self.c.dot(g) - 0.5 * s.d * s.r
    }
    fn dr_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let s = self.parts(w, g, p);
        self.j * w + s.a + self.j * g * s.r
    }
    fn dr_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Vector3<f64> {
        let s = self.parts(w, g, p);
        self.b.transpose() * w - self.c + s.gq * s.r + self.j * g * (s.r * s.r)
    }
    fn d2r_domega2(&self, _: &Vector3<f64>, g: &Vector3<f64>, _: f64) -> Matrix3<f64> {
        let jg = self.j * g;
        self.j - jg * jg.transpose() / g.dot(&jg)
    }
    fn d2r_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
        let s = self.parts(w, g, p);
        self.b + self.j * g * s.dr.transpose() + self.j * s.r
    }
    fn d2r_dgamma2(&self, w: &Vector3<f64>, g: &Vector3<f64>, p: f64) -> Matrix3<f64> {
        let s = self.parts(w, g, p);
        (s.gq + self.j * g * (2.0 * s.r)) * s.dr.transpose()
            + (self.b + self.b.transpose()) * s.r
            + self.j * (s.r * s.r)
    }
}

/// A heavy asymmetric top (centre of mass off every principal axis), no gyroscopic term.
fn heavy_top() -> Gyro {
    Gyro {
        j: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        k: Vector3::zeros(),
        b: Matrix3::zeros(),
        c: Vector3::new(0.3, -0.2, 0.5) * 9.81,
    }
}

/// A gyrostat with a rotor, a non-symmetric coupling and a full inertia tensor.
fn gyrostat() -> Gyro {
    let j = Matrix3::new(2.0, 0.3, -0.2, 0.3, 1.5, 0.1, -0.2, 0.1, 1.0);
    Gyro {
        j,
        k: Vector3::new(0.4, -0.3, 0.2),
        b: Matrix3::new(0.1, -0.3, 0.2, 0.25, 0.0, -0.15, 0.05, 0.35, -0.1),
        c: Vector3::new(-0.5, 0.7, 1.2) * 9.81,
    }
}

fn initial_state() -> (Vector3<f64>, Vector3<f64>) {
    (
        Vector3::new(1.0, -0.5, 2.0),
        Vector3::new(0.3, 0.4, 0.866).normalize(),
    )
}

/// `Ω₀ = ω₀ − (ω₀·γ₀)γ₀` (Ω₀ ⊥ γ₀) and `p_ψ` (9) of the full state.
fn reduced_state<M: Lagrangian>(
    m: &M,
    w0: &Vector3<f64>,
    g0: &Vector3<f64>,
) -> (Vector3<f64>, f64) {
    (w0 - g0 * w0.dot(g0), m.cyclic_momentum(w0, g0))
}

const T_END: f64 = 5.0;
const N_OUT: usize = 50;

fn times(scale: f64) -> Vec<f64> {
    (0..=N_OUT)
        .map(|i| i as f64 * T_END / N_OUT as f64 * scale)
        .collect()
}

fn max_diff(a: &[Vector3<f64>], b: &[Vector3<f64>], scale: f64) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y * scale).amax())
        .fold(0.0, |m, d| if d.is_nan() { f64::NAN } else { m.max(d) })
}

/// The options of one run in units where time runs `s` times faster: output times `t/s`, the
/// absolute tolerance of the angular velocities `s·rate_atol`.
fn options(s: f64) -> SimOptions {
    let base = SimOptions::default();
    SimOptions {
        rate_atol: Some(base.atol * s),
        ..base
    }
    .at_times(times(1.0 / s))
}

/// `simulate_reduced` of the heavy top with inertia and potential scaled by k: the motion is the
/// same, so is the work (at k = 1e9 an earlier version stopped with "too many steps").
#[test]
fn scaled_heavy_top_reduced_takes_the_same_steps() {
    let (w0, g0) = initial_state();
    let top = heavy_top();
    let (big_omega0, p) = reduced_state(&top, &w0, &g0);
    // Recorded at fixed times: the step sizes themselves differ at round-off level (the error
    // estimate is a difference of stages), so the ends of the steps do too.
    let opts = SimOptions::default().at_times(times(1.0));
    let base = simulate_reduced(&top, big_omega0, g0, p, T_END, &opts).expect("unscaled");
    for k in [1e-9, 1e-3, 1e3, 1e9] {
        let m = top.scaled(k, 1.0);
        let tr = simulate_reduced(&m, big_omega0, g0, p * k, T_END, &opts)
            .unwrap_or_else(|e| panic!("k = {k:e}: {e}"));
        eprintln!(
            "heavy top, J and U × {k:e}: {} steps ({} rejected) vs {} ({}) unscaled",
            tr.stats.accepted_steps,
            tr.stats.rejected_steps,
            base.stats.accepted_steps,
            base.stats.rejected_steps
        );
        assert_eq!(tr.stats, base.stats, "k = {k:e}");
        let dg = max_diff(&tr.gamma, &base.gamma, 1.0);
        // The gauge Ω·γ = 0 holds to the integration error (a quadratic invariant), the same in
        // every unit.
        let gauge = |tr: &ReducedTrajectory| {
            tr.big_omega
                .iter()
                .zip(&tr.gamma)
                .map(|(w, g)| w.dot(g).abs())
                .fold(0.0, f64::max)
        };
        let (g_scaled, g_base) = (gauge(&tr), gauge(&base));
        assert!(dg < 1e-12, "k = {k:e}: γ differs by {dg:e}");
        assert!(g_scaled < 1e-9, "k = {k:e}: Ω·γ = {g_scaled:e}");
        assert!(
            (g_scaled - g_base).abs() < 1e-12,
            "k = {k:e}: Ω·γ = {g_scaled:e} vs {g_base:e}"
        );
    }
}

/// Both simulations of one model and initial state, in the units `(k, s)`.
fn check_scalings(name: &str, model: &Gyro) {
    let (w0, g0) = initial_state();
    let (big_omega0, p) = reduced_state(model, &w0, &g0);
    let full0 = simulate_full(model, w0, g0, T_END, &options(1.0)).expect("full");
    let red0 = simulate_reduced(model, big_omega0, g0, p, T_END, &options(1.0)).expect("reduced");
    for k in [1e-9, 1e-4, 1.0, 1e4, 1e9] {
        for s in [1e-9, 1e-4, 1.0, 1e4, 1e9] {
            let m = model.scaled(k, s);
            let t_end = T_END / s;
            let opts = options(s);
            let full = simulate_full(&m, w0 * s, g0, t_end, &opts)
                .unwrap_or_else(|e| panic!("{name} full, k = {k:e}, s = {s:e}: {e}"));
            let red = simulate_reduced(&m, big_omega0 * s, g0, p * k * s, t_end, &opts)
                .unwrap_or_else(|e| panic!("{name} reduced, k = {k:e}, s = {s:e}: {e}"));
            let dg_full = max_diff(&full.gamma, &full0.gamma, 1.0);
            let dw_full = max_diff(&full.omega, &full0.omega, s) / s;
            let dg_red = max_diff(&red.gamma, &red0.gamma, 1.0);
            let dw_red = max_diff(&red.big_omega, &red0.big_omega, s) / s;
            let dpsi = red
                .psi
                .iter()
                .zip(&red0.psi)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            eprintln!(
                "{name}, k = {k:.0e}, s = {s:.0e}: full {} steps ({} rejected) vs {} ({}), \
                 reduced {} ({}) vs {} ({}); |Δγ| {dg_full:.1e} / {dg_red:.1e}, |Δω|/s \
                 {dw_full:.1e} / {dw_red:.1e}, |Δψ| {dpsi:.1e}",
                full.stats.accepted_steps,
                full.stats.rejected_steps,
                full0.stats.accepted_steps,
                full0.stats.rejected_steps,
                red.stats.accepted_steps,
                red.stats.rejected_steps,
                red0.stats.accepted_steps,
                red0.stats.rejected_steps,
            );
            assert_eq!(full.t.len(), full0.t.len());
            for (a, b) in full.t.iter().zip(&full0.t) {
                assert!((a * s - b).abs() <= 1e-15 * T_END);
            }
            assert_eq!(full.stats, full0.stats, "{name} full, k = {k:e}, s = {s:e}");
            assert_eq!(
                red.stats, red0.stats,
                "{name} reduced, k = {k:e}, s = {s:e}"
            );
            for (what, d) in [
                ("full γ", dg_full),
                ("full ω/s", dw_full),
                ("reduced γ", dg_red),
                ("reduced Ω/s", dw_red),
                ("ψ", dpsi),
            ] {
                assert!(
                    d < 1e-10,
                    "{name}, k = {k:e}, s = {s:e}: {what} differs by {d:e}"
                );
            }
        }
    }
}

#[test]
fn inertia_potential_momentum_and_time_scalings_heavy_top() {
    check_scalings("heavy top", &heavy_top());
}

#[test]
fn inertia_potential_momentum_and_time_scalings_gyrostat() {
    check_scalings("gyrostat", &gyrostat());
}

/// Lengths: a heavy ellipsoid on a plane (configuration-dependent `J = I + m uuᵀ`) with its
/// semi-axes and offset scaled by ℓ and its inertia by ℓ² has `J → ℓ²J`, `U → ℓU`: the same
/// motion with time scaled by `s = ℓ^{−1/2}` (a pendulum's period goes as `√ℓ`), `p_ψ → ℓ^{3/2}p_ψ`.
#[test]
fn lengths_scale_time_by_the_square_root_ellipsoid() {
    let body = |l: f64| {
        let i = Matrix3::new(1.2, 0.1, -0.05, 0.1, 1.6, 0.08, -0.05, 0.08, 2.0);
        Ellipsoid::new(
            i * (l * l),
            Vector3::new(0.8, 1.0, 1.3) * l,
            Vector3::new(0.05, -0.1, 0.08) * l,
            1.5,
            9.81,
        )
    };
    let (w0, g0) = initial_state();
    let m0 = body(1.0);
    let (big_omega0, p) = reduced_state(&m0, &w0, &g0);
    let full0 = simulate_full(&m0, w0, g0, T_END, &options(1.0)).expect("full");
    let red0 = simulate_reduced(&m0, big_omega0, g0, p, T_END, &options(1.0)).expect("reduced");
    for l in [1e-9, 1e-3, 1e3, 1e9] {
        let m = body(l);
        let s = 1.0 / l.sqrt();
        let opts = options(s);
        let full = simulate_full(&m, w0 * s, g0, T_END / s, &opts)
            .unwrap_or_else(|e| panic!("ℓ = {l:e}: {e}"));
        let red = simulate_reduced(&m, big_omega0 * s, g0, p * l * l * s, T_END / s, &opts)
            .unwrap_or_else(|e| panic!("ℓ = {l:e}: {e}"));
        let dg =
            max_diff(&full.gamma, &full0.gamma, 1.0).max(max_diff(&red.gamma, &red0.gamma, 1.0));
        let dw =
            max_diff(&full.omega, &full0.omega, s).max(max_diff(&red.omega, &red0.omega, s)) / s;
        eprintln!(
            "ellipsoid, ℓ = {l:.0e}: full {} steps vs {}, reduced {} vs {}; |Δγ| {dg:.1e}, |Δω|/s {dw:.1e}",
            full.stats.accepted_steps,
            full0.stats.accepted_steps,
            red.stats.accepted_steps,
            red0.stats.accepted_steps
        );
        assert_eq!(full.stats, full0.stats, "ℓ = {l:e}");
        assert_eq!(red.stats, red0.stats, "ℓ = {l:e}");
        assert!(dg < 1e-10 && dw < 1e-10, "ℓ = {l:e}: {dg:e} {dw:e}");
    }
}

/// Rotating the body frame by Q rotates γ, ω and Ω, and changes nothing else: not ψ, not the
/// integrals, not the steps.
#[test]
fn rotating_the_body_frame_rotates_gamma_and_nothing_else() {
    let (w0, g0) = initial_state();
    for (name, model) in [("heavy top", heavy_top()), ("gyrostat", gyrostat())] {
        let (big_omega0, p) = reduced_state(&model, &w0, &g0);
        let full0 = simulate_full(&model, w0, g0, T_END, &options(1.0)).expect("full");
        let red0 =
            simulate_reduced(&model, big_omega0, g0, p, T_END, &options(1.0)).expect("reduced");
        for angles in [(0.3, -1.1, 2.0), (2.5, 0.4, -0.7)] {
            let q = *Rotation3::from_euler_angles(angles.0, angles.1, angles.2).matrix();
            let m = model.rotated(&q);
            let full = simulate_full(&m, q * w0, q * g0, T_END, &options(1.0)).expect("full");
            let red = simulate_reduced(&m, q * big_omega0, q * g0, p, T_END, &options(1.0))
                .expect("reduced");
            let rot = |v: &[Vector3<f64>]| v.iter().map(|x| q * x).collect::<Vec<_>>();
            let d = [
                max_diff(&full.gamma, &rot(&full0.gamma), 1.0),
                max_diff(&full.omega, &rot(&full0.omega), 1.0),
                max_diff(&red.gamma, &rot(&red0.gamma), 1.0),
                max_diff(&red.big_omega, &rot(&red0.big_omega), 1.0),
            ];
            let scalars = |a: &[f64], b: &[f64]| {
                a.iter()
                    .zip(b)
                    .map(|(x, y)| (x - y).abs())
                    .fold(0.0, f64::max)
            };
            let ds = [
                scalars(&red.psi, &red0.psi),
                scalars(&full.energy, &full0.energy),
                scalars(&full.p_psi, &full0.p_psi),
                scalars(&red.energy, &red0.energy),
            ];
            eprintln!(
                "{name} rotated by {angles:?}: full {} steps vs {}, reduced {} vs {}; \
                 |Δ(γ, ω, γ_red, Ω)| {:?}, |Δ(ψ, E, p, E')| {:?}",
                full.stats.accepted_steps,
                full0.stats.accepted_steps,
                red.stats.accepted_steps,
                red0.stats.accepted_steps,
                d.map(|x| format!("{x:.1e}")),
                ds.map(|x| format!("{x:.1e}")),
            );
            assert_eq!(full.stats, full0.stats, "{name}");
            assert_eq!(red.stats, red0.stats, "{name}");
            assert!(
                d.iter().chain(&ds).all(|&x| x < 1e-10),
                "{name}: {d:?} {ds:?}"
            );
        }
    }
}

/// `a → −a`, `ω → −ω` (so `p_ψ → −p_ψ`) is time reversal: started from the reversed final
/// state, the motion retraces γ backwards, `γ̃(t) = γ(T − t)`, and returns to the reversed
/// initial state.
#[test]
fn reversing_momentum_and_gyroscopic_terms_runs_the_motion_backwards() {
    let (w0, g0) = initial_state();
    let opts = SimOptions::with_tolerances(1e-12, 1e-12).at_times(times(1.0));
    for (name, model) in [("heavy top", heavy_top()), ("gyrostat", gyrostat())] {
        let rev = model.reversed();
        let fwd = simulate_full(&model, w0, g0, T_END, &opts).expect("full");
        let n = fwd.t.len() - 1;
        let back = simulate_full(&rev, -fwd.omega[n], fwd.gamma[n], T_END, &opts).expect("full");
        let mut d: f64 = 0.0;
        for i in 0..=n {
            d = d
                .max((back.gamma[i] - fwd.gamma[n - i]).amax())
                .max((back.omega[i] + fwd.omega[n - i]).amax());
        }
        assert!((back.p_psi[0] + fwd.p_psi[0]).abs() < 1e-9);

        let (big_omega0, p) = reduced_state(&model, &w0, &g0);
        let fwd = simulate_reduced(&model, big_omega0, g0, p, T_END, &opts).expect("reduced");
        let back = simulate_reduced(&rev, -fwd.big_omega[n], fwd.gamma[n], -p, T_END, &opts)
            .expect("reduced");
        let mut dr: f64 = 0.0;
        for i in 0..=n {
            dr = dr
                .max((back.gamma[i] - fwd.gamma[n - i]).amax())
                .max((back.big_omega[i] + fwd.big_omega[n - i]).amax())
                .max((back.psi[i] - (fwd.psi[n - i] - fwd.psi[n])).abs());
        }
        eprintln!("{name}, time reversal: full {d:.1e}, reduced {dr:.1e}");
        assert!(d < 1e-8 && dr < 1e-8, "{name}: {d:e} {dr:e}");
    }
}

/// Huge but finite inputs: a correct answer, or an error naming the input; never a panic or a
/// hang (the step budget bounds the work).
#[test]
fn huge_values_give_an_answer_or_a_clear_error() {
    // The Lagrange top J = diag(2, 2, 1) standing upright and spinning with p_ψ = 1e150: a
    // steady motion, ψ = p_ψ t / C.
    let lagrange = Gyro {
        j: Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 1.0)),
        k: Vector3::zeros(),
        b: Matrix3::zeros(),
        c: Vector3::new(0.0, 0.0, 9.81),
    };
    let p = 1e150;
    let tr = simulate_reduced(
        &lagrange,
        Vector3::zeros(),
        Vector3::z(),
        p,
        T_END,
        &options(1.0),
    )
    .expect("steady motion");
    for (t, (g, psi)) in tr.t.iter().zip(tr.gamma.iter().zip(&tr.psi)) {
        assert_eq!(*g, Vector3::z());
        assert!(
            (psi - p * t).abs() <= 1e-14 * p * t,
            "{psi:e} vs {:e}",
            p * t
        );
    }
    let tr = simulate_full(
        &lagrange,
        Vector3::z() * p,
        Vector3::z(),
        T_END,
        &options(1.0),
    )
    .expect("steady motion");
    assert!(tr.gamma.iter().all(|g| *g == Vector3::z()));

    // Tilted: a precession far too fast for the step budget.
    let (w0, g0) = initial_state();
    let model = heavy_top();
    let small = SimOptions {
        max_steps: 2_000,
        ..SimOptions::default()
    };
    let r = simulate_reduced(&model, Vector3::zeros(), g0, p, 1.0, &small);
    assert!(matches!(r, Err(RouthError::TooManySteps { .. })), "{r:?}");
    let r = simulate_full(&model, w0 * p, g0, 1.0, &small);
    assert!(matches!(r, Err(RouthError::TooManySteps { .. })), "{r:?}");

    // So large that the vector field overflows at the start: the input is named.
    let r = simulate_reduced(&model, Vector3::zeros(), g0, 1e200, 1.0, &small);
    assert!(
        matches!(r, Err(RouthError::InvalidOption { what: "p_psi", .. })),
        "{r:?}"
    );
    eprintln!("{}", r.unwrap_err());
    let r = simulate_reduced(&model, w0 * 1e200, g0, 1.0, 1.0, &small);
    assert!(
        matches!(
            r,
            Err(RouthError::InvalidOption {
                what: "big_omega0",
                ..
            })
        ),
        "{r:?}"
    );
    let r = simulate_full(&model, w0 * 1e200, g0, 1.0, &small);
    assert!(
        matches!(r, Err(RouthError::InvalidOption { what: "omega0", .. })),
        "{r:?}"
    );
    eprintln!("{}", r.unwrap_err());
    // A model whose own outputs overflow (J ~ 1e200: JγγᵀJ overflows): the model is named.
    let r = simulate_reduced(
        &model.scaled(1e200, 1.0),
        Vector3::zeros(),
        g0,
        1.0,
        1.0,
        &small,
    );
    assert!(matches!(r, Err(RouthError::NonFiniteModel { .. })), "{r:?}");
    eprintln!("{}", r.unwrap_err());
}
