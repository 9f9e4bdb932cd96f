//! `orbit_nonlinear_stability` (docs/method.md §12) against what it does not
//! compute: the symplectic form against finite differences of the energy (`ι_F Ω = dE`); the
//! twist at small amplitude against the steady motion's Birkhoff normal form (a different
//! algorithm, in a canonical chart of `T*S²`: `τ → D/(π ω_k³)`); the twist's independence of the
//! section and of the chart; the run-time model against the derive.

use routh::periodic::{orbit_nonlinear_stability_in, orbit_symplectic_form, SectionChart};
use routh::{
    lyapunov_family, nonlinear_stability, orbit_nonlinear_stability, Lagrangian, Matrix3, Model,
    NonlinearOptions, OrbitEventKind, OrbitNonlinearOptions, OrbitNonlinearVerdict, OrbitOptions,
    OrbitStability, PeriodicOrbit, SteadyMotion, Vector3,
};
use std::f64::consts::PI;

/// A heavy body with principal moments `inertia`, centre of mass on e₃ at `l` (m g = 1).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = l * gamma.z,
)]
struct Body {
    inertia: Vector3<f64>,
    l: f64,
}

const TEXT: &str = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z";

fn body() -> Body {
    Body {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        l: 1.5,
    }
}

fn hanging<M: routh::Routhian>(m: &M) -> SteadyMotion {
    SteadyMotion::at(m, -Vector3::z(), 0.0, true).unwrap()
}

fn vector_field(m: &Body, x: &[f64; 6]) -> [f64; 6] {
    let w = Vector3::new(x[0], x[1], x[2]);
    let g = Vector3::new(x[3], x[4], x[5]);
    let eq = m.full_equations(&w, &g);
    let wd = eq.inertia.try_inverse().unwrap() * eq.right_side;
    let gd = g.cross(&w);
    [wd.x, wd.y, wd.z, gd.x, gd.y, gd.z]
}

/// `Ω(F, w) = dE(w)` for every `w` tangent to the leaf: the form is the one the flow is
/// Hamiltonian for, with the sign of a canonical chart (`ι_{X_H}Ω = dH`). `dE` by central
/// differences of the energy.
#[test]
fn the_symplectic_form_makes_the_flow_hamiltonian_for_the_energy() {
    let m = Body {
        inertia: Vector3::new(1.3, 2.1, 2.9),
        l: 0.7,
    };
    let g = Vector3::new(0.3, -0.5, 0.7).normalize();
    let w = Vector3::new(0.4, -1.1, 0.6);
    let x = [w.x, w.y, w.z, g.x, g.y, g.z];
    let f = routh::nalgebra::Vector6::from_row_slice(&vector_field(&m, &x));
    let x6 = routh::nalgebra::Vector6::from_row_slice(&x);
    let energy = |y: &routh::nalgebra::Vector6<f64>| {
        m.energy(
            &Vector3::new(y[0], y[1], y[2]),
            &Vector3::new(y[3], y[4], y[5]),
        )
    };
    // Directions tangent to the leaf (p_ψ and |γ|² fixed to first order): random directions
    // with the two gradients projected out.
    let jm = m.d2l_domega2(&g);
    let lw = m.dl_domega(&w, &g);
    let n: Matrix3<f64> = m.d2l_domega_dgamma(&w, &g);
    let dp = routh::nalgebra::Vector6::from_iterator(
        (jm * g)
            .iter()
            .chain((n.transpose() * g + lw).iter())
            .copied(),
    );
    let dg = routh::nalgebra::Vector6::new(0.0, 0.0, 0.0, g.x, g.y, g.z);
    let q = routh::nalgebra::Matrix6x2::from_columns(&[dp, dg]).qr().q();
    for seed in 0..4 {
        let r =
            routh::nalgebra::Vector6::from_fn(|i, _| ((i * 7 + seed * 13) as f64 * 0.731).sin());
        let t = r - q * (q.transpose() * r);
        let h = 1e-5;
        let de = (energy(&(x6 + t * h)) - energy(&(x6 - t * h))) / (2.0 * h);
        let om = orbit_symplectic_form(&m, &x6, &f, &t);
        assert!(
            (om - de).abs() < 1e-8 * de.abs().max(1.0),
            "Ω(F, w) = {om}, dE(w) = {de}"
        );
    }
}

/// The Lyapunov family's first orbits at two small amplitudes, their twist extrapolated to zero
/// amplitude (linear in the energy above the steady motion).
fn small_orbits<M: routh::Routhian>(m: &M, mode: usize) -> (PeriodicOrbit, PeriodicOrbit, f64) {
    let s = hanging(m);
    let opts = OrbitOptions {
        initial_amplitude: 2e-3,
        initial_step: 0.004,
        max_step: 0.004,
        ..OrbitOptions::default().with_max_orbits(3)
    };
    let fam = lyapunov_family(m, &s, mode, &opts).unwrap();
    (fam.orbits[0].clone(), fam.orbits[2].clone(), s.energy)
}

/// `τ → D/(π ω_k³)` at zero amplitude on the family of mode k (D the Arnold determinant of the
/// hanging body's normal form `H = ω₁I₁ + ω₂I₂ + c₂₀I₁² + c₁₁I₁I₂ + c₀₂I₂²`): on the torus
/// `(I₁, I₂)` of the energy level the section map turns by `ν_j/ν_k` with `ν = ∂H/∂I`, and the
/// curve `I_j` encloses `A = 2πI_j`. A factor 2π or a sign wrong in the twist fails here.
#[test]
fn twist_at_small_amplitude_is_the_steady_motions_normal_form() {
    let m = body();
    let nf = nonlinear_stability(&m, &hanging(&m), &NonlinearOptions::default()).unwrap();
    assert_eq!(nf.krein_signs, [1, 1], "{nf}");
    let [w1, w2] = nf.frequencies;
    let d = nf.arnold_determinant;
    let opts = OrbitNonlinearOptions::default();
    for mode in 0..2 {
        let (wk, wj) = if mode == 0 { (w1, w2) } else { (w2, w1) };
        let (a, b, es) = small_orbits(&m, mode);
        let ra = orbit_nonlinear_stability(&m, &a, &opts).unwrap();
        let rb = orbit_nonlinear_stability(&m, &b, &opts).unwrap();
        assert_eq!(ra.verdict, OrbitNonlinearVerdict::OrbitallyStable, "{ra}");
        assert!(ra.area_defect < 1e-6, "{ra}");
        // ρ → ω_j/ω_k mod 1 (within the amplitude's shift of the frequencies).
        let rho0 = (wj / wk).rem_euclid(1.0);
        assert!(
            (ra.rotation_number - rho0).abs() < 1e-3,
            "{} vs {rho0}",
            ra.rotation_number
        );
        assert!(
            ((2.0 * PI * ra.rotation_number).cos() - a.stability_index).abs() < 1e-7,
            "cos 2πρ = k"
        );
        let (ea, eb) = (a.energy - es, b.energy - es);
        let tau0 = ra.twist - (rb.twist - ra.twist) / (eb - ea) * ea;
        let expected = d / (PI * wk.powi(3));
        eprintln!(
            "mode {mode}: ρ = {}, τ(0) = {tau0:e}, D/(πω³) = {expected:e}, area defect {:e}",
            ra.rotation_number, ra.area_defect
        );
        assert!(
            (tau0 - expected).abs() < 1e-6 * expected.abs(),
            "mode {mode}: τ(0) = {tau0:e} (τ = {:e}, {:e} at h = {ea:e}, {eb:e}) vs D/(πω³) = {expected:e}",
            ra.twist,
            rb.twist
        );
    }
}

/// The twist and the rotation number depend on neither the section (its normal tilted) nor the
/// chart (sheared linear coordinates, another complement for the level's correction); and a
/// run-time model from the same text gives the derive's.
#[test]
fn twist_is_an_invariant_and_the_same_on_a_run_time_model() {
    let m = body();
    let s = hanging(&m);
    let fam = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(8)).unwrap();
    let o = fam.orbits.last().unwrap();
    assert_eq!(o.stability, OrbitStability::Elliptic);
    let opts = OrbitNonlinearOptions::default();
    let base = orbit_nonlinear_stability(&m, o, &opts).unwrap();
    let charts = [
        SectionChart {
            tilt: routh::nalgebra::Vector6::new(0.3, -0.2, 0.1, 0.4, 0.0, -0.3),
            ..Default::default()
        },
        SectionChart {
            shear: 0.7,
            complement: Some([
                routh::nalgebra::Vector6::new(1.0, 0.2, 0.0, 0.1, 0.0, 0.3),
                routh::nalgebra::Vector6::new(0.0, 1.0, 0.5, 0.0, 0.2, 0.0),
                routh::nalgebra::Vector6::new(0.1, 0.0, 0.0, 0.3, 0.4, 1.0),
            ]),
            ..Default::default()
        },
    ];
    for c in &charts {
        let r = orbit_nonlinear_stability_in(&m, o, c, &opts).unwrap();
        eprintln!("{r} vs {base}");
        assert!((r.rotation_number - base.rotation_number).abs() < 1e-8);
        assert!(
            (r.twist - base.twist).abs() < 1e-6 * base.twist.abs(),
            "{} vs {}",
            r.twist,
            base.twist
        );
    }
    let rt = Model::new(TEXT, &[("inertia", m.inertia.into()), ("l", m.l.into())]).unwrap();
    let r = orbit_nonlinear_stability(&rt, o, &opts).unwrap();
    assert!((r.twist - base.twist).abs() < 1e-8 * base.twist.abs());
    assert_eq!(r.verdict, base.verdict);
}

/// Hyperbolic orbits are unstable, a hand-written model is refused by name.
#[test]
fn linear_verdicts_and_refusals() {
    let m = body();
    let s = hanging(&m);
    let fam = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(3)).unwrap();
    let mut o = fam.orbits[0].clone();
    o.stability = OrbitStability::Hyperbolic;
    let r = orbit_nonlinear_stability(&m, &o, &OrbitNonlinearOptions::default()).unwrap();
    assert_eq!(r.verdict, OrbitNonlinearVerdict::Unstable);
    assert!(r.twist.is_nan() && r.rotation_number.is_nan());
    let bad = OrbitNonlinearOptions {
        twist_tol: 0.0,
        ..Default::default()
    };
    let e = orbit_nonlinear_stability(&m, &fam.orbits[0], &bad).unwrap_err();
    assert!(e.to_string().contains("twist_tol"), "{e}");
}

/// Along the swing family of mode 0 with `nonlinear`, the resonance events sit where `k` is
/// −1/2 or 0 and the twist events where `τ` changes sign (recomputed on another section).
#[test]
fn nonlinear_events_along_a_family() {
    let m = body();
    let s = hanging(&m);
    let opts = OrbitOptions {
        nonlinear: true,
        ..OrbitOptions::default().with_max_orbits(40)
    };
    let fam = lyapunov_family(&m, &s, 0, &opts).unwrap();
    let plain = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(40)).unwrap();
    // The linear events are the same with and without.
    let linear = |f: &routh::OrbitFamily| {
        f.events
            .iter()
            .filter(|e| {
                matches!(
                    e.kind,
                    OrbitEventKind::Fold
                        | OrbitEventKind::BranchPoint
                        | OrbitEventKind::PeriodDoubling
                )
            })
            .map(|e| (e.kind, e.energy))
            .collect::<Vec<_>>()
    };
    let (a, b) = (linear(&fam), linear(&plain));
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.0, y.0);
        assert!((x.1 - y.1).abs() < 1e-8);
    }
    let ks: Vec<f64> = fam.orbits.iter().map(|o| o.stability_index).collect();
    eprintln!("k along the family: {ks:?}");
    for e in &fam.events {
        eprintln!("{} at E = {}", e.kind, e.energy);
        match e.kind {
            OrbitEventKind::ThirdOrderResonance => {
                assert!((e.orbit.stability_index + 0.5).abs() < 1e-6)
            }
            OrbitEventKind::FourthOrderResonance => assert!(e.orbit.stability_index.abs() < 1e-6),
            OrbitEventKind::TwistDegenerate => {
                let near = orbit_nonlinear_stability_in(
                    &m,
                    &e.orbit,
                    &SectionChart {
                        shear: 0.5,
                        ..Default::default()
                    },
                    &OrbitNonlinearOptions::default(),
                )
                .unwrap();
                assert!(near.twist.abs() < 1e-5, "τ = {}", near.twist);
            }
            _ => {}
        }
    }
    assert!(
        fam.events.iter().any(|e| e.kind != OrbitEventKind::Fold
            && e.kind != OrbitEventKind::BranchPoint
            && e.kind != OrbitEventKind::PeriodDoubling),
        "no nonlinear event along {:?}",
        ks
    );
}

/// `tr Φ(T)` by central differences of `simulate_full` (an integration routh's variational
/// equations play no part in).
fn fd_index(m: &Body, o: &PeriodicOrbit) -> f64 {
    let opts = routh::SimOptions::with_tolerances(1e-12, 1e-13);
    let end = |w: Vector3<f64>, g: Vector3<f64>| {
        let t = routh::simulate_full(m, w, g, o.period, &opts).unwrap();
        let (w1, g1) = (*t.omega.last().unwrap(), *t.gamma.last().unwrap());
        [w1.x, w1.y, w1.z, g1.x, g1.y, g1.z]
    };
    // An orthonormal basis: the three ω axes, two tangents of the sphere at γ₀, and γ₀ itself,
    // whose diagonal entry is 1 (|γ| is conserved, so the radial part of δγ(T) is δ|γ|).
    let g0 = o.gamma0;
    let u = g0.cross(&Vector3::new(0.3, 0.5, 0.7)).normalize();
    let v = g0.cross(&u);
    let h = 1e-6;
    let mut trace = 1.0;
    for i in 0..5 {
        let (mut wp, mut wm) = (o.omega0, o.omega0);
        let (mut gp, mut gm) = (g0, g0);
        let dir = [u, v];
        if i < 3 {
            wp[i] += h;
            wm[i] -= h;
        } else {
            gp = (g0 + dir[i - 3] * h).normalize();
            gm = (g0 - dir[i - 3] * h).normalize();
        }
        let (ep, em) = (end(wp, gp), end(wm, gm));
        let d: Vec<f64> = (0..6).map(|k| (ep[k] - em[k]) / (2.0 * h)).collect();
        trace += if i < 3 {
            d[i]
        } else {
            let b = dir[i - 3];
            d[3] * b.x + d[4] * b.y + d[5] * b.z
        };
    }
    (trace - 4.0) / 2.0
}

/// The chart over the middle moment: its curves' points are where an independent monodromy
/// (finite differences of `simulate_full`) has `k = 1`, `0` or `−1/2`, and where the twist,
/// recomputed on another chart of the section, vanishes; the curves are continued in `(x, h)`:
/// the resonance 1/3 is a tongue that turns back in `x`, one curve through its tip, and a point
/// of it between the grid's `x` is an event of the family traced there from its steady motion.
#[test]
fn orbit_chart_curves_are_where_the_conditions_hold() {
    let make = |b: f64| {
        (
            Body {
                inertia: Vector3::new(1.0, b, 3.0),
                l: 1.5,
            },
            0.0,
        )
    };
    let opts = routh::OrbitChartOptions {
        nx: 4,
        ..Default::default()
    };
    let chart = routh::orbit_chart(make, -Vector3::z(), 0, (1.9, 2.1), (0.0, 2.8), &opts).unwrap();
    assert_eq!(chart.x.len(), 4);
    assert!(chart.stop.is_none() && chart.failures.iter().all(|f| f.is_none()));
    let kinds: Vec<_> = chart
        .curves
        .iter()
        .map(|c| (c.kind, c.points.len()))
        .collect();
    // k = 1, k = 0 and τ = 0 cross the chart: one curve each, from x = 1.9 to 2.1.
    for kind in [
        OrbitEventKind::BranchPoint,
        OrbitEventKind::FourthOrderResonance,
        OrbitEventKind::TwistDegenerate,
    ] {
        let c: Vec<_> = chart.curves.iter().filter(|c| c.kind == kind).collect();
        assert_eq!(c.len(), 1, "{kind}: {kinds:?}");
        let (a, b) = (c[0].points[0], c[0].points[c[0].points.len() - 1]);
        assert!(a[0] == 1.9 && b[0] == 2.1, "{kind}: {:?}", c[0].points);
    }
    // k = −1/2: met twice at x = 2.0333 and 2.1 by the families, once by none at 1.9667: one
    // curve, both ends at x = 2.1, its tip between 1.9667 and 2.0333.
    let third: Vec<_> = chart
        .curves
        .iter()
        .filter(|c| c.kind == OrbitEventKind::ThirdOrderResonance)
        .collect();
    assert_eq!(third.len(), 1, "{kinds:?}");
    let pts = &third[0].points;
    assert!(pts[0][0] == 2.1 && pts[pts.len() - 1][0] == 2.1, "{pts:?}");
    let tip = pts.iter().map(|p| p[0]).fold(f64::INFINITY, f64::min);
    assert!(1.9667 < tip && tip < 2.0333, "tip at x = {tip}");
    // Every curve point at an x of the grid is the family's own event there (traced from
    // another seed, or from another x).
    for c in &chart.curves {
        for p in &c.points {
            let Some(i) = chart.x.iter().position(|&x| x == p[0]) else {
                continue;
            };
            let es = chart.steady_energy[i];
            let fam = chart.families[i].as_ref().unwrap();
            let near = fam
                .events
                .iter()
                .filter(|e| e.kind == c.kind)
                .map(|e| (e.energy - es - p[1]).abs())
                .fold(f64::INFINITY, f64::min);
            assert!(near < 1e-6, "{} at {p:?}: {near:e}", c.kind);
        }
    }
    // A point of the tongue between the grid's x: the family at that x, traced from its steady
    // motion, meets k = −1/2 there, and finite differences say k = −1/2.
    let p = pts
        .iter()
        .filter(|p| p[1] > 1.3 && !chart.x.contains(&p[0]))
        .min_by(|a, b| (a[0] - 2.05).abs().total_cmp(&(b[0] - 2.05).abs()))
        .copied()
        .expect("a point between the grid's x");
    let (m, _) = make(p[0]);
    let s = hanging(&m);
    let o = OrbitOptions {
        nonlinear: true,
        energy_bounds: Some((s.energy, s.energy + p[1] + 0.05)),
        max_orbits: 400,
        ..Default::default()
    };
    let fam = lyapunov_family(&m, &s, 0, &o).unwrap();
    let ev = fam
        .events
        .iter()
        .filter(|e| e.kind == OrbitEventKind::ThirdOrderResonance)
        .min_by(|a, b| {
            (a.energy - s.energy - p[1])
                .abs()
                .total_cmp(&(b.energy - s.energy - p[1]).abs())
        })
        .expect("the resonance on the family");
    assert!(
        (ev.energy - s.energy - p[1]).abs() < 1e-6,
        "{p:?} vs {}",
        ev.energy - s.energy
    );
    let k_fd = fd_index(&m, &ev.orbit);
    assert!((k_fd + 0.5).abs() < 1e-5, "k = {k_fd}");
    // Every event at the chart's first and last x, checked independently.
    for (i, fam) in chart.families.iter().enumerate() {
        if i != 0 && i != 3 {
            continue;
        }
        let (m, _) = make(chart.x[i]);
        for e in &fam.as_ref().unwrap().events {
            let k_fd = fd_index(&m, &e.orbit);
            match e.kind {
                OrbitEventKind::BranchPoint => assert!((k_fd - 1.0).abs() < 1e-5, "k = {k_fd}"),
                OrbitEventKind::FourthOrderResonance => assert!(k_fd.abs() < 1e-5, "k = {k_fd}"),
                OrbitEventKind::ThirdOrderResonance => {
                    assert!((k_fd + 0.5).abs() < 1e-5, "k = {k_fd}")
                }
                OrbitEventKind::TwistDegenerate => {
                    let r = orbit_nonlinear_stability_in(
                        &m,
                        &e.orbit,
                        &SectionChart {
                            shear: -0.4,
                            ..Default::default()
                        },
                        &OrbitNonlinearOptions::default(),
                    )
                    .unwrap();
                    assert!(r.twist.abs() < 1e-6, "τ = {}", r.twist);
                }
                _ => {}
            }
        }
    }
}

/// The largest distance in `(ω, γ)` from the orbit's path of a motion started at `γ₀` turned by
/// `delta` about an axis across it, over `periods` periods (an integration of its own).
fn escape(m: &derived_models::AsymmetricTop, o: &PeriodicOrbit, delta: f64, periods: usize) -> f64 {
    let path = routh::orbit_path(m, o, 4001).unwrap();
    let pts: Vec<[f64; 6]> = (0..path.t.len())
        .map(|i| {
            let (w, g) = (path.omega[i], path.gamma[i]);
            [w.x, w.y, w.z, g.x, g.y, g.z]
        })
        .collect();
    let axis = o.gamma0.cross(&Vector3::new(0.3, -0.7, 0.2)).normalize();
    let g = routh::nalgebra::Rotation3::new(axis * delta) * o.gamma0;
    let t_end = o.period * periods as f64;
    let times: Vec<f64> = (0..=periods * 40)
        .map(|i| t_end * i as f64 / (periods * 40) as f64)
        .collect();
    let opts = routh::SimOptions::with_tolerances(1e-11, 1e-12).at_times(times);
    let tr = routh::simulate_full(m, o.omega0, g, t_end, &opts).unwrap();
    (0..tr.t.len())
        .map(|i| {
            let (w, g) = (tr.omega[i], tr.gamma[i]);
            let x = [w.x, w.y, w.z, g.x, g.y, g.z];
            pts.iter()
                .map(|p| (0..6).map(|k| (p[k] - x[k]).powi(2)).sum::<f64>())
                .fold(f64::INFINITY, f64::min)
                .sqrt()
        })
        .fold(0.0, f64::max)
}

/// At a resonance of order three of the asymmetric top's swings (no reflection symmetry: the
/// resonant term is not zero) the verdict is unstable, and a motion started 1e−2 from the orbit
/// leaves its neighbourhood, while from an orbitally stable orbit of the same family it stays.
#[test]
fn a_third_order_resonance_is_unstable_and_the_motion_leaves() {
    let m = derived_models::AsymmetricTop {
        inertia: Vector3::new(1.0, 3.0, 6.0),
        com: Vector3::new(0.4, 0.3, 1.5),
        mass: 1.0,
        g: 1.0,
    };
    let s = routh::steady_motions(&m, 0.0)
        .unwrap()
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .unwrap();
    let opts = OrbitOptions {
        nonlinear: true,
        ..OrbitOptions::default().with_max_orbits(60)
    };
    let fam = lyapunov_family(&m, &s, 0, &opts).unwrap();
    let e = fam
        .events
        .iter()
        .find(|e| e.kind == OrbitEventKind::ThirdOrderResonance)
        .expect("a resonance of order three");
    let r = orbit_nonlinear_stability(&m, &e.orbit, &OrbitNonlinearOptions::default()).unwrap();
    assert_eq!(r.resonance, Some(routh::OrbitResonance::Third), "{r}");
    assert_eq!(r.verdict, OrbitNonlinearVerdict::Unstable, "{r}");
    // An orbitally stable orbit of the family before the resonance, away from it.
    let stable = fam
        .orbits
        .iter()
        .rev()
        .filter(|o| o.energy < e.energy && (o.stability_index + 0.5).abs() > 0.2)
        .find(|o| o.stability == OrbitStability::Elliptic)
        .expect("an elliptic orbit");
    let rs = orbit_nonlinear_stability(&m, stable, &OrbitNonlinearOptions::default()).unwrap();
    assert_eq!(rs.verdict, OrbitNonlinearVerdict::OrbitallyStable, "{rs}");
    let (d_res, d_stable) = (
        escape(&m, &e.orbit, 1e-2, 150),
        escape(&m, stable, 1e-2, 150),
    );
    eprintln!("resonant: {d_res}, stable: {d_stable}");
    assert!(
        d_stable < 0.05,
        "the stable orbit's neighbour went {d_stable} away"
    );
    assert!(
        d_res > 0.15,
        "the resonant orbit's neighbour stayed within {d_res}"
    );
}

/// The Kovalevskaya top (moments 2 : 2 : 1, centre of mass on e₁), integrable: invariant curves
/// (its tori) surround every elliptic orbit, so at each resonance of order three of its family
/// the resonant term vanishes (the map has an integral) and the verdict is never `Unstable`.
#[test]
fn kovalevskaya_resonances_of_order_three_are_not_unstable() {
    let m = Body3 {
        inertia: Vector3::new(2.0, 2.0, 1.0),
        com: Vector3::new(1.0, 0.0, 0.0),
    };
    let s = routh::steady_motions(&m, 0.5)
        .unwrap()
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .unwrap();
    let opts = OrbitOptions {
        nonlinear: true,
        ..OrbitOptions::default().with_max_orbits(60)
    };
    let fam = lyapunov_family(&m, &s, 0, &opts).unwrap();
    let third: Vec<_> = fam
        .events
        .iter()
        .filter(|e| e.kind == OrbitEventKind::ThirdOrderResonance)
        .collect();
    assert!(
        third.len() >= 2,
        "{:?}",
        fam.events.iter().map(|e| e.kind).collect::<Vec<_>>()
    );
    for e in third {
        let r = orbit_nonlinear_stability(&m, &e.orbit, &OrbitNonlinearOptions::default()).unwrap();
        assert_eq!(r.resonance, Some(routh::OrbitResonance::Third), "{r}");
        assert_ne!(r.verdict, OrbitNonlinearVerdict::Unstable, "{r}");
    }
}

/// A heavy body with principal moments `inertia` and centre of mass `com` (m g = 1).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = com.dot(gamma),
)]
struct Body3 {
    inertia: Vector3<f64>,
    com: Vector3<f64>,
}

/// An axially symmetric body (A₁ = A₂, centre of mass on e₃): its swings are degenerate (the
/// reduced system is integrable, every multiplier 1), and the verdict says so instead of a twist.
#[test]
fn symmetric_bodies_swings_are_undecided_as_degenerate() {
    let m = Body {
        inertia: Vector3::new(1.0, 1.0, 1.6),
        l: 1.0,
    };
    let fam = lyapunov_family(
        &m,
        &hanging(&m),
        0,
        &OrbitOptions::default().with_max_orbits(4),
    )
    .unwrap();
    let o = fam.orbits.last().unwrap();
    assert!(o.degenerate, "{o}");
    let r = orbit_nonlinear_stability(&m, o, &OrbitNonlinearOptions::default()).unwrap();
    assert_eq!(r.verdict, OrbitNonlinearVerdict::Undecided);
    assert!(r.reason.contains("degenerate") && r.twist.is_nan(), "{r}");
}

type V6 = routh::nalgebra::Vector6<f64>;

fn state(w: Vector3<f64>, g: Vector3<f64>) -> V6 {
    V6::new(w.x, w.y, w.z, g.x, g.y, g.z)
}

/// `(E, p_ψ, |γ|²)` at `x` and their gradients by central differences.
fn levels_fd(m: &Body, x: &V6) -> ([f64; 3], [V6; 3]) {
    let f = |y: &V6| {
        let (w, g) = (
            Vector3::new(y[0], y[1], y[2]),
            Vector3::new(y[3], y[4], y[5]),
        );
        [
            m.energy(&w, &g),
            m.cyclic_momentum(&w, &g),
            g.norm_squared(),
        ]
    };
    let h = 1e-6;
    let mut grads = [V6::zeros(); 3];
    for i in 0..6 {
        let (mut p, mut q) = (*x, *x);
        p[i] += h;
        q[i] -= h;
        let (fp, fq) = (f(&p), f(&q));
        for k in 0..3 {
            grads[k][i] = (fp[k] - fq[k]) / (2.0 * h);
        }
    }
    (f(x), grads)
}

/// The rotation number of the section map's orbit through `y`, by a weighted Birkhoff average
/// of the angle steps about the fixed point in the chart `(u₁, u₂)` (Das, Sander & Yorke: the
/// error falls faster than any power of the number of iterates on an invariant curve), and the
/// Euclidean area the iterates enclose in that chart.
fn rotation_and_area(
    m: &Body,
    o: &PeriodicOrbit,
    ell: &V6,
    u: [V6; 2],
    y0: V6,
    n: usize,
) -> (f64, f64) {
    let x0 = state(o.omega0, o.gamma0);
    let opts = routh::SimOptions::with_tolerances(1e-12, 1e-13);
    let flow = |y: &V6, t: f64| {
        let tr = routh::simulate_full(
            m,
            Vector3::new(y[0], y[1], y[2]),
            Vector3::new(y[3], y[4], y[5]).normalize(),
            t,
            &opts,
        )
        .unwrap();
        state(*tr.omega.last().unwrap(), *tr.gamma.last().unwrap())
    };
    let mut y = y0;
    let mut pts = Vec::with_capacity(n + 1);
    pts.push([u[0].dot(&(y - x0)), u[1].dot(&(y - x0))]);
    for _ in 0..n {
        // The return near T: a secant on ℓ·(φ_t(y) − x₀) = 0 in t.
        let s = |t: f64| ell.dot(&(flow(&y, t) - x0));
        let (mut t0, mut t1) = (0.95 * o.period, 1.05 * o.period);
        let (mut s0, mut s1) = (s(t0), s(t1));
        for _ in 0..30 {
            let t2 = t1 - s1 * (t1 - t0) / (s1 - s0);
            let s2 = s(t2);
            (t0, s0, t1, s1) = (t1, s1, t2, s2);
            if s2.abs() < 1e-14 {
                break;
            }
        }
        y = flow(&y, t1);
        pts.push([u[0].dot(&(y - x0)), u[1].dot(&(y - x0))]);
    }
    // Angle steps, clockwise positive in a positively oriented chart.
    let ang: Vec<f64> = pts.iter().map(|p| p[1].atan2(p[0])).collect();
    let w = |t: f64| {
        if t <= 0.0 || t >= 1.0 {
            0.0
        } else {
            (-1.0 / (t * (1.0 - t))).exp()
        }
    };
    let (mut num, mut den) = (0.0, 0.0);
    for k in 0..n {
        let mut d = ang[k] - ang[k + 1];
        d = d.rem_euclid(2.0 * PI);
        let wk = w((k as f64 + 0.5) / n as f64);
        num += wk * d;
        den += wk;
    }
    // The area: the iterates sorted by angle, the shoelace formula.
    let mut sorted = pts.clone();
    sorted.sort_by(|a, b| a[1].atan2(a[0]).total_cmp(&b[1].atan2(b[0])));
    let mut area = 0.0;
    for k in 0..sorted.len() {
        let (a, b) = (sorted[k], sorted[(k + 1) % sorted.len()]);
        area += 0.5 * (a[0] * b[1] - b[0] * a[1]);
    }
    (num / den / (2.0 * PI), area.abs())
}

/// τ against the rotation numbers of invariant curves around the orbit, measured by iterating
/// the Poincaré map of `simulate_full` on another section (the hyperplane normal to the flow at
/// the orbit's start): `ρ(A) = ρ + τA`, `A = |Ω(u₁, u₂)| × the curve's area in the chart`.
#[test]
fn twist_is_the_slope_of_rotation_numbers_of_invariant_curves() {
    let m = body();
    let s = hanging(&m);
    let fam = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(8)).unwrap();
    let o = fam.orbits.last().unwrap();
    let rep = orbit_nonlinear_stability(&m, o, &OrbitNonlinearOptions::default()).unwrap();
    let x0 = state(o.omega0, o.gamma0);
    let f0 = routh::nalgebra::Vector6::from_row_slice(&vector_field(
        &m,
        &[x0[0], x0[1], x0[2], x0[3], x0[4], x0[5]],
    ));
    let ell = f0 / f0.norm_squared();
    let (c0, grads) = levels_fd(&m, &x0);
    // The section's tangent plane: orthonormal (u₁, u₂) ⊥ ℓ, ∇E, ∇p_ψ, ∇|γ|².
    let rows = routh::nalgebra::Matrix4x6::from_rows(&[
        ell.transpose(),
        grads[0].transpose(),
        grads[1].transpose(),
        grads[2].transpose(),
    ]);
    let svd = rows.transpose().svd(true, false);
    let q = svd.u.unwrap();
    let basis: Vec<V6> = (0..4).map(|i| q.column(i).into()).collect();
    let project = |v: V6| basis.iter().fold(v, |acc, b| acc - b * b.dot(&v));
    let u1 = project(V6::new(0.3, 0.8, -0.2, 0.5, 0.1, 0.4)).normalize();
    let mut u2 = project(V6::new(-0.6, 0.2, 0.9, -0.1, 0.7, 0.3));
    u2 = (u2 - u1 * u1.dot(&u2)).normalize();
    let mut om = orbit_symplectic_form(&m, &x0, &u1, &u2);
    if om < 0.0 {
        u2 = -u2;
        om = -om;
    }
    // Starts at distance r along u₁, put onto the section and the levels by Gauss–Newton.
    let start = |r: f64| {
        let mut y = x0 + u1 * r;
        for _ in 0..6 {
            let (c, g) = levels_fd(&m, &y);
            let res = routh::nalgebra::Vector4::new(
                ell.dot(&(y - x0)),
                c[0] - c0[0],
                c[1] - c0[1],
                c[2] - c0[2],
            );
            let j = routh::nalgebra::Matrix4x6::from_rows(&[
                ell.transpose(),
                g[0].transpose(),
                g[1].transpose(),
                g[2].transpose(),
            ]);
            y -= j.transpose() * (j * j.transpose()).try_inverse().unwrap() * res;
        }
        y
    };
    let mut samples = Vec::new();
    for r in [0.01, 0.02] {
        let (rho, area) = rotation_and_area(&m, o, &ell, [u1, u2], start(r), 400);
        samples.push((rho, om * area));
    }
    let slope = (samples[1].0 - samples[0].0) / (samples[1].1 - samples[0].1);
    eprintln!(
        "ρ(A): {samples:?}; slope {slope:e} vs τ = {:e}, ρ₀ = {}",
        rep.twist, rep.rotation_number
    );
    assert!((samples[0].0 - rep.rotation_number).abs() < 1e-3);
    assert!(
        (slope - rep.twist).abs() < 0.01 * rep.twist.abs(),
        "slope of ρ(A) {slope:e} vs τ {:e}",
        rep.twist
    );
}
