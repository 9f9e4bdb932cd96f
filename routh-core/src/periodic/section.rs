//! Poincaré sections at fixed `(p_ψ, E)` (docs/method.md §11).
//!
//! The surface is the plane `γ·n = 0` through the body coordinates of the vertical, crossed with
//! `d(γ·n)/dt > 0` (`n` a unit vector of the body, [`SectionOptions::normal`], default `e₁`). On
//! a level of `p_ψ` and `E` the reduced system has two degrees of freedom, so the crossings form
//! a two-dimensional picture, drawn in the coordinates `θ = atan2(γ·b, γ·a)` (the angle of γ on
//! the great circle `n^⊥`, with `a, b, n` right-handed) and `M_n = n·∂L/∂ω` (the angular momentum
//! about `n`, which `θ` is conjugate to up to sign). A periodic orbit crossing the plane `j` times
//! a period shows as `j` fixed points of the section's map.

use nalgebra::{Vector3, Vector6};
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

use super::flow::{field, join, split};
use super::PeriodicOrbit;
use crate::sim::dop853::{self, Accepted, Config};
use crate::solve::locate::{estimated_distance, illinois, End};
use crate::validate::check_finite;
use crate::{Lagrangian, RouthError};

/// The most orbits of one section.
pub(crate) const MAX_ORBITS: usize = 100_000;
/// The most crossings of one orbit of a section (at 24 bytes each).
pub(crate) const MAX_CROSSINGS: usize = 10_000_000;
/// The most crossings of a whole section, `orbits × crossings` (about 240 MB).
pub(crate) const MAX_POINTS: usize = 10_000_000;

/// Settings of a Poincaré section: at most 10⁵ orbits of at most 10⁷ crossings, and at most 10⁷
/// crossings in all ([`poincare_section`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SectionOptions {
    /// The plane is `γ·n = 0` (body frame; normalised).
    pub normal: Vector3<f64>,
    /// How many orbits [`poincare_section`] starts (spread over the section).
    pub orbits: usize,
    /// Crossings recorded per orbit.
    pub crossings: usize,
    /// Relative tolerance of the integration.
    pub rtol: f64,
    /// Absolute tolerance of the integration.
    pub atol: f64,
    /// Integration steps allowed per crossing (an orbit that stops crossing ends there).
    pub steps_per_crossing: usize,
    /// Cancellation and progress (not a setting: not serialised, not compared).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub control: crate::RunControl,
}

impl Default for SectionOptions {
    fn default() -> Self {
        SectionOptions {
            normal: Vector3::x(),
            orbits: 50,
            crossings: 200,
            rtol: 1e-10,
            atol: 1e-12,
            steps_per_crossing: 2000,
            control: crate::RunControl::default(),
        }
    }
}

impl SectionOptions {
    /// With the plane `γ·n = 0`.
    pub fn with_normal(mut self, n: Vector3<f64>) -> Self {
        self.normal = n;
        self
    }
    /// With `orbits` orbits of `crossings` crossings each.
    pub fn with_size(mut self, orbits: usize, crossings: usize) -> Self {
        self.orbits = orbits;
        self.crossings = crossings;
        self
    }

    fn validate(&self) -> Result<Vector3<f64>, RouthError> {
        check_finite("SectionOptions::normal", self.normal.as_slice())?;
        // The largest component, not the length: |n|² of 1e160·e₁ overflows and of 1e−200·e₁
        // underflows, and both are the plane of e₁.
        if self.normal.amax() == 0.0 {
            return Err(RouthError::InvalidOption {
                what: "SectionOptions::normal",
                reason: "must be a non-zero vector".into(),
            });
        }
        for (what, v) in [
            ("SectionOptions::rtol", self.rtol),
            ("SectionOptions::atol", self.atol),
        ] {
            if !(v.is_finite() && v > 0.0 && v < 1.0) {
                return Err(RouthError::InvalidOption {
                    what,
                    reason: format!("must be in (0, 1), got {v}"),
                });
            }
        }
        if self.crossings == 0 || self.steps_per_crossing == 0 {
            return Err(RouthError::InvalidOption {
                what: "SectionOptions::crossings",
                reason: "must be at least 1".into(),
            });
        }
        if self.orbits == 0 {
            return Err(RouthError::InvalidOption {
                what: "SectionOptions::orbits",
                reason: "must be at least 1".into(),
            });
        }
        if self.orbits > MAX_ORBITS || self.crossings > MAX_CROSSINGS {
            return Err(RouthError::InvalidOption {
                what: if self.orbits > MAX_ORBITS {
                    "SectionOptions::orbits"
                } else {
                    "SectionOptions::crossings"
                },
                reason: format!(
                    "at most {MAX_ORBITS} orbits of at most {MAX_CROSSINGS} crossings, got {} orbits of {} crossings",
                    self.orbits, self.crossings
                ),
            });
        }
        // Scale-free: 1e160·e₁ and 1e-200·e₁ are the same plane.
        let m = self.normal.amax();
        Ok((self.normal / m).normalize())
    }
}

/// The frame `(a, b)` of the plane `n^⊥`, `a × b = n`.
fn frame(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let pick = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let a = (pick - n * n.dot(&pick)).normalize();
    (a, n.cross(&a))
}

/// One orbit of a section: where it started and its crossings `(θ, M_n)`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SectionOrbit {
    /// `ω` at the start (on the section).
    pub omega0: Vector3<f64>,
    /// `γ` at the start.
    pub gamma0: Vector3<f64>,
    /// The crossings, in order: `[θ, M_n]`.
    pub points: Vec<[f64; 2]>,
    /// Why it has fewer crossings than asked (`None` when complete).
    pub stop: Option<String>,
}

/// A Poincaré section at `(p_ψ, E)`.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PoincareSection {
    /// The cyclic momentum.
    pub p_psi: f64,
    /// The energy.
    pub energy: f64,
    /// The plane's normal `n` (unit, body frame).
    pub normal: Vector3<f64>,
    /// The orbits.
    pub orbits: Vec<SectionOrbit>,
}

impl PoincareSection {
    /// Every crossing of every orbit, `[θ, M_n]`.
    pub fn points(&self) -> impl Iterator<Item = &[f64; 2]> {
        self.orbits.iter().flat_map(|o| o.points.iter())
    }
}

/// The section's coordinates of a state on the plane.
fn coords<M: Lagrangian + ?Sized>(
    model: &M,
    n: &Vector3<f64>,
    w: &Vector3<f64>,
    g: &Vector3<f64>,
) -> [f64; 2] {
    let (a, b) = frame(n);
    [g.dot(&b).atan2(g.dot(&a)), n.dot(&model.dl_domega(w, g))]
}

/// States on the section at `(p_ψ, E)`: γ on the great circle `n^⊥` at the angle θ, `ω·n = α`,
/// and `ω = αn + uγ + v(n × γ)` with `u` from `p_ψ` (linear) and `v > 0` from `E` (the larger
/// root of a quadratic), spread over a grid of `(θ, α)` and thinned to at most `count`.
pub(crate) fn section_starts<M: Lagrangian + ?Sized>(
    model: &M,
    p_psi: f64,
    energy: f64,
    count: usize,
    normal: &Vector3<f64>,
) -> Vec<(Vector3<f64>, Vector3<f64>)> {
    let n = normal.normalize();
    // A grid of 48² candidates, finer until it holds `count` starts (a level whose motions
    // cover a small part of the plane) or has 4·count candidates or more.
    let mut grid = 48usize;
    loop {
        let found = starts_on_grid(model, p_psi, energy, &n, grid);
        if found.len() >= count || grid * grid >= 4 * count || grid >= 4096 {
            return thinned(found, count);
        }
        grid *= 2;
    }
}

/// At most `count` of `found`, spread evenly over it.
fn thinned<T: Copy>(found: Vec<T>, count: usize) -> Vec<T> {
    if found.len() <= count {
        return found;
    }
    let step = found.len() as f64 / count as f64;
    (0..count)
        .map(|i| found[((i as f64 + 0.5) * step) as usize])
        .collect()
}

/// The starts of [`section_starts`] on a `grid × grid` lattice of `(θ, α)`.
fn starts_on_grid<M: Lagrangian + ?Sized>(
    model: &M,
    p_psi: f64,
    energy: f64,
    n: &Vector3<f64>,
    grid: usize,
) -> Vec<(Vector3<f64>, Vector3<f64>)> {
    let (a, b) = frame(n);
    // α's range from the energy above the potential's least value on the circle.
    let mut umin = f64::INFINITY;
    let mut jmin = f64::INFINITY;
    for i in 0..grid {
        let th = std::f64::consts::TAU * i as f64 / grid as f64;
        let g = a * th.cos() + b * th.sin();
        umin = umin.min(model.energy(&Vector3::zeros(), &g));
        let j = model.d2l_domega2(&g);
        jmin = jmin.min(j.symmetric_eigenvalues().min());
    }
    let amax = if jmin > 0.0 && energy > umin {
        (2.0 * (energy - umin) / jmin).sqrt()
    } else {
        0.0
    };
    let mut found = Vec::new();
    for i in 0..grid {
        let th = std::f64::consts::TAU * (i as f64 + 0.5) / grid as f64;
        let g = a * th.cos() + b * th.sin();
        let m = n.cross(&g);
        let j = model.d2l_domega2(&g);
        let av = model.dl_domega(&Vector3::zeros(), &g);
        let u_pot = model.energy(&Vector3::zeros(), &g);
        let gjg = g.dot(&(j * g));
        if gjg.is_nan() || gjg <= 0.0 {
            continue;
        }
        for k in 0..grid {
            let alpha = amax * (2.0 * (k as f64 + 0.5) / grid as f64 - 1.0);
            let u0 = (p_psi - av.dot(&g) - alpha * n.dot(&(j * g))) / gjg;
            let w0 = n * alpha + g * u0;
            let d = m - g * (m.dot(&(j * g)) / gjg);
            let qa = 0.5 * d.dot(&(j * d));
            let qb = w0.dot(&(j * d));
            let qc = 0.5 * w0.dot(&(j * w0)) + u_pot - energy;
            let disc = qb * qb - 4.0 * qa * qc;
            if !(qa > 0.0 && disc >= 0.0) {
                continue;
            }
            let v = (-qb + disc.sqrt()) / (2.0 * qa);
            if v > 0.0 {
                found.push((w0 + d * v, g));
            }
        }
    }
    found
}

/// Integrates one orbit and records its upward crossings of `γ·n = 0`, until `max` crossings or
/// `t_end`.
fn crossings<M: Lagrangian + Sync + ?Sized>(
    model: &M,
    omega0: &Vector3<f64>,
    gamma0: &Vector3<f64>,
    n: &Vector3<f64>,
    max: usize,
    t_end: f64,
    opts: &SectionOptions,
) -> (Vec<[f64; 2]>, Vec<f64>, Option<String>) {
    let x0 = join(omega0, gamma0);
    let (rtol, atol) = (opts.rtol, opts.atol);
    let weights = dop853::componentwise(rtol, atol);
    let cfg = Config {
        weights: &weights,
        h_max: f64::INFINITY,
        h_init: None,
        max_steps: opts
            .steps_per_crossing
            .saturating_mul(max)
            .saturating_add(1000),
        dense: true,
        control: Some(&opts.control),
    };
    let mut points = Vec::new();
    let mut times = Vec::new();
    let mut prev = (0.0, gamma0.dot(n));
    let rhs = |_t: f64, x: &Vector6<f64>| field(model, x);
    let result = dop853::integrate(rhs, 0.0, x0, t_end, &cfg, |s: &Accepted<'_, 6>| {
        let (_, g) = split(s.y);
        let now = (s.t, g.dot(n));
        if prev.1 < 0.0 && now.1 >= 0.0 {
            if let Some(dense) = s.dense {
                let value = |t: f64| {
                    let (_, g) = split(&dense.eval(t));
                    g.dot(n)
                };
                let lo = End::new(prev.0, prev.1, ());
                let hi = End::new(now.0, now.1, ());
                let tol = 1e-14 * 1f64.max(now.0.abs());
                let z = illinois(
                    lo,
                    hi,
                    100,
                    |t| Ok::<_, RouthError>(Some((value(t), ()))),
                    |lo, hi| estimated_distance(lo, hi) <= tol || hi.at - lo.at <= tol,
                )?;
                let (w, g) = split(&dense.eval(z.at));
                points.push(coords(model, n, &w, &g));
                times.push(z.at);
            }
        }
        prev = now;
        if points.len() >= max {
            // Ends the integration: read below as "enough crossings", not as a failure.
            return Err(RouthError::NonFiniteState { t: f64::NAN });
        }
        Ok(())
    });
    let stop = match result {
        Ok(_) => None,
        Err(_) if points.len() >= max => None,
        Err(e) => Some(e.to_string()),
    };
    (points, times, stop)
}

/// The Poincaré section at `(p_ψ, E)`: [`SectionOptions::orbits`] orbits started on the plane
/// (`section_starts`), each integrated (in parallel, rayon) for [`SectionOptions::crossings`]
/// upward crossings of `γ·n = 0`, located on the integrator's dense output by the crate's event
/// locator. An orbit that cannot be integrated or stops crossing keeps what it has, with
/// [`SectionOrbit::stop`] saying why.
///
/// Errors: non-finite `p_ψ` or `E`, invalid options, and a level `(p_ψ, E)` with no motion on
/// the plane.
pub fn poincare_section<M: Lagrangian + Sync>(
    model: &M,
    p_psi: f64,
    energy: f64,
    opts: &SectionOptions,
) -> Result<PoincareSection, RouthError> {
    check_finite("p_psi", &[p_psi])?;
    check_finite("energy", &[energy])?;
    let n = opts.validate()?;
    if opts.orbits.saturating_mul(opts.crossings) > MAX_POINTS {
        return Err(RouthError::InvalidOption {
            what: "SectionOptions::crossings",
            reason: format!(
                "{} orbits × {} crossings is over the budget of {MAX_POINTS} crossings of one section (about 240 MB): ask for fewer",
                opts.orbits, opts.crossings
            ),
        });
    }
    let starts = section_starts(model, p_psi, energy, opts.orbits, &n);
    if starts.is_empty() {
        return Err(RouthError::InvalidOption {
            what: "energy",
            reason: format!(
                "no motion at p_ψ = {p_psi}, E = {energy} crosses the plane γ·n = 0 (n = ({:.3}, {:.3}, {:.3})): the energy is below the level's least value there",
                n.x, n.y, n.z
            ),
        });
    }
    let done = AtomicUsize::new(0);
    let total = starts.len();
    let orbits = starts
        .par_iter()
        .map(|(w, g)| {
            let (points, _, stop) =
                crossings(model, w, g, &n, opts.crossings, f64::MAX / 4.0, opts);
            opts.control
                .report(done.fetch_add(1, Ordering::Relaxed) + 1, total);
            SectionOrbit {
                omega0: *w,
                gamma0: *g,
                points,
                stop,
            }
        })
        .collect();
    opts.control.check()?;
    Ok(PoincareSection {
        p_psi,
        energy,
        normal: n,
        orbits,
    })
}

/// Where a periodic orbit crosses the section over one period: the fixed points of the section's
/// map that the orbit is (one per upward crossing; at most [`SectionOptions::crossings`], whose
/// steps are also the budget of the period's integration).
pub fn orbit_crossings<M: Lagrangian + Sync>(
    model: &M,
    orbit: &PeriodicOrbit,
    opts: &SectionOptions,
) -> Result<Vec<[f64; 2]>, RouthError> {
    let n = opts.validate()?;
    super::flow::check_orbit(orbit)?;
    // The steps of one period are budgeted as those of `opts.crossings` crossings (an orbit of
    // period 1e300 ends on the budget instead of integrating for ever).
    let (points, _, stop) = crossings(
        model,
        &orbit.omega0,
        &orbit.gamma0,
        &n,
        opts.crossings.max(1),
        orbit.period,
        opts,
    );
    match stop {
        Some(why) => Err(RouthError::InvalidOption {
            what: "orbit",
            reason: format!("could not integrate the orbit over its period: {why}"),
        }),
        None => Ok(points),
    }
}
