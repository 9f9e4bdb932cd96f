//! The events of orbit families (docs/method.md §11), each re-located by a computation routh does
//! not make: planar swings of a heavy body with distinct moments are pendulum motions whose
//! period is `4K(m)/ω₀` in closed form, and whose stability index is the trace of a monodromy
//! integrated here by a fixed-step classical Runge–Kutta method on the Euler–Poisson equations
//! and their variational equations, written out in this file (not the crate's vector field,
//! integrator or corrector). The swing amplitude where `k = ±1` is found by bisection on that
//! trace; routh's events must sit there, at any `max_step`, with their own orbit on the family.

use crate::common::{
    closure_gap, elliptic_k, fd_trace, hanging, heavy_body, swing_index, HeavyTop,
};
use routh_core::{
    lyapunov_family, steady_motions, switch_branch, Matrix3, OrbitEvent, OrbitEventKind,
    OrbitFamily, OrbitOptions, Vector3,
};

/// The body: `J = diag(1, 1.6, 2.3)`, centre of mass on `e₃`, `mgl = 1` (`U = mgl γ₃`).
const J: [f64; 3] = [1.0, 1.6, 2.3];
const MGL: f64 = 1.0;

fn body() -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(J[0], J[1], J[2])),
        mgr: Vector3::new(0.0, 0.0, MGL),
    }
}

/// The energies `−mgl cos θ₀` of the swings about `axis` where `k = target`, for amplitudes up
/// to `max_energy`: a scan of 80 amplitudes and bisection to `1e−13` in `θ₀`.
fn independent_events(
    j: [f64; 3],
    mgl: f64,
    axis: usize,
    target: f64,
    max_energy: f64,
) -> Vec<f64> {
    let n = 6000;
    let f = |th: f64| swing_index(j, mgl, axis, th, n) - target;
    let top = (-max_energy / mgl).acos();
    let grid: Vec<f64> = (1..=80).map(|i| top * i as f64 / 80.0).collect();
    let mut out = Vec::new();
    let mut prev = (grid[0], f(grid[0]));
    for &th in &grid[1..] {
        let v = f(th);
        if prev.1 * v < 0.0 {
            let (mut lo, mut hi, mut flo) = (prev.0, th, prev.1);
            while hi - lo > 1e-13 {
                let mid = 0.5 * (lo + hi);
                let fm = f(mid);
                if fm * flo > 0.0 {
                    lo = mid;
                    flo = fm;
                } else {
                    hi = mid;
                }
            }
            out.push(-mgl * (0.5 * (lo + hi)).cos());
        }
        prev = (th, v);
    }
    out
}

/// The axis of a planar swing family: the axis its angular velocity is about.
fn swing_axis(f: &OrbitFamily) -> usize {
    let o = &f.orbits[f.orbits.len() / 2];
    if o.omega0.x.abs() >= o.omega0.y.abs() {
        0
    } else {
        1
    }
}

fn kind_target(kind: OrbitEventKind) -> f64 {
    match kind {
        OrbitEventKind::BranchPoint => 1.0,
        OrbitEventKind::PeriodDoubling => -1.0,
        OrbitEventKind::ThirdOrderResonance => -0.5,
        OrbitEventKind::FourthOrderResonance => 0.0,
        OrbitEventKind::Fold | OrbitEventKind::TwistDegenerate => f64::NAN,
    }
}

/// Every branch point and period doubling of both planar swing families of the hanging body
/// `J = diag(j)`, `mgl`, at `p_ψ = 0` (energies up to `max_energy`), at `max_step` 0.02, 0.04 and
/// 0.08, is where the independent monodromy puts it: `|ΔE| ≤ 1e−9·max(1, |E|)` (the contract's
/// `event_tol`); its orbit is on the family (planar, `k` within 1e−9 of ±1, the period `4K(m)/ω₀`
/// of its own amplitude) and none is missing or spurious.
fn planar_events_are_where_the_monodromy_puts_them(j: [f64; 3], mgl: f64, max_energy: f64) {
    let m = heavy_body(j[0], j[1], j[2], mgl);
    let h = hanging(&m, 0.0);
    // The independent events, per swing axis and kind (the scan is the same for every step).
    let reference: Vec<Vec<(OrbitEventKind, f64)>> = (0..2)
        .map(|axis| {
            let mut v: Vec<(OrbitEventKind, f64)> = Vec::new();
            for kind in [OrbitEventKind::BranchPoint, OrbitEventKind::PeriodDoubling] {
                for e in independent_events(j, mgl, axis, kind_target(kind), max_energy) {
                    v.push((kind, e));
                }
            }
            v
        })
        .collect();
    assert!(
        reference.iter().map(Vec::len).sum::<usize>() >= 2,
        "the scan finds the branch points of both families: {reference:?}"
    );
    for max_step in [0.02, 0.04, 0.08] {
        let opts = OrbitOptions {
            max_step,
            max_orbits: 400,
            energy_bounds: Some((-2.0 * mgl, max_energy)),
            ..OrbitOptions::default()
        };
        for mode in 0..2 {
            let f = lyapunov_family(&m, &h, mode, &opts).unwrap();
            let axis = swing_axis(&f);
            let want = &reference[axis];
            let got: Vec<&OrbitEvent> = f.events.iter().collect();
            assert_eq!(
                got.len(),
                want.len(),
                "max_step {max_step}, mode {mode}: routh {:?} vs independent {want:?}",
                got.iter().map(|e| (e.kind, e.energy)).collect::<Vec<_>>()
            );
            for (e, (kind, energy)) in got.iter().zip(want) {
                assert_eq!(e.kind, *kind);
                assert!(
                    (e.energy - energy).abs() <= 1e-9 * energy.abs().max(1.0),
                    "max_step {max_step}, mode {mode}: {:?} at E = {:.12}, independent {energy:.12} (ΔE = {:.2e})",
                    e.kind,
                    e.energy,
                    e.energy - energy
                );
                let o = &e.orbit;
                assert!(
                    (o.stability_index - kind_target(e.kind)).abs() <= 1e-9,
                    "the event orbit's k = {:.12}",
                    o.stability_index
                );
                // On the planar family: out-of-plane components zero, period of the pendulum.
                let out_of_plane = if axis == 0 {
                    [o.omega0.y, o.omega0.z, o.gamma0.x]
                } else {
                    [o.omega0.x, o.omega0.z, o.gamma0.y]
                };
                assert!(
                    out_of_plane.iter().all(|c| c.abs() < 1e-9),
                    "event orbit off the plane: {out_of_plane:?}"
                );
                let theta0 = (-o.energy / mgl).acos();
                let exact = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / (mgl / j[axis]).sqrt();
                assert!(
                    (o.period - exact).abs() <= 1e-8 * exact,
                    "event period {} vs 4K/ω₀ {exact}",
                    o.period
                );
            }
            // The whole family stays planar (drifts of 3.7e−3 were once seen).
            for o in &f.orbits {
                let off = if axis == 0 {
                    o.gamma0.x.abs().max(o.omega0.y.abs()).max(o.omega0.z.abs())
                } else {
                    o.gamma0.y.abs().max(o.omega0.x.abs()).max(o.omega0.z.abs())
                };
                assert!(
                    off < 1e-9,
                    "orbit at E = {} off its plane by {off:e}",
                    o.energy
                );
            }
        }
    }
}

/// (1) The reference body, `J = diag(1, 1.6, 2.3)`, `mgl = 1`, up to `E = 0.9`.
#[test]
fn events_of_planar_swings_are_where_an_independent_monodromy_puts_them() {
    planar_events_are_where_the_monodromy_puts_them(J, MGL, 0.9);
}

/// (1) The body of `examples/periodic.rs`, `J = diag(1, 2, 3)`, `mgl = 1.5`, up to `E = 1.2`: its
/// two branch points (E ≈ 0.968 and 0.352) re-located independently.
#[test]
fn the_examples_swing_events_are_where_an_independent_monodromy_puts_them() {
    planar_events_are_where_the_monodromy_puts_them([1.0, 2.0, 3.0], 1.5, 1.2);
}

/// The independent index itself converges: RK4 at 6000 and 12000 steps agree to 1e−11 on a large
/// swing (so the bisection above resolves the events to far better than 1e−9).
#[test]
fn the_independent_index_is_converged() {
    let a = swing_index(J, MGL, 0, 2.0, 6000);
    let b = swing_index(J, MGL, 0, 2.0, 12000);
    assert!((a - b).abs() < 1e-11, "{a} vs {b}");
}

/// (1) A case off the planes: `p_ψ = 0.5`, the non-planar family of mode 1 and its branch point at
/// E ≈ 0.46244683 (placed there by an independent scipy computation of k along the family): the
/// event is found at three step sizes at one energy (to 1e−9), with `k = 1` to 1e−9, and its orbit
/// closes under `simulate_full` (a different integrator, no corrector).
#[test]
fn a_branch_point_off_the_planes_is_the_same_at_every_step() {
    let m = body();
    let h = hanging(&m, 0.5);
    let mut energies = Vec::new();
    for max_step in [0.02, 0.04, 0.08] {
        let opts = OrbitOptions {
            max_step,
            max_orbits: 400,
            energy_bounds: Some((-2.0, 0.6)),
            ..OrbitOptions::default()
        };
        let f = lyapunov_family(&m, &h, 1, &opts).unwrap();
        let bp: Vec<_> = f
            .events
            .iter()
            .filter(|e| e.kind == OrbitEventKind::BranchPoint)
            .collect();
        assert_eq!(bp.len(), 1, "max_step {max_step}: {:?}", f.events);
        let e = bp[0];
        assert!((e.orbit.stability_index - 1.0).abs() <= 1e-9);
        assert!((e.energy - 0.46244683).abs() < 2e-8, "E = {}", e.energy);
        let o = &e.orbit;
        let gap = closure_gap(&m, o);
        assert!(gap < 1e-8, "the event orbit does not close: {gap:e}");
        energies.push(e.energy);
    }
    let spread = energies.iter().cloned().fold(f64::MIN, f64::max)
        - energies.iter().cloned().fold(f64::MAX, f64::min);
    assert!(spread <= 1e-9, "{energies:?}");
}

/// (5) Branch switching: the family crossing the planar swings at their branch point is made of
/// periodic orbits (closed by `simulate_full`) that leave the plane, at energies on one side of
/// the branch point (a pitchfork: the energy is stationary there), and passes through the event.
#[test]
fn switch_branch_follows_the_crossing_family() {
    let m = body();
    let h = hanging(&m, 0.0);
    let opts = OrbitOptions {
        max_orbits: 400,
        energy_bounds: Some((-2.0, 0.9)),
        ..OrbitOptions::default()
    };
    let f = lyapunov_family(&m, &h, 0, &opts).unwrap();
    let axis = swing_axis(&f);
    let bp = f
        .events
        .iter()
        .find(|e| e.kind == OrbitEventKind::BranchPoint)
        .expect("a branch point on the swings");
    let sw = switch_branch(
        &m,
        bp,
        &OrbitOptions {
            max_orbits: 30,
            ..opts.clone()
        },
    )
    .unwrap();
    assert!(sw.orbits.len() >= 10, "{} orbits", sw.orbits.len());
    let side = sw
        .orbits
        .iter()
        .map(|o| (o.energy - bp.energy).signum())
        .filter(|s| *s != 0.0)
        .collect::<Vec<_>>();
    let mut off_plane = 0;
    for o in &sw.orbits {
        let gap = closure_gap(&m, o);
        assert!(
            gap < 1e-7,
            "orbit at E = {} does not close: {gap:e}",
            o.energy
        );
        let off = if axis == 0 {
            o.gamma0.x.abs().max(o.omega0.y.abs())
        } else {
            o.gamma0.y.abs().max(o.omega0.x.abs())
        };
        if off > 1e-3 {
            off_plane += 1;
        }
    }
    assert!(off_plane >= 5, "the crossing family leaves the plane");
    // A pitchfork: far from the event the crossing family lies on one side of it in energy.
    let far: Vec<f64> = side.iter().rev().take(3).cloned().collect();
    assert!(far.iter().all(|s| *s == far[0]), "{side:?}");
    // A period doubling's family is not a branch point's: the wrong event is an error.
    let mut wrong = bp.clone();
    wrong.kind = OrbitEventKind::PeriodDoubling;
    assert!(switch_branch(&m, &wrong, &opts).is_err());
}

/// (1) The events of the example's body with the centre of mass off the principal axes
/// (`J = diag(1, 3, 6)`, `m g r = (0.4, 0.3, 1.5)`, mode 0 from the hanging position): no plane
/// there, so each event's orbit is checked by computations routh does not make for it — it
/// closes under `simulate_full`, and its index from a monodromy built by central differences of
/// `simulate_full` is ±1 to 1e−5 (the differences' own accuracy); with `|dk/dE|` of order one
/// that places the event to about 1e−5 in energy, independently of the corrector.
#[test]
fn off_axis_events_are_at_k_of_plus_minus_one_by_finite_differences() {
    let m = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(1.0, 3.0, 6.0)),
        mgr: Vector3::new(0.4, 0.3, 1.5),
    };
    let h = steady_motions(&m, 0.0)
        .unwrap()
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .unwrap();
    let f = lyapunov_family(
        &m,
        &h,
        0,
        &OrbitOptions {
            max_orbits: 120,
            ..OrbitOptions::default()
        },
    )
    .unwrap();
    let kinds: Vec<OrbitEventKind> = f.events.iter().map(|e| e.kind).collect();
    assert!(
        kinds.contains(&OrbitEventKind::PeriodDoubling)
            && kinds.contains(&OrbitEventKind::BranchPoint),
        "{kinds:?}"
    );
    for e in &f.events {
        let o = &e.orbit;
        assert!(
            closure_gap(&m, o) < 1e-8,
            "{:?} at E = {}",
            e.kind,
            e.energy
        );
        let k_fd = 0.5 * (fd_trace(&m, o.omega0, o.gamma0, o.period) - 4.0);
        assert!(
            (k_fd - kind_target(e.kind)).abs() < 1e-5,
            "{:?} at E = {}: k by finite differences {k_fd}",
            e.kind,
            e.energy
        );
    }
}
