//! Running the `routh` binary as a user would, shared by the CLI's test files.
#![allow(dead_code)]

use std::process::{Command, Output};

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
