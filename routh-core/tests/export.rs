//! CSV export read back by a parser written here (split on commas, columns by header name): every
//! column holds the field it is named after, numbers round-trip exactly, the row counts match.

use std::collections::HashMap;

use routh_core::{
    bifurcation_diagram, simulate_full, simulate_reduced, stability_atlas, AtlasOptions,
    ContinuationOptions, Lagrangian, SimOptions, Stability, Vector3,
};
use test_models::Gyrostat;

/// Header names → column index, and the rows as fields.
fn parse(csv: &str) -> (HashMap<String, usize>, Vec<Vec<String>>) {
    let mut lines = csv.lines();
    let header: HashMap<String, usize> = (lines.next().unwrap().split(','))
        .enumerate()
        .map(|(i, n)| (n.to_string(), i))
        .collect();
    let rows: Vec<Vec<String>> = lines
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect();
    assert!(rows.iter().all(|r| r.len() == header.len()));
    (header, rows)
}

fn num(h: &HashMap<String, usize>, row: &[String], name: &str) -> f64 {
    row[h[name]]
        .parse()
        .unwrap_or_else(|_| panic!("{name}: {}", row[h[name]]))
}

#[test]
fn trajectory_columns_hold_their_fields() {
    let top = Gyrostat::heavy_top(
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(0.3, -0.2, 0.5),
        1.0,
        9.81,
    );
    let (w, g) = (
        Vector3::new(1.0, -0.5, 2.0),
        Vector3::new(0.3, 0.4, 0.866).normalize(),
    );
    let plain = simulate_full(&top, w, g, 1.0, &SimOptions::default()).unwrap();
    let (h, rows) = parse(&plain.to_csv());
    assert_eq!(h.len(), 11);
    assert!(!h.contains_key("q_w"));
    let tr = simulate_full(&top, w, g, 1.0, &SimOptions::default().with_attitude()).unwrap();
    let (h, rows_att) = parse(&tr.to_csv());
    assert_eq!(rows.len(), plain.len());
    assert_eq!(rows_att.len(), tr.len());
    let euler = tr.euler_angles();
    for (i, r) in rows_att.iter().enumerate() {
        assert_eq!(num(&h, r, "t"), tr.t[i]);
        assert_eq!(num(&h, r, "omega_2"), tr.omega[i].y);
        assert_eq!(num(&h, r, "gamma_3"), tr.gamma[i].z);
        assert_eq!(num(&h, r, "energy"), tr.energy[i]);
        assert_eq!(num(&h, r, "p_psi_drift"), tr.p_psi[i] - tr.p_psi[0]);
        assert_eq!(num(&h, r, "euler_theta"), euler[i][1]);
        // The quaternion columns describe an attitude with Rᵀe₃ = γ.
        let q = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
            num(&h, r, "q_w"),
            num(&h, r, "q_x"),
            num(&h, r, "q_y"),
            num(&h, r, "q_z"),
        ));
        let g = q.inverse_transform_vector(&Vector3::z());
        assert!((g - tr.gamma[i].normalize()).amax() < 1e-14);
    }
    let p = top.cyclic_momentum(&w, &g);
    let rt = simulate_reduced(&top, w - g * w.dot(&g), g, p, 1.0, &SimOptions::default()).unwrap();
    let (h, rows) = parse(&rt.to_csv());
    assert_eq!(rows.len(), rt.len());
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(num(&h, r, "psi"), rt.psi[i]);
        assert_eq!(num(&h, r, "big_omega_1"), rt.big_omega[i].x);
        assert_eq!(num(&h, r, "omega_3"), rt.omega[i].z);
    }
    let path = std::env::temp_dir().join(format!("routh-export-{}.csv", std::process::id()));
    tr.write_csv(&path).unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), tr.to_csv());
    let _ = std::fs::remove_file(&path);
}

#[test]
fn diagram_and_atlas_tables() {
    let top = Gyrostat::lagrange_top(1.0, 1.25, 1.0);
    let d = bifurcation_diagram(
        |p| (top.clone(), p),
        (0.5, 5.0),
        &ContinuationOptions::default(),
    )
    .unwrap();
    let (h, rows) = parse(&d.to_csv());
    let n: usize = d.branches.iter().map(|b| b.points.len()).sum();
    assert_eq!(rows.len(), n);
    let mut k = 0;
    for (b, branch) in d.branches.iter().enumerate() {
        for q in &branch.points {
            let r = &rows[k];
            k += 1;
            assert_eq!(r[h["branch"]], b.to_string());
            assert_eq!(num(&h, r, "s"), q.s);
            assert_eq!(num(&h, r, "gamma_2"), q.steady.gamma.y);
            assert_eq!(num(&h, r, "psi_dot"), q.steady.psi_dot);
            let want = match q.report.verdict {
                Stability::SecularlyStable => "secularly_stable",
                Stability::GyroscopicallyStabilized => "gyroscopically_stabilized",
                Stability::Unstable => "unstable",
                Stability::Degenerate => "degenerate",
            };
            assert_eq!(r[h["verdict"]], want);
        }
    }
    let (h, rows) = parse(&d.events_to_csv());
    assert_eq!(rows.len(), d.events.len());
    assert!(rows.iter().any(|r| r[h["kind"]] == "hamiltonian_hopf"));

    let opts = AtlasOptions {
        nx: 7,
        ny: 5,
        ..AtlasOptions::default()
    };
    let atlas = stability_atlas(
        |mgl, p| (Gyrostat::lagrange_top(1.0, 1.25, mgl), p),
        Vector3::z(),
        (0.5, 1.5),
        (1.0, 4.0),
        &opts,
    )
    .unwrap();
    let (h, rows) = parse(&atlas.to_csv());
    assert_eq!(rows.len(), 35);
    for r in &rows {
        let (x, y) = (num(&h, r, "x"), num(&h, r, "y"));
        let i = atlas.x.iter().position(|&v| v == x).unwrap();
        let j = atlas.y.iter().position(|&v| v == y).unwrap();
        assert_eq!(r[h["verdict"]].is_empty(), atlas.verdicts[j][i].is_none());
    }
    // The sleeping top at mgl = 0.5, p = 4 is secularly stable (p² > mgl C²/(C − A₁)).
    let corner = rows
        .iter()
        .find(|r| num(&h, r, "x") == 0.5 && num(&h, r, "y") == 4.0)
        .unwrap();
    assert_eq!(corner[h["verdict"]], "secularly_stable");
    let (h, rows) = parse(&atlas.boundaries_to_csv());
    let n: usize = atlas.boundaries.iter().map(|b| b.points.len()).sum();
    assert_eq!(rows.len(), n);
    assert!(rows.iter().all(|r| !r[h["kind"]].is_empty()));
}
