//! The integration loop shared by [`simulate_full`](super::simulate_full) and
//! [`simulate_reduced`](super::simulate_reduced): the chosen [`Method`], the error weights of
//! [`SimOptions`] and the [`Output`] points.

use crate::solve::norm::stable_norm;
use nalgebra::{SVector, UnitQuaternion, Vector3};

use super::{attitude, dop853, lie, Method, Output, SimOptions, SimStats};
use crate::RouthError;

/// An autonomous vector field `y ↦ (ẏ, w)`, with `w` the angular velocity that moves γ
/// (`y[3..6]`): `γ̇ = w × γ`. Implemented by the drivers' fields with `#[inline(always)]`.
pub(super) trait Field<const N: usize> {
    fn eval(&mut self, y: &SVector<f64, N>) -> Result<(SVector<f64, N>, Vector3<f64>), RouthError>;
}

/// A [`Field`] as the right-hand side `f(t, y)` of [`dop853::integrate`].
struct Autonomous<'a, F>(&'a mut F);

impl<const N: usize, F: Field<N>> dop853::Rhs<N> for Autonomous<'_, F> {
    #[inline(always)]
    fn eval(&mut self, _t: f64, y: &SVector<f64, N>) -> Result<SVector<f64, N>, RouthError> {
        self.0.eval(y).map(|(d, _)| d)
    }
}

/// Integrates `y' = field(y).0` from `y0` at `t = 0` to `t_end` with the chosen method and
/// output, calling `record` at every output point. `field` returns `(ẏ, w)` with `w` the
/// angular velocity that moves γ (`y[3..6]`): `γ̇ = w × γ`.
///
/// `lie_attitude`: with [`Method::LieRk4`], an initial attitude `R₀` (body → space) moved along
/// by the rotations of the steps, `R₁ = R₀ exp(−[u]×)` with `γ₁ = exp([u]×)γ₀`
/// ([`lie::step`]), so that `γ = Rᵀe₃` stays exact to round-off; it is passed to `record`
/// (`None` otherwise, and always with [`Method::Dop853`], where an attitude is part of `y`).
pub(super) fn drive<const N: usize, F, R>(
    mut field: F,
    y0: SVector<f64, N>,
    t_end: f64,
    opts: &SimOptions,
    lie_attitude: Option<UnitQuaternion<f64>>,
    mut record: R,
) -> Result<SimStats, RouthError>
where
    F: Field<N>,
    R: FnMut(f64, &SVector<f64, N>, Option<&UnitQuaternion<f64>>),
{
    let times: Option<&[f64]> = match &opts.output {
        Output::Steps => None,
        Output::Times(ts) => Some(ts),
    };
    match opts.method {
        Method::Dop853 => {
            let (rtol, atol) = (opts.rtol, opts.atol);
            let rate_atol = opts.rate_atol.unwrap_or(atol);
            // Per-3-vector weights (see `SimOptions`): y[0..3] is the angular velocity, y[3..6]
            // γ, any further component (ψ) is weighted on its own.
            let weights = move |y0: &SVector<f64, N>, y1: &SVector<f64, N>| {
                let len = |at| {
                    stable_norm(split3(y0, at).as_slice())
                        .max(stable_norm(split3(y1, at).as_slice()))
                };
                let (w_rate, w_gamma) = (rate_atol + rtol * len(0), atol + rtol * len(3));
                SVector::<f64, N>::from_fn(|i, _| match i {
                    0..=2 => w_rate,
                    3..=5 => w_gamma,
                    _ => atol + rtol * y0[i].abs().max(y1[i].abs()),
                })
            };
            let cfg = dop853::Config {
                weights: &weights,
                h_max: opts.h_max.unwrap_or(f64::INFINITY),
                h_init: opts.h_init,
                max_steps: opts.max_steps,
                dense: times.is_some(),
                control: None,
            };
            let mut next = 0;
            match times {
                None => record(0.0, &y0, None),
                Some(ts) => {
                    while next < ts.len() && ts[next] <= 0.0 {
                        record(ts[next], &y0, None);
                        next += 1;
                    }
                }
            }
            let counters =
                dop853::integrate(Autonomous(&mut field), 0.0, y0, t_end, &cfg, |acc| {
                    match (times, acc.dense) {
                        (None, _) => record(acc.t, acc.y, None),
                        (Some(ts), dense) => {
                            while next < ts.len() && ts[next] <= acc.t {
                                let tn = ts[next];
                                match dense {
                                    Some(d) if tn < acc.t => record(tn, &d.eval(tn), None),
                                    _ => record(tn, acc.y, None),
                                }
                                next += 1;
                            }
                        }
                    }
                    Ok(())
                })?;
            Ok(SimStats {
                accepted_steps: counters.accepted,
                rejected_steps: counters.rejected,
                rhs_evaluations: counters.evaluations,
            })
        }
        // Taylor's method has its own loop (module `taylor`), which both drivers call instead.
        Method::Taylor => Err(super::checks::invalid(
            "method",
            "Method::Taylor is integrated by its own loop, not by this one",
        )),
        Method::LieRk4 { step } => {
            // Segments [start, end] of equal sub-steps, recording at the end of each sub-step
            // (Steps) or only at the end of the segment (Times).
            let segments: Vec<f64> = match times {
                None => vec![t_end],
                Some(ts) => ts.to_vec(),
            };
            let mut total = 0.0;
            let mut prev = 0.0;
            for &end in &segments {
                total += ((end - prev) / step).ceil();
                prev = end;
            }
            if total > opts.max_steps as f64 {
                // Reported before integrating: `steps` is the number the run would need.
                return Err(RouthError::TooManySteps {
                    t: t_end,
                    steps: total as usize,
                });
            }
            // The vector field at the start: surfaces errors even when nothing is integrated.
            let (d0, w0) = field.eval(&y0)?;
            if !(d0.iter().all(|x| x.is_finite()) && w0.iter().all(|x| x.is_finite())) {
                return Err(RouthError::NonFiniteState { t: 0.0 });
            }
            let mut stats = SimStats {
                rhs_evaluations: 1,
                ..SimStats::default()
            };
            let mut q = lie_attitude;
            if times.is_none() {
                record(0.0, &y0, q.as_ref());
            }
            let mut t = 0.0;
            let mut y = y0;
            for &end in &segments {
                let n = ((end - t) / step).ceil() as usize;
                let h = if n > 0 { (end - t) / n as f64 } else { 0.0 };
                let start = t;
                for i in 1..=n {
                    let (y1, u) = lie::step(&mut |y: &SVector<f64, N>| field.eval(y), &y, h)?;
                    y = y1;
                    if let Some(r) = q.as_mut() {
                        *r *= attitude::exp(&-u);
                    }
                    stats.accepted_steps += 1;
                    stats.rhs_evaluations += 4;
                    t = if i == n { end } else { start + i as f64 * h };
                    if !y.iter().all(|x| x.is_finite()) {
                        return Err(RouthError::NonFiniteState { t });
                    }
                    if times.is_none() {
                        record(t, &y, q.as_ref());
                    }
                }
                t = end;
                if times.is_some() {
                    record(t, &y, q.as_ref());
                }
            }
            Ok(stats)
        }
    }
}

#[inline]
pub(super) fn split3<const N: usize>(y: &SVector<f64, N>, at: usize) -> Vector3<f64> {
    Vector3::new(y[at], y[at + 1], y[at + 2])
}

/// A field of `N` components extended by the attitude quaternion `q` at `y[N..N + 4]`, moved by
/// the angular velocity `ω` (full) or Ω (reduced) of `y[0..3]`: `q̇ = ½ q ⊗ (0, ω)` (module
/// [`attitude`]). For [`Method::Dop853`] only (the Lie method moves the attitude exactly).
pub(super) struct WithAttitude<F>(pub(super) F);
