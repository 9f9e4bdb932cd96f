//! `--opt KEY=VALUE`: any field of an analysis's options struct, as a user would give it. It does
//! what the command's own flag does (`--opt max_orbits=3` is `--max-orbits 3`: a family of three
//! orbits), a field no flag reaches acts (the library's check of it answers), and an unknown key
//! or a value of the wrong type is bad input (exit code 2) naming the key and the valid ones.

mod common;

use common::{fails_with, ok, ASYMMETRIC, SWINGING, TOP};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    serde_json::from_str(&ok(args)).expect("JSON")
}

/// Bad input: exit code 2, a message containing each of `needles`.
fn bad_input(args: &[&str], needles: &[&str]) {
    fails_with(args, 2, needles);
}

fn with<'a>(head: &[&'a str], tail: &[&'a str]) -> Vec<&'a str> {
    head.iter().chain(tail).copied().collect()
}

/// `routh orbits` of the asymmetric top's hanging position, mode 0, then `tail`.
fn family<'a>(tail: &[&'a str]) -> Vec<&'a str> {
    let mut v = vec!["orbits", ASYMMETRIC];
    v.extend("-p 0 --mode 0 --gamma -0.25,-0.19,-0.95".split_whitespace());
    v.extend(tail);
    v
}

#[test]
fn opt_max_orbits_is_the_flag() {
    let by_opt = json(&family(&["--opt", "max_orbits=3", "--json"]));
    let by_flag = json(&family(&["--max-orbits", "3", "--json"]));
    assert_eq!(by_opt[0]["orbits"].as_array().map(Vec::len), Some(3));
    assert_eq!(by_opt, by_flag);
    // Given after the flags, --opt overrides them.
    let both = json(&family(&[
        "--max-orbits",
        "5",
        "--opt",
        "max_orbits=2",
        "--json",
    ]));
    assert_eq!(both[0]["orbits"].as_array().map(Vec::len), Some(2));
}

#[test]
fn opt_reaches_fields_no_flag_does() {
    // energy_bounds: the family stays within them (a JSON pair, as --energy LO..HI).
    let v = json(&family(&[
        "--opt",
        "energy_bounds=[-1.6, -1.55]",
        "--opt",
        "max_orbits=50",
        "--json",
    ]));
    let energies: Vec<f64> = v[0]["orbits"]
        .as_array()
        .unwrap()
        .iter()
        .map(|o| o["energy"].as_f64().unwrap())
        .collect();
    assert!(!energies.is_empty() && energies.len() < 50, "{energies:?}");
    // The end is located on the bound (to the event tolerance).
    assert!(
        energies.iter().all(|e| (-1.6..=-1.55 + 1e-8).contains(e)),
        "{energies:?}"
    );
    // The library's own check of a field reaches the user in its words: the family it refuses
    // is listed as skipped (as a resonant start is), a single orbit is bad input.
    let out = ok(&family(&["--opt", "min_step=1"]));
    assert!(
        out.contains("invalid option OrbitOptions::min_step: 1 exceeds max_step = 0.1"),
        "{out}"
    );
    let guess = "--omega 1,0,0 --gamma 0,0,-1 --period 5.4 --opt newton_tol=1e-300";
    bad_input(
        &with(
            &["orbit", SWINGING],
            &guess.split_whitespace().collect::<Vec<_>>(),
        ),
        &["newton_tol", "below what double precision delivers"],
    );
}

#[test]
fn opt_of_the_section_and_the_simulation() {
    let args = [
        "section", TOP, "-p", "0", "-e", "-0.5", "--json", "--opt", "orbits=2",
    ];
    let v = json(&with(&args, &["--opt", "crossings=3"]));
    let orbits = v["orbits"].as_array().unwrap();
    assert_eq!(orbits.len(), 2);
    assert!(orbits
        .iter()
        .all(|o| o["points"].as_array().unwrap().len() <= 3));
    assert_eq!(
        v,
        json(&with(&args[..7], &["--orbits", "2", "--crossings", "3"]))
    );
    // h_max: no recorded step longer.
    let v = json(&[
        "simulate",
        TOP,
        "--omega",
        "0,0.3,5",
        "--gamma",
        "0.6,0,0.8",
        "--t-end",
        "1",
        "--opt",
        "h_max=0.05",
        "--json",
    ]);
    let t: Vec<f64> = v["t"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!(t.windows(2).all(|w| w[1] - w[0] <= 0.05 + 1e-12), "{t:?}");
}

/// `--opt method=Taylor`: the simulation by Taylor's method ends where DOP853's does (the
/// asymmetric top, both at their default tolerances, t = 20), with its own step count.
#[test]
fn opt_chooses_taylors_method() {
    let run = |extra: &[&str]| {
        let mut args = vec![
            "simulate",
            ASYMMETRIC,
            "--omega",
            "0.3,0.2,1.5",
            "--gamma",
            "0.6,0,0.8",
            "--t-end",
            "20",
            "--json",
        ];
        args.extend(extra);
        json(&args)
    };
    let (dop, taylor) = (run(&[]), run(&["--opt", "method=Taylor"]));
    let last = |v: &Value, key: &str| -> Vec<f64> {
        let rows = v[key].as_array().unwrap();
        rows[rows.len() - 1]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    for key in ["omega", "gamma"] {
        let (a, b) = (last(&dop, key), last(&taylor, key));
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() < 1e-7, "{key}: {a:?} vs {b:?}");
        }
    }
    assert_ne!(
        dop["t"].as_array().unwrap().len(),
        taylor["t"].as_array().unwrap().len(),
        "two methods, two meshes"
    );
}

#[test]
fn an_unknown_key_is_bad_input_naming_the_valid_ones() {
    bad_input(
        &family(&["--opt", "max_orbit=3"]),
        &[
            "unknown option `max_orbit`",
            "did you mean `max_orbits`",
            "newton_tol",
            "max_period_ratio",
        ],
    );
    // The chart sets its families' energy bounds itself.
    bad_input(
        &[
            "orbit-chart",
            SWINGING,
            "--parameter",
            "mgl=1..2",
            "--excess-energy",
            "0..1",
            "--gamma",
            "0,0,-1",
            "--opt",
            "energy_bounds=[0, 1]",
        ],
        &["unknown option `energy_bounds`", "join_tol", "max_orbits"],
    );
    bad_input(
        &family(&["--opt", "max_orbits=many"]),
        &["option `max_orbits`", "invalid type: string \"many\""],
    );
    bad_input(&family(&["--opt", "max_orbits"]), &["KEY=VALUE"]);
    bad_input(
        &["diagram", TOP, "-p", "0..5", "--opt", "nonlinear=maybe"],
        &["option `nonlinear`"],
    );
}

#[test]
fn opt_nonlinear_of_a_diagram_is_the_flag() {
    let by_opt = ok(&[
        "diagram",
        TOP,
        "-p",
        "1..3",
        "--opt",
        "nonlinear=true",
        "--json",
    ]);
    let by_flag = ok(&["diagram", TOP, "-p", "1..3", "--nonlinear", "--json"]);
    assert_eq!(by_opt, by_flag);
}
