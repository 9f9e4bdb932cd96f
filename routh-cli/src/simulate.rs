//! `routh simulate`: the full (Euler–Poisson) or reduced (Routh) equations integrated.

use crate::cli::Simulate;
use crate::commands::load;
use crate::error::CliError;
use crate::options::options;
use crate::table::{num, vec3, Table};
use routh::{simulate_full, simulate_reduced, SimOptions, Vector3};
use serde_json::Value;

/// At most this many samples in the table (every recorded step goes to `--csv`/`--json`).
const SAMPLES: usize = 11;

/// Indices of at most [`SAMPLES`] evenly spread steps, the first and the last included.
fn samples(n: usize) -> Vec<usize> {
    if n <= SAMPLES {
        return (0..n).collect();
    }
    (0..SAMPLES).map(|k| k * (n - 1) / (SAMPLES - 1)).collect()
}

/// Runs `routh simulate` and returns what it prints.
pub fn simulate(s: &Simulate) -> Result<String, CliError> {
    let model = load(&s.model)?;
    let opts: SimOptions = options(
        [
            ("rtol", s.rtol.map(Value::from)),
            ("atol", s.atol.map(Value::from)),
        ],
        &s.opts,
    )?;
    let omega = Vector3::from(s.omega);
    let gamma = Vector3::from(s.gamma);
    // The library checks the tolerances, t_end and |γ| = 1: its refusals are bad input.
    let input = |e: routh::RouthError| CliError::Input(e.to_string());
    match (s.reduced, s.momentum) {
        (true, Some(p)) => {
            let tr = simulate_reduced(&model, omega, gamma, p, s.t_end, &opts).map_err(input)?;
            if s.output.json {
                return Ok(serde_json::to_string_pretty(&tr)? + "\n");
            }
            if s.output.csv {
                return Ok(tr.to_csv());
            }
            let mut t = Table::new(&["t", "Omega", "gamma", "psi_dot", "E"]);
            for i in samples(tr.t.len()) {
                t.row(vec![
                    format!("{:.6}", tr.t[i]),
                    vec3(&tr.big_omega[i]),
                    vec3(&tr.gamma[i]),
                    num(tr.psi_dot[i]),
                    num(tr.energy[i]),
                ]);
            }
            Ok(format!(
                "reduced equations at p_psi = {p}: {} steps; energy drift {:.3e}, |γ|² − 1 up to \
                 {:.3e}\n{}",
                tr.t.len(),
                tr.energy_drift(),
                tr.gamma_norm_error(),
                t.render()
            ))
        }
        (true, None) => Err(CliError::Input("--reduced needs --momentum P".into())),
        (false, _) => {
            let tr = simulate_full(&model, omega, gamma, s.t_end, &opts).map_err(input)?;
            if s.output.json {
                return Ok(serde_json::to_string_pretty(&tr)? + "\n");
            }
            if s.output.csv {
                return Ok(tr.to_csv());
            }
            let mut t = Table::new(&["t", "omega", "gamma", "E", "p_psi"]);
            for i in samples(tr.t.len()) {
                t.row(vec![
                    format!("{:.6}", tr.t[i]),
                    vec3(&tr.omega[i]),
                    vec3(&tr.gamma[i]),
                    num(tr.energy[i]),
                    num(tr.p_psi[i]),
                ]);
            }
            Ok(format!(
                "full equations: {} steps; energy drift {:.3e}, p_psi drift {:.3e}, |γ|² − 1 up \
                 to {:.3e}\n{}",
                tr.t.len(),
                tr.energy_drift(),
                tr.p_psi_drift(),
                tr.gamma_norm_error(),
                t.render()
            ))
        }
    }
}
