//! A compact DOP853 (Dormand–Prince 8(5,3)) integrator with Hairer's step-size control, initial
//! step heuristic and 7th-order dense output, for small fixed-size systems `y' = f(t, y)`.
//!
//! This follows Hairer's `dop853.f` (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.10): the
//! error is a weighted RMS norm, the 5th- and 3rd-order estimators are combined as
//! `err = |h|·err₅²/sqrt(N(err₅² + 0.01·err₃²))`, and the step factor is
//! `h_new = h / clamp(err^{1/8}/0.9, 1/6, 1/0.333)`. Two departures, both so that a change of
//! units changes nothing:
//!
//! - the weights `sk` of the norm come from the caller ([`Weights`]), so that the simulation can
//!   weigh 3-vectors by their Euclidean length (rotation invariance) and give the angular
//!   velocities their own absolute tolerance (units of 1/time); Hairer's componentwise
//!   `sk = atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|)` is [`componentwise`];
//! - the initial-step heuristic estimates the (p+1)-th derivative as `d₁·(d₂/d₁)^p` instead of
//!   Hairer's `max(d₁, d₂)`, which mixes the units 1/time and 1/time² (see [`initial_step`]).

use nalgebra::SVector;

use super::tableau::{A, B, BHH, C, D, ER};
use crate::RouthError;

/// The right-hand side `f(t, y)`. Closures implement it; the simulation's vector fields implement
/// it with `#[inline(always)]`, so that the field is compiled into the stage loop and the stage
/// values reach it in registers rather than through memory.
pub(crate) trait Rhs<const N: usize> {
    /// `f(t, y)`.
    fn eval(&mut self, t: f64, y: &SVector<f64, N>) -> Result<SVector<f64, N>, RouthError>;
}

impl<const N: usize, F> Rhs<N> for F
where
    F: FnMut(f64, &SVector<f64, N>) -> Result<SVector<f64, N>, RouthError>,
{
    #[inline(always)]
    fn eval(&mut self, t: f64, y: &SVector<f64, N>) -> Result<SVector<f64, N>, RouthError> {
        self(t, y)
    }
}

/// `f.eval(t, y)` kept out of line, for the evaluations outside the step loop (the first one and
/// the initial-step heuristic), so that the inlined field is compiled only where it is hot.
#[inline(never)]
fn eval_cold<const N: usize, F: Rhs<N>>(
    f: &mut F,
    t: f64,
    y: &SVector<f64, N>,
) -> Result<SVector<f64, N>, RouthError> {
    f.eval(t, y)
}

/// Safety factor of the step-size controller.
const SAFE: f64 = 0.9;
/// Lower bound `h_new/h ≥ FAC1`.
const FAC1: f64 = 0.333;
/// Upper bound `h_new/h ≤ FAC2`.
const FAC2: f64 = 6.0;
/// Step reduction after a step that produced non-finite values.
const NONFINITE_SHRINK: f64 = 0.1;

/// The weights `sk` of the error norm of a step from `y₀` to `y₁`: the error of component i is
/// measured as `eᵢ/skᵢ` (accept when the RMS is ≤ 1). Every `skᵢ` must be positive.
pub(crate) type Weights<'a, const N: usize> =
    &'a dyn Fn(&SVector<f64, N>, &SVector<f64, N>) -> SVector<f64, N>;

/// Hairer's componentwise weights `skᵢ = atol + rtol·max(|y₀ᵢ|, |y₁ᵢ|)` (the periodic orbits'
/// integrations, and the tests).
pub(crate) fn componentwise<const N: usize>(
    rtol: f64,
    atol: f64,
) -> impl Fn(&SVector<f64, N>, &SVector<f64, N>) -> SVector<f64, N> {
    move |y0, y1| y0.zip_map(y1, |a, b| atol + rtol * a.abs().max(b.abs()))
}

/// Settings of one adaptive integration (validated by the caller).
#[derive(Clone, Copy)]
pub(crate) struct Config<'a, const N: usize> {
    /// The weights of the error norm.
    pub weights: Weights<'a, N>,
    /// Largest step (`f64::INFINITY` for none).
    pub h_max: f64,
    /// Initial step; `None` for Hairer's heuristic.
    pub h_init: Option<f64>,
    /// Budget of attempted steps.
    pub max_steps: usize,
    /// Whether to prepare the dense output of every accepted step (3 more evaluations a step).
    pub dense: bool,
    /// The caller's run control, looked at before every step (`None`: not cancellable).
    pub control: Option<&'a crate::RunControl>,
}

/// Work counters of one integration.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Counters {
    pub accepted: usize,
    pub rejected: usize,
    pub evaluations: usize,
}

/// The 7th-order continuous extension of one accepted step `[t_old, t_old + h]`.
#[derive(Debug, Clone)]
pub(crate) struct DenseStep<const N: usize> {
    t_old: f64,
    h: f64,
    cont: [SVector<f64, N>; 8],
}

impl<const N: usize> DenseStep<N> {
    /// The interpolated state at `t` (Hairer's `contd8`); exact at both ends up to round-off.
    pub fn eval(&self, t: f64) -> SVector<f64, N> {
        let s = (t - self.t_old) / self.h;
        let s1 = 1.0 - s;
        let c = &self.cont;
        let conp = c[4] + (c[5] + (c[6] + c[7] * s) * s1) * s;
        c[0] + (c[1] + (c[2] + (c[3] + conp * s1) * s) * s1) * s
    }
}

/// One accepted step as seen by the output callback.
pub(crate) struct Accepted<'a, const N: usize> {
    /// End of the step (the new current time).
    pub t: f64,
    /// State at `t`.
    pub y: &'a SVector<f64, N>,
    /// Continuous extension over `[t_old, t]`, when `Config::dense` is set.
    pub dense: Option<&'a DenseStep<N>>,
}

#[inline]
fn all_finite<const N: usize>(v: &SVector<f64, N>) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// The result of one trial step of size `h` from `(t, y)` with `k[0] = f(t, y)`.
struct Trial<const N: usize> {
    y_new: SVector<f64, N>,
    /// Scaled error estimate (accept when ≤ 1); may be non-finite.
    err: f64,
}

/// `y + h·Σⱼ a_{I+1,j+1}·k[j]` over the non-zero coefficients of row `I`, accumulated in the
/// order of j. With `I` a constant the loop is unrolled and the zero coefficients vanish at
/// compile time (the stage values are the same, bit for bit, as those of a loop over the row).
#[inline(always)]
fn stage_input<const I: usize, const N: usize>(
    y: &SVector<f64, N>,
    k: &[SVector<f64, N>; 16],
    h: f64,
) -> SVector<f64, N> {
    let mut yi = *y;
    let mut j = 0;
    while j < I {
        let a = A[I][j];
        if a != 0.0 {
            yi += k[j] * (h * a);
        }
        j += 1;
    }
    yi
}

/// [`stage_input`] for a stage `i` known only at run time (a jump to the unrolled row), so that
/// the stages share one call site of the right-hand side.
#[inline(always)]
fn stage_input_at<const N: usize>(
    i: usize,
    y: &SVector<f64, N>,
    k: &[SVector<f64, N>; 16],
    h: f64,
) -> SVector<f64, N> {
    match i {
        1 => stage_input::<1, N>(y, k, h),
        2 => stage_input::<2, N>(y, k, h),
        3 => stage_input::<3, N>(y, k, h),
        4 => stage_input::<4, N>(y, k, h),
        5 => stage_input::<5, N>(y, k, h),
        6 => stage_input::<6, N>(y, k, h),
        7 => stage_input::<7, N>(y, k, h),
        8 => stage_input::<8, N>(y, k, h),
        9 => stage_input::<9, N>(y, k, h),
        10 => stage_input::<10, N>(y, k, h),
        11 => stage_input::<11, N>(y, k, h),
        13 => stage_input::<13, N>(y, k, h),
        14 => stage_input::<14, N>(y, k, h),
        15 => stage_input::<15, N>(y, k, h),
        _ => unreachable!("stage {i} is not built from A"),
    }
}

/// Computes stages 2–12 into `k[1..12]`, the 8th-order solution and the error estimate.
#[inline(always)]
fn trial_step<const N: usize, F>(
    f: &mut F,
    t: f64,
    y: &SVector<f64, N>,
    h: f64,
    k: &mut [SVector<f64, N>; 16],
    weights: Weights<'_, N>,
) -> Result<Trial<N>, RouthError>
where
    F: Rhs<N>,
{
    for i in 1..12 {
        let yi = stage_input_at(i, y, k, h);
        k[i] = f.eval(t + C[i] * h, &yi)?;
    }
    let mut incr = SVector::<f64, N>::zeros();
    for (j, b) in B.iter().enumerate() {
        if *b != 0.0 {
            incr += k[j] * *b;
        }
    }
    let y_new = y + incr * h;
    let sk = weights(y, &y_new);
    let (mut err5, mut err3) = (0.0, 0.0);
    for i in 0..N {
        let sk = sk[i];
        let e3 = incr[i] - BHH[0] * k[0][i] - BHH[1] * k[8][i] - BHH[2] * k[11][i];
        err3 += (e3 / sk).powi(2);
        let e5: f64 = ER.iter().zip(k.iter()).map(|(e, kj)| e * kj[i]).sum();
        err5 += (e5 / sk).powi(2);
    }
    let mut deno = err5 + 0.01 * err3;
    if deno <= 0.0 {
        deno = 1.0;
    }
    let err = h.abs() * err5 * (1.0 / (N as f64 * deno)).sqrt();
    Ok(Trial { y_new, err })
}

/// The initial step: Hairer's `hinit` of `dop853.f` (order p + 1 = 8), with a time-consistent
/// estimate of the higher derivatives.
///
/// With `d₀ = ‖y₀‖`, `d₁ = ‖f(y₀)‖` (weighted norms) the trial `h₀ = 0.01·d₀/d₁` and
/// `d₂ = ‖f(y₀ + h₀f₀) − f₀‖/h₀` (≈ ‖y''‖), Hairer takes `h₁ = (0.01/max(d₁, d₂))^{1/(p+1)}` as
/// if `‖y^{(p+1)}‖ ≈ max(d₁, d₂)`; but d₁ has units 1/time and d₂ 1/time², so the first step
/// (and so the step count) would depend on the unit of time. Here the rate `ν = d₂/d₁` is taken
/// as the factor each derivative adds: `‖y^{(p+1)}‖ ≈ d₁ν^p`, `h₁ = (0.01/(d₁ν^p))^{1/(p+1)}`
/// (the same as Hairer's when ν = 1), and `h = min(100h₀, h₁, h_max)`. Every quantity scales as
/// 1/time when time does, so h scales with it.
fn initial_step<const N: usize, F>(
    f: &mut F,
    t: f64,
    y: &SVector<f64, N>,
    f0: &SVector<f64, N>,
    cfg: &Config<'_, N>,
    counters: &mut Counters,
) -> Result<f64, RouthError>
where
    F: Rhs<N>,
{
    const ORDER: f64 = 8.0;
    let sk = (cfg.weights)(y, y);
    let d1 = f0.component_div(&sk).norm();
    let d0 = y.component_div(&sk).norm();
    if !(d1 > 0.0 && d0 > 0.0 && d1.is_finite() && d0.is_finite()) {
        // At rest (f = 0) or degenerate weights: nothing sets a time scale.
        return Ok(1e-6f64.min(cfg.h_max));
    }
    let h0 = (0.01 * (d0 / d1)).min(cfg.h_max);
    let y1 = y + f0 * h0;
    let f1 = eval_cold(f, t + h0, &y1)?;
    counters.evaluations += 1;
    let d2 = (f1 - f0).component_div(&sk).norm() / h0;
    let h1 = if !d2.is_finite() {
        h0 * 1e-3
    } else {
        // ln h₁ = (ln 0.01 − ln d₁ − p ln ν)/(p + 1); ν = 0 gives h₁ = ∞.
        let nu = d2 / d1;
        ((0.01f64.ln() - d1.ln() - (ORDER - 1.0) * nu.ln()) / ORDER).exp()
    };
    Ok((100.0 * h0).min(h1).min(cfg.h_max))
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` to `t_end > t0`, calling `on_step` after every
/// accepted step (the initial point is not reported). The last step ends exactly at `t_end`.
///
/// Errors: whatever `f` or `on_step` returns; `StepSizeUnderflow` when `0.1·h ≤ |t|·ε` (or `h`
/// is subnormal); `TooManySteps` when `max_steps` steps were attempted; `NonFiniteState` when
/// `f(t0, y0)` is not finite, or when non-finite trial values shrink the step to underflow.
pub(crate) fn integrate<const N: usize, F, O>(
    mut f: F,
    t0: f64,
    y0: SVector<f64, N>,
    t_end: f64,
    cfg: &Config<'_, N>,
    mut on_step: O,
) -> Result<Counters, RouthError>
where
    F: Rhs<N>,
    O: FnMut(&Accepted<'_, N>) -> Result<(), RouthError>,
{
    let mut counters = Counters::default();
    let mut t = t0;
    let mut y = y0;
    let mut k = [SVector::<f64, N>::zeros(); 16];
    k[0] = eval_cold(&mut f, t, &y)?;
    counters.evaluations += 1;
    if !all_finite(&k[0]) {
        return Err(RouthError::NonFiniteState { t });
    }
    if t_end <= t0 {
        return Ok(counters);
    }
    let mut h = match cfg.h_init {
        Some(h) => h.min(cfg.h_max),
        None => initial_step(&mut f, t, &y, &k[0], cfg, &mut counters)?,
    };
    let mut reject = false;
    let mut nonfinite = false;
    let mut attempts = 0usize;
    loop {
        if attempts >= cfg.max_steps {
            return Err(RouthError::TooManySteps { t, steps: attempts });
        }
        if let Some(c) = cfg.control {
            c.check()?;
        }
        if !(h.is_normal() && 0.1 * h > t.abs() * f64::EPSILON) {
            return Err(if nonfinite {
                RouthError::NonFiniteState { t }
            } else {
                RouthError::StepSizeUnderflow { t, h }
            });
        }
        let last = t + 1.01 * h >= t_end;
        if last {
            h = t_end - t;
        }
        attempts += 1;

        let trial = trial_step(&mut f, t, &y, h, &mut k, cfg.weights)?;
        counters.evaluations += 11;
        if !(trial.err.is_finite() && all_finite(&trial.y_new)) {
            nonfinite = true;
            reject = true;
            counters.rejected += 1;
            h *= NONFINITE_SHRINK;
            continue;
        }
        let err = trial.err;
        let fac11 = err.sqrt().sqrt().sqrt();
        let fac = (fac11 / SAFE).clamp(1.0 / FAC2, 1.0 / FAC1);
        let mut h_new = h / fac;

        if err <= 1.0 {
            // Stage 13: f at the new point, reused as stage 1 of the next step (FSAL).
            let t_new = if last { t_end } else { t + h };
            let k13 = f.eval(t_new, &trial.y_new)?;
            counters.evaluations += 1;
            if !all_finite(&k13) {
                nonfinite = true;
                reject = true;
                counters.rejected += 1;
                h *= NONFINITE_SHRINK;
                continue;
            }
            nonfinite = false;
            k[12] = k13;
            let dense = if cfg.dense {
                Some(dense_step(
                    &mut f,
                    t,
                    &y,
                    &trial.y_new,
                    h,
                    &mut k,
                    &mut counters,
                )?)
            } else {
                None
            };
            t = t_new;
            y = trial.y_new;
            k[0] = k13;
            counters.accepted += 1;
            on_step(&Accepted {
                t,
                y: &y,
                dense: dense.as_ref(),
            })?;
            if last {
                return Ok(counters);
            }
            h_new = h_new.min(cfg.h_max);
            if reject {
                h_new = h_new.min(h);
            }
            reject = false;
        } else {
            h_new = h / (1.0 / FAC1).min(fac11 / SAFE);
            reject = true;
            counters.rejected += 1;
        }
        h = h_new;
    }
}

/// Stages 14–16 and the coefficients of the continuous extension (Hairer's `dop853.f`).
fn dense_step<const N: usize, F>(
    f: &mut F,
    t: f64,
    y: &SVector<f64, N>,
    y_new: &SVector<f64, N>,
    h: f64,
    k: &mut [SVector<f64, N>; 16],
    counters: &mut Counters,
) -> Result<DenseStep<N>, RouthError>
where
    F: Rhs<N>,
{
    for i in 13..16 {
        let yi = stage_input_at(i, y, k, h);
        k[i] = f.eval(t + C[i] * h, &yi)?;
    }
    counters.evaluations += 3;
    let ydiff = y_new - y;
    let bspl = k[0] * h - ydiff;
    let mut cont = [SVector::<f64, N>::zeros(); 8];
    cont[0] = *y;
    cont[1] = ydiff;
    cont[2] = bspl;
    cont[3] = ydiff - k[12] * h - bspl;
    for (r, drow) in D.iter().enumerate() {
        let mut s = SVector::<f64, N>::zeros();
        for (j, d) in drow.iter().enumerate() {
            if *d != 0.0 {
                s += k[j] * *d;
            }
        }
        cont[4 + r] = s * h;
    }
    Ok(DenseStep { t_old: t, h, cont })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cfg<const N: usize>(weights: Weights<'_, N>, dense: bool) -> Config<'_, N> {
        Config {
            weights,
            h_max: f64::INFINITY,
            h_init: None,
            max_steps: 100_000,
            dense,
            control: None,
        }
    }

    /// Row sums of A equal the nodes, and the weights satisfy the first order conditions.
    #[test]
    fn tableau_consistency() {
        for i in 1..16 {
            if i == 12 {
                continue; // stage 13 is f(t + h, y_new), not built from A
            }
            let s: f64 = A[i].iter().sum();
            assert!((s - C[i]).abs() < 1e-14, "row {i}: {s} vs {}", C[i]);
        }
        // Σb = 1, Σb c = 1/2, ..., Σ b c^{q−1} = 1/q for q ≤ 8 (quadrature order 8).
        for q in 1..=8 {
            let s: f64 = B.iter().zip(C.iter()).map(|(b, c)| b * c.powi(q - 1)).sum();
            assert!((s - 1.0 / q as f64).abs() < 1e-13, "q = {q}: {s}");
        }
        // The 5th-order error estimator integrates constants to zero, the 3rd-order one uses
        // weights summing to one.
        assert!(ER.iter().sum::<f64>().abs() < 1e-14);
        assert!((BHH.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }

    /// Global error on y' = λy scales with the tolerance, and the dense output is accurate.
    #[test]
    fn tolerance_proportionality_and_dense_output() {
        // Harmonic oscillator, exact (cos t, −sin t).
        let f = |_t: f64, y: &SVector<f64, 2>| -> Result<SVector<f64, 2>, RouthError> {
            Ok(SVector::<f64, 2>::new(y[1], -y[0]))
        };
        let mut errors = vec![];
        for &tol in &[1e-6, 1e-8, 1e-10, 1e-12] {
            let mut max_err: f64 = 0.0;
            let mut max_dense: f64 = 0.0;
            let mut t_old = 0.0;
            let c = integrate(
                f,
                0.0,
                SVector::<f64, 2>::new(1.0, 0.0),
                20.0,
                &cfg(&componentwise(tol, tol), true),
                |acc| {
                    let exact = SVector::<f64, 2>::new(acc.t.cos(), -acc.t.sin());
                    max_err = max_err.max((acc.y - exact).amax());
                    if let Some(d) = acc.dense {
                        for s in [0.13, 0.5, 0.87] {
                            let tm = t_old + s * (acc.t - t_old);
                            let ex = SVector::<f64, 2>::new(tm.cos(), -tm.sin());
                            max_dense = max_dense.max((d.eval(tm) - ex).amax());
                        }
                        assert!((d.eval(acc.t) - acc.y).amax() < 1e-14);
                        assert!((d.eval(t_old) - d.cont[0]).amax() < 1e-14);
                    }
                    t_old = acc.t;
                    Ok(())
                },
            )
            .unwrap();
            assert!(c.accepted > 0);
            assert!(max_err < 1e3 * tol, "tol {tol:e}: error {max_err:e}");
            assert!(
                max_dense < 1e3 * tol,
                "tol {tol:e}: dense error {max_dense:e}"
            );
            errors.push(max_err);
        }
        // Tighter tolerance, smaller error (by ≥ 30 per factor 100).
        for w in errors.windows(2) {
            assert!(w[1] < w[0] / 30.0, "{errors:?}");
        }
    }

    #[test]
    fn ends_exactly_at_t_end_and_counts() {
        let f = |t: f64, y: &SVector<f64, 1>| -> Result<SVector<f64, 1>, RouthError> {
            Ok(SVector::<f64, 1>::new(-y[0] + t.sin()))
        };
        let mut last_t = 0.0;
        let mut n = 0;
        let c = integrate(
            f,
            0.0,
            SVector::<f64, 1>::new(1.0),
            3.7,
            &cfg(&componentwise(1e-9, 1e-9), false),
            |a| {
                assert!(a.t > last_t);
                last_t = a.t;
                n += 1;
                Ok(())
            },
        )
        .unwrap();
        assert_eq!(last_t, 3.7);
        assert_eq!(n, c.accepted);
        // Exact: y = (3/2)e^{−t} + (sin t − cos t)/2.
        let mut y_end = 0.0;
        integrate(
            f,
            0.0,
            SVector::<f64, 1>::new(1.0),
            3.7,
            &cfg(&componentwise(1e-11, 1e-11), false),
            |a| {
                y_end = a.y[0];
                Ok(())
            },
        )
        .unwrap();
        let t: f64 = 3.7;
        let exact = 1.5 * (-t).exp() + (t.sin() - t.cos()) / 2.0;
        assert!((y_end - exact).abs() < 1e-10, "{y_end} vs {exact}");
    }

    #[test]
    fn errors_are_values() {
        // Blow-up y' = y²: y = 1/(1 − t), singular at t = 1.
        let f = |_t: f64, y: &SVector<f64, 1>| -> Result<SVector<f64, 1>, RouthError> {
            Ok(SVector::<f64, 1>::new(y[0] * y[0]))
        };
        let r = integrate(
            f,
            0.0,
            SVector::<f64, 1>::new(1.0),
            2.0,
            &cfg(&componentwise(1e-8, 1e-8), false),
            |_| Ok(()),
        );
        assert!(
            matches!(
                r,
                Err(RouthError::StepSizeUnderflow { .. })
                    | Err(RouthError::TooManySteps { .. })
                    | Err(RouthError::NonFiniteState { .. })
            ),
            "{r:?}"
        );
        let w = componentwise(1e-8, 1e-8);
        let mut small = cfg(&w, false);
        small.max_steps = 3;
        let g = |_t: f64, y: &SVector<f64, 1>| -> Result<SVector<f64, 1>, RouthError> {
            Ok(SVector::<f64, 1>::new(-y[0]))
        };
        let r = integrate(g, 0.0, SVector::<f64, 1>::new(1.0), 100.0, &small, |_| {
            Ok(())
        });
        assert!(
            matches!(r, Err(RouthError::TooManySteps { steps: 3, .. })),
            "{r:?}"
        );
        // Errors from the right-hand side propagate.
        let bad = |t: f64, y: &SVector<f64, 1>| -> Result<SVector<f64, 1>, RouthError> {
            if t > 0.5 {
                Err(RouthError::NonFiniteState { t: -1.0 })
            } else {
                Ok(*y)
            }
        };
        let r = integrate(
            bad,
            0.0,
            SVector::<f64, 1>::new(1.0),
            1.0,
            &cfg(&componentwise(1e-8, 1e-8), false),
            |_| Ok(()),
        );
        assert_eq!(r, Err(RouthError::NonFiniteState { t: -1.0 }));
        // NaN at the start.
        let nan = |_t: f64, _y: &SVector<f64, 1>| -> Result<SVector<f64, 1>, RouthError> {
            Ok(SVector::<f64, 1>::new(f64::NAN))
        };
        let r = integrate(
            nan,
            0.0,
            SVector::<f64, 1>::new(1.0),
            1.0,
            &cfg(&componentwise(1e-8, 1e-8), false),
            |_| Ok(()),
        );
        assert_eq!(r, Err(RouthError::NonFiniteState { t: 0.0 }));
    }
}
