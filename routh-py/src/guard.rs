//! Rust work run with the GIL released and guarded against panics: a panic inside routh must
//! not cross into the interpreter (PyO3 would turn it into a `PanicException`, a
//! `BaseException` that `except Exception` does not catch). It becomes a `routh.RouthError`
//! with `kind == "Panic"` instead, a value like every other error.

use crate::convert::RouthError;
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f` with the GIL released; a panic in `f` becomes a `routh.RouthError` (kind "Panic").
pub fn detached<R, F>(py: Python<'_>, f: F) -> PyResult<R>
where
    F: FnOnce() -> R + Send,
    R: Send,
{
    py.detach(|| catch_unwind(AssertUnwindSafe(f)))
        .map_err(|payload| panic_err(py, payload.as_ref()))
}

/// The `routh.RouthError` that reports a panic's message.
fn panic_err(py: Python<'_>, payload: &(dyn std::any::Any + Send)) -> PyErr {
    let msg = payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".to_string());
    let err = RouthError::new_err(format!("internal error in routh (please report it): {msg}"));
    let _ = err.value(py).setattr("kind", "Panic");
    err
}
