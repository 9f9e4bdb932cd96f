//! The Birkhoff normal form of the sleeping Lagrange top, derived by hand in docs/method.md §10.8
//! (polar chart, circular modes, average of H₄): the reference the nonlinear-stability tests
//! compare `nonlinear_stability` with, written once here for the library's, the CLI's tests.

/// The sleeping Lagrange top's normal form to order four.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleepingTopNormalForm {
    /// `[c₂₀, c₁₁, c₀₂]` of `H₄ = c₂₀I₁² + c₁₁I₁I₂ + c₀₂I₂²`.
    pub normal_form: [f64; 3],
    /// `[ω₁, ω₂]`.
    pub frequencies: [f64; 2],
    /// `s₁s₂`, the product of the Krein signs.
    pub sign_product: f64,
    /// Arnold's determinant `D = c₂₀ω₂² − s₁s₂c₁₁ω₁ω₂ + c₀₂ω₁²`.
    pub arnold_determinant: f64,
}

/// The sleeping top `A₁ = A₂ = a`, `C = c`, `mgl = g` at momentum `p` (above Maievskii's bound,
/// `p² > 4ag`): with `d = √(p² − 4ag)`, `a₁ = (p² + 2ag)/(12a d²)`, `a₂ = p/(4ad)`,
/// `a₃ = (3a − 2c)/(6ac)`: `c₂₀ = a₁ + a₂ + a₃`, `c₁₁ = 4a₁ − 2a₃`, `c₀₂ = a₁ − a₂ + a₃`, and
/// `ω₁ = (λp + d)/2a`, `σ₂ = (d − λp)/2a` (`λ = (2a − c)/c`, `ω₂ = |σ₂|`, `s₁s₂ = sign σ₂`).
pub fn sleeping_top_normal_form(a: f64, c: f64, g: f64, p: f64) -> SleepingTopNormalForm {
    let d = (p * p - 4.0 * a * g).sqrt();
    let a1 = (p * p + 2.0 * a * g) / (12.0 * a * d * d);
    let a2 = p / (4.0 * a * d);
    let a3 = (3.0 * a - 2.0 * c) / (6.0 * a * c);
    let cs = [a1 + a2 + a3, 4.0 * a1 - 2.0 * a3, a1 - a2 + a3];
    let lambda = (2.0 * a - c) / c;
    let (w1, sigma2) = ((lambda * p + d) / (2.0 * a), (d - lambda * p) / (2.0 * a));
    let w2 = sigma2.abs();
    let s12 = sigma2.signum();
    SleepingTopNormalForm {
        normal_form: cs,
        frequencies: [w1, w2],
        sign_product: s12,
        arnold_determinant: cs[0] * w2 * w2 - s12 * cs[1] * w1 * w2 + cs[2] * w1 * w1,
    }
}
