//! Random inputs of the runtime property test: scalars, vectors and matrices log-uniform over
//! `1e−6…1e6` with random signs, special values (NaN, ±∞, ±0, subnormals, ±1e300) mixed in, random
//! models and random options of every public function.

use rand::Rng;
use rand_chacha::ChaCha8Rng;
use routh_core::families::ContinuationOptions;
use routh_core::nalgebra::{Rotation3, Unit};
use routh_core::sim::{Method, Output, SimOptions};
use routh_core::stability::ClassifyOptions;
use routh_core::steady::SearchOptions;
use routh_core::{Matrix3, Vector3};

use crate::{Gyrostat, HeavyTop};

/// The special values mixed into every scalar input.
pub(crate) const SPECIALS: [f64; 12] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    0.0,
    -0.0,
    5e-324,
    -5e-324,
    1e-310,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN_POSITIVE,
];

pub(crate) fn special(rng: &mut ChaCha8Rng) -> f64 {
    SPECIALS[rng.gen_range(0..SPECIALS.len())]
}

/// `10^U(lo, hi)`.
pub(crate) fn log_uniform(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    10f64.powf(rng.gen_range(lo..hi))
}

/// `±10^U(lo, hi)`.
pub(crate) fn signed_log(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    let x = log_uniform(rng, lo, hi);
    if rng.gen_bool(0.5) {
        -x
    } else {
        x
    }
}

/// `x`, or with probability `p` a special value.
pub(crate) fn spiced(rng: &mut ChaCha8Rng, p: f64, x: f64) -> f64 {
    if rng.gen_bool(p) {
        special(rng)
    } else {
        x
    }
}

/// A scalar input: `x`, or a special value with probability 10 %.
pub(crate) fn maybe(rng: &mut ChaCha8Rng, x: f64) -> f64 {
    spiced(rng, 0.1, x)
}

/// A model parameter: `±1e−6…1e6`, sometimes 0, special with probability `specials`.
pub(crate) fn param(rng: &mut ChaCha8Rng, specials: f64) -> f64 {
    let x = if rng.gen_bool(0.05) {
        0.0
    } else {
        signed_log(rng, -6.0, 6.0)
    };
    spiced(rng, specials, x)
}

pub(crate) fn param_vec(rng: &mut ChaCha8Rng, sp: f64) -> Vector3<f64> {
    match rng.gen_range(0..10) {
        // Along one body axis: principal-axis steady motions exist.
        0..=2 => {
            let mut v = Vector3::zeros();
            v[rng.gen_range(0..3)] = param(rng, sp);
            v
        }
        3 => Vector3::zeros(),
        _ => Vector3::new(param(rng, sp), param(rng, sp), param(rng, sp)),
    }
}

pub(crate) fn unit_vector(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    loop {
        let v = Vector3::new(
            rng.gen_range(-1.0..1.0),
            rng.gen_range(-1.0..1.0),
            rng.gen_range(-1.0..1.0),
        );
        let n = v.norm();
        if n > 1e-3 && n <= 1.0 {
            return v / n;
        }
    }
}

pub(crate) fn rotation(rng: &mut ChaCha8Rng) -> Matrix3<f64> {
    let axis = Unit::new_normalize(unit_vector(rng));
    *Rotation3::from_axis_angle(&axis, rng.gen_range(-3.2..3.2)).matrix()
}

/// An inertia-like matrix: mostly symmetric positive definite with eigenvalues `1e−6…1e6`
/// (diagonal or rotated), now and then indefinite, singular, non-symmetric or non-finite.
pub(crate) fn inertia(rng: &mut ChaCha8Rng, sp: f64) -> Matrix3<f64> {
    let mut d = Vector3::new(
        log_uniform(rng, -6.0, 6.0),
        log_uniform(rng, -6.0, 6.0),
        log_uniform(rng, -6.0, 6.0),
    );
    let kind = rng.gen_range(0..40);
    match kind {
        0..=2 => d[rng.gen_range(0..3)] *= -1.0, // indefinite
        3..=4 => d[rng.gen_range(0..3)] = 0.0,   // singular
        5 => d = Vector3::zeros(),
        _ => {}
    }
    if rng.gen_bool(0.3) {
        // Symmetric: two equal moments.
        d[1] = d[0];
    }
    match kind {
        6 => Matrix3::from_fn(|_, _| param(rng, sp)), // non-symmetric
        7 if sp > 0.0 => {
            let mut m = Matrix3::from_diagonal(&d);
            m[(rng.gen_range(0..3), rng.gen_range(0..3))] = special(rng);
            m
        }
        _ if rng.gen_bool(0.5) => Matrix3::from_diagonal(&d),
        _ => {
            let r = rotation(rng);
            r * Matrix3::from_diagonal(&d) * r.transpose()
        }
    }
}

/// `sp`: the probability of a special value in each parameter.
pub(crate) fn heavy_top(rng: &mut ChaCha8Rng, sp: f64) -> HeavyTop {
    HeavyTop {
        j: inertia(rng, sp),
        mgr: param_vec(rng, sp),
    }
}

pub(crate) fn gyrostat(rng: &mut ChaCha8Rng, sp: f64) -> Gyrostat {
    Gyrostat {
        inertia: inertia(rng, sp),
        rotor: if rng.gen_bool(0.5) {
            Vector3::zeros()
        } else {
            param_vec(rng, sp)
        },
        coupling: match rng.gen_range(0..4) {
            0 | 1 => Matrix3::zeros(),
            2 => Matrix3::from_diagonal(&param_vec(rng, sp)),
            _ => Matrix3::from_fn(|_, _| param(rng, sp)),
        },
        com: param_vec(rng, sp),
        mass: param(rng, sp),
        g: param(rng, sp),
    }
}

/// A scalar like p_ψ: `±1e−6…1e6`, 0, or special.
pub(crate) fn scalar(rng: &mut ChaCha8Rng) -> f64 {
    let x = if rng.gen_bool(0.05) {
        0.0
    } else {
        signed_log(rng, -6.0, 6.0)
    };
    maybe(rng, x)
}

pub(crate) fn vector(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    if rng.gen_bool(0.1) {
        return Vector3::zeros();
    }
    let s = log_uniform(rng, -6.0, 6.0);
    let v = unit_vector(rng) * s;
    Vector3::new(maybe(rng, v.x), maybe(rng, v.y), maybe(rng, v.z))
}

/// A vertical: mostly unit (random, a body axis, or just within/outside the tolerance 1e−8),
/// sometimes anything.
pub(crate) fn gamma(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    let g = match rng.gen_range(0..20) {
        0..=3 => {
            let mut v = Vector3::zeros();
            v[rng.gen_range(0..3)] = if rng.gen_bool(0.5) { 1.0 } else { -1.0 };
            v
        }
        4 => unit_vector(rng) * (1.0 + 0.9e-8),
        5 => unit_vector(rng) * (1.0 + 2e-8),
        6 => Vector3::zeros(),
        7 => unit_vector(rng) * log_uniform(rng, -6.0, 6.0),
        _ => unit_vector(rng),
    };
    if rng.gen_bool(0.3) {
        Vector3::new(maybe(rng, g.x), maybe(rng, g.y), maybe(rng, g.z))
    } else {
        g
    }
}

pub(crate) fn tolerance(rng: &mut ChaCha8Rng, lo: f64, hi: f64) -> f64 {
    let x = log_uniform(rng, lo, hi);
    maybe(rng, x)
}

pub(crate) fn sim_options(rng: &mut ChaCha8Rng, t_end: f64) -> SimOptions {
    let method = if rng.gen_bool(0.25) {
        let n = rng.gen_range(1..60) as f64;
        let step = if t_end.is_finite() && t_end > 0.0 {
            t_end / n
        } else {
            1e-3
        };
        Method::LieRk4 {
            step: maybe(rng, step),
        }
    } else {
        Method::Dop853
    };
    let output = if rng.gen_bool(0.2) {
        let k = rng.gen_range(0..6);
        let span = if t_end.is_finite() { t_end } else { 1.0 };
        let mut ts: Vec<f64> = (0..k).map(|_| span * rng.gen_range(0.0..=1.0)).collect();
        if rng.gen_bool(0.8) {
            ts.sort_by(f64::total_cmp);
        }
        let ts = ts.into_iter().map(|t| spiced(rng, 0.03, t)).collect();
        Output::Times(ts)
    } else {
        Output::Steps
    };
    SimOptions {
        rtol: tolerance(rng, -15.0, -2.0),
        atol: tolerance(rng, -15.0, -2.0),
        rate_atol: if rng.gen_bool(0.3) {
            let x = log_uniform(rng, -12.0, 2.0);
            Some(maybe(rng, x))
        } else {
            None
        },
        method,
        h_max: if rng.gen_bool(0.2) {
            let x = log_uniform(rng, -6.0, 1.0);
            Some(maybe(rng, x))
        } else {
            None
        },
        h_init: if rng.gen_bool(0.2) {
            let x = log_uniform(rng, -9.0, 0.0);
            Some(maybe(rng, x))
        } else {
            None
        },
        max_steps: rng.gen_range(0..=60),
        output,
        attitude: false,
    }
}

pub(crate) fn t_end(rng: &mut ChaCha8Rng) -> f64 {
    let t = log_uniform(rng, -6.0, 1.0);
    let t = if rng.gen_bool(0.03) { -t } else { t };
    maybe(rng, t)
}

pub(crate) fn search_options(rng: &mut ChaCha8Rng) -> SearchOptions {
    SearchOptions {
        starts: rng.gen_range(0..=20),
        max_iterations: rng.gen_range(0..=30),
        gradient_tol: tolerance(rng, -14.0, 0.5),
        zero_eigenvalue_tol: tolerance(rng, -14.0, 0.5),
    }
}

pub(crate) fn classify_options(rng: &mut ChaCha8Rng) -> ClassifyOptions {
    if rng.gen_bool(0.3) {
        return ClassifyOptions::default();
    }
    ClassifyOptions {
        zero_eigenvalue_tol: tolerance(rng, -14.0, 0.5),
        steady_tol: tolerance(rng, -12.0, 0.5),
        double_root_tol: tolerance(rng, -14.0, 0.5),
    }
}

pub(crate) fn continuation_options(rng: &mut ChaCha8Rng) -> ContinuationOptions {
    let mut o = ContinuationOptions {
        max_steps: 50,
        max_branches: 4,
        seeds: 2,
        verify_counts: false,
        search: SearchOptions {
            starts: 20,
            ..SearchOptions::default()
        },
        ..ContinuationOptions::default()
    };
    if rng.gen_bool(0.3) {
        o.initial_step = tolerance(rng, -4.0, -0.5);
        o.max_step = tolerance(rng, -3.0, 0.5);
        o.min_step = tolerance(rng, -9.0, -3.0);
        o.newton_tol = tolerance(rng, -14.0, -2.0);
        o.event_tol = tolerance(rng, -14.0, -2.0);
        o.max_steps = rng.gen_range(0..=50);
        o.max_branches = rng.gen_range(0..=4);
        o.seeds = rng.gen_range(0..=2);
        o.search = search_options(rng);
        o.classify = classify_options(rng);
    }
    o
}

pub(crate) fn range(rng: &mut ChaCha8Rng) -> (f64, f64) {
    let a = signed_log(rng, -3.0, 3.0);
    let b = a + a.abs().max(1e-3) * log_uniform(rng, -3.0, 0.5);
    let r = if rng.gen_bool(0.05) { (b, a) } else { (a, b) };
    (maybe(rng, r.0), maybe(rng, r.1))
}

// ---------------------------------------------------------------------------------------------
// The properties.
