//! Export of every result class: `to_pandas()`, `to_csv(path)`, `to_json()` and the class method
//! `from_json(text)`. The work is done by the pure-Python module `routh._export` (pandas is an
//! optional dependency there); these methods only hand the object to it.

use crate::convert::helper;
use crate::nonlinear::NonlinearReport;
use crate::orbit_nonlinear::{OrbitChart, OrbitChartCurve, OrbitNonlinearReport};
use crate::orbits::{OrbitEvent, OrbitFamily, PeriodicOrbit, PoincareSection};
use crate::results::{
    Atlas, Boundary, Branch, Certificate, CircleReport, Diagram, Event, StabilityReport,
    SteadyMotion,
};
use crate::trajectory::{ReducedTrajectory, Trajectory};
use pyo3::prelude::*;
use pyo3::types::PyType;

/// The four export methods on each class named (a macro because a `#[pyclass]` cannot inherit
/// methods from a Rust base).
macro_rules! export_methods {
    ($($class:ident),* $(,)?) => {$(
        #[pymethods]
        impl $class {
            /// The result as a pandas DataFrame, columns as in docs/python.md ("Export"). Raises
            /// ImportError when pandas is not installed.
            ///
            /// >>> d = top.bifurcation_diagram((0.0, 5.0))
            /// >>> df = d.to_pandas()
            /// >>> events = df[df.kind != "point"]
            fn to_pandas(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
                helper(slf.py(), "routh._export", "to_pandas", (slf,))
            }
            /// Writes `to_pandas()` to the CSV file `path`, whole or not at all, by routh's one
            /// writer (a temporary file renamed; a link written through, a device in place); an
            /// error is an OSError naming `path`. Floats are written so that `pandas.read_csv(path)`
            /// gives the same numbers (on pandas < 3 pass `float_precision="round_trip"`).
            ///
            /// >>> top.classify(top.steady_motions(3.0)[0]).to_csv("report.csv")
            fn to_csv(slf: &Bound<'_, Self>, path: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                helper(slf.py(), "routh._export", "to_csv", (slf, path))
            }
            /// The result as JSON text; `from_json` makes it again with the same numbers (NaN and
            /// ±∞ are the strings "NaN", "Infinity", "-Infinity").
            ///
            /// >>> text = top.steady_motions(3.0)[0].to_json()
            fn to_json(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
                helper(slf.py(), "routh._export", "to_json", (slf,))
            }
            /// The result of `to_json()` made again (raises RouthError for text that is not one).
            ///
            /// >>> m = routh.SteadyMotion.from_json(text)
            #[classmethod]
            fn from_json(cls: &Bound<'_, PyType>, text: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
                helper(cls.py(), "routh._export", "from_json", (text, cls))
            }
        }
    )*};
}

export_methods!(
    SteadyMotion,
    StabilityReport,
    CircleReport,
    Branch,
    Event,
    Diagram,
    Boundary,
    Atlas,
    Trajectory,
    ReducedTrajectory,
    Certificate,
    NonlinearReport,
    PeriodicOrbit,
    OrbitEvent,
    OrbitFamily,
    PoincareSection,
    OrbitNonlinearReport,
    OrbitChart,
    OrbitChartCurve,
);

/// `routh._routh._write_file(path, text)`: writes `text` (UTF-8) to `path` through routh's one
/// writer (`routh::files::write_file`: whole or not at all, a temporary beside the file renamed
/// over it; links written through, pipes and devices in place, modes kept). `to_csv` hands it
/// the text pandas renders. Raises the `OSError` subclass of the system's error (its `errno`,
/// `strerror` and `filename`, the path as given), e.g. `FileNotFoundError` for a missing
/// directory, `IsADirectoryError`, `PermissionError`.
#[pyfunction]
pub fn _write_file(py: Python<'_>, path: std::path::PathBuf, text: &str) -> PyResult<()> {
    let bytes = text.as_bytes();
    crate::guard::detached(py, || routh::files::write_file(&path, bytes))?
        .map_err(|e| os_error(&path, &e))
}

/// The Python `OSError` (its subclass by errno) of a write error of `path`.
fn os_error(path: &std::path::Path, e: &std::io::Error) -> PyErr {
    use pyo3::exceptions::PyOSError;
    let inner = e
        .get_ref()
        .and_then(|r| r.downcast_ref::<routh::files::WriteError>())
        .map_or(e, |w| w.io_error());
    let filename = path.to_string_lossy().into_owned();
    match inner.raw_os_error() {
        Some(errno) => {
            // `strerror` without Rust's " (os error N)".
            let text = inner.to_string();
            let strerror = text
                .strip_suffix(&format!(" (os error {errno})"))
                .unwrap_or(&text)
                .to_string();
            PyOSError::new_err((errno, strerror, filename))
        }
        None => PyOSError::new_err(e.to_string()),
    }
}
