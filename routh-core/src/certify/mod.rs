//! Certified completeness of the steady-motion search (docs/method.md §9): a proof, by interval
//! arithmetic, that the steady motions returned are all the critical points of the amended
//! potential on the sphere, each the only one in its enclosure — or the regions where the proof
//! could not be completed.
//!
//! The sphere is covered by the six faces of the cube, each a chart
//! `γ(u, v) = x/|x|`, `x = σe_k + u e_a + v e_b`, `|u|, |v| ≤ 1`. In a chart the steady motions
//! are the zeros of `F(u, v) = (t_a, t_b)`, the two free components of the tangential gradient
//! `t = ∂R/∂γ − (∂R/∂γ·γ)γ` of (33) (its third component follows from `t·γ = 0`, and `γ_k ≠ 0`
//! on the face). Each box of a chart is
//! - **excluded** when the interval enclosure of `F` over the box (natural or mean-value form)
//!   omits 0 in a component: no steady motion in the box;
//! - **certified** when the Krawczyk operator `K = m − Y F(m) + (I − Y F'(X))(X − m)` maps the box
//!   into its interior: exactly one steady motion in the box (and it lies in `K`);
//! - otherwise bisected, down to [`CertifyOptions::min_width`], below which it is **undecided**.
//!
//! Every zero lies in some leaf box, so when no box is undecided the certified ones hold all of
//! them. A motion near the edge of a chart or of a box may be certified twice; two enclosures
//! are proved to hold the same motion when one maps into the other's uniqueness box, and the
//! certificate is marked incomplete if two enclosures meet without that proof.
//!
//! A circle of steady motions (a symmetric body) has no isolated zeros: its boxes stay
//! undecided, and the circle is reported as an [`UndecidedRegion`], its tube. So is a
//! degenerate critical point (e.g. a quartic minimum), where `F'` is singular. The certificate
//! never claims a count it has not proved.
//!
//! The enclosures of `∂R/∂γ` and `∂²R/∂γ²` come from the derive's certification tape (the same
//! expression DAG as the generated f64 code, evaluated with [`Interval`]s), so a hand-written
//! model, which has no tape, cannot be certified.

mod chart;
mod interval;
mod krawczyk;
mod regions;
mod tape;

/// The interval arithmetic and the tape's scalar interface behind the certificate: public for
/// the tests that check them against exact arithmetic, not an API of routh.
#[doc(hidden)]
pub use interval::{Interval, LIBM_ULPS};
#[doc(hidden)]
pub use routh_tape::{Func, GradHess, TapeScalar};

/// `∂R/∂γ` and `∂²R/∂γ²` at `Ω = 0` of a derived model, with the model's parameter values bound:
/// what [`crate::Routhian::certification_tape`] returns (the typed tape of `routh-tape`).
#[doc(hidden)]
pub type RouthTape = routh_tape::CertificationTape;

use chart::{ChartBox, Evaluator, Face};
use krawczyk::{inflate, refine, test_box, tighten, Verdict, MAX_ENCLOSURE};
use regions::{distinct, regions, Found};

use crate::error::RouthError;
use crate::model::Routhian;
use crate::steady::SteadyMotion;
use crate::validate::check_finite;
use nalgebra::Vector3;
use std::time::{Duration, Instant};

/// The smallest [`CertifyOptions::min_width`] accepted: a box is split down to
/// `min_width·1e-6` near a regular zero, and the chart coordinates (up to 1, resolution
/// 2.2e-16) cannot split a box much narrower than 1e-15.
#[doc(hidden)]
pub const MIN_WIDTH: f64 = 1e-9;

/// Options of [`steady_motions_certified`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CertifyOptions {
    /// Boxes per side of each face of the cube at the start (default 4).
    pub initial_split: usize,
    /// Smallest side of a box in chart coordinates before it is left undecided (default 1e-3;
    /// each face has side 2; at least 1e-9: a smaller one is refused).
    pub min_width: f64,
    /// Budget of boxes examined in all; what is left when it runs out is undecided
    /// (default 400 000).
    pub max_boxes: usize,
    /// Krawczyk iterations that shrink a certified enclosure (default 30).
    pub refine_iterations: usize,
}

impl Default for CertifyOptions {
    fn default() -> Self {
        CertifyOptions {
            initial_split: 4,
            min_width: 1e-3,
            max_boxes: 400_000,
            refine_iterations: 30,
        }
    }
}

/// A steady motion proved to exist, alone in its enclosure.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct CertifiedMotion {
    /// A box of `R³` (an interval per component of γ) containing the steady motion's γ, at most
    /// `1e−10` wide in each component (a motion that cannot be enclosed that tightly is left
    /// undecided); no other steady motion lies in the chart box it was certified in. It is
    /// tightened by Newton's method in floating point and a Krawczyk test on a box of half-width
    /// `1e−14`…`1e−11` around the Newton point.
    pub enclosure: [Interval; 3],
    /// The steady motion at the centre of the enclosure (unit γ), with `isolated: true`: within
    /// `1e−10` of the motion, so [`classify`](crate::classify) accepts it.
    pub steady: SteadyMotion,
}

/// A region of the sphere where the certified search could neither exclude nor certify steady
/// motions: the tube around a circle of steady motions, a degenerate critical point, or what
/// the budget left.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct UndecidedRegion {
    /// A box of `R³` containing the region's points of the sphere.
    pub hull: [Interval; 3],
    /// Number of undecided chart boxes in the region.
    pub boxes: usize,
}

/// The result of [`steady_motions_certified`].
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Certificate {
    /// The cyclic momentum.
    pub p_psi: f64,
    /// The steady motions proved to exist, each once.
    pub motions: Vec<CertifiedMotion>,
    /// The regions left undecided (empty when [`Certificate::complete`]).
    pub undecided: Vec<UndecidedRegion>,
    /// Whether the proof is complete: every box of the sphere was excluded or certified and
    /// every pair of enclosures was proved distinct or identical, so `motions` are all the
    /// steady motions at `p_psi`.
    pub complete: bool,
    /// Pairs of certified enclosures that meet but could not be proved to hold the same motion
    /// (each makes the certificate incomplete; normally 0).
    pub ambiguous_pairs: usize,
    /// Chart boxes examined.
    pub boxes: usize,
    /// Chart boxes excluded (no steady motion).
    pub excluded: usize,
    /// Wall time of the proof.
    pub elapsed: Duration,
}

impl std::fmt::Display for Certificate {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.complete {
            write!(
                f,
                "certified: exactly {} steady motion(s) at p_ψ = {}",
                self.motions.len(),
                self.p_psi
            )?;
        } else {
            write!(
                f,
                "not certified: {} steady motion(s) proved at p_ψ = {}, {} region(s) undecided",
                self.motions.len(),
                self.p_psi,
                self.undecided.len()
            )?;
        }
        write!(
            f,
            " ({} boxes, {} excluded, {:.1} ms)",
            self.boxes,
            self.excluded,
            self.elapsed.as_secs_f64() * 1e3
        )
    }
}

/// Proves how many steady motions the model has at `p_psi` (the critical points of the amended
/// potential (34) on the sphere), by interval arithmetic over a cover of the sphere by charts
/// (see the [module documentation](self)). Returns the motions proved to exist, each once with
/// an enclosure, and the regions left undecided; [`Certificate::complete`] says whether the
/// motions are provably all of them.
///
/// The model must come from `#[derive(Lagrangian)]` (the proof evaluates the derive's
/// certification tape); a hand-written model gives [`RouthError::InvalidModel`].
///
/// (This example needs the derive, so it runs as a doctest of the `routh` crate, whose root
/// documentation has it too.)
///
/// ```ignore
/// use routh::{Lagrangian, Vector3};
/// use routh::certify::{steady_motions_certified, CertifyOptions};
///
/// /// A heavy asymmetric top (centre of mass on the third axis).
/// #[derive(Lagrangian)]
/// #[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
/// struct Top { inertia: Vector3<f64>, mgl: f64 }
///
/// let top = Top { inertia: Vector3::new(1.0, 2.0, 3.0), mgl: 1.0 };
/// let cert = steady_motions_certified(&top, 0.5, &CertifyOptions::default()).unwrap();
/// assert!(cert.complete);
/// println!("{cert}");
/// for m in &cert.motions {
///     println!("γ = {:.6?}", m.steady.gamma);
/// }
/// ```
///
/// Errors: a non-finite `p_psi`, invalid options, a model without a certification tape.
pub fn steady_motions_certified<M: Routhian>(
    model: &M,
    p_psi: f64,
    opts: &CertifyOptions,
) -> Result<Certificate, RouthError> {
    let start = Instant::now();
    check_finite("p_psi", &[p_psi])?;
    if opts.initial_split == 0 || opts.initial_split > 1024 {
        return Err(RouthError::InvalidOption {
            what: "CertifyOptions::initial_split",
            reason: format!("{} is not in 1..=1024", opts.initial_split),
        });
    }
    if !(opts.min_width >= MIN_WIDTH && opts.min_width < 2.0) {
        return Err(RouthError::InvalidOption {
            what: "CertifyOptions::min_width",
            reason: format!(
                "{:e} is not in [{MIN_WIDTH:e}, 2): a box is split down to min_width·1e-6 near a \
                 regular zero, and chart coordinates (up to 1) cannot resolve boxes narrower \
                 than about 1e-15",
                opts.min_width
            ),
        });
    }
    let tape = model
        .certification_tape()
        .ok_or_else(|| RouthError::InvalidModel {
            what: "certification tape",
            reason: "the model has no interval enclosure of its derivatives \
                     (only #[derive(Lagrangian)] models can be certified)"
                .into(),
        })?;
    let mut ev = Evaluator {
        tape: &tape,
        p: Interval::point(p_psi),
        scratch: Vec::with_capacity(tape.len()),
    };

    let n = opts.initial_split;
    let mut stack: Vec<ChartBox> = Vec::new();
    for face in Face::all() {
        for i in 0..n {
            for j in 0..n {
                let edge = |k: usize| -1.0 + 2.0 * k as f64 / n as f64;
                stack.push(ChartBox {
                    face,
                    u: Interval::new(edge(i), edge(i + 1)),
                    v: Interval::new(edge(j), edge(j + 1)),
                });
            }
        }
    }
    let (mut boxes, mut excluded) = (0usize, 0usize);
    let mut found: Vec<Found> = Vec::new();
    let mut undecided: Vec<ChartBox> = Vec::new();
    while let Some(b) = stack.pop() {
        if boxes >= opts.max_boxes {
            undecided.push(b);
            continue;
        }
        boxes += 1;
        match test_box(&mut ev, &b) {
            Verdict::Excluded => excluded += 1,
            Verdict::Unique(ku, kv) => {
                let unique = (inflate(b.u), inflate(b.v));
                let tight = match tighten(&mut ev, b.face, unique, (ku, kv)) {
                    Some(t) => t,
                    None => refine(&mut ev, b.face, (ku, kv), opts.refine_iterations),
                };
                let gamma = b.face.gamma(tight.0, tight.1).0;
                if gamma
                    .iter()
                    .any(|g| g.width().is_nan() || g.width() > MAX_ENCLOSURE)
                {
                    // Proved to exist, but not located to MAX_ENCLOSURE: its `steady` could not
                    // be trusted to be the motion; leave it undecided.
                    undecided.push(b);
                    continue;
                }
                found.push(Found {
                    face: b.face,
                    unique,
                    gamma,
                });
            }
            Verdict::Split(q) => {
                // Below `min_width` only boxes that look like a regular zero (a contraction
                // estimate that a few more halvings bring below 1) are split further.
                let w = b.u.width().max(b.v.width());
                // A box a few ulps wide cannot be split into two different boxes.
                if w <= 64.0 * f64::EPSILON
                    || (w <= opts.min_width && (q > 16.0 || w <= opts.min_width * 1e-6))
                {
                    undecided.push(b);
                } else if b.u.width() >= b.v.width() {
                    let (l, r) = b.u.bisect();
                    stack.push(ChartBox { u: l, ..b });
                    stack.push(ChartBox { u: r, ..b });
                } else {
                    let (l, r) = b.v.bisect();
                    stack.push(ChartBox { v: l, ..b });
                    stack.push(ChartBox { v: r, ..b });
                }
            }
        }
    }

    let (distinct, ambiguous_pairs) = distinct(&found);
    let mut motions = Vec::new();
    for f in distinct {
        let g = &f.gamma;
        let centre = Vector3::new(g[0].mid(), g[1].mid(), g[2].mid()).normalize();
        motions.push(CertifiedMotion {
            enclosure: *g,
            steady: SteadyMotion::at(model, centre, p_psi, true)?,
        });
    }
    let undecided = regions(&undecided);
    Ok(Certificate {
        p_psi,
        complete: undecided.is_empty() && ambiguous_pairs == 0,
        motions,
        undecided,
        ambiguous_pairs,
        boxes,
        excluded,
        elapsed: start.elapsed(),
    })
}
