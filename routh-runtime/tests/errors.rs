//! Errors of `Model::new` and `Model::from_toml`: the derive's messages, at the line and column
//! of the mistake in the text; parameters missing, given twice, of a wrong shape; unused
//! parameters allowed; `set`/`with`; `from_file` with a missing file.

use nalgebra::{Matrix3, Vector3};
use routh_core::{Lagrangian, Routhian};
use routh_runtime::{Model, ModelError, Param};

const TOP: &str = "kinetic = 0.5 * omega.dot(diag(inertia) * omega),\npotential = mass * gamma.z";

fn top_params() -> Vec<(&'static str, Param)> {
    vec![("inertia", [1.0, 1.0, 2.0].into()), ("mass", 1.0.into())]
}

fn err(text: &str, params: &[(&str, Param)]) -> ModelError {
    Model::new(text, params).expect_err("an error")
}

#[test]
fn unknown_name_at_its_use() {
    let text = TOP.replace("mass * gamma", "mas * gamma");
    let e = err(&text, &top_params());
    assert!(e.message.starts_with("unknown name `mas`"), "{e}");
    assert_eq!((e.line, e.column, e.width), (2, 13, 3), "{e}");
    assert_eq!(e.source_line, "potential = mas * gamma.z");
    assert!(
        e.to_string()
            .contains("2 | potential = mas * gamma.z\n  |             ^^^"),
        "{e}"
    );
}

#[test]
fn a_parameter_the_text_uses_and_is_not_given_is_an_unknown_name() {
    let e = err(TOP, &[("inertia", [1.0, 1.0, 2.0].into())]);
    assert!(e.message.starts_with("unknown name `mass`"), "{e}");
    assert_eq!((e.line, e.column), (2, 13));
}

#[test]
fn shape_mismatch_at_the_expression() {
    let text = "kinetic = 0.5 * omega.dot(diag(inertia) * omega),\n  potential = mass * gamma";
    let e = err(text, &top_params());
    assert_eq!(e.message, "`potential` must be a scalar, found a 3-vector");
    assert_eq!((e.line, e.column, e.width), (2, 15, 12));
    // A parameter of the wrong shape for its use: a scalar given where a vector is used.
    let e = err(TOP, &[("inertia", 1.0.into()), ("mass", 1.0.into())]);
    assert_eq!((e.line, e.column), (1, 27), "{e}");
    assert!(e.message.contains("diag"), "{e}");
}

#[test]
fn kinetic_not_quadratic() {
    let text =
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega) * omega.x,\npotential = mass * gamma.z";
    let e = err(text, &top_params());
    assert!(
        e.message
            .starts_with("`kinetic` must be a homogeneous quadratic form in `omega`"),
        "{e}"
    );
    assert_eq!((e.line, e.column), (1, 11));
}

#[test]
fn syntax_and_lexing_errors() {
    let e = err(&format!("{TOP} +"), &top_params());
    assert_eq!((e.line, e.column), (2, 28), "{e}");
    let e = err("kinetic = 0.5 * omega.dot(omega),\npotential = \"a", &[]);
    assert!(e.message.contains("cannot be read"), "{e}");
    assert!(!e.message.contains("Rust"), "{e}");
    assert_eq!((e.line, e.column), (2, 13));
    // Unbalanced brackets and a misspelt item, in the language's own words.
    let e = err("kinetic = 0.5 * omega.dot(omega,\npotential = gamma.z", &[]);
    assert_eq!(e.message, "`(` is never closed", "{e}");
    assert_eq!((e.line, e.column), (1, 26));
    let e = err(
        "kinetic = 0.5 * omega.dot(omega)),\npotential = gamma.z",
        &[],
    );
    assert_eq!(e.message, "`)` closes no bracket", "{e}");
    let e = err(
        "kinetic = 0.5 * omega.dot(omega],\npotential = gamma.z",
        &[],
    );
    assert!(e.message.starts_with("`]` does not close the `(`"), "{e}");
    let e = err(
        "kinetik = 0.5 * omega.dot(omega),\npotential = gamma.z",
        &[],
    );
    assert!(e.message.contains("did you mean `kinetic`?"), "{e}");
    assert!(!e.message.contains("crate"), "{e}");
    assert_eq!((e.line, e.column), (1, 1));
    let e = err("potential = mass * gamma.z", &[("mass", 1.0.into())]);
    assert!(e.message.contains("missing `kinetic"), "{e}");
    assert_eq!((e.line, e.column), (1, 1));
}

#[test]
fn every_mistake_is_reported() {
    let text = "kinetic = 0.5 * omega.dot(diag(inertiaa) * omega),\npotential = mas * gamma.z";
    let e = err(text, &top_params());
    assert_eq!(e.others.len(), 1, "{e}");
    assert_eq!((e.line, e.others[0].line), (1, 2));
}

#[test]
fn parameters_twice_invalid_or_unused() {
    let mut p = top_params();
    p.push(("mass", 2.0.into()));
    let e = err(TOP, &p);
    assert_eq!(e.message, "parameter `mass` is given twice");
    assert_eq!((e.line, e.column), (2, 13));
    let e = err(
        TOP,
        &[
            ("inertia", [1.0; 3].into()),
            ("mass", 1.0.into()),
            ("fn", 1.0.into()),
        ],
    );
    assert!(
        e.message.contains("`fn` is not a valid parameter name"),
        "{e}"
    );
    // Unused parameters are fine.
    let mut p = top_params();
    p.push(("unused", Matrix3::identity().into()));
    assert!(Model::new(TOP, &p).is_ok());
}

#[test]
fn set_and_with_check_names_and_shapes() {
    let mut m = Model::new(TOP, &top_params()).unwrap();
    let g = Vector3::new(0.0, 0.0, 1.0);
    assert_eq!(m.amended_potential(&g, 0.0), 1.0);
    m.set("mass", 3.0).unwrap();
    assert_eq!(m.amended_potential(&g, 0.0), 3.0);
    let heavier = m.with("mass", 5.0).unwrap();
    assert_eq!(heavier.amended_potential(&g, 0.0), 5.0);
    assert_eq!(m.amended_potential(&g, 0.0), 3.0);
    let e = m.set("mas", 1.0).unwrap_err();
    assert!(e.message.contains("unknown parameter `mas`"), "{e}");
    let e = m.with("mass", [1.0, 2.0, 3.0]).unwrap_err();
    assert!(
        e.message.contains("`mass` is a f64, not a Vector3<f64>"),
        "{e}"
    );
    // The kinetic matrix follows a vector parameter.
    m.set("inertia", Vector3::new(2.0, 3.0, 4.0)).unwrap();
    assert_eq!(
        m.d2l_domega2(&g),
        Matrix3::from_diagonal(&Vector3::new(2.0, 3.0, 4.0))
    );
}

const TOML: &str = r#"[model]
lagrangian = """
    kinetic = 0.5 * omega.dot(inertia * omega),
    linear = (rotor + coupling * gamma).dot(omega),
    potential = mass * g * com.dot(gamma),
"""
symmetric = ["inertia"]          # optional
[parameters]
inertia = [[2.0, 0.1, 0.0], [0.1, 2.5, 0.0], [0.0, 0.0, 3.0]]
rotor = [0.0, 0.0, 0.5]
coupling = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
com = [0.0, 0.0, 1.0]
mass = 1
g = 9.81
[latex]
mass = "m"
"#;

#[test]
fn toml_of_each_shape() {
    let m = Model::from_toml(TOML).unwrap();
    assert_eq!(m.get("mass"), Some(Param::Scalar(1.0)));
    assert_eq!(
        m.get("rotor"),
        Some(Param::Vector(Vector3::new(0.0, 0.0, 0.5)))
    );
    let i = Matrix3::new(2.0, 0.1, 0.0, 0.1, 2.5, 0.0, 0.0, 0.0, 3.0);
    assert_eq!(m.get("inertia"), Some(Param::Matrix(i)));
    assert_eq!(m.symmetric(), ["inertia".to_string()]);
    assert_eq!(m.latex_symbols().get("mass").map(String::as_str), Some("m"));
    let g = Vector3::new(0.0, 0.0, 1.0);
    assert_eq!(m.d2l_domega2(&g), i);
    // U_r at rest with p_ψ = (K, γ): only the potential m g (r_c, γ).
    assert!((m.amended_potential(&g, 0.5) - 9.81).abs() < 1e-14);
}

#[test]
fn toml_errors_are_placed_in_the_file() {
    // A mistake in the Lagrangian: line 5 of the file, column 17.
    let e = Model::from_toml(&TOML.replace("mass * g", "mas * g")).unwrap_err();
    assert!(e.message.starts_with("unknown name `mas`"), "{e}");
    assert_eq!((e.line, e.column), (5, 17), "{e}");
    assert_eq!(e.source_line, "    potential = mas * g * com.dot(gamma),");
    // Missing parameter: an unknown name at its use.
    let e = Model::from_toml(&TOML.replace("g = 9.81\n", "")).unwrap_err();
    assert!(e.message.starts_with("unknown name `g`"), "{e}");
    assert_eq!((e.line, e.column), (5, 24), "{e}");
    // Given twice: TOML's duplicate key, at the second.
    let e = Model::from_toml(&TOML.replace("g = 9.81\n", "g = 9.81\ng = 1.0\n")).unwrap_err();
    assert!(e.message.contains("duplicate key"), "{e}");
    assert_eq!(e.line, 15, "{e}");
    // Mis-shaped values.
    for bad in [
        "[1.0, 2.0]",
        "\"x\"",
        "[[1, 2, 3], [4, 5, 6]]",
        "[[1, 2, 3], [4, 5, 6], [7, 8]]",
        "true",
    ] {
        let e = Model::from_toml(&TOML.replace("[0.0, 0.0, 0.5]", bad)).unwrap_err();
        assert!(
            e.message.contains("parameter `rotor` is not a number"),
            "{bad}: {e}"
        );
        assert_eq!((e.line, e.column), (10, 9), "{bad}: {e}");
    }
    // A symmetric name that is not a matrix parameter.
    let e = Model::from_toml(&TOML.replace("[\"inertia\"]", "[\"rotor\"]")).unwrap_err();
    assert!(e.message.contains("not a matrix parameter"), "{e}");
    assert_eq!(e.line, 7);
    // TOML syntax.
    let e = Model::from_toml(&TOML.replace("mass = 1", "mass = ")).unwrap_err();
    assert_eq!(e.line, 13, "{e}");
    // Unknown sections are refused; unused parameters are not.
    assert!(Model::from_toml(&format!("{TOML}[other]\nx = 1\n")).is_err());
    let unused = TOML.replace("g = 9.81\n", "g = 9.81\nunused = [1, 2, 3]\n");
    assert!(Model::from_toml(&unused).is_ok());
}

#[test]
fn from_file_with_a_missing_file() {
    let e = Model::from_file("/nonexistent/model.toml").unwrap_err();
    assert!(e.message.contains("/nonexistent/model.toml"), "{e}");
    assert_eq!((e.line, e.column), (1, 1));
}

#[test]
fn nan_and_infinite_parameters_are_refused_naming_them_huge_ones_are_values() {
    // Model::new: at the parameter's first use in the text.
    let e = err(
        TOP,
        &[
            ("inertia", [1.0, 1.0, 2.0].into()),
            ("mass", f64::NAN.into()),
        ],
    );
    assert!(e.message.contains("parameter `mass` is NaN"), "{e}");
    assert_eq!((e.line, e.column), (2, 13));
    let e = err(
        TOP,
        &[
            ("inertia", [1.0, f64::NEG_INFINITY, 2.0].into()),
            ("mass", 1.0.into()),
        ],
    );
    assert!(
        e.message
            .contains("parameter `inertia` has an infinite component [1]"),
        "{e}"
    );
    // set / with: refused, the model unchanged.
    let mut m = Model::new(TOP, &top_params()).unwrap();
    let e = m.set("mass", f64::INFINITY).unwrap_err();
    assert!(e.message.contains("parameter `mass` is infinite"), "{e}");
    assert_eq!(m.get("mass"), Some(Param::Scalar(1.0)));
    let mut bad = Matrix3::identity();
    bad[(2, 1)] = f64::NAN;
    let m = Model::new(
        "kinetic = 0.5 * omega.dot(j * omega), potential = gamma.z",
        &[("j", Matrix3::identity().into())],
    )
    .unwrap();
    let e = m.with("j", bad).unwrap_err();
    assert!(e.message.contains("`j` has a NaN entry [2][1]"), "{e}");
    // TOML: at the value in the file.
    let e = Model::from_toml(
        "[model]\nlagrangian = \"kinetic = 0.5 * omega.dot(omega), potential = mass * gamma.z\"\n[parameters]\nmass = nan\n",
    )
    .unwrap_err();
    assert!(e.message.contains("parameter `mass` is NaN"), "{e}");
    assert_eq!((e.line, e.column), (4, 8));
    let e = Model::from_toml(
        "[model]\nlagrangian = \"kinetic = 0.5 * omega.dot(omega), potential = com.dot(gamma)\"\n[parameters]\ncom = [0, -inf, 1]\n",
    )
    .unwrap_err();
    assert!(
        e.message.contains("`com` has an infinite component [1]"),
        "{e}"
    );
    let g = Vector3::new(0.0, 0.0, 1.0);
    let m = Model::new(
        TOP,
        &[
            ("inertia", [1e308, 1.0, 2.0].into()),
            ("mass", 1e308.into()),
        ],
    )
    .unwrap();
    assert!(!m.energy(&Vector3::new(10.0, 0.0, 0.0), &g).is_finite());
}

/// Hostile texts: deep, long and large. Each builds or is refused with a
/// placed error; none may crash (a stack overflow aborts the process, so each is run in a
/// child process of this test binary, see [`hostile_texts_build_or_are_refused_never_crash`]).
fn hostile_case(name: &str) -> Result<Model, ModelError> {
    let kinetic = "kinetic = 0.5 * omega.dot(omega),\npotential = ";
    let sum = |n: usize| {
        (0..n)
            .map(|i| format!("{}.5 * gamma.{}", i % 7, ["x", "y", "z"][i % 3]))
            .collect::<Vec<_>>()
            .join(" + ")
    };
    let none: &[(&str, Param)] = &[];
    match name {
        "minus-7000" => Model::new(&format!("{kinetic}{}gamma.z", "-".repeat(7000)), none),
        "spaced-minus-7000" => Model::new(&format!("{kinetic}{}gamma.z", "- ".repeat(7000)), none),
        "not-7000" => Model::new(&format!("{kinetic}{}gamma.z", "!".repeat(7000)), none),
        "parens-7000" => Model::new(
            &format!("{kinetic}{}gamma.z{}", "(".repeat(7000), ")".repeat(7000)),
            none,
        ),
        "methods-50000" => Model::new(
            &format!("{kinetic}gamma.z{}", ".sin()".repeat(50_000)),
            none,
        ),
        "sum-50000" => Model::new(&format!("{kinetic}{}", sum(50_000)), none),
        "product-20000" => Model::new(
            &format!("{kinetic}{}", vec!["gamma.z"; 20_000].join(" * ")),
            none,
        ),
        "one-megabyte" => {
            let text = format!("{kinetic}{}", sum(70_000));
            assert!(text.len() > 1 << 20);
            Model::new(&text, none)
        }
        "toml-sum-50000" => Model::from_toml(&format!(
            "[model]\nlagrangian = \"\"\"\n{kinetic}{}\n\"\"\"\n",
            sum(50_000)
        )),
        "small-stack-thread" => std::thread::Builder::new()
            .stack_size(128 << 10)
            .spawn(move || Model::new(&format!("{kinetic}{}", sum(50_000)), none))
            .unwrap()
            .join()
            .unwrap(),
        _ => panic!("no case {name}"),
    }
}

#[test]
fn hostile_texts_build_or_are_refused_never_crash() {
    const CHILD: &str = "ROUTH_HOSTILE_CASE";
    if let Ok(name) = std::env::var(CHILD) {
        match hostile_case(&name) {
            Ok(_) => println!("HOSTILE ok"),
            Err(e) => println!("HOSTILE err {}:{} {}", e.line, e.column, e.message),
        }
        return;
    }
    // (case, expected: "ok" or the start of the error "err line:column" and a word of it)
    let cases = [
        ("minus-7000", "err 2:77", "in a row"),
        ("spaced-minus-7000", "err 2:141", "in a row"),
        ("not-7000", "err 2:77", "in a row"),
        ("parens-7000", "err 2:77", "nested more than 64"),
        ("methods-50000", "err 2:13", "nested more than 200"),
        ("sum-50000", "ok", ""),
        ("product-20000", "ok", ""),
        ("one-megabyte", "ok", ""),
        ("toml-sum-50000", "ok", ""),
        ("small-stack-thread", "ok", ""),
    ];
    let exe = std::env::current_exe().unwrap();
    for (name, expected, word) in cases {
        let out = std::process::Command::new(&exe)
            .args([
                // The test's path in the one test binary (tests/main.rs) of this crate.
                concat!(
                    module_path!(),
                    "::hostile_texts_build_or_are_refused_never_crash"
                )
                .split_once("::")
                .map_or("", |(_, path)| path),
                "--exact",
                "--nocapture",
                "--test-threads=1",
            ])
            .env(CHILD, name)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{name}: the child failed ({:?}):\n{stdout}\n{}",
            out.status,
            String::from_utf8_lossy(&out.stderr)
        );
        let line = stdout
            .lines()
            .find_map(|l| l.split_once("HOSTILE ").map(|(_, r)| r))
            .unwrap_or_else(|| panic!("{name}: no result in\n{stdout}"));
        assert!(
            line.starts_with(expected) && line.contains(word),
            "{name}: expected `{expected}` … `{word}`, got `{line}`"
        );
    }
}
