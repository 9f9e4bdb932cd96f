//! The runtime property test of routh-core, shared by two test targets: every public runtime
//! function is called on random models and random inputs, extreme values mixed in, and must
//!
//! - never panic (each call runs under `catch_unwind`),
//! - never hang (a watchdog aborts the run if one call takes longer than [`WATCHDOG`], and the
//!   test fails if one call uses more than [`CALL_BUDGET`] of CPU time on its thread: a hang
//!   detector, not a timing assertion on speed, and one the machine's load does not trip),
//! - on `Err`, name the input or computation that failed (non-empty `Display`; for
//!   `RouthError::NonFinite` a known input name and a non-finite value; for
//!   `RouthError::InvalidOption` a non-empty name),
//! - on `Ok`, return finite values (trajectories, steady motions with a unit γ, stability
//!   reports with finite eigenvalues and roots, diagrams).
//!
//! Models: the closed-form [`HeavyTop`](crate::HeavyTop) (fast, most calls), the num-dual
//! [`Gyrostat`] and the same gyrostat declared with `#[derive(Lagrangian)]`
//! (generated code; the only kind the certified search accepts), with parameters log-uniform over
//! `1e−6…1e6` with random signs, now and then an indefinite, singular, non-symmetric or
//! non-finite inertia. Every scalar input (γ, Ω, p_ψ, t_end, options) is replaced with
//! probability 10 % by one of NaN, ±∞, ±0, a subnormal, ±1e300.
//!
//! Two parts ([`Part`]): each case draws its model first; the cases on the hand-written models
//! (and the regression cases) run in routh-core's `tests/runtime_properties.rs`, the cases on the
//! derived gyrostat in the facade's `tests/runtime_properties.rs` (the derive needs the facade,
//! which routh-core's tests must not depend on). Both draw the same cases from the same seed, so
//! together they run every case once.
//!
//! Reproducing: the run is seeded (default [`DEFAULT_SEED`]; `ROUTH_PROPTEST_SEED=<u64>`
//! overrides it) and every case has its own generator derived from `(seed, case)`, so a failure
//! report `seed = S, case = C` is replayed alone with
//! `ROUTH_PROPTEST_SEED=S ROUTH_PROPTEST_CASE=C cargo test -p routh-core --test
//! runtime_properties -- --nocapture` (or `-p routh` for the derived part).
//! `ROUTH_PROPTEST_CASES=<n>` changes the number of cases, `ROUTH_PROPTEST_CALL_BUDGET_MS=<ms>`
//! the time allowed to one call (default 2000).

mod cases;
mod harness;
mod inputs;
mod regression;

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

pub use cases::{run_case, Model};
pub use harness::Harness;

use cases::run_one;
use harness::Current;
use regression::regression_cases;

use crate::Gyrostat;

/// The default seed (deterministic CI runs; override with `ROUTH_PROPTEST_SEED`).
pub const DEFAULT_SEED: u64 = 0x5EED_2024_0013_0005;
/// Default number of cases (each case is one call of one public function on one random input),
/// shared between the two parts. It was 110 000 when one test ran both; 125 000 keeps at least
/// [`MIN_INPUTS_HAND`] in the hand-written part (about 11 % of the cases draw the derived
/// gyrostat).
pub const DEFAULT_CASES: u64 = 125_000;
/// The minimum number of inputs the hand-written part must exercise.
pub const MIN_INPUTS_HAND: u64 = 100_000;
/// The minimum number of inputs the derived part must exercise.
pub const MIN_INPUTS_DERIVED: u64 = 10_000;
/// A single call using more CPU time than this (on its own thread) fails the test (test profile,
/// opt-level 1): a hang detector that the load of the machine does not trip.
pub const CALL_BUDGET: Duration = Duration::from_secs(2);
/// A single call slower than this is a hang: the watchdog reports it and ends the process.
pub const WATCHDOG: Duration = Duration::from_secs(30);

/// Runs one case on the derived gyrostat built from its num-dual twin `twin`: calls
/// [`run_case`] with the derived model, the harness, the case's generator and the function drawn.
pub type DerivedCase<'a> = &'a dyn Fn(&mut Harness, &mut ChaCha8Rng, &Gyrostat, u32);

/// Which cases a run executes, by the model each case draws.
pub enum Part<'a> {
    /// The cases on the hand-written models ([`HeavyTop`](crate::HeavyTop),
    /// [`Gyrostat`]) and the regression cases: routh-core's test.
    Hand,
    /// The cases on the derived gyrostat: the facade's test, which supplies the derived model.
    Derived(DerivedCase<'a>),
}

impl Part<'_> {
    fn name(&self) -> &'static str {
        match self {
            Part::Hand => "hand-written models",
            Part::Derived(_) => "derived gyrostat",
        }
    }

    fn other_command(&self) -> &'static str {
        match self {
            Part::Hand => "`cargo test -p routh --test main runtime_properties::`",
            Part::Derived(_) => "`cargo test -p routh-core --test main runtime_properties::`",
        }
    }

    fn min_inputs(&self) -> u64 {
        match self {
            Part::Hand => MIN_INPUTS_HAND,
            Part::Derived(_) => MIN_INPUTS_DERIVED,
        }
    }
}

/// The generator of one case: independent of every other case.
fn case_rng(seed: u64, case: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(case);
    rng
}

fn env_u64(name: &str) -> Option<u64> {
    let v = std::env::var(name).ok()?;
    let v = v.trim();
    let parsed = match v.strip_prefix("0x") {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => v.parse(),
    };
    Some(parsed.unwrap_or_else(|_| panic!("{name} = {v:?} is not a u64")))
}

/// Runs the property test's cases of `part` (all of them, or the one named by
/// `ROUTH_PROPTEST_CASE`), prints the statistics per function and panics on any failure.
pub fn run(part: Part<'_>) {
    let seed = env_u64("ROUTH_PROPTEST_SEED").unwrap_or(DEFAULT_SEED);
    let only = env_u64("ROUTH_PROPTEST_CASE");
    let cases = env_u64("ROUTH_PROPTEST_CASES").unwrap_or(DEFAULT_CASES);
    println!(
        "runtime_properties ({}): seed = {seed} (ROUTH_PROPTEST_SEED to override)",
        part.name()
    );

    // Silence the default panic message of caught panics (they are reported below), but keep it
    // when replaying one case.
    let quiet = Arc::new(AtomicBool::new(only.is_none()));
    let default_hook = std::panic::take_hook();
    {
        let quiet = quiet.clone();
        std::panic::set_hook(Box::new(move |info| {
            if !quiet.load(Ordering::Relaxed) {
                default_hook(info);
            }
        }));
    }

    // The watchdog: a call that runs for longer than WATCHDOG is a hang; report it and stop.
    let current = Arc::new(Mutex::new(Current::default()));
    let done = Arc::new(AtomicU64::new(0));
    let watchdog = {
        let (current, done) = (current.clone(), done.clone());
        std::thread::spawn(move || {
            while done.load(Ordering::Relaxed) == 0 {
                std::thread::sleep(Duration::from_millis(100));
                let c = current.lock().unwrap();
                if let Some(since) = c.since {
                    if since.elapsed() > WATCHDOG {
                        eprintln!(
                            "HANG: {} has run for more than {WATCHDOG:?} (seed = {seed}, case = \
                             {}; replay with ROUTH_PROPTEST_SEED={seed} ROUTH_PROPTEST_CASE={})",
                            c.function, c.case, c.case
                        );
                        std::process::exit(101);
                    }
                }
            }
        })
    };

    let mut h = Harness {
        seed,
        case: 0,
        stats: BTreeMap::new(),
        failures: Vec::new(),
        failure_count: 0,
        current,
        verbose: only.is_some(),
    };
    let start = Instant::now();
    let mut other = 0u64;
    match only {
        Some(case) => {
            if !run_one(&mut h, &part, seed, case) {
                println!(
                    "case {case} draws a model of the other part: replay it with {}",
                    part.other_command()
                );
            }
        }
        None => {
            for case in 0..cases {
                if !run_one(&mut h, &part, seed, case) {
                    other += 1;
                }
            }
            if matches!(part, Part::Hand) {
                regression_cases(&mut h);
            }
        }
    }
    let elapsed = start.elapsed();
    done.store(1, Ordering::Relaxed);
    watchdog.join().unwrap();
    quiet.store(false, Ordering::Relaxed);

    let total: u64 = h.stats.values().map(|s| s.calls).sum();
    println!(
        "runtime_properties ({}): {total} inputs in {elapsed:.2?}; {other} cases left to the \
         other part",
        part.name()
    );
    println!(
        "  {:<32} {:>8} {:>8} {:>12} (case)",
        "function", "calls", "Ok", "slowest"
    );
    for (f, s) in &h.stats {
        println!(
            "  {f:<32} {:>8} {:>8} {:>12.2?} ({})",
            s.calls, s.ok, s.slowest, s.slowest_case
        );
    }
    if !h.failures.is_empty() {
        panic!(
            "{} failures (seed = {seed}; replay one with ROUTH_PROPTEST_SEED={seed} \
             ROUTH_PROPTEST_CASE=<case>), the first ones:\n{}",
            h.failure_count,
            h.failures.join("\n")
        );
    }
    let min_inputs = part.min_inputs();
    if only.is_none() && cases >= DEFAULT_CASES {
        assert!(
            total >= min_inputs,
            "only {total} inputs exercised (at least {min_inputs} required)"
        );
    }
}
