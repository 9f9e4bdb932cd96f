//! The result classes: steady motions, reports, diagrams, atlases, trajectories, certificates.
//! Arrays are built once, when the result is made, and handed out as numpy arrays.

use crate::convert::{event_kind, helper, nonlinear_verdict, vec3, vecs, verdict};
use numpy::{Complex64, PyArray1, PyArray2};
use pyo3::prelude::*;

/// A steady motion (paper (33)): the vertical `gamma` (body frame, (3,) array), the cyclic
/// momentum `p_psi`, the spin `psi_dot` (38), the multiplier `mu`, the `energy` (3), the amended
/// potential `amended_potential` (34) and whether it is `isolated` (not on a circle of them).
///
/// >>> m = top.steady_motions(3.0)[0]
/// >>> m.gamma, m.psi_dot, m.energy
#[pyclass(module = "routh", frozen)]
pub struct SteadyMotion {
    pub(crate) inner: routh::SteadyMotion,
}

#[pymethods]
impl SteadyMotion {
    /// The vertical in the body frame, a unit (3,) float64 array.
    #[getter]
    fn gamma<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        vec3(py, &self.inner.gamma)
    }
    /// The cyclic momentum p_ψ (9).
    #[getter]
    fn p_psi(&self) -> f64 {
        self.inner.p_psi
    }
    /// The spin ψ̇ about the vertical (38).
    #[getter]
    fn psi_dot(&self) -> f64 {
        self.inner.psi_dot
    }
    /// The Lagrange multiplier μ of |γ|² = 1 in (32).
    #[getter]
    fn mu(&self) -> f64 {
        self.inner.mu
    }
    /// The energy (3) of the steady motion.
    #[getter]
    fn energy(&self) -> f64 {
        self.inner.energy
    }
    /// The amended potential U_r(γ, p_ψ) (34).
    #[getter]
    fn amended_potential(&self) -> f64 {
        self.inner.amended_potential
    }
    /// Whether the steady motion is isolated (false on a circle of steady motions).
    #[getter]
    fn isolated(&self) -> bool {
        self.inner.isolated
    }
    /// A small HTML table (Jupyter).
    fn _repr_html_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._display", "motion_html", (slf,))
    }
    fn __repr__(&self) -> String {
        let g = self.inner.gamma;
        format!(
            "SteadyMotion(gamma=[{:.6}, {:.6}, {:.6}], p_psi={}, psi_dot={:.6}, energy={:.6}, isolated={})",
            g.x,
            g.y,
            g.z,
            self.inner.p_psi,
            self.inner.psi_dot,
            self.inner.energy,
            if self.inner.isolated { "True" } else { "False" }
        )
    }
}

/// The stability of a steady motion (sections 4–5): `verdict` ("secularly_stable",
/// "gyroscopically_stabilized", "unstable", "degenerate"), `degree_of_instability`,
/// `restricted_hessian_eigenvalues` ((2,) float64) and `f2_roots` ((4,) complex128).
///
/// >>> r = top.classify(top.steady_motions(3.0)[0])
/// >>> r.verdict, r.degree_of_instability, r.f2_roots
#[pyclass(module = "routh", frozen, get_all)]
pub struct StabilityReport {
    /// One of "secularly_stable", "gyroscopically_stabilized", "unstable", "degenerate".
    pub verdict: &'static str,
    /// The number of negative eigenvalues of the restricted second variation (62)–(63).
    pub degree_of_instability: usize,
    /// The eigenvalues of the restricted second variation, (2,) float64.
    pub restricted_hessian_eigenvalues: Py<PyAny>,
    /// The roots λ of the characteristic polynomial f₂, (4,) complex128.
    pub f2_roots: Py<PyAny>,
}

impl StabilityReport {
    pub(crate) fn new(py: Python<'_>, r: &routh::StabilityReport) -> StabilityReport {
        let roots: Vec<Complex64> = r
            .f2_roots
            .iter()
            .map(|z| Complex64::new(z.re, z.im))
            .collect();
        StabilityReport {
            verdict: verdict(r.verdict),
            degree_of_instability: r.degree_of_instability,
            restricted_hessian_eigenvalues: PyArray1::from_slice(
                py,
                &r.restricted_hessian_eigenvalues,
            )
            .into_any()
            .unbind(),
            f2_roots: PyArray1::from_vec(py, roots).into_any().unbind(),
        }
    }
}

#[pymethods]
impl StabilityReport {
    /// A small HTML table (Jupyter).
    fn _repr_html_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._display", "report_html", (slf,))
    }
    fn __repr__(&self, py: Python<'_>) -> String {
        let eig = self
            .restricted_hessian_eigenvalues
            .bind(py)
            .repr()
            .map(|r| r.to_string())
            .unwrap_or_default();
        format!(
            "StabilityReport(verdict='{}', degree_of_instability={}, restricted_hessian_eigenvalues={})",
            self.verdict, self.degree_of_instability, eig
        )
    }
}

/// A circle of steady motions of a body symmetric about `axis`, decided modulo the symmetry by
/// the doubly amended potential (`Model.classify_circle`): `verdict` ("stable", "unstable",
/// "degenerate"), `curvature` = V'' = `across` + `momentum_term`, the conserved `axis_momentum`,
/// the unit `axis` ((3,) float64) and the plain `report` of `classify`.
///
/// >>> c = top.classify_circle(circle_motion, (0.0, 0.0, 1.0))
/// >>> c.verdict, c.curvature
#[pyclass(module = "routh", frozen, get_all)]
pub struct CircleReport {
    /// One of "stable", "unstable", "degenerate" (modulo the symmetry).
    pub verdict: &'static str,
    /// V'', the second derivative of the doubly amended potential across the circle.
    pub curvature: f64,
    /// The restricted second variation of U_r across the circle.
    pub across: f64,
    /// What holding the axis momentum fixed adds, ≥ 0.
    pub momentum_term: f64,
    /// The conserved momentum about the axis, e·∂L/∂ω.
    pub axis_momentum: f64,
    /// The unit axis, (3,) float64.
    pub axis: Py<PyAny>,
    /// `classify` of the same motion (degenerate on a circle).
    pub report: Py<StabilityReport>,
}

impl CircleReport {
    pub(crate) fn new(py: Python<'_>, c: &routh::CircleReport) -> PyResult<CircleReport> {
        Ok(CircleReport {
            verdict: match c.verdict {
                routh::CircleStability::Stable => "stable",
                routh::CircleStability::Unstable => "unstable",
                routh::CircleStability::Degenerate => "degenerate",
            },
            curvature: c.curvature,
            across: c.across,
            momentum_term: c.momentum_term,
            axis_momentum: c.axis_momentum,
            axis: vec3(py, &c.axis).into_any().unbind(),
            report: Py::new(py, StabilityReport::new(py, &c.report))?,
        })
    }
}

#[pymethods]
impl CircleReport {
    fn __repr__(&self) -> String {
        format!(
            "CircleReport(verdict='{}', curvature={:e}, across={:e}, momentum_term={:e})",
            self.verdict, self.curvature, self.across, self.momentum_term
        )
    }
}

/// One branch of a bifurcation diagram: the parameter `s` (n,), the verticals `gamma` (n, 3),
/// the momentum `p_psi` (9) and energy `energy` (3) of each steady motion (n,) (the
/// energy–momentum diagram plots `energy` against `p_psi`), the `verdicts` (list of n strings)
/// and whether its motions are `isolated`.
#[pyclass(module = "routh", frozen, get_all)]
pub struct Branch {
    /// The parameter along the branch, (n,) float64.
    pub s: Py<PyAny>,
    /// The vertical γ at each point, (n, 3) float64.
    pub gamma: Py<PyAny>,
    /// The cyclic momentum p_ψ (9) at each point, (n,) float64.
    pub p_psi: Py<PyAny>,
    /// The energy (3) at each point, (n,) float64.
    pub energy: Py<PyAny>,
    /// The verdict at each point.
    pub verdicts: Vec<&'static str>,
    /// False on a branch of circles of steady motions.
    pub isolated: bool,
}

#[pymethods]
impl Branch {
    fn __repr__(&self) -> String {
        format!(
            "Branch(n={}, isolated={})",
            self.verdicts.len(),
            self.isolated
        )
    }
    fn __len__(&self) -> usize {
        self.verdicts.len()
    }
}

/// An event on a branch: `kind` ("fold", "branch_point", "hamiltonian_hopf"; with
/// `nonlinear=True` also "arnold_degenerate", "resonance"), where (`s`, `gamma`), on which
/// `branch`, the verdicts `before` and `after`, and for the nonlinear events their `resonance`
/// and `nonlinear` verdicts.
#[pyclass(module = "routh", frozen, get_all)]
pub struct Event {
    /// "fold", "branch_point", "hamiltonian_hopf", "arnold_degenerate" or "resonance".
    pub kind: &'static str,
    /// The parameter at the event.
    pub s: f64,
    /// The vertical at the event, (3,) float64.
    pub gamma: Py<PyAny>,
    /// The index of the branch in `diagram.branches`.
    pub branch: usize,
    /// The verdict just before the event.
    pub before: &'static str,
    /// The verdict just after.
    pub after: &'static str,
    /// For a "resonance" event, "1:2" or "1:3"; else None.
    pub resonance: Option<String>,
    /// For the nonlinear events ("arnold_degenerate", "resonance", with `nonlinear=True`): the
    /// nonlinear verdicts (before, at, after), e.g. ("lyapunov_stable", "undecided",
    /// "lyapunov_stable"); else None.
    pub nonlinear: Option<(&'static str, &'static str, &'static str)>,
}

#[pymethods]
impl Event {
    fn __repr__(&self) -> String {
        format!(
            "Event(kind='{}', s={:.8}, branch={}, before='{}', after='{}')",
            self.kind, self.s, self.branch, self.before, self.after
        )
    }
}

/// A bifurcation diagram: `branches` and `events`, `stop` (None, or why it stopped early: a
/// budget ran out) and `checks`, its self-check: a list of `(s, on_branches, searched)`, the
/// number of steady motions on the branches at `s` (between consecutive events) against a global
/// search there (`consistent()`: all agree). `plot(ax=None)` draws it with matplotlib; in
/// Jupyter it shows its tables and figure.
///
/// >>> d = top.bifurcation_diagram((0.0, 5.0))
/// >>> [(e.kind, round(e.s, 6), e.before, e.after) for e in d.events]
/// >>> ax = d.plot()
#[pyclass(module = "routh", frozen, get_all)]
pub struct Diagram {
    /// The branches of steady motions.
    pub branches: Vec<Py<Branch>>,
    /// The folds, branch points and Hamiltonian–Hopf points.
    pub events: Vec<Py<Event>>,
    /// None when the diagram is complete; otherwise why it stopped early (a budget ran out):
    /// the branches and events are those computed so far.
    pub stop: Option<String>,
    /// The count checks `(s, on_branches, searched)`: steady motions on the branches at `s`
    /// (a circle counts once) and found by a global search there.
    pub checks: Vec<(f64, usize, usize)>,
}

impl Diagram {
    pub(crate) fn new(py: Python<'_>, d: &routh::BifurcationDiagram) -> PyResult<Diagram> {
        let mut branches = Vec::with_capacity(d.branches.len());
        for b in &d.branches {
            let col = |f: fn(&routh::BranchSample) -> f64| {
                let v: Vec<f64> = b.points.iter().map(f).collect();
                PyArray1::from_vec(py, v).into_any().unbind()
            };
            let g: Vec<_> = b.points.iter().map(|p| p.steady.gamma).collect();
            branches.push(Py::new(
                py,
                Branch {
                    s: col(|p| p.s),
                    gamma: vecs(py, &g).into_any().unbind(),
                    p_psi: col(|p| p.steady.p_psi),
                    energy: col(|p| p.steady.energy),
                    verdicts: b.points.iter().map(|p| verdict(p.report.verdict)).collect(),
                    isolated: b.isolated,
                },
            )?);
        }
        let mut events = Vec::with_capacity(d.events.len());
        for e in &d.events {
            events.push(Py::new(
                py,
                Event {
                    kind: event_kind(e.kind),
                    s: e.s,
                    gamma: vec3(py, &e.gamma).into_any().unbind(),
                    branch: e.branch,
                    before: verdict(e.before),
                    after: verdict(e.after),
                    resonance: e
                        .nonlinear
                        .as_ref()
                        .and_then(|n| n.resonance)
                        .map(|r| r.to_string()),
                    nonlinear: e.nonlinear.as_ref().map(|n| {
                        (
                            nonlinear_verdict(n.before),
                            nonlinear_verdict(n.at),
                            nonlinear_verdict(n.after),
                        )
                    }),
                },
            )?);
        }
        Ok(Diagram {
            branches,
            events,
            stop: d.stop.as_ref().map(ToString::to_string),
            checks: d
                .checks
                .iter()
                .map(|c| (c.s, c.on_branches, c.searched))
                .collect(),
        })
    }
}

#[pymethods]
impl Diagram {
    /// Whether every count check of `checks` agreed (True when none was made).
    fn consistent(&self) -> bool {
        self.checks.iter().all(|c| c.1 == c.2)
    }
    /// Draw the diagram (s against γ₃; stable solid, unstable dashed, events marked and named);
    /// keyword arguments go to `routh._plot.plot_diagram` (`xlabel`, `ylabel`, `values`,
    /// `circles`, `axis`).
    #[pyo3(signature = (ax=None, component=2, **kwargs))]
    fn plot(
        slf: &Bound<'_, Self>,
        ax: Option<Py<PyAny>>,
        component: usize,
        kwargs: Option<&Bound<'_, pyo3::types::PyDict>>,
    ) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        let f = py.import("routh._plot")?.getattr("plot_diagram")?;
        Ok(f.call((slf, ax, component), kwargs)?.unbind())
    }
    /// The figure of `plot()` as SVG (Jupyter).
    fn _repr_svg_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._plot", "svg_of", (slf,))
    }
    /// The branches and events as HTML tables, with the figure (Jupyter).
    fn _repr_html_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._display", "diagram_html", (slf,))
    }
    fn __repr__(&self) -> String {
        format!(
            "BifurcationDiagram({} branches, {} events)",
            self.branches.len(),
            self.events.len()
        )
    }
}

/// A boundary curve of a stability atlas: `kind` and its `points` ((n, 2) float64 of (x, y)).
#[pyclass(module = "routh", frozen, get_all)]
pub struct Boundary {
    /// "fold", "branch_point", "hamiltonian_hopf", "arnold_degenerate" or "resonance".
    pub kind: &'static str,
    /// The points (x, y) of the curve, (n, 2) float64.
    pub points: Py<PyAny>,
}

#[pymethods]
impl Boundary {
    fn __repr__(&self, py: Python<'_>) -> String {
        let n = self.points.bind(py).len().unwrap_or(0);
        format!("Boundary(kind='{}', points={n})", self.kind)
    }
}

/// A stability atlas over a 2-parameter family: grid `x` (nx,), `y` (ny,), `verdicts` (ny rows
/// of nx: `verdicts[j][i]` at (x[i], y[j]), as in Rust; None where there is no steady motion or
/// it was lost), `lost` (the same layout: True where the motion was lost, not absent), `stop`
/// (None, or why the atlas stopped early) and the `boundaries`.
///
/// >>> a = routh.stability_atlas(lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1],
/// ...                           (0.5, 2.0), (0.5, 5.0), nx=21, ny=21)
/// >>> ax = a.plot()
#[pyclass(module = "routh", frozen, get_all)]
pub struct Atlas {
    /// The grid in the first parameter, (nx,) float64.
    pub x: Py<PyAny>,
    /// The grid in the second parameter, (ny,) float64.
    pub y: Py<PyAny>,
    /// `verdicts[j][i]` at (x[i], y[j]) (ny rows of nx); None where the steady motion does not
    /// exist (beyond a fold) or was lost (see `lost`).
    pub verdicts: Vec<Vec<Option<&'static str>>>,
    /// `lost[j][i]`: True where `verdicts[j][i]` is None because the motion was lost (its
    /// continuation stalled away from a fold: nothing is known there), False where it does not
    /// exist and wherever there is a verdict.
    pub lost: Vec<Vec<bool>>,
    /// None when the atlas is complete; otherwise why it stopped early (a budget ran out).
    pub stop: Option<String>,
    /// The curves where the verdict changes.
    pub boundaries: Vec<Py<Boundary>>,
}

impl Atlas {
    pub(crate) fn new(py: Python<'_>, a: &routh::StabilityAtlas) -> PyResult<Atlas> {
        let mut boundaries = Vec::new();
        for b in &a.boundaries {
            let rows: Vec<Vec<f64>> = b.points.iter().map(|&(x, y)| vec![x, y]).collect();
            let points = if rows.is_empty() {
                PyArray2::<f64>::zeros(py, [0, 2], false)
                    .into_any()
                    .unbind()
            } else {
                PyArray2::from_vec2(py, &rows)?.into_any().unbind()
            };
            boundaries.push(Py::new(
                py,
                Boundary {
                    kind: event_kind(b.kind),
                    points,
                },
            )?);
        }
        Ok(Atlas {
            x: PyArray1::from_slice(py, &a.x).into_any().unbind(),
            y: PyArray1::from_slice(py, &a.y).into_any().unbind(),
            verdicts: a
                .verdicts
                .iter()
                .map(|row| row.iter().map(|v| v.map(verdict)).collect())
                .collect(),
            lost: a.lost.clone(),
            stop: a.stop.as_ref().map(ToString::to_string),
            boundaries,
        })
    }
}

#[pymethods]
impl Atlas {
    /// Draw the atlas (verdict regions in their tints and hatches, boundary curves, a legend);
    /// keyword arguments go to `routh._plot.plot_atlas` (`xlabel`, `ylabel`: the parameters'
    /// names and units).
    #[pyo3(signature = (ax=None, **kwargs))]
    fn plot(
        slf: &Bound<'_, Self>,
        ax: Option<Py<PyAny>>,
        kwargs: Option<&Bound<'_, pyo3::types::PyDict>>,
    ) -> PyResult<Py<PyAny>> {
        let py = slf.py();
        let f = py.import("routh._plot")?.getattr("plot_atlas")?;
        Ok(f.call((slf, ax), kwargs)?.unbind())
    }
    /// The figure of `plot()` as SVG (Jupyter).
    fn _repr_svg_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._plot", "svg_of", (slf,))
    }
    /// The verdict counts and boundaries as HTML, with the figure (Jupyter).
    fn _repr_html_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._display", "atlas_html", (slf,))
    }
    fn __repr__(&self) -> String {
        let lost = self.lost.iter().flatten().filter(|&&l| l).count();
        format!(
            "StabilityAtlas({}x{} grid, {} boundaries{}{})",
            self.verdicts.first().map_or(0, Vec::len),
            self.verdicts.len(),
            self.boundaries.len(),
            if lost > 0 {
                format!(", {lost} cells lost")
            } else {
                String::new()
            },
            if self.stop.is_some() {
                ", stopped early"
            } else {
                ""
            }
        )
    }
}

/// A certified enumeration of the steady motions at one momentum: `complete` (every steady
/// motion is in `motions`, proven by interval arithmetic), `motions`, `p_psi`, `boxes`.
///
/// >>> c = top.certify(2.2)
/// >>> c.complete, [m.gamma for m in c.motions]
#[pyclass(module = "routh", frozen, get_all)]
pub struct Certificate {
    /// Whether the enumeration is proven complete.
    pub complete: bool,
    /// The certified steady motions.
    pub motions: Vec<Py<SteadyMotion>>,
    /// The momentum.
    pub p_psi: f64,
    /// How many boxes the search examined.
    pub boxes: usize,
    /// How many regions were left undecided.
    pub undecided: usize,
}

#[pymethods]
impl Certificate {
    /// A small HTML table (Jupyter).
    fn _repr_html_(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        helper(slf.py(), "routh._display", "certificate_html", (slf,))
    }
    fn __repr__(&self) -> String {
        format!(
            "Certificate(complete={}, motions={}, p_psi={}, boxes={}, undecided={})",
            if self.complete { "True" } else { "False" },
            self.motions.len(),
            self.p_psi,
            self.boxes,
            self.undecided
        )
    }
}
