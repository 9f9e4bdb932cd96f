//! Resonances and the nonlinear verdict from the normal form (docs/method.md §10.4).

use super::{NonlinearOptions, NonlinearVerdict, Resonance};

/// The low-order resonance `ω₁ = kω₂` (`k = 1, 2, 3`, the only ones with `|k₁| + |k₂| ≤ 4` once
/// `ω₁ ≥ ω₂`), if its relative distance `|kω₂ − ω₁|/ω₁` is within `tol`, with that distance.
pub(crate) fn detect_resonance(omega: [f64; 2], tol: f64) -> Option<(Resonance, f64)> {
    [
        (Resonance::OneToOne, 1.0),
        (Resonance::OneToTwo, 2.0),
        (Resonance::OneToThree, 3.0),
    ]
    .into_iter()
    .map(|(r, k)| (r, (k * omega[1] - omega[0]).abs() / omega[0]))
    .find(|&(_, d)| d <= tol)
}

/// Everything the verdict is made of.
pub(crate) struct Inputs {
    pub(crate) omega: [f64; 2],
    pub(crate) signs: [i8; 2],
    pub(crate) c: [f64; 3],
    pub(crate) d: f64,
    pub(crate) resonance: Option<(Resonance, f64)>,
    pub(crate) resonant_cubic: f64,
    pub(crate) cubic_scale: f64,
    pub(crate) resonant_quartic: f64,
}

/// The verdict, the criterion applied and, for `Undecided`, the reason.
pub(crate) fn decide(x: &Inputs, opts: &NonlinearOptions) -> (NonlinearVerdict, String) {
    let [w1, w2] = x.omega;
    if x.signs[0] == x.signs[1] {
        return (
            NonlinearVerdict::SecularlyStable,
            "H₂ is definite: the energy is a Lyapunov function (Lagrange–Dirichlet)".into(),
        );
    }
    match x.resonance {
        Some((Resonance::OneToOne, dist)) => (
            NonlinearVerdict::Undecided,
            format!(
                "1:1 resonance (distance {dist:.2e}) with opposite Krein signs: a \
                 Hamiltonian–Hopf point, not decided by the fourth-order normal form"
            ),
        ),
        Some((Resonance::OneToTwo, dist)) => {
            if x.resonant_cubic > opts.criterion_tol * x.cubic_scale.max(f64::MIN_POSITIVE) {
                (
                    NonlinearVerdict::Unstable,
                    format!(
                        "1:2 resonance (distance {dist:.2e}) with a non-zero resonant cubic \
                         coefficient {:.3e}: unstable by Markeev's third-order resonance theorem",
                        x.resonant_cubic
                    ),
                )
            } else {
                (
                    NonlinearVerdict::Undecided,
                    format!(
                        "1:2 resonance (distance {dist:.2e}) whose resonant cubic coefficient \
                         vanishes: Markeev's criterion does not apply"
                    ),
                )
            }
        }
        Some((Resonance::OneToThree, dist)) => {
            // On the resonant ray I₂ = 3I₁ (H₂ = 0) the normal form is
            // ρ²(c₂₀ + 3c₁₁ + 9c₀₂ + 2·3√3|b| cos θ) = ρ²(D/ω₂² + 6√3|b| cos θ).
            let lhs = (x.d / (w2 * w2)).abs();
            let rhs = 6.0 * 3f64.sqrt() * x.resonant_quartic;
            let scale = lhs.max(rhs).max(f64::MIN_POSITIVE);
            if (lhs - rhs).abs() <= opts.criterion_tol * scale {
                (
                    NonlinearVerdict::Undecided,
                    format!(
                        "1:3 resonance (distance {dist:.2e}) on the boundary of Markeev's \
                         criterion: |c₂₀ + 3c₁₁ + 9c₀₂| = {lhs:.6e} ≈ 6√3|b| = {rhs:.6e}"
                    ),
                )
            } else if lhs > rhs {
                (
                    NonlinearVerdict::LyapunovStable,
                    format!(
                        "1:3 resonance (distance {dist:.2e}), stable by Markeev's fourth-order \
                         resonance criterion: |c₂₀ + 3c₁₁ + 9c₀₂| = {lhs:.6e} > 6√3|b| = {rhs:.6e}"
                    ),
                )
            } else {
                (
                    NonlinearVerdict::Unstable,
                    format!(
                        "1:3 resonance (distance {dist:.2e}), unstable by Markeev's fourth-order \
                         resonance criterion: |c₂₀ + 3c₁₁ + 9c₀₂| = {lhs:.6e} < 6√3|b| = {rhs:.6e}"
                    ),
                )
            }
        }
        None => {
            let [c20, c11, c02] = x.c;
            let scale = c20.abs() * w2 * w2 + c11.abs() * w1 * w2 + c02.abs() * w1 * w1;
            if x.d.abs() <= opts.arnold_tol * scale || x.d.is_nan() {
                (
                    NonlinearVerdict::Undecided,
                    format!(
                        "Arnold's determinant vanishes: D = {:.3e} (scale {scale:.3e})",
                        x.d
                    ),
                )
            } else {
                (
                    NonlinearVerdict::LyapunovStable,
                    format!(
                        "no resonance of order ≤ 4 and D = {:.6e} ≠ 0: Lyapunov stable by the \
                         Arnold–Moser theorem",
                        x.d
                    ),
                )
            }
        }
    }
}
