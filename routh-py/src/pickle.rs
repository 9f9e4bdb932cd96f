//! Pickling (and `copy`/`deepcopy`) of `routh.Model` and of every result class.
//!
//! Each class's `__reduce__` returns `(routh._restore, (kind, state))`; `routh._restore` (a
//! Python function of the package, so that pickle finds it by name) calls [`_restore`] here.
//!
//! - `Model`: its text, parameters (in order, as plain floats and lists), symmetric list and
//!   LaTeX symbols. The receiving process builds the model again from them; the compiled model
//!   is cached per process ([`model_from_parts`]), so unpickling the same model many times
//!   (one copy per task) derives it once and shares its JIT-compiled tapes, and only the
//!   parameter values are set.
//! - The classes that wrap a Rust result (`SteadyMotion`, `PeriodicOrbit`, `OrbitFamily`,
//!   `OrbitEvent`): the JSON of the Rust value (serde, numbers round-trip exactly), made into
//!   the Python object again by the constructor the analyses use.
//! - The classes that hold numpy arrays and strings: their fields (numpy pickles the arrays
//!   bit for bit, NaN included; nested result objects pickle themselves).

use crate::convert::{model_err, param, RouthError};
use crate::latex::LatexFormulas;
use crate::model::Model;
use crate::nonlinear::NonlinearReport;
use crate::orbits::{OrbitEvent, OrbitFamily, PeriodicOrbit, PoincareSection};
use crate::results::{
    Atlas, Boundary, Branch, Certificate, CircleReport, Diagram, Event, StabilityReport,
    SteadyMotion,
};
use crate::trajectory::{ReducedTrajectory, Trajectory};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use pyo3::IntoPyObjectExt;
use routh::Param;
use std::collections::{BTreeMap, HashMap};
use std::sync::{Mutex, OnceLock};

/// Every string a result's `&'static str` field can hold (verdicts, event kinds, stabilities).
const NAMES: &[&str] = &[
    "secularly_stable",
    "gyroscopically_stabilized",
    "unstable",
    "degenerate",
    "lyapunov_stable",
    "undecided",
    "stable",
    "fold",
    "branch_point",
    "hamiltonian_hopf",
    "arnold_degenerate",
    "resonance",
    "period_doubling",
    "elliptic",
    "parabolic",
    "hyperbolic",
    "inverse_hyperbolic",
];

/// The `&'static str` equal to `s`, or an error (a state not made by `__reduce__`).
fn name(s: &str) -> PyResult<&'static str> {
    NAMES
        .iter()
        .copied()
        .find(|n| *n == s)
        .ok_or_else(|| RouthError::new_err(format!("unpickling: unknown name {s:?}")))
}

fn names(v: Vec<String>) -> PyResult<Vec<&'static str>> {
    v.iter().map(|s| name(s)).collect()
}

/// `(routh._restore, (kind, state))`.
fn reduce<'py, S>(py: Python<'py>, kind: &str, state: S) -> PyResult<Bound<'py, PyTuple>>
where
    S: IntoPyObject<'py>,
{
    let f = py.import("routh")?.getattr("_restore")?;
    let state = state.into_bound_py_any(py)?;
    let args = PyTuple::new(py, [kind.into_bound_py_any(py)?, state])?;
    PyTuple::new(py, [f, args.into_any()])
}

/// The JSON of a Rust result (serde; `float_roundtrip`: numbers come back equal).
macro_rules! json {
    ($v:expr) => {
        serde_json::to_string($v).map_err(|e| RouthError::new_err(format!("pickling: {e}")))
    };
}

/// The Rust result of type `$t` from the JSON string `$state`.
macro_rules! from_json {
    ($t:ty, $state:expr) => {{
        let s: String = $state.extract()?;
        serde_json::from_str::<$t>(&s).map_err(|e| RouthError::new_err(format!("unpickling: {e}")))
    }};
}

/// A parameter as plain Python: a float, a list of 3 or 3 lists of 3.
fn param_plain(py: Python<'_>, p: &Param) -> PyResult<Py<PyAny>> {
    match p {
        Param::Scalar(x) => x.into_py_any(py),
        Param::Vector(v) => vec![v.x, v.y, v.z].into_py_any(py),
        Param::Matrix(m) => {
            let rows: Vec<Vec<f64>> = (0..3)
                .map(|i| (0..3).map(|j| m[(i, j)]).collect())
                .collect();
            rows.into_py_any(py)
        }
    }
}

fn shape(p: &Param) -> char {
    match p {
        Param::Scalar(_) => 's',
        Param::Vector(_) => 'v',
        Param::Matrix(_) => 'm',
    }
}

/// The compiled models of this process, by text, symmetric list, LaTeX symbols and parameter
/// names and shapes (what compilation depends on; the values are set on a clone).
fn cache() -> &'static Mutex<HashMap<String, routh::Model>> {
    static CACHE: OnceLock<Mutex<HashMap<String, routh::Model>>> = OnceLock::new();
    CACHE.get_or_init(|| Mutex::new(HashMap::new()))
}

/// The most models kept in the per-process cache (it is emptied when full).
const CACHE_SIZE: usize = 64;

/// The model of these parts: a clone of the cached model of the same text with the values set
/// (sharing its compiled tapes), else built and cached.
pub(crate) fn model_from_parts(
    text: &str,
    params: &[(String, Param)],
    symmetric: &[String],
    latex: BTreeMap<String, String>,
) -> Result<routh::Model, routh::ModelError> {
    let shapes: Vec<(&str, char)> = params.iter().map(|(n, p)| (n.as_str(), shape(p))).collect();
    let key = format!("{text:?}\u{0}{symmetric:?}\u{0}{latex:?}\u{0}{shapes:?}");
    if let Ok(c) = cache().lock() {
        if let Some(m) = c.get(&key) {
            let mut m = m.clone();
            for (n, p) in params {
                m.set(n, *p)?;
            }
            return Ok(m);
        }
    }
    let refs: Vec<(&str, Param)> = params.iter().map(|(n, p)| (n.as_str(), *p)).collect();
    let sym: Vec<&str> = symmetric.iter().map(String::as_str).collect();
    let m = routh::Model::with_symmetric(text, &refs, &sym)?.with_latex_symbols(latex);
    if let Ok(mut c) = cache().lock() {
        if c.len() >= CACHE_SIZE {
            c.clear();
        }
        c.insert(key, m.clone());
    }
    Ok(m)
}

/// Makes a pickled object again: `kind` names its class, `state` is what its `__reduce__` gave.
#[pyfunction]
pub fn _restore(py: Python<'_>, kind: &str, state: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    match kind {
        "Model" => {
            type State = (
                String,
                Vec<(String, Py<PyAny>)>,
                Vec<String>,
                BTreeMap<String, String>,
            );
            let (text, ps, symmetric, latex): State = state.extract()?;
            let mut params = Vec::with_capacity(ps.len());
            for (n, v) in ps {
                let p = param(&n, v.bind(py))?;
                params.push((n, p));
            }
            let m =
                crate::guard::detached(py, || model_from_parts(&text, &params, &symmetric, latex))?
                    .map_err(|e| model_err(py, &e))?;
            Model::wrap(m).into_py_any(py)
        }
        "SteadyMotion" => SteadyMotion {
            inner: from_json!(routh::SteadyMotion, state)?,
        }
        .into_py_any(py),
        "PeriodicOrbit" => {
            let o = from_json!(routh::PeriodicOrbit, state)?;
            PeriodicOrbit::new(py, &o).into_py_any(py)
        }
        "OrbitFamily" => {
            let f = from_json!(routh::OrbitFamily, state)?;
            OrbitFamily::new(py, &f)?.into_py_any(py)
        }
        "OrbitEvent" => {
            let e = from_json!(routh::OrbitEvent, state)?;
            OrbitEvent {
                kind: e.kind.as_str(),
                energy: e.energy,
                orbit: Py::new(py, PeriodicOrbit::new(py, &e.orbit))?,
                before: e.before.as_str(),
                after: e.after.as_str(),
                inner: e,
            }
            .into_py_any(py)
        }
        "StabilityReport" => {
            let (v, degree, eig, roots): (String, usize, Py<PyAny>, Py<PyAny>) = state.extract()?;
            StabilityReport {
                verdict: name(&v)?,
                degree_of_instability: degree,
                restricted_hessian_eigenvalues: eig,
                f2_roots: roots,
            }
            .into_py_any(py)
        }
        "CircleReport" => {
            type State = (String, f64, f64, f64, f64, Py<PyAny>, Py<StabilityReport>);
            let (v, curvature, across, momentum_term, axis_momentum, axis, report): State =
                state.extract()?;
            CircleReport {
                verdict: name(&v)?,
                curvature,
                across,
                momentum_term,
                axis_momentum,
                axis,
                report,
            }
            .into_py_any(py)
        }
        "Branch" => {
            type State = (
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Vec<String>,
                bool,
            );
            let (s, gamma, p_psi, energy, verdicts, isolated): State = state.extract()?;
            Branch {
                s,
                gamma,
                p_psi,
                energy,
                verdicts: names(verdicts)?,
                isolated,
            }
            .into_py_any(py)
        }
        "Event" => {
            type State = (
                String,
                f64,
                Py<PyAny>,
                usize,
                String,
                String,
                Option<String>,
                Option<(String, String, String)>,
            );
            let (k, s, gamma, branch, before, after, resonance, nonlinear): State =
                state.extract()?;
            let nonlinear = match nonlinear {
                Some((a, b, c)) => Some((name(&a)?, name(&b)?, name(&c)?)),
                None => None,
            };
            Event {
                kind: name(&k)?,
                s,
                gamma,
                branch,
                before: name(&before)?,
                after: name(&after)?,
                resonance,
                nonlinear,
            }
            .into_py_any(py)
        }
        "Diagram" => {
            type State = (
                Vec<Py<Branch>>,
                Vec<Py<Event>>,
                Option<String>,
                Vec<(f64, usize, usize)>,
            );
            let (branches, events, stop, checks): State = state.extract()?;
            Diagram {
                branches,
                events,
                stop,
                checks,
            }
            .into_py_any(py)
        }
        "Boundary" => {
            let (k, points): (String, Py<PyAny>) = state.extract()?;
            Boundary {
                kind: name(&k)?,
                points,
            }
            .into_py_any(py)
        }
        "Atlas" => {
            type State = (
                Py<PyAny>,
                Py<PyAny>,
                Vec<Vec<Option<String>>>,
                Vec<Vec<bool>>,
                Option<String>,
                Vec<Py<Boundary>>,
            );
            let (x, y, verdicts, lost, stop, boundaries): State = state.extract()?;
            let verdicts = verdicts
                .into_iter()
                .map(|col| {
                    col.into_iter()
                        .map(|v| v.map(|s| name(&s)).transpose())
                        .collect::<PyResult<Vec<_>>>()
                })
                .collect::<PyResult<Vec<_>>>()?;
            Atlas {
                x,
                y,
                verdicts,
                lost,
                stop,
                boundaries,
            }
            .into_py_any(py)
        }
        "Trajectory" => {
            type State = (
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Option<Py<PyAny>>,
                Option<Py<PyAny>>,
                usize,
            );
            let (t, omega, gamma, energy, p_psi, attitude, euler, len): State = state.extract()?;
            Trajectory {
                t,
                omega,
                gamma,
                energy,
                p_psi,
                attitude,
                euler,
                len,
            }
            .into_py_any(py)
        }
        "ReducedTrajectory" => {
            type Arrays = (
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
                Py<PyAny>,
            );
            type State = (Arrays, Option<Py<PyAny>>, Option<Py<PyAny>>, usize);
            let ((t, big_omega, gamma, psi, psi_dot, omega, energy, p_psi), attitude, euler, len): State =
                state.extract()?;
            ReducedTrajectory {
                t,
                big_omega,
                gamma,
                psi,
                psi_dot,
                omega,
                energy,
                p_psi,
                attitude,
                euler,
                len,
            }
            .into_py_any(py)
        }
        "Certificate" => {
            type State = (bool, Vec<Py<SteadyMotion>>, f64, usize, usize);
            let (complete, motions, p_psi, boxes, undecided): State = state.extract()?;
            Certificate {
                complete,
                motions,
                p_psi,
                boxes,
                undecided,
            }
            .into_py_any(py)
        }
        "NonlinearReport" => {
            type State = (
                String,
                String,
                Py<StabilityReport>,
                Py<PyAny>,
                (i8, i8),
                Py<PyAny>,
                f64,
                Option<String>,
                f64,
            );
            let (v, reason, linear, frequencies, krein_signs, normal_form, d, resonance, dist): State =
                state.extract()?;
            NonlinearReport {
                verdict: name(&v)?,
                reason,
                linear,
                frequencies,
                krein_signs,
                normal_form,
                arnold_determinant: d,
                resonance,
                resonance_distance: dist,
            }
            .into_py_any(py)
        }
        "LatexFormulas" => {
            let (lagrangian, psi_dot, routhian, amended_potential, a, g, c): (
                String,
                String,
                String,
                String,
                String,
                String,
                String,
            ) = state.extract()?;
            LatexFormulas {
                lagrangian,
                psi_dot,
                routhian,
                amended_potential,
                a,
                g,
                c,
            }
            .into_py_any(py)
        }
        "PoincareSection" => {
            type State = (f64, f64, Py<PyAny>, Vec<Py<PyAny>>, Py<PyAny>);
            let (p_psi, energy, normal, points, starts): State = state.extract()?;
            PoincareSection {
                p_psi,
                energy,
                normal,
                points,
                starts,
            }
            .into_py_any(py)
        }
        other => Err(RouthError::new_err(format!(
            "unpickling: unknown class {other:?}"
        ))),
    }
}

#[pymethods]
impl Model {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let m = self.get()?;
        let params = m
            .parameters()
            .iter()
            .map(|(n, p)| Ok((n.clone(), param_plain(py, p)?)))
            .collect::<PyResult<Vec<_>>>()?;
        let state = (
            m.lagrangian_text().to_string(),
            params,
            m.symmetric().to_vec(),
            m.latex_symbols().clone(),
        );
        reduce(py, "Model", state)
    }
}

#[pymethods]
impl SteadyMotion {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "SteadyMotion", json!(&self.inner)?)
    }
}

#[pymethods]
impl PeriodicOrbit {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "PeriodicOrbit", json!(&self.inner)?)
    }
}

#[pymethods]
impl OrbitFamily {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "OrbitFamily", json!(&self.inner)?)
    }
}

#[pymethods]
impl OrbitEvent {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "OrbitEvent", json!(&self.inner)?)
    }
}

#[pymethods]
impl StabilityReport {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.verdict,
            self.degree_of_instability,
            self.restricted_hessian_eigenvalues.clone_ref(py),
            self.f2_roots.clone_ref(py),
        );
        reduce(py, "StabilityReport", state)
    }
}

#[pymethods]
impl CircleReport {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.verdict,
            self.curvature,
            self.across,
            self.momentum_term,
            self.axis_momentum,
            self.axis.clone_ref(py),
            self.report.clone_ref(py),
        );
        reduce(py, "CircleReport", state)
    }
}

#[pymethods]
impl Branch {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.s.clone_ref(py),
            self.gamma.clone_ref(py),
            self.p_psi.clone_ref(py),
            self.energy.clone_ref(py),
            self.verdicts.clone(),
            self.isolated,
        );
        reduce(py, "Branch", state)
    }
}

#[pymethods]
impl Event {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.kind,
            self.s,
            self.gamma.clone_ref(py),
            self.branch,
            self.before,
            self.after,
            self.resonance.clone(),
            self.nonlinear,
        );
        reduce(py, "Event", state)
    }
}

#[pymethods]
impl Diagram {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let branches: Vec<Py<Branch>> = self.branches.iter().map(|b| b.clone_ref(py)).collect();
        let events: Vec<Py<Event>> = self.events.iter().map(|e| e.clone_ref(py)).collect();
        let state = (branches, events, self.stop.clone(), self.checks.clone());
        reduce(py, "Diagram", state)
    }
}

#[pymethods]
impl Boundary {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce(py, "Boundary", (self.kind, self.points.clone_ref(py)))
    }
}

#[pymethods]
impl Atlas {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let boundaries: Vec<Py<Boundary>> =
            self.boundaries.iter().map(|b| b.clone_ref(py)).collect();
        let state = (
            self.x.clone_ref(py),
            self.y.clone_ref(py),
            self.verdicts.clone(),
            self.lost.clone(),
            self.stop.clone(),
            boundaries,
        );
        reduce(py, "Atlas", state)
    }
}

fn opt(py: Python<'_>, o: &Option<Py<PyAny>>) -> Option<Py<PyAny>> {
    o.as_ref().map(|a| a.clone_ref(py))
}

#[pymethods]
impl Trajectory {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.t.clone_ref(py),
            self.omega.clone_ref(py),
            self.gamma.clone_ref(py),
            self.energy.clone_ref(py),
            self.p_psi.clone_ref(py),
            opt(py, &self.attitude),
            opt(py, &self.euler),
            self.len,
        );
        reduce(py, "Trajectory", state)
    }
}

#[pymethods]
impl ReducedTrajectory {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let arrays = (
            self.t.clone_ref(py),
            self.big_omega.clone_ref(py),
            self.gamma.clone_ref(py),
            self.psi.clone_ref(py),
            self.psi_dot.clone_ref(py),
            self.omega.clone_ref(py),
            self.energy.clone_ref(py),
            self.p_psi.clone_ref(py),
        );
        let state = (
            arrays,
            opt(py, &self.attitude),
            opt(py, &self.euler),
            self.len,
        );
        reduce(py, "ReducedTrajectory", state)
    }
}

#[pymethods]
impl Certificate {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let motions: Vec<Py<SteadyMotion>> = self.motions.iter().map(|m| m.clone_ref(py)).collect();
        let state = (
            self.complete,
            motions,
            self.p_psi,
            self.boxes,
            self.undecided,
        );
        reduce(py, "Certificate", state)
    }
}

#[pymethods]
impl NonlinearReport {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.verdict,
            self.reason.clone(),
            self.linear.clone_ref(py),
            self.frequencies.clone_ref(py),
            self.krein_signs,
            self.normal_form.clone_ref(py),
            self.arnold_determinant,
            self.resonance.clone(),
            self.resonance_distance,
        );
        reduce(py, "NonlinearReport", state)
    }
}

#[pymethods]
impl LatexFormulas {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let state = (
            self.lagrangian.clone(),
            self.psi_dot.clone(),
            self.routhian.clone(),
            self.amended_potential.clone(),
            self.a.clone(),
            self.g.clone(),
            self.c.clone(),
        );
        reduce(py, "LatexFormulas", state)
    }
}

#[pymethods]
impl PoincareSection {
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let points: Vec<Py<PyAny>> = self.points.iter().map(|p| p.clone_ref(py)).collect();
        let state = (
            self.p_psi,
            self.energy,
            self.normal.clone_ref(py),
            points,
            self.starts.clone_ref(py),
        );
        reduce(py, "PoincareSection", state)
    }
}
