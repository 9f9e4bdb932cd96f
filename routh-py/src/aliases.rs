//! The earlier Python names of three `Model` methods, kept as aliases of the Rust names:
//! `load` = `from_file`, `simulate` = `simulate_full`, `certify` = `steady_motions_certified`.

use crate::convert::Real;
use crate::model::Model;
use crate::results::Certificate;
use crate::trajectory::Trajectory;
use pyo3::prelude::*;
use pyo3::types::PyDict;

#[pymethods]
impl Model {
    /// Alias of `Model.from_file` (the Rust name), kept for existing code.
    ///
    /// >>> gyrostat = routh.Model.load("examples/models/gyrostat.toml")
    #[staticmethod]
    fn load(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Model> {
        Model::from_file(py, path)
    }

    /// Alias of `Model.simulate_full` (the Rust name), kept for existing code.
    ///
    /// >>> tr = top.simulate([0, 0.3, 5.0], [0.6, 0, 0.8], 10.0)
    #[pyo3(signature = (omega0, gamma0, t_end, *, times=None, **options))]
    fn simulate(
        &self,
        py: Python<'_>,
        omega0: &Bound<'_, PyAny>,
        gamma0: &Bound<'_, PyAny>,
        t_end: Real,
        times: Option<Vec<f64>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Trajectory> {
        self.simulate_full(py, omega0, gamma0, t_end, times, options)
    }

    /// Alias of `Model.steady_motions_certified` (the Rust name), kept for existing code.
    ///
    /// >>> c = top.certify(2.2)
    #[pyo3(signature = (p_psi, *, initial_split=None, min_width=None, max_boxes=None,
                        refine_iterations=None))]
    fn certify(
        &self,
        py: Python<'_>,
        p_psi: Real,
        initial_split: Option<usize>,
        min_width: Option<f64>,
        max_boxes: Option<usize>,
        refine_iterations: Option<usize>,
    ) -> PyResult<Certificate> {
        self.steady_motions_certified(
            py,
            p_psi,
            initial_split,
            min_width,
            max_boxes,
            refine_iterations,
        )
    }
}
