//! Running the `routh` binary as a user would, shared by the CLI's test files.
#![allow(dead_code)]

use std::process::{Command, Output};

/// The Lagrange top of the examples (A₁ = 1, C = 1.25, mgl = 1).
pub const TOP: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../examples/models/heavy_top.toml"
);
/// The asymmetric top of the examples.
pub const ASYMMETRIC: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../examples/models/asymmetric_top.toml"
);
/// A heavy body J = diag(1, 2, 3), m g l = 1.5, whose swings about e₁ are a pendulum.
pub const SWINGING: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/tests/models/swinging_body.toml"
);
/// The heavy body with moments 1 : 4 : 1 of the orbit-chart example.
pub const BODY_141: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../examples/models/body_141.toml"
);

/// `routh ARGS…`, its exit code and both streams.
pub fn routh(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_routh"))
        .args(args)
        .output()
        .expect("the routh binary runs")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// `routh ARGS…` with exit code 0: its stdout.
pub fn ok(args: &[&str]) -> String {
    let o = routh(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: stderr {}", stderr(&o));
    stdout(&o)
}

/// Exit code `code` and a message on stderr containing each of `needles`, no panic, nothing on
/// stdout.
pub fn fails_with(args: &[&str], code: i32, needles: &[&str]) {
    let o = routh(args);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(code), "{args:?}: stderr {err}");
    for n in needles {
        assert!(err.contains(n), "{args:?}: stderr {err:?} lacks {n:?}");
    }
    assert!(!err.contains("panicked"), "{err}");
    assert!(stdout(&o).is_empty(), "{}", stdout(&o));
}

/// [`fails_with`] one needle.
pub fn fails(args: &[&str], code: i32, needle: &str) {
    fails_with(args, code, &[needle]);
}
