//! `routh`: the command line of the routh toolkit (steady motions, stability, bifurcation
//! diagrams of a model read from a TOML file). Run `routh --help`.
#![forbid(unsafe_code)]

mod args;
mod atlas;
mod certify;
mod cli;
mod commands;
mod diagram;
mod error;
mod files;
mod interrupt;
mod nonlinear;
mod options;
mod orbit_chart;
mod orbit_out;
mod orbits;
mod progress;
mod simulate;
mod table;

use clap::Parser;
use cli::{Cli, Command};
use error::CliError;
use std::io::Write;

fn run(cli: &Cli) -> Result<String, CliError> {
    match &cli.command {
        Command::Steady(a) => commands::steady(a),
        Command::Classify(a) => commands::classify(a),
        Command::Nonlinear(a) => nonlinear::nonlinear(a),
        Command::Diagram(d) => diagram::diagram(d),
        Command::Atlas(a) => atlas::atlas(a),
        Command::Simulate(s) => simulate::simulate(s),
        Command::Certify(c) => certify::certify(c),
        Command::Orbit(o) => orbits::orbit(o),
        Command::Orbits(o) => orbits::orbits(o),
        Command::Section(s) => orbits::section(s),
        Command::OrbitChart(c) => orbit_chart::orbit_chart(c),
        Command::Formulas(f) => commands::formulas(f),
    }
}

fn main() {
    // Usage errors: clap prints them and exits with code 2.
    let cli = Cli::parse();
    interrupt::install();
    let result = run(&cli);
    if interrupt::requested() {
        interrupt::end();
    }
    match result {
        Ok(text) => {
            let mut out = std::io::stdout().lock();
            if let Err(e) = out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
                // A closed pipe (`| head`): no message, but not success either — the status a
                // shell shows for a program ended by SIGPIPE, as coreutils' (128 + 13).
                if e.kind() == std::io::ErrorKind::BrokenPipe {
                    std::process::exit(141);
                }
                fail(&format!("cannot write to standard output: {e}"), 1);
            }
        }
        Err(e) => fail(&e.to_string(), e.exit_code()),
    }
}

/// `error: MESSAGE` on stderr (a stderr that cannot be written is no reason to panic), then
/// exits with `code`.
fn fail(message: &str, code: i32) -> ! {
    let _ = writeln!(std::io::stderr(), "error: {message}");
    std::process::exit(code)
}
