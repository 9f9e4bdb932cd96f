//! `--opt KEY=VALUE`: any field of an analysis's options struct, laid over its `Default` by
//! `routh::options` (as Python's keywords are), after the command's own flags (which are the
//! same fields by other names: `--max-orbits N` is `--opt max_orbits=N`).

use crate::cli::Opts;
use crate::error::CliError;
use routh::options::{overlay, Options};
use serde_json::Value;

/// `T::default()` with the command's `flags` (`None`: not given) and then its `--opt` pairs
/// laid over it; an unknown key or a value of the wrong type is bad input (exit code 2).
pub fn options<T: Options>(
    flags: impl IntoIterator<Item = (&'static str, Option<Value>)>,
    opts: &Opts,
) -> Result<T, CliError> {
    let flags = flags
        .into_iter()
        .filter_map(|(k, v)| v.map(|v| (k.to_string(), v)));
    overlay(
        T::default(),
        flags.chain(opts.opt.iter().cloned()),
        serde_json::from_value,
    )
    .map_err(|e| CliError::Input(format!("--opt: {e}")))
}
