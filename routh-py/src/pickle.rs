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
//!   `OrbitEvent`, `OrbitNonlinearReport`, `OrbitChartCurve`; `OrbitParameterFamily` and
//!   `OrbitChart` with their parameter's name): the JSON of the Rust value (serde, numbers round-trip exactly), made into
//!   the Python object again by the constructor the analyses use.
//! - The classes that hold numpy arrays and strings: their fields (numpy pickles the arrays
//!   bit for bit, NaN included; nested result objects pickle themselves).

use crate::convert::{model_err, param, RouthError};
use crate::latex::LatexFormulas;
use crate::model::Model;
use crate::nonlinear::NonlinearReport;
use crate::orbit_nonlinear::{OrbitChart, OrbitChartCurve, OrbitNonlinearReport};
use crate::orbits::{
    OrbitEvent, OrbitFamily, OrbitParameterFamily, PeriodicOrbit, PoincareSection,
};
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

/// The Rust result of type `$t` from the JSON string `$state` (its NaN and infinities as
/// `null`, as `serde_json` writes them, or as the strings `"NaN"`, `"Infinity"`, `"-Infinity"`
/// of `to_json`: [`crate::lenient`]).
macro_rules! from_json {
    ($t:ty, $state:expr) => {{
        let s: String = $state.extract()?;
        crate::lenient::from_str::<$t>(&s)
            .map_err(|e| RouthError::new_err(format!("unpickling: {e}")))
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
        "OrbitParameterFamily" => {
            let (name, json): (String, Bound<'_, PyAny>) = state.extract()?;
            let f = from_json!(routh::OrbitParameterFamily, json)?;
            OrbitParameterFamily::new(py, name, &f)?.into_py_any(py)
        }
        "OrbitNonlinearReport" => {
            let r = from_json!(routh::OrbitNonlinearReport, state)?;
            OrbitNonlinearReport::new(py, &r)?.into_py_any(py)
        }
        "OrbitChartCurve" => {
            let c = from_json!(routh::OrbitChartCurve, state)?;
            OrbitChartCurve::new(py, &c)?.into_py_any(py)
        }
        "OrbitChart" => {
            let (name, json): (String, Bound<'_, PyAny>) = state.extract()?;
            let c = from_json!(routh::OrbitChart, json)?;
            OrbitChart::new(py, name, &c)?.into_py_any(py)
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

/// `__reduce__` of each class: `(routh._restore, (kind, state))` with `kind` the class's name
/// (what [`_restore`] matches on) and `state` the expression after `=>`, in which `$s` is the
/// object and `$py` the GIL token.
macro_rules! reduce_by {
    ($($ty:ident |$s:ident, $py:ident| => $state:expr;)*) => {$(
        #[pymethods]
        impl $ty {
            fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
                let ($s, $py) = (self, py);
                reduce(py, stringify!($ty), $state)
            }
        }
    )*};
}

fn opt(py: Python<'_>, o: &Option<Py<PyAny>>) -> Option<Py<PyAny>> {
    o.as_ref().map(|a| a.clone_ref(py))
}

fn refs<T>(py: Python<'_>, v: &[Py<T>]) -> Vec<Py<T>> {
    v.iter().map(|x| x.clone_ref(py)).collect()
}

reduce_by! {
    Model |o, py| => {
        let m = o.get()?;
        let params = m
            .parameters()
            .iter()
            .map(|(n, p)| Ok((n.clone(), param_plain(py, p)?)))
            .collect::<PyResult<Vec<_>>>()?;
        (
            m.lagrangian_text().to_string(),
            params,
            m.symmetric().to_vec(),
            m.latex_symbols().clone(),
        )
    };
    SteadyMotion |o, _py| => json!(&o.inner)?;
    PeriodicOrbit |o, _py| => json!(&o.inner)?;
    OrbitFamily |o, _py| => json!(&o.inner)?;
    OrbitEvent |o, _py| => json!(&o.inner)?;
    OrbitParameterFamily |o, _py| => (o.name.clone(), json!(&o.inner)?);
    OrbitNonlinearReport |o, _py| => json!(&o.inner)?;
    OrbitChartCurve |o, _py| => json!(&o.inner)?;
    OrbitChart |o, _py| => (o.parameter.clone(), json!(&o.inner)?);
    StabilityReport |o, py| => (
        o.verdict,
        o.degree_of_instability,
        o.restricted_hessian_eigenvalues.clone_ref(py),
        o.f2_roots.clone_ref(py),
    );
    CircleReport |o, py| => (
        o.verdict,
        o.curvature,
        o.across,
        o.momentum_term,
        o.axis_momentum,
        o.axis.clone_ref(py),
        o.report.clone_ref(py),
    );
    Branch |o, py| => (
        o.s.clone_ref(py),
        o.gamma.clone_ref(py),
        o.p_psi.clone_ref(py),
        o.energy.clone_ref(py),
        o.verdicts.clone(),
        o.isolated,
    );
    Event |o, py| => (
        o.kind,
        o.s,
        o.gamma.clone_ref(py),
        o.branch,
        o.before,
        o.after,
        o.resonance.clone(),
        o.nonlinear,
    );
    Diagram |o, py| => (
        refs(py, &o.branches),
        refs(py, &o.events),
        o.stop.clone(),
        o.checks.clone(),
    );
    Boundary |o, py| => (o.kind, o.points.clone_ref(py));
    Atlas |o, py| => (
        o.x.clone_ref(py),
        o.y.clone_ref(py),
        o.verdicts.clone(),
        o.lost.clone(),
        o.stop.clone(),
        refs(py, &o.boundaries),
    );
    Trajectory |o, py| => (
        o.t.clone_ref(py),
        o.omega.clone_ref(py),
        o.gamma.clone_ref(py),
        o.energy.clone_ref(py),
        o.p_psi.clone_ref(py),
        opt(py, &o.attitude),
        opt(py, &o.euler),
        o.len,
    );
    ReducedTrajectory |o, py| => (
        (
            o.t.clone_ref(py),
            o.big_omega.clone_ref(py),
            o.gamma.clone_ref(py),
            o.psi.clone_ref(py),
            o.psi_dot.clone_ref(py),
            o.omega.clone_ref(py),
            o.energy.clone_ref(py),
            o.p_psi.clone_ref(py),
        ),
        opt(py, &o.attitude),
        opt(py, &o.euler),
        o.len,
    );
    Certificate |o, py| => (
        o.complete,
        refs(py, &o.motions),
        o.p_psi,
        o.boxes,
        o.undecided,
    );
    NonlinearReport |o, py| => (
        o.verdict,
        o.reason.clone(),
        o.linear.clone_ref(py),
        o.frequencies.clone_ref(py),
        o.krein_signs,
        o.normal_form.clone_ref(py),
        o.arnold_determinant,
        o.resonance.clone(),
        o.resonance_distance,
    );
    LatexFormulas |o, _py| => (
        o.lagrangian.clone(),
        o.psi_dot.clone(),
        o.routhian.clone(),
        o.amended_potential.clone(),
        o.a.clone(),
        o.g.clone(),
        o.c.clone(),
    );
    PoincareSection |o, py| => (
        o.p_psi,
        o.energy,
        o.normal.clone_ref(py),
        refs(py, &o.points),
        o.starts.clone_ref(py),
    );
}
