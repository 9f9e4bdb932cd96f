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
