//! Rust work run with the GIL released and guarded against panics: a panic inside routh must
//! not cross into the interpreter (PyO3 would turn it into a `PanicException`, a
//! `BaseException` that `except Exception` does not catch). It becomes a `routh.RouthError`
//! with `kind == "Panic"` instead, a value like every other error.

use crate::convert::RouthError;
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::RecvTimeoutError;

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

/// How often the waiting thread looks for a signal (Ctrl-C) while long work runs.
const SIGNAL_POLL: std::time::Duration = std::time::Duration::from_millis(50);

/// The stack of the threads long work runs on.
const WORK_STACK: usize = 64 << 20;

/// Runs `f` on a thread of its own while the calling thread, with the GIL released, looks for
/// signals every 50 ms: on Ctrl-C, `cancel` is set (work that polls it, a family, stops at its
/// next evaluation), `f` is waited for and the signal's exception (`KeyboardInterrupt`) is
/// raised. A panic in `f` becomes a `routh.RouthError` (kind "Panic").
pub fn cooperative<R, F>(py: Python<'_>, cancel: &AtomicBool, f: F) -> PyResult<R>
where
    F: FnOnce() -> R + Send,
    R: Send,
{
    let mut interrupted: Option<PyErr> = None;
    let out = std::thread::scope(|s| {
        let (tx, rx) = std::sync::mpsc::channel();
        let spawned = std::thread::Builder::new()
            .name("routh-work".into())
            .stack_size(WORK_STACK)
            .spawn_scoped(s, move || {
                let _ = tx.send(catch_unwind(AssertUnwindSafe(f)));
            });
        if spawned.is_err() {
            return None;
        }
        let mut rx = rx;
        loop {
            let (got, back) = py.detach(move || (rx.recv_timeout(SIGNAL_POLL), rx));
            rx = back;
            match got {
                Ok(r) => return Some(r),
                Err(RecvTimeoutError::Timeout) => {
                    if interrupted.is_none() {
                        if let Err(e) = py.check_signals() {
                            cancel.store(true, Ordering::SeqCst);
                            interrupted = Some(e);
                        }
                    }
                }
                Err(RecvTimeoutError::Disconnected) => return None,
            }
        }
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    match out {
        Some(r) => r.map_err(|payload| panic_err(py, payload.as_ref())),
        None => Err(RouthError::new_err(
            "internal error: the work thread could not run",
        )),
    }
}

/// Runs `f` with a [`routh::RunControl`] whose cancel flag a Ctrl-C sets (see [`cooperative`]):
/// an analysis of the core that takes the control in its options stops at its next integration
/// step and the `KeyboardInterrupt` is raised.
pub fn cancellable<R, F>(py: Python<'_>, f: F) -> PyResult<R>
where
    F: FnOnce(routh::RunControl) -> R + Send,
    R: Send,
{
    let cancel = std::sync::Arc::new(AtomicBool::new(false));
    let control = routh::RunControl::default().with_cancel(cancel.clone());
    cooperative(py, &cancel, move || f(control))
}

/// Runs `f` on a thread of its own while the calling thread, with the GIL released, looks for
/// signals every 50 ms: on Ctrl-C the signal's exception (`KeyboardInterrupt`) is raised at
/// once and `f` (which cannot be stopped: it owns everything it uses) finishes in the
/// background, its result dropped. A panic in `f` becomes a `routh.RouthError` (kind "Panic").
pub fn interruptible<R, F>(py: Python<'_>, f: F) -> PyResult<R>
where
    F: FnOnce() -> R + Send + 'static,
    R: Send + 'static,
{
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::Builder::new()
        .name("routh-work".into())
        .stack_size(WORK_STACK)
        .spawn(move || {
            let _ = tx.send(catch_unwind(AssertUnwindSafe(f)));
        })
        .map_err(|e| RouthError::new_err(format!("cannot start the work thread: {e}")))?;
    let mut rx = rx;
    loop {
        let (got, back) = py.detach(move || (rx.recv_timeout(SIGNAL_POLL), rx));
        rx = back;
        match got {
            Ok(r) => return r.map_err(|payload| panic_err(py, payload.as_ref())),
            Err(RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(RecvTimeoutError::Disconnected) => {
                return Err(RouthError::new_err("internal error: the work thread ended"))
            }
        }
    }
}
