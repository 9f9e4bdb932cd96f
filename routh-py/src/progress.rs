//! Progress of long work (`progress=True`): a tqdm bar (`tqdm.auto`) when tqdm is installed,
//! else a line on `sys.stderr` rewritten in place (`routh: <what>: <n>`). Ticks come from Rust
//! threads that do not hold the GIL; the display is refreshed at most every 0.1 s (tqdm) or
//! 0.25 s (stderr), so the cost per tick is an atomic add and a clock read.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// A progress display of a count of evaluations.
pub struct Progress {
    bar: Option<Py<PyAny>>,
    what: &'static str,
    count: AtomicUsize,
    /// The count last shown and when.
    shown: Mutex<(usize, Instant)>,
}

impl Progress {
    /// `None` unless `enabled`; a tqdm bar if `import tqdm` works, else the stderr line.
    pub fn new(py: Python<'_>, enabled: bool, what: &'static str) -> PyResult<Option<Progress>> {
        if !enabled {
            return Ok(None);
        }
        // tqdm.auto picks the notebook widget in Jupyter, the text bar elsewhere.
        let module = py.import("tqdm.auto").or_else(|_| py.import("tqdm"));
        let bar = match module.and_then(|t| t.getattr("tqdm")) {
            Ok(tqdm) => {
                let kw = PyDict::new(py);
                kw.set_item("desc", what)?;
                kw.set_item("unit", "eval")?;
                Some(tqdm.call((), Some(&kw))?.unbind())
            }
            Err(_) => None,
        };
        Ok(Some(Progress {
            bar,
            what,
            count: AtomicUsize::new(0),
            shown: Mutex::new((0, Instant::now())),
        }))
    }

    fn period(&self) -> Duration {
        Duration::from_millis(if self.bar.is_some() { 100 } else { 250 })
    }

    /// One more evaluation; refreshes the display (taking the GIL) when it is due. Call it
    /// without the GIL held.
    pub fn tick(&self) {
        let n = self.count.fetch_add(1, Ordering::Relaxed) + 1;
        // try_lock: a tick never waits (another thread may be showing, with the GIL).
        let due = match self.shown.try_lock() {
            Ok(s) => s.1.elapsed() >= self.period(),
            Err(_) => false,
        };
        if due {
            Python::attach(|py| self.show(py, n, false));
        }
    }

    /// Shows the count `n` (the final line when `last`).
    fn show(&self, py: Python<'_>, n: usize, last: bool) {
        let Ok(mut shown) = self.shown.try_lock() else {
            return;
        };
        if n < shown.0 {
            return;
        }
        match &self.bar {
            Some(bar) => {
                let _ = bar.call_method1(py, "update", (n - shown.0,));
            }
            None => {
                let end = if last { " done\n" } else { "" };
                let line = format!("\rrouth: {}: {n}{end}", self.what);
                if let Ok(err) = py.import("sys").and_then(|s| s.getattr("stderr")) {
                    let _ = err.call_method1("write", (line,));
                    let _ = err.call_method0("flush");
                }
            }
        }
        *shown = (n, Instant::now());
    }

    /// Shows the final count and closes the bar (call with the GIL, once the work is over).
    pub fn close(&self, py: Python<'_>) {
        self.show(py, self.count.load(Ordering::Relaxed), true);
        if let Some(bar) = &self.bar {
            let _ = bar.call_method0(py, "close");
        }
    }
}
