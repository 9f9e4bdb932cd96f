//! The two ways a run fails, and their exit codes.

use thiserror::Error;

/// Why a command failed: bad input (exit code 2) or a failed computation (exit code 1).
#[derive(Debug, Error)]
pub enum CliError {
    /// Unreadable or invalid model file, unknown parameter, bad range, … (exit code 2).
    #[error("{0}")]
    Input(String),
    /// The analysis itself failed (no convergence, an unwritable output, …) (exit code 1).
    #[error("{0}")]
    Compute(String),
}

impl CliError {
    /// The process exit code: 2 for bad input, 1 for a failed computation.
    pub fn exit_code(&self) -> i32 {
        match self {
            CliError::Input(_) => 2,
            CliError::Compute(_) => 1,
        }
    }
}

impl From<routh::RouthError> for CliError {
    /// Bad input (exit code 2) where the library refused what it was given — a non-finite
    /// number, a γ that is not a unit vector, an invalid model or option, a γ that is not a
    /// steady motion — also at a parameter value of a family; a failed computation (exit code
    /// 1) otherwise.
    fn from(e: routh::RouthError) -> Self {
        if is_bad_input(&e) {
            CliError::Input(e.to_string())
        } else {
            CliError::Compute(e.to_string())
        }
    }
}

/// Whether the library refused its input (rather than failing in the computation).
fn is_bad_input(e: &routh::RouthError) -> bool {
    use routh::RouthError as E;
    match e {
        E::NonFinite { .. }
        | E::NonUnitGamma { .. }
        | E::InvalidModel { .. }
        | E::InvalidOption { .. }
        | E::NotASteadyMotion { .. } => true,
        E::AtParameter { source, .. } => is_bad_input(source),
        _ => false,
    }
}

impl From<serde_json::Error> for CliError {
    fn from(e: serde_json::Error) -> Self {
        CliError::Compute(format!("cannot write JSON: {e}"))
    }
}

impl From<routh::plot::PlotError> for CliError {
    fn from(e: routh::plot::PlotError) -> Self {
        CliError::Compute(format!("cannot draw the figure: {e}"))
    }
}
