//! The harness of the runtime property test: each call under `catch_unwind` and the clock, its
//! `Err` or `Ok` value checked (the properties), the statistics and the failures kept.

use std::collections::BTreeMap;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use routh_core::stability::StabilityReport;
use routh_core::steady::SteadyMotion;
use routh_core::{BifurcationDiagram, RouthError, Vector3};

use super::{env_u64, CALL_BUDGET};

/// The names of the inputs that a `RouthError::NonFinite` may carry: the arguments and options
/// of the public functions, as spelled in their signatures.
const INPUT_NAMES: &[&str] = &[
    "omega0",
    "gamma0",
    "big_omega0",
    "t_end",
    "rtol",
    "atol",
    "rate_atol",
    "step",
    "h_max",
    "h_init",
    "output time",
    "p_psi",
    "gamma",
    "gamma_guess",
    "steady.p_psi",
    "steady.gamma",
    "range",
    "s0",
    "p_psi returned by the family",
];

/// What is wrong with an error value, if anything.
pub(crate) fn error_defect(e: &RouthError) -> Option<String> {
    if e.to_string().trim().is_empty() {
        return Some("empty Display".into());
    }
    match e {
        RouthError::NonFinite { what, value } => {
            if !INPUT_NAMES.contains(what) {
                return Some(format!("NonFinite names an unknown input {what:?}"));
            }
            if value.is_finite() {
                return Some(format!("NonFinite carries a finite value {value:e}"));
            }
        }
        RouthError::InvalidOption { what, reason }
            if what.trim().is_empty() || reason.trim().is_empty() =>
        {
            return Some("InvalidOption without a name or a reason".into());
        }
        RouthError::NonFiniteModel { what, .. }
        | RouthError::NoConvergence { what, .. }
        | RouthError::InvalidModel { what, .. }
            if what.trim().is_empty() =>
        {
            return Some("empty `what`".into());
        }
        RouthError::AtParameter { source, .. } => return error_defect(source),
        _ => {}
    }
    None
}

pub(crate) fn finite(x: &[f64]) -> bool {
    x.iter().all(|v| v.is_finite())
}

pub(crate) fn vecs_finite(v: &[Vector3<f64>]) -> bool {
    v.iter().all(|x| finite(x.as_slice()))
}

pub(crate) fn steady_defect(s: &SteadyMotion) -> Option<String> {
    if !finite(s.gamma.as_slice()) || (s.gamma.norm() - 1.0).abs() > 1e-8 {
        return Some(format!("steady motion with a non-unit γ {:?}", s.gamma));
    }
    if !finite(&[s.p_psi, s.psi_dot, s.mu, s.amended_potential, s.energy]) {
        return Some(format!("non-finite steady motion {s:?}"));
    }
    None
}

pub(crate) fn report_defect(r: &StabilityReport) -> Option<String> {
    let roots_finite = r
        .f2_roots
        .iter()
        .all(|z| z.re.is_finite() && z.im.is_finite());
    if !finite(&r.restricted_hessian_eigenvalues) || !roots_finite {
        return Some(format!("non-finite stability report {r:?}"));
    }
    if r.degree_of_instability > 2 {
        return Some(format!("degree of instability {}", r.degree_of_instability));
    }
    None
}

pub(crate) fn diagram_defect(d: &BifurcationDiagram) -> Option<String> {
    for b in &d.branches {
        for p in &b.points {
            if !p.s.is_finite() {
                return Some(format!("branch point at s = {}", p.s));
            }
            if let Some(e) = steady_defect(&p.steady).or_else(|| report_defect(&p.report)) {
                return Some(e);
            }
        }
    }
    for e in &d.events {
        if !e.s.is_finite() || !finite(e.gamma.as_slice()) || e.branch >= d.branches.len() {
            return Some(format!("bad event {e:?}"));
        }
    }
    None
}

/// The calls of one function: how many, how many `Ok`, the slowest and its case.
#[derive(Default)]
pub(crate) struct Stats {
    pub(crate) calls: u64,
    pub(crate) ok: u64,
    pub(crate) slowest: Duration,
    pub(crate) slowest_case: u64,
}

/// What the watchdog sees: the function running and since when.
#[derive(Default)]
pub(crate) struct Current {
    pub(crate) function: &'static str,
    pub(crate) case: u64,
    pub(crate) since: Option<Instant>,
}

/// The state of one run: the case being run, the statistics per function and the failures.
pub struct Harness {
    pub(crate) seed: u64,
    pub(crate) case: u64,
    pub(crate) stats: BTreeMap<&'static str, Stats>,
    pub(crate) failures: Vec<String>,
    pub(crate) failure_count: u64,
    pub(crate) current: Arc<Mutex<Current>>,
    /// Print every input and error (when replaying one case).
    pub(crate) verbose: bool,
}

impl Harness {
    /// Runs `call` under `catch_unwind` and the clock, and checks its result with `defect`
    /// (what is wrong with an `Ok` value). `inputs` describes the inputs, only on failure.
    pub(crate) fn check<T>(
        &mut self,
        function: &'static str,
        inputs: impl FnOnce() -> String,
        call: impl FnOnce() -> Result<T, RouthError>,
        defect: impl FnOnce(&T) -> Option<String>,
    ) {
        {
            let mut c = self.current.lock().unwrap();
            *c = Current {
                function,
                case: self.case,
                since: Some(Instant::now()),
            };
        }
        let verbose = self.verbose;
        let mut inputs = Some(inputs);
        let mut text = None;
        if verbose {
            let t = (inputs.take().unwrap())();
            println!("{function} (case {}): {t}", self.case);
            text = Some(t);
        }
        let start = Instant::now();
        let cpu_start = cpu_time::ThreadTime::try_now().ok();
        let outcome = catch_unwind(AssertUnwindSafe(call));
        let elapsed = start.elapsed();
        // The budget is checked on the CPU time of this thread, which other work on the machine
        // does not stretch (wall time does: under a loaded CI the same call took over 2 s); the
        // wall-clock watchdog still catches a hang. Where thread CPU time is not available,
        // wall time is used.
        let cpu = cpu_start.map_or(elapsed, |t| t.elapsed());
        self.current.lock().unwrap().since = None;

        let stats = self.stats.entry(function).or_default();
        stats.calls += 1;
        if elapsed >= stats.slowest {
            stats.slowest = elapsed;
            stats.slowest_case = self.case;
        }
        let problem = match outcome {
            Err(payload) => {
                let msg = payload
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| payload.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                Some(format!("PANIC: {msg}"))
            }
            Ok(Ok(value)) => {
                stats.ok += 1;
                defect(&value).map(|d| format!("non-finite or invalid Ok: {d}"))
            }
            Ok(Err(e)) => {
                if verbose {
                    println!("  -> Err({e:?})");
                }
                error_defect(&e).map(|d| format!("bad error {e:?}: {d}"))
            }
        };
        let problem = problem.or_else(|| {
            let budget =
                env_u64("ROUTH_PROPTEST_CALL_BUDGET_MS").map_or(CALL_BUDGET, Duration::from_millis);
            (cpu > budget).then(|| format!("took {cpu:?} of CPU time (> {budget:?})"))
        });
        if let Some(p) = problem {
            self.failure_count += 1;
            if self.failures.len() < 20 {
                self.failures.push(format!(
                    "{function} (seed = {}, case = {}): {p}\n    inputs: {}",
                    self.seed,
                    self.case,
                    text.unwrap_or_else(|| (inputs.take().unwrap())())
                ));
            }
        }
    }
}

/// What is wrong with a trajectory, if anything.
pub(crate) fn trajectory_defect(tr: &routh_core::Trajectory) -> Option<String> {
    let ok = finite(&tr.t) && vecs_finite(&tr.omega) && finite(&tr.energy) && finite(&tr.p_psi);
    (!ok).then(|| format!("trajectory {tr:?}"))
}
