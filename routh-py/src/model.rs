//! `routh.Model`: the run-time model and the analyses on it.

use crate::convert::{model_err, param, param_to_py, routh_err, vector3, Real};
use crate::guard::{cancellable, detached, interruptible};
use crate::latex::{aligned, LatexFormulas, SympyFormulas};
use crate::nonlinear::NonlinearReport;
use crate::options::from_keywords;
use crate::progress::Progress;
use crate::results::{Certificate, CircleReport, Diagram, StabilityReport, SteadyMotion};
use crate::trajectory::{ReducedTrajectory, Trajectory};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use routh::sim::Output;
use routh::{CertifyOptions, ContinuationOptions, Param, SimOptions};

/// A rigid-body model: a Lagrangian in the language of `#[derive(Lagrangian)]` and the values
/// of its parameters (float, 3-sequence or 3x3 nested sequence / numpy array).
///
/// >>> top = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), "
/// ...                   "potential = mgl * gamma.z", {"inertia": [1, 1, 1.25], "mgl": 1.0})
/// >>> [m.gamma for m in top.steady_motions(3.0)]
#[pyclass(module = "routh", frozen)]
pub struct Model {
    pub(crate) inner: std::sync::RwLock<routh::Model>,
}

impl Model {
    pub(crate) fn get(&self) -> PyResult<routh::Model> {
        self.inner
            .read()
            .map(|m| m.clone())
            .map_err(|_| crate::RouthError::new_err("the model's lock is poisoned"))
    }
    pub(crate) fn wrap(m: routh::Model) -> Model {
        Model {
            inner: std::sync::RwLock::new(m),
        }
    }
}

/// The options of a simulation from its keywords, `times` the recorded output.
pub(crate) fn sim_options(
    function: &str,
    times: Option<Vec<f64>>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<SimOptions> {
    let mut o: SimOptions = from_keywords(function, options)?;
    if let Some(t) = times {
        o.output = Output::Times(t);
    }
    Ok(o)
}

#[pymethods]
impl Model {
    #[new]
    #[pyo3(signature = (lagrangian, parameters=None))]
    fn new(
        py: Python<'_>,
        lagrangian: &str,
        parameters: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Model> {
        let mut params: Vec<(String, Param)> = Vec::new();
        if let Some(d) = parameters {
            for (k, v) in d.iter() {
                let name: String = k.extract()?;
                let p = param(&name, &v)?;
                params.push((name, p));
            }
        }
        let refs: Vec<(&str, Param)> = params.iter().map(|(n, p)| (n.as_str(), *p)).collect();
        let text = lagrangian.to_string();
        let m = detached(py, move || routh::Model::new(&text, &refs))?
            .map_err(|e| model_err(py, &e))?;
        Ok(Model::wrap(m))
    }

    /// A model from the text of a TOML file (`[model] lagrangian = ...`, `[parameters]`,
    /// optional `[latex]` symbols). Raises `ModelError` with the line and column.
    ///
    /// >>> m = routh.Model.from_toml(open("examples/models/heavy_top.toml").read())
    #[staticmethod]
    fn from_toml(py: Python<'_>, text: &str) -> PyResult<Model> {
        let t = text.to_string();
        let m =
            detached(py, move || routh::Model::from_toml(&t))?.map_err(|e| model_err(py, &e))?;
        Ok(Model::wrap(m))
    }

    /// A model from a TOML file (see `from_toml`); the Rust `Model::from_file`. `load` is an
    /// alias.
    ///
    /// >>> gyrostat = routh.Model.from_file("examples/models/gyrostat.toml")
    #[staticmethod]
    pub(crate) fn from_file(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Model> {
        let m =
            detached(py, move || routh::Model::from_file(&path))?.map_err(|e| model_err(py, &e))?;
        Ok(Model::wrap(m))
    }

    /// Set a parameter in place (same shape as before: float, 3-vector or 3x3).
    ///
    /// >>> top.set("mgl", 2.0)
    fn set(&self, py: Python<'_>, name: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let p = param(name, value)?;
        let mut g = self
            .inner
            .write()
            .map_err(|_| crate::RouthError::new_err("the model's lock is poisoned"))?;
        g.set(name, p).map_err(|e| model_err(py, &e))
    }

    /// A copy with some parameters changed; the model itself is unchanged.
    ///
    /// >>> heavier = top.with_params(mgl=2.0, inertia=[1.0, 1.0, 1.5])
    #[pyo3(signature = (**kw))]
    fn with_params(&self, py: Python<'_>, kw: Option<&Bound<'_, PyDict>>) -> PyResult<Model> {
        let mut m = self.get()?;
        if let Some(d) = kw {
            for (k, v) in d.iter() {
                let name: String = k.extract()?;
                let p = param(&name, &v)?;
                m.set(&name, p).map_err(|e| model_err(py, &e))?;
            }
        }
        Ok(Model::wrap(m))
    }

    /// The value of a parameter (float or numpy array), or None.
    fn get_param(&self, py: Python<'_>, name: &str) -> PyResult<Option<Py<PyAny>>> {
        Ok(self.get()?.get(name).map(|p| param_to_py(py, &p)))
    }

    /// The parameters as a dict.
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (n, p) in self.get()?.parameters() {
            d.set_item(n, param_to_py(py, p))?;
        }
        Ok(d)
    }

    /// The LaTeX symbols of the TOML file's `[latex]` table (name → symbol).
    #[getter]
    fn latex_symbols(&self) -> PyResult<std::collections::BTreeMap<String, String>> {
        Ok(self.get()?.latex_symbols().clone())
    }

    /// The simplified formulas as text: `{"L": ..., "U_r": ..., "psi_dot": ...}` (the
    /// Lagrangian, the amended potential (34) and ψ̇ at rest (38)).
    #[getter]
    fn formulas(&self) -> PyResult<std::collections::BTreeMap<&'static str, String>> {
        let m = self.get()?;
        let [l, u, p] = m.formulas();
        Ok([
            ("L", l.to_string()),
            ("U_r", u.to_string()),
            ("psi_dot", p.to_string()),
        ]
        .into_iter()
        .collect())
    }

    /// The Lagrangian's text.
    #[getter]
    fn lagrangian(&self) -> PyResult<String> {
        Ok(self.get()?.lagrangian_text().to_string())
    }

    /// The amended potential U_r(γ, p_ψ) (34) at a unit vertical `gamma` (| |γ| − 1 | ≤ 1e-8,
    /// the tolerance of `simulate` and `classify`). Raises `RouthError` for a non-finite input
    /// (kind "NonFinite"), a γ off the unit sphere (kind "NonUnitGamma") or where the formula
    /// has no finite value (kind "NonFiniteModel").
    ///
    /// >>> top.amended_potential([0, 0, 1], 2.0)      # p²/(2C) + mgl
    /// 2.6
    fn amended_potential(
        &self,
        py: Python<'_>,
        gamma: &Bound<'_, PyAny>,
        p_psi: Real,
    ) -> PyResult<f64> {
        let p_psi = p_psi.0;
        use routh::Routhian;
        let g = unit_gamma_and_p_psi(py, gamma, p_psi)?;
        let u = self.get()?.amended_potential(&g, p_psi);
        if !u.is_finite() {
            let e = routh::RouthError::NonFiniteModel {
                what: "amended_potential",
                gamma: [g.x, g.y, g.z],
            };
            return Err(routh_err(py, &e));
        }
        Ok(u)
    }

    /// The steady motions at cyclic momentum `p_psi` (paper (33)): the critical points of
    /// U_r on the sphere |γ| = 1, as a list of `SteadyMotion`.
    ///
    /// >>> [m.gamma for m in top.steady_motions(3.0)]
    fn steady_motions(&self, py: Python<'_>, p_psi: Real) -> PyResult<Vec<SteadyMotion>> {
        let p_psi = p_psi.0;
        let m = self.get()?;
        let v =
            detached(py, || routh::steady_motions(&m, p_psi))?.map_err(|e| routh_err(py, &e))?;
        Ok(v.into_iter().map(|inner| SteadyMotion { inner }).collect())
    }

    /// The stability of a steady motion (sections 4–5, errata E5/E8) as a `StabilityReport`.
    ///
    /// >>> top.classify(top.steady_motions(3.0)[0]).verdict
    fn classify(&self, py: Python<'_>, motion: &SteadyMotion) -> PyResult<StabilityReport> {
        let m = self.get()?;
        let s = motion.inner.clone();
        let r = detached(py, || routh::classify(&m, &s))?.map_err(|e| routh_err(py, &e))?;
        Ok(StabilityReport::new(py, &r))
    }

    /// A circle of steady motions of a body symmetric about the body axis `axis` (3 numbers),
    /// decided modulo the symmetry by the doubly amended potential, where `classify` can only
    /// say "degenerate". Raises `RouthError` if the model is not symmetric about `axis` at the
    /// motion, or if the motion lies on the axis.
    ///
    /// >>> c = [m for m in top.steady_motions(3.0) if not m.isolated][0]
    /// >>> top.classify_circle(c, (0, 0, 1)).verdict
    /// 'stable'
    fn classify_circle(
        &self,
        py: Python<'_>,
        motion: &SteadyMotion,
        axis: &Bound<'_, PyAny>,
    ) -> PyResult<CircleReport> {
        let axis = vector3("axis", axis)?;
        let m = self.get()?;
        let s = motion.inner.clone();
        let r = detached(py, || routh::classify_circle(&m, &s, &axis))?
            .map_err(|e| routh_err(py, &e))?;
        CircleReport::new(py, &r)
    }

    /// The nonlinear (Lyapunov) stability of a steady motion from the Birkhoff normal form of
    /// the reduced Hamiltonian to order four: Arnold–Moser away from resonances, Markeev's
    /// criteria at 1:2 and 1:3, as a `NonlinearReport`. Keywords: the fields of the Rust
    /// `NonlinearOptions` (those of its `classify` by their own names), defaults its `Default`.
    ///
    /// >>> m = max(top.steady_motions(2.2), key=lambda s: s.gamma[2])  # sleeping (γ₃ = 1)
    /// >>> top.nonlinear_stability(m).verdict   # gyroscopically stabilised: Arnold–Moser
    /// 'lyapunov_stable'
    /// >>> top.nonlinear_stability(top.steady_motions(2.2)[0]).verdict   # the hanging top
    /// 'secularly_stable'
    #[pyo3(signature = (motion, **options))]
    fn nonlinear_stability(
        &self,
        py: Python<'_>,
        motion: &SteadyMotion,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<NonlinearReport> {
        let opts: routh::NonlinearOptions = from_keywords("nonlinear_stability", options)?;
        let m = self.get()?;
        let s = motion.inner.clone();
        let r = detached(py, || routh::nonlinear_stability(&m, &s, &opts))?
            .map_err(|e| routh_err(py, &e))?;
        NonlinearReport::new(py, &r)
    }

    /// The bifurcation diagram over the momentum p_ψ ∈ (lo, hi). Keywords: the fields of the
    /// Rust `ContinuationOptions`, defaults its `Default`; `progress=True` shows the count of evaluations (tqdm
    /// if installed, else a line on stderr). The GIL is released during the work.
    ///
    /// >>> d = top.bifurcation_diagram((0.0, 5.0))
    /// >>> [(e.kind, round(e.s, 6)) for e in d.events]
    /// [('hamiltonian_hopf', 2.0), ('branch_point', 2.5)]
    #[pyo3(signature = (range, *, progress=false, **options))]
    fn bifurcation_diagram(
        &self,
        py: Python<'_>,
        range: (Real, Real),
        progress: bool,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Diagram> {
        let range = (range.0 .0, range.1 .0);
        let opts: ContinuationOptions = from_keywords("bifurcation_diagram", options)?;
        let m = self.get()?;
        let bar = Progress::new(py, progress, "steady-motion evaluations")?;
        // Ctrl-C sets the diagram's cancel flag: it stops at its next continuation step.
        let mut opts = opts;
        let d = cancellable(py, |c| {
            opts.control = c;
            routh::bifurcation_diagram(
                |p| {
                    if let Some(b) = &bar {
                        b.tick();
                    }
                    (m.clone(), p)
                },
                range,
                &opts,
            )
        });
        if let Some(b) = &bar {
            b.close(py);
        }
        Diagram::new(py, &d?.map_err(|e| routh_err(py, &e))?)
    }

    /// Integrate the full equations (8) from (ω₀, γ₀) to `t_end`; the Rust `simulate_full`.
    /// `simulate` is an alias. Keywords: the fields of the Rust `SimOptions` (`rtol`, `atol`,
    /// `max_steps`, `h_max`, `method`, `attitude`, …), defaults its `Default` (DOP853). `times`:
    /// record exactly at these times (dense output) instead of at every step; `attitude=True`: also integrate the attitude (`tr.attitude`, quaternions
    /// (x, y, z, w), `tr.euler_angles()`, `tr.plot_apex()`).
    ///
    /// >>> tr = top.simulate_full([0, 0.3, 5.0], [0.6, 0, 0.8], 10.0, attitude=True,
    /// ...                        times=np.linspace(0, 10, 2001))
    /// >>> tr.omega.shape
    /// (2001, 3)
    #[pyo3(signature = (omega0, gamma0, t_end, *, times=None, **options))]
    pub(crate) fn simulate_full(
        &self,
        py: Python<'_>,
        omega0: &Bound<'_, PyAny>,
        gamma0: &Bound<'_, PyAny>,
        t_end: Real,
        times: Option<Vec<f64>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Trajectory> {
        let opts = sim_options("simulate_full", times, options)?;
        let t_end = t_end.0;
        let w = vector3("omega0", omega0)?;
        let g = vector3("gamma0", gamma0)?;
        let m = self.get()?;
        let t = interruptible(py, move || routh::simulate_full(&m, w, g, t_end, &opts))?
            .map_err(|e| routh_err(py, &e))?;
        Ok(Trajectory::new(py, &t))
    }

    /// Integrate the reduced equations (13) from (Ω₀, γ₀) at momentum `p_psi` to `t_end`, and
    /// reconstruct ψ, ψ̇, ω = Ω + ψ̇γ (and the attitude with `attitude=True`, by (15)).
    /// Keywords as `simulate`.
    ///
    /// >>> red = top.simulate_reduced([0, 0.3, 0], [0.6, 0, 0.8], 3.0, 10.0)
    /// >>> red.big_omega.shape == (len(red.t), 3)
    /// True
    #[pyo3(signature = (big_omega0, gamma0, p_psi, t_end, *, times=None, **options))]
    #[allow(clippy::too_many_arguments)]
    fn simulate_reduced(
        &self,
        py: Python<'_>,
        big_omega0: &Bound<'_, PyAny>,
        gamma0: &Bound<'_, PyAny>,
        p_psi: Real,
        t_end: Real,
        times: Option<Vec<f64>>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<ReducedTrajectory> {
        let opts = sim_options("simulate_reduced", times, options)?;
        let (p_psi, t_end) = (p_psi.0, t_end.0);
        let w = vector3("big_omega0", big_omega0)?;
        let g = vector3("gamma0", gamma0)?;
        let m = self.get()?;
        let t = interruptible(py, move || {
            routh::simulate_reduced(&m, w, g, p_psi, t_end, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        Ok(ReducedTrajectory::new(py, &t))
    }

    /// A certified enumeration of the steady motions at `p_psi` (interval arithmetic): when
    /// `c.complete`, `c.motions` are all the steady motions, proven; the Rust
    /// `steady_motions_certified`. `certify` is an alias. Keywords default to the
    /// Rust `CertifyOptions::default()` (initial_split 4, min_width 1e-3, max_boxes 400 000,
    /// refine_iterations 30); what is left when `max_boxes` runs out is `c.undecided`.
    ///
    /// >>> c = top.steady_motions_certified(2.2)
    /// >>> c.complete, len(c.motions)
    /// (True, 2)
    #[pyo3(signature = (p_psi, *, initial_split=None, min_width=None, max_boxes=None,
                        refine_iterations=None))]
    pub(crate) fn steady_motions_certified(
        &self,
        py: Python<'_>,
        p_psi: Real,
        initial_split: Option<usize>,
        min_width: Option<f64>,
        max_boxes: Option<usize>,
        refine_iterations: Option<usize>,
    ) -> PyResult<Certificate> {
        let p_psi = p_psi.0;
        let d = CertifyOptions::default();
        let opts = CertifyOptions {
            initial_split: initial_split.unwrap_or(d.initial_split),
            min_width: min_width.unwrap_or(d.min_width),
            max_boxes: max_boxes.unwrap_or(d.max_boxes),
            refine_iterations: refine_iterations.unwrap_or(d.refine_iterations),
        };
        let m = self.get()?;
        let c = interruptible(py, move || {
            routh::steady_motions_certified(&m, p_psi, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        let mut motions = Vec::with_capacity(c.motions.len());
        for cm in &c.motions {
            motions.push(Py::new(
                py,
                SteadyMotion {
                    inner: cm.steady.clone(),
                },
            )?);
        }
        Ok(Certificate {
            complete: c.complete,
            motions,
            p_psi: c.p_psi,
            boxes: c.boxes,
            undecided: c.undecided.len(),
        })
    }

    /// The derived formulas in LaTeX (`routh.LatexFormulas`: `lagrangian`, `psi_dot`,
    /// `routhian`, `amended_potential`, `a`, `g`, `c`), with the TOML's `[latex]` symbols.
    ///
    /// >>> f = top.latex()
    /// >>> print(f.amended_potential)
    fn latex(&self) -> PyResult<LatexFormulas> {
        Ok(LatexFormulas::new(self.get()?.latex()))
    }

    /// The same seven formulas in SymPy's syntax (`routh.SympyFormulas`), parameters by their
    /// names (`inertia_3` for a component, from 1).
    ///
    /// >>> top.sympy().amended_potential
    fn sympy(&self) -> PyResult<SympyFormulas> {
        Ok(SympyFormulas::new(self.get()?.sympy()))
    }

    /// The seven formulas as SymPy objects: a dict name → expression (`sympy.Matrix` for `a`,
    /// `g`, `c`), with real symbols `omega1 … gamma3 p_psi` (`Omega1 …` in `psi_dot` and
    /// `routhian`) and the parameters by their names; `self.sympy().to_sympy()`. Raises
    /// ImportError without SymPy.
    ///
    /// >>> U = top.to_sympy()["amended_potential"]
    fn to_sympy(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let f = Bound::new(py, SympyFormulas::new(self.get()?.sympy()))?;
        crate::convert::helper(py, "routh._sympy", "to_sympy", (f,))
    }

    /// The values of the seven formulas computed by the model's generated code (not from the
    /// formulas' text) at `omega` (Ω in `psi_dot` and `routhian`), `gamma` and `p_psi`: a dict
    /// with the floats `lagrangian` L(ω, γ), `psi_dot` ψ̇(Ω, γ, p_ψ), `routhian` R(Ω, γ, p_ψ),
    /// `amended_potential` U_r(γ, p_ψ), and the (3, 3) arrays `a`, `g`, `c` of (64) at Ω = 0.
    /// What the formulas of `sympy()` and `latex()` evaluate to (at a unit `gamma`: the
    /// formulas are simplified with |γ|² = 1). Raises `RouthError` for a non-finite input
    /// (kind "NonFinite", naming it) and a γ off the unit sphere (kind "NonUnitGamma", as
    /// `amended_potential`).
    ///
    /// >>> top.formula_values([0.1, 0.2, 0.3], [0, 0, 1], 2.0)["amended_potential"]
    /// 2.6
    fn formula_values<'py>(
        &self,
        py: Python<'py>,
        omega: &Bound<'_, PyAny>,
        gamma: &Bound<'_, PyAny>,
        p_psi: Real,
    ) -> PyResult<Bound<'py, PyDict>> {
        use routh::{Lagrangian, Routhian};
        let p_psi = p_psi.0;
        let w = vector3("omega", omega)?;
        if let Some(&value) = w.iter().find(|x| !x.is_finite()) {
            let e = routh::RouthError::NonFinite {
                what: "omega",
                value,
            };
            return Err(routh_err(py, &e));
        }
        let g = unit_gamma_and_p_psi(py, gamma, p_psi)?;
        let m = self.get()?;
        let d = PyDict::new(py);
        d.set_item("lagrangian", m.lagrangian(&w, &g))?;
        d.set_item("psi_dot", m.psi_dot(&w, &g, p_psi))?;
        d.set_item("routhian", m.routhian(&w, &g, p_psi))?;
        d.set_item("amended_potential", m.amended_potential(&g, p_psi))?;
        let sys = m.gyroscopic_system(&g, p_psi);
        for (name, x) in [("a", sys.a), ("g", sys.g), ("c", sys.c)] {
            d.set_item(name, param_to_py(py, &Param::Matrix(x)))?;
        }
        Ok(d)
    }

    /// Jupyter shows a model as its Routh function R (14) and amended potential U_r (34).
    fn _repr_latex_(&self) -> PyResult<String> {
        let f = self.get()?.latex();
        Ok(aligned(&[
            ("R", &f.routhian),
            ("U_r", &f.amended_potential),
        ]))
    }

    fn __repr__(&self) -> PyResult<String> {
        let m = self.get()?;
        let names: Vec<&str> = m.parameters().iter().map(|(n, _)| n.as_str()).collect();
        Ok(format!("routh.Model(parameters={names:?})"))
    }

    fn __copy__(&self) -> PyResult<Model> {
        Ok(Model::wrap(self.get()?))
    }

    #[pyo3(signature = (*_args))]
    fn __deepcopy__(&self, _args: &Bound<'_, PyTuple>) -> PyResult<Model> {
        Ok(Model::wrap(self.get()?))
    }
}

/// `gamma` as a 3-vector, after checking that it and `p_psi` are finite (`NonFinite` naming
/// the input) and that `| |γ| − 1 | ≤ UNIT_GAMMA_TOL` (`NonUnitGamma`, as the analyses).
fn unit_gamma_and_p_psi(
    py: Python<'_>,
    gamma: &Bound<'_, PyAny>,
    p_psi: f64,
) -> PyResult<routh::nalgebra::Vector3<f64>> {
    let g = vector3("gamma", gamma)?;
    let non_finite = |what: &'static str, value: f64| routh::RouthError::NonFinite { what, value };
    if let Some(&x) = g.iter().find(|x| !x.is_finite()) {
        return Err(routh_err(py, &non_finite("gamma", x)));
    }
    if !p_psi.is_finite() {
        return Err(routh_err(py, &non_finite("p_psi", p_psi)));
    }
    let tol = routh::validate::UNIT_GAMMA_TOL;
    let norm = g.norm();
    if (norm - 1.0).abs() > tol {
        let e = routh::RouthError::NonUnitGamma {
            what: "gamma",
            norm,
            tol,
        };
        return Err(routh_err(py, &e));
    }
    Ok(g)
}

/// Seconds per call of `steady_motions` + `classify` of every motion, timed in Rust (for the
/// benchmark of docs/performance.md): `n` repetitions at `p_psi`.
#[pyfunction]
pub fn _bench_rust(py: Python<'_>, model: &Model, p_psi: f64, n: usize) -> PyResult<f64> {
    let m = model.get()?;
    detached(py, || {
        let start = std::time::Instant::now();
        for _ in 0..n.max(1) {
            let ms = routh::steady_motions(&m, p_psi)?;
            for s in &ms {
                std::hint::black_box(routh::classify(&m, s)?);
            }
        }
        Ok(start.elapsed().as_secs_f64() / n.max(1) as f64)
    })?
    .map_err(|e: routh::RouthError| routh_err(py, &e))
}
