//! The chart of a mode's Lyapunov family over a body parameter `x` and the energy `h` above the
//! steady motion (docs/method.md §12.4): for each `x` of a grid the family is followed with its
//! linear and nonlinear events located to `event_tol` in the energy; from those events the
//! chart's curves are continued in `(x, h)` (`curves.rs`).

use nalgebra::Vector3;

use super::{lyapunov_family, OrbitEventKind, OrbitFamily, OrbitOptions, OrbitStop};
use crate::{steady_motion_near, RouthError, Routhian, SteadyMotion};

mod curves;

/// Settings of [`orbit_chart`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitChartOptions {
    /// The options of each family (its `nonlinear` is set by the chart; its energy bounds are
    /// the chart's energies above each steady motion; its `control` cancels the chart).
    pub orbit: OrbitOptions,
    /// The number of values of `x`, both ends included (at least 2).
    pub nx: usize,
    /// The widest window, as a fraction of the chart's range of `h`, about the predicted `h` in
    /// which a curve's next point is searched (docs/method.md §12.4). Default `0.05`.
    pub join_tol: f64,
}

impl Default for OrbitChartOptions {
    fn default() -> Self {
        OrbitChartOptions {
            orbit: OrbitOptions {
                max_orbits: 200,
                ..OrbitOptions::default()
            },
            nx: 41,
            join_tol: 0.05,
        }
    }
}

/// A curve of the chart: where the family's orbits meet one kind of event, as `(x, h)` points
/// in their order along the curve (a curve may turn back in `x`), each an event located on the
/// family at its `x` (continued in `(x, h)` from the events of the grid's families,
/// docs/method.md §12.4).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitChartCurve {
    /// The event: `Fold`, `BranchPoint` (`k = 1`), `PeriodDoubling` (`k = −1`),
    /// `ThirdOrderResonance` (`k = −1/2`), `FourthOrderResonance` (`k = 0`), `TwistDegenerate`.
    pub kind: OrbitEventKind,
    /// `(x, h)`, `h = E − E_s(x)`.
    pub points: Vec<[f64; 2]>,
}

/// The chart of [`orbit_chart`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct OrbitChart {
    /// The values of the parameter.
    pub x: Vec<f64>,
    /// The energy `E_s(x)` of the steady motion (NaN where none was found).
    pub steady_energy: Vec<f64>,
    /// The family at each `x` (`None` where the steady motion or the family failed; the reason
    /// in [`OrbitChart::failures`]).
    pub families: Vec<Option<OrbitFamily>>,
    /// Why the steady motion or the family at each `x` failed (`None` where it did not).
    pub failures: Vec<Option<String>>,
    /// The curves where the orbits change linear stability (`k = ±1`, folds), meet the
    /// resonances of order three and four, and lose their twist.
    pub curves: Vec<OrbitChartCurve>,
    /// Why the chart ended early (`Interrupted`), `None` when every `x` was done.
    pub stop: Option<OrbitStop>,
}

impl OrbitChart {
    /// The families' orbits as `(x, h, k)` rows, for figures of the regions by stability.
    pub fn samples(&self) -> Vec<[f64; 3]> {
        let mut out = Vec::new();
        for ((x, es), fam) in self.x.iter().zip(&self.steady_energy).zip(&self.families) {
            for o in fam.iter().flat_map(|f| &f.orbits) {
                out.push([*x, o.energy - es, o.stability_index]);
            }
        }
        out
    }
}

/// The chart of the Lyapunov family of `mode` over the parameter `x ∈ x_range` and the energy
/// `h = E − E_s(x) ∈ excess_energy` above the steady motion (docs/method.md §12): `family(x)`
/// gives the model at `x` and its `p_ψ`; the steady motion is found near `gamma_guess` at the
/// first `x` and followed from one `x` to the next. Each family is traced with
/// [`OrbitOptions::nonlinear`] set, its events located in the energy to `event_tol`; from each
/// event not yet on a curve, the curve of its kind is continued in `(x, h)` both ways (a secant
/// predictor in `h`, the step in `x` adapted to the prediction's error and landing on every `x`
/// of the grid, each point an event located on the family at its `x`): [`OrbitChartCurve`]s
/// exact at every point, with points between the grid's where they bend. A curve ends where it
/// leaves the chart or turns back in `x`.
///
/// The steady motions are found one `x` after the other, the families traced in parallel
/// (rayon; the models must be `Send`), then the curves. A failure at one `x` (no steady motion, an unstable one,
/// a family that does not start) is recorded in [`OrbitChart::failures`], not an error. Cancelled
/// through `opts.orbit.control`, the chart keeps the families it has, `stop` `Interrupted`. Errors: invalid options or ranges; the
/// model's own errors are per `x`.
pub fn orbit_chart<M: Routhian + Send, F: Fn(f64) -> (M, f64)>(
    family: F,
    gamma_guess: Vector3<f64>,
    mode: usize,
    x_range: (f64, f64),
    excess_energy: (f64, f64),
    opts: &OrbitChartOptions,
) -> Result<OrbitChart, RouthError> {
    use rayon::prelude::*;
    check(x_range, excess_energy, mode, opts)?;
    let nx = opts.nx;
    let xs: Vec<f64> = (0..nx)
        .map(|i| x_range.0 + (x_range.1 - x_range.0) * i as f64 / (nx - 1) as f64)
        .collect();
    let control = &opts.orbit.control;
    // The steady motions, one x after the other (each from the last one's γ): cheap.
    let mut guess = gamma_guess;
    let mut starts: Vec<Result<(M, SteadyMotion), RouthError>> = Vec::with_capacity(nx);
    for &x in &xs {
        if control.is_cancelled() {
            break;
        }
        let (model, p_psi) = family(x);
        let s = steady_motion_near(&model, guess, p_psi);
        if let Ok(s) = &s {
            guess = s.gamma;
        }
        starts.push(s.map(|s| (model, s)));
    }
    // The families, in parallel (rayon): the bulk of the work.
    let done = std::sync::atomic::AtomicUsize::new(0);
    let traced: Vec<Result<Traced, RouthError>> = starts
        .into_par_iter()
        .map(|start| {
            let (model, s) = start?;
            let gamma = s.gamma;
            let o = OrbitOptions {
                nonlinear: true,
                energy_bounds: Some((s.energy + excess_energy.0, s.energy + excess_energy.1)),
                control: control.cancel_only(),
                ..opts.orbit.clone()
            };
            let fam = lyapunov_family(&model, &s, mode, &o);
            let n = done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            control.report(n, nx);
            Ok((s.energy, gamma, fam?))
        })
        .collect();
    let mut chart = OrbitChart {
        x: Vec::with_capacity(nx),
        steady_energy: Vec::with_capacity(nx),
        families: Vec::with_capacity(nx),
        failures: Vec::with_capacity(nx),
        curves: Vec::new(),
        stop: None,
    };
    let mut gammas = Vec::with_capacity(nx);
    for (x, t) in xs.iter().zip(traced) {
        chart.x.push(*x);
        gammas.push(t.as_ref().map_or(Vector3::zeros(), |t| t.1));
        match t {
            Ok((es, _, fam)) => {
                if fam.stop == Some(OrbitStop::Interrupted) {
                    chart.stop = Some(OrbitStop::Interrupted);
                }
                chart.steady_energy.push(es);
                chart.families.push(Some(fam));
                chart.failures.push(None);
            }
            Err(e) => {
                if matches!(e, RouthError::Interrupted) {
                    chart.stop = Some(OrbitStop::Interrupted);
                }
                chart.steady_energy.push(f64::NAN);
                chart.families.push(None);
                chart.failures.push(Some(e.to_string()));
            }
        }
    }
    if control.is_cancelled() {
        chart.stop = Some(OrbitStop::Interrupted);
    }
    if chart.stop.is_none() {
        let tracing = curves::Tracing {
            family: &family,
            xs: &xs,
            h_range: excess_energy,
            join_tol: opts.join_tol,
            opts: &opts.orbit,
        };
        match trace_curves(&chart, &gammas, &tracing) {
            Ok(c) => chart.curves = c,
            Err(RouthError::Interrupted) => chart.stop = Some(OrbitStop::Interrupted),
            Err(e) => return Err(e),
        }
    }
    Ok(chart)
}

fn check(
    x_range: (f64, f64),
    h: (f64, f64),
    mode: usize,
    opts: &OrbitChartOptions,
) -> Result<(), RouthError> {
    let bad = |what: &'static str, reason: String| Err(RouthError::InvalidOption { what, reason });
    if !(x_range.0.is_finite() && x_range.1.is_finite() && x_range.0 < x_range.1) {
        return bad("x_range", format!("need finite lo < hi, got {x_range:?}"));
    }
    if !(h.0.is_finite() && h.1.is_finite() && 0.0 <= h.0 && h.0 < h.1) {
        return bad(
            "excess_energy",
            format!("need finite 0 ≤ lo < hi (energies above the steady motion), got {h:?}"),
        );
    }
    if mode > 1 {
        return bad("mode", format!("0 (ω₁) or 1 (ω₂), got {mode}"));
    }
    if !(2..=10_000).contains(&opts.nx) {
        return bad("nx", format!("need 2 ≤ nx ≤ 10000, got {}", opts.nx));
    }
    if !(opts.join_tol > 0.0 && opts.join_tol.is_finite()) {
        return bad(
            "join_tol",
            format!("must be positive, got {}", opts.join_tol),
        );
    }
    Ok(())
}

/// A family of the chart with its steady motion's energy and `γ`.
type Traced = (f64, Vector3<f64>, OrbitFamily);

/// The kinds of the chart's curves, in the order they are listed.
const KINDS: [OrbitEventKind; 6] = [
    OrbitEventKind::Fold,
    OrbitEventKind::BranchPoint,
    OrbitEventKind::PeriodDoubling,
    OrbitEventKind::ThirdOrderResonance,
    OrbitEventKind::FourthOrderResonance,
    OrbitEventKind::TwistDegenerate,
];

/// The curves through the events of the grid's families: for each kind, every event not on a
/// curve already traced starts one.
fn trace_curves<M: Routhian, F: Fn(f64) -> (M, f64)>(
    chart: &OrbitChart,
    gammas: &[Vector3<f64>],
    tracing: &curves::Tracing<'_, F>,
) -> Result<Vec<OrbitChartCurve>, RouthError> {
    let mut out: Vec<OrbitChartCurve> = Vec::new();
    for kind in KINDS {
        for (i, fam) in chart.families.iter().enumerate() {
            let Some(fam) = fam else { continue };
            let (x, es) = (chart.x[i], chart.steady_energy[i]);
            for ev in fam.events.iter().filter(|e| e.kind == kind) {
                let h = ev.energy - es;
                if tracing.covered(&out, kind, x, h) {
                    continue;
                }
                let Some((_, anchor)) = curves::anchor_of(fam, ev) else {
                    continue;
                };
                let seed = curves::Point {
                    x,
                    h,
                    steady_gamma: gammas[i],
                    anchor_h: anchor.energy - es,
                    anchor,
                };
                out.push(tracing.curve(kind, seed)?);
            }
        }
    }
    Ok(out)
}
