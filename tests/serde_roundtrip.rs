//! Every result type (and the options) survives a round trip through JSON (feature `serde`, on by
//! default): `from_json(to_json(x)) == x` field for field, f64 bit for bit (serde_json with
//! `float_roundtrip`); for the types without `PartialEq` (the certificate) or holding NaN (a
//! nonlinear report of an unstable motion, most errors) the JSON of the decoded value equals the
//! JSON of the original. Every instance is built by running the analysis on a real body.
//!
//! Covered, by the public function that returns it (routh, routh-core, routh-runtime):
//!
//! | type | from | test |
//! |---|---|---|
//! | `SimOptions`, `Method`, `Output` | options of `simulate_*` | `trajectories_round_trip` |
//! | `Trajectory`, `SimStats` (in it), attitude and Euler angles | `simulate_full` | `trajectories_round_trip` |
//! | `ReducedTrajectory` | `simulate_reduced` | `trajectories_round_trip` |
//! | `ApexLocus` | `sim::attitude::classify_apex_locus` | `trajectories_round_trip` |
//! | `SteadyMotion`, `SearchOptions`, `SearchResult` | `steady_motions`, `steady_motion_search` | `steady_motions_reports_and_matrices_round_trip` |
//! | `StabilityReport`, `Stability`, `ClassifyOptions` | `classify` | `steady_motions_reports_and_matrices_round_trip` |
//! | `KreinReport` | `stability::krein_report` | `steady_motions_reports_and_matrices_round_trip` |
//! | `Classified` | `classified_steady_motions` | `classified_motions_round_trip` |
//! | `CircleReport`, `CircleStability` | `classify_circle` | `classified_motions_round_trip` |
//! | `GyroscopicSystem`, `RouthBundle`, `FullEquations`, `ReducedEquations`, `RankOneInertia` | `Routhian::gyroscopic_system`, `bundle`, `full_equations`, `reduced_equations` | `steady_motions_reports_and_matrices_round_trip` |
//! | `ContinuationOptions`, `BifurcationDiagram`, `Branch`, `BranchPoint`, `BranchEvent`, `EventKind` | `bifurcation_diagram` | `diagrams_and_atlases_round_trip` |
//! | `StopReason` | `BifurcationDiagram::stop` | `diagrams_and_atlases_round_trip` |
//! | `CountCheck` | `BifurcationDiagram::checks` | `diagrams_and_atlases_round_trip` |
//! | `AtlasOptions`, `StabilityAtlas`, `BoundaryCurve` | `stability_atlas` | `diagrams_and_atlases_round_trip` |
//! | `CertifyOptions`, `Certificate`, `CertifiedMotion`, `UndecidedRegion`, `Interval` | `steady_motions_certified` | `certificates_round_trip` |
//! | `NonlinearOptions`, `NonlinearReport`, `NonlinearVerdict`, `Resonance` | `nonlinear_stability` | `nonlinear_reports_and_events_round_trip` |
//! | `NonlinearEvent` | `families::nonlinear_events` | `nonlinear_reports_and_events_round_trip` |
//! | `LinearNormalForm`, `Jet` | `nonlinear::linear_normal_form` | `nonlinear_reports_and_events_round_trip` |
//! | `RouthError` (tagged, with its message) | every fallible function | `errors_round_trip` |
//! | `LatexFormulas` | `DerivedFormulas::latex`, `Model::latex` | `formulas_models_and_their_errors_round_trip` |
//! | `SympyFormulas` | `Model::sympy` | `formulas_models_and_their_errors_round_trip` |
//! | `Param`, `ModelError` | `Model::get`, `Model::new` | `formulas_models_and_their_errors_round_trip` |
//! | `fluid::FluidParameters` | `fluid::kirchhoff_lagrangian` | `formulas_models_and_their_errors_round_trip` |
//!
//! Not covered, on purpose: `Model` itself (an input holding compiled tapes; its text and
//! parameters are what to save), the tapes of routh-tape (internal to the derive), the plot
//! options and `plot::PlotError` (errors of writing a file, not results of an analysis).
#![cfg(feature = "serde")]

use derived_models::{AsymmetricTop, LagrangeTop};
use routh::certify::{steady_motions_certified, CertifyOptions, Interval};
use routh::families::nonlinear_events;
use routh::families::BifurcationDiagram;
use routh::nonlinear::{linear_normal_form, Jet};
use routh::sim::attitude::classify_apex_locus;
use routh::stability::krein_report;
use routh::steady::{steady_motion_search, SearchOptions};
use routh::{
    bifurcation_diagram, classified_steady_motions, classify, nonlinear_stability, simulate_full,
    simulate_reduced, stability_atlas, steady_motions, AtlasOptions, ClassifyOptions,
    ContinuationOptions, DerivedFormulas, EventKind, GyroscopicSystem, Lagrangian, Model,
    NonlinearOptions, NonlinearVerdict, Param, RouthError, Routhian, SimOptions, SteadyMotion,
    StopReason, Vector3,
};
use serde::{de::DeserializeOwned, Serialize};

fn round_trip<T: Serialize + DeserializeOwned + PartialEq + std::fmt::Debug>(x: &T) -> String {
    let json = serde_json::to_string(x).expect("serialise");
    let back: T = serde_json::from_str(&json).expect("deserialise");
    assert_eq!(&back, x, "{json}");
    json
}

/// For values holding NaN (where `==` fails by definition): the decoded value prints the same
/// (`Debug`, every field, NaN as `NaN`) and re-serialises to the same text.
fn round_trip_nan<T: Serialize + DeserializeOwned + std::fmt::Debug>(x: &T) -> String {
    let json = round_trip_json(x);
    let back: T = serde_json::from_str(&json).expect("deserialise");
    assert_eq!(format!("{back:?}"), format!("{x:?}"), "{json}");
    json
}

/// For types without `PartialEq`: the JSON of the decoded value is the same text.
fn round_trip_json<T: Serialize + DeserializeOwned>(x: &T) -> String {
    let json = serde_json::to_string(x).expect("serialise");
    let back: T = serde_json::from_str(&json).expect("deserialise");
    assert_eq!(serde_json::to_string(&back).expect("again"), json);
    json
}

fn top() -> AsymmetricTop {
    AsymmetricTop {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        mass: 1.0,
        g: 9.81,
        com: Vector3::new(0.3, -0.2, 0.5),
    }
}

#[test]
fn trajectories_round_trip() {
    let model = top();
    let (w, g) = (
        Vector3::new(1.0, -0.5, 2.0),
        Vector3::new(0.3, 0.4, 0.866).normalize(),
    );
    for opts in [
        SimOptions::default(),
        SimOptions::lie_rk4(0.01).with_attitude(),
        SimOptions::default()
            .with_attitude()
            .at_times(vec![0.0, 0.5, 1.0]),
    ] {
        round_trip(&opts);
        let tr = simulate_full(&model, w, g, 1.0, &opts).unwrap();
        let json = round_trip(&tr);
        assert!(json.contains("\"omega\"") && json.contains("\"attitude\""));
        assert!(tr.attitude.is_empty() || tr.attitude.len() == tr.t.len());
        let p = model.cyclic_momentum(&w, &g);
        let rt = simulate_reduced(&model, w - g * w.dot(&g), g, p, 1.0, &opts).unwrap();
        round_trip(&rt);
    }
}

#[test]
fn steady_motions_reports_and_matrices_round_trip() {
    let model = top();
    let motions = steady_motions(&model, 3.0).unwrap();
    assert!(!motions.is_empty());
    round_trip(&motions);
    round_trip(&SearchOptions::default());
    round_trip(&ClassifyOptions::default());
    round_trip(&steady_motion_search(&model, 3.0, &SearchOptions::default()).unwrap());
    for s in &motions {
        let r = classify(&model, s).unwrap();
        round_trip(&r);
        round_trip(&r.verdict);
        round_trip(&krein_report(&model, s, &ClassifyOptions::default()).unwrap());
        let sys: GyroscopicSystem = model.gyroscopic_system(&s.gamma, s.p_psi);
        round_trip(&sys);
        round_trip(&model.bundle(&Vector3::new(0.1, 0.2, 0.3), &s.gamma, s.p_psi));
        round_trip(&model.full_equations(&Vector3::new(0.1, 0.2, 0.3), &s.gamma));
    }
}

#[test]
fn diagrams_and_atlases_round_trip() {
    let top = LagrangeTop::example();
    round_trip(&ContinuationOptions::default());
    let d: BifurcationDiagram = bifurcation_diagram(
        |p| (top.clone(), p),
        (0.5, 6.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    assert!(!d.branches.is_empty() && !d.events.is_empty());
    round_trip(&d);
    round_trip(&d.events[0].kind);
    let cut = bifurcation_diagram(
        |p| (top.clone(), p),
        (0.0, 5.0),
        &ContinuationOptions {
            max_branches: 2,
            ..Default::default()
        },
    )
    .unwrap();
    assert!(matches!(cut.stop, Some(StopReason::MaxBranches { .. })));
    round_trip(&cut);
    round_trip(&cut.stop);
    let checked = bifurcation_diagram(
        |p| (top.clone(), p),
        (0.5, 6.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    round_trip(&checked);
    let opts = AtlasOptions {
        nx: 9,
        ny: 9,
        ..AtlasOptions::default()
    };
    round_trip(&opts);
    let atlas = stability_atlas(
        |mgl: f64, p: f64| (LagrangeTop::with_mgl(1.0, 1.25, mgl), p),
        Vector3::z(),
        (0.5, 2.0),
        (0.5, 5.0),
        &opts,
    )
    .unwrap();
    assert!(!atlas.boundaries.is_empty());
    round_trip(&atlas);
}

#[test]
fn certificates_round_trip() {
    round_trip(&CertifyOptions::default());
    let cert = steady_motions_certified(&top(), 1.0, &CertifyOptions::default()).unwrap();
    assert!(!cert.motions.is_empty());
    let json = round_trip_json(&cert);
    assert!(json.contains("\"enclosure\""));
}

/// The nonlinear options and results (`ContinuationOptions::nonlinear`, `BranchEvent::nonlinear`,
/// `AtlasOptions::nonlinear`, `StabilityAtlas::nonlinear`) survive the round trip; JSON without
/// the new fields (written before they existed) still reads, as `None` / empty.
#[test]
fn nonlinear_events_and_curves_round_trip() {
    use routh::{EventKind, NonlinearOptions};
    let top = LagrangeTop::example();
    let copts = ContinuationOptions {
        verify_counts: false,
        nonlinear: Some(NonlinearOptions::default()),
        ..ContinuationOptions::default()
    };
    round_trip(&copts);
    let d = bifurcation_diagram(|p| (top.clone(), p), (1.5, 3.0), &copts).unwrap();
    assert!(d
        .events
        .iter()
        .any(|e| e.kind == EventKind::ArnoldDegenerate && e.nonlinear.is_some()));
    round_trip(&d);
    let aopts = AtlasOptions {
        nx: 9,
        ny: 9,
        nonlinear: Some(NonlinearOptions::default()),
        ..AtlasOptions::default()
    };
    round_trip(&aopts);
    let atlas = stability_atlas(
        |mgl: f64, p: f64| (LagrangeTop::with_mgl(1.0, 1.25, mgl), p),
        Vector3::z(),
        (0.5, 2.0),
        (0.5, 5.0),
        &aopts,
    )
    .unwrap();
    assert!(!atlas.nonlinear.is_empty());
    round_trip(&atlas);
    // Old JSON: drop the new keys.
    let mut v = serde_json::to_value(ContinuationOptions::default()).unwrap();
    v.as_object_mut().unwrap().remove("nonlinear");
    let back: ContinuationOptions = serde_json::from_value(v).unwrap();
    assert_eq!(back, ContinuationOptions::default());
    let mut v = serde_json::to_value(&d.events[0]).unwrap();
    v.as_object_mut().unwrap().remove("nonlinear");
    let back: routh::BranchEvent = serde_json::from_value(v).unwrap();
    assert_eq!(back.nonlinear, None);
}

/// A Lagrange top's looping apex, classified from a simulation's Euler angles.
#[test]
fn apex_locus_round_trips() {
    let top = LagrangeTop::example();
    let g0 = Vector3::new(0.3f64.sin(), 0.0, 0.3f64.cos());
    // Spin 6 about the axis and a backwards push of the apex: ψ̇ changes sign, loops.
    let w0 = Vector3::new(0.0, -1.5, 6.0);
    let tr = simulate_full(&top, w0, g0, 6.0, &SimOptions::default().with_attitude()).unwrap();
    let locus = classify_apex_locus(&tr.t, &tr.euler_angles(), 0.02).expect("a precession");
    round_trip(&locus);
}

#[test]
fn classified_motions_round_trip() {
    let all = classified_steady_motions(&LagrangeTop::example(), 3.0).unwrap();
    assert_eq!(all.len(), 3);
    round_trip(&all);
    let json = round_trip(&all[0]);
    assert!(json.contains("\"report\"") && json.contains("\"motion\""));
    let circle = all.iter().find(|c| !c.motion.isolated).expect("the circle");
    let report = routh::classify_circle(&LagrangeTop::example(), &circle.motion, &Vector3::z());
    let json = round_trip(&report.unwrap());
    assert!(json.contains("\"Stable\""), "{json}");
}

/// The Lagrange top `A = 1, C = 0.8, mgl = 1` sleeping (as in routh-core's nonlinear tests): a
/// Lyapunov-stable report with finite fields, an unstable one with NaN fields, the 1:2 and 1:3
/// resonance events over `p ∈ [2.1, 4]`, and the linear normal form with its Hamiltonian jet.
#[test]
fn nonlinear_reports_and_events_round_trip() {
    let top = LagrangeTop::with_mgl(1.0, 0.8, 1.0);
    let opts = NonlinearOptions::default();
    round_trip(&opts);
    let stable = nonlinear_stability(
        &top,
        &SteadyMotion::at(&top, Vector3::z(), 3.0, true).unwrap(),
        &opts,
    )
    .unwrap();
    assert_eq!(stable.verdict, NonlinearVerdict::LyapunovStable);
    assert!(stable.resonance_distance.is_nan()); // no resonance
    round_trip_nan(&stable);
    round_trip(&stable.verdict);
    let unstable = nonlinear_stability(
        &top,
        &SteadyMotion::at(&top, Vector3::z(), 1.0, true).unwrap(),
        &opts,
    )
    .unwrap();
    assert_eq!(unstable.verdict, NonlinearVerdict::Unstable);
    assert!(unstable.frequencies[0].is_nan());
    let json = round_trip_nan(&unstable);
    assert!(json.contains("\"NaN\""), "{json}");
    let back: routh::NonlinearReport = serde_json::from_str(&json).unwrap();
    assert!(back.frequencies.iter().all(|w| w.is_nan()));
    assert_eq!(back.linear, unstable.linear);

    let family = |p: f64| (top.clone(), p);
    let copts = ContinuationOptions {
        verify_counts: false,
        ..Default::default()
    };
    let d = bifurcation_diagram(family, (2.1, 4.0), &copts).unwrap();
    let ev = nonlinear_events(family, lagrange_r, &d, &opts, 1e-10).unwrap();
    let resonances: Vec<_> = ev.iter().filter_map(|e| e.resonance).collect();
    assert!(resonances.len() >= 2, "{ev:?}");
    assert!(ev
        .iter()
        .all(|e| e.kind == EventKind::Resonance || e.kind == EventKind::ArnoldDegenerate));
    round_trip_nan(&ev);
    round_trip(&resonances);

    let r = |w: &[Jet; 3], g: &[Jet; 3], p: f64| lagrange_r(&top, w, g, p);
    let nf = linear_normal_form(&r, &Vector3::z(), 3.0).expect("two frequencies");
    let json = round_trip(&nf);
    // 70 Taylor coefficients of the jet, beyond serde's derive for arrays.
    assert!(json.matches(',').count() > 70);
    round_trip(&nf.hamiltonian);
}

/// `R = ½ΩᵀIΩ − mgl γ₃ − ½(p − (IΩ)·γ)²/(γᵀIγ)` (39) of a Lagrange top, at jets.
fn lagrange_r(top: &LagrangeTop, w: &[Jet; 3], g: &[Jet; 3], p: f64) -> Jet {
    let i = [top.a1, top.a1, top.c];
    let iw = [w[0] * i[0], w[1] * i[1], w[2] * i[2]];
    let ig = [g[0] * i[0], g[1] * i[1], g[2] * i[2]];
    let dot = |a: &[Jet; 3], b: &[Jet; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let q = -dot(&iw, g) + p;
    dot(&iw, w) * 0.5 - g[2] * top.mgl() - q * q / dot(&ig, g) * 0.5
}

/// Real failures of the analyses: each is written as `{"kind": …, fields…, "message": …}`, read
/// back to an error with the same fields (compared by re-serialising, NaN included) and the same
/// message.
#[test]
fn errors_round_trip() {
    let top = LagrangeTop::example();
    let tilted = Vector3::new(0.6, 0.0, 0.8);
    let mut errors: Vec<RouthError> = vec![
        steady_motions(&top, f64::NAN).unwrap_err(),
        simulate_full(
            &top,
            Vector3::z(),
            2.0 * Vector3::z(),
            1.0,
            &SimOptions::default(),
        )
        .unwrap_err(),
        classify(
            &top,
            &SteadyMotion {
                gamma: tilted,
                ..SteadyMotion::at(&top, Vector3::z(), 3.0, true).unwrap()
            },
        )
        .unwrap_err(),
        simulate_full(
            &top,
            Vector3::new(0.1, 0.2, 3.0),
            tilted,
            100.0,
            &SimOptions {
                max_steps: 5,
                ..SimOptions::default()
            },
        )
        .unwrap_err(),
        bifurcation_diagram(
            |p| (top.clone(), p),
            (0.5, 6.0),
            &ContinuationOptions {
                max_steps: 0,
                ..Default::default()
            },
        )
        .unwrap_err(),
        bifurcation_diagram(
            |p| (top.clone(), if p > 1.0 { f64::INFINITY } else { p }),
            (0.5, 6.0),
            &ContinuationOptions::default(),
        )
        .unwrap_err(),
    ];
    errors.push(RouthError::AtParameter {
        s: 2.5,
        source: Box::new(errors[0].clone()),
    });
    let kinds: Vec<String> = errors
        .iter()
        .map(|e| {
            let json = round_trip_nan(e);
            let v: serde_json::Value = serde_json::from_str(&json).unwrap();
            assert_eq!(v["message"], e.to_string(), "{json}");
            let back: RouthError = serde_json::from_str(&json).unwrap();
            assert_eq!(back.to_string(), e.to_string());
            if !json.contains("NaN") && !json.contains("Infinity") {
                assert_eq!(&back, e);
            }
            v["kind"].as_str().unwrap().to_string()
        })
        .collect();
    for kind in [
        "NonFinite",
        "NonUnitGamma",
        "NotASteadyMotion",
        "TooManySteps",
        "InvalidOption",
        "AtParameter",
    ] {
        assert!(kinds.iter().any(|k| k == kind), "{kind} not in {kinds:?}");
    }
    // `message` is optional on input: it is recomputed from the fields.
    let e: RouthError =
        serde_json::from_str(r#"{"kind": "NonFinite", "what": "omega0", "value": "-Infinity"}"#)
            .unwrap();
    assert_eq!(e.to_string(), "non-finite input: omega0 = -inf");
    assert!(serde_json::from_str::<RouthError>(r#"{"kind": "NoSuchError"}"#).is_err());
    // An unbounded interval: ±∞ survive.
    round_trip(&Interval::ENTIRE);
}

#[test]
fn formulas_models_and_their_errors_round_trip() {
    let derived = LagrangeTop::example().latex();
    assert!(derived.amended_potential.contains("p_\\psi"));
    round_trip(&derived);
    let text = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z";
    let model = Model::new(
        text,
        &[
            ("inertia", Vector3::new(1.0, 1.0, 1.25).into()),
            ("mgl", 1.0.into()),
        ],
    )
    .unwrap();
    round_trip(&model.latex());
    round_trip(&model.sympy());
    let inertia = model.get("inertia").unwrap();
    assert_eq!(inertia, Param::Vector(Vector3::new(1.0, 1.0, 1.25)));
    round_trip(&inertia);
    round_trip(&model.get("mgl").unwrap());
    let err = Model::new(
        &text.replace("mgl *", "mlg *"),
        &[("inertia", inertia), ("mgl", 1.0.into())],
    )
    .unwrap_err();
    let json = round_trip(&err);
    assert!(json.contains("mlg"), "{json}");
    let fluid = derived_models::Kirchhoff::chiral().parameters(2.0).unwrap();
    round_trip(&fluid);
}
