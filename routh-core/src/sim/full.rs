//! [`simulate_full`]: the full equations of motion (8) for `(ω, γ)`.

use nalgebra::{SVector, UnitQuaternion, Vector3};

use super::checks::{
    all_finite, check_unit_gamma, flow_tape, non_finite_record, too_large, validate,
};
use super::drive::{drive, split3, Field, WithAttitude};
use super::field::{full_vector_field, FullField};
use super::{attitude, taylor, Method, SimOptions, Trajectory};
use crate::solve::norm::stable_norm;
use crate::validate::check_finite;
use crate::{Lagrangian, RouthError};

/// Simulates the full equations of motion (8) from `(ω₀, γ₀)` at `t = 0` to `t_end`.
///
/// The state is `(ω, γ)`; ω̇ is solved from
/// `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − (∂²L/∂ω∂γ)(γ × ω)` with `J = ∂²L/∂ω²` by a square-root-free
/// Cholesky factorisation (factorised once when `J` does not depend on γ; when
/// `J = J₀ + c(γ) v(γ) v(γ)ᵀ`, a body on a plane, `J₀` is factorised once and each solve is
/// Sherman–Morrison, docs/method.md §2a), and `γ̇ = γ × ω` (see [`full_vector_field`]). Along the trajectory the energy (3), the cyclic
/// momentum (9) and `|γ|²` are recorded; they are first integrals, so their drift measures the
/// integration error.
///
/// γ₀ must be a unit vector (`| |γ₀| − 1 | ≤ 1e−8`, [`UNIT_GAMMA_TOL`](crate::validate::UNIT_GAMMA_TOL)); it is used as given
/// (not normalised).
///
/// # Errors
///
/// [`RouthError::NonFinite`] for non-finite `ω₀`, `γ₀`, `t_end`, tolerances or options;
/// [`RouthError::InvalidOption`] for `t_end < 0`, invalid [`SimOptions`], or a finite `ω₀` so
/// large that the vector field overflows (`what: "omega0"`); [`RouthError::NonFiniteModel`]
/// when the vector field is not finite at `(0, γ₀)`;
/// [`RouthError::NonUnitGamma`]; [`RouthError::KineticNotPositiveDefinite`] when `J(γ)` has no
/// Cholesky factor (at γ₀ or later); [`RouthError::StepSizeUnderflow`],
/// [`RouthError::TooManySteps`] and [`RouthError::NonFiniteState`] from the integrator;
/// [`RouthError::InvalidOption`] for [`Method::Taylor`] with a model that has no
/// [`flow_tape`](Lagrangian::flow_tape).
///
/// # Example
///
/// A heavy symmetric (Lagrange) top `L = ½(A(ω₁² + ω₂²) + Cω₃²) − m g l γ₃` (a model written by
/// hand is shown at [`steady_motions`](crate::steady_motions)):
///
/// ```
/// # use test_models::HeavyTop;
/// use routh_core::{simulate_full, SimOptions, Vector3};
///
/// let top = HeavyTop::lagrange(2.0, 1.0, 1.0); // A = 2, C = 1, m g l = 1
/// let gamma0 = Vector3::new(0.6, 0.0, 0.8); // tilted
/// let omega0 = Vector3::new(0.0, 0.3, 5.0); // spinning fast
/// let traj = simulate_full(&top, omega0, gamma0, 10.0, &SimOptions::default())?;
///
/// assert_eq!(traj.t[0], 0.0);
/// assert_eq!(*traj.t.last().unwrap(), 10.0);
/// // The spin ω₃ of a Lagrange top is constant (Euler's third equation).
/// assert!(traj.omega.iter().all(|w| (w.z - 5.0).abs() < 1e-9));
/// // Energy (3), cyclic momentum (9) and |γ|² are kept.
/// assert!(traj.energy_drift() < 1e-8);
/// assert!(traj.p_psi_drift() < 1e-8);
/// assert!(traj.gamma_norm_error() < 1e-9);
/// # Ok::<(), routh_core::RouthError>(())
/// ```
pub fn simulate_full<M: Lagrangian>(
    model: &M,
    omega0: Vector3<f64>,
    gamma0: Vector3<f64>,
    t_end: f64,
    opts: &SimOptions,
) -> Result<Trajectory, RouthError> {
    check_finite("omega0", omega0.as_slice())?;
    check_finite("gamma0", gamma0.as_slice())?;
    validate(opts, t_end)?;
    check_unit_gamma(&gamma0)?;
    // A finite input for which the vector field overflows: say which input is too large.
    // The recorded integrals count too: an ω₀ for which the energy (3) overflows (|ω₀| = 1e300)
    // is too large even where the field is finite (found by tests/runtime_properties.rs).
    let finite_at = |w: &Vector3<f64>| {
        full_vector_field(model, w, &gamma0).map(|(a, b)| {
            all_finite(&a)
                && all_finite(&b)
                && model.energy(w, &gamma0).is_finite()
                && model.cyclic_momentum(w, &gamma0).is_finite()
        })
    };
    if !finite_at(&omega0)? {
        return Err(if finite_at(&Vector3::zeros())? {
            too_large("omega0", stable_norm(omega0.as_slice()), "(8)")
        } else {
            RouthError::NonFiniteModel {
                what: "full vector field (8) at omega = 0",
                gamma: [gamma0.x, gamma0.y, gamma0.z],
            }
        });
    }
    let mut y0 = SVector::<f64, 6>::zeros();
    y0.fixed_rows_mut::<3>(0).copy_from(&omega0);
    y0.fixed_rows_mut::<3>(3).copy_from(&gamma0);

    let mut traj = Trajectory::default();
    let mut push = |t: f64, w: Vector3<f64>, g: Vector3<f64>, q: Option<UnitQuaternion<f64>>| {
        traj.t.push(t);
        traj.omega.push(w);
        traj.gamma.push(g);
        traj.energy.push(model.energy(&w, &g));
        traj.p_psi.push(model.cyclic_momentum(&w, &g));
        traj.gamma_norm_sq.push(g.norm_squared());
        if let Some(q) = q {
            traj.attitude.push(q);
        }
    };
    let q0 = opts.attitude.then(|| attitude::initial_attitude(&gamma0));
    let stats = match (q0, opts.method) {
        (q0, Method::Taylor) => {
            let tape = flow_tape(model)?;
            let q0 = q0.map(|q| q.into_inner());
            let start = taylor::Start {
                omega0,
                gamma0,
                q0,
                gauge: None,
            };
            taylor::integrate(&tape, start, t_end, opts, |t, w, g, q, _| {
                let q = q.map(|q| attitude::aligned(&q, &g));
                push(t, w, g, q)
            })?
        }
        (Some(q0), Method::Dop853) => {
            let mut y0q = SVector::<f64, 10>::zeros();
            y0q.fixed_rows_mut::<6>(0).copy_from(&y0);
            attitude::write(&mut y0q, 6, q0.quaternion());
            let field = WithAttitude(FullRhs(FullField::new(model)));
            drive(field, y0q, t_end, opts, None, |t, y, _| {
                let g = split3(y, 3);
                let q = attitude::aligned(&attitude::read(y, 6), &g);
                push(t, split3(y, 0), g, Some(q))
            })?
        }
        (q0, _) => {
            let field = FullRhs(FullField::new(model));
            drive(field, y0, t_end, opts, q0, |t, y, q| {
                push(t, split3(y, 0), split3(y, 3), q.copied())
            })?
        }
    };
    // A finite state can still overflow the recorded integrals (a fixed-step run gone unstable).
    non_finite_record(&traj.t, &[&traj.energy, &traj.p_psi])?;
    traj.stats = stats;
    Ok(traj)
}

/// The state `(ω, γ)` of (8) and its rates.
pub(super) struct FullRhs<'a, M: ?Sized>(pub(super) FullField<'a, M>);

impl<M: Lagrangian + ?Sized> Field<6> for FullRhs<'_, M> {
    #[inline(always)]
    fn eval(&mut self, y: &SVector<f64, 6>) -> Result<(SVector<f64, 6>, Vector3<f64>), RouthError> {
        let (w, g) = (split3(y, 0), split3(y, 3));
        let (w_dot, g_dot) = self.0.eval(&w, &g)?;
        let mut d = SVector::<f64, 6>::zeros();
        d.fixed_rows_mut::<3>(0).copy_from(&w_dot);
        d.fixed_rows_mut::<3>(3).copy_from(&g_dot);
        // γ̇ = γ × ω = (−ω) × γ.
        Ok((d, -w))
    }
}

impl<'a, M: Lagrangian + ?Sized> Field<10> for WithAttitude<FullRhs<'a, M>> {
    #[inline(always)]
    fn eval(
        &mut self,
        y: &SVector<f64, 10>,
    ) -> Result<(SVector<f64, 10>, Vector3<f64>), RouthError> {
        let (d6, w) = self.0.eval(&y.fixed_rows::<6>(0).into_owned())?;
        let mut d = SVector::<f64, 10>::zeros();
        d.fixed_rows_mut::<6>(0).copy_from(&d6);
        attitude::write(
            &mut d,
            6,
            &attitude::rate(&attitude::read(y, 6), &split3(y, 0)),
        );
        Ok((d, w))
    }
}
