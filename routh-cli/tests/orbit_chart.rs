//! `routh orbit --nonlinear`, `routh orbits --nonlinear` and `routh orbit-chart` run as a user
//! would. The twist at small amplitude is checked against `routh nonlinear`'s normal form of the
//! hanging position (τ → D/(π ω₁³), docs/method.md §12.3): a different algorithm; the chart's
//! files against their documented columns and the library's JSON schema.

mod common;

use common::{fails, ok, BODY_141, SWINGING as BODY};
use std::f64::consts::PI;

/// The CSV's row as `column → value`.
fn row(csv: &str) -> std::collections::HashMap<String, String> {
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let vals: Vec<&str> = lines.next().unwrap().split(',').collect();
    head.iter()
        .zip(vals)
        .map(|(h, v)| (h.to_string(), v.to_string()))
        .collect()
}

#[test]
fn orbit_nonlinear_twist_is_the_normal_forms_at_small_amplitude() {
    // The hanging position's ω₁, ω₂ and D from `routh nonlinear`.
    let nf = ok(&["nonlinear", BODY, "-p", "0", "--csv"]);
    let hanging = nf
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect::<Vec<_>>())
        .find(|f| f[3].parse::<f64>().unwrap() < -0.9)
        .expect("the hanging position");
    let (w1, d): (f64, f64) = (hanging[6].parse().unwrap(), hanging[11].parse().unwrap());
    // Swings about e₁ (ω₀² = mgl/J₁ = 1.5) of amplitude θ: τ(θ) = τ₀ + O(θ²).
    let twist = |theta: f64| -> f64 {
        let g = format!("0,{},{}", theta.sin(), -theta.cos());
        let period = format!("{}", 2.0 * PI / 1.5f64.sqrt());
        let csv = ok(&[
            "orbit",
            BODY,
            "--omega",
            "0,0,0",
            "--gamma",
            &g,
            "--period",
            &period,
            "--nonlinear",
            "--csv",
        ]);
        let r = row(&csv);
        assert_eq!(r["nonlinear"], "orbitally_stable", "{csv}");
        r["twist"].parse().unwrap()
    };
    let (a, b) = (0.02, 0.04);
    let (ta, tb) = (twist(a), twist(b));
    let tau0 = ta - (tb - ta) / (b * b - a * a) * a * a;
    let expected = d / (PI * w1.powi(3));
    assert!(
        (tau0 - expected).abs() < 1e-5 * expected.abs(),
        "τ₀ = {tau0} vs D/(πω₁³) = {expected}"
    );
    // The table says the same.
    let g = format!("0,{},{}", a.sin(), -a.cos());
    let t = ok(&[
        "orbit",
        BODY,
        "--omega",
        "0,0,0",
        "--gamma",
        &g,
        "--period",
        "5.13",
        "--nonlinear",
    ]);
    assert!(
        t.contains("orbitally_stable") && t.contains("rotation_number"),
        "{t}"
    );
}

#[test]
fn orbits_nonlinear_lists_the_new_events() {
    let out = ok(&[
        "orbits",
        BODY,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "0,0,-1",
        "--nonlinear",
        "--max-orbits",
        "40",
        "--csv",
    ]);
    let kinds: Vec<&str> = out
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(7).unwrap())
        .collect();
    assert!(kinds.contains(&"twist_degenerate"), "{kinds:?}");
    assert!(kinds.contains(&"fourth_order_resonance"), "{kinds:?}");
    // Without the flag, none of them.
    let plain = ok(&[
        "orbits",
        BODY,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "0,0,-1",
        "--max-orbits",
        "40",
        "--csv",
    ]);
    assert!(!plain.contains("twist_degenerate") && !plain.contains("resonance"));
}

#[test]
fn orbit_chart_table_csv_and_json() {
    let args = [
        "orbit-chart",
        BODY_141,
        "--parameter",
        "alpha=0.6..1.0",
        "--excess-energy",
        "0..1.9",
        "--gamma",
        "0,0,-1",
        "--nx",
        "3",
    ];
    let table = ok(&args);
    assert!(
        table.contains("branch_point") && table.contains("twist_degenerate"),
        "{table}"
    );
    let csv = ok(&[&args[..], &["--csv"]].concat());
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("curve,kind,parameter_name,x,h"));
    let mut n = 0;
    for l in lines {
        let f: Vec<&str> = l.split(',').collect();
        assert_eq!(f[2], "alpha");
        let (x, h): (f64, f64) = (f[3].parse().unwrap(), f[4].parse().unwrap());
        assert!((0.6..=1.0).contains(&x) && (0.0..=1.9).contains(&h), "{l}");
        n += 1;
    }
    assert!(n >= 3);
    let json = ok(&[&args[..], &["--json"]].concat());
    let chart: routh::OrbitChart = serde_json::from_str(&json).expect("the library's schema");
    assert_eq!(chart.x, vec![0.6, 0.8, 1.0]);
    assert!(
        json.contains("\"routh\": \"OrbitChart\"")
            && json.contains("\"parameter_name\": \"alpha\"")
    );
    assert_eq!(
        chart.curves.iter().map(|c| c.points.len()).sum::<usize>(),
        n,
        "the CSV has every point of the JSON"
    );
}

#[test]
fn orbit_chart_refuses_bad_input_with_exit_code_2() {
    let base = ["orbit-chart", BODY_141, "--gamma", "0,0,-1"];
    for (extra, needle) in [
        (
            vec!["--parameter", "beta=0..1", "--excess-energy", "0..1"],
            "beta",
        ),
        (
            vec!["--parameter", "alpha=0..1", "--excess-energy", "-1..1"],
            "excess-energy",
        ),
        (
            vec!["--parameter", "alpha=1..0", "--excess-energy", "0..1"],
            "alpha",
        ),
        (
            vec![
                "--parameter",
                "alpha=0..1",
                "--excess-energy",
                "0..1",
                "--nx",
                "1",
            ],
            "nx",
        ),
        (
            vec![
                "--parameter",
                "alpha=0..1",
                "--excess-energy",
                "0..1",
                "--mode",
                "2",
            ],
            "mode",
        ),
    ] {
        fails(&[&base[..], &extra[..]].concat(), 2, needle);
    }
}
