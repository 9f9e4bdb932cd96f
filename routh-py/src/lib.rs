//! `routh._routh`: the compiled half of the Python package `routh` (docs/python.md).
//!
//! Every analysis of `routh` is exposed on the run-time [`routh::Model`]: steady motions (paper
//! (33)), their classification (section 4–5, errata E5/E8), bifurcation diagrams and
//! stability atlases of families, simulation of the full (8) and reduced (13) equations, and
//! certified enumeration, and periodic orbits (relative periodic orbits, their Lyapunov families,
//! Floquet stability and Poincaré sections; their orbital stability beyond linear and orbit
//! charts). Vectors go in and out as numpy arrays; errors become the Python
//! exceptions `routh.RouthError` and `routh.ModelError`; long work releases the GIL.
//!
//! The pure-Python layer (`python/routh/__init__.py`) adds plots and reprs.

#![forbid(unsafe_code)]

mod aliases;
mod convert;
mod export;
mod family;
mod guard;
mod latex;
mod lenient;
mod nonlinear;
mod options;
mod orbit_nonlinear;
mod orbits;
mod pickle;
mod plot_style;
mod progress;
mod results;
mod trajectory;

use pyo3::prelude::*;

pub use convert::{ModelError, RouthError};
use latex::{LatexFormulas, SympyFormulas};
use results::{
    Atlas, Boundary, Branch, Certificate, CircleReport, Diagram, Event, StabilityReport,
    SteadyMotion,
};
use trajectory::{ReducedTrajectory, Trajectory};

mod model;
use model::Model;

/// The extension module `routh._routh`.
#[pymodule]
fn _routh(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("RouthError", py.get_type::<RouthError>())?;
    m.add("ModelError", py.get_type::<ModelError>())?;
    m.add_class::<Model>()?;
    m.add_class::<SteadyMotion>()?;
    m.add_class::<StabilityReport>()?;
    m.add_class::<CircleReport>()?;
    m.add_class::<Diagram>()?;
    m.add_class::<Branch>()?;
    m.add_class::<Event>()?;
    m.add_class::<Atlas>()?;
    m.add_class::<Boundary>()?;
    m.add_class::<Trajectory>()?;
    m.add_class::<ReducedTrajectory>()?;
    m.add_class::<Certificate>()?;
    m.add_class::<LatexFormulas>()?;
    m.add_class::<SympyFormulas>()?;
    m.add_class::<nonlinear::NonlinearReport>()?;
    m.add_class::<orbits::PeriodicOrbit>()?;
    m.add_class::<orbits::OrbitFamily>()?;
    m.add_class::<orbits::OrbitEvent>()?;
    m.add_class::<orbits::OrbitParameterFamily>()?;
    m.add_class::<orbits::PoincareSection>()?;
    m.add_class::<orbit_nonlinear::OrbitNonlinearReport>()?;
    m.add_class::<orbit_nonlinear::OrbitChart>()?;
    m.add_class::<orbit_nonlinear::OrbitChartCurve>()?;
    m.add_function(wrap_pyfunction!(family::bifurcation_diagram, m)?)?;
    m.add_function(wrap_pyfunction!(family::stability_atlas, m)?)?;
    m.add_function(wrap_pyfunction!(orbit_nonlinear::orbit_chart, m)?)?;
    m.add_function(wrap_pyfunction!(model::_bench_rust, m)?)?;
    m.add_function(wrap_pyfunction!(options::_options_schema, m)?)?;
    m.add_function(wrap_pyfunction!(pickle::_restore, m)?)?;
    m.add_function(wrap_pyfunction!(plot_style::plot_style, m)?)?;
    m.add_function(wrap_pyfunction!(export::_write_file, m)?)?;
    m.add("MAX_ATLAS_NODES", family::MAX_ATLAS_NODES)?;
    Ok(())
}
