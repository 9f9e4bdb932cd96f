//! `nonlinear_stability` on models with a Routh-function tape (the derive's and a run-time
//! `Model`'s), against the same method fed by a hand-written `R` (39) evaluated at jets: the
//! tape must give the same frequencies, Krein signs, Birkhoff coefficients and verdicts.

use crate::common::close_to;
use routh::nonlinear::{nonlinear_stability_from_jet, Jet};
use routh::{
    nonlinear_stability, Lagrangian, Model, NonlinearOptions, NonlinearVerdict, Stability,
    SteadyMotion, Vector3,
};

/// A heavy top with principal moments `inertia` and centre of mass on e₃ at height `l` (m g = 1).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = l * gamma.z,
)]
struct Top {
    inertia: Vector3<f64>,
    l: f64,
}

/// `R = ½ΩᵀIΩ − l γ₃ − ½(p − (IΩ)·γ)²/(γᵀIγ)` (39), written by hand over jets.
fn hand_r(top: &Top) -> impl Fn(&[Jet; 3], &[Jet; 3], f64) -> Jet + '_ {
    move |w: &[Jet; 3], g: &[Jet; 3], p: f64| {
        let i = top.inertia;
        let iw = [w[0] * i.x, w[1] * i.y, w[2] * i.z];
        let ig = [g[0] * i.x, g[1] * i.y, g[2] * i.z];
        let dot = |a: &[Jet; 3], b: &[Jet; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let q = -dot(&iw, g) + p;
        dot(&iw, w) * 0.5 - g[2] * top.l - q * q / dot(&ig, g) * 0.5
    }
}

#[test]
fn the_tape_gives_the_hand_written_normal_form() {
    let opts = NonlinearOptions::default();
    let text = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z";
    // An asymmetric prolate top (I₃ smallest) sleeping at momenta on its gyroscopic stretch, and
    // a Lagrange top above Maievskii's bound.
    for (inertia, p) in [
        (Vector3::new(2.0, 2.5, 1.5), 6.0),
        (Vector3::new(2.0, 2.5, 1.5), 9.0),
        (Vector3::new(1.0, 1.0, 0.8), 2.5),
    ] {
        let top = Top { inertia, l: 1.0 };
        let runtime = Model::new(text, &[("inertia", inertia.into()), ("l", 1.0.into())]).unwrap();
        let s = SteadyMotion::at(&top, Vector3::z(), p, true).unwrap();
        let hand = nonlinear_stability_from_jet(&top, &s, &hand_r(&top), &opts).unwrap();
        assert_eq!(hand.linear.verdict, Stability::GyroscopicallyStabilized);
        let derived = nonlinear_stability(&top, &s, &opts).unwrap();
        let s_rt = SteadyMotion::at(&runtime, Vector3::z(), p, true).unwrap();
        let from_text = nonlinear_stability(&runtime, &s_rt, &opts).unwrap();
        for rep in [&derived, &from_text] {
            assert_eq!(rep.verdict, hand.verdict, "{rep}\nvs\n{hand}");
            assert_eq!(rep.krein_signs, hand.krein_signs);
            assert_eq!(rep.resonance, hand.resonance);
            for k in 0..2 {
                assert!(close_to(
                    rep.frequencies[k],
                    hand.frequencies[k],
                    1e-9,
                    hand.frequencies[0]
                ));
            }
            let scale = hand.normal_form.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            for k in 0..3 {
                assert!(
                    close_to(rep.normal_form[k], hand.normal_form[k], 1e-9, scale),
                    "c[{k}]: {} vs {}",
                    rep.normal_form[k],
                    hand.normal_form[k]
                );
            }
        }
        assert_ne!(hand.verdict, NonlinearVerdict::Unstable, "{hand}");
    }
}

/// The hand derivation (docs/method.md §10.8, `test_models::birkhoff`) as
/// `([c₂₀, c₁₁, c₀₂], [ω₁, ω₂], s₁s₂, D)`.
fn lagrange_top_by_hand(a: f64, c: f64, g: f64, p: f64) -> ([f64; 3], [f64; 2], f64, f64) {
    let h = test_models::birkhoff::sleeping_top_normal_form(a, c, g, p);
    (
        h.normal_form,
        h.frequencies,
        h.sign_product,
        h.arnold_determinant,
    )
}

/// Check (c): `nonlinear_stability` (the derive's R tape, and a run-time model's) on the sleeping
/// Lagrange top against the closed form derived by hand (docs/method.md §10.8), to 1e−8 relative,
/// at several momenta and inertias: prolate tops on their gyroscopic stretch (one exactly at the
/// 1:2 resonance p² = 16/3 of A = 1, C = 0.8, where the closed form gives c = (1.25, 1.25, 0.25),
/// D = 19/3), and an oblate top on both sides of its secular bound p² = gC²/(C − A).
#[test]
fn sleeping_lagrange_top_normal_form_matches_the_hand_derivation() {
    let opts = NonlinearOptions::default();
    let text = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z";
    let cases = [
        (1.0, 0.8, 1.0, 2.1),
        (1.0, 0.8, 1.0, (16.0f64 / 3.0).sqrt()),
        (1.0, 0.8, 1.0, 3.0),
        (1.0, 0.8, 1.0, 7.5),
        (2.0, 1.2, 0.7, 2.6),
        (2.0, 1.2, 0.7, 5.0),
        (1.5, 0.5, 2.0, 4.0),
        (1.0, 1.5, 1.0, 2.05), // oblate, gyroscopic: 4 < p² < 4.5
        (1.0, 1.5, 1.0, 3.0),  // oblate, secular
    ];
    let mut worst = 0.0f64;
    for (a, c, g, p) in cases {
        let inertia = Vector3::new(a, a, c);
        let top = Top { inertia, l: g };
        let runtime = Model::new(text, &[("inertia", inertia.into()), ("l", g.into())]).unwrap();
        let (cs, w, s12, d) = lagrange_top_by_hand(a, c, g, p);
        let s = SteadyMotion::at(&top, Vector3::z(), p, true).unwrap();
        let s_rt = SteadyMotion::at(&runtime, Vector3::z(), p, true).unwrap();
        for rep in [
            nonlinear_stability(&top, &s, &opts).unwrap(),
            nonlinear_stability(&runtime, &s_rt, &opts).unwrap(),
        ] {
            println!("A = {a}, C = {c}, mgl = {g}, p = {p}: {rep}");
            let rel = |x: f64, y: f64, scale: f64| (x - y).abs() / scale;
            let c_scale = cs.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            for (k, (&code, &hand)) in rep.normal_form.iter().zip(&cs).enumerate() {
                let e = rel(code, hand, c_scale);
                worst = worst.max(e);
                assert!(e <= 1e-8, "c[{k}] = {code} by hand {hand}");
            }
            for (k, (&code, &hand)) in rep.frequencies.iter().zip(&w).enumerate() {
                let e = rel(code, hand, w[0]);
                worst = worst.max(e);
                assert!(e <= 1e-8, "ω[{k}] = {code} by hand {hand}");
            }
            assert_eq!(
                f64::from(rep.krein_signs[0] * rep.krein_signs[1]),
                s12,
                "{rep}"
            );
            let d_scale =
                cs[0].abs() * w[1] * w[1] + cs[1].abs() * w[0] * w[1] + cs[2].abs() * w[0] * w[0];
            let e = rel(rep.arnold_determinant, d, d_scale);
            worst = worst.max(e);
            assert!(e <= 1e-8, "D = {} by hand {d}", rep.arnold_determinant);
            let expected = if s12 > 0.0 {
                NonlinearVerdict::SecularlyStable
            } else if rep.resonance.is_some() {
                rep.verdict // the resonances of check (e), tested on their own
            } else {
                NonlinearVerdict::LyapunovStable
            };
            assert_eq!(rep.verdict, expected, "{rep}");
        }
    }
    println!("largest relative difference from the hand derivation: {worst:.2e}");
}

/// The indicators of the nonlinear events, computed here from a report: `D/scale`,
/// `ω₁/ω₂ − 2`, `ω₁/ω₂ − 3`.
fn event_indicators(rep: &routh::NonlinearReport) -> [f64; 3] {
    let [w1, w2] = rep.frequencies;
    let [c20, c11, c02] = rep.normal_form;
    let scale = c20.abs() * w2 * w2 + c11.abs() * w1 * w2 + c02.abs() * w1 * w1;
    [rep.arnold_determinant / scale, w1 / w2 - 2.0, w1 / w2 - 3.0]
}

/// `ContinuationOptions::nonlinear` on the sleeping asymmetric prolate top I = diag(2, 2.5, 1.5),
/// mgl = 1, over p_ψ ∈ [3, 12]: (1) with the option off the diagram is the same as before (the
/// option on adds events and changes nothing else: same branches, same linear events); (2) the
/// nonlinear events are those of the post-pass `nonlinear_events` fed by a hand-written R; (3)
/// each lies within 1e−9·max(1, |s|) of an independent location: a scan of the sleeping top's
/// `nonlinear_stability` over 181 momenta for sign changes of D/scale and ω₁/ω₂ − k, each then
/// bisected 60 times in p_ψ (the steady motion is γ = e₃ at every p_ψ, no continuation).
#[test]
fn diagram_option_locates_the_nonlinear_events() {
    use routh::families::nonlinear_events;
    use routh::{bifurcation_diagram, ContinuationOptions, EventKind};
    let top = Top {
        inertia: Vector3::new(2.0, 2.5, 1.5),
        l: 1.0,
    };
    let family = |p: f64| (top.clone(), p);
    let range = (3.0, 12.0);
    let off = ContinuationOptions {
        verify_counts: false,
        ..Default::default()
    };
    let on = ContinuationOptions {
        nonlinear: Some(NonlinearOptions::default()),
        ..off.clone()
    };
    let t0 = std::time::Instant::now();
    let d_off = bifurcation_diagram(family, range, &off).unwrap();
    let t1 = std::time::Instant::now();
    let d_on = bifurcation_diagram(family, range, &on).unwrap();
    let t2 = std::time::Instant::now();
    println!(
        "diagram: {:.2} s without the option, {:.2} s with it",
        (t1 - t0).as_secs_f64(),
        (t2 - t1).as_secs_f64()
    );
    let nonlinear_kind =
        |k: EventKind| matches!(k, EventKind::ArnoldDegenerate | EventKind::Resonance);
    // (1) Off: no nonlinear event; on: the same diagram plus the nonlinear events.
    assert!(d_off
        .events
        .iter()
        .all(|e| !nonlinear_kind(e.kind) && e.nonlinear.is_none()));
    assert_eq!(d_on.branches, d_off.branches);
    assert_eq!(d_on.stop, d_off.stop);
    let linear: Vec<_> = d_on
        .events
        .iter()
        .filter(|e| !nonlinear_kind(e.kind))
        .cloned()
        .collect();
    assert_eq!(linear, d_off.events);
    let added: Vec<_> = d_on
        .events
        .iter()
        .filter(|e| nonlinear_kind(e.kind))
        .collect();
    for e in &added {
        println!("{e}");
        assert!(e.nonlinear.is_some());
    }
    assert!(d_on.events.windows(2).all(|w| w[0].s <= w[1].s));
    // (2) The post-pass with a hand-written R finds the same events.
    let jets = |m: &Top, w: &[Jet; 3], g: &[Jet; 3], p: f64| hand_r(m)(w, g, p);
    let post = nonlinear_events(family, jets, &d_off, &NonlinearOptions::default(), 1e-10).unwrap();
    assert_eq!(post.len(), added.len(), "{post:?}");
    for (a, b) in post.iter().zip(&added) {
        assert_eq!(a.kind, b.kind);
        assert_eq!(a.branch, b.branch);
        assert_eq!(Some(a.verdicts()), b.nonlinear);
        assert!(
            (a.s - b.s).abs() <= 1e-9 * a.s.abs().max(1.0),
            "{} vs {}",
            a.s,
            b.s
        );
    }
    // (3) An independent location on the sleeping top.
    let opts = NonlinearOptions::default();
    let at = |p: f64| {
        let s = SteadyMotion::at(&top, Vector3::z(), p, true).unwrap();
        let rep = nonlinear_stability(&top, &s, &opts).unwrap();
        (rep.linear.verdict == Stability::GyroscopicallyStabilized).then(|| event_indicators(&rep))
    };
    let mut expected = Vec::new();
    let grid: Vec<f64> = (0..=180)
        .map(|k| range.0 + (range.1 - range.0) * f64::from(k) / 180.0)
        .collect();
    for w in grid.windows(2) {
        let (Some(a), Some(b)) = (at(w[0]), at(w[1])) else {
            continue;
        };
        for k in 0..3 {
            if a[k] * b[k] >= 0.0 {
                continue;
            }
            let (mut lo, mut hi) = (w[0], w[1]);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                match at(mid) {
                    Some(v) if v[k] * a[k] > 0.0 => lo = mid,
                    _ => hi = mid,
                }
            }
            let s = 0.5 * (lo + hi);
            // A zero of D, not a pole: D/scale small there.
            if k == 0 && at(s).is_none_or(|v| v[0].abs() > 1e-6) {
                continue;
            }
            expected.push((k, s));
        }
    }
    println!("independent scan: {expected:?}");
    let on_sleeping: Vec<_> = added.iter().filter(|e| e.gamma.z > 0.999).collect();
    assert!(!expected.is_empty());
    assert_eq!(on_sleeping.len(), expected.len(), "{on_sleeping:?}");
    for (e, (k, s)) in on_sleeping.iter().zip(&expected) {
        let kind = if *k == 0 {
            EventKind::ArnoldDegenerate
        } else {
            EventKind::Resonance
        };
        assert_eq!(e.kind, kind);
        let r = e.nonlinear.unwrap().resonance;
        assert_eq!(
            r,
            [
                None,
                Some(routh::Resonance::OneToTwo),
                Some(routh::Resonance::OneToThree)
            ][*k]
        );
        let err = (e.s - s).abs() / s.abs().max(1.0);
        println!(
            "{} at {:.12}: independent {s:.12}, |Δs|/max(1, s) = {err:.1e}",
            e.kind, e.s
        );
        assert!(err <= 1e-9);
    }
}

/// `AtlasOptions::nonlinear` on the sleeping prolate Lagrange top A = 1, C = 0.8 over
/// (mgl, p_ψ) ∈ [0.5, 1.5] × [1.5, 4]: the 1:2 and 1:3 curves against their closed forms
/// (§10.5: ω₁/ω₂ = (λp + d)/(λp − d), λ = 1.5, d² = p² − 4A·mgl, so 1:2 at p² = 16·mgl/3 and 1:3
/// at p² = 64·mgl/7), every crossing to 1e−8; no D = 0 curve (D > 0, §10.8); the segments join
/// crossings of the same curve; and with the option off the atlas is the same without curves.
#[test]
fn atlas_option_draws_the_resonance_curves_of_the_lagrange_top() {
    use routh::{stability_atlas, AtlasOptions, EventKind, Resonance};
    let family = |mgl: f64, p: f64| {
        (
            Top {
                inertia: Vector3::new(1.0, 1.0, 0.8),
                l: mgl,
            },
            p,
        )
    };
    let off = AtlasOptions {
        nx: 9,
        ny: 11,
        ..Default::default()
    };
    let on = AtlasOptions {
        nonlinear: Some(NonlinearOptions::default()),
        ..off.clone()
    };
    let (x, y) = ((0.5, 1.5), (1.5, 4.0));
    let a_off = stability_atlas(family, Vector3::z(), x, y, &off).unwrap();
    let a_on = stability_atlas(family, Vector3::z(), x, y, &on).unwrap();
    assert!(a_off.nonlinear.is_empty());
    let mut stripped = a_on.clone();
    stripped.nonlinear.clear();
    assert_eq!(stripped, a_off);
    assert!(a_on
        .nonlinear
        .iter()
        .all(|c| c.kind != EventKind::ArnoldDegenerate));
    for (res, k) in [
        (Resonance::OneToTwo, 16.0 / 3.0),
        (Resonance::OneToThree, 64.0 / 7.0),
    ] {
        let curve = a_on
            .nonlinear
            .iter()
            .find(|c| c.resonance == Some(res))
            .unwrap_or_else(|| panic!("no {res} curve"));
        assert_eq!(curve.kind, EventKind::Resonance);
        // p = √(k·mgl) crosses every column x = mgl in the range: at least one crossing each.
        assert!(curve.crossings.len() >= 9, "{res}: {:?}", curve.crossings);
        let mut worst = 0.0f64;
        for &(mgl, p) in &curve.crossings {
            worst = worst.max((p * p / (k * mgl) - 1.0).abs());
        }
        println!(
            "{res}: {} crossings, {} segments, largest |p²/(k·mgl) − 1| = {worst:.1e}",
            curve.crossings.len(),
            curve.segments.len()
        );
        assert!(worst <= 1e-8, "{res}: {worst:e}");
        assert!(curve.segments.len() >= curve.crossings.len() - 2);
        for s in &curve.segments {
            for q in s {
                assert!(curve.crossings.contains(q));
            }
        }
    }
}

/// `ContinuationOptions::nonlinear` on the oblate Lagrange top A = 1, C = 1.25, mgl = 1 over
/// p_ψ ∈ [1.5, 3], against closed forms only: on its gyroscopic stretch 2 < p < 2.5 (Maievskii,
/// secular bound) ω₁/ω₂ = (λp + d)/(λp − d), λ = 0.6, so 1:2 at p² = 4/0.96 and 1:3 at
/// p² = 4/0.91; and D of the hand derivation (§10.8) vanishes once, at the root of the closed
/// form found here by bisection (p* ≈ 2.438052). Each event to 1e−9·max(1, |s|); the verdicts:
/// undecided at D = 0 and at 1:2 (no resonant term: the symmetry), Lyapunov stable at 1:3 and on
/// both sides of each.
#[test]
fn diagram_option_on_the_oblate_lagrange_top_matches_the_closed_forms() {
    use routh::{bifurcation_diagram, ContinuationOptions, EventKind, Resonance};
    let (a, c, g) = (1.0, 1.25, 1.0);
    let top = Top {
        inertia: Vector3::new(a, a, c),
        l: g,
    };
    let opts = ContinuationOptions {
        verify_counts: false,
        nonlinear: Some(NonlinearOptions::default()),
        ..Default::default()
    };
    let d = bifurcation_diagram(|p: f64| (top.clone(), p), (1.5, 3.0), &opts).unwrap();
    // The zero of D by bisection of the closed form on (2.3, 2.5 − 1e−9).
    let dd = |p: f64| lagrange_top_by_hand(a, c, g, p).3;
    let (mut lo, mut hi) = (2.3, 2.5 - 1e-9);
    assert!(dd(lo) > 0.0 && dd(hi) < 0.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if dd(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let expected = [
        (
            EventKind::Resonance,
            Some(Resonance::OneToTwo),
            (4.0f64 / 0.96).sqrt(),
        ),
        (
            EventKind::Resonance,
            Some(Resonance::OneToThree),
            (4.0f64 / 0.91).sqrt(),
        ),
        (EventKind::ArnoldDegenerate, None, 0.5 * (lo + hi)),
    ];
    let found: Vec<_> = d.events.iter().filter(|e| e.nonlinear.is_some()).collect();
    for e in &found {
        println!("{e}");
    }
    assert_eq!(found.len(), expected.len());
    for (e, (kind, res, s)) in found.iter().zip(expected) {
        let n = e.nonlinear.unwrap();
        assert_eq!((e.kind, n.resonance), (kind, res));
        let err = (e.s - s).abs() / s.max(1.0);
        println!(
            "{kind} {res:?}: {:.12} against the closed form {s:.12}: {err:.1e}",
            e.s
        );
        assert!(err <= 1e-9, "{err:e}");
        assert!(e.gamma.z > 1.0 - 1e-12);
        let at = if res == Some(Resonance::OneToThree) {
            NonlinearVerdict::LyapunovStable
        } else {
            NonlinearVerdict::Undecided
        };
        assert_eq!(n.at, at, "{e}");
        assert_eq!(n.before, NonlinearVerdict::LyapunovStable);
        assert_eq!(n.after, NonlinearVerdict::LyapunovStable);
    }
}

/// `AtlasOptions::nonlinear` on the atlas's threads: the curves of the sleeping prolate Lagrange
/// top above (A = 1, C = 0.8) from `stability_atlas_parallel` on 1, 2 and 3 threads are those of
/// the sequential `stability_atlas`, bit for bit (each crossing is located from its own edge).
#[test]
fn atlas_nonlinear_curves_do_not_depend_on_the_number_of_threads() {
    use routh::{stability_atlas, stability_atlas_parallel, AtlasOptions};
    let family = |mgl: f64, p: f64| {
        (
            Top {
                inertia: Vector3::new(1.0, 1.0, 0.8),
                l: mgl,
            },
            p,
        )
    };
    let opts = AtlasOptions {
        nx: 7,
        ny: 9,
        nonlinear: Some(NonlinearOptions::default()),
        ..Default::default()
    };
    let (x, y) = ((0.5, 1.5), (1.5, 4.0));
    let sequential = stability_atlas(family, Vector3::z(), x, y, &opts).unwrap();
    assert!(sequential.nonlinear.len() >= 2);
    for threads in [1, 2, 3] {
        let o = AtlasOptions {
            threads,
            ..opts.clone()
        };
        let parallel = stability_atlas_parallel(family, Vector3::z(), x, y, &o).unwrap();
        assert_eq!(parallel, sequential, "{threads} threads");
    }
}
