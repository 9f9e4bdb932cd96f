//! The vector fields of the full equations (8) and of the reduced equations (13), apart from the
//! integrator drivers that use them.

use nalgebra::{Matrix3, Vector3};

use crate::model::{Lagrangian, RankOneInertia, Routhian};
use crate::validate::{gamma_array, min_eigenvalue};
use crate::RouthError;

/// The vector field of the full equations (8) solved for ω̇:
/// `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)`, `γ̇ = γ × ω`, with `J = ∂²L/∂ω²`
/// (docs/method.md §2), from [`Lagrangian::full_equations`]. Returns `(ω̇, γ̇)`. The system in
/// `J` is solved by a square-root-free Cholesky factorisation (LDLᵀ of its lower triangle),
/// falling back to Cholesky proper near singularity. (A simulation of a model with
/// `J = J₀ + c v vᵀ`, [`Lagrangian::constant_inertia`], solves by Sherman–Morrison instead,
/// docs/method.md §2a.)
///
/// Errors: [`RouthError::KineticNotPositiveDefinite`] when the Cholesky factorisation of a
/// finite `J(γ)` fails. Non-finite model outputs give non-finite rates (no error), so that an
/// integrator can shrink its step.
#[inline(always)]
pub fn full_vector_field<M: Lagrangian + ?Sized>(
    model: &M,
    omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
) -> Result<(Vector3<f64>, Vector3<f64>), RouthError> {
    // One evaluation: J itself, factorised once, is cheaper than preparing J₀ for
    // Sherman–Morrison (a simulation prepares it once for all its stages). The same verdicts as
    // `FullField::eval` with a new cache: NaN for non-finite terms, else LDLᵀ or Cholesky's.
    // Always inlined, so that a caller's loop (an ODE crate's stages) keeps the terms in
    // registers: out of line, `ode_solvers` on the top took 1.41× the hand right side instead
    // of 1.16× (`benches/simulate.rs`).
    let gamma_dot = gamma.cross(omega);
    let eq = model.full_equations(omega, gamma);
    let omega_dot = solve_spd(&eq.inertia, &eq.right_side, gamma, |k, g| {
        RouthError::KineticNotPositiveDefinite {
            gamma: gamma_array(g),
            min_eigenvalue: min_eigenvalue(k),
        }
    })?;
    Ok((omega_dot, gamma_dot))
}

/// The factorisation of the first `J(γ)` a vector field solved with, kept and reused while `J`
/// is bitwise the same (every model whose inertia does not depend on γ: tops, gyrostats), so
/// that a simulation factorises a constant `J` once. Once a different `J` is met, `J` depends on
/// the state (an ellipsoid on a plane): from then on every solve factorises afresh and nothing
/// is compared or stored. Solutions are bit for bit those of a new factorisation either way.
#[derive(Default)]
pub(super) enum InertiaCache {
    /// Nothing solved yet.
    #[default]
    Empty,
    /// Every `J` so far was this one.
    Kept(Matrix3<f64>, Ldl),
    /// `J` has changed: it depends on the state.
    Varies,
}

impl InertiaCache {
    /// `J⁻¹b` on the fast path: by the kept factorisation when `J` is the kept one, else by a
    /// new [`Ldl`] when `J` is finite and clearly positive definite. A non-finite `b` gives NaN.
    /// `None` when the fast path declines (`J` not finite, or not clearly positive definite):
    /// the caller then decides with Cholesky.
    #[inline(always)]
    fn solve(&mut self, j: &Matrix3<f64>, b: &Vector3<f64>) -> Option<Vector3<f64>> {
        if !all_finite(b) {
            return Some(Vector3::repeat(f64::NAN));
        }
        match self {
            InertiaCache::Varies => {}
            InertiaCache::Kept(key, inv) => {
                if same_bits(key, j) {
                    return Some(inv.solve(b));
                }
                *self = InertiaCache::Varies;
            }
            InertiaCache::Empty => {
                if j.iter().all(|x| x.is_finite()) {
                    let inv = Ldl::new(j)?;
                    *self = InertiaCache::Kept(*j, inv);
                    return Some(inv.solve(b));
                }
                return None;
            }
        }
        if j.iter().all(|x| x.is_finite()) {
            Ldl::new(j).map(|inv| inv.solve(b))
        } else {
            None
        }
    }
}

/// How a vector field solves with the kinetic matrix `J(γ)`: by Sherman–Morrison when the
/// model has the form `J = J₀ + c v vᵀ` ([`Lagrangian::constant_inertia`], docs/method.md §2a),
/// else through the [`InertiaCache`].
///
/// With `J₀ = LDLᵀ` factorised once per simulation, `J⁻¹b = y − u (c v·y)/(1 + c v·u)` where
/// `y = J₀⁻¹b` and `u = J₀⁻¹v`: two solves with a kept factorisation (for a diagonal `J₀` three
/// products each) and one division, where a fresh factorisation of `J` would put three divisions
/// and the elimination on the critical path of every stage. For `c ≥ 0` and `J₀` positive
/// definite the denominator is at least 1 and `J` is at least as positive definite as `J₀`, so
/// the formula needs no verdict of its own; otherwise (`c < 0`, `J₀` not clearly positive
/// definite, non-finite `c` or `v`) it declines, and `J = J₀ + c v vᵀ` goes to the cache and to
/// Cholesky as any other `J` would.
pub(super) struct InertiaSolver {
    /// `J₀` and, when it is clearly positive definite, its factorisation.
    constant: Option<(Matrix3<f64>, Option<Ldl>)>,
    cache: InertiaCache,
}

impl InertiaSolver {
    #[inline]
    pub(super) fn new<M: Lagrangian + ?Sized>(model: &M) -> Self {
        Self::with_constant(model.constant_inertia())
    }

    /// The solver for a model whose [`Lagrangian::constant_inertia`] is `constant`.
    #[inline]
    fn with_constant(constant: Option<Matrix3<f64>>) -> Self {
        let constant = constant
            .filter(|j0| j0.iter().all(|x| x.is_finite()))
            .map(|j0| {
                let base = Ldl::new(&j0).filter(|_| condition_bound(&j0) <= MAX_BASE_CONDITION);
                (j0, base)
            });
        InertiaSolver {
            constant,
            cache: InertiaCache::default(),
        }
    }

    /// The kinetic matrix of one evaluation: `J₀ + c v vᵀ` when the equations carry the
    /// rank-one part and the model has `J₀`, else the `J` the equations carry.
    #[inline(always)]
    fn matrix(&self, j: &Matrix3<f64>, rank_one: Option<&RankOneInertia>) -> Matrix3<f64> {
        match (rank_one, &self.constant) {
            (Some(r), Some((j0, _))) => r.complete(j0),
            _ => *j,
        }
    }

    /// `J⁻¹b` on the fast path (see [`InertiaCache::solve`]; `None` when it declines). When
    /// the model has `J₀`, the equations' own `j` is not read, so that an inlined generated body
    /// need not compute it.
    #[inline(always)]
    fn solve(
        &mut self,
        j: &Matrix3<f64>,
        rank_one: Option<&RankOneInertia>,
        b: &Vector3<f64>,
    ) -> Option<Vector3<f64>> {
        if let (Some(r), Some((j0, base))) = (rank_one, &self.constant) {
            if let Some(x) = base.and_then(|base| sherman_morrison(&base, r, b)) {
                return Some(x);
            }
            return self.cache.solve(&r.complete(j0), b);
        }
        self.cache.solve(j, b)
    }
}

/// The largest bound [`condition_bound`] of `J₀` for which [`InertiaSolver`] uses
/// Sherman–Morrison. Its error, measured against Cholesky of the completed matrix, grows like
/// the condition number of `J₀`: `sherman_morrison_matches_cholesky` widened to κ(J₀) up to
/// 10⁸ and 30 000 cases gave within 4× of Cholesky's error for κ(J₀) < 2, 9× below 10, 70×
/// near 100 and 200× beyond. Up to 16 it stays within the factor 20 that the LDLᵀ of `J` itself
/// is held to (10× at worst in the test as it stands). Solid bodies are well inside (a uniform
/// ellipsoid with semi-axes 0.8, 1.2, 2 has κ(I) = 2.6, a disc 2); a needle is not, and is
/// solved through `J`.
const MAX_BASE_CONDITION: f64 = 16.0;

/// An upper bound of the condition number `λ_max/λ_min` of a symmetric positive definite 3×3
/// matrix, cheap enough to take once per simulation: `λ_max ≤ ‖K‖_∞` and
/// `λ_min = det K/(λ_mid λ_max) ≥ det K/‖K‖_∞²`, so `κ ≤ ‖K‖_∞³/det K` (∞ when `det K ≤ 0`).
fn condition_bound(k: &Matrix3<f64>) -> f64 {
    let norm = (0..3)
        .map(|i| k.row(i).iter().map(|x| x.abs()).sum::<f64>())
        .fold(0.0, f64::max);
    let det = k.determinant();
    if det > 0.0 {
        norm.powi(3) / det
    } else {
        f64::INFINITY
    }
}

/// `(J₀ + c v vᵀ)⁻¹ b` from the factorisation of `J₀` (see [`InertiaSolver`]); NaN for a
/// non-finite `b`, `None` unless `c ≥ 0` and `c`, `v` and the denominator are finite.
#[inline(always)]
fn sherman_morrison(base: &Ldl, r: &RankOneInertia, b: &Vector3<f64>) -> Option<Vector3<f64>> {
    if !all_finite(b) {
        return Some(Vector3::repeat(f64::NAN));
    }
    let (c, v) = (r.weight, &r.vector);
    if !(c >= 0.0 && c.is_finite() && all_finite(v)) {
        return None;
    }
    let (y, u) = (base.solve(b), base.solve(v));
    let denominator = 1.0 + c * v.dot(&u);
    if !denominator.is_finite() {
        return None;
    }
    Some(y - u * (c * v.dot(&y) / denominator))
}

/// [`full_vector_field`] with an [`InertiaSolver`], for a simulation: the values are those of
/// [`full_vector_field`] bit for bit, except for a model with `J = J₀ + c v vᵀ`, which is solved
/// by Sherman–Morrison (as accurate, see [`MAX_BASE_CONDITION`]), and the same verdicts.
pub(super) struct FullField<'a, M: ?Sized> {
    model: &'a M,
    inertia: InertiaSolver,
}

impl<'a, M: Lagrangian + ?Sized> FullField<'a, M> {
    #[inline]
    pub(super) fn new(model: &'a M) -> Self {
        FullField {
            model,
            inertia: InertiaSolver::new(model),
        }
    }

    #[inline(always)]
    pub(super) fn eval(
        &mut self,
        omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
    ) -> Result<(Vector3<f64>, Vector3<f64>), RouthError> {
        let gamma_dot = gamma.cross(omega);
        // Read in place, see `ReducedField::eval`.
        let eq = self.model.full_equations(omega, gamma);
        let rhs = &eq.right_side;
        if let Some(omega_dot) = self.inertia.solve(&eq.inertia, eq.rank_one.as_ref(), rhs) {
            return Ok((omega_dot, gamma_dot));
        }
        // Declined by the fast path (which has already tried `Ldl` on a finite J): NaN for a
        // non-finite J, else the Cholesky verdict.
        let j = &self.inertia.matrix(&eq.inertia, eq.rank_one.as_ref());
        if !j.iter().all(|x| x.is_finite()) {
            return Ok((Vector3::repeat(f64::NAN), gamma_dot));
        }
        let omega_dot = cholesky_solve(j, rhs, gamma, |k, g| {
            RouthError::KineticNotPositiveDefinite {
                gamma: gamma_array(g),
                min_eigenvalue: min_eigenvalue(k),
            }
        })?;
        Ok((omega_dot, gamma_dot))
    }
}

#[inline]
fn same_bits(a: &Matrix3<f64>, b: &Matrix3<f64>) -> bool {
    a.iter()
        .zip(b.iter())
        .all(|(x, y)| x.to_bits() == y.to_bits())
}

#[inline]
fn all_finite(v: &Vector3<f64>) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The vector field of the reduced equations (13) in the gauge of errata E4, with (15):
/// `A Ω̇ = ∂R/∂Ω × Ω + ∂R/∂γ × γ − M γ̇` with `Ω̇·γ = 0`, `γ̇ = γ × Ω`, `ψ̇ = −∂R/∂p_ψ`,
/// where `A = ∂²R/∂Ω²` and `M = ∂²R/∂Ω∂γ`, from [`Routhian::reduced_equations`]. Returns
/// `(Ω̇, γ̇, ψ̇)`.
///
/// # The gauge, and the solve through J
///
/// `A` annihilates γ (E4), so the γ-component of (13) is an identity and Ω̇ is fixed only up to a
/// multiple of γ; the gauge `Ω̇·γ = 0` picks one, and with `γ̇·Ω = 0` it keeps `Ω·γ` at its
/// initial value.
///
/// For `L = ½ωᵀJω + a·ω − U` (every model of the DSL), differentiating (14) twice in Ω gives
/// `A = J − (Jγ)(Jγ)ᵀ/(γᵀJγ)`, so `A J⁻¹b = b − Jγ (γ·b)/(γᵀJγ) = b` for every `b ⊥ γ`, and
/// the right side `b` is orthogonal to γ (by `Mᵀγ = −∂R/∂Ω`, E6). Hence the gauge solution is
/// `Ω̇ = y − (γ·y/|γ|²)γ` with `y = J⁻¹b`: the singular A is never factorised, and for a body
/// whose J does not depend on γ (tops, gyrostats) the factorisation of J is made once per
/// simulation (the inertia cache) and every evaluation is multiplications and one division,
/// `1/|γ|²`, off the critical path. It is scale-free: J carries the units of A, and the
/// projection none.
///
/// When J is not clearly positive definite (the fast path declines), the solve falls back to
/// `(A + cγγᵀ)Ω̇ = b` with `A` from [`Routhian::d2r_domega2`] and `c = tr(A)/2`, the mean of
/// the two non-zero eigenvalues of A (so that `A + cγγᵀ` is as well conditioned as A on γ^⊥,
/// and c scales with J), by Cholesky, whose failure is the error.
///
/// Errors: [`RouthError::SingularReducedKinetic`] (with the smallest eigenvalue of
/// `A + cγγᵀ`) when that Cholesky factorisation fails for finite entries.
#[inline(always)]
pub fn reduced_vector_field<M: Routhian + ?Sized>(
    model: &M,
    big_omega: &Vector3<f64>,
    gamma: &Vector3<f64>,
    p_psi: f64,
) -> Result<(Vector3<f64>, Vector3<f64>, f64), RouthError> {
    // One evaluation: through J itself, as in `full_vector_field`.
    ReducedField {
        model,
        p_psi,
        inertia: InertiaSolver::with_constant(None),
    }
    .eval(big_omega, gamma)
}

/// [`reduced_vector_field`] on the level `p_ψ`, with an [`InertiaSolver`].
pub(super) struct ReducedField<'a, M: ?Sized> {
    model: &'a M,
    p_psi: f64,
    inertia: InertiaSolver,
}

impl<'a, M: Routhian + ?Sized> ReducedField<'a, M> {
    #[inline]
    pub(super) fn new(model: &'a M, p_psi: f64) -> Self {
        ReducedField {
            model,
            p_psi,
            inertia: InertiaSolver::new(model),
        }
    }

    #[inline(always)]
    pub(super) fn eval(
        &mut self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
    ) -> Result<(Vector3<f64>, Vector3<f64>, f64), RouthError> {
        let gamma_dot = gamma.cross(big_omega);
        // Taken before the solve, so that the division is off its critical path.
        let r_gamma = 1.0 / gamma.norm_squared();
        // Read in place (not moved out of the returned struct): the move is a copy by 16-byte
        // loads of what the generated code has just stored 8 bytes at a time, which the
        // processor cannot forward from its store buffer (9% of a simulation of the ellipsoid).
        let eq = self.model.reduced_equations(big_omega, gamma, self.p_psi);
        let solved = self
            .inertia
            .solve(&eq.inertia, eq.rank_one.as_ref(), &eq.right_side);
        let big_omega_dot = match solved {
            Some(y) => y - gamma * (gamma.dot(&y) * r_gamma),
            None => self.singular_inertia(big_omega, gamma, &eq.right_side)?,
        };
        Ok((big_omega_dot, gamma_dot, eq.psi_dot))
    }

    /// The solve when `J` is not clearly positive definite: `(A + cγγᵀ)Ω̇ = b` by Cholesky.
    #[inline(never)]
    fn singular_inertia(
        &self,
        big_omega: &Vector3<f64>,
        gamma: &Vector3<f64>,
        rhs: &Vector3<f64>,
    ) -> Result<Vector3<f64>, RouthError> {
        let a = self.model.d2r_domega2(big_omega, gamma, self.p_psi);
        let gauge = 0.5 * a[(0, 0)] + 0.5 * a[(1, 1)] + 0.5 * a[(2, 2)];
        let k = a + gamma * gamma.transpose() * gauge;
        solve_spd(&k, rhs, gamma, |k, g| RouthError::SingularReducedKinetic {
            gamma: gamma_array(g),
            min_eigenvalue: min_eigenvalue(k),
        })
    }
}

/// Solves `K x = rhs` for a symmetric positive definite K, reading its lower triangle (as
/// Cholesky does): by [`Ldl`] when K is clearly positive definite, else by nalgebra's
/// Cholesky, whose failure is the error. Non-finite `K` or `rhs` give a NaN solution.
#[inline(always)]
fn solve_spd(
    k: &Matrix3<f64>,
    rhs: &Vector3<f64>,
    gamma: &Vector3<f64>,
    error: impl Fn(&Matrix3<f64>, &Vector3<f64>) -> RouthError,
) -> Result<Vector3<f64>, RouthError> {
    if !(k.iter().all(|x| x.is_finite()) && all_finite(rhs)) {
        return Ok(Vector3::repeat(f64::NAN));
    }
    if let Some(inv) = Ldl::new(k) {
        return Ok(inv.solve(rhs));
    }
    cholesky_solve(k, rhs, gamma, error)
}

/// The slow path of [`solve_spd`], out of line.
#[inline(never)]
fn cholesky_solve(
    k: &Matrix3<f64>,
    rhs: &Vector3<f64>,
    gamma: &Vector3<f64>,
    error: impl Fn(&Matrix3<f64>, &Vector3<f64>) -> RouthError,
) -> Result<Vector3<f64>, RouthError> {
    match k.cholesky() {
        Some(ch) => Ok(ch.solve(rhs)),
        None => Err(error(k, gamma)),
    }
}

/// `K = L D Lᵀ` of a symmetric 3×3 matrix K from its lower triangle (Cholesky without square
/// roots: `D = diag(d₁, d₂, d₃)` holds the squares of the Cholesky factor's diagonal), kept so
/// that a solve is multiplications only.
///
/// Every evaluation of the vector fields solves with K, and the solve is on the critical path of
/// the integrator (each stage needs the previous one). Cholesky puts three square roots and six
/// divisions in a chain there; the usual LDLᵀ two rounds of divisions (`1/d₁` before `d₂`). Here
/// the pivots are carried multiplied by `k₁₁` (fraction-free elimination), so that all three
/// divisions are taken side by side, once, at the end:
/// `d₂' = k₁₁d₂ = k₁₁k₂₂ − k₂₁²`, `m₃₂' = k₁₁k₃₂ − k₃₁k₂₁`, `s₃₃' = k₁₁k₃₃ − k₃₁²` and
/// `Δ = k₁₁²d₂d₃ = d₂'s₃₃' − m₃₂'²`; the solve is
/// `z₂ = k₁₁b₂ − k₂₁b₁`, `t₃ = k₁₁b₃ − k₃₁b₁`, `x₃ = (d₂'t₃ − m₃₂'z₂)/Δ`,
/// `x₂ = (z₂ − m₃₂'x₃)/d₂'`, `x₁ = (b₁ − k₂₁x₂ − k₃₁x₃)/k₁₁`. These are the quantities of the
/// usual recurrence scaled by powers of `k₁₁`, formed from the same products, so they carry the
/// same relative rounding errors, and the solve is as accurate as Cholesky (see
/// `matches_cholesky_on_ill_conditioned_matrices`). A constant K (tops, gyrostats) is factorised
/// once ([`InertiaCache`]), and a diagonal one is then solved by three independent products.
///
/// Shorter chains were tried and rejected: the adjugate `adj K/det K`, and pivots from the
/// leading minors (`d₃ = det K/M₂`), lose accuracy through the cancellation in `det K`: on a
/// rotated K with condition number κ their error grows like κ²ε, Cholesky's like κε.
///
/// [`Ldl::new`] declines (`None`) unless every pivot exceeds `1e-13` times its diagonal entry:
/// the pivots of Cholesky and of this factorisation differ by a few ε of the diagonal, so
/// outside that margin both find K positive definite, and inside it the caller asks Cholesky,
/// whose verdict (and error) is then exactly that of before. It also declines when `Δ`, a
/// product of four entries, over- or underflows (entries beyond about 1e±75), where Cholesky
/// still works.
#[derive(Debug, Clone, Copy)]
pub(super) struct Ldl {
    k11: f64,
    k21: f64,
    k31: f64,
    d2: f64,
    m32: f64,
    /// `1/k₁₁`, `1/d₂'`, `1/Δ`.
    r1: f64,
    r2: f64,
    q: f64,
    /// For a diagonal K (all multipliers zero): `1/K₂₂ = k₁₁/d₂'` and `1/K₃₃ = k₁₁d₂'/Δ`, so
    /// that the solve is three independent products; `None` otherwise.
    diagonal: Option<(f64, f64)>,
}

/// Pivots must exceed this fraction of their diagonal entry (see [`Ldl`]).
const PIVOT_MARGIN: f64 = 1e-13;

impl Ldl {
    #[inline]
    pub(super) fn new(k: &Matrix3<f64>) -> Option<Ldl> {
        let (k11, k21, k31) = (k[(0, 0)], k[(1, 0)], k[(2, 0)]);
        let (k22, k32, k33) = (k[(1, 1)], k[(2, 1)], k[(2, 2)]);
        let d2 = k11 * k22 - k21 * k21;
        let m32 = k11 * k32 - k31 * k21;
        let s33 = k11 * k33 - k31 * k31;
        let delta = d2 * s33 - m32 * m32;
        let (r1, r2, q) = (1.0 / k11, 1.0 / d2, 1.0 / delta);
        // d₁ > 0, d₂ = d₂'/k₁₁ and d₃ = Δ/(k₁₁d₂') clearly positive. Written so that NaN
        // declines; infinite entries decline too (∞ is not > ∞).
        let clear = k11 > 0.0
            && d2 > PIVOT_MARGIN * k22.abs() * k11
            && delta > PIVOT_MARGIN * k33.abs() * d2 * k11
            && r1.is_normal()
            && r2.is_normal()
            && q.is_normal();
        let diagonal = (k21 == 0.0 && k31 == 0.0 && m32 == 0.0).then_some((k11 * r2, k11 * d2 * q));
        clear.then_some(Ldl {
            k11,
            k21,
            k31,
            d2,
            m32,
            r1,
            r2,
            q,
            diagonal,
        })
    }

    /// `K⁻¹b`: the elimination scaled by `k₁₁` (see [`Ldl`]). Always inlined: it is on the
    /// critical path of every stage, and with three call sites (two in Sherman–Morrison)
    /// LLVM otherwise keeps it out of line.
    #[inline(always)]
    pub(super) fn solve(&self, b: &Vector3<f64>) -> Vector3<f64> {
        if let Some((r22, r33)) = self.diagonal {
            return Vector3::new(b.x * self.r1, b.y * r22, b.z * r33);
        }
        let z2 = self.k11 * b.y - self.k21 * b.x;
        let t3 = self.k11 * b.z - self.k31 * b.x;
        let x3 = (self.d2 * t3 - self.m32 * z2) * self.q;
        let x2 = (z2 - self.m32 * x3) * self.r2;
        let x1 = (b.x - self.k21 * x2 - self.k31 * x3) * self.r1;
        Vector3::new(x1, x2, x3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Rotation3;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// The factorisation solves like Cholesky, reads only the lower triangle, is scale-free within
    /// its range, and declines (leaving the verdict to Cholesky) near and past singularity.
    #[test]
    fn ldl_matches_cholesky() {
        let k = Matrix3::new(4.0, 1.0, -0.5, 1.0, 3.0, 0.25, -0.5, 0.25, 2.0);
        let b = Vector3::new(0.3, -1.2, 2.5);
        let x = Ldl::new(&k).expect("SPD").solve(&b);
        let y = k.cholesky().expect("SPD").solve(&b);
        assert!((x - y).amax() < 4e-16 * y.amax(), "{x} vs {y}");
        // Only the lower triangle is read.
        let mut upper = k;
        upper[(0, 1)] = 100.0;
        assert_eq!(Ldl::new(&upper).expect("SPD").solve(&b), x);
        // Scale-free: powers of two are exact, so the solution is the same to the bit.
        for s in [2f64.powi(-200), 2f64.powi(200)] {
            let xs = Ldl::new(&(k * s)).expect("SPD").solve(&b) * s;
            assert_eq!(xs, x, "{s:e}");
        }
        // Beyond about 1e±150 the product d₂d₃ leaves the range: declined, and `solve_spd`
        // solves by Cholesky.
        let err = |_: &Matrix3<f64>, _: &Vector3<f64>| RouthError::NonFiniteState { t: 0.0 };
        for s in [1e-200, 1e200] {
            assert!(Ldl::new(&(k * s)).is_none(), "{s:e}");
            let xs = solve_spd(&(k * s), &b, &Vector3::z(), err).unwrap() * s;
            assert!((xs - y).amax() < 4e-16 * y.amax(), "{s:e}");
        }
        // Singular, indefinite, singular to working precision, non-finite: declined.
        let singular = Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        let indefinite = Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        let negative = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
        let nearly = Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0 + 1e-15, 0.0, 0.0, 0.0, 1.0);
        for m in [singular, indefinite, negative, nearly, Matrix3::zeros()] {
            assert!(Ldl::new(&m).is_none(), "{m}");
        }
        // Any non-finite entry of the lower triangle.
        for (i, j) in [(0, 0), (1, 0), (2, 0), (1, 1), (2, 1), (2, 2)] {
            for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut m = k;
                m[(i, j)] = x;
                m[(j, i)] = x;
                assert!(Ldl::new(&m).is_none(), "{m}");
            }
        }
    }

    /// A random rotation of `diag(1, κ^u, κ)` (u uniform in [0, 1]) times a scale `10^s`, s
    /// uniform in `[−range, range]`; returns the matrix and the scale.
    fn random_spd(rng: &mut ChaCha8Rng, cond: f64, range: f64) -> (Matrix3<f64>, f64) {
        let axis = Vector3::new(rng.gen(), rng.gen(), rng.gen::<f64>()) - Vector3::repeat(0.5);
        let rot = Rotation3::new(axis * 6.0);
        let lam = Vector3::new(1.0, cond.powf(rng.gen()), cond);
        let scale = 10f64.powf(rng.gen_range(-range..range));
        let k = rot.matrix() * Matrix3::from_diagonal(&lam) * rot.matrix().transpose() * scale;
        ((k + k.transpose()) * 0.5, scale)
    }

    /// `K x` with the rounding of each product compensated (two-product via `mul_add`, and a
    /// compensated sum): the right side of which `x` is the exact solution, to working precision.
    fn compensated_product(k: &Matrix3<f64>, x: &Vector3<f64>) -> Vector3<f64> {
        Vector3::from_fn(|r, _| {
            let (mut s, mut c) = (0.0f64, 0.0f64);
            for j in 0..3 {
                let p = k[(r, j)] * x[j];
                let e = k[(r, j)].mul_add(x[j], -p);
                let t = s + p;
                c += if s.abs() >= p.abs() {
                    (s - t) + p
                } else {
                    (p - t) + s
                } + e;
                s = t;
            }
            s + c
        })
    }

    /// On random rotated SPD matrices with condition numbers κ from 1 to 1e12, the error of the
    /// solution (against the exact x of `b = Kx` computed with compensated products) is within a
    /// small factor of Cholesky's (or of κε); the adjugate (nalgebra's 3×3 inverse) is not.
    #[test]
    fn matches_cholesky_on_ill_conditioned_matrices() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let (mut worst, mut worst_adj): (f64, f64) = (0.0, 0.0);
        for i in 0..3000 {
            let cond = 10f64.powf(12.0 * (i % 100) as f64 / 99.0);
            let (k, _) = random_spd(&mut rng, cond, 5.0);
            let x_true =
                Vector3::new(rng.gen(), rng.gen(), rng.gen::<f64>()) - Vector3::repeat(0.5);
            let b = compensated_product(&k, &x_true);
            let Some(ch) = k.cholesky() else { continue };
            let e_ch = (ch.solve(&b) - x_true).norm() / x_true.norm();
            let e_ldl = match Ldl::new(&k) {
                Some(inv) => (inv.solve(&b) - x_true).norm() / x_true.norm(),
                None => continue,
            };
            let floor = 1e-16 * cond;
            worst = worst.max(e_ldl / (e_ch + floor));
            // The adjugate, for comparison.
            let adj = k.try_inverse().expect("invertible") * b;
            worst_adj = worst_adj.max(((adj - x_true).norm() / x_true.norm()) / (e_ch + floor));
        }
        assert!(worst < 20.0, "LDLᵀ error / Cholesky error up to {worst}");
        assert!(worst_adj > 1e3, "the adjugate is worse: {worst_adj}");
    }

    /// The cache gives the solutions of a fresh factorisation, bit for bit, through all three of
    /// its states: kept while J repeats, then, once J changes, afresh for every J (including a
    /// return to the first one).
    #[test]
    fn inertia_cache_solves_like_a_fresh_factorisation() {
        let mut rng = ChaCha8Rng::seed_from_u64(0xCAC4E);
        let spd = |rng: &mut ChaCha8Rng| {
            let a = Matrix3::from_fn(|_, _| rng.gen_range(-1.0..1.0));
            a * a.transpose() + Matrix3::identity()
        };
        let (j1, j2, j3) = (spd(&mut rng), spd(&mut rng), spd(&mut rng));
        let mut cache = InertiaCache::default();
        for (k, j) in [j1, j1, j1, j2, j1, j3, j3].iter().enumerate() {
            let b = Vector3::from_fn(|_, _| rng.gen_range(-5.0..5.0));
            let got = cache.solve(j, &b).expect("clearly positive definite");
            let want = Ldl::new(j).expect("clearly positive definite").solve(&b);
            assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "solve {k}");
            let state = match cache {
                InertiaCache::Empty => "empty",
                InertiaCache::Kept(..) => "kept",
                InertiaCache::Varies => "varies",
            };
            assert_eq!(state, if k < 3 { "kept" } else { "varies" }, "solve {k}");
        }
        // A singular J is declined in every state, and a non-finite b gives NaN.
        let singular = Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert!(InertiaCache::default()
            .solve(&singular, &Vector3::x())
            .is_none());
        assert!(cache.solve(&singular, &Vector3::x()).is_none());
        let nan = cache.solve(&j1, &Vector3::new(f64::NAN, 0.0, 0.0)).unwrap();
        assert!(nan.iter().all(|x| x.is_nan()));
    }

    /// Sherman–Morrison from the factorisation of `J₀` solves `J₀ + c v vᵀ` as accurately as
    /// Cholesky of the completed matrix when `J₀` is as well conditioned as the solver requires:
    /// random rotated `J₀` with condition numbers up to [`MAX_BASE_CONDITION`], `c` from 1e-6 to
    /// 1e6 of its scale, against the exact `x` of `b = Jx` (compensated products, as above),
    /// within the factor 20 of Cholesky's error (or of κ(J)ε) that LDLᵀ is held to. Beyond that
    /// the factor grows like κ(J₀) (measured: 70 near 100, 200 beyond), which is why the solver
    /// then factorises `J` instead.
    #[test]
    fn sherman_morrison_matches_cholesky() {
        let mut rng = ChaCha8Rng::seed_from_u64(0x5A4E);
        let mut worst: f64 = 0.0;
        for i in 0..5000 {
            let cond = MAX_BASE_CONDITION.powf((i % 50) as f64 / 49.0);
            let (j0, scale) = random_spd(&mut rng, cond, 3.0);
            let r = RankOneInertia {
                weight: scale * 10f64.powf(rng.gen_range(-6.0..6.0)),
                vector: Vector3::from_fn(|_, _| rng.gen_range(-1.0..1.0)),
            };
            let j = r.complete(&j0);
            let x_true = Vector3::from_fn(|_, _| rng.gen_range(-0.5..0.5));
            let b = compensated_product(&j, &x_true);
            let Some(ch) = j.cholesky() else { continue };
            let base = Ldl::new(&j0).expect("positive definite");
            let x = sherman_morrison(&base, &r, &b).expect("c ≥ 0");
            let err = |y: Vector3<f64>| (y - x_true).norm() / x_true.norm();
            let eig = j.symmetric_eigenvalues();
            let floor = 1e-16 * eig.max() / eig.min();
            worst = worst.max(err(x) / (err(ch.solve(&b)) + floor));
        }
        assert!(
            worst < 20.0,
            "Sherman–Morrison error / Cholesky error up to {worst}"
        );
    }

    /// The bound is an upper bound of the condition number, tight for multiples of the identity,
    /// and keeps ill-conditioned or singular `J₀` off Sherman–Morrison.
    #[test]
    fn condition_bound_bounds() {
        let mut rng = ChaCha8Rng::seed_from_u64(0xC0D);
        for _ in 0..1000 {
            let a = Matrix3::from_fn(|_, _| rng.gen_range(-1.0..1.0));
            let k = a * a.transpose() + Matrix3::identity() * 1e-3;
            let eig = k.symmetric_eigenvalues();
            assert!(condition_bound(&k) >= eig.max() / eig.min() * (1.0 - 1e-12));
        }
        assert!((condition_bound(&(Matrix3::identity() * 3.0)) - 1.0).abs() < 1e-15);
        assert_eq!(condition_bound(&Matrix3::zeros()), f64::INFINITY);
        let needle = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.02));
        assert!(InertiaSolver::with_constant(Some(needle))
            .constant
            .unwrap()
            .1
            .is_none());
        let body = Matrix3::from_diagonal(&Vector3::new(5.44, 4.64, 2.08));
        assert!(InertiaSolver::with_constant(Some(body))
            .constant
            .unwrap()
            .1
            .is_some());
    }

    /// The solver takes Sherman–Morrison when it may and otherwise hands `J₀ + c v vᵀ` to the
    /// cache, never the equations' own J (which an inlined body need not compute): `c < 0`,
    /// a non-finite `c`, or a `J₀` that is not positive definite give the cache's solution of
    /// the completed matrix (or its refusal), bit for bit; without `J₀` the equations' J is used.
    #[test]
    fn inertia_solver_falls_back_to_the_completed_matrix() {
        let j0 = Matrix3::new(2.0, 0.3, 0.0, 0.3, 1.5, -0.2, 0.0, -0.2, 1.0);
        let v = Vector3::new(0.4, -1.0, 0.7);
        let b = Vector3::new(1.0, 2.0, -3.0);
        let unused = Matrix3::repeat(f64::NAN);
        let bits = |x: Vector3<f64>| x.map(f64::to_bits);
        let ldl = |j: &Matrix3<f64>| Ldl::new(j).map(|f| bits(f.solve(&b)));
        let mut solver = InertiaSolver::with_constant(Some(j0));
        // c ≥ 0: Sherman–Morrison, close to the completed matrix's solution.
        let r = RankOneInertia {
            weight: 3.0,
            vector: v,
        };
        let x = solver
            .solve(&unused, Some(&r), &b)
            .expect("positive definite");
        let y = r.complete(&j0).cholesky().unwrap().solve(&b);
        assert!((x - y).amax() < 1e-15 * y.amax(), "{x} vs {y}");
        // c < 0, still positive definite: the cache's factorisation of J₀ + c v vᵀ.
        let r = RankOneInertia {
            weight: -0.1,
            vector: v,
        };
        let got = solver.solve(&unused, Some(&r), &b).map(bits);
        assert_eq!(got, ldl(&r.complete(&j0)));
        assert!(got.is_some());
        // c < 0 past definiteness: declined (the field then asks Cholesky of the same matrix).
        let r = RankOneInertia {
            weight: -10.0,
            vector: v,
        };
        assert!(solver.solve(&unused, Some(&r), &b).is_none());
        assert_eq!(solver.matrix(&unused, Some(&r)), r.complete(&j0));
        // Non-finite c: the completed matrix is not finite, declined.
        let r = RankOneInertia {
            weight: f64::NAN,
            vector: v,
        };
        assert!(solver.solve(&unused, Some(&r), &b).is_none());
        // A singular J₀ made definite by c v vᵀ... is not: J₀ = 0 gives the rank-one J.
        let mut singular = InertiaSolver::with_constant(Some(Matrix3::zeros()));
        let r = RankOneInertia {
            weight: 1.0,
            vector: v,
        };
        assert!(singular.solve(&unused, Some(&r), &b).is_none());
        // J₀ semi-definite, completed to definite: the cache solves the completed matrix.
        let semi = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.0));
        let mut solver = InertiaSolver::with_constant(Some(semi));
        let r = RankOneInertia {
            weight: 2.0,
            vector: Vector3::z(),
        };
        let got = solver.solve(&unused, Some(&r), &b).map(bits);
        assert_eq!(got, ldl(&r.complete(&semi)));
        // Without J₀, or without c v vᵀ: the equations' J.
        let j = r.complete(&j0);
        let mut none = InertiaSolver::with_constant(None);
        assert_eq!(none.solve(&j, Some(&r), &b).map(bits), ldl(&j));
        let mut solver = InertiaSolver::with_constant(Some(j0));
        assert_eq!(solver.solve(&j, None, &b).map(bits), ldl(&j));
        // A non-finite right side: NaN.
        let nan = Vector3::new(f64::NAN, 0.0, 0.0);
        let r = RankOneInertia {
            weight: 1.0,
            vector: v,
        };
        let x = solver.solve(&unused, Some(&r), &nan).unwrap();
        assert!(x.iter().all(|x| x.is_nan()));
    }

    /// `solve_spd` keeps Cholesky's verdict: an error exactly where Cholesky fails, NaN for
    /// non-finite input.
    #[test]
    fn solve_spd_verdicts() {
        let err = |_: &Matrix3<f64>, _: &Vector3<f64>| RouthError::NonFiniteState { t: 0.0 };
        let g = Vector3::z();
        let b = Vector3::new(1.0, 2.0, 3.0);
        let indefinite = Matrix3::new(1.0, 2.0, 0.0, 2.0, 1.0, 0.0, 0.0, 0.0, 1.0);
        assert!(solve_spd(&indefinite, &b, &g, err).is_err());
        // Positive definite but declined by the margin: Cholesky's solution.
        let nearly = Matrix3::new(1.0, 1.0, 0.0, 1.0, 1.0 + 1e-14, 0.0, 0.0, 0.0, 1.0);
        assert_eq!(
            solve_spd(&nearly, &b, &g, err).unwrap(),
            nearly.cholesky().unwrap().solve(&b)
        );
        let x = solve_spd(
            &Matrix3::identity(),
            &Vector3::new(f64::INFINITY, 0.0, 0.0),
            &g,
            err,
        );
        assert!(x.unwrap().iter().all(|v| v.is_nan()));
    }
}
