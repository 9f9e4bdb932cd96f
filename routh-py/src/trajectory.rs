//! The trajectories of `Model.simulate` (full equations (8)) and `Model.simulate_reduced`
//! (reduced equations (13) with the reconstruction (15)), as numpy arrays, with the attitude
//! when it was integrated (`attitude=True`), its Euler angles, the apex locus figure and the
//! Jupyter reprs.

use crate::convert::{helper, quaternions, rows3, vecs, RouthError};
use numpy::PyArray1;
use pyo3::prelude::*;

/// The error of `euler_angles()` / `plot_apex()` on a run without attitude.
fn no_attitude() -> PyErr {
    RouthError::new_err("no attitude: simulate with attitude=True")
}

/// The methods both trajectory classes share (their fields `attitude`, `euler`, `len` have the
/// same meaning): Euler angles, the apex locus, the Jupyter reprs, `len` and `repr`. A macro
/// because a `#[pyclass]` cannot inherit methods from a Rust base.
macro_rules! attitude_methods {
    ($class:ident, $name:literal) => {
        #[pymethods]
        impl $class {
            /// The z-x-z Euler angles (ψ, θ, φ) of the attitude, (n, 3): `R = R_z(ψ) R_x(θ)
            /// R_z(φ)`, ψ the precession, θ the nutation (γ₃ = cos θ), φ the proper rotation; ψ
            /// and φ unwrapped. Raises `RouthError` when the attitude was not integrated
            /// (`attitude=True`).
            fn euler_angles(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
                self.euler
                    .as_ref()
                    .map(|e| e.clone_ref(py))
                    .ok_or_else(no_attitude)
            }
            /// Draws the apex locus with matplotlib: the path in space of the body axis `axis`
            /// (the symmetry axis e₃ of a top by default) on the unit sphere, seen from above, as
            /// the Rust SVG (`routh::plot::apex_locus_svg`): upper hemisphere solid, lower
            /// dotted, start ring, end dot, horizon dashed. Returns the axes. Needs
            /// `attitude=True`.
            #[pyo3(signature = (ax=None, axis=(0.0, 0.0, 1.0)))]
            fn plot_apex(
                slf: &Bound<'_, Self>,
                ax: Option<Py<PyAny>>,
                axis: (f64, f64, f64),
            ) -> PyResult<Py<PyAny>> {
                if slf.get().attitude.is_none() {
                    return Err(no_attitude());
                }
                helper(slf.py(), "routh._plot", "plot_apex", (slf, ax, axis))
            }
            /// The apex locus as SVG (Jupyter), None without attitude.
            fn _repr_svg_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
                helper(slf.py(), "routh._display", "trajectory_svg", (slf,))
            }
            /// A summary table (and the apex locus) as HTML (Jupyter).
            fn _repr_html_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
                helper(slf.py(), "routh._display", "trajectory_html", (slf,))
            }
            fn __len__(&self) -> usize {
                self.len
            }
            fn __repr__(&self) -> String {
                let attitude = if self.attitude.is_some() {
                    "True"
                } else {
                    "False"
                };
                format!(concat!($name, "(n={}, attitude={})"), self.len, attitude)
            }
        }
    };
}

/// A solution of the full equations (8): `t` (n,), `omega` (n, 3), `gamma` (n, 3), the
/// recorded integrals `energy` (n,) and `p_psi` (n,), and with `attitude=True` the attitude
/// `attitude` (n, 4).
///
/// `attitude[k]` is the rotation R body → space at `t[k]` as a unit quaternion in the order
/// **(x, y, z, w)**, scalar last, as `scipy.spatial.transform.Rotation.from_quat` reads it:
/// `x_space = R x_body`, `γ = Rᵀe₃`, `Ṙ = R[ω]×`, and `R(0)` the attitude with Euler angle
/// ψ(0) = 0. It is None when the attitude was not integrated.
///
/// >>> tr = top.simulate([0, 0.3, 5.0], [0.6, 0, 0.8], 10.0, attitude=True)
/// >>> tr.attitude.shape == (len(tr.t), 4)
/// True
/// >>> psi, theta, phi = tr.euler_angles().T      # z-x-z, ψ and φ unwrapped
/// >>> ax = tr.plot_apex()                         # the apex locus, seen from above
#[pyclass(module = "routh", frozen)]
pub struct Trajectory {
    /// Times, (n,).
    #[pyo3(get)]
    pub t: Py<PyAny>,
    /// Angular velocity in the body frame, (n, 3).
    #[pyo3(get)]
    pub omega: Py<PyAny>,
    /// The vertical in the body frame, (n, 3).
    #[pyo3(get)]
    pub gamma: Py<PyAny>,
    /// The energy (3) at each time, (n,).
    #[pyo3(get)]
    pub energy: Py<PyAny>,
    /// The cyclic momentum (9) at each time, (n,).
    #[pyo3(get)]
    pub p_psi: Py<PyAny>,
    /// The attitude, (n, 4) unit quaternions (x, y, z, w); None without `attitude=True`.
    #[pyo3(get)]
    pub attitude: Option<Py<PyAny>>,
    pub(crate) euler: Option<Py<PyAny>>,
    pub(crate) len: usize,
}

impl Trajectory {
    pub(crate) fn new(py: Python<'_>, t: &routh::Trajectory) -> Trajectory {
        Trajectory {
            t: PyArray1::from_slice(py, &t.t).into_any().unbind(),
            omega: vecs(py, &t.omega).into_any().unbind(),
            gamma: vecs(py, &t.gamma).into_any().unbind(),
            energy: PyArray1::from_slice(py, &t.energy).into_any().unbind(),
            p_psi: PyArray1::from_slice(py, &t.p_psi).into_any().unbind(),
            attitude: quaternions(py, &t.attitude),
            euler: rows3(py, &t.euler_angles()),
            len: t.len(),
        }
    }
}

attitude_methods!(Trajectory, "Trajectory");

/// A solution of the reduced equations (13): `t`, `big_omega` (n, 3), `gamma` (n, 3), the
/// reconstructed `psi`, `psi_dot`, `omega` (n, 3), `energy`, `p_psi`, and with `attitude=True`
/// the attitude `attitude` (n, 4), quaternions (x, y, z, w) as in [`Trajectory`].
///
/// The attitude is reconstructed by (15), `R = R_z(ψ) R_Ω`; the gauge angle `psi` is not the
/// Euler angle ψ of `euler_angles()` (they differ by the Euler ψ of R_Ω, constant on a steady
/// motion).
///
/// >>> red = top.simulate_reduced([0, 0.3, 0], [0.6, 0, 0.8], 3.0, 10.0, attitude=True)
/// >>> red.euler_angles().shape == (len(red.t), 3)
/// True
#[pyclass(module = "routh", frozen)]
pub struct ReducedTrajectory {
    /// Times, (n,).
    #[pyo3(get)]
    pub t: Py<PyAny>,
    /// The reduced velocity Ω, (n, 3).
    #[pyo3(get)]
    pub big_omega: Py<PyAny>,
    /// The vertical, (n, 3).
    #[pyo3(get)]
    pub gamma: Py<PyAny>,
    /// The cyclic angle ψ, (n,).
    #[pyo3(get)]
    pub psi: Py<PyAny>,
    /// ψ̇ (38), (n,).
    #[pyo3(get)]
    pub psi_dot: Py<PyAny>,
    /// The angular velocity ω = Ω + ψ̇γ, (n, 3).
    #[pyo3(get)]
    pub omega: Py<PyAny>,
    /// The energy, (n,).
    #[pyo3(get)]
    pub energy: Py<PyAny>,
    /// The cyclic momentum, (n,).
    #[pyo3(get)]
    pub p_psi: Py<PyAny>,
    /// The attitude, (n, 4) unit quaternions (x, y, z, w); None without `attitude=True`.
    #[pyo3(get)]
    pub attitude: Option<Py<PyAny>>,
    pub(crate) euler: Option<Py<PyAny>>,
    pub(crate) len: usize,
}

impl ReducedTrajectory {
    pub(crate) fn new(py: Python<'_>, t: &routh::ReducedTrajectory) -> ReducedTrajectory {
        ReducedTrajectory {
            t: PyArray1::from_slice(py, &t.t).into_any().unbind(),
            big_omega: vecs(py, &t.big_omega).into_any().unbind(),
            gamma: vecs(py, &t.gamma).into_any().unbind(),
            psi: PyArray1::from_slice(py, &t.psi).into_any().unbind(),
            psi_dot: PyArray1::from_slice(py, &t.psi_dot).into_any().unbind(),
            omega: vecs(py, &t.omega).into_any().unbind(),
            energy: PyArray1::from_slice(py, &t.energy).into_any().unbind(),
            p_psi: PyArray1::from_slice(py, &t.p_psi).into_any().unbind(),
            attitude: quaternions(py, &t.attitude),
            euler: rows3(py, &t.euler_angles()),
            len: t.len(),
        }
    }
}

attitude_methods!(ReducedTrajectory, "ReducedTrajectory");
