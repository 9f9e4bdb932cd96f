//! The cases of the runtime property test: which public function of routh-core a case calls
//! (by weight), on which model, with which random inputs.

use std::fmt::Debug;

use rand::Rng;
use rand_chacha::ChaCha8Rng;
use routh_core::certify::{steady_motions_certified, CertifyOptions};
use routh_core::families::{self, AtlasOptions};
use routh_core::sim::{self, Output};
use routh_core::stability;
use routh_core::steady::{self, SteadyMotion};
use routh_core::{
    bifurcation_diagram, classify, continue_branch, simulate_full, simulate_reduced,
    stability_atlas, steady_motion_near, steady_motions, Routhian,
};

use super::harness::{diagram_defect, finite, report_defect, steady_defect, vecs_finite, Harness};
use super::inputs::{
    classify_options, continuation_options, gamma, gyrostat, heavy_top, log_uniform, maybe, range,
    scalar, search_options, sim_options, t_end, vector,
};
use super::{case_rng, Part};
use crate::{Gyrostat, HeavyTop};

/// A model whose family over a parameter `s` can be formed (the weight scaled by `s`).
pub trait Model: Routhian + Clone + Debug + Sync {
    /// The model with its weight scaled by `s`.
    fn scaled(&self, s: f64) -> Self;
}

impl Model for HeavyTop {
    fn scaled(&self, s: f64) -> Self {
        HeavyTop {
            j: self.j,
            mgr: self.mgr * s,
        }
    }
}

impl Model for Gyrostat {
    fn scaled(&self, s: f64) -> Self {
        Gyrostat {
            g: self.g * s,
            ..self.clone()
        }
    }
}

/// One case: one public function of routh-core (`pick`, drawn with the case's model) on one random input
/// drawn from `rng`, on `model`.
pub fn run_case<M: Model>(h: &mut Harness, rng: &mut ChaCha8Rng, model: &M, pick: u32) {
    match pick {
        0 => {
            let (w, g, t) = (vector(rng), gamma(rng), t_end(rng));
            let o = sim_options(rng, t);
            let steps_not_recorded = matches!(&o.output, Output::Times(ts) if ts.is_empty());
            h.check(
                "simulate_full",
                || format!("{model:?}, omega0 = {w:?}, gamma0 = {g:?}, t_end = {t:e}, {o:?}"),
                || simulate_full(model, w, g, t, &o),
                |tr| {
                    let ok = finite(&tr.t)
                        && vecs_finite(&tr.omega)
                        && vecs_finite(&tr.gamma)
                        && finite(&tr.energy)
                        && finite(&tr.p_psi)
                        && finite(&tr.gamma_norm_sq)
                        && (!tr.is_empty() || steps_not_recorded);
                    (!ok).then(|| format!("trajectory {tr:?}"))
                },
            );
        }
        1 => {
            let (w, g, p, t) = (vector(rng), gamma(rng), scalar(rng), t_end(rng));
            let o = sim_options(rng, t);
            let steps_not_recorded = matches!(&o.output, Output::Times(ts) if ts.is_empty());
            h.check(
                "simulate_reduced",
                || {
                    format!(
                        "{model:?}, big_omega0 = {w:?}, gamma0 = {g:?}, p_psi = {p:e}, \
                         t_end = {t:e}, {o:?}"
                    )
                },
                || simulate_reduced(model, w, g, p, t, &o),
                |tr| {
                    let ok = finite(&tr.t)
                        && vecs_finite(&tr.big_omega)
                        && vecs_finite(&tr.gamma)
                        && vecs_finite(&tr.omega)
                        && finite(&tr.psi)
                        && finite(&tr.psi_dot)
                        && finite(&tr.energy)
                        && finite(&tr.p_psi)
                        && finite(&tr.gamma_norm_sq)
                        && (!tr.is_empty() || steps_not_recorded);
                    (!ok).then(|| format!("trajectory {tr:?}"))
                },
            );
        }
        2 => {
            // The vector fields pass non-finite model outputs through as non-finite rates (so
            // that an integrator can shrink its step): only panics and errors are checked.
            let (w, g) = (vector(rng), gamma(rng));
            h.check(
                "sim::full_vector_field",
                || format!("{model:?}, omega = {w:?}, gamma = {g:?}"),
                || sim::full_vector_field(model, &w, &g),
                |_| None,
            );
        }
        3 => {
            let (w, g, p) = (vector(rng), gamma(rng), scalar(rng));
            h.check(
                "sim::reduced_vector_field",
                || format!("{model:?}, big_omega = {w:?}, gamma = {g:?}, p_psi = {p:e}"),
                || sim::reduced_vector_field(model, &w, &g, p),
                |_| None,
            );
        }
        4 => {
            let (g, p, iso) = (gamma(rng), scalar(rng), rng.gen_bool(0.8));
            h.check(
                "SteadyMotion::at",
                || format!("{model:?}, gamma = {g:?}, p_psi = {p:e}, isolated = {iso}"),
                || SteadyMotion::at(model, g, p, iso),
                steady_defect,
            );
        }
        5 => {
            let (g, p) = (gamma(rng), scalar(rng));
            h.check(
                "stability::f2_coefficients",
                || format!("{model:?}, gamma = {g:?}, p_psi = {p:e}"),
                || stability::f2_coefficients(model, &g, p),
                |c| (!finite(c)).then(|| format!("coefficients {c:?}")),
            );
        }
        6 => {
            let (g, p) = (gamma(rng), scalar(rng));
            h.check(
                "steady_motion_near",
                || format!("{model:?}, gamma_guess = {g:?}, p_psi = {p:e}"),
                || steady_motion_near(model, g, p),
                steady_defect,
            );
        }
        7 | 8 => {
            // classify on a steady motion found by Newton (valid input, the interesting path)
            // or on a random record (mostly not a steady motion).
            let (g, p) = (gamma(rng), scalar(rng));
            let steady = match steady_motion_near(model, g, p) {
                Ok(s) if rng.gen_bool(0.8) => s,
                _ => SteadyMotion {
                    p_psi: p,
                    gamma: g,
                    psi_dot: scalar(rng),
                    mu: scalar(rng),
                    amended_potential: scalar(rng),
                    energy: scalar(rng),
                    isolated: rng.gen_bool(0.5),
                },
            };
            if pick == 7 {
                h.check(
                    "classify",
                    || format!("{model:?}, {steady:?}"),
                    || classify(model, &steady),
                    report_defect,
                );
            } else {
                let o = classify_options(rng);
                h.check(
                    "stability::classify_with",
                    || format!("{model:?}, {steady:?}, {o:?}"),
                    || stability::classify_with(model, &steady, &o),
                    report_defect,
                );
            }
        }
        9 => {
            let (p, o) = (scalar(rng), search_options(rng));
            h.check(
                "steady::steady_motion_search",
                || format!("{model:?}, p_psi = {p:e}, {o:?}"),
                || steady::steady_motion_search(model, p, &o),
                |r| r.motions.iter().find_map(steady_defect),
            );
        }
        10 => {
            let p = scalar(rng);
            h.check(
                "steady_motions",
                || format!("{model:?}, p_psi = {p:e}"),
                || steady_motions(model, p),
                |v| v.iter().find_map(steady_defect),
            );
        }
        11 => {
            let p = scalar(rng);
            h.check(
                "steady::steady_motion_search (default search)",
                || format!("{model:?}, p_psi = {p:e}"),
                || steady::steady_motion_search(model, p, &steady::SearchOptions::default()),
                |r| r.motions.iter().find_map(steady_defect),
            );
        }
        12 => {
            let (r, o) = (range(rng), continuation_options(rng));
            let over_p = rng.gen_bool(0.5);
            let p = scalar(rng);
            h.check(
                "bifurcation_diagram",
                || format!("{model:?}, over p_psi: {over_p}, p_psi = {p:e}, {r:?}, {o:?}"),
                || {
                    if over_p {
                        bifurcation_diagram(|s| (model.clone(), s), r, &o)
                    } else {
                        bifurcation_diagram(|s| (model.scaled(s), p), r, &o)
                    }
                },
                diagram_defect,
            );
        }
        13 => {
            let (r, o) = (range(rng), continuation_options(rng));
            let s0 = if rng.gen_bool(0.9) && r.0.is_finite() && r.1.is_finite() {
                let u: f64 = rng.gen_range(0.0..=1.0);
                maybe(rng, r.0 + (r.1 - r.0) * u)
            } else {
                scalar(rng)
            };
            let (g, p, over_p) = (gamma(rng), scalar(rng), rng.gen_bool(0.5));
            h.check(
                "continue_branch",
                || {
                    format!(
                        "{model:?}, over p_psi: {over_p}, p_psi = {p:e}, gamma_guess = {g:?}, \
                         s0 = {s0:e}, {r:?}, {o:?}"
                    )
                },
                || {
                    if over_p {
                        continue_branch(|s| (model.clone(), s), g, s0, r, &o)
                    } else {
                        continue_branch(|s| (model.scaled(s), p), g, s0, r, &o)
                    }
                },
                diagram_defect,
            );
        }
        15 => {
            let p = scalar(rng);
            let w = log_uniform(rng, 1e-6, 1.0);
            let o = CertifyOptions {
                max_boxes: rng.gen_range(0..3000),
                min_width: maybe(rng, w),
                initial_split: rng.gen_range(0..6),
                refine_iterations: rng.gen_range(0..40),
            };
            h.check(
                "certify::steady_motions_certified",
                || format!("{model:?}, p_psi = {p:e}, {o:?}"),
                || steady_motions_certified(model, p, &o),
                |c| {
                    let ok = c.boxes <= o.max_boxes
                        && c.complete == (c.undecided.is_empty() && c.ambiguous_pairs == 0);
                    (!ok)
                        .then(|| format!("inconsistent certificate {c:?}"))
                        .or_else(|| c.motions.iter().find_map(|m| steady_defect(&m.steady)))
                },
            );
        }
        16 => {
            let (g, p) = (gamma(rng), scalar(rng));
            let o = classify_options(rng);
            let steady = match steady_motion_near(model, g, p) {
                Ok(s) => s,
                Err(_) => return,
            };
            h.check(
                "stability::krein_report",
                || format!("{model:?}, {steady:?}, {o:?}"),
                || stability::krein_report(model, &steady, &o),
                |k| report_defect(&k.report),
            );
        }
        17 => {
            let (r, o) = (range(rng), continuation_options(rng));
            let p = scalar(rng);
            h.check(
                "families::bifurcation_diagram (checks)",
                || format!("{model:?}, p_psi = {p:e}, {r:?}, {o:?}"),
                || families::bifurcation_diagram(|s| (model.scaled(s), p), r, &o),
                diagram_defect,
            );
        }
        18 => {
            let (p, o) = (scalar(rng), search_options(rng));
            h.check(
                "steady::steady_motion_search",
                || format!("{model:?}, p_psi = {p:e}, {o:?}"),
                || steady::steady_motion_search(model, p, &o),
                |r| r.motions.iter().find_map(steady_defect),
            );
        }
        19 => {
            let (x, y, g) = (range(rng), range(rng), gamma(rng));
            let o = AtlasOptions {
                nx: rng.gen_range(0..4),
                ny: rng.gen_range(0..4),
                max_curve_points: rng.gen_range(0..20),
                threads: rng.gen_range(0..3),
                ..AtlasOptions::default()
            };
            h.check(
                "families::stability_atlas_parallel",
                || format!("{model:?}, gamma_guess = {g:?}, x = {x:?}, y = {y:?}, {o:?}"),
                || families::stability_atlas_parallel(|a, b| (model.scaled(a), b), g, x, y, &o),
                |a| {
                    let ok = finite(&a.x) && finite(&a.y);
                    (!ok).then(|| "non-finite atlas grid".to_string())
                },
            );
        }
        _ => {
            let (x, y, g) = (range(rng), range(rng), gamma(rng));
            let o = AtlasOptions {
                nx: rng.gen_range(0..4),
                ny: rng.gen_range(0..4),
                max_curve_points: rng.gen_range(0..20),
                threads: 1,
                ..AtlasOptions::default()
            };
            h.check(
                "stability_atlas",
                || format!("{model:?}, gamma_guess = {g:?}, x = {x:?}, y = {y:?}, {o:?}"),
                || stability_atlas(|a, b| (model.scaled(a), b), g, x, y, &o),
                |a| {
                    let ok = finite(&a.x) && finite(&a.y);
                    (!ok).then(|| "non-finite atlas grid".to_string())
                },
            );
        }
    }
}

/// Which function a case calls, by weight (cheap functions often, searches and continuation
/// rarely), and which model; runs it if the model belongs to `part`. Returns whether it ran.
pub(crate) fn run_one(h: &mut Harness, part: &Part<'_>, seed: u64, case: u64) -> bool {
    h.case = case;
    let mut rng = case_rng(seed, case);
    let roll = rng.gen_range(0..10_000u32);
    let pick = match roll {
        0..=1_399 => 0,      // simulate_full
        1_400..=2_799 => 1,  // simulate_reduced
        2_800..=3_899 => 2,  // full_vector_field
        3_900..=4_999 => 3,  // reduced_vector_field
        5_000..=5_999 => 4,  // SteadyMotion::at
        6_000..=6_899 => 5,  // f2_coefficients
        6_900..=7_799 => 6,  // steady_motion_near
        7_800..=8_599 => 7,  // classify
        8_600..=9_399 => 8,  // classify_with
        9_400..=9_899 => 9,  // steady_motion_search (≤ 20 starts)
        9_900..=9_919 => 10, // steady_motions (default search)
        9_920..=9_939 => 11, // steady_motion_search (default search)
        9_940..=9_959 => 12, // bifurcation_diagram
        9_960..=9_989 => 13, // continue_branch
        _ => 14,             // stability_atlas
    };
    // A second roll, in place of 8 % of the simulations, for the functions added later.
    let pick = if pick <= 1 && rng.gen_bool(0.08) {
        match rng.gen_range(0..100u32) {
            0..=59 => 15,  // steady_motions_certified
            60..=89 => 16, // krein_report
            90..=93 => 17, // bifurcation_diagram, a second draw
            94..=97 => 18, // steady_motion_search, a second draw
            _ => 19,       // stability_atlas_parallel
        }
    } else {
        pick
    };
    // The num-dual gyrostat is slower: one case in five, and rarely for the global searches.
    // The default search (400 starts, 1600 more when the Morse check fails) on the gyrostat takes
    // up to ~3 s at opt-level 1 (num-dual's copies): only the heavy top is searched with it.
    let gyro = if pick == 10 || pick == 11 {
        false
    } else if pick >= 9 {
        rng.gen_bool(0.05)
    } else {
        rng.gen_bool(0.2)
    };
    // Special values in the model's parameters (1 % each), except for the default search: a
    // subnormal moment of inertia makes every operation ~100× slower (microcode assists) and
    // the 2000-start search then takes seconds.
    let sp = if pick == 10 || pick == 11 { 0.0 } else { 0.01 };
    // The certified search needs the derive's tape: mostly the derived gyrostat there; the
    // derived gyrostat (the same parameters as the num-dual twin) also takes a share of the rest.
    let derived = if pick == 15 {
        rng.gen_bool(0.9)
    } else {
        pick != 10 && pick != 11 && rng.gen_bool(0.1)
    };
    match (derived, part) {
        (true, Part::Derived(run_derived)) => {
            let twin = gyrostat(&mut rng, sp);
            run_derived(h, &mut rng, &twin, pick);
        }
        (false, Part::Hand) if gyro => {
            let m = gyrostat(&mut rng, sp);
            run_case(h, &mut rng, &m, pick);
        }
        (false, Part::Hand) => {
            let m = heavy_top(&mut rng, sp);
            run_case(h, &mut rng, &m, pick);
        }
        // The case belongs to the other part.
        _ => return false,
    }
    true
}
