//! [`simulate_reduced`]: the reduced equations (13) for `(Ω, γ)` on a level of `p_ψ`, with the
//! reconstruction (15) of the rotation angle ψ.

use nalgebra::{SVector, UnitQuaternion, Vector3};

use super::checks::{
    all_finite, check_unit_gamma, flow_tape, non_finite_record, too_large, validate,
};
use super::drive::{drive, split3, Field, WithAttitude};
use super::field::{reduced_vector_field, ReducedField};
use super::{attitude, taylor, Method, ReducedTrajectory, SimOptions};
use crate::solve::norm::stable_norm;
use crate::validate::check_finite;
use crate::{RouthError, Routhian};

impl<'a, M: Routhian + ?Sized> Field<11> for WithAttitude<ReducedRhs<'a, M>> {
    #[inline(always)]
    fn eval(
        &mut self,
        y: &SVector<f64, 11>,
    ) -> Result<(SVector<f64, 11>, Vector3<f64>), RouthError> {
        let (d7, w) = self.0.eval(&y.fixed_rows::<7>(0).into_owned())?;
        let mut d = SVector::<f64, 11>::zeros();
        d.fixed_rows_mut::<7>(0).copy_from(&d7);
        attitude::write(
            &mut d,
            7,
            &attitude::rate(&attitude::read(y, 7), &split3(y, 0)),
        );
        Ok((d, w))
    }
}

/// The state `(Ω, γ, ψ)` of (13), (15) on the level `p_psi`, and its rates.
pub(super) struct ReducedRhs<'a, M: ?Sized>(pub(super) ReducedField<'a, M>);

impl<M: Routhian + ?Sized> Field<7> for ReducedRhs<'_, M> {
    #[inline(always)]
    fn eval(&mut self, y: &SVector<f64, 7>) -> Result<(SVector<f64, 7>, Vector3<f64>), RouthError> {
        let (w, g) = (split3(y, 0), split3(y, 3));
        let (w_dot, g_dot, psi_dot) = self.0.eval(&w, &g)?;
        let mut d = SVector::<f64, 7>::zeros();
        d.fixed_rows_mut::<3>(0).copy_from(&w_dot);
        d.fixed_rows_mut::<3>(3).copy_from(&g_dot);
        d[6] = psi_dot;
        // γ̇ = γ × Ω = (−Ω) × γ.
        Ok((d, -w))
    }
}

/// Simulates the reduced equations (13) from `(Ω₀, γ₀)` at `t = 0` to `t_end` on the level
/// `p_ψ` of the cyclic momentum (9), and reconstructs the rotation angle ψ of the rotating frame
/// by (15), `ψ̇ = −∂R/∂p_ψ`, with `ψ(0) = 0`.
///
/// The equations are solved in the gauge of errata E4 (see [`reduced_vector_field`]):
/// `∂²R/∂Ω²` is singular along γ, the component of Ω along γ is a gauge, and the integration
/// keeps `Ω·γ` at its initial value. Ω₀ is used as given: the usual choice is `Ω₀·γ₀ = 0`, for
/// which `ψ̇` is the whole rotation rate about the vertical. With `Ω₀·γ₀ = s ≠ 0` the body motion
/// `ω = Ω + ψ̇γ` is the same and ψ differs by `s·t` (since `ψ̇(Ω + sγ) = ψ̇(Ω) − s` by (38)).
///
/// The full state corresponding to `(Ω₀, γ₀, p_ψ)` is `ω₀ = Ω₀ + ψ̇(Ω₀, γ₀, p_ψ) γ₀` (7), (12).
/// Recorded along the way: E' (16) (equal to E of (3)), `(∂R/∂Ω, γ)` (17) (identically p_ψ),
/// `|γ|²`, ψ̇ and the reconstructed ω.
///
/// # Errors
///
/// As [`simulate_full`](super::simulate_full) (an overflowing input is named `"p_psi"` or
/// `"big_omega0"`), plus [`RouthError::DegenerateVerticalInertia`] when
/// `γ₀ᵀJ(γ₀)γ₀ ≤ 0` (ψ̇ of (38) undefined), and
/// [`RouthError::SingularReducedKinetic`] when `∂²R/∂Ω² + cγγᵀ` has no Cholesky factor;
/// [`RouthError::InvalidOption`] for [`Method::Taylor`] with a model that has no
/// [`flow_tape`](crate::Lagrangian::flow_tape).
///
/// With [`Method::Taylor`] the body's motion is integrated by Taylor's method on the flow tape
/// of (8) from `ω₀ = Ω₀ + ψ̇γ₀`, and `(Ω, ψ)` are read from it in the same gauge: `Ω·γ = Ω₀·γ₀`
/// and `ω = Ω + ψ̇γ` give `ψ̇ = (ω·γ − Ω₀·γ₀)/|γ|²`, whose Taylor series is integrated for ψ
/// (docs/method.md §2c).
pub fn simulate_reduced<M: Routhian>(
    model: &M,
    big_omega0: Vector3<f64>,
    gamma0: Vector3<f64>,
    p_psi: f64,
    t_end: f64,
    opts: &SimOptions,
) -> Result<ReducedTrajectory, RouthError> {
    check_finite("big_omega0", big_omega0.as_slice())?;
    check_finite("gamma0", gamma0.as_slice())?;
    check_finite("p_psi", &[p_psi])?;
    validate(opts, t_end)?;
    check_unit_gamma(&gamma0)?;
    let vertical_inertia = gamma0.dot(&(model.d2l_domega2(&gamma0) * gamma0));
    // Also rejects NaN.
    if vertical_inertia.is_nan() || vertical_inertia <= 0.0 {
        return Err(RouthError::DegenerateVerticalInertia {
            gamma: [gamma0.x, gamma0.y, gamma0.z],
            value: vertical_inertia,
        });
    }
    // As in `simulate_full`, the recorded E' (16) and (17) must be finite at the start too.
    let finite_at = |w: &Vector3<f64>, p: f64| {
        reduced_vector_field(model, w, &gamma0, p).map(|(a, b, c)| {
            let r = model.bundle(w, &gamma0, p);
            let recorded = [r.dr_domega.dot(w) - r.routhian, r.dr_domega.dot(&gamma0)];
            all_finite(&a)
                && all_finite(&b)
                && c.is_finite()
                && recorded.iter().all(|x| x.is_finite())
        })
    };
    if !finite_at(&big_omega0, p_psi)? {
        let zero = Vector3::zeros();
        return Err(if !finite_at(&zero, 0.0)? {
            RouthError::NonFiniteModel {
                what: "reduced vector field (13) at Omega = 0, p_psi = 0",
                gamma: [gamma0.x, gamma0.y, gamma0.z],
            }
        } else if !finite_at(&zero, p_psi)? {
            too_large("p_psi", p_psi.abs(), "(13)")
        } else {
            too_large("big_omega0", stable_norm(big_omega0.as_slice()), "(13)")
        });
    }
    let mut y0 = SVector::<f64, 7>::zeros();
    y0.fixed_rows_mut::<3>(0).copy_from(&big_omega0);
    y0.fixed_rows_mut::<3>(3).copy_from(&gamma0);

    let mut traj = ReducedTrajectory::default();
    let mut record = |t: f64, y: &SVector<f64, 7>, q: Option<UnitQuaternion<f64>>| {
        let (w, g) = (split3(y, 0), split3(y, 3));
        if let Some(q) = q {
            // (15): R = R_z(ψ) R_Ω.
            traj.attitude.push(attitude::about_vertical(y[6]) * q);
        }
        // Only R, ∂R/∂Ω and ψ̇ (not the whole bundle, see `reduced_vector_field`).
        let (psi_dot, dr_domega) = (model.psi_dot(&w, &g, p_psi), model.dr_domega(&w, &g, p_psi));
        traj.t.push(t);
        traj.big_omega.push(w);
        traj.gamma.push(g);
        traj.psi.push(y[6]);
        traj.psi_dot.push(psi_dot);
        traj.omega.push(w + g * psi_dot);
        traj.energy
            .push(dr_domega.dot(&w) - model.routhian(&w, &g, p_psi));
        traj.p_psi.push(dr_domega.dot(&g));
        traj.gamma_norm_sq.push(g.norm_squared());
    };
    let q0 = opts.attitude.then(|| attitude::initial_attitude(&gamma0));
    let stats = match (q0, opts.method) {
        (q0, Method::Taylor) => {
            // The body's motion by Taylor's method on the flow tape of (8), from
            // ω₀ = Ω₀ + ψ̇γ₀ (7); Ω and ψ are read from it in the gauge Ω·γ = Ω₀·γ₀ of (13).
            let tape = flow_tape(model)?;
            let s = big_omega0.dot(&gamma0);
            let omega0 = big_omega0 + gamma0 * model.psi_dot(&big_omega0, &gamma0, p_psi);
            let q0 = q0.map(|q| q.into_inner());
            let start = taylor::Start {
                omega0,
                gamma0,
                q0,
                gauge: Some(s),
            };
            taylor::integrate(&tape, start, t_end, opts, |t, w, g, q, psi| {
                let psi = psi.unwrap_or(0.0);
                let mut y = SVector::<f64, 7>::zeros();
                let big = w - g * ((w.dot(&g) - s) / g.norm_squared());
                y.fixed_rows_mut::<3>(0).copy_from(&big);
                y.fixed_rows_mut::<3>(3).copy_from(&g);
                y[6] = psi;
                // The body's attitude R = R_z(ψ) R_Ω (15): `record` takes R_Ω.
                let q = q.map(|q| attitude::about_vertical(-psi) * attitude::aligned(&q, &g));
                record(t, &y, q)
            })?
        }
        (Some(q0), Method::Dop853) => {
            let mut y0q = SVector::<f64, 11>::zeros();
            y0q.fixed_rows_mut::<7>(0).copy_from(&y0);
            attitude::write(&mut y0q, 7, q0.quaternion());
            let field = WithAttitude(ReducedRhs(ReducedField::new(model, p_psi)));
            drive(field, y0q, t_end, opts, None, |t, y, _| {
                let q = attitude::aligned(&attitude::read(y, 7), &split3(y, 3));
                record(t, &y.fixed_rows::<7>(0).into_owned(), Some(q))
            })?
        }
        (q0, _) => {
            let field = ReducedRhs(ReducedField::new(model, p_psi));
            drive(field, y0, t_end, opts, q0, |t, y, q| {
                record(t, y, q.copied())
            })?
        }
    };
    let omega: Vec<f64> = (traj.omega.iter())
        .map(|w| if all_finite(w) { 0.0 } else { f64::NAN })
        .collect();
    let columns = [
        &traj.psi[..],
        &traj.psi_dot,
        &omega,
        &traj.energy,
        &traj.p_psi,
    ];
    non_finite_record(&traj.t, &columns)?;
    traj.stats = stats;
    Ok(traj)
}
