//! Families given as Python callables: `routh.bifurcation_diagram` and `routh.stability_atlas`.
//!
//! The Rust continuation runs with the GIL released; each evaluation of the family re-acquires
//! it to call Python. A Python exception raised by the family stops the work (every later
//! evaluation returns a NaN momentum at once, which the Rust side rejects) and is re-raised.

use crate::convert::{routh_err, vector3, Real, RouthError};
use crate::guard::cooperative;
use crate::model::Model;
use crate::options::from_keywords;
use crate::progress::Progress;
use crate::results::{Atlas, Diagram};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use routh::{AtlasOptions, ContinuationOptions};
use std::sync::Mutex;

/// A Python family `f(*args) -> (Model, p_psi)` made callable from Rust threads.
pub(crate) struct PyFamily {
    f: Py<PyAny>,
    fallback: routh::Model,
    error: Mutex<Option<PyErr>>,
    progress: Option<Progress>,
    /// Set on Ctrl-C: every later evaluation returns a NaN momentum, which stops the work.
    pub(crate) cancel: std::sync::atomic::AtomicBool,
}

impl PyFamily {
    /// Call once with the GIL held (errors surface at once, and give the fallback model).
    pub(crate) fn new(
        py: Python<'_>,
        f: Py<PyAny>,
        first: (f64, f64),
        two: bool,
        progress: bool,
    ) -> PyResult<PyFamily> {
        let out = if two {
            f.call1(py, first)?
        } else {
            f.call1(py, (first.0,))?
        };
        let (m, _) = extract(out.bind(py))?;
        let progress = Progress::new(py, progress, "family evaluations")?;
        if let Some(p) = &progress {
            p.tick(); // the call above (not due yet: the display was just made)
        }
        Ok(PyFamily {
            f,
            fallback: m,
            error: Mutex::new(None),
            progress,
            cancel: std::sync::atomic::AtomicBool::new(false),
        })
    }

    fn failed(&self) -> bool {
        self.error.lock().map(|e| e.is_some()).unwrap_or(true)
    }

    /// Evaluates the family at `args` from a Rust thread without the GIL: takes the GIL for
    /// the Python call only.
    pub(crate) fn call(&self, args: (f64, f64), two: bool) -> (routh::Model, f64) {
        if self.failed() || self.cancel.load(std::sync::atomic::Ordering::Relaxed) {
            return (self.fallback.clone(), f64::NAN);
        }
        if let Some(p) = &self.progress {
            p.tick();
        }
        Python::attach(|py| {
            let out = if two {
                self.f.call1(py, args)
            } else {
                self.f.call1(py, (args.0,))
            };
            match out.and_then(|o| extract(o.bind(py))) {
                Ok(r) => r,
                Err(e) => {
                    if let Ok(mut slot) = self.error.lock() {
                        slot.get_or_insert(e);
                    }
                    (self.fallback.clone(), f64::NAN)
                }
            }
        })
    }

    /// The family's exception if it raised one, else `other`.
    pub(crate) fn finish(self, py: Python<'_>, other: PyErr) -> PyErr {
        self.close(py);
        match self.error.into_inner() {
            Ok(Some(e)) => e,
            _ => other,
        }
    }

    pub(crate) fn close(&self, py: Python<'_>) {
        if let Some(p) = &self.progress {
            p.close(py);
        }
    }

    pub(crate) fn take_error(&self) -> Option<PyErr> {
        self.error.lock().ok().and_then(|mut e| e.take())
    }
}

fn extract(o: &Bound<'_, PyAny>) -> PyResult<(routh::Model, f64)> {
    let (m, p): (Bound<'_, Model>, f64) = o.extract().map_err(|_| {
        pyo3::exceptions::PyTypeError::new_err(
            "the family must return a tuple (routh.Model, p_psi)",
        )
    })?;
    Ok((m.get().get()?, p))
}

/// The bifurcation diagram of a family `s -> (Model, p_psi)` over `s ∈ (lo, hi)`. Keywords: the
/// fields of the Rust `ContinuationOptions`, defaults its `Default` (`nonlinear=True`: the
/// nonlinear events too); `progress=True` shows the count of
/// family evaluations. The family is called with the GIL held; the continuation between calls
/// runs without it. An exception raised by the family stops the work and is re-raised.
///
/// >>> d = routh.bifurcation_diagram(lambda mgl: (top.with_params(mgl=mgl), 3.0), (0.5, 3.0))
/// >>> sorted((e.kind, round(e.s, 6)) for e in d.events)
/// [('branch_point', 1.44), ('hamiltonian_hopf', 2.25)]
#[pyfunction]
#[pyo3(signature = (family, range, *, progress=false, **options))]
pub fn bifurcation_diagram(
    py: Python<'_>,
    family: Py<PyAny>,
    range: (Real, Real),
    progress: bool,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Diagram> {
    let range = (range.0 .0, range.1 .0);
    let opts: ContinuationOptions = from_keywords("bifurcation_diagram", options)?;
    let fam = PyFamily::new(py, family, (range.0, 0.0), false, progress)?;
    let r = cooperative(py, &fam.cancel, || {
        routh::bifurcation_diagram(|s| fam.call((s, 0.0), false), range, &opts)
    });
    let r = match r {
        Ok(r) => r,
        Err(panic) => return Err(fam.finish(py, panic)),
    };
    match r {
        Ok(d) => {
            fam.close(py);
            if let Some(e) = fam.take_error() {
                return Err(e);
            }
            Diagram::new(py, &d)
        }
        Err(e) => {
            let other = routh_err(py, &e);
            Err(fam.finish(py, other))
        }
    }
}

/// The stability atlas of a family `(x, y) -> (Model, p_psi)` over `[x0, x1] × [y0, y1]`,
/// following the steady motion near `gamma_guess`. Keywords: the fields of the Rust
/// `AtlasOptions`, defaults its `Default`; a grid of more than `MAX_ATLAS_NODES` nodes is refused.
///
/// >>> a = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
/// ...                           (0.5, 2.0), (0.5, 5.0), nx=21, ny=21)
/// >>> a.verdicts[0][0], [b.kind for b in a.boundaries]
#[pyfunction]
#[pyo3(signature = (family, gamma_guess, x, y, *, progress=false, **options))]
pub fn stability_atlas(
    py: Python<'_>,
    family: Py<PyAny>,
    gamma_guess: &Bound<'_, PyAny>,
    x: (Real, Real),
    y: (Real, Real),
    progress: bool,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<Atlas> {
    let (x, y) = ((x.0 .0, x.1 .0), (y.0 .0, y.1 .0));
    let g = vector3("gamma_guess", gamma_guess)?;
    let opts: AtlasOptions = from_keywords("stability_atlas", options)?;
    check_grid(py, opts.nx, opts.ny)?;
    let fam = PyFamily::new(py, family, (x.0, y.0), true, progress)?;
    let r = cooperative(py, &fam.cancel, || {
        routh::stability_atlas(|a, b| fam.call((a, b), true), g, x, y, &opts)
    });
    let r = match r {
        Ok(r) => r,
        Err(panic) => return Err(fam.finish(py, panic)),
    };
    match r {
        Ok(a) => {
            fam.close(py);
            if let Some(e) = fam.take_error() {
                return Err(e);
            }
            Atlas::new(py, &a)
        }
        Err(e) => {
            let other = routh_err(py, &e);
            Err(fam.finish(py, other))
        }
    }
}

/// The largest atlas grid, `nx·ny` nodes: larger grids are refused before any allocation (the
/// Rust atlas allocates its grid up front, and an overflowing or unallocatable size would abort
/// the interpreter). Ten million nodes is far beyond what a classification per node can fill in
/// a session.
pub const MAX_ATLAS_NODES: usize = 10_000_000;

/// `nx·ny ≤ MAX_ATLAS_NODES`, else a `routh.RouthError` of kind "InvalidOption".
fn check_grid(py: Python<'_>, nx: usize, ny: usize) -> PyResult<()> {
    match nx.checked_mul(ny) {
        Some(n) if n <= MAX_ATLAS_NODES => Ok(()),
        _ => {
            let err = RouthError::new_err(format!(
                "invalid option nx, ny: a grid of {nx} x {ny} nodes exceeds the limit of \
                 {MAX_ATLAS_NODES} nodes"
            ));
            let _ = err.value(py).setattr("kind", "InvalidOption");
            Err(err)
        }
    }
}
