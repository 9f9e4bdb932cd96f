//! The nonlinear stability report (Birkhoff normal form to order four, Arnold–Moser).

use crate::convert::nonlinear_verdict;
use crate::results::StabilityReport;
use numpy::PyArray1;
use pyo3::prelude::*;

/// The nonlinear stability of a steady motion: `verdict` ("secularly_stable",
/// "lyapunov_stable", "unstable", "undecided") and why (`reason`), the linear report
/// (`linear`), the frequencies ω₁ ≥ ω₂ ((2,) float64; NaN when linearly unstable), the Krein
/// signs (s₁, s₂) of H₂ = s₁ω₁I₁ + s₂ω₂I₂, the normal form (c₂₀, c₁₁, c₀₂) of
/// H₄ = c₂₀I₁² + c₁₁I₁I₂ + c₀₂I₂² ((3,) float64), Arnold's determinant
/// D = c₂₀ω₂² − s₁s₂c₁₁ω₁ω₂ + c₀₂ω₁², and the `resonance` ("1:1", "1:2", "1:3" or None).
///
/// >>> m = max(top.steady_motions(2.2), key=lambda s: s.gamma[2])   # the sleeping top (γ₃ = 1), gyroscopically stabilised
/// >>> r = top.nonlinear_stability(m)
/// >>> r.verdict, r.arnold_determinant
#[pyclass(module = "routh", frozen, get_all)]
pub struct NonlinearReport {
    /// "secularly_stable", "lyapunov_stable", "unstable" or "undecided".
    pub verdict: &'static str,
    /// Why: the theorem applied, or what is missing for a decision.
    pub reason: String,
    /// The linear report (`Model.classify`).
    pub linear: Py<StabilityReport>,
    /// ω₁ ≥ ω₂ > 0, (2,) float64 (NaN when linearly unstable).
    pub frequencies: Py<PyAny>,
    /// The Krein signs (s₁, s₂), each ±1 (0 when linearly unstable).
    pub krein_signs: (i8, i8),
    /// (c₂₀, c₁₁, c₀₂), (3,) float64.
    pub normal_form: Py<PyAny>,
    /// Arnold's determinant D.
    pub arnold_determinant: f64,
    /// "1:1", "1:2", "1:3" or None.
    pub resonance: Option<String>,
    /// The relative distance to the nearest resonance of order ≤ 4.
    pub resonance_distance: f64,
}

impl NonlinearReport {
    pub(crate) fn new(py: Python<'_>, r: &routh::NonlinearReport) -> PyResult<NonlinearReport> {
        Ok(NonlinearReport {
            verdict: nonlinear_verdict(r.verdict),
            reason: r.reason.clone(),
            linear: Py::new(py, StabilityReport::new(py, &r.linear))?,
            frequencies: PyArray1::from_slice(py, &r.frequencies).into_any().unbind(),
            krein_signs: (r.krein_signs[0], r.krein_signs[1]),
            normal_form: PyArray1::from_slice(py, &r.normal_form).into_any().unbind(),
            arnold_determinant: r.arnold_determinant,
            resonance: r.resonance.map(|x| x.to_string()),
            resonance_distance: r.resonance_distance,
        })
    }
}

#[pymethods]
impl NonlinearReport {
    fn __repr__(&self) -> String {
        format!(
            "NonlinearReport(verdict='{}', arnold_determinant={:.6e}, resonance={}, reason='{}')",
            self.verdict,
            self.arnold_determinant,
            self.resonance
                .as_ref()
                .map_or("None".to_string(), |r| format!("'{r}'")),
            self.reason
        )
    }
}
