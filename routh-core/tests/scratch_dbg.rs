use routh_core::{bifurcation_diagram, ContinuationOptions, Matrix3, Vector3};
use test_models::HeavyTop;

fn show(j: [f64; 3], m: f64, range: (f64, f64), s: f64) {
    let top = HeavyTop { j: Matrix3::from_diagonal(&Vector3::new(j[0], j[1], j[2])), mgr: Vector3::new(0.0, 0.0, m) };
    let d = bifurcation_diagram(|p| (top.clone(), p), range, &ContinuationOptions::default()).unwrap();
    for e in &d.events { println!("{e}"); }
    println!("count_at {}", d.count_at(s));
    for (i, b) in d.branches.iter().enumerate() {
        let c = b.points.windows(2).filter(|w| (w[0].s < s) != (w[1].s < s)).count();
        println!("branch {i} isolated {} n {} crosses {c}", b.isolated, b.points.len());
        for (k, w) in b.points.windows(2).enumerate() {
            if (w[0].s - s).abs() < 1e-3 || (w[1].s - s).abs() < 1e-3 || ((w[0].s < s) != (w[1].s < s)) {
                println!("  seg {k}: {:.12} {:?} -> {:.12} {:?}", w[0].s, w[0].steady.gamma.as_slice(), w[1].s, w[1].steady.gamma.as_slice());
            }
        }
    }
}

#[test]
fn dbg() {
    show([2.8963017981772854, 3.0454051892415364, 2.400342840199023], 1.2154879793322573, (2.843655441940367, 4.092980152670558), 3.7577189774612947);
    show([0.788719851067416, 0.7621267119618403, 2.049865802130186], 1.830041446856198, (2.2641887448958338, 3.0846192482300534), 2.469389366879567);
}
