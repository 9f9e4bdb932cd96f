//! Periodic motions in Python: `Model.periodic_orbit`, `Model.lyapunov_family`,
//! `Model.continue_orbit`, `Model.continue_orbit_in`, `Model.period_doubled_family`,
//! `Model.switch_branch`, `Model.poincare_section`,
//! `Model.orbit_crossings`, `Model.orbit_path`, and their results `PeriodicOrbit`,
//! `OrbitFamily`, `OrbitEvent`, `OrbitParameterFamily`, `PoincareSection` (numpy arrays,
//! lower-case strings).
//!
//! The keywords of the orbit analyses are the fields of the Rust `OrbitOptions`, defaults its
//! `Default` (crate::options).

use crate::convert::{helper, model_err, model_err_unplaced, routh_err, vec3, vector3, Real};
use crate::guard::{cancellable, interruptible};
use crate::model::Model;
use crate::options::from_keywords;
use crate::results::SteadyMotion;
use crate::trajectory::Trajectory;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use routh::{Complex, OrbitOptions, Param, SectionOptions};

/// A periodic orbit of the full equations (8), a relative periodic orbit of the body: a point
/// `omega0`, `gamma0` ((3,) float64), `period`, `energy`, `p_psi`, the precession Δψ over one
/// period (`precession`, in (−π, π]), the turn Δφ about the body axis e₃ over one period
/// (`body_turn`, in (−π, π]; 0 unless the body is axially symmetric), the Floquet `multipliers`
/// μ, 1/μ ((2,) complex128), the `stability_index` k = (μ + 1/μ)/2, `stability` ("elliptic",
/// "parabolic", "hyperbolic", "inverse_hyperbolic") and `degenerate` (True: the orbit is not
/// isolated on its energy level, a planar swing or nutation of an axially symmetric body,
/// reported with k = 1 by theorem).
#[pyclass(module = "routh", frozen)]
pub struct PeriodicOrbit {
    /// ω at a point of the orbit, (3,).
    #[pyo3(get)]
    pub omega0: Py<PyAny>,
    /// γ at the same point, (3,), unit.
    #[pyo3(get)]
    pub gamma0: Py<PyAny>,
    /// The period T.
    #[pyo3(get)]
    pub period: f64,
    /// The energy (3).
    #[pyo3(get)]
    pub energy: f64,
    /// The cyclic momentum (9).
    #[pyo3(get)]
    pub p_psi: f64,
    /// Δψ over one period, in (−π, π].
    #[pyo3(get)]
    pub precession: f64,
    /// Δφ, the turn about the body axis e₃ over one period, in (−π, π]: on an axially symmetric
    /// body the orbit is periodic modulo it; 0 on any other body.
    #[pyo3(get)]
    pub body_turn: f64,
    /// μ, 1/μ, (2,) complex128.
    #[pyo3(get)]
    pub multipliers: Py<PyAny>,
    /// k = (μ + 1/μ)/2.
    #[pyo3(get)]
    pub stability_index: f64,
    /// "elliptic", "parabolic", "hyperbolic" or "inverse_hyperbolic".
    #[pyo3(get)]
    pub stability: &'static str,
    /// True: not isolated on its energy level (a planar swing or nutation of an axially
    /// symmetric body); k = 1, μ = 1/μ = 1 and "parabolic" by theorem.
    #[pyo3(get)]
    pub degenerate: bool,
    /// Half the orbit's extent in (ω, γ).
    #[pyo3(get)]
    pub amplitude: f64,
    pub(crate) inner: routh::PeriodicOrbit,
}

impl PeriodicOrbit {
    pub(crate) fn new(py: Python<'_>, o: &routh::PeriodicOrbit) -> PeriodicOrbit {
        let mu: Vec<Complex<f64>> = o.multipliers.to_vec();
        PeriodicOrbit {
            omega0: vec3(py, &o.omega0).into_any().unbind(),
            gamma0: vec3(py, &o.gamma0).into_any().unbind(),
            period: o.period,
            energy: o.energy,
            p_psi: o.p_psi,
            precession: o.precession,
            body_turn: o.body_turn,
            multipliers: PyArray1::from_vec(py, mu).into_any().unbind(),
            stability_index: o.stability_index,
            stability: o.stability.as_str(),
            degenerate: o.degenerate,
            amplitude: o.amplitude,
            inner: o.clone(),
        }
    }
}

#[pymethods]
impl PeriodicOrbit {
    fn __repr__(&self) -> String {
        format!(
            "PeriodicOrbit(period={:.10}, energy={:.10}, p_psi={}, precession={:.6}, body_turn={:.6}, stability_index={:.8}, stability='{}', degenerate={})",
            self.period,
            self.energy,
            self.p_psi,
            self.precession,
            self.body_turn,
            self.stability_index,
            self.stability,
            if self.degenerate { "True" } else { "False" }
        )
    }
}

/// A fold, branch point or period doubling of a family: `kind` ("fold", "branch_point",
/// "period_doubling"; with `nonlinear=True` also "twist_degenerate", "third_order_resonance",
/// "fourth_order_resonance"), `energy`, the `orbit` there, the stabilities `before` and `after`.
#[pyclass(module = "routh", frozen)]
pub struct OrbitEvent {
    /// "fold", "branch_point", "period_doubling" (with `nonlinear=True` also
    /// "twist_degenerate", "third_order_resonance", "fourth_order_resonance").
    #[pyo3(get)]
    pub kind: &'static str,
    /// The energy where it happens.
    #[pyo3(get)]
    pub energy: f64,
    /// The orbit there.
    #[pyo3(get)]
    pub orbit: Py<PeriodicOrbit>,
    /// The stability just before (in the family's order).
    #[pyo3(get)]
    pub before: &'static str,
    /// The stability just after.
    #[pyo3(get)]
    pub after: &'static str,
    pub(crate) inner: routh::OrbitEvent,
}

#[pymethods]
impl OrbitEvent {
    fn __repr__(&self) -> String {
        format!(
            "OrbitEvent(kind='{}', energy={:.12}, before='{}', after='{}')",
            self.kind, self.energy, self.before, self.after
        )
    }
}

/// A family of periodic orbits at one p_ψ, in the order of continuation: `orbits`
/// (list[PeriodicOrbit]), `events` (list[OrbitEvent]), `stop` (why it ended, a string, or None),
/// and the columns `energy`, `period`, `stability_index`, `precession` ((n,) float64) and
/// `stability` (list[str]). `plot()` draws the stability diagram (k against E).
#[pyclass(module = "routh", frozen)]
pub struct OrbitFamily {
    /// The orbits.
    #[pyo3(get)]
    pub orbits: Vec<Py<PeriodicOrbit>>,
    /// The events.
    #[pyo3(get)]
    pub events: Vec<Py<OrbitEvent>>,
    /// Why the family ended (None: it reached the end asked for).
    #[pyo3(get)]
    pub stop: Option<String>,
    /// The energies, (n,).
    #[pyo3(get)]
    pub energy: Py<PyAny>,
    /// The periods, (n,).
    #[pyo3(get)]
    pub period: Py<PyAny>,
    /// The stability indices k, (n,).
    #[pyo3(get)]
    pub stability_index: Py<PyAny>,
    /// The precessions Δψ, (n,).
    #[pyo3(get)]
    pub precession: Py<PyAny>,
    /// The stabilities, list[str].
    #[pyo3(get)]
    pub stability: Vec<&'static str>,
    pub(crate) inner: routh::OrbitFamily,
}

impl OrbitFamily {
    pub(crate) fn new(py: Python<'_>, f: &routh::OrbitFamily) -> PyResult<OrbitFamily> {
        let col = |g: fn(&routh::PeriodicOrbit) -> f64| {
            let v: Vec<f64> = f.orbits.iter().map(g).collect();
            PyArray1::from_vec(py, v).into_any().unbind()
        };
        let orbits = f
            .orbits
            .iter()
            .map(|o| Py::new(py, PeriodicOrbit::new(py, o)))
            .collect::<PyResult<_>>()?;
        let events = f
            .events
            .iter()
            .map(|e| {
                Py::new(
                    py,
                    OrbitEvent {
                        kind: e.kind.as_str(),
                        energy: e.energy,
                        orbit: Py::new(py, PeriodicOrbit::new(py, &e.orbit))?,
                        before: e.before.as_str(),
                        after: e.after.as_str(),
                        inner: e.clone(),
                    },
                )
            })
            .collect::<PyResult<_>>()?;
        Ok(OrbitFamily {
            orbits,
            events,
            stop: f.stop.as_ref().map(|s| s.to_string()),
            energy: col(|o| o.energy),
            period: col(|o| o.period),
            stability_index: col(|o| o.stability_index),
            precession: col(|o| o.precession),
            stability: f.orbits.iter().map(|o| o.stability.as_str()).collect(),
            inner: f.clone(),
        })
    }
}

#[pymethods]
impl OrbitFamily {
    fn __len__(&self) -> usize {
        self.orbits.len()
    }
    fn __repr__(&self) -> String {
        format!(
            "OrbitFamily({} orbits, {} events, stop={})",
            self.orbits.len(),
            self.events.len(),
            self.stop
                .as_ref()
                .map_or("None".to_string(), |s| format!("'{s}'"))
        )
    }
    /// Draws the family with matplotlib: `quantity="stability_index"` (k against E, the lines
    /// k = ±1, events marked and named) or `"period"` (T against E). Returns the axes.
    #[pyo3(signature = (ax=None, quantity="stability_index"))]
    fn plot(slf: &Bound<'_, Self>, ax: Option<Py<PyAny>>, quantity: &str) -> PyResult<Py<PyAny>> {
        helper(
            slf.py(),
            "routh._plot",
            "plot_orbit_family",
            (slf, ax, quantity),
        )
    }
}

/// A family of periodic orbits at one energy through a parameter of the model
/// (`Model.continue_orbit_in`): `family` (an `OrbitFamily`: its orbits, events and `stop`),
/// `name` (the parameter, or "p_psi"), `parameter` ((n,) float64, its value at each orbit of
/// `family.orbits`) and `event_parameter` ((k,) float64, at each event of `family.events`).
#[pyclass(module = "routh", frozen)]
pub struct OrbitParameterFamily {
    /// The parameter's name ("p_psi" for the cyclic momentum).
    #[pyo3(get)]
    pub name: String,
    /// The orbits (all at one energy), their events and why the family ended.
    #[pyo3(get)]
    pub family: Py<OrbitFamily>,
    /// The parameter at each orbit of `family.orbits`, (n,).
    #[pyo3(get)]
    pub parameter: Py<PyAny>,
    /// The parameter at each event of `family.events`, (k,).
    #[pyo3(get)]
    pub event_parameter: Py<PyAny>,
    pub(crate) inner: routh::OrbitParameterFamily,
}

impl OrbitParameterFamily {
    pub(crate) fn new(
        py: Python<'_>,
        name: String,
        f: &routh::OrbitParameterFamily,
    ) -> PyResult<OrbitParameterFamily> {
        Ok(OrbitParameterFamily {
            name,
            family: Py::new(py, OrbitFamily::new(py, &f.family)?)?,
            parameter: PyArray1::from_slice(py, &f.parameter).into_any().unbind(),
            event_parameter: PyArray1::from_slice(py, &f.event_parameter)
                .into_any()
                .unbind(),
            inner: f.clone(),
        })
    }
}

#[pymethods]
impl OrbitParameterFamily {
    fn __len__(&self) -> usize {
        self.inner.parameter.len()
    }
    fn __repr__(&self) -> String {
        let f = &self.inner;
        let span = match (f.parameter.first(), f.parameter.last()) {
            (Some(a), Some(b)) => format!("{}={a}..{b}", self.name),
            _ => self.name.clone(),
        };
        format!(
            "OrbitParameterFamily({span}, {} orbits, {} events, stop={})",
            f.family.orbits.len(),
            f.family.events.len(),
            f.family
                .stop
                .as_ref()
                .map_or("None".to_string(), |s| format!("'{s}'"))
        )
    }
}

/// A Poincaré section at (p_ψ, E): the upward crossings of the plane γ·n = 0 by many orbits, in
/// the coordinates θ (the angle of γ on the great circle n^⊥) and M_n = n·∂L/∂ω: `points`
/// (list of (k, 2) float64, one per orbit), `starts` ((m, 6): ω₀, γ₀ of each orbit), `normal`
/// ((3,)). `plot(fixed_points=None)` draws it.
#[pyclass(module = "routh", frozen)]
pub struct PoincareSection {
    /// The cyclic momentum.
    #[pyo3(get)]
    pub p_psi: f64,
    /// The energy.
    #[pyo3(get)]
    pub energy: f64,
    /// The plane's normal n, (3,).
    #[pyo3(get)]
    pub normal: Py<PyAny>,
    /// The crossings of each orbit, each (k, 2): [θ, M_n].
    #[pyo3(get)]
    pub points: Vec<Py<PyAny>>,
    /// (ω₀, γ₀) of each orbit, (m, 6).
    #[pyo3(get)]
    pub starts: Py<PyAny>,
}

#[pymethods]
impl PoincareSection {
    fn __repr__(&self) -> String {
        format!(
            "PoincareSection(p_psi={}, energy={}, {} orbits)",
            self.p_psi,
            self.energy,
            self.points.len()
        )
    }
    /// Draws the section with matplotlib (one colour per orbit, small dots), and the
    /// `fixed_points` ((k, 2), e.g. `Model.orbit_crossings(orbit)`) as larger marks. Returns the
    /// axes.
    #[pyo3(signature = (ax=None, fixed_points=None))]
    fn plot(
        slf: &Bound<'_, Self>,
        ax: Option<Py<PyAny>>,
        fixed_points: Option<Py<PyAny>>,
    ) -> PyResult<Py<PyAny>> {
        helper(
            slf.py(),
            "routh._plot",
            "plot_section",
            (slf, ax, fixed_points),
        )
    }
}

/// Rows of `N` numbers as an (n, N) float64 array (also when n = 0).
pub(crate) fn rows<const N: usize>(py: Python<'_>, rows: &[[f64; N]]) -> PyResult<Py<PyAny>> {
    let flat: Vec<f64> = rows.iter().flatten().copied().collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([rows.len(), N])
        .map_err(|e| crate::RouthError::new_err(e.to_string()))?
        .into_any()
        .unbind())
}

impl Model {
    /// A family started at an event of another (`period_doubled_family`, `switch_branch`), the
    /// GIL released while it runs.
    fn family_at_event(
        &self,
        py: Python<'_>,
        event: &OrbitEvent,
        mut opts: OrbitOptions,
        start: fn(
            &routh::Model,
            &routh::OrbitEvent,
            &routh::OrbitOptions,
        ) -> Result<routh::OrbitFamily, routh::RouthError>,
    ) -> PyResult<OrbitFamily> {
        let m = self.get()?;
        let e = event.inner.clone();
        let f = cancellable(py, |c| {
            opts.control = c;
            start(&m, &e, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        OrbitFamily::new(py, &f)
    }
}

#[pymethods]
impl Model {
    /// Correct a guess (ω, γ, T) to a periodic orbit of the full equations at the guess's
    /// energy and p_ψ: period, precession, Floquet multipliers and stability. Keywords: the
    /// fields of the Rust `OrbitOptions` (`rtol`, `atol`, `newton_tol`, `max_iter`, …).
    ///
    /// >>> o = m.periodic_orbit([0, 0, 0], [0, np.sin(0.5), -np.cos(0.5)], 6.0)
    /// >>> o.stability
    #[pyo3(signature = (omega, gamma, period, **options))]
    fn periodic_orbit(
        &self,
        py: Python<'_>,
        omega: &Bound<'_, PyAny>,
        gamma: &Bound<'_, PyAny>,
        period: Real,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PeriodicOrbit> {
        let w = vector3("omega", omega)?;
        let g = vector3("gamma", gamma)?;
        let mut opts: OrbitOptions = from_keywords("periodic_orbit", options)?;
        let m = self.get()?;
        let o = cancellable(py, |c| {
            opts.control = c;
            routh::periodic_orbit(&m, w, g, period.0, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        Ok(PeriodicOrbit::new(py, &o))
    }

    /// The Lyapunov family of mode `mode` (0: the faster frequency, 1: the slower) born at a
    /// linearly stable steady motion, followed through the energy at its p_ψ, with folds,
    /// branch points and period doublings located (and with `nonlinear=True` where the twist
    /// of the Poincaré map vanishes and where k = −1/2, 0: the resonances of order three and
    /// four, as the events "twist_degenerate", "third_order_resonance",
    /// "fourth_order_resonance"; `Model.orbit_nonlinear_stability`). Keywords: every field of
    /// the Rust `OrbitOptions` (`max_orbits`, `energy_bounds`, `max_step`, `rtol`, `nonlinear`,
    /// …), defaults its `Default`; an unknown keyword is a `TypeError` listing them.
    ///
    /// >>> f = m.lyapunov_family(hanging, 0, max_orbits=40)
    /// >>> [(e.kind, round(e.energy, 6)) for e in f.events]
    #[pyo3(signature = (motion, mode=0, **options))]
    fn lyapunov_family(
        &self,
        py: Python<'_>,
        motion: &SteadyMotion,
        mode: usize,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitFamily> {
        let mut opts: OrbitOptions = from_keywords("lyapunov_family", options)?;
        let m = self.get()?;
        let s = motion.inner.clone();
        let f = cancellable(py, |c| {
            opts.control = c;
            routh::lyapunov_family(&m, &s, mode, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        OrbitFamily::new(py, &f)
    }

    /// Follow the family through `orbit` over `energy_range` = (lo, hi), through folds.
    /// Keywords: the fields of the Rust `OrbitOptions`.
    #[pyo3(signature = (orbit, energy_range, **options))]
    fn continue_orbit(
        &self,
        py: Python<'_>,
        orbit: &PeriodicOrbit,
        energy_range: (Real, Real),
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitFamily> {
        let mut opts: OrbitOptions = from_keywords("continue_orbit", options)?;
        let m = self.get()?;
        let o = orbit.inner.clone();
        let range = (energy_range.0 .0, energy_range.1 .0);
        let f = cancellable(py, |c| {
            opts.control = c;
            routh::continue_orbit(&m, &o, range, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        OrbitFamily::new(py, &f)
    }

    /// Follow the family through `orbit` at its energy as the parameter `name` of the model
    /// goes over `s_range` = (lo, hi), through folds (the Rust `continue_orbit_in`). `name` is a
    /// scalar parameter (the orbit must be one of this model, at its value of `name`) or "p_psi"
    /// (also "momentum": the cyclic momentum, from the orbit's p_ψ). Returns an
    /// `OrbitParameterFamily` (`family`, `parameter`, `event_parameter`). Raises `ModelError` for
    /// a name that is not a scalar parameter, `RouthError` (kind "InvalidOption") for a start
    /// outside `s_range` or an orbit that is not one of this model, and the other errors of the
    /// Rust function.
    ///
    /// >>> o = m.periodic_orbit([1, 0, 0], [0, 0, -1], 5.4)
    /// >>> f = m.continue_orbit_in(o, "mgl", (1.2, 2.0))
    /// >>> f.parameter[0], f.family.period[0]
    #[pyo3(signature = (orbit, name, s_range, **options))]
    fn continue_orbit_in(
        &self,
        py: Python<'_>,
        orbit: &PeriodicOrbit,
        name: &str,
        s_range: (Real, Real),
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitParameterFamily> {
        let mut opts: OrbitOptions = from_keywords("continue_orbit_in", options)?;
        let m = self.get()?;
        let o = orbit.inner.clone();
        let s_range = (s_range.0 .0, s_range.1 .0);
        let f = if name == "p_psi" || name == "momentum" {
            let s0 = o.p_psi;
            cancellable(py, |c| {
                opts.control = c;
                routh::continue_orbit_in(|s| (m.clone(), s), &o, s0, s_range, &opts)
            })?
        } else {
            // The name and shape checked once (a ModelError), the value the orbit's start.
            let s0 = match (m.with(name, 0.0), m.get(name)) {
                (Ok(_), Some(Param::Scalar(v))) => v,
                (Err(e), _) => return Err(model_err(py, &e)),
                _ => {
                    return Err(model_err_unplaced(
                        py,
                        &format!("parameter `{name}` is not a number"),
                    ))
                }
            };
            let p = o.p_psi;
            cancellable(py, |c| {
                opts.control = c;
                // `with` of a finite value of a scalar parameter does not fail; a NaN p_ψ would
                // stop the family with an error naming s.
                let family = |s: f64| match m.with(name, s) {
                    Ok(ms) => (ms, p),
                    Err(_) => (m.clone(), f64::NAN),
                };
                routh::continue_orbit_in(family, &o, s0, s_range, &opts)
            })?
        }
        .map_err(|e| routh_err(py, &e))?;
        let name = if name == "momentum" { "p_psi" } else { name };
        OrbitParameterFamily::new(py, name.to_string(), &f)
    }

    /// The family of orbits of twice the period born at a "period_doubling" event. Keywords:
    /// the fields of the Rust `OrbitOptions`.
    #[pyo3(signature = (event, **options))]
    fn period_doubled_family(
        &self,
        py: Python<'_>,
        event: &OrbitEvent,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitFamily> {
        let opts = from_keywords("period_doubled_family", options)?;
        self.family_at_event(py, event, opts, routh::period_doubled_family)
    }

    /// The family of orbits crossing this one's family at a "branch_point" event, followed both
    /// ways from it (docs/method.md §11): at a symmetry-breaking branch point (planar swings of
    /// a body with a plane of symmetry) the orbits that leave the plane. Raises `RouthError`
    /// (kind "InvalidOption") for an event that is not a branch point, or one where no second
    /// family crosses with its energy stationary, and (kind "NoConvergence") when the crossing
    /// family's first orbit cannot be corrected.
    ///
    /// >>> f = m.lyapunov_family(hanging, 0, max_orbits=30)
    /// >>> bp = next(e for e in f.events if e.kind == "branch_point")
    /// >>> g = m.switch_branch(bp, max_orbits=20)
    #[pyo3(signature = (event, **options))]
    fn switch_branch(
        &self,
        py: Python<'_>,
        event: &OrbitEvent,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<OrbitFamily> {
        let opts = from_keywords("switch_branch", options)?;
        self.family_at_event(py, event, opts, routh::switch_branch)
    }

    /// The Poincaré section at (p_psi, energy): `orbits` orbits started on the plane γ·n = 0,
    /// each followed for `crossings` upward crossings (in parallel, the GIL released).
    /// Keywords: the fields of the Rust `SectionOptions` (`normal`, `orbits`, `crossings`,
    /// `rtol`, `atol`, `steps_per_crossing`), defaults its `Default`.
    #[pyo3(signature = (p_psi, energy, **options))]
    fn poincare_section(
        &self,
        py: Python<'_>,
        p_psi: Real,
        energy: Real,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<PoincareSection> {
        let mut opts: SectionOptions = from_keywords("poincare_section", options)?;
        let m = self.get()?;
        let s = cancellable(py, |c| {
            opts.control = c;
            routh::poincare_section(&m, p_psi.0, energy.0, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        let points = s
            .orbits
            .iter()
            .map(|o| rows(py, &o.points))
            .collect::<PyResult<_>>()?;
        let starts: Vec<[f64; 6]> = s
            .orbits
            .iter()
            .map(|o| {
                let (w, g) = (o.omega0, o.gamma0);
                [w.x, w.y, w.z, g.x, g.y, g.z]
            })
            .collect();
        let starts = rows(py, &starts)?;
        Ok(PoincareSection {
            p_psi: s.p_psi,
            energy: s.energy,
            normal: vec3(py, &s.normal).into_any().unbind(),
            points,
            starts,
        })
    }

    /// Where a periodic orbit crosses the section γ·n = 0 upwards over one period: its fixed
    /// points in the section's coordinates, (k, 2). Keywords: those of `poincare_section`.
    #[pyo3(signature = (orbit, **options))]
    fn orbit_crossings(
        &self,
        py: Python<'_>,
        orbit: &PeriodicOrbit,
        options: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<Py<PyAny>> {
        let mut opts: SectionOptions = from_keywords("orbit_crossings", options)?;
        let m = self.get()?;
        let o = orbit.inner.clone();
        let pts = cancellable(py, |c| {
            opts.control = c;
            routh::orbit_crossings(&m, &o, &opts)
        })?
        .map_err(|e| routh_err(py, &e))?;
        rows(py, &pts)
    }

    /// The orbit sampled at `n` equally spaced times over one period (with the attitude): a
    /// `Trajectory` for figures (γ on the sphere, `plot_apex()`).
    #[pyo3(signature = (orbit, n=200))]
    fn orbit_path(&self, py: Python<'_>, orbit: &PeriodicOrbit, n: usize) -> PyResult<Trajectory> {
        let m = self.get()?;
        let o = orbit.inner.clone();
        let t = interruptible(py, move || routh::orbit_path(&m, &o, n))?
            .map_err(|e| routh_err(py, &e))?;
        Ok(Trajectory::new(py, &t))
    }
}
