//! The `routh` binary run as a user would, its numbers checked against closed forms of the
//! Lagrange top (A₁ = 1, C = 1.25, mgl = 1 in examples/models/heavy_top.toml).

mod common;

use common::{routh, stderr, stdout, ASYMMETRIC, TOP};
use std::process::Output;

fn json(o: &Output) -> serde_json::Value {
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(o));
    serde_json::from_slice(&o.stdout).expect("valid JSON")
}

/// A bad input: exit code 2 and a message on stderr containing `needle`, no panic.
fn rejects(args: &[&str], needle: &str) {
    let o = routh(args);
    assert_eq!(o.status.code(), Some(2), "{args:?}: stderr {}", stderr(&o));
    assert!(
        stderr(&o).contains(needle),
        "{args:?}: stderr {:?} lacks {needle:?}",
        stderr(&o)
    );
    assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
}

#[test]
fn steady_json_matches_closed_forms_of_the_lagrange_top() {
    // With I(γ₃) = A₁ + (C − A₁)γ₃²: ψ̇ = p/I, U_r = mgl γ₃ + p²/(2I) (40); the two vertical
    // motions γ = ±e₃, and the tilted family where ∂U_r/∂γ ∥ γ: p²(C − A₁)γ₃ = mgl I².
    let v = json(&routh(&["steady", TOP, "--momentum", "3", "--json"]));
    let motions = v.as_array().expect("an array");
    assert_eq!(motions.len(), 3);
    let (a1, c, mgl, p) = (1.0, 1.25, 1.0, 3.0);
    let mut vertical = 0;
    for m in motions {
        let g3 = m["gamma"][2].as_f64().unwrap();
        let inertia = a1 + (c - a1) * g3 * g3;
        let psi_dot = m["psi_dot"].as_f64().unwrap();
        assert!((psi_dot - p / inertia).abs() < 1e-9, "ψ̇ = p/I");
        let u_r = m["amended_potential"].as_f64().unwrap();
        assert!(
            (u_r - (mgl * g3 + 0.5 * p * p / inertia)).abs() < 1e-9,
            "U_r (40)"
        );
        if (g3.abs() - 1.0).abs() < 1e-9 {
            vertical += 1;
        } else {
            let lhs = p * p * (c - a1) * g3;
            assert!((lhs - mgl * inertia * inertia).abs() < 1e-8, "tilted: {g3}");
        }
    }
    assert_eq!(vertical, 2);
}

#[test]
fn steady_table_and_csv() {
    let o = routh(&["steady", TOP, "--momentum", "3"]);
    assert_eq!(o.status.code(), Some(0));
    let text = stdout(&o);
    assert!(
        text.starts_with("3 steady motion(s) at p_psi = 3"),
        "{text}"
    );
    assert!(text.contains("psi_dot"));
    let csv = stdout(&routh(&["steady", TOP, "--momentum", "3", "--csv"]));
    assert_eq!(csv.lines().count(), 4, "{csv}");
    let row: Vec<f64> = csv
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|f| f.parse().unwrap())
        .collect();
    assert_eq!(row.len(), 8);
    assert_eq!(row[0], 3.0);
}

#[test]
fn classify_verdicts_follow_maievskii_and_the_secular_bound() {
    // The upright top (γ = +e₃) is unstable below p = 2 (p² = 4A₁mgl), gyroscopically
    // stabilised between 2 and 2.5 (p² = mglC²/(C − A₁)), secularly stable above.
    for (p, verdict) in [
        ("1.5", "Unstable"),
        ("2.25", "GyroscopicallyStabilized"),
        ("3", "SecularlyStable"),
    ] {
        let v = json(&routh(&["classify", TOP, "--momentum", p, "--json"]));
        let up = v
            .as_array()
            .unwrap()
            .iter()
            .find(|c| (c["motion"]["gamma"][2].as_f64().unwrap() - 1.0).abs() < 1e-9)
            .expect("the upright motion");
        assert_eq!(up["report"]["verdict"], verdict, "p = {p}");
        assert_eq!(up["p_psi"].as_f64(), Some(p.parse().unwrap()));
    }
    let o = routh(&["classify", TOP, "-p", "3"]);
    assert!(stdout(&o).contains("secularly stable"), "{}", stdout(&o));
}

#[test]
fn classify_with_an_axis_decides_the_circle_of_the_lagrange_top() {
    // At p = 3 the tilted steady motions of the top form a circle about e₃: `classify` alone
    // says degenerate (with one negative eigenvalue), modulo the symmetry it is stable.
    let v = json(&routh(&[
        "classify", TOP, "-p", "3", "--axis", "0,0,1", "--json",
    ]));
    let rows = v.as_array().unwrap();
    let circle = rows
        .iter()
        .find(|c| c["motion"]["isolated"] == false)
        .expect("the circle");
    assert_eq!(circle["report"]["verdict"], "Degenerate");
    assert_eq!(circle["circle"]["verdict"], "Stable");
    assert!(circle["circle"]["curvature"].as_f64().unwrap() > 0.0);
    assert!(rows
        .iter()
        .filter(|c| c["motion"]["isolated"] == true)
        .all(|c| c.get("circle").is_none()));
    let o = routh(&["classify", TOP, "-p", "3", "--axis", "0,0,1"]);
    assert!(
        stdout(&o).contains("stable modulo the symmetry"),
        "{}",
        stdout(&o)
    );
    // The axis at any scale is the same axis.
    for axis in ["0,0,1e160", "0,0,1e-200", "0,0,1e-310"] {
        let w = json(&routh(&[
            "classify", TOP, "-p", "3", "--axis", axis, "--json",
        ]));
        assert_eq!(w, v, "--axis {axis}");
    }
    // e₁ is not an axis of symmetry of the top: an error, not a verdict.
    let o = routh(&["classify", TOP, "-p", "3", "--axis", "1,0,0"]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("not symmetric about the axis"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn diagram_over_momentum_finds_the_two_classical_bounds() {
    let dir = std::env::temp_dir().join(format!("routh-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("d.svg");
    let svg_arg = svg.to_str().unwrap();
    let v = json(&routh(&[
        "diagram",
        TOP,
        "--momentum",
        "0..5",
        "--json",
        "--svg",
        svg_arg,
    ]));
    let events = v["events"].as_array().unwrap();
    let at = |kind: &str| {
        events
            .iter()
            .find(|e| e["kind"] == kind)
            .and_then(|e| e["s"].as_f64())
            .unwrap_or_else(|| panic!("no {kind} event in {events:?}"))
    };
    let (a1, c, mgl) = (1.0f64, 1.25f64, 1.0f64);
    // Maievskii: p² = 4A₁mgl; the secular bound: p² = mglC²/(C − A₁).
    assert!((at("HamiltonianHopf") - (4.0 * a1 * mgl).sqrt()).abs() < 1e-6);
    assert!((at("BranchPoint") - (mgl * c * c / (c - a1)).sqrt()).abs() < 1e-6);
    let figure = std::fs::read_to_string(&svg).expect("the SVG was written");
    assert!(figure.contains("<svg"));
    std::fs::remove_dir_all(&dir).ok();

    let table = stdout(&routh(&["diagram", TOP, "--momentum", "0..5"]));
    assert!(table.contains("Hamiltonian–Hopf  2.000000"), "{table}");
    assert!(table.contains("branch point      2.500000"), "{table}");
    let em = std::env::temp_dir().join(format!("routh-cli-em-{}.svg", std::process::id()));
    let em_arg = em.to_str().unwrap();
    let o = routh(&[
        "diagram",
        TOP,
        "-p",
        "0..5",
        "--energy-momentum-svg",
        em_arg,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&em).unwrap().contains("p_ψ"));
    std::fs::remove_file(&em).ok();
    rejects(
        &[
            "diagram",
            TOP,
            "--parameter",
            "c=1..2",
            "-p",
            "3",
            "--energy-momentum-svg",
            em_arg,
        ],
        "cannot be used with",
    );
    let csv = stdout(&routh(&["diagram", TOP, "--momentum", "0..5", "--csv"]));
    assert!(csv.lines().count() > 50, "{csv}");
}

/// A diagram over a range a few ulps wide has one branch per steady motion, not three (one per
/// seed).
#[test]
fn a_diagram_over_a_tiny_range_has_each_branch_once() {
    let steady = json(&routh(&["steady", TOP, "-p", "1.9", "--json"]));
    let n = steady.as_array().unwrap().len();
    let v = json(&routh(&[
        "diagram",
        TOP,
        "--momentum",
        "1.9..1.900000000000001",
        "--json",
    ]));
    let branches = v["branches"].as_array().unwrap();
    assert!(n >= 2, "{steady}");
    assert_eq!(branches.len(), n, "{v}");
}

#[test]
fn diagram_over_a_parameter() {
    // At p = 3 the secular bound p² = mglC²/(C − A₁) in C (A₁ = mgl = 1): C² − 9C + 9 = 0,
    // C = (9 − √45)/2 ≈ 1.1459 in 1.05..1.6 (the other root, 7.85, is outside).
    let v = json(&routh(&[
        "diagram",
        TOP,
        "--parameter",
        "c=1.05..1.6",
        "--momentum",
        "3",
        "--json",
    ]));
    let bp: Vec<f64> = v["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "BranchPoint")
        .map(|e| e["s"].as_f64().unwrap())
        .collect();
    let expected = (9.0 - 45f64.sqrt()) / 2.0;
    assert!(
        bp.iter().any(|s| (s - expected).abs() < 1e-6),
        "{bp:?} vs {expected}"
    );
}

#[test]
fn formulas_give_the_amended_potential_of_the_model() {
    let v = json(&routh(&["formulas", TOP, "--json"]));
    let u = v["amended_potential"].as_str().unwrap();
    assert!(u.contains("p_ψ") && u.contains("γ₃"), "{u}");
}

/// `formulas --latex` prints the seven formulas of `Model::latex` of the same file, each named;
/// `--latex --json` is the `LatexFormulas` object. The amended potential of the Lagrange top
/// must be `mgl γ₃ + ½(p_ψ − …)²/…` with the parameters' symbols, not an empty or elided form.
#[test]
fn formulas_latex_prints_the_seven_formulas_of_the_model() {
    let model = routh::Model::from_file(TOP).unwrap();
    let expected = model.latex();
    let v = json(&routh(&["formulas", TOP, "--latex", "--json"]));
    let back: routh::LatexFormulas = serde_json::from_value(v).unwrap();
    assert_eq!(back, expected);
    let o = routh(&["formulas", TOP, "--latex"]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let text = stdout(&o);
    for (name, lhs, formula) in [
        ("lagrangian", "L(\\omega, \\gamma) = ", &expected.lagrangian),
        (
            "psi_dot",
            "\\dot\\psi(\\Omega, \\gamma, p_\\psi) = ",
            &expected.psi_dot,
        ),
        (
            "routhian",
            "R(\\Omega, \\gamma, p_\\psi) = ",
            &expected.routhian,
        ),
        (
            "amended_potential",
            "U_r(\\gamma, p_\\psi) = ",
            &expected.amended_potential,
        ),
        ("a", "A = ", &expected.a),
        ("g", "G = ", &expected.g),
        ("c", "C = ", &expected.c),
    ] {
        assert!(
            !formula.is_empty() && !formula.contains("not printed"),
            "{name}: {formula}"
        );
        // A display block (`align*`) each, the formula on the line `lhs &= …`.
        let line = format!("\n{} &= ", lhs.trim_end_matches(" = "));
        assert!(
            text.contains(&format!("% {name}: ")),
            "{name} not named in\n{text}"
        );
        assert!(text.contains(&line), "{line} not in\n{text}");
    }
    assert_eq!(text, expected.display());
    assert_eq!(text.matches("\\begin{align*}").count(), 7);
    assert!(expected.amended_potential.contains("p_\\psi"));
    assert!(expected.a.contains("pmatrix") && expected.c.contains("pmatrix"));
    // `--document`: the whole document, titled by the file's name.
    let o = routh(&["formulas", TOP, "--latex", "--document"]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let stem = std::path::Path::new(TOP)
        .file_stem()
        .unwrap()
        .to_string_lossy();
    let doc = stdout(&o);
    assert_eq!(
        doc,
        expected.document(&format!("Derived formulas of {stem}"))
    );
    assert!(doc.starts_with("\\documentclass{article}") && doc.ends_with("\\end{document}\n"));
}

/// `formulas --sympy` prints the seven formulas of `Model::sympy` of the same file as
/// `name = formula` lines, after a `Symbol` line for every symbol; `--sympy --json` is the
/// `SympyFormulas` object. The heavy top has parameters `g` and `c`: G and C are printed as `g_`
/// and `c_`, so that no line rebinds a symbol (G's line rebound the `g` that C uses). (That the script runs and agrees with the model,
/// also for parameters named `lambda`, `sin`, `nan`, is routh-py's tests/test_formulas.py and
/// tests/test_hostile_formulas.py.)
#[test]
fn formulas_sympy_prints_the_seven_formulas_of_the_model() {
    let model = routh::Model::from_file(TOP).unwrap();
    let expected = model.sympy();
    let v = json(&routh(&["formulas", TOP, "--sympy", "--json"]));
    let back: routh::SympyFormulas = serde_json::from_value(v).unwrap();
    assert_eq!(back, expected);
    let o = routh(&["formulas", TOP, "--sympy"]);
    assert_eq!(o.status.code(), Some(0), "stderr: {}", stderr(&o));
    let text = stdout(&o);
    for (name, formula) in [
        ("lagrangian", &expected.lagrangian),
        ("psi_dot", &expected.psi_dot),
        ("routhian", &expected.routhian),
        ("amended_potential", &expected.amended_potential),
        ("a", &expected.a),
        ("g_", &expected.g),
        ("c_", &expected.c),
    ] {
        let line = format!("{name} = {formula}\n");
        assert!(text.contains(&line), "{line} not in\n{text}");
    }
    assert!(text.starts_with("from sympy import *\n"));
    for (ident, name) in &expected.symbols {
        let line = format!("{ident} = Symbol(\"{name}\", real=True)\n");
        assert!(text.contains(&line), "{line} not in\n{text}");
    }
    assert!(expected.symbols.iter().any(|(i, _)| i == "g"));
    assert!(expected.symbols.iter().any(|(i, _)| i == "c"));
    assert!(expected.amended_potential.contains("p_psi"));
    assert!(!expected.amended_potential.contains('\\'));
    assert!(expected.c.starts_with("Matrix([["));
}

#[test]
fn bad_input_exits_with_code_2_and_names_the_problem() {
    rejects(
        &["steady", "no/such/model.toml", "-p", "1"],
        "no/such/model.toml",
    );
    rejects(&["steady", TOP], "--momentum");
    rejects(&["steady", TOP, "-p", "NaN"], "not a finite number");
    rejects(&["steady", TOP, "-p", "x"], "not a number");
    rejects(&["diagram", TOP, "--momentum", "5..0"], "inverted");
    rejects(
        &["diagram", TOP, "--momentum", "0..inf"],
        "not a finite number",
    );
    rejects(&["diagram", TOP, "--momentum", "3"], "not a range");
    // `0...1` is not 0..0.1; negative numbers reach the value's own check (not
    // clap's tip about `--`); a relative tolerance above 1 is refused.
    rejects(&["diagram", TOP, "--momentum", "0...1"], "two dots");
    let sim = ["simulate", TOP, "--omega", "0,0,1", "--gamma", "0,0,1"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        sim.iter().chain(extra).copied().collect()
    };
    rejects(&with(&["--t-end", "-1"]), "`-1` must be above 0");
    rejects(
        &with(&["--t-end", "1", "--rtol", "2"]),
        "not a relative tolerance",
    );
    rejects(
        &with(&["--t-end", "1", "--atol", "-1e-9"]),
        "`-1e-9` must be above 0",
    );
    // A NaN or infinite parameter in the model file: exit code 2, naming it.
    let bad = std::env::temp_dir().join(format!("routh-cli-nan-{}.toml", std::process::id()));
    let src = std::fs::read_to_string(TOP).unwrap();
    let line = src
        .lines()
        .find(|l| l.trim_start().starts_with("mass"))
        .expect("a mass parameter")
        .to_string();
    std::fs::write(&bad, src.replace(&line, "mass = nan")).unwrap();
    rejects(
        &["steady", bad.to_str().unwrap(), "-p", "1"],
        "parameter `mass` is NaN",
    );
    std::fs::remove_file(&bad).ok();
    rejects(
        &[
            "diagram",
            TOP,
            "--parameter",
            "nope=1..2",
            "--momentum",
            "3",
        ],
        "unknown parameter `nope`",
    );
    rejects(
        &["diagram", TOP, "--parameter", "c=2..1", "--momentum", "3"],
        "inverted",
    );
    rejects(&["frobnicate", TOP], "frobnicate");
    let gyrostat = TOP.replace("heavy_top", "gyrostat");
    rejects(
        &[
            "diagram",
            &gyrostat,
            "--parameter",
            "com=0..1",
            "--momentum",
            "1",
        ],
        "parameter `com` is a Vector3<f64>, not a f64",
    );
    // Model files with errors: the message carries the position.
    let dir = std::env::temp_dir().join(format!("routh-cli-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    let bad_arg = bad.to_str().unwrap();
    std::fs::write(
        &bad,
        "[model]\nlagrangian = \"kinetic = 0.5 * a1 * omega.x * omega.x + zz, potential = gamma.z\"\n[parameters]\na1 = 1.0\n",
    )
    .unwrap();
    rejects(&["steady", bad_arg, "-p", "1"], "unknown name `zz`");
    rejects(
        &["steady", bad_arg, "-p", "1"],
        "bad.toml: line 2, column 56",
    );
    std::fs::write(&bad, "[model\n").unwrap();
    rejects(&["classify", bad_arg, "-p", "1"], "line");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn atlas_boundaries_are_the_classical_curves() {
    // Over (mgl, p): Maievskii's p² = 4A₁mgl and the secular bound p² = mglC²/(C − A₁)
    // = 6.25 mgl (A₁ = 1, C = 1.25).
    let dir = std::env::temp_dir().join(format!("routh-cli-atlas-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("a.svg");
    let v = json(&routh(&[
        "atlas",
        TOP,
        "--x",
        "mass=0.5..1.5",
        "--y",
        "momentum=0..5",
        "--gamma",
        "0,0,1",
        "--nx",
        "11",
        "--ny",
        "11",
        "--json",
        "--svg",
        svg.to_str().unwrap(),
    ]));
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    std::fs::remove_dir_all(&dir).ok();
    let curves = v["boundaries"].as_array().unwrap();
    for (kind, factor) in [("HamiltonianHopf", 4.0), ("BranchPoint", 6.25)] {
        let c = curves
            .iter()
            .find(|c| c["kind"] == kind)
            .unwrap_or_else(|| panic!("no {kind} curve"));
        let points = c["points"].as_array().unwrap();
        assert!(points.len() > 5);
        for p in points {
            let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
            assert!((y * y - factor * x).abs() < 1e-4, "{kind}: ({x}, {y})");
        }
    }
}

#[test]
fn simulate_keeps_the_invariants_of_the_lagrange_top() {
    let g3 = (1.0f64 - 0.01).sqrt();
    let gamma = format!("0,0.1,{g3}");
    let v = json(&routh(&[
        "simulate", TOP, "--omega", "0,0,5", "--gamma", &gamma, "--t-end", "10", "--json",
    ]));
    let t = v["t"].as_array().unwrap();
    assert_eq!(t.last().and_then(|t| t.as_f64()), Some(10.0));
    // Euler's third equation: ω₃ constant; E = ½Cω₃² + mgl γ₃ and p_ψ = Cω₃γ₃ at the start.
    for w in v["omega"].as_array().unwrap() {
        assert!((w[2].as_f64().unwrap() - 5.0).abs() < 1e-9);
    }
    let e0 = 0.5 * 1.25 * 25.0 + g3;
    for e in v["energy"].as_array().unwrap() {
        assert!((e.as_f64().unwrap() - e0).abs() < 1e-8);
    }
    let p0 = 1.25 * 5.0 * g3;
    assert!((v["p_psi"][0].as_f64().unwrap() - p0).abs() < 1e-12);

    // The reduced equations at p = 3 started at rest on the upright steady motion stay there.
    let o = routh(&[
        "simulate",
        TOP,
        "--omega",
        "0,0,0",
        "--gamma",
        "0,0,1",
        "--t-end",
        "5",
        "--reduced",
        "--momentum",
        "3",
        "--csv",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let csv = stdout(&o);
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let col = header
        .iter()
        .position(|h| *h == "psi_dot")
        .expect("psi_dot column");
    for line in csv.lines().skip(1) {
        let psi_dot: f64 = line.split(',').nth(col).unwrap().parse().unwrap();
        assert!((psi_dot - 3.0 / 1.25).abs() < 1e-9, "ψ̇ = p/C");
    }

    rejects(
        &[
            "simulate", TOP, "--omega", "0,0,5", "--gamma", "0,0,2", "--t-end", "1",
        ],
        "unit vector",
    );
    rejects(
        &[
            "simulate", TOP, "--omega", "0,5", "--gamma", "0,0,1", "--t-end", "1",
        ],
        "X,Y,Z",
    );
    rejects(
        &[
            "simulate",
            TOP,
            "--omega",
            "0,0,5",
            "--gamma",
            "0,0,1",
            "--t-end",
            "1",
            "--reduced",
        ],
        "--momentum",
    );
}

#[test]
fn certify_proves_the_two_vertical_motions_alone_below_the_family() {
    // At p = 1.5 the tilted family does not exist (p²(C − A₁)γ₃ < mgl(A₁ + (C − A₁)γ₃²)² on
    // [−1, 1]): the steady motions are exactly γ = ±e₃.
    let v = json(&routh(&["certify", TOP, "--momentum", "1.5", "--json"]));
    assert_eq!(v["complete"], true, "{v}");
    let motions = v["motions"].as_array().unwrap();
    assert_eq!(motions.len(), 2);
    for m in motions {
        assert!((m["gamma"][2].as_f64().unwrap().abs() - 1.0).abs() < 1e-9);
    }
}

#[test]
fn atlas_bad_axes_are_bad_input() {
    let base = ["atlas", TOP, "--gamma", "0,0,1"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> { [&base[..], extra].concat() };
    rejects(
        &with(&["--x", "mass=0.5..1.5", "--y", "momentum=0..5", "-p", "1"]),
        "already `momentum`",
    );
    rejects(
        &with(&["--x", "mass=0.5..1.5", "--y", "c=1..2"]),
        "--momentum P",
    );
    rejects(
        &with(&["--x", "zz=0.5..1.5", "--y", "momentum=0..5"]),
        "unknown parameter `zz`",
    );
    rejects(
        &with(&["--x", "mass=1.5..0.5", "--y", "momentum=0..5"]),
        "inverted",
    );
    rejects(
        &with(&["--x", "mass=0.5..1.5", "--y", "momentum=0..5", "--nx", "1"]),
        "--nx",
    );
}

#[test]
fn an_unwritable_figure_is_a_failed_run_exit_code_1() {
    let o = routh(&[
        "diagram",
        TOP,
        "--momentum",
        "0..5",
        "--svg",
        "/nonexistent-dir/routh/d.svg",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("cannot write /nonexistent-dir/routh/d.svg"),
        "{}",
        stderr(&o)
    );
}

/// A run that fails while writing its figures (the second cannot be written) leaves the first
/// figure's old file byte-identical and no temporary file beside it: all or none.
#[test]
fn a_run_that_fails_while_writing_leaves_the_old_files_as_they_were() {
    let dir = std::env::temp_dir().join(format!("routh-cli-keep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let old = dir.join("old.svg");
    let before = b"<svg>the figure of yesterday</svg>\n".to_vec();
    std::fs::write(&old, &before).unwrap();
    let o = routh(&[
        "diagram",
        TOP,
        "--momentum",
        "0..5",
        "--svg",
        old.to_str().unwrap(),
        "--energy-momentum-svg",
        "/nonexistent-dir/routh/em.svg",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("/nonexistent-dir/routh/em.svg"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        std::fs::read(&old).unwrap(),
        before,
        "the old figure was changed"
    );
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(
        left,
        vec![std::ffi::OsString::from("old.svg")],
        "temporaries left"
    );
    // A target that is a directory: the figure is drawn to a temporary, the rename fails, the
    // directory is untouched and named.
    let o = routh(&[
        "atlas",
        TOP,
        "--x",
        "mass=0.5..1.5",
        "--y",
        "momentum=0..5",
        "--nx",
        "3",
        "--ny",
        "3",
        "--gamma",
        "0,0,1",
        "--svg",
        dir.to_str().unwrap(),
    ]);
    assert_ne!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains(dir.to_str().unwrap()), "{}", stderr(&o));
    assert_eq!(std::fs::read(&old).unwrap(), before);
    std::fs::remove_dir_all(&dir).ok();
}

/// Arnold's determinant D of the upright Lagrange top A₁ = 1, C = 1.25, mgl = 1 at momentum
/// `p`, from the normal form derived by hand in docs/method.md §10.8.
fn arnold_determinant_by_hand(p: f64) -> f64 {
    test_models::birkhoff::sleeping_top_normal_form(1.0, 1.25, 1.0, p).arnold_determinant
}

#[test]
fn nonlinear_verdicts_and_arnold_determinant_of_the_upright_top() {
    // Gyroscopically stabilised at p = 2.25 (2 < p < 2.5) with D > 0 and no resonance of order
    // ≤ 4 (ω₁/ω₂ ≈ 7.5): Lyapunov stable by Arnold–Moser; secularly stable at p = 3.
    for (p, verdict) in [(2.25, "LyapunovStable"), (3.0, "SecularlyStable")] {
        let v = json(&routh(&[
            "nonlinear",
            TOP,
            "--momentum",
            &p.to_string(),
            "--json",
        ]));
        let up = v
            .as_array()
            .unwrap()
            .iter()
            .find(|c| (c["motion"]["gamma"][2].as_f64().unwrap() - 1.0).abs() < 1e-9)
            .expect("the upright motion");
        assert_eq!(up["report"]["verdict"], verdict, "p = {p}: {up}");
        if p == 2.25 {
            let d = up["report"]["arnold_determinant"].as_f64().unwrap();
            let hand = arnold_determinant_by_hand(p);
            assert!(
                (d - hand).abs() <= 1e-8 * hand.abs(),
                "D = {d}, by hand {hand}"
            );
        }
    }
    let o = routh(&["nonlinear", TOP, "-p", "2.25", "--csv"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("p_psi,gamma1"), "{}", stdout(&o));
    assert!(stdout(&o).contains("lyapunov_stable"), "{}", stdout(&o));
}

#[test]
fn diagram_nonlinear_locates_arnolds_degenerate_point() {
    // D of the upright top changes sign once in (2.4, 2.45) (method.md §10.8): bisect the hand
    // formula, and find the same point as an ArnoldDegenerate event of `diagram --nonlinear`.
    let (mut lo, mut hi) = (2.4f64, 2.45f64);
    assert!(arnold_determinant_by_hand(lo) > 0.0 && arnold_determinant_by_hand(hi) < 0.0);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if arnold_determinant_by_hand(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let plain = json(&routh(&[
        "diagram",
        TOP,
        "--momentum",
        "2.2..2.48",
        "--json",
    ]));
    let v = json(&routh(&[
        "diagram",
        TOP,
        "--momentum",
        "2.2..2.48",
        "--nonlinear",
        "--json",
    ]));
    let kinds = |v: &serde_json::Value| -> Vec<String> {
        v["events"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["kind"].as_str().unwrap().to_string())
            .collect()
    };
    assert!(!kinds(&plain).iter().any(|k| k == "ArnoldDegenerate"));
    let found: Vec<f64> = v["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "ArnoldDegenerate")
        .map(|e| e["s"].as_f64().unwrap())
        .collect();
    assert_eq!(found.len(), 1, "{:?}", kinds(&v));
    assert!(
        (found[0] - lo).abs() < 1e-8,
        "D = 0 at {} by hand, {} found",
        lo,
        found[0]
    );
    let table = stdout(&routh(&["diagram", TOP, "-p", "2.2..2.48", "--nonlinear"]));
    assert!(table.contains("Lyapunov stable -> "), "{table}");
}

const RESONANT: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/models/resonant_body.toml"
);

#[test]
fn orbits_follow_the_swings_and_name_their_events() {
    // The hanging position of the asymmetric top (centre of mass at m g c = (0.4, 0.3, 1.5)):
    // γ = −c/|c|. Its mode-0 swings have two period doublings (k = −1) and a branch point.
    let v = json(&routh(&[
        "orbits",
        ASYMMETRIC,
        "--momentum",
        "0",
        "--mode",
        "0",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "40",
        "--json",
    ]));
    let families = v.as_array().expect("an array");
    assert_eq!(families.len(), 1);
    let f = &families[0];
    let g = &f["motion"]["gamma"];
    let c = (0.16f64 + 0.09 + 2.25).sqrt();
    for (i, ci) in [0.4, 0.3, 1.5].iter().enumerate() {
        assert!((g[i].as_f64().unwrap() + ci / c).abs() < 1e-9);
    }
    let orbits = f["orbits"].as_array().unwrap();
    assert_eq!(orbits.len(), 40);
    let events = f["events"].as_array().unwrap();
    let doublings: Vec<f64> = f["events"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|e| e["kind"] == "PeriodDoubling")
        .map(|e| e["orbit"]["stability_index"].as_f64().unwrap())
        .collect();
    assert_eq!(doublings.len(), 2, "{}", f["events"]);
    assert!(doublings.iter().all(|k| (k + 1.0).abs() < 1e-6));
    // CSV: a header, one row per orbit, then one per event; the table names the events.
    let o = routh(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "40",
        "--csv",
    ]);
    assert_eq!(stdout(&o).lines().count(), 1 + 40 + events.len());
    let o = routh(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "0",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "40",
    ]);
    assert!(
        stdout(&o).contains("period_doubling at E = "),
        "{}",
        stdout(&o)
    );
}

#[test]
fn orbits_refuse_a_resonant_start_and_draw_one_family() {
    // A body J = diag(1, 4, 4.5) hanging at p_ψ = 0 has the frequencies √(mgl/J₁) = 1 and
    // √(mgl/J₂) = 1/2: a 1:2 resonance, so mode 1 starts no family; the upright body is
    // unstable.
    let o = routh(&["orbits", RESONANT, "--momentum", "0", "--max-orbits", "3"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("1 Lyapunov family"), "{out}");
    assert!(
        out.contains("mode 1: invalid option mode: resonant start"),
        "{out}"
    );
    assert!(out.contains("unstable: no Lyapunov family"), "{out}");
    // The hanging Lagrange top at p_ψ = 0 has two equal frequencies √(mgl/A₁), and one family
    // of small orbits, its planar swings (mode 0): degenerate (not isolated on their energy
    // level, k = 1), with their turn about the axis.
    let o = routh(&["orbits", TOP, "--momentum", "0", "--max-orbits", "5"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("1 Lyapunov family"), "{out}");
    assert!(out.contains("body_turn"), "{out}");
    assert_eq!(out.matches("parabolic (degenerate)").count(), 5, "{out}");
    assert!(
        out.contains("mode 1: invalid option mode: an axially symmetric body"),
        "{out}"
    );
    assert!(out.contains("unstable: no Lyapunov family"), "{out}");
    // --svg needs one family.
    let dir = std::env::temp_dir().join(format!("routh-cli-orbits-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("k.svg");
    rejects(
        &[
            "orbits",
            ASYMMETRIC,
            "-p",
            "0",
            "--max-orbits",
            "5",
            "--svg",
            svg.to_str().unwrap(),
        ],
        "draw one family",
    );
    assert!(!svg.exists());
    let o = routh(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "1",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "8",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("<svg") && text.contains("k = ±1"),
        "{}",
        &text[..200.min(text.len())]
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn section_prints_crossings_on_the_energy_level() {
    let o = routh(&[
        "section",
        ASYMMETRIC,
        "--momentum",
        "0",
        "--energy",
        "-1",
        "--orbits",
        "5",
        "--crossings",
        "20",
        "--csv",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some("orbit,theta,m_n"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert!(!rows.is_empty() && rows.len() <= 100);
    assert!(rows
        .iter()
        .all(|r| r[1].abs() <= std::f64::consts::PI && r[2].is_finite()));
    // Below the least energy of the level there is nothing to cut: bad input, named.
    let o = routh(&["section", ASYMMETRIC, "-p", "0", "-e", "-5"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("no motion"), "{}", stderr(&o));
}
