//! Periodic orbits, their multipliers and families (docs/method.md §11), checked against what the
//! code does not compute: the pendulum's period in closed form (complete elliptic integral by the
//! arithmetic–geometric mean), the linear limit `k → cos(2π ω_j/ω_k)`, multipliers from a
//! monodromy built by finite differences of `simulate_full` and from the growth of perturbations
//! in long simulations, time reversal, and the period-doubled orbits next to a period doubling.

use crate::common::{elliptic_k, fd_trace, hanging, heavy_body as body, HeavyTop};
use routh_core::{
    continue_orbit, lyapunov_family, orbit_crossings, period_doubled_family, periodic_orbit,
    poincare_section, simulate_full, steady_motions, Lagrangian, Matrix3, OrbitEventKind,
    OrbitOptions, OrbitStability, OrbitStop, RouthError, SectionOptions, SimOptions, Vector3,
};
use std::f64::consts::PI;

/// (a) Planar swings of a heavy body about its first principal axis at `p_ψ = 0`: the pendulum
/// `θ̈ = −(mgl/A) sin θ`, period `4K(sin²(θ₀/2))/ω₀`, no precession.
#[test]
fn pendulum_period_is_the_elliptic_integral() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let w0 = (1.5f64 / 1.0).sqrt();
    for theta0 in [0.1f64, 0.8, 1.6, 2.5, 3.0] {
        let gamma = Vector3::new(0.0, theta0.sin(), -theta0.cos());
        let o = periodic_orbit(
            &m,
            Vector3::zeros(),
            gamma,
            2.0 * PI / w0,
            &OrbitOptions::default(),
        )
        .unwrap();
        let exact = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / w0;
        assert!(
            (o.period - exact).abs() <= 1e-8 * exact,
            "θ₀ = {theta0}: T = {} vs 4K/ω₀ = {exact}",
            o.period
        );
        assert!(o.precession.abs() < 1e-8, "Δψ = {}", o.precession);
        assert!(o.p_psi.abs() < 1e-12 && o.gamma0.x.abs() < 1e-9);
        assert!((o.energy + 1.5 * theta0.cos()).abs() < 1e-9);
    }
}

/// (b) + (c): the first orbit of each Lyapunov family at the hanging position has the period
/// `2π/ω_k` and `k = cos(2π ω_j/ω_k)` (the other swing, linear and uncoupled at zero amplitude);
/// along the family the index agrees with the trace of a finite-difference monodromy of
/// `simulate_full`.
#[test]
fn lyapunov_families_start_on_the_linear_orbits() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let s = hanging(&m, 0.0);
    let freqs = [(1.5f64 / 1.0).sqrt(), (1.5f64 / 2.0).sqrt()];
    for mode in 0..2 {
        let opts = OrbitOptions::default().with_max_orbits(12);
        let fam = lyapunov_family(&m, &s, mode, &opts).unwrap();
        let (wk, wj) = (freqs[mode], freqs[1 - mode]);
        let first = &fam.orbits[0];
        assert!(
            (first.period - 2.0 * PI / wk).abs() < 1e-5,
            "mode {mode}: T = {}",
            first.period
        );
        let k_lin = (2.0 * PI * wj / wk).cos();
        assert!(
            (first.stability_index - k_lin).abs() < 1e-4,
            "mode {mode}: k = {} vs {k_lin}",
            first.stability_index
        );
        assert!(
            fam.orbits.len() >= 6,
            "{} orbits, stop {:?}",
            fam.orbits.len(),
            fam.stop
        );
        // Energies rise away from the hanging position; p_ψ stays 0.
        assert!(fam
            .orbits
            .iter()
            .all(|o| o.energy > s.energy && o.p_psi.abs() < 1e-10));
        let o = fam.orbits.last().unwrap();
        let k_fd = 0.5 * (fd_trace(&m, o.omega0, o.gamma0, o.period) - 4.0);
        assert!(
            (o.stability_index - k_fd).abs() < 1e-5,
            "mode {mode}: k = {} vs finite differences {k_fd}",
            o.stability_index
        );
    }
}

/// (d) Time reversal `(ω, γ)(t) ↦ (−ω, γ)(−t)` maps an orbit onto an orbit of the same period,
/// energy and multipliers, and precession `−Δψ`.
#[test]
fn reversed_orbits_are_orbits() {
    let m = body(1.0, 1.4, 2.1, 1.0);
    let s = steady_motions(&m, 0.3).unwrap();
    let hang = s.iter().find(|s| s.gamma.z < 0.0).unwrap();
    let fam = lyapunov_family(&m, hang, 1, &OrbitOptions::default().with_max_orbits(6)).unwrap();
    let o = fam.orbits.last().unwrap();
    let r = periodic_orbit(&m, -o.omega0, o.gamma0, o.period, &OrbitOptions::default()).unwrap();
    assert!((r.period - o.period).abs() < 1e-8 * o.period);
    assert!((r.energy - o.energy).abs() < 1e-10);
    assert!(
        (r.p_psi + o.p_psi).abs() < 1e-10,
        "p_ψ changes sign: {} {}",
        r.p_psi,
        o.p_psi
    );
    assert!((r.stability_index - o.stability_index).abs() < 1e-6);
    assert!((r.precession + o.precession).abs() < 1e-7);
}

/// (c) The multiplier of a hyperbolic orbit is the growth of a small perturbation per period in
/// a long simulation.
#[test]
fn hyperbolic_multiplier_is_the_growth_of_perturbations() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let s = hanging(&m, 0.0);
    let fam = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(80)).unwrap();
    let o = fam
        .orbits
        .iter()
        .find(|o| o.stability_index > 3.0)
        .unwrap_or_else(|| panic!("no strongly hyperbolic orbit: {:?}", fam.stop));
    let mu = o.multipliers[0].re;
    // Perturb out of the plane; sample the distance at whole periods. The perturbation's
    // component along the unstable direction grows by μ a period, the rest at most linearly (a
    // change of energy shifts the phase), so the ratio of late distances tends to μ.
    let d0 = 1e-10;
    let g1 = (o.gamma0 + Vector3::new(d0, 0.0, 0.0)).normalize();
    let times: Vec<f64> = (0..=6).map(|n| n as f64 * o.period).collect();
    let opts = SimOptions::with_tolerances(1e-12, 1e-14).at_times(times);
    let a = simulate_full(&m, o.omega0, o.gamma0, 6.0 * o.period, &opts).unwrap();
    let b = simulate_full(&m, o.omega0, g1, 6.0 * o.period, &opts).unwrap();
    let dist: Vec<f64> = (0..a.t.len())
        .map(|i| {
            ((a.gamma[i] - b.gamma[i]).norm_squared() + (a.omega[i] - b.omega[i]).norm_squared())
                .sqrt()
        })
        .collect();
    let n = dist.len() - 1;
    let rate = dist[n] / dist[n - 1];
    assert!(
        (rate - mu).abs() < 0.02 * mu,
        "growth per period {rate} vs μ = {mu} (distances {dist:?})"
    );
}

/// (e) Next to each period doubling of a swing family a family of orbits of twice the period
/// is born, and `periodic_orbit` from one of its orbits finds it again (period 2T, not T).
///
/// The centre of mass is off the principal axes: the swings of a body with it on an axis are
/// symmetric under a half-period shift composed with a reflection, which makes the monodromy a
/// square (`k = 2k_½² − 1 ≥ −1`) and rules period doubling out.
#[test]
fn period_doubling_gives_orbits_of_twice_the_period() {
    let mut m = body(1.0, 3.0, 6.0, 1.5);
    m.mgr = Vector3::new(0.4, 0.3, 1.5);
    let s = steady_motions(&m, 0.0)
        .unwrap()
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .unwrap();
    let fam = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(40)).unwrap();
    let pds: Vec<_> = fam
        .events
        .iter()
        .filter(|e| e.kind == OrbitEventKind::PeriodDoubling)
        .collect();
    assert!(pds.len() >= 2, "{:?} {:?}", fam.events, fam.stop);
    for pd in pds {
        assert!((pd.orbit.stability_index + 1.0).abs() < 1e-6, "{pd}");
        let opts = OrbitOptions::default().with_max_orbits(4);
        let dbl = period_doubled_family(&m, pd, &opts).unwrap();
        let o = dbl.orbits.last().unwrap();
        assert!(
            (o.period - 2.0 * pd.orbit.period).abs() < 0.05 * pd.orbit.period,
            "T = {} vs 2T = {}",
            o.period,
            2.0 * pd.orbit.period
        );
        assert!((o.energy - pd.energy).abs() < 0.1);
        let again =
            periodic_orbit(&m, o.omega0, o.gamma0, o.period, &OrbitOptions::default()).unwrap();
        assert!((again.period - o.period).abs() < 1e-7 * o.period);
        // Not the orbit of period T traversed twice: over T it does not close.
        let half = simulate_full(
            &m,
            o.omega0,
            o.gamma0,
            0.5 * o.period,
            &SimOptions::with_tolerances(1e-12, 1e-13),
        )
        .unwrap();
        let n = half.t.len() - 1;
        let gap = (half.gamma[n] - o.gamma0).norm() + (half.omega[n] - o.omega0).norm();
        assert!(gap > 1e-4, "the doubled orbit closes after T: gap {gap}");
    }
}

/// `continue_orbit` follows a family over an energy range and ends on its bounds.
#[test]
fn continue_orbit_reaches_the_range() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let gamma = Vector3::new(0.0, 0.5f64.sin(), -0.5f64.cos());
    let o = periodic_orbit(&m, Vector3::zeros(), gamma, 5.0, &OrbitOptions::default()).unwrap();
    let (lo, hi) = (o.energy - 0.05, o.energy + 0.05);
    let fam = continue_orbit(&m, &o, (lo, hi), &OrbitOptions::default()).unwrap();
    assert_eq!(fam.stop, None, "{:?}", fam.stop);
    let first = fam.orbits.first().unwrap().energy;
    let last = fam.orbits.last().unwrap().energy;
    assert!(
        (first - lo).abs() < 1e-9 && (last - hi).abs() < 1e-9,
        "{first} {last}"
    );
    // Periods grow with the energy (the pendulum's 4K/ω₀).
    assert!(fam.orbits.windows(2).all(|w| w[1].period > w[0].period));
}

/// Wrong inputs are errors, not panics.
#[test]
fn bad_guesses_are_errors() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let s = hanging(&m, 0.0);
    let o = OrbitOptions::default();
    let steady = periodic_orbit(&m, s.gamma * s.psi_dot, s.gamma, 3.0, &o);
    assert!(
        matches!(steady, Err(RouthError::InvalidOption { .. })),
        "{steady:?}"
    );
    let g = Vector3::new(0.0, 0.1, -1.0).normalize();
    assert!(matches!(
        periodic_orbit(&m, Vector3::new(f64::NAN, 0.0, 0.0), g, 3.0, &o),
        Err(RouthError::NonFinite { .. })
    ));
    assert!(matches!(
        periodic_orbit(&m, Vector3::zeros(), g, -1.0, &o),
        Err(RouthError::InvalidOption { .. })
    ));
    assert!(matches!(
        periodic_orbit(&m, Vector3::zeros(), g * 2.0, 3.0, &o),
        Err(RouthError::NonUnitGamma { .. })
    ));
    assert!(lyapunov_family(&m, &s, 2, &o).is_err());
    // A resonant start: ω₂/ω₁ = 1/2 exactly for B = 4A is not a resonance of mode 0 (ratio
    // 1/2), but mode 1 has ω₁/ω₂ = 2.
    let r = body(1.0, 4.0, 3.0, 1.0);
    let e = lyapunov_family(&r, &hanging(&r, 0.0), 1, &o).unwrap_err();
    assert!(e.to_string().contains("resonant"), "{e}");
}

/// The section of the planar swing family: the orbit's crossings are fixed points of the
/// section's map, and the section's orbits keep their energy level.
#[test]
fn poincare_section_shows_the_orbits() {
    let m = body(1.0, 2.0, 3.0, 1.5);
    let gamma = Vector3::new(0.0, 0.8f64.sin(), -0.8f64.cos());
    let o = periodic_orbit(&m, Vector3::zeros(), gamma, 5.0, &OrbitOptions::default()).unwrap();
    // The swing lies in the plane γ₁ = 0 itself; cut it with γ₂ = 0 instead.
    let opts = SectionOptions::default()
        .with_normal(Vector3::y())
        .with_size(8, 30);
    let fixed = orbit_crossings(&m, &o, &opts).unwrap();
    assert_eq!(fixed.len(), 1, "{fixed:?}");
    let sec = poincare_section(&m, o.p_psi, o.energy, &opts).unwrap();
    assert_eq!(sec.orbits.len(), 8);
    assert!(sec
        .orbits
        .iter()
        .all(|o| o.points.len() == 30 || o.stop.is_some()));
    assert!(sec.points().all(|p| p[0].is_finite() && p[1].is_finite()));
    // The energy is kept along each section orbit (a start's level is (p_ψ, E)).
    for so in &sec.orbits {
        assert!((m.energy(&so.omega0, &so.gamma0) - o.energy).abs() < 1e-9);
        assert!(m.cyclic_momentum(&so.omega0, &so.gamma0).abs() < 1e-9);
    }
    let _ = OrbitStop::MaxOrbits;
    let _ = OrbitStability::Elliptic;
}

/// The default [`Lagrangian::full_jacobian`] (central differences of `full_equations`, for
/// hand-written models) agrees with the heavy top's closed form to its documented ~8 digits.
#[test]
fn default_full_jacobian_matches_the_closed_form() {
    /// The same body with the trait's default `full_jacobian`.
    struct Plain<'a>(&'a HeavyTop);
    impl Lagrangian for Plain<'_> {
        fn lagrangian(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> f64 {
            self.0.lagrangian(w, g)
        }
        fn dl_domega(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
            self.0.dl_domega(w, g)
        }
        fn dl_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Vector3<f64> {
            self.0.dl_dgamma(w, g)
        }
        fn d2l_domega2(&self, g: &Vector3<f64>) -> Matrix3<f64> {
            self.0.d2l_domega2(g)
        }
        fn d2l_domega_dgamma(&self, w: &Vector3<f64>, g: &Vector3<f64>) -> Matrix3<f64> {
            self.0.d2l_domega_dgamma(w, g)
        }
    }
    let mut m = body(1.0, 2.0, 3.0, 1.5);
    m.mgr = Vector3::new(0.4, -0.3, 1.5);
    for (w, g) in [
        (Vector3::new(0.3, -1.2, 2.0), Vector3::new(0.1, 0.7, -0.3)),
        (Vector3::new(-4.0, 0.5, 0.01), Vector3::new(-0.9, 0.2, 0.4)),
    ] {
        let exact = m.full_jacobian(&w, &g);
        let fd = Plain(&m).full_jacobian(&w, &g);
        let scale = exact.dright_domega.amax().max(exact.dright_dgamma.amax());
        assert!((exact.dright_domega - fd.dright_domega).amax() < 1e-8 * scale);
        assert!((exact.dright_dgamma - fd.dright_dgamma).amax() < 1e-8 * scale);
        assert!((exact.right_side - fd.right_side).amax() < 1e-14 * scale);
        assert!(fd.dinertia_dgamma.iter().all(|d| d.amax() < 1e-8));
    }
}
