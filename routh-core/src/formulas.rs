//! The derived formulas of a model in LaTeX ([`LatexFormulas`]) and in SymPy's syntax ([`SympyFormulas`]), as returned by
//! [`DerivedFormulas::latex`](crate::DerivedFormulas::latex) for a `#[derive(Lagrangian)]`
//! model (and by run-time models, which print them from the same expression graph).

/// The formulas that the symbolic engine derived for a model, in LaTeX (math mode, without
/// delimiters), printed from the same expression graph as the generated code.
///
/// Order: in a product the number first, then the parameters (in the order of the model's
/// fields), then `\omega_1 \omega_2 \omega_3`, `\gamma_1 \gamma_2 \gamma_3`, `p_\psi`, then the
/// rest; a sum by decreasing degree in ω (or Ω), γ and p_ψ, terms of equal degree by their
/// exponents of ω₁ … γ₃, p_ψ in that order (`\omega_1^{2} + \omega_1 \omega_2`), then by their
/// parameters, with a leading negative term put after the first positive one (`1 - \gamma_3^{2}`).
///
/// Symbols: `\omega_i` (or `\Omega_i` in functions of the relative angular velocity),
/// `\gamma_i`, `p_\psi`; each parameter as its name in `\mathit{…}` unless the model gives it a
/// symbol (`#[lagrangian(latex = "I")]` on the field), components subscripted from 1
/// (`I_{11}`, `\mathit{com}_{3}`). Functions of γ are simplified with `|γ|² = 1` where that
/// shortens them (they are then equal to the generated code on the sphere only). The matrices
/// A, G, C are written entry by entry with the paper's intermediate quantities named and
/// defined after the matrix: `\gamma^{\mathsf{T}} J \gamma` (the denominator of (38)),
/// `\dot\psi` (ψ̇ at rest, (38)) and `\mu = (∂R/∂γ, γ)` (errata E6), as far as the matrix uses
/// them. A long formula (more than 250 nodes of expression tree; a matrix: more than 1000 in all
/// its entries) comes with its common subexpressions named and defined after it too:
/// `… \quad \text{where} \quad \sigma_{1} = …,\; \sigma_{2} = …` (each definition uses only the
/// names before it). A formula too large even so is replaced by a `\text{(… not printed)}`.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LatexFormulas {
    /// `L(ω, γ)`.
    pub lagrangian: String,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38).
    pub psi_dot: String,
    /// The Routh function `R(Ω, γ, p_ψ)` of (14).
    pub routhian: String,
    /// The amended potential (34) `U_r(γ, p_ψ) = −R(0, γ, p_ψ)`.
    pub amended_potential: String,
    /// `A = ∂²R/∂Ω²` at Ω = 0 (64), a `pmatrix`.
    pub a: String,
    /// The gyroscopic matrix `G` of (64) at Ω = 0, a `pmatrix`.
    pub g: String,
    /// The stiffness matrix `C` of (64) at Ω = 0, a `pmatrix`.
    pub c: String,
}

/// The derived formulas of [`LatexFormulas`] in SymPy's syntax (Python's infix: `*`, `/`,
/// `**`, `sqrt(…)`), to parse with `sympy.sympify` and keep computing: the same expressions,
/// in the same canonical order, simplified on the sphere the same way.
///
/// Symbols: `omega1 omega2 omega3` (`Omega1 …` in ψ̇ and R, functions of the relative angular
/// velocity), `gamma1 gamma2 gamma3`, `p_psi`; each parameter by its field's name (`mgl`),
/// components with indices from 1 (`inertia_1`, `I_12`), as in the LaTeX, unless that is not a
/// free Python identifier (`lambda`, `sin`, `nan`: see [`SympyFormulas::symbols`]). Matrices are
/// `Matrix([[…], […], […]])`. A formula is written out in full unless its expression tree is
/// very large (more than 20 000 nodes); then it refers to named subexpressions `sigma1`,
/// `sigma2`, … defined in [`SympyFormulas::definitions`], in order, each using only the names
/// before it. Python's `routh.Model.to_sympy()` substitutes them (and reads a sum of any
/// length, which Python's own parser, and so `sympify`, refuses beyond about a thousand terms).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SympyFormulas {
    /// `L(ω, γ)`.
    pub lagrangian: String,
    /// `ψ̇(Ω, γ, p_ψ)` of (12)/(38).
    pub psi_dot: String,
    /// The Routh function `R(Ω, γ, p_ψ)` of (14).
    pub routhian: String,
    /// The amended potential (34) `U_r(γ, p_ψ) = −R(0, γ, p_ψ)`.
    pub amended_potential: String,
    /// `A = ∂²R/∂Ω²` at Ω = 0 (64), a `Matrix`.
    pub a: String,
    /// The gyroscopic matrix `G` of (64) at Ω = 0, a `Matrix`.
    pub g: String,
    /// The stiffness matrix `C` of (64) at Ω = 0, a `Matrix`.
    pub c: String,
    /// `(name, expression)` of the named subexpressions, in order (empty when every formula is
    /// written out in full).
    pub definitions: Vec<(String, String)>,
    /// `(identifier, name)` of every symbol the text may use, the state's first (`omega1 …
    /// omega3`, `Omega1 …`, `gamma1 …`, `p_psi`), then the parameters' in order: the text
    /// calls a symbol by its identifier, SymPy by its name. They are the same but for a
    /// parameter whose name is not a free Python identifier (a keyword such as `lambda`, a name
    /// the text uses: `sin`, `sqrt`, `Abs`, `Matrix`, `Symbol`, `nan`, `oo`, `sigma1`, a
    /// state's; a non-ASCII one), written under its name with `_` appended (`lambda_`), and for
    /// one whose name is another's (a parameter `omega1`, a scalar `com_1` beside a vector
    /// `com`), whose name gets the `_` too. (Empty in a document written before it existed.)
    #[cfg_attr(feature = "serde", serde(default))]
    pub symbols: Vec<(String, String)>,
}
