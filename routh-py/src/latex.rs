//! `routh.LatexFormulas`: the formulas a model's reduction derives, in LaTeX (docs/api.md, "Out"),
//! from `routh::Model::latex()`.

use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The seven derived formulas of a model in LaTeX (math mode, no delimiters): `lagrangian`
/// L(ω, γ), `psi_dot` ψ̇(Ω, γ, p_ψ) (12)/(38), `routhian` R(Ω, γ, p_ψ) (14),
/// `amended_potential` U_r(γ, p_ψ) = −R(0, γ, p_ψ) (34), and the matrices `a`, `g`, `c` of the
/// linearisation (64) at Ω = 0 (`pmatrix`). Parameters print as the TOML's `[latex]` symbols.
/// In Jupyter the object shows as the typeset formulas; `f["routhian"]` and `f.as_dict()` also
/// work.
///
/// >>> f = top.latex()
/// >>> sorted(f.as_dict())
/// ['a', 'amended_potential', 'c', 'g', 'lagrangian', 'psi_dot', 'routhian']
#[pyclass(module = "routh", frozen, get_all)]
pub struct LatexFormulas {
    /// L(ω, γ).
    pub lagrangian: String,
    /// ψ̇(Ω, γ, p_ψ) of (12)/(38).
    pub psi_dot: String,
    /// The Routh function R(Ω, γ, p_ψ) of (14).
    pub routhian: String,
    /// The amended potential U_r(γ, p_ψ) = −R(0, γ, p_ψ) of (34).
    pub amended_potential: String,
    /// A = ∂²R/∂Ω² at Ω = 0 (64), a `pmatrix`.
    pub a: String,
    /// The gyroscopic matrix G of (64) at Ω = 0, a `pmatrix`.
    pub g: String,
    /// The stiffness matrix C of (64) at Ω = 0, a `pmatrix`.
    pub c: String,
}

/// The names of the formulas, with the symbol each is shown under.
const NAMES: [(&str, &str); 7] = [
    ("lagrangian", "L"),
    ("psi_dot", r"\dot\psi"),
    ("routhian", "R"),
    ("amended_potential", "U_r"),
    ("a", "A"),
    ("g", "G"),
    ("c", "C"),
];

impl LatexFormulas {
    pub(crate) fn new(f: routh::LatexFormulas) -> LatexFormulas {
        LatexFormulas {
            lagrangian: f.lagrangian,
            psi_dot: f.psi_dot,
            routhian: f.routhian,
            amended_potential: f.amended_potential,
            a: f.a,
            g: f.g,
            c: f.c,
        }
    }

    fn field(&self, name: &str) -> Option<&str> {
        Some(match name {
            "lagrangian" => &self.lagrangian,
            "psi_dot" => &self.psi_dot,
            "routhian" => &self.routhian,
            "amended_potential" => &self.amended_potential,
            "a" => &self.a,
            "g" => &self.g,
            "c" => &self.c,
            _ => return None,
        })
    }
}

/// `$$\begin{aligned} sym &= tex \\ … \end{aligned}$$` of the given (symbol, tex) pairs.
pub fn aligned(rows: &[(&str, &str)]) -> String {
    let body: Vec<String> = rows.iter().map(|(s, t)| format!("{s} &= {t}")).collect();
    format!(
        "$$\\begin{{aligned}}\n{}\n\\end{{aligned}}$$",
        body.join(" \\\\\n")
    )
}

#[pymethods]
impl LatexFormulas {
    /// The formulas as a dict, name → LaTeX.
    fn as_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, _) in NAMES {
            d.set_item(name, self.field(name).unwrap_or_default())?;
        }
        Ok(d)
    }
    /// `f["routhian"]`: a formula by name (KeyError for another name).
    fn __getitem__(&self, name: &str) -> PyResult<String> {
        self.field(name)
            .map(str::to_string)
            .ok_or_else(|| PyKeyError::new_err(name.to_string()))
    }
    /// The seven formulas typeset (Jupyter).
    fn _repr_latex_(&self) -> String {
        let rows: Vec<(&str, &str)> = NAMES
            .iter()
            .map(|&(name, sym)| (sym, self.field(name).unwrap_or_default()))
            .collect();
        aligned(&rows)
    }
    fn __repr__(&self) -> String {
        format!(
            "LatexFormulas(routhian={:?}, amended_potential={:?}, ...)",
            self.routhian, self.amended_potential
        )
    }
}

/// The seven derived formulas of a model in SymPy's syntax (`routh::Model::sympy()`): the same
/// fields as `LatexFormulas`, strings to parse with `sympy.sympify`, with `omega1` (`Omega1`
/// in `psi_dot` and `routhian`), `gamma1`, `p_psi`, the parameters by their names and their
/// components from 1 (`inertia_3`, `I_12`); matrices as `Matrix([[…], …])`. `definitions` is a
/// list of `(name, expression)` of the subexpressions `sigma1, sigma2, …` that a very large
/// formula refers to (usually empty); `symbols` the `(identifier, name)` of every symbol (a
/// parameter named `lambda` or `sin` is `lambda_`, `sin_` in the text). `to_sympy()` parses
/// everything (SymPy needed), whatever the length of a sum.
///
/// >>> f = top.sympy()
/// >>> f.lagrangian
/// '1/2*(inertia_1*omega1**2 + inertia_2*omega2**2 + inertia_3*omega3**2) - mgl*gamma3'
#[pyclass(module = "routh", frozen, get_all)]
pub struct SympyFormulas {
    /// L(ω, γ).
    pub lagrangian: String,
    /// ψ̇(Ω, γ, p_ψ) of (12)/(38).
    pub psi_dot: String,
    /// The Routh function R(Ω, γ, p_ψ) of (14).
    pub routhian: String,
    /// The amended potential U_r(γ, p_ψ) = −R(0, γ, p_ψ) of (34).
    pub amended_potential: String,
    /// A = ∂²R/∂Ω² at Ω = 0 (64), a `Matrix`.
    pub a: String,
    /// The gyroscopic matrix G of (64) at Ω = 0, a `Matrix`.
    pub g: String,
    /// The stiffness matrix C of (64) at Ω = 0, a `Matrix`.
    pub c: String,
    /// `(name, expression)` of the named subexpressions, in order.
    pub definitions: Vec<(String, String)>,
    /// `(identifier, name)` of every symbol: the text calls it by its identifier, SymPy by its
    /// name. The same but for a parameter whose name is not a free Python identifier (`lambda`,
    /// `sin`, `nan`, …: `lambda_`) or is another's (a parameter `omega1`: named `omega1_`).
    pub symbols: Vec<(String, String)>,
}

impl SympyFormulas {
    pub(crate) fn new(f: routh::SympyFormulas) -> SympyFormulas {
        SympyFormulas {
            lagrangian: f.lagrangian,
            psi_dot: f.psi_dot,
            routhian: f.routhian,
            amended_potential: f.amended_potential,
            a: f.a,
            g: f.g,
            c: f.c,
            definitions: f.definitions,
            symbols: f.symbols,
        }
    }

    fn field(&self, name: &str) -> Option<&str> {
        Some(match name {
            "lagrangian" => &self.lagrangian,
            "psi_dot" => &self.psi_dot,
            "routhian" => &self.routhian,
            "amended_potential" => &self.amended_potential,
            "a" => &self.a,
            "g" => &self.g,
            "c" => &self.c,
            _ => return None,
        })
    }
}

#[pymethods]
impl SympyFormulas {
    /// The formulas as a dict, name → SymPy text.
    fn as_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        for (name, _) in NAMES {
            d.set_item(name, self.field(name).unwrap_or_default())?;
        }
        Ok(d)
    }
    /// `f["routhian"]`: a formula by name (KeyError for another name).
    fn __getitem__(&self, name: &str) -> PyResult<String> {
        self.field(name)
            .map(str::to_string)
            .ok_or_else(|| PyKeyError::new_err(name.to_string()))
    }
    /// The formulas as SymPy objects: a dict name → expression (`sympy.Matrix` for `a`, `g`,
    /// `c`), every symbol real, the named subexpressions substituted. Raises ImportError
    /// without SymPy.
    fn to_sympy(slf: &Bound<'_, Self>) -> PyResult<Py<PyAny>> {
        crate::convert::helper(slf.py(), "routh._sympy", "to_sympy", (slf,))
    }
    fn __repr__(&self) -> String {
        format!(
            "SympyFormulas(routhian={:?}, amended_potential={:?}, ...)",
            self.routhian, self.amended_potential
        )
    }
}
