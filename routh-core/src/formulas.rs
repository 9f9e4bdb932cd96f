//! The derived formulas of a model in LaTeX ([`LatexFormulas`]), as returned by
//! [`DerivedFormulas::latex`](crate::DerivedFormulas::latex) for a `#[derive(Lagrangian)]`
//! model (and by run-time models, which print them from the same expression graph).

/// The formulas that the symbolic engine derived for a model, in LaTeX (math mode, without
/// delimiters), printed from the same expression graph as the generated code.
///
/// Symbols: `\omega_i` (or `\Omega_i` in functions of the relative angular velocity),
/// `\gamma_i`, `p_\psi`; each parameter as its name in `\mathit{…}` unless the model gives it a
/// symbol (`#[lagrangian(latex = "I")]` on the field), components subscripted from 1
/// (`I_{11}`, `\mathit{com}_{3}`). Functions of γ are simplified with `|γ|² = 1` where that
/// shortens them (they are then equal to the generated code on the sphere only). A long formula
/// (more than 250 nodes of expression tree; for a matrix, in all its entries) comes with its
/// common subexpressions named and defined after it, inner ones first:
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
