//! The integration tests of `routh` in one test binary: each file of `tests/` is a module of
//! it, so that `cargo test` builds and links one binary for them instead of one per file. Run one
//! file's tests with `cargo test -p routh --test main <file>::`.
//!
//! A new test file is a new `mod` line below; `every_test_file_is_a_module` fails until it is.

mod certify;
mod circles;
mod common;
mod derived_formulas;
mod dsl;
mod example_models;
mod examples_facts;
mod examples_models;
mod expand;
mod generated_stability;
mod generated_vs_numdual;
mod kirchhoff;
mod latex;
mod latex_document;
mod nonlinear;
mod orbit_nonlinear;
mod plot;
mod plot_trajectory;
mod routh_identities;
mod routh_tape;
mod runtime_model;
mod runtime_properties;
mod serde_roundtrip;
mod taylor;
mod ui;

/// Every `tests/*.rs` file of every crate whose integration tests are one binary (a
/// `tests/main.rs`) is compiled as a module of it (cargo does not build the files on their own:
/// `autotests = false`), so a test file left out would silently never run. One check for the
/// whole workspace, here in the facade's harness.
#[test]
fn every_test_file_is_a_module() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut crates = vec![root.to_path_buf()];
    for entry in std::fs::read_dir(root).unwrap() {
        crates.push(entry.unwrap().path());
    }
    let mut missing = Vec::new();
    let mut harnesses = 0;
    for krate in crates {
        let dir = krate.join("tests");
        let Ok(main) = std::fs::read_to_string(dir.join("main.rs")) else {
            continue;
        };
        harnesses += 1;
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else {
                continue;
            };
            if path.extension().is_some_and(|e| e == "rs")
                && stem != "main"
                && !main.lines().any(|l| l.trim() == format!("mod {stem};"))
            {
                missing.push(path.display().to_string());
            }
        }
    }
    // The facade, routh-core, routh-codegen, routh-runtime and routh-symbolic.
    assert!(harnesses >= 5, "found {harnesses} test harnesses");
    assert!(
        missing.is_empty(),
        "not a module of their tests/main.rs: {missing:?}"
    );
}
