//! The flow of the full equations (8) over one period with its derivative: the state
//! `x = (ω, γ)`, the variational matrix `Φ` (`Φ' = DF(x)Φ`, `Φ(0) = I`) and the attitude, as one
//! system of 46 equations integrated by the crate's DOP853 (docs/method.md §11).

use nalgebra::{Matrix3, Matrix6, Quaternion, SVector, UnitQuaternion, Vector3, Vector6};

use super::{OrbitOptions, PeriodicOrbit};
use crate::sim::dop853::{self, Accepted, Config};
use crate::validate::{gamma_array, min_eigenvalue};
use crate::{simulate_full, Lagrangian, RouthError, SimOptions, Trajectory};

/// The state (6), `Φ` column by column (36) and the attitude quaternion `(w, x, y, z)` (4).
pub(crate) const DIM: usize = 46;
const PHI: usize = 6;
const QUAT: usize = 42;

/// `(ω, γ)` as one vector.
pub(crate) fn join(omega: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector6<f64> {
    Vector6::new(omega.x, omega.y, omega.z, gamma.x, gamma.y, gamma.z)
}

/// `(ω, γ)` of one vector.
pub(crate) fn split(x: &Vector6<f64>) -> (Vector3<f64>, Vector3<f64>) {
    (x.fixed_rows::<3>(0).into(), x.fixed_rows::<3>(3).into())
}

/// `F(x) = (ω̇, γ̇)` of (8) and its Jacobian `DF(x)` (see [`crate::FullJacobian`]):
/// `∂ω̇/∂ω = J⁻¹∂f/∂ω`, `∂ω̇/∂γ_k = J⁻¹(∂f/∂γ_k − (∂J/∂γ_k)ω̇)`, `∂γ̇/∂ω = [γ]×`,
/// `∂γ̇/∂γ = −[ω]×`.
#[inline]
pub(crate) fn field_and_jacobian<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
) -> Result<(Vector6<f64>, Matrix6<f64>), RouthError> {
    let (w, g) = split(x);
    let jac = model.full_jacobian(&w, &g);
    let Some(chol) = jac.inertia.cholesky() else {
        return Err(RouthError::KineticNotPositiveDefinite {
            gamma: gamma_array(&g),
            min_eigenvalue: min_eigenvalue(&jac.inertia),
        });
    };
    let w_dot = chol.solve(&jac.right_side);
    let g_dot = g.cross(&w);
    let mut dg = jac.dright_dgamma;
    for k in 0..3 {
        let col = jac.dinertia_dgamma[k] * w_dot;
        for i in 0..3 {
            dg[(i, k)] -= col[i];
        }
    }
    let a_ww = chol.solve(&jac.dright_domega);
    let a_wg = chol.solve(&dg);
    let mut a = Matrix6::zeros();
    a.fixed_view_mut::<3, 3>(0, 0).copy_from(&a_ww);
    a.fixed_view_mut::<3, 3>(0, 3).copy_from(&a_wg);
    a.fixed_view_mut::<3, 3>(3, 0).copy_from(&g.cross_matrix());
    a.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(-w.cross_matrix()));
    let f = Vector6::new(w_dot.x, w_dot.y, w_dot.z, g_dot.x, g_dot.y, g_dot.z);
    Ok((f, a))
}

/// `F(x)` alone (no Jacobian), as [`crate::sim::full_vector_field`].
pub(crate) fn field<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
) -> Result<Vector6<f64>, RouthError> {
    let (w, g) = split(x);
    let (wd, gd) = crate::sim::full_vector_field(model, &w, &g)?;
    Ok(join(&wd, &gd))
}

/// The gradients of the energy (3) and of the cyclic momentum (9) in `x = (ω, γ)`:
/// `∂E/∂ω = Jω`, `∂E/∂γ = Nᵀω − ∂L/∂γ`, `∂p/∂ω = Jγ`, `∂p/∂γ = Nᵀγ + ∂L/∂ω` with
/// `N = ∂²L/∂ω∂γ`, and their values.
pub(crate) fn integrals<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
) -> (f64, Vector6<f64>, f64, Vector6<f64>) {
    let (w, g) = split(x);
    let j = model.d2l_domega2(&g);
    let n: Matrix3<f64> = model.d2l_domega_dgamma(&w, &g);
    let lw = model.dl_domega(&w, &g);
    let lg = model.dl_dgamma(&w, &g);
    let e = model.energy(&w, &g);
    let p = lw.dot(&g);
    let de = join(&(j * w), &(n.tr_mul(&w) - lg));
    let dp = join(&(j * g), &(n.tr_mul(&g) + lw));
    (e, de, p, dp)
}

/// The flow over `[0, t]` from `x0`.
pub(crate) struct Shot {
    /// `φ_t(x₀)`.
    pub end: Vector6<f64>,
    /// `Φ(t)`.
    pub monodromy: Matrix6<f64>,
    /// `R(t)` with `R(0) = I` (body to space at `t`, in the space frame of the body at 0).
    pub turn: UnitQuaternion<f64>,
    /// Half the largest distance from `x₀` of the accepted steps' states (a cheap bound of
    /// half the orbit's diameter; 0 at a steady motion).
    pub reach: f64,
}

/// Integrates (8), its variational equations and the attitude from `x0` over `[0, t]`.
pub(crate) fn shoot<M: Lagrangian + ?Sized>(
    model: &M,
    x0: &Vector6<f64>,
    t: f64,
    opts: &OrbitOptions,
) -> Result<Shot, RouthError> {
    let mut y0 = SVector::<f64, DIM>::zeros();
    y0.fixed_rows_mut::<6>(0).copy_from(x0);
    for i in 0..6 {
        y0[PHI + 7 * i] = 1.0;
    }
    y0[QUAT] = 1.0;
    let (rtol, atol) = (opts.rtol, opts.atol);
    // Error control on the state and the attitude (10 components); the variational matrix rides
    // along on the same steps (its equations are the state's linearisation), as is usual for
    // monodromies. The RMS norm divides by all 46 components, so the controlled ones are
    // weighed by √(10/46) to keep their tolerance.
    let scale = (10.0f64 / DIM as f64).sqrt();
    let weights = move |a: &SVector<f64, DIM>, b: &SVector<f64, DIM>| {
        SVector::<f64, DIM>::from_fn(|i, _| {
            if (PHI..PHI + 36).contains(&i) {
                f64::INFINITY
            } else {
                scale * (atol + rtol * a[i].abs().max(b[i].abs()))
            }
        })
    };
    let cfg = Config {
        weights: &weights,
        h_max: f64::INFINITY,
        h_init: None,
        max_steps: opts.max_steps,
        dense: false,
        control: Some(&opts.control),
    };
    let rhs = |_t: f64, y: &SVector<f64, DIM>| -> Result<SVector<f64, DIM>, RouthError> {
        let x: Vector6<f64> = y.fixed_rows::<6>(0).into();
        let (f, a) = field_and_jacobian(model, &x)?;
        let phi = nalgebra::Matrix6::from_column_slice(&y.as_slice()[PHI..PHI + 36]);
        let dphi = a * phi;
        let q = Quaternion::new(y[QUAT], y[QUAT + 1], y[QUAT + 2], y[QUAT + 3]);
        let (w, _) = split(&x);
        // q̇ = ½ q ⊗ (0, ω): Ṙ = R[ω]× with ω in the body frame.
        let dq = q * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
        let mut out = SVector::<f64, DIM>::zeros();
        out.fixed_rows_mut::<6>(0).copy_from(&f);
        out.as_mut_slice()[PHI..PHI + 36].copy_from_slice(dphi.as_slice());
        out[QUAT] = dq.w;
        out[QUAT + 1] = dq.i;
        out[QUAT + 2] = dq.j;
        out[QUAT + 3] = dq.k;
        Ok(out)
    };
    let mut last = y0;
    let mut reach = 0.0f64;
    dop853::integrate(rhs, 0.0, y0, t, &cfg, |s: &Accepted<'_, DIM>| {
        last = *s.y;
        let x: Vector6<f64> = s.y.fixed_rows::<6>(0).into();
        reach = reach.max((x - x0).norm());
        Ok(())
    })?;
    let end: Vector6<f64> = last.fixed_rows::<6>(0).into();
    let monodromy = Matrix6::from_column_slice(&last.as_slice()[PHI..PHI + 36]);
    let q = Quaternion::new(last[QUAT], last[QUAT + 1], last[QUAT + 2], last[QUAT + 3]);
    Ok(Shot {
        end,
        monodromy,
        turn: UnitQuaternion::from_quaternion(q),
        reach: 0.5 * reach,
    })
}

/// `φ_t(x₀)` alone (no variational equations, no attitude), under the same error control of
/// the state as [`shoot`]: for residuals whose Jacobian is not needed.
pub(crate) fn flow_end<M: Lagrangian + ?Sized>(
    model: &M,
    x0: &Vector6<f64>,
    t: f64,
    opts: &OrbitOptions,
) -> Result<Vector6<f64>, RouthError> {
    let weights = dop853::componentwise(opts.rtol, opts.atol);
    let cfg = Config {
        weights: &weights,
        h_max: f64::INFINITY,
        h_init: None,
        max_steps: opts.max_steps,
        dense: false,
        control: Some(&opts.control),
    };
    let mut end = *x0;
    dop853::integrate(
        |_t: f64, x: &Vector6<f64>| field(model, x),
        0.0,
        *x0,
        t,
        &cfg,
        |s: &Accepted<'_, 6>| {
            end = *s.y;
            Ok(())
        },
    )?;
    Ok(end)
}

/// `Δψ ∈ (−π, π]` of a turn `R(T)` (with `R(0) = I`) about the vertical `γ₀` (body coordinates
/// at 0, which are the space coordinates of that frame): `q = (cos Δψ/2, sin Δψ/2 γ₀)`.
pub(crate) fn precession(turn: &UnitQuaternion<f64>, gamma0: &Vector3<f64>) -> f64 {
    let q = turn.quaternion();
    let s = q.imag().dot(gamma0);
    let mut a = 2.0 * s.atan2(q.w);
    if a <= -std::f64::consts::PI {
        a += 2.0 * std::f64::consts::PI;
    } else if a > std::f64::consts::PI {
        a -= 2.0 * std::f64::consts::PI;
    }
    a
}

/// The most samples [`orbit_path`] takes (a million: about 200 MB with the attitude).
const MAX_PATH_SAMPLES: usize = 1_000_000;

/// The orbit sampled at `2 ≤ n ≤ 10⁶` equally spaced times over one period (`t = 0` and `t = T`
/// included), with the attitude: for figures (γ on the sphere, the apex locus) and tables.
pub fn orbit_path<M: Lagrangian>(
    model: &M,
    orbit: &PeriodicOrbit,
    n: usize,
) -> Result<Trajectory, RouthError> {
    if !(2..=MAX_PATH_SAMPLES).contains(&n) {
        return Err(RouthError::InvalidOption {
            what: "n",
            reason: format!(
                "need between 2 and {MAX_PATH_SAMPLES} samples (each ≈ 200 bytes), got {n}"
            ),
        });
    }
    check_orbit(orbit)?;
    // `T·i/(n − 1)` rounds above `T` for some `T` and `n` at `i = n − 1`: the last time is `T`.
    let times = (0..n)
        .map(|i| (orbit.period * i as f64 / (n - 1) as f64).min(orbit.period))
        .collect();
    let opts = SimOptions::with_tolerances(1e-11, 1e-12)
        .with_attitude()
        .at_times(times);
    simulate_full(model, orbit.omega0, orbit.gamma0, orbit.period, &opts)
}

/// Refuses an orbit whose start or period cannot be integrated (one read from a file, or built
/// by hand), naming the orbit's field rather than the integrator's argument.
pub(crate) fn check_orbit(orbit: &PeriodicOrbit) -> Result<(), RouthError> {
    crate::validate::check_finite("orbit.omega0", orbit.omega0.as_slice())?;
    crate::validate::unit_gamma("orbit.gamma0", &orbit.gamma0)?;
    if !(orbit.period.is_finite() && orbit.period > 0.0) {
        return Err(RouthError::InvalidOption {
            what: "orbit.period",
            reason: format!("must be positive and finite, got {}", orbit.period),
        });
    }
    Ok(())
}

/// The point nearest `x` with `p_ψ = p` and `|γ| = 1`: minimum-norm Gauss–Newton steps on the
/// two constraints (three are plenty from a point off them at second order).
pub(crate) fn onto_level<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
    p: f64,
) -> Vector6<f64> {
    let mut x = *x;
    for _ in 0..4 {
        let (_, _, px, dp) = integrals(model, &x);
        let (_, g) = split(&x);
        let c = nalgebra::Vector2::new(px - p, 0.5 * (g.norm_squared() - 1.0));
        let mut j = nalgebra::SMatrix::<f64, 2, 6>::zeros();
        j.set_row(0, &dp.transpose());
        for k in 0..3 {
            j[(1, 3 + k)] = g[k];
        }
        let Some(inv) = (j * j.transpose()).try_inverse() else {
            break;
        };
        x -= j.transpose() * (inv * c);
    }
    let (w, g) = split(&x);
    join(&w, &g.normalize())
}
