//! The integration tests of `routh-codegen` in one test binary: each file of `tests/` is a module of
//! it, so that `cargo test` builds and links one binary for them instead of one per file. Run one
//! file's tests with `cargo test -p routh-codegen --test main <file>::`.
//!
//! A new test file is a new `mod` line below; `every_test_file_is_a_module` fails until it is.

mod deep;
mod front_end;
mod fuzz;
mod stiffness;

/// Every `tests/*.rs` file is compiled as a module of this binary (cargo does not build them on
/// their own: `autotests = false`), so a test file left out would silently never run.
#[test]
fn every_test_file_is_a_module() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let main = std::fs::read_to_string(dir.join("main.rs")).unwrap();
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let Some(stem) = path.file_stem().and_then(|s| s.to_str()) else {
            continue;
        };
        if path.extension().is_some_and(|e| e == "rs")
            && stem != "main"
            && !main.lines().any(|l| l.trim() == format!("mod {stem};"))
        {
            missing.push(stem.to_owned());
        }
    }
    assert!(
        missing.is_empty(),
        "tests/*.rs not in tests/main.rs: {missing:?}"
    );
}
