//! Orbital stability beyond linear and orbit charts in Python (docs/method.md §12):
//! `Model.orbit_nonlinear_stability` and its `OrbitNonlinearReport`; `routh.orbit_chart` and
//! `Model.orbit_chart` and their `OrbitChart` (with its `OrbitChartCurve`s). Kinds and verdicts
//! are lower-case strings, arrays numpy, as in the rest of the package.

use crate::convert::{helper, model_err, model_err_unplaced, routh_err, vector3, Real, RouthError};
use crate::family::PyFamily;
use crate::guard::{cancellable, cooperative};
use crate::model::Model;
use crate::options::from_keywords;
use crate::orbits::{rows, OrbitFamily, PeriodicOrbit};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use routh::{OrbitChartOptions, OrbitNonlinearOptions, Param};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

/// The orbital stability of a periodic orbit beyond the linear test
/// (`Model.orbit_nonlinear_stability`): the `orbit`, its `rotation_number` ρ ∈ (0, 1) (the turn
/// of the Poincaré map's linear part, cos 2πρ = k; NaN unless elliptic), the `twist` τ = dρ/dA
/// (A the symplectic area enclosed by an invariant curve, not A/2π; NaN unless elliptic), the
/// `resonance` ("third", "fourth" or None), the `verdict` ("orbitally_stable", "unstable",
/// "undecided"), why (`reason`) and `area_defect` (a check of the jets: 0 for an exactly
/// area-preserving map; NaN unless elliptic).
///
/// >>> r = m.orbit_nonlinear_stability(f.orbits[3])
/// >>> r.verdict, r.twist
#[pyclass(module = "routh", frozen)]
pub struct OrbitNonlinearReport {
    /// The orbit analysed.
    #[pyo3(get)]
    pub orbit: Py<PeriodicOrbit>,
    /// ρ ∈ (0, 1), cos 2πρ = k; NaN unless the orbit is elliptic.
    #[pyo3(get)]
    pub rotation_number: f64,
    /// τ = dρ/dA at A = 0 (A the enclosed symplectic area); NaN unless elliptic.
    #[pyo3(get)]
    pub twist: f64,
    /// "third" (k = −1/2), "fourth" (k = 0) within `resonance_tol`, or None.
    #[pyo3(get)]
    pub resonance: Option<&'static str>,
    /// "orbitally_stable", "unstable" or "undecided".
    #[pyo3(get)]
    pub verdict: &'static str,
    /// Why: the theorem or criterion applied, or what left the test undecided.
    #[pyo3(get)]
    pub reason: String,
    /// |Re(c/λ)|/|c/λ| of the normal form's cubic coefficient: 0 for an exactly
    /// area-preserving map (NaN unless elliptic).
    #[pyo3(get)]
    pub area_defect: f64,
    pub(crate) inner: routh::OrbitNonlinearReport,
}

impl OrbitNonlinearReport {
    pub(crate) fn new(
        py: Python<'_>,
        r: &routh::OrbitNonlinearReport,
    ) -> PyResult<OrbitNonlinearReport> {
        Ok(OrbitNonlinearReport {
            orbit: Py::new(py, PeriodicOrbit::new(py, &r.orbit))?,
            rotation_number: r.rotation_number,
            twist: r.twist,
            resonance: r.resonance.map(|x| x.as_str()),
            verdict: r.verdict.as_str(),
            reason: r.reason.clone(),
            area_defect: r.area_defect,
            inner: r.clone(),
        })
    }
}

#[pymethods]
impl OrbitNonlinearReport {
    fn __repr__(&self) -> String {
        format!(
            "OrbitNonlinearReport(verdict='{}', rotation_number={:.10}, twist={:.6e}, resonance={}, reason='{}')",
            self.verdict,
            self.rotation_number,
            self.twist,
            self.resonance
                .map_or("None".to_string(), |r| format!("'{r}'")),
            self.reason
        )
    }
}

/// A curve of an orbit chart: where the family's orbits meet one kind of event, `kind` (an
/// orbit event kind: "fold", "branch_point" (k = 1), "period_doubling" (k = −1),
/// "third_order_resonance" (k = −1/2), "fourth_order_resonance" (k = 0), "twist_degenerate"
/// (τ = 0)), and its `points` ((n, 2) float64: (x, h), h = E − E_s(x), in the order of x).
#[pyclass(module = "routh", frozen)]
pub struct OrbitChartCurve {
    /// The event kind along the curve.
    #[pyo3(get)]
    pub kind: &'static str,
    /// (x, h) of each point, (n, 2).
    #[pyo3(get)]
    pub points: Py<PyAny>,
    pub(crate) inner: routh::OrbitChartCurve,
}

impl OrbitChartCurve {
    pub(crate) fn new(py: Python<'_>, c: &routh::OrbitChartCurve) -> PyResult<OrbitChartCurve> {
        Ok(OrbitChartCurve {
            kind: c.kind.as_str(),
            points: rows(py, &c.points)?,
            inner: c.clone(),
        })
    }
}

#[pymethods]
impl OrbitChartCurve {
    fn __len__(&self) -> usize {
        self.inner.points.len()
    }
    fn __repr__(&self) -> String {
        format!(
            "OrbitChartCurve(kind='{}', {} points)",
            self.kind,
            self.inner.points.len()
        )
    }
}

/// The chart of a mode's Lyapunov family over a parameter x and the energy h = E − E_s(x)
/// above the steady motion (`routh.orbit_chart`, `Model.orbit_chart`): `parameter` (the name of
/// x), `x` and `steady_energy` ((nx,) float64; NaN where no steady motion was found), the
/// `families` (an `OrbitFamily` per x, None where it failed, the reason in `failures`), the
/// `curves` (list[OrbitChartCurve]) where the orbits change linear stability, meet the
/// resonances of order three and four and lose their twist, `stop` (None, or why the chart ended
/// early) and `samples` ((n, 3) float64: x, h, k of every orbit). `plot()` draws it;
/// `to_pandas()` has a row per orbit, `curves_frame()` a row per curve point.
#[pyclass(module = "routh", frozen)]
pub struct OrbitChart {
    /// The name of the parameter x (the axis's label).
    #[pyo3(get)]
    pub parameter: String,
    /// The values of x, (nx,).
    #[pyo3(get)]
    pub x: Py<PyAny>,
    /// E_s(x), the energy of the steady motion at each x, (nx,) (NaN where none was found).
    #[pyo3(get)]
    pub steady_energy: Py<PyAny>,
    /// The family at each x (None where the steady motion or the family failed).
    #[pyo3(get)]
    pub families: Vec<Option<Py<OrbitFamily>>>,
    /// Why the steady motion or the family at each x failed (None where it did not).
    #[pyo3(get)]
    pub failures: Vec<Option<String>>,
    /// The curves, each of one event kind.
    #[pyo3(get)]
    pub curves: Vec<Py<OrbitChartCurve>>,
    /// Why the chart ended early (None: every x was done).
    #[pyo3(get)]
    pub stop: Option<String>,
    /// (x, h, k) of every orbit of every family, (n, 3).
    #[pyo3(get)]
    pub samples: Py<PyAny>,
    pub(crate) inner: routh::OrbitChart,
}

impl OrbitChart {
    pub(crate) fn new(
        py: Python<'_>,
        parameter: String,
        c: &routh::OrbitChart,
    ) -> PyResult<OrbitChart> {
        let families = c
            .families
            .iter()
            .map(|f| {
                f.as_ref()
                    .map(|f| Py::new(py, OrbitFamily::new(py, f)?))
                    .transpose()
            })
            .collect::<PyResult<_>>()?;
        let curves = c
            .curves
            .iter()
            .map(|k| Py::new(py, OrbitChartCurve::new(py, k)?))
            .collect::<PyResult<_>>()?;
        Ok(OrbitChart {
            parameter,
            x: PyArray1::from_slice(py, &c.x).into_any().unbind(),
            steady_energy: PyArray1::from_slice(py, &c.steady_energy)
                .into_any()
                .unbind(),
            families,
            failures: c.failures.clone(),
            curves,
            stop: c.stop.as_ref().map(|s| s.to_string()),
            samples: rows(py, &c.samples())?,
            inner: c.clone(),
        })
    }
}

#[pymethods]
impl OrbitChart {
    fn __len__(&self) -> usize {
        self.inner.x.len()
    }
    fn __repr__(&self) -> String {
        let c = &self.inner;
        let span = match (c.x.first(), c.x.last()) {
            (Some(a), Some(b)) => format!("{}={a}..{b}", self.parameter),
            _ => self.parameter.clone(),
        };
        let orbits: usize = c.families.iter().flatten().map(|f| f.orbits.len()).sum();
        let failed = c.failures.iter().filter(|f| f.is_some()).count();
        format!(
            "OrbitChart({span}, {} values, {orbits} orbits, {} curves, {failed} failed, stop={})",
            c.x.len(),
            c.curves.len(),
            self.stop
                .as_ref()
                .map_or("None".to_string(), |s| format!("'{s}'"))
        )
    }
    /// Draws the chart with matplotlib: the orbits as small marks coloured by their linear
    /// stability (the regions), the curves as lines, one dash pattern per kind, and a legend of
    /// what is drawn; x labelled with the parameter's name (or `xlabel`), y with h = E − E_s.
    /// Returns the axes.
    #[pyo3(signature = (ax=None, xlabel=None))]
    fn plot(
        slf: &Bound<'_, Self>,
        ax: Option<Py<PyAny>>,
        xlabel: Option<String>,
    ) -> PyResult<Py<PyAny>> {
        helper(
            slf.py(),
            "routh._plot",
            "plot_orbit_chart",
            (slf, ax, xlabel),
        )
    }
    /// The curves' points as a pandas DataFrame: columns `kind`, `curve` (the index in
    /// `curves`), `x`, `h`, one row per point.
    fn curves_frame(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._frames", "curves_frame", (slf,))
    }
}

/// A `routh.RouthError` of kind "InvalidOption".
fn invalid(py: Python<'_>, what: &str, reason: &str) -> PyErr {
    let err = RouthError::new_err(format!("invalid option {what}: {reason}"));
    let _ = err.value(py).setattr("kind", "InvalidOption");
    err
}

/// A family `x -> (Model, p_psi)` of the chart.
type ChartFamily = Box<dyn Fn(f64) -> (routh::Model, f64) + Send + Sync>;

/// The family `x -> (model with name = x, p_psi)` of a run-time model (or `x -> (model, x)` for
/// "p_psi"/"momentum"), the name checked once (a `ModelError`).
fn parameter_family(
    py: Python<'_>,
    m: &routh::Model,
    name: &str,
    momentum: Option<f64>,
) -> PyResult<ChartFamily> {
    if name == "p_psi" || name == "momentum" {
        if momentum.is_some() {
            return Err(invalid(
                py,
                "momentum",
                "the chart goes through p_psi itself: momentum cannot be given too",
            ));
        }
        let m = m.clone();
        return Ok(Box::new(move |x| (m.clone(), x)));
    }
    match (m.with(name, 0.0), m.get(name)) {
        (Ok(_), Some(Param::Scalar(_))) => {}
        (Err(e), _) => return Err(model_err(py, &e)),
        _ => {
            return Err(model_err_unplaced(
                py,
                &format!("parameter `{name}` is not a number"),
            ))
        }
    }
    let (m, name, momentum) = (m.clone(), name.to_string(), momentum.unwrap_or(0.0));
    // `with` of a finite value of a scalar parameter does not fail; a NaN p_ψ would make the
    // chart record a failure at that x naming it.
    Ok(Box::new(move |x| match m.with(&name, x) {
        Ok(mx) => (mx, momentum),
        Err(_) => (m.clone(), f64::NAN),
    }))
}

/// The work of `orbit_chart` on a run-time model swept through its parameter `name`.
#[allow(clippy::too_many_arguments)]
fn chart_of_model(
    py: Python<'_>,
    m: &routh::Model,
    name: &str,
    gamma_guess: routh::Vector3<f64>,
    mode: usize,
    x_range: (f64, f64),
    excess_energy: (f64, f64),
    momentum: Option<f64>,
    mut opts: OrbitChartOptions,
) -> PyResult<OrbitChart> {
    let family = parameter_family(py, m, name, momentum)?;
    let c = cancellable(py, |c| {
        opts.orbit.control = c;
        routh::orbit_chart(&family, gamma_guess, mode, x_range, excess_energy, &opts)
    })?
    .map_err(|e| routh_err(py, &e))?;
    let name = if name == "momentum" { "p_psi" } else { name };
    OrbitChart::new(py, name.to_string(), &c)
}

/// The chart of the Lyapunov family of `mode` (0: the faster frequency ω₁, 1: the slower) over
/// a parameter x ∈ `x_range` and the energy h = E − E_s(x) ∈ `excess_energy` above the steady
/// motion (docs/method.md §12; the Rust `orbit_chart`): at each of `nx` values of x the steady
/// motion near `gamma_guess` (followed from one x to the next), its family with the linear and
/// nonlinear events located, then each curve continued in (x, h) from those events
/// (docs/method.md §12.4).
///
/// `family` is a `Model` — x is then its scalar parameter named `parameter` (or "p_psi": the
/// momentum), the momentum `momentum` (default 0) — or a callable `x -> (Model, p_psi)`
/// (`parameter` then only names the axis, default "x"; `momentum` must not be given). The other
/// keywords are the fields of the Rust `OrbitChartOptions`, defaults its `Default`: `nx`,
/// `join_tol` (the widest window, a fraction of the chart's ranges, in which a curve's next
/// point is searched about its prediction) and those of each family, the fields of its `orbit` (`max_orbits`
/// (default 200), `max_step`, `rtol`, …; not `energy_bounds` and `nonlinear`, which the chart
/// sets). A failure at one x is recorded in
/// `failures`, not raised; invalid ranges or options raise `RouthError` (kind "InvalidOption"),
/// an unknown parameter `ModelError`; an exception raised by a callable family is re-raised.
///
/// >>> c = routh.orbit_chart(m, [0, 0, -1], (1.9, 2.1), (0.0, 2.8), parameter="b", nx=5)
/// >>> [(k.kind, len(k)) for k in c.curves]
#[pyfunction]
#[pyo3(signature = (family, gamma_guess, x_range, excess_energy, *, mode=0, parameter=None,
                    momentum=None, **options))]
#[allow(clippy::too_many_arguments)]
pub fn orbit_chart(
    py: Python<'_>,
    family: &Bound<'_, PyAny>,
    gamma_guess: &Bound<'_, PyAny>,
    x_range: (Real, Real),
    excess_energy: (Real, Real),
    mode: usize,
    parameter: Option<String>,
    momentum: Option<Real>,
    options: Option<&Bound<'_, PyDict>>,
) -> PyResult<OrbitChart> {
    let g = vector3("gamma_guess", gamma_guess)?;
    let x_range = (x_range.0 .0, x_range.1 .0);
    let excess = (excess_energy.0 .0, excess_energy.1 .0);
    let opts: OrbitChartOptions = from_keywords("orbit_chart", options)?;
    if let Ok(model) = family.cast::<Model>() {
        let Some(name) = parameter else {
            return Err(invalid(
                py,
                "parameter",
                "name the parameter of the model the chart goes through (parameter=\"...\", \
                 or \"p_psi\")",
            ));
        };
        let m = model.get().get()?;
        let p = momentum.map(|r| r.0);
        return chart_of_model(py, &m, &name, g, mode, x_range, excess, p, opts);
    }
    if !family.is_callable() {
        return Err(pyo3::exceptions::PyTypeError::new_err(format!(
            "orbit_chart: family must be a routh.Model or a callable x -> (Model, p_psi), not {}",
            family.get_type().name()?
        )));
    }
    if momentum.is_some() {
        return Err(invalid(
            py,
            "momentum",
            "a callable family gives p_psi itself: momentum is for a Model only",
        ));
    }
    let name = parameter.unwrap_or_else(|| "x".to_string());
    let fam = PyFamily::new(py, family.clone().unbind(), (x_range.0, 0.0), false, false)?;
    let cancel = Arc::new(AtomicBool::new(false));
    let mut opts = opts;
    opts.orbit.control = routh::RunControl::default().with_cancel(cancel.clone());
    let r = cooperative(py, &cancel, || {
        routh::orbit_chart(
            |x| fam.call((x, 0.0), false),
            g,
            mode,
            x_range,
            excess,
            &opts,
        )
    });
    let r = match r {
        Ok(r) => r,
        Err(e) => return Err(fam.finish(py, e)),
    };
    match r {
        Ok(c) => {
            fam.close(py);
            if let Some(e) = fam.take_error() {
                return Err(e);
            }
            OrbitChart::new(py, name, &c)
        }
        Err(e) => {
            let other = routh_err(py, &e);
            Err(fam.finish(py, other))
        }
    }
}

#[pymethods]
impl Model {
    /// The orbital stability of a periodic orbit of this model beyond the linear test
    /// (docs/method.md §12; the Rust `orbit_nonlinear_stability`): the rotation number and the
    /// twist of the isoenergetic Poincaré map from its Taylor expansion to order three (exact
    /// jets of the flow), and the verdict of Moser's twist theorem or of the resonances of
    /// order three and four. Keywords: the fields of the Rust `OrbitNonlinearOptions`, defaults
    /// its `Default`: `rtol`, `atol` (the jets' integration), `resonance_tol` (|k + 1/2| or |k|
    /// at most this is a resonance), `twist_tol` (a twist this small relative to its terms counts
    /// as zero), `criterion_tol`, `max_steps` (per period). Raises `RouthError` (kind "InvalidOption")
    /// for a bad value, and the orbit's own checks (an orbit that is not one: a non-finite or
    /// non-positive period, γ₀ not unit, …).
    ///
    /// >>> f = m.lyapunov_family(hanging, 0, max_orbits=8)
    /// >>> r = m.orbit_nonlinear_stability(f.orbits[-1])
    /// >>> r.verdict, r.rotation_number, r.twist
    #[pyo3(signature = (orbit, **options))]
    fn orbit_nonlinear_stability(
        &self,
        py: Python<'_>,
        orbit: &PeriodicOrbit,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitNonlinearReport> {
        let mut opts: OrbitNonlinearOptions = from_keywords("orbit_nonlinear_stability", options)?;
        let m = self.get()?;
        let o = orbit.inner.clone();
        let r = cancellable(py, |c| {
            opts.control = c;
            routh::orbit_nonlinear_stability(&m, &o, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        OrbitNonlinearReport::new(py, &r)
    }

    /// The orbit chart of this model through its scalar parameter `parameter` (or "p_psi"):
    /// `routh.orbit_chart(m, gamma_guess, x_range, excess_energy, parameter=parameter, ...)`,
    /// at the momentum `momentum` (default 0).
    ///
    /// >>> c = m.orbit_chart("b", [0, 0, -1], (1.9, 2.1), (0.0, 2.8), nx=5)
    /// >>> c.plot()
    #[pyo3(signature = (parameter, gamma_guess, x_range, excess_energy, *, mode=0, momentum=None,
                        **options))]
    #[allow(clippy::too_many_arguments)]
    fn orbit_chart(
        &self,
        py: Python<'_>,
        parameter: &str,
        gamma_guess: &Bound<'_, PyAny>,
        x_range: (Real, Real),
        excess_energy: (Real, Real),
        mode: usize,
        momentum: Option<Real>,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitChart> {
        let g = vector3("gamma_guess", gamma_guess)?;
        let opts: OrbitChartOptions = from_keywords("orbit_chart", options)?;
        let m = self.get()?;
        chart_of_model(
            py,
            &m,
            parameter,
            g,
            mode,
            (x_range.0 .0, x_range.1 .0),
            (excess_energy.0 .0, excess_energy.1 .0),
            momentum.map(|r| r.0),
            opts,
        )
    }
}
