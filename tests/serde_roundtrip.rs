//! Every result type (and the options) survives a round trip through JSON (feature `serde`, on by
//! default): `from_json(to_json(x)) == x` field for field, f64 bit for bit (serde_json with
//! `float_roundtrip`); for the types without `PartialEq` (the certificate) the JSON of the
//! decoded value equals the JSON of the original.
#![cfg(feature = "serde")]

use derived_models::{AsymmetricTop, LagrangeTop};
use routh::certify::{steady_motions_certified, CertifyOptions};
use routh::families::BifurcationDiagram;
use routh::stability::classify_with_krein;
use routh::steady::{steady_motions_with, SearchOptions};
use routh::{
    bifurcation_diagram, classify, simulate_full, simulate_reduced, stability_atlas,
    steady_motions, AtlasOptions, ClassifyOptions, ContinuationOptions, GyroscopicSystem,
    Lagrangian, Routhian, SimOptions, Vector3,
};
use serde::{de::DeserializeOwned, Serialize};

fn round_trip<T: Serialize + DeserializeOwned + PartialEq + std::fmt::Debug>(x: &T) -> String {
    let json = serde_json::to_string(x).expect("serialise");
    let back: T = serde_json::from_str(&json).expect("deserialise");
    assert_eq!(&back, x, "{json}");
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
    round_trip(&steady_motions_with(&model, 3.0, &SearchOptions::default()).unwrap());
    for s in &motions {
        let r = classify(&model, s).unwrap();
        round_trip(&r);
        round_trip(&r.verdict);
        round_trip(&classify_with_krein(&model, s, &ClassifyOptions::default()).unwrap());
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
