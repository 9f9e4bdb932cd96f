//! The linearisation of the full equations (8) by finite differences, and the matching of the
//! roots of f₂ to its eigenvalues: at a steady motion the 6×6 Jacobian of (8) has the four roots
//! of f₂ and a double zero (errata E5). Written from the [`Lagrangian`] trait methods only, so
//! that it checks `classify` (which works on the Routh function) against something it did not
//! produce.

use nalgebra::{Complex, Matrix6, Vector3, Vector6};
use routh_core::{classify, Lagrangian, Routhian, SteadyMotion};

/// The state `(ω, γ)` as one vector.
pub fn state(omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(omega.x, omega.y, omega.z, gamma.x, gamma.y, gamma.z)
}

/// The state `ω = ψ̇γ` of a steady motion (7).
pub fn steady_state(s: &SteadyMotion) -> Vector6<f64> {
    state(&(s.psi_dot * s.gamma), &s.gamma)
}

/// The full equations (8) solved for ω̇: `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)`,
/// `γ̇ = γ × ω`.
pub fn full_field<M: Lagrangian + ?Sized>(m: &M, x: &Vector6<f64>) -> Vector6<f64> {
    let w = Vector3::new(x[0], x[1], x[2]);
    let g = Vector3::new(x[3], x[4], x[5]);
    let gdot = g.cross(&w);
    let rhs = m.dl_domega(&w, &g).cross(&w) + m.dl_dgamma(&w, &g).cross(&g)
        - m.d2l_domega_dgamma(&w, &g) * gdot;
    let wdot = m.d2l_domega2(&g).lu().solve(&rhs).expect("J invertible");
    state(&wdot, &gdot)
}

/// Central finite-difference Jacobian of [`full_field`] at `x` with step `h` and one Richardson
/// extrapolation (error O(h⁴)).
pub fn fd_jacobian<M: Lagrangian + ?Sized>(m: &M, x: &Vector6<f64>, h: f64) -> Matrix6<f64> {
    let mut jac = Matrix6::zeros();
    for k in 0..6 {
        let d = |h: f64| {
            let (mut xp, mut xm) = (*x, *x);
            xp[k] += h;
            xm[k] -= h;
            (full_field(m, &xp) - full_field(m, &xm)) / (2.0 * h)
        };
        jac.set_column(k, &((4.0 * d(h / 2.0) - d(h)) / 3.0));
    }
    jac
}

/// The result of [`match_roots`].
#[derive(Debug, Clone)]
pub struct RootMatch {
    /// The largest distance between a root and its partner.
    pub worst: f64,
    /// The candidates nobody was matched to.
    pub leftover: Vec<Complex<f64>>,
}

/// Greedy matching within a tolerance: each root of `got` in turn takes the nearest root of
/// `want` not taken yet, which must lie within `tol(partner)`. Returns the largest distance, or a
/// message naming the first root left unmatched.
pub fn match_roots_within(
    got: &[Complex<f64>],
    want: &[Complex<f64>],
    tol: impl Fn(&Complex<f64>) -> f64,
) -> Result<f64, String> {
    let mut used = vec![false; want.len()];
    let mut worst = 0.0f64;
    for z in got {
        let (k, d) = want
            .iter()
            .enumerate()
            .filter(|(k, _)| !used[*k])
            .map(|(k, w)| (k, (z - w).norm()))
            .min_by(|x, y| x.1.total_cmp(&y.1))
            .ok_or("more roots than expected")?;
        if d > tol(&want[k]) {
            return Err(format!("root {z} unmatched: nearest {} at {d:e}", want[k]));
        }
        used[k] = true;
        worst = worst.max(d);
    }
    Ok(worst)
}

/// The roots of f₂ of the sleeping Lagrange top γ = e₃ in closed form (docs/errata.md, classical
/// checks): with k = p²(2A₁ − C)²/C², f₂(λ) = (A₁λ² + h)² + kλ², so
/// λ = (i/2A₁)(±√k ± √(p² − 4A₁mgl)) (complex square root).
pub fn sleeping_top_roots(a1: f64, c: f64, mgl: f64, p: f64) -> Vec<Complex<f64>> {
    let sk = p.abs() * (2.0 * a1 - c).abs() / c;
    let d = Complex::new(p * p - 4.0 * a1 * mgl, 0.0).sqrt();
    let i = Complex::new(0.0, 1.0);
    let mut out = Vec::new();
    for s1 in [1.0, -1.0] {
        for s2 in [1.0, -1.0] {
            out.push(i * (d * s2 + sk * s1) / (2.0 * a1));
        }
    }
    out
}

/// Greedy matching: each root in `roots` in turn takes the nearest candidate not taken yet.
///
/// # Panics
/// When there are fewer candidates than roots.
pub fn match_roots(roots: &[Complex<f64>], candidates: &[Complex<f64>]) -> RootMatch {
    let mut rest = candidates.to_vec();
    let mut worst = 0.0f64;
    for r in roots {
        let k = (0..rest.len())
            .min_by(|&a, &b| (rest[a] - r).norm().total_cmp(&(rest[b] - r).norm()))
            .expect("at least as many candidates as roots");
        worst = worst.max((rest[k] - r).norm());
        rest.remove(k);
    }
    RootMatch {
        worst,
        leftover: rest,
    }
}

/// Checks the roots of f₂ that `classify` reports at the steady motion `s` against the
/// eigenvalues of [`fd_jacobian`] (step 1e-3) at `ω = ψ̇γ`: each root within `1e-6·|λ|max` of a
/// distinct eigenvalue, the two eigenvalues left over within `1e-4·|λ|max` of zero (a double zero
/// may split by the square root of the differencing error). Returns the worst relative mismatch
/// of the roots.
///
/// # Panics
/// On a mismatch, naming `what`.
pub fn assert_f2_roots_are_jacobian_eigenvalues<M: Routhian>(
    model: &M,
    s: &SteadyMotion,
    what: &str,
) -> f64 {
    let report = classify(model, s).expect("classify");
    let eig: Vec<Complex<f64>> = fd_jacobian(model, &steady_state(s), 1e-3)
        .complex_eigenvalues()
        .iter()
        .copied()
        .collect();
    let scale = report
        .f2_roots
        .iter()
        .map(|r| r.norm())
        .fold(1e-300, f64::max);
    let matched = match_roots(&report.f2_roots, &eig);
    let worst = matched.worst / scale;
    assert!(
        worst <= 1e-6,
        "{what}: f₂ roots {:?} vs Jacobian eigenvalues {eig:?}",
        report.f2_roots
    );
    for z in matched.leftover {
        assert!(
            z.norm() <= 1e-4 * scale,
            "{what}: leftover eigenvalue {z} is not zero"
        );
    }
    worst
}
