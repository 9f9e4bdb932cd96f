//! Mutated model texts: tokens and characters deleted, inserted and replaced,
//! unicode, huge numbers, NaN and infinite parameters. `Model::new` and `Model::from_toml` must
//! never panic, and every error must point inside the text (its line exists, its column is on
//! the line or just past its end); a model that builds must evaluate without panicking.

use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_core::{Lagrangian, Routhian};
use routh_runtime::{Model, ModelError, Param};
use std::panic::{catch_unwind, AssertUnwindSafe};

const TEXTS: [&str; 3] = [
    "kinetic = 0.5 * omega.dot(diag(inertia) * omega),\npotential = mass * g * com.dot(gamma)",
    "kinetic = 0.5 * omega.dot(inertia * omega),\nlinear = (rotor + coupling * gamma).dot(omega),\npotential = mass * g * com.dot(gamma),",
    "let c3 = gamma.dot(diag(axes) * gamma).sqrt(),\nlet n = grad(c3, gamma),\nkinetic = 0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),\npotential = mass * g * c3.abs().ln() + com.norm() * gamma.x.sin(),",
];

/// Pieces inserted: tokens of the language, other Rust tokens, unicode, odd numbers.
const PIECES: [&str; 40] = [
    "omega",
    "gamma",
    "mass",
    "inertia",
    "com",
    "rotor",
    "coupling",
    "axes",
    "g",
    "let",
    "kinetic",
    "potential",
    "linear",
    "=",
    ",",
    "*",
    "+",
    "-",
    "/",
    "(",
    ")",
    "[",
    "]",
    ".",
    "dot",
    "cross",
    "powi(3)",
    "sqrt()",
    "diag",
    "grad",
    "1e308",
    "1e-320",
    "NaN",
    "0x1F",
    "\"s\"",
    "'c'",
    "é",
    "γ",
    "🦀",
    "\u{202e}",
];

fn check_position(e: &ModelError, text: &str, what: &str) {
    let lines: Vec<&str> = text.split('\n').collect();
    assert!(
        (1..=lines.len()).contains(&e.line),
        "{what}: line {} outside 1..={} in\n{text}\n{e}",
        e.line,
        lines.len()
    );
    let len = lines[e.line - 1].trim_end_matches('\r').chars().count();
    assert!(
        (1..=len + 1).contains(&e.column),
        "{what}: column {} outside 1..={} of line {} in\n{text}\n{e}",
        e.column,
        len + 1,
        e.line
    );
    for o in &e.others {
        check_position(o, text, what);
    }
}

/// Splits at char boundaries.
fn char_positions(s: &str) -> Vec<usize> {
    s.char_indices().map(|(i, _)| i).chain([s.len()]).collect()
}

fn mutate(rng: &mut ChaCha8Rng, text: &str) -> String {
    let mut s = text.to_string();
    for _ in 0..rng.gen_range(1..4) {
        let pos = char_positions(&s);
        let a = pos[rng.gen_range(0..pos.len())];
        let b = pos[rng.gen_range(0..pos.len())].max(a);
        let b = b.min(a + 12).min(s.len());
        let b = (b..=s.len())
            .find(|&i| s.is_char_boundary(i))
            .unwrap_or(s.len());
        let piece = PIECES[rng.gen_range(0..PIECES.len())];
        match rng.gen_range(0..6) {
            0 => s.replace_range(a..b, ""),
            1 => s.insert_str(a, piece),
            2 => s.replace_range(a..b, piece),
            3 => {
                // Replace a whole word by another.
                let words: Vec<String> = s.split_whitespace().map(str::to_string).collect();
                if !words.is_empty() {
                    let w = &words[rng.gen_range(0..words.len())];
                    s = s.replacen(w.as_str(), piece, 1);
                }
            }
            4 => {
                let c = char::from_u32(rng.gen_range(0..0x11000)).unwrap_or('¿');
                s.insert(a, c);
            }
            _ => {
                let n = [
                    "1e308",
                    "-1e308",
                    "1e400",
                    "123456789012345678901234567890",
                    "0.0",
                ];
                s.insert_str(a, n[rng.gen_range(0..n.len())]);
            }
        }
    }
    s
}

fn value(rng: &mut ChaCha8Rng) -> f64 {
    // NaN and infinities are refused (naming the parameter): rare, so that most cases build.
    if rng.gen_ratio(1, 128) {
        return [f64::NAN, f64::INFINITY][rng.gen_range(0..2)];
    }
    match rng.gen_range(2..8) {
        2 => 1e308,
        3 => -1e-320,
        4 => 0.0,
        _ => rng.gen_range(-3.0..3.0),
    }
}

fn params(rng: &mut ChaCha8Rng) -> Vec<(&'static str, Param)> {
    let mut v = |n: usize| -> Vec<f64> { (0..n).map(|_| value(rng)).collect() };
    let (a, b, c, d, e, f, g) = (v(3), v(3), v(9), v(3), v(3), v(1), v(1));
    let mut p: Vec<(&'static str, Param)> = vec![
        ("inertia", Param::from([a[0], a[1], a[2]])),
        ("rotor", Param::from([b[0], b[1], b[2]])),
        (
            "coupling",
            Param::Matrix(nalgebra::Matrix3::from_row_slice(&c)),
        ),
        ("com", Param::from([d[0], d[1], d[2]])),
        ("axes", Param::from([e[0], e[1], e[2]])),
        ("mass", Param::from(f[0])),
        ("g", Param::from(g[0])),
    ];
    // Sometimes a parameter is missing, of another shape, or given twice.
    match rng.gen_range(0..6) {
        0 => {
            p.remove(rng.gen_range(0..p.len()));
        }
        1 => {
            let k = rng.gen_range(0..p.len());
            p[k].1 = Param::from(1.0);
        }
        2 => p.push(("mass", Param::from(2.0))),
        _ => {}
    }
    p
}

/// Builds and, when it builds, evaluates every method once.
fn exercise(text: &str, params: &[(&str, Param)]) -> Result<(), ModelError> {
    let m = Model::new(text, params)?;
    let (w, g) = (Vector3::new(0.3, -0.2, 1.1), Vector3::new(0.0, 0.6, 0.8));
    let _ = m.bundle(&w, &g, 0.7);
    let _ = m.gyroscopic_system(&g, 0.7);
    let _ = m.full_equations(&w, &g);
    let _ = m.reduced_equations(&w, &g, 0.7);
    let _ = m.energy(&w, &g);
    let _ = m
        .certification_tape()
        .map(|t| t.eval(g.into(), 0.7, &mut Vec::new()));
    Ok(())
}

#[test]
fn mutated_texts_never_panic_and_errors_point_into_the_text() {
    let cases: usize = std::env::var("ROUTH_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(10_000);
    let mut rng = ChaCha8Rng::seed_from_u64(0x22);
    let (mut built, mut errors) = (0, 0);
    let start = std::time::Instant::now();
    for case in 0..cases {
        let base = TEXTS[case % TEXTS.len()];
        let text = if case % 10 == 0 {
            base.to_string()
        } else {
            mutate(&mut rng, base)
        };
        let p = params(&mut rng);
        let r = catch_unwind(AssertUnwindSafe(|| exercise(&text, &p)));
        match r {
            Err(_) => panic!("case {case} panicked on\n{text}\nwith {p:?}"),
            Ok(Ok(())) => built += 1,
            Ok(Err(e)) => {
                errors += 1;
                check_position(&e, &text, &format!("case {case}"));
                assert!(!e.message.is_empty());
            }
        }
    }
    println!(
        "fuzz: {cases} texts in {:.2?}: {built} built, {errors} errors",
        start.elapsed()
    );
    assert_eq!(built + errors, cases);
    assert!(
        built > cases / 25,
        "too few valid models ({built}) to exercise evaluation"
    );
}

#[test]
fn mutated_toml_never_panics_and_errors_point_into_the_file() {
    let src = r#"[model]
lagrangian = """
    kinetic = 0.5 * omega.dot(inertia * omega),
    potential = mass * g * com.dot(gamma),
"""
symmetric = ["inertia"]
[parameters]
inertia = [[2.0, 0.1, 0.0], [0.1, 2.5, 0.0], [0.0, 0.0, 3.0]]
com = [0.0, 0.0, 1.0]
mass = 1
g = 9.81
"#;
    let mut rng = ChaCha8Rng::seed_from_u64(0x7011);
    for case in 0..2_000 {
        let text = mutate(&mut rng, src);
        let r = catch_unwind(AssertUnwindSafe(|| Model::from_toml(&text)));
        match r {
            Err(_) => panic!("case {case} panicked on\n{text}"),
            Ok(Ok(_)) => {}
            Ok(Err(e)) => check_position(&e, &text, &format!("toml case {case}")),
        }
    }
}

/// A random scalar expression over γ and `mass` of about `budget` nodes, shaped at random:
/// long flat chains, deep nesting (brackets, method calls, signs) or a bushy tree.
fn expression(rng: &mut ChaCha8Rng, budget: usize, out: &mut String) {
    if budget <= 1 {
        let leaf = ["gamma.x", "gamma.y", "gamma.z", "mass", "1.5", "2"];
        out.push_str(leaf[rng.gen_range(0..leaf.len())]);
        return;
    }
    match rng.gen_range(0..6) {
        // A flat chain of binary operators (how generated models look).
        0 => {
            let n = rng.gen_range(2..=budget.min(4000));
            for k in 0..n {
                if k > 0 {
                    out.push_str([" + ", " - ", " * "][rng.gen_range(0..3)]);
                }
                expression(rng, 1, out);
            }
        }
        // Signs in a row.
        1 => {
            let n = rng.gen_range(1..=budget.min(150));
            out.push_str(&"-".repeat(n));
            expression(rng, budget - n.min(budget - 1), out);
        }
        // Brackets.
        2 => {
            out.push('(');
            expression(rng, budget - 1, out);
            out.push(')');
        }
        // A method.
        3 => {
            out.push('(');
            expression(rng, budget - 1, out);
            out.push_str([").sin()", ").cos()", ").powi(2)", ").abs()"][rng.gen_range(0..4)]);
        }
        // Two halves.
        _ => {
            let left = rng.gen_range(1..budget);
            out.push('(');
            expression(rng, left, out);
            out.push_str([") + (", ") * (", ") - ("][rng.gen_range(0..3)]);
            expression(rng, budget - left, out);
            out.push(')');
        }
    }
}

/// Model texts generated with random shapes and sizes (deep, long, bushy; up to thousands of
/// terms): each builds or is refused with an error placed in the text, never a panic or a crash.
/// Bounded: a few seconds.
#[test]
fn generated_texts_of_any_shape_build_or_are_refused() {
    let mut rng = ChaCha8Rng::seed_from_u64(0x34);
    let start = std::time::Instant::now();
    let (mut built, mut refused) = (0, 0);
    let mut case = 0;
    while case < 400 && start.elapsed() < std::time::Duration::from_secs(4) {
        let budget = [5, 50, 400, 5000][case % 4];
        let mut potential = String::new();
        expression(&mut rng, budget, &mut potential);
        let text = format!("kinetic = 0.5 * omega.dot(omega),\npotential = {potential}");
        let p = [("mass", Param::from(1.5))];
        match catch_unwind(AssertUnwindSafe(|| Model::new(&text, &p))) {
            Err(_) => panic!("case {case} panicked on a text of {} bytes", text.len()),
            Ok(Ok(_)) => built += 1,
            Ok(Err(e)) => {
                refused += 1;
                check_position(&e, &text, &format!("generated case {case}"));
            }
        }
        case += 1;
    }
    println!(
        "generated: {case} texts in {:.2?}: {built} built, {refused} refused",
        start.elapsed()
    );
    assert!(built > 0 && refused > 0, "{built} built, {refused} refused");
}
