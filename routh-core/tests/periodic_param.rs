//! Families of periodic orbits at a fixed energy through a parameter of the model
//! (`continue_orbit_in`, docs/method.md §11 "Families in a parameter"), checked against what the
//! code does not compute: the pendulum's period `4K(m)/ω₀` in closed form along a family in a
//! moment of inertia; a branch point in a moment where a stability index integrated here by a
//! fixed-step Runge–Kutta method on the Euler–Poisson equations and their variational equations
//! (not the crate's vector field, integrator or corrector) crosses 1; `periodic_orbit` on the
//! member models; and the families through the energy at the other end of a family in `p_ψ`.

use crate::common::{elliptic_k, hanging, heavy_body as body, swing_index};
use routh_core::{
    continue_orbit_in, lyapunov_family, periodic_orbit, OrbitEventKind, OrbitOptions, OrbitStop,
    PeriodicOrbit, RouthError, Vector3,
};

/// The turning point `γ = (0, sin θ₀, −cos θ₀)` of the planar swing about `e₁`.
fn turning(theta0: f64) -> Vector3<f64> {
    Vector3::new(0.0, theta0.sin(), -theta0.cos())
}

/// Whether the orbit's point is a planar swing about `e₁` (ω ∥ e₁, γ ⊥ e₁).
fn planar(o: &PeriodicOrbit) -> bool {
    o.omega0.y.abs() <= 1e-9 && o.omega0.z.abs() <= 1e-9 && o.gamma0.x.abs() <= 1e-9
}

/// (a) The planar swing about `e₁` of `J = diag(a, 2, 3)`, `mgl = 1.5`, `p_ψ = 0`, at the energy
/// `E = −1.5 cos θ₀` of the amplitude `θ₀ = 1`, through the moment `a ∈ [0.8, 1.5]`: the swing
/// is a pendulum of amplitude `θ₀` (fixed by `E`) and frequency `√(mgl/a)`, so every orbit's
/// period is `4K(sin²(θ₀/2))/√(mgl/a)` of its own `a`; the family stays planar, at its energy,
/// ends on both ends of the range, and `periodic_orbit` on the member model at a few of its
/// orbits gives the same period.
#[test]
fn swing_through_a_moment_is_the_pendulum_of_that_moment() {
    let (mgl, theta0) = (1.5, 1.0f64);
    let energy = -mgl * theta0.cos();
    let member = |a: f64| (body(a, 2.0, 3.0, mgl), 0.0);
    let period = |a: f64| 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / (mgl / a).sqrt();
    let opts = OrbitOptions::default();
    let first = periodic_orbit(
        &member(1.0).0,
        Vector3::zeros(),
        turning(theta0),
        6.0,
        &opts,
    )
    .unwrap();
    assert!((first.period - period(1.0)).abs() < 1e-8, "{first}");
    let f = continue_orbit_in(member, &first, 1.0, (0.8, 1.5), &opts).unwrap();
    assert_eq!(f.family.stop, None, "both ends of the range");
    assert_eq!(f.parameter.len(), f.family.orbits.len());
    assert!(
        f.family.orbits.len() >= 5,
        "{} orbits",
        f.family.orbits.len()
    );
    assert_eq!(f.parameter.first().copied(), Some(0.8));
    assert_eq!(f.parameter.last().copied(), Some(1.5));
    assert!(
        f.parameter.windows(2).all(|w| w[0] < w[1]),
        "{:?}",
        f.parameter
    );
    let mut worst = 0.0f64;
    for (o, &a) in f.family.orbits.iter().zip(&f.parameter) {
        let err = (o.period - period(a)).abs();
        worst = worst.max(err);
        assert!(err < 1e-8, "a = {a}: T = {} vs {}", o.period, period(a));
        assert!(planar(o), "a = {a}: {o}");
        assert!(
            (o.energy - energy).abs() < 1e-9,
            "a = {a}: E = {}",
            o.energy
        );
        assert!(o.p_psi.abs() < 1e-12, "a = {a}: p_ψ = {}", o.p_psi);
    }
    eprintln!(
        "{} orbits over a ∈ [0.8, 1.5], worst |T − 4K/ω₀| = {worst:.2e}",
        f.family.orbits.len()
    );
    // (c) periodic_orbit on the member model at a few orbits: the same period.
    let n = f.family.orbits.len();
    for i in [0, n / 3, 2 * n / 3, n - 1] {
        let (o, a) = (&f.family.orbits[i], f.parameter[i]);
        let again = periodic_orbit(&member(a).0, o.omega0, o.gamma0, o.period, &opts).unwrap();
        assert!(
            (again.period - o.period).abs() < 1e-9 * o.period,
            "a = {a}: {} vs {}",
            again.period,
            o.period
        );
    }
}

/// (b) Events: the planar swing about `e₁` of `J = diag(1, B, 2.3)`, `mgl = 1`, at the energy
/// `E = 0.2724760148064` where the family through the energy of `B = 1.6` has its branch point,
/// through `B ∈ [1.4, 1.8]`. The swing itself does not depend on `B` (its period is the
/// pendulum's of `A = 1`), its stability does: the family in `B` has a branch point where the
/// independent index crosses 1 (bisection in `B` on the Runge–Kutta monodromy), which is
/// `B = 1.6`; routh's event sits there at `max_step` 0.02, 0.04 and 0.08, with `k = 1` to 1e−9
/// and its orbit planar.
#[test]
fn branch_point_in_a_moment_is_where_an_independent_monodromy_puts_it() {
    let (c, mgl) = (2.3, 1.0);
    let energy = 0.2724760148064f64;
    let theta0 = (-energy / mgl).acos();
    // The independent branch point: k(B) = 1, bisection to 1e−12 on [1.5, 1.7].
    let k = |b: f64| swing_index([1.0, b, c], mgl, 0, theta0, 6000) - 1.0;
    let (mut lo, mut hi) = (1.5, 1.7);
    let flo = k(lo);
    assert!(flo * k(hi) < 0.0, "k − 1 changes sign on [1.5, 1.7]");
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if k(mid) * flo > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let b_ref = 0.5 * (lo + hi);
    eprintln!("independent branch point: B = {b_ref:.12}");
    assert!((b_ref - 1.6).abs() < 1e-7, "B = {b_ref}");
    let member = |b: f64| (body(1.0, b, c, mgl), 0.0);
    let opts = OrbitOptions::default();
    let first = periodic_orbit(
        &member(1.5).0,
        Vector3::zeros(),
        turning(theta0),
        7.0,
        &opts,
    )
    .unwrap();
    let mut found = Vec::new();
    for max_step in [0.02, 0.04, 0.08] {
        let opts = OrbitOptions::default().with_max_step(max_step);
        let f = continue_orbit_in(member, &first, 1.5, (1.4, 1.8), &opts).unwrap();
        assert_eq!(f.family.stop, None, "max_step {max_step}");
        assert_eq!(f.event_parameter.len(), f.family.events.len());
        let bps: Vec<usize> = (0..f.family.events.len())
            .filter(|&i| f.family.events[i].kind == OrbitEventKind::BranchPoint)
            .collect();
        assert_eq!(bps.len(), 1, "max_step {max_step}: {:?}", f.family.events);
        let (e, b) = (&f.family.events[bps[0]], f.event_parameter[bps[0]]);
        eprintln!(
            "max_step {max_step}: {} orbits, branch point at B = {b:.12} (k − 1 = {:.2e}, E − E₀ = {:.2e})",
            f.family.orbits.len(),
            e.orbit.stability_index - 1.0,
            e.energy - energy
        );
        assert!((b - b_ref).abs() < 1e-8, "B = {b} vs {b_ref}");
        assert!((e.orbit.stability_index - 1.0).abs() < 1e-9, "{}", e.orbit);
        assert!((e.energy - energy).abs() < 1e-9, "{}", e.orbit);
        assert!(planar(&e.orbit), "{}", e.orbit);
        found.push(b);
    }
    let spread = found.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
        - found.iter().cloned().fold(f64::INFINITY, f64::min);
    eprintln!("spread over max_step: {spread:.2e}");
    assert!(spread < 1e-9, "{found:?}");
}

/// (c) A family in `p_ψ` (`s ↦ (the same body, s)`) of `J = diag(1, 1.6, 2.3)`, `mgl = 1`, at the
/// energy `E = −0.8`: from the orbit of the Lyapunov family (mode 0) at `p_ψ = 0.3` to
/// `p_ψ = 0.5`, where it must be the orbit of that energy of the Lyapunov family at `p_ψ = 0.5`
/// (followed through the energy, ended exactly on it): the same period, precession and index.
#[test]
fn family_in_the_momentum_meets_the_family_through_the_energy() {
    let m = body(1.0, 1.6, 2.3, 1.0);
    let energy = -0.8;
    let at_energy = |p: f64| -> PeriodicOrbit {
        let opts = OrbitOptions::default().with_energy_bounds(-2.0, energy);
        let f = lyapunov_family(&m, &hanging(&m, p), 0, &opts).unwrap();
        assert_eq!(f.stop, Some(OrbitStop::EnergyBound { energy }), "p_ψ = {p}");
        f.orbits.last().unwrap().clone()
    };
    let start = at_energy(0.3);
    let end = at_energy(0.5);
    let opts = OrbitOptions::default();
    let f = continue_orbit_in(|p| (m.clone(), p), &start, 0.3, (0.3, 0.5), &opts).unwrap();
    eprintln!(
        "{} orbits, stop {:?}, events {:?}",
        f.family.orbits.len(),
        f.family.stop,
        f.family.events
    );
    assert_eq!(f.family.stop, None);
    assert_eq!(f.parameter.last().copied(), Some(0.5));
    for (o, &p) in f.family.orbits.iter().zip(&f.parameter) {
        assert!(
            (o.energy - energy).abs() < 1e-9,
            "p_ψ = {p}: E = {}",
            o.energy
        );
        assert!((o.p_psi - p).abs() < 1e-9, "p_ψ = {p}: {}", o.p_psi);
    }
    let last = f.family.orbits.last().unwrap();
    eprintln!("family in p_ψ at 0.5: {last}\nfamily in E at −0.8:  {end}");
    assert!((last.period - end.period).abs() < 1e-8, "{last}\n{end}");
    assert!(
        (last.precession - end.precession).abs() < 1e-8,
        "{last}\n{end}"
    );
    assert!(
        (last.stability_index - end.stability_index).abs() < 1e-6,
        "{last}\n{end}"
    );
    // periodic_orbit on the member at a middle orbit: the same period.
    let i = f.family.orbits.len() / 2;
    let (o, p) = (&f.family.orbits[i], f.parameter[i]);
    let again = periodic_orbit(&m, o.omega0, o.gamma0, o.period, &opts).unwrap();
    assert!((again.period - o.period).abs() < 1e-9 * o.period);
    assert!((again.p_psi - p).abs() < 1e-9);
}

/// (d) Bad input is an error, never a panic: an orbit of another member than `family(s0)`, a
/// `p_ψ` that is not the family's at `s0`, `s0` outside the range, an empty or non-finite range,
/// and a family whose `p_ψ` is not finite.
#[test]
fn bad_input_is_an_error() {
    let member = |a: f64| (body(a, 2.0, 3.0, 1.5), 0.0);
    let opts = OrbitOptions::default();
    let orbit = periodic_orbit(&member(1.0).0, Vector3::zeros(), turning(1.0), 6.0, &opts).unwrap();
    // The orbit of a = 1 given as one of a = 1.2 (the same energy and p_ψ there, another period).
    let e = continue_orbit_in(member, &orbit, 1.2, (0.8, 1.5), &opts).unwrap_err();
    assert!(
        matches!(
            e,
            RouthError::InvalidOption { what: "orbit", .. } | RouthError::NoConvergence { .. }
        ),
        "{e}"
    );
    // Another p_ψ.
    let e = continue_orbit_in(|a| (member(a).0, 0.3), &orbit, 1.0, (0.8, 1.5), &opts).unwrap_err();
    assert!(
        matches!(e, RouthError::InvalidOption { what: "orbit", .. }),
        "{e}"
    );
    // s0 outside the range.
    let e = continue_orbit_in(member, &orbit, 1.0, (1.1, 1.5), &opts).unwrap_err();
    assert!(
        matches!(e, RouthError::InvalidOption { what: "s0", .. }),
        "{e}"
    );
    let e = continue_orbit_in(member, &orbit, f64::NAN, (0.8, 1.5), &opts).unwrap_err();
    assert!(
        matches!(e, RouthError::InvalidOption { what: "s0", .. }),
        "{e}"
    );
    // Empty and non-finite ranges.
    for range in [
        (f64::NAN, 1.5),
        (0.8, f64::NAN),
        (1.5, 0.8),
        (0.8, f64::INFINITY),
    ] {
        let e = continue_orbit_in(member, &orbit, 1.0, range, &opts).unwrap_err();
        assert!(
            matches!(e, RouthError::InvalidOption { what: "range", .. }),
            "{e}"
        );
    }
    // A family with a non-finite p_ψ.
    let e =
        continue_orbit_in(|a| (member(a).0, f64::NAN), &orbit, 1.0, (0.8, 1.5), &opts).unwrap_err();
    assert!(matches!(e, RouthError::AtParameter { .. }), "{e}");
}
