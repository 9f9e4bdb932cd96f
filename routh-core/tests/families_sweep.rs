//! A randomised sweep of bifurcation diagrams: symmetric, asymmetric and off-axis
//! heavy tops over random ranges, ranges centred on their closed-form branch points and ranges
//! whose seeds fall exactly on a branch point. Every diagram must succeed with no budget
//! exhausted, and [`BifurcationDiagram::count_at`] must equal the number of steady motions
//!
//! - at random `s` of the range, and
//! - at `s` at distance `k·1e−6·max(1, |s_e|)`, `k ∈ [1.2, 50]`, from every event `s_e`,
//!
//! where the number of steady motions is counted in closed form ([`closed_form_count`]: the
//! critical points of `U_r = p²/(2γᵀJγ) + mgr·γ` on the sphere reduce to the roots of one scalar
//! equation, counted by its monotone pieces). Independently, the global search
//! ([`steady_motion_search`]) must agree with the closed form wherever its Morse self-check says
//! `consistent`; the points where it does not are counted (and printed).
//!
//! `cargo test -p routh-core --test main families_sweep::` runs 150 bodies;
//! `cargo test -p routh-core --test main families_sweep:: -- --ignored --nocapture` runs 1000.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_core::steady::{steady_motion_search, SearchOptions};
use routh_core::{bifurcation_diagram, ContinuationOptions, Matrix3, Vector3};
use test_models::HeavyTop;

mod closed_form {
    //! The number of steady motions of a heavy top at `p_ψ = p`, in closed form.
    //!
    //! With `n = γᵀJγ`, `∂U_r/∂γ = −(p²/n²)Jγ + m` (`m = mgr`), a critical point on the sphere is
    //! `m = (λ + μJ)γ` with `μ = p²/n² > 0`. Write `ν = λ/μ`.
    //!
    //! - Components with `m_i ≠ 0`: `γ_i = m_i/(μ(ν + J_i))`. When every `m_i ≠ 0`, `|γ| = 1`
    //!   gives `μ² = S₀(ν) = Σ m_i²/(ν + J_i)²`, then `n = S₁/S₀` with `S₁ = Σ J_i m_i²/(ν + J_i)²`,
    //!   and `μ = p²/n²` becomes `h(ν) := S₁/S₀^{3/4} = p`: one steady motion per root. `h > 0`
    //!   tends to `+∞` at the poles `ν = −J_i` and to `0` at `ν → ±∞`; between its critical points
    //!   it is monotone, so the roots are counted exactly by the monotone pieces whose range
    //!   contains `p`.
    //! - `m = (0, 0, m₃)` (the centre of mass on the third axis): the poles `γ = ±e₃`, and for each
    //!   `i ∈ {1, 2}` with `ν = −J_i`: `γ₃ = m₃n²/(p²(J₃ − J_i))`, `n = J_i + (J₃ − J_i)γ₃²`, so
    //!   `q(n) = m₃²n⁴/(p⁴(J₃ − J_i)) − (n − J_i) = 0` with `n` strictly between `J_i` and `J₃`
    //!   (`0 < γ₃² < 1`). Each root is two tilted steady motions `γ_i = ±√(1 − γ₃²)` of an
    //!   asymmetric body, or one circle of them when `J₁ = J₂` (counted once, as the search and
    //!   the diagram do).
    use super::Vector3;

    /// Number of steady motions (a circle counts once) of the heavy top `diag(j)`, `m = mgr`,
    /// at `p`; `None` for a configuration this module does not cover (`m` with exactly one zero
    /// component).
    pub fn closed_form_count(j: Vector3<f64>, m: Vector3<f64>, p: f64) -> Option<usize> {
        let p = p.abs();
        if m.iter().all(|v| *v != 0.0) {
            return Some(all_components(j, m, p));
        }
        if m.x != 0.0 || m.y != 0.0 || m.z == 0.0 {
            return None;
        }
        if p == 0.0 {
            return Some(2);
        }
        let m3 = m.z;
        let tilted = |ji: f64| -> usize {
            let (j3, a) = (j.z, m3 * m3 / (p.powi(4) * (j.z - ji)));
            let q = |n: f64| a * n.powi(4) - (n - ji);
            let (lo, hi) = (ji.min(j3), ji.max(j3));
            // q'' = 12an² has one sign on n > 0: at most two roots, split by q's extremum.
            let mut cuts = vec![lo];
            let nstar = (1.0 / (4.0 * a)).cbrt();
            if a > 0.0 && nstar > lo && nstar < hi {
                cuts.push(nstar);
            }
            cuts.push(hi);
            cuts.windows(2)
                .filter(|w| (q(w[0]) > 0.0) != (q(w[1]) > 0.0))
                .count()
        };
        if j.x == j.y {
            Some(2 + tilted(j.x))
        } else {
            Some(2 + 2 * tilted(j.x) + 2 * tilted(j.y))
        }
    }

    /// `log h(ν)` and its derivative in `ν`, `S₀, S₁` as above.
    fn log_h(j: &Vector3<f64>, m: &Vector3<f64>, nu: f64) -> (f64, f64) {
        let (mut s0, mut s1, mut d0, mut d1) = (0.0, 0.0, 0.0, 0.0);
        for i in 0..3 {
            let r = 1.0 / (nu + j[i]);
            let w = m[i] * m[i] * r * r;
            s0 += w;
            s1 += j[i] * w;
            d0 += -2.0 * w * r;
            d1 += -2.0 * j[i] * w * r;
        }
        (s1.ln() - 0.75 * s0.ln(), d1 / s1 - 0.75 * d0 / s0)
    }

    /// Every `m_i ≠ 0`: the number of roots of `h(ν) = p`.
    fn all_components(j: Vector3<f64>, m: Vector3<f64>, p: f64) -> usize {
        if p == 0.0 {
            return 2;
        }
        let mut poles: Vec<f64> = j.iter().map(|v| -v).collect();
        poles.sort_by(f64::total_cmp);
        poles.dedup();
        // Intervals of ν as maps from t ∈ (0, 1), with the value of h at both ends
        // (+∞ at a pole, 0 at ±∞).
        let mut pieces: Vec<Box<dyn Fn(f64) -> f64>> = Vec::new();
        let first = poles[0];
        let last = *poles.last().unwrap();
        pieces.push(Box::new(move |t: f64| first - (1.0 - t) / t));
        for w in poles.windows(2) {
            let (a, b) = (w[0], w[1]);
            pieces.push(Box::new(move |t: f64| a + (b - a) * t));
        }
        pieces.push(Box::new(move |t: f64| last + t / (1.0 - t)));
        let log_p = p.ln();
        let mut count = 0;
        let k = pieces.len();
        for (i, nu_of) in pieces.iter().enumerate() {
            // The values of log h at the ends of the monotone pieces of this interval.
            let left = if i == 0 {
                f64::NEG_INFINITY
            } else {
                f64::INFINITY
            };
            let right = if i == k - 1 {
                f64::NEG_INFINITY
            } else {
                f64::INFINITY
            };
            let mut ends = vec![left];
            let samples = 4000;
            let dh = |t: f64| log_h(&j, &m, nu_of(t)).1;
            let mut t0 = 0.5 / samples as f64;
            let mut d0 = dh(t0);
            for s in 1..samples {
                let t1 = (s as f64 + 0.5) / samples as f64;
                let d1 = dh(t1);
                if (d0 > 0.0) != (d1 > 0.0) {
                    // Bisect the zero of the derivative: an extremum of h.
                    let (mut a, mut b, da) = (t0, t1, d0);
                    for _ in 0..200 {
                        let c = 0.5 * (a + b);
                        if c <= a || c >= b {
                            break;
                        }
                        if (dh(c) > 0.0) == (da > 0.0) {
                            a = c;
                        } else {
                            b = c;
                        }
                    }
                    let ta = if (log_h(&j, &m, nu_of(a)).0 - log_p).abs()
                        < (log_h(&j, &m, nu_of(b)).0 - log_p).abs()
                    {
                        a
                    } else {
                        b
                    };
                    ends.push(log_h(&j, &m, nu_of(ta)).0);
                }
                t0 = t1;
                d0 = d1;
            }
            ends.push(right);
            count += ends
                .windows(2)
                .filter(|w| (w[0] > log_p) != (w[1] > log_p))
                .count();
        }
        count
    }
}
use closed_form::closed_form_count;

/// The closed-form branch points in `p` of the poles `γ = ±e₃` of a top `diag(A, B, C)` with the
/// centre of mass on `e₃` (weight `mgl`): with `γ = (sin θ, 0, cos θ)`,
/// `U_r ≈ ½p²/C·(1 − (A − C)θ²/C) + σ·mgl(1 − θ²/2)` at the pole `σe₃`, whose curvature vanishes
/// at `p² = σ·mgl·C²/(C − A)` (and likewise with `B`).
fn pole_branch_points(a: f64, b: f64, c: f64, mgl: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for x in [a, b] {
        for sigma in [1.0, -1.0] {
            let p2 = sigma * mgl * c * c / (c - x);
            if p2.is_finite() && p2 > 0.0 {
                out.push(p2.sqrt());
            }
        }
    }
    out
}

struct Case {
    top: HeavyTop,
    range: (f64, f64),
    what: String,
}

fn random_case(rng: &mut ChaCha8Rng, k: usize) -> Case {
    let kind = k % 3;
    let a = rng.gen_range(0.5..3.0);
    let b = if kind == 0 {
        a
    } else {
        a * rng.gen_range(0.6..1.6)
    };
    // Near-spherical bodies now and then.
    let c = if rng.gen_bool(0.2) {
        a * (1.0 + rng.gen_range(-0.03..0.03))
    } else {
        rng.gen_range(0.5..3.0)
    };
    let mgl = rng.gen_range(0.2..2.0);
    let com = if kind == 2 {
        Vector3::new(
            rng.gen_range(-0.5..0.5),
            rng.gen_range(-0.5..0.5),
            rng.gen_range(0.5..1.0),
        )
        .normalize()
    } else {
        Vector3::z()
    };
    let top = HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(a, b, c)),
        mgr: mgl * com,
    };
    let bps: Vec<f64> = if kind == 2 {
        Vec::new()
    } else {
        pole_branch_points(a, b, c, mgl)
            .into_iter()
            .filter(|p| *p < 30.0)
            .collect()
    };
    let mode = rng.gen_range(0..3);
    let range = if mode == 0 || bps.is_empty() {
        let lo = rng.gen_range(0.0..4.0);
        (lo, lo + rng.gen_range(0.3..4.0))
    } else {
        let bp = bps[rng.gen_range(0..bps.len())];
        let w = bp * rng.gen_range(0.01..0.5);
        if mode == 1 {
            // Centred on the branch point.
            (bp - w, bp + w)
        } else {
            // A seed (one of 5, ends included) exactly on the branch point.
            let j = rng.gen_range(0..5) as f64;
            let lo = bp - j * w / 2.0;
            (lo, lo + 2.0 * w)
        }
    };
    let range = (range.0.max(0.0), range.1);
    Case {
        what: format!(
            "inertia ({a}, {b}, {c}), mgr {:?}, range {:?}, mode {mode}",
            top.mgr.as_slice(),
            range
        ),
        top,
        range,
    }
}

/// Figures of a sweep.
#[derive(Default, Debug)]
struct Figures {
    /// Diagrams computed.
    bodies: usize,
    /// `count_at` compared with the closed form: at random `s`, next to events.
    random_checks: usize,
    near_checks: usize,
    /// Of those, where the global search was also compared (its self-check consistent).
    search_checks: usize,
    /// Where the search's self-check said `consistent: false` (no comparison of the search).
    search_unsure: usize,
    events: usize,
    branches: usize,
}

/// Runs `n` cases; returns the failures and prints the figures.
fn sweep(n: usize, seed: u64) -> Vec<String> {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let opts = ContinuationOptions::default();
    let mut failures = Vec::new();
    let mut f = Figures::default();
    let t0 = std::time::Instant::now();
    for k in 0..n {
        let case = random_case(&mut rng, k);
        let top = case.top.clone();
        let d = match bifurcation_diagram(|p| (top.clone(), p), case.range, &opts) {
            Ok(d) => d,
            Err(e) => {
                failures.push(format!("{}: error {e}", case.what));
                continue;
            }
        };
        if let Some(stop) = &d.stop {
            failures.push(format!("{}: stopped: {stop}", case.what));
            continue;
        }
        f.bodies += 1;
        f.events += d.events.len();
        f.branches += d.branches.len();
        let (lo, hi) = case.range;
        let away = |s: f64, k: f64| {
            d.events
                .iter()
                .all(|e| (e.s - s).abs() >= k * 1e-6 * e.s.abs().max(1.0))
        };
        // Random s, and s just beside every event (both sides), at 1.2 … 50 × 1e−6·max(1, |s|).
        let mut at: Vec<(f64, bool)> = Vec::new();
        for _ in 0..3 {
            let s: f64 = rng.gen_range(lo..hi);
            if away(s, 1.2) {
                at.push((s, false));
            }
        }
        for e in &d.events {
            for side in [-1.0, 1.0] {
                let k = 1.2 * (50f64 / 1.2).powf(rng.gen_range(0.0..1.0));
                let s = e.s + side * k * 1e-6 * e.s.abs().max(1.0);
                if s > lo && s < hi && away(s, 1.2) {
                    at.push((s, true));
                }
            }
        }
        let j = case.top.j.diagonal();
        for (s, near) in at {
            let Some(exact) = closed_form_count(j, case.top.mgr, s) else {
                continue;
            };
            if near {
                f.near_checks += 1;
            } else {
                f.random_checks += 1;
            }
            let on = d.count_at(s);
            if on != exact {
                failures.push(format!(
                    "{}: at s = {s}{}: count_at {on}, closed form {exact}",
                    case.what,
                    if near { " (next to an event)" } else { "" }
                ));
            }
            match steady_motion_search(&case.top, s, &SearchOptions::default()) {
                Ok(found) if found.consistent => {
                    f.search_checks += 1;
                    if found.motions.len() != exact {
                        failures.push(format!(
                            "{}: at s = {s}: steady_motions {} (consistent), closed form {exact}",
                            case.what,
                            found.motions.len()
                        ));
                    }
                }
                Ok(found) => {
                    f.search_unsure += 1;
                    println!(
                        "search unsure: {}: at s = {s}: {} motions, closed form {exact}",
                        case.what,
                        found.motions.len()
                    );
                }
                Err(e) => failures.push(format!("{}: at s = {s}: search error {e}", case.what)),
            }
        }
    }
    println!(
        "sweep of {n} bodies (seed {seed}): {} failures, {f:?}, {:.1} s",
        failures.len(),
        t0.elapsed().as_secs_f64()
    );
    for f in &failures {
        println!("FAIL {f}");
    }
    failures
}

#[test]
fn closed_form_count_of_the_lagrange_top() {
    // A₁ = 1, C = 1.25, mgl = 1: one circle of tilted precessions beyond the secular bound
    // p² = mglC²/(C − A₁) = 6.25, none below.
    let j = Vector3::new(1.0, 1.0, 1.25);
    let m = Vector3::new(0.0, 0.0, 1.0);
    assert_eq!(closed_form_count(j, m, 1.0), Some(2));
    assert_eq!(closed_form_count(j, m, 2.6), Some(3));
    assert_eq!(closed_form_count(j, m, 2.4), Some(2));
    // An asymmetric top: two tilted motions per root; the symmetric one, one circle.
    let ja = Vector3::new(1.0, 1.1, 1.25);
    assert_eq!(closed_form_count(ja, m, 10.0).map(|c| c % 2), Some(0));
    // Off-axis: p = 0 has the two equilibria ±m/|m|; small p two; a large p near the
    // principal axes 6 (every axis' pole steadily rotating, both ways).
    let mo = Vector3::new(0.1, 0.2, 1.0);
    assert_eq!(closed_form_count(ja, mo, 1e-3), Some(2));
    assert_eq!(closed_form_count(ja, mo, 100.0), Some(6));
}

#[test]
fn sweep_of_150_random_tops_never_fails_and_counts_right() {
    let failures = sweep(150, 20);
    assert!(failures.is_empty(), "{} failures", failures.len());
}

#[test]
#[ignore = "1000 bodies: minutes; run with -- --ignored"]
fn sweep_of_1000_random_tops_never_fails_and_counts_right() {
    let failures = sweep(1000, 2020);
    assert!(failures.is_empty(), "{} failures", failures.len());
}
