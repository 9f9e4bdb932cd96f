//! Paper Example 3 end to end: the equations (8) of the Lagrangian of errata E3
//! (`routh::fluid::kirchhoff_lagrangian`, declared with the derive in `derived-models`),
//! integrated by `routh::simulate_full`, reproduce Kirchhoff's equations (52) integrated directly
//! in `(ω, v)` by a classical Runge–Kutta method written here.

use derived_models::{FluidBody, Kirchhoff};
use routh::nalgebra::{Matrix6, Vector6};
use routh::{simulate_full, Matrix3, SimOptions, Vector3};

/// Kirchhoff's equations (52) in the momenta `m = ∂T/∂ω = aω + bᵀv`, `p = ∂T/∂v = bω + cv`:
/// `ṁ = m × ω + p × v`, `ṗ = p × ω`, with `(ω, v)` recovered from the 6×6 kinetic matrix.
struct Direct {
    mass_inv: Matrix6<f64>,
    mass: Matrix6<f64>,
}

impl Direct {
    fn new(body: &Kirchhoff) -> Self {
        let mut mass = Matrix6::zeros();
        mass.fixed_view_mut::<3, 3>(0, 0).copy_from(&body.a);
        mass.fixed_view_mut::<3, 3>(0, 3)
            .copy_from(&body.b.transpose());
        mass.fixed_view_mut::<3, 3>(3, 0).copy_from(&body.b);
        mass.fixed_view_mut::<3, 3>(3, 3).copy_from(&body.c);
        let mass_inv = mass.cholesky().expect("T positive definite").inverse();
        Direct { mass_inv, mass }
    }

    /// `(ω, v)` from the momenta `(m, p)`.
    fn velocities(&self, y: &Vector6<f64>) -> (Vector3<f64>, Vector3<f64>) {
        let u = self.mass_inv * y;
        (u.fixed_rows::<3>(0).into(), u.fixed_rows::<3>(3).into())
    }

    fn momenta(&self, omega: &Vector3<f64>, v: &Vector3<f64>) -> Vector6<f64> {
        let mut u = Vector6::zeros();
        u.fixed_rows_mut::<3>(0).copy_from(omega);
        u.fixed_rows_mut::<3>(3).copy_from(v);
        self.mass * u
    }

    fn rate(&self, y: &Vector6<f64>) -> Vector6<f64> {
        let (w, v) = self.velocities(y);
        let m: Vector3<f64> = y.fixed_rows::<3>(0).into();
        let p: Vector3<f64> = y.fixed_rows::<3>(3).into();
        let mut d = Vector6::zeros();
        d.fixed_rows_mut::<3>(0)
            .copy_from(&(m.cross(&w) + p.cross(&v)));
        d.fixed_rows_mut::<3>(3).copy_from(&p.cross(&w));
        d
    }

    /// Classical RK4 with `steps_per_unit` steps per unit of time, sampled at `t = i·dt_out`.
    fn integrate(
        &self,
        y0: Vector6<f64>,
        n_out: usize,
        dt_out: f64,
        substeps: usize,
    ) -> Vec<Vector6<f64>> {
        let h = dt_out / substeps as f64;
        let mut y = y0;
        let mut out = vec![y];
        for _ in 1..n_out {
            for _ in 0..substeps {
                let k1 = self.rate(&y);
                let k2 = self.rate(&(y + 0.5 * h * k1));
                let k3 = self.rate(&(y + 0.5 * h * k2));
                let k4 = self.rate(&(y + h * k3));
                y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            }
            out.push(y);
        }
        out
    }
}

/// A body with general (non-diagonal, non-symmetric `b`) coefficients: `M = LLᵀ + ½E` for a fixed
/// pseudo-random `L`.
fn general_body() -> Kirchhoff {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let l = Matrix6::<f64>::from_fn(|_, _| next());
    let m: Matrix6<f64> = l * l.transpose() + Matrix6::identity() * 0.5;
    let m = (m + m.transpose()) * 0.5;
    Kirchhoff {
        a: m.fixed_view::<3, 3>(0, 0).into(),
        b: m.fixed_view::<3, 3>(3, 0).into(),
        c: m.fixed_view::<3, 3>(3, 3).into(),
    }
}

fn check(body: &Kirchhoff, omega0: Vector3<f64>, v0: Vector3<f64>, t_end: f64) {
    let direct = Direct::new(body);
    // p₀ = bω₀ + cv₀, k = |p₀|, γ₀ = p₀/k (body frame).
    let p0 = body.b * omega0 + body.c * v0;
    let k = p0.norm();
    let gamma0 = p0 / k;
    let f = body.parameters(k).unwrap();
    let model = FluidBody::from(&f);

    let n_out = 201;
    let dt = t_end / (n_out - 1) as f64;
    let times: Vec<f64> = (0..n_out).map(|i| i as f64 * dt).collect();
    let opts = SimOptions::with_tolerances(1e-13, 1e-15).at_times(times.clone());
    let traj = simulate_full(&model, omega0, gamma0, t_end, &opts).unwrap();
    let reference = direct.integrate(direct.momenta(&omega0, &v0), n_out, dt, 100);
    assert_eq!(traj.t.len(), reference.len());

    let kirchhoff_55_0 = reference[0]
        .fixed_rows::<3>(0)
        .dot(&reference[0].fixed_rows::<3>(3));
    let energy_0 = body.energy(&omega0, &v0);
    let (mut e_omega, mut e_impulse, mut e_v, mut e_55, mut e_energy) =
        (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (i, y) in reference.iter().enumerate() {
        let (w, v) = direct.velocities(y);
        let p: Vector3<f64> = y.fixed_rows::<3>(3).into();
        let (w_r, g_r) = (traj.omega[i], traj.gamma[i]);
        // ω(t) agree.
        e_omega = e_omega.max((w_r - w).norm());
        // kγ(t) = bω(t) + cv(t) along the motion.
        e_impulse = e_impulse.max((k * g_r - (body.b * w + body.c * v)).norm());
        e_impulse = e_impulse.max((k * g_r - p).norm());
        // The velocity reconstructed by (58) from (ω, γ) is Kirchhoff's v.
        e_v = e_v.max((f.velocity(&w_r, &g_r) - v).norm());
        // errata E7: Kirchhoff's constant (55) is k·p_ψ, not p_ψ.
        e_55 = e_55.max((f.kirchhoff_constant(traj.p_psi[i]) - kirchhoff_55_0).abs());
        // The energy (3) of L is Kirchhoff's T (54).
        e_energy = e_energy.max((traj.energy[i] - energy_0).abs());
    }
    eprintln!(
        "k = {k:.4}: max |Δω| = {e_omega:.1e}, max |kγ − (bω + cv)| = {e_impulse:.1e}, \
         max |Δv| = {e_v:.1e}, (55) drift {e_55:.1e}, energy drift {e_energy:.1e}"
    );
    let scale = omega0.norm().max(v0.norm()).max(1.0);
    assert!(e_omega < 1e-8 * scale, "ω differs by {e_omega:e}");
    assert!(
        e_impulse < 1e-8 * scale,
        "kγ − (bω + cv) up to {e_impulse:e}"
    );
    assert!(e_v < 1e-8 * scale, "v differs by {e_v:e}");
    assert!(
        e_55 < 1e-9 * (1.0 + kirchhoff_55_0.abs()),
        "(55) off by {e_55:e}"
    );
    assert!(
        e_energy < 1e-9 * (1.0 + energy_0),
        "energy off by {e_energy:e}"
    );
    // The test is not vacuous: k ≠ 1, so p_ψ and k·p_ψ differ, and the body tumbles.
    assert!((k - 1.0).abs() > 0.1, "k = {k}");
    assert!((traj.p_psi[0] - kirchhoff_55_0).abs() > 1e-3);
    let turn = traj
        .gamma
        .iter()
        .map(|g| g.dot(&gamma0))
        .fold(1.0f64, f64::min);
    assert!(
        turn < 0.9,
        "the impulse direction should move in the body frame: {turn}"
    );
}

#[test]
fn equations_8_with_errata_e3_lagrangian_reproduce_kirchhoff_52_chiral_body() {
    check(
        &Kirchhoff::chiral(),
        Vector3::new(0.4, -0.9, 0.7),
        Vector3::new(0.3, 0.5, -0.6),
        10.0,
    );
}

#[test]
fn equations_8_with_errata_e3_lagrangian_reproduce_kirchhoff_52_general_body() {
    let body = general_body();
    // Check that the body is general indeed: b is far from symmetric.
    assert!((body.b - body.b.transpose()).norm() > 0.1);
    check(
        &body,
        Vector3::new(-0.8, 0.3, 1.2),
        Vector3::new(1.1, -0.4, 0.2),
        10.0,
    );
}

#[test]
fn kirchhoff_lagrangian_is_symmetric_in_its_outputs() {
    let body = general_body();
    let f = body.parameters(1.7).unwrap();
    let m: Matrix3<f64> = f.potential;
    assert!((m - m.transpose()).norm() < 1e-14);
    assert!((f.kinetic - f.kinetic.transpose()).norm() < 1e-14);
}
