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
    fn from(e: routh::RouthError) -> Self {
        CliError::Compute(e.to_string())
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
