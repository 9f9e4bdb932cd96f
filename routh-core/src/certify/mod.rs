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

mod interval;
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

/// A face of the cube: `x = σe_k + u e_a + v e_b`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Face {
    k: usize,
    sigma: f64,
}

impl Face {
    fn all() -> [Face; 6] {
        std::array::from_fn(|i| Face {
            k: i / 2,
            sigma: if i % 2 == 0 { 1.0 } else { -1.0 },
        })
    }
    /// The two free axes `(a, b)`.
    fn ab(self) -> (usize, usize) {
        ((self.k + 1) % 3, (self.k + 2) % 3)
    }
    /// `γ(u, v)` and `1/r`, as intervals.
    fn gamma(self, u: Interval, v: Interval) -> ([Interval; 3], Interval) {
        let one = Interval::point(1.0);
        let r_inv = (one + u.sqr() + v.sqr()).sqrt().recip();
        let (a, b) = self.ab();
        let mut g = [Interval::point(0.0); 3];
        g[self.k] = Interval::point(self.sigma) * r_inv;
        g[a] = u * r_inv;
        g[b] = v * r_inv;
        (g, r_inv)
    }
    /// The chart coordinates `(u, v) = σ(γ_a, γ_b)/γ_k` of a box of γ (`None` if `γ_k` may vanish
    /// or has the other sign).
    fn coordinates(self, g: &[Interval; 3]) -> Option<(Interval, Interval)> {
        let gk = Interval::point(self.sigma) * g[self.k];
        if gk.lo <= 0.0 {
            return None;
        }
        let (a, b) = self.ab();
        Some((g[a] / gk, g[b] / gk))
    }
}

/// A box of a chart.
#[derive(Debug, Clone, Copy)]
struct ChartBox {
    face: Face,
    u: Interval,
    v: Interval,
}

/// `F` and (optionally) `F'` over a chart box.
struct Field {
    f: [Interval; 2],
    df: Option<[[Interval; 2]; 2]>,
}

fn dot(a: &[Interval; 3], b: &[Interval; 3]) -> Interval {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The evaluator: the tape, `p_ψ` and a scratch buffer.
struct Evaluator<'a> {
    tape: &'a RouthTape,
    p: Interval,
    scratch: Vec<Interval>,
}

impl Evaluator<'_> {
    /// `F = (t_a, t_b)` over the box, and `F'` if `jacobian`.
    fn field(&mut self, b: &ChartBox, jacobian: bool) -> Field {
        let (gamma, r_inv) = b.face.gamma(b.u, b.v);
        let (g, h) = self.tape.eval(gamma, self.p, &mut self.scratch);
        let gg = dot(&g, &gamma);
        let (ia, ib) = b.face.ab();
        let t = |i: usize| g[i] - gg * gamma[i];
        let f = [t(ia), t(ib)];
        if !jacobian {
            return Field { f, df: None };
        }
        // dt/dγ = H − γ(Hγ + g)ᵀ − (g·γ)I.
        let w: [Interval; 3] = std::array::from_fn(|j| dot(&h[j], &gamma) + g[j]);
        let dt = |i: usize, j: usize| {
            let x = h[i][j] - gamma[i] * w[j];
            if i == j {
                x - gg
            } else {
                x
            }
        };
        // dγ/du = (e_a − γγ_a)/r, dγ/dv = (e_b − γγ_b)/r.
        let dgamma = |c: usize| -> [Interval; 3] {
            std::array::from_fn(|j| {
                let e = if j == c {
                    Interval::point(1.0)
                } else {
                    Interval::point(0.0)
                };
                (e - gamma[j] * gamma[c]) * r_inv
            })
        };
        let (du, dv) = (dgamma(ia), dgamma(ib));
        let row = |i: usize| -> [Interval; 2] {
            let d: [Interval; 3] = std::array::from_fn(|j| dt(i, j));
            [dot(&d, &du), dot(&d, &dv)]
        };
        Field {
            f,
            df: Some([row(ia), row(ib)]),
        }
    }
}

/// What one Krawczyk step found on a box.
enum Verdict {
    /// No steady motion in the box.
    Excluded,
    /// Exactly one, inside the given sub-box.
    Unique(Interval, Interval),
    /// Not decided at this size; the Krawczyk contraction estimate `‖I − Y F'(X)‖∞` (∞ when it
    /// could not be formed). It halves with the box near a regular zero and stays large near a
    /// circle of zeros, where `F'` is singular.
    Split(f64),
}

fn excludes_zero(x: Interval) -> bool {
    x.lo > 0.0 || x.hi < 0.0
}

/// `x` widened by 5% of its width on each side.
fn inflate(x: Interval) -> Interval {
    let e = 0.05 * x.width();
    Interval::new((x.lo - e).next_down(), (x.hi + e).next_up())
}

/// One test of a box: exclusion by the natural and mean-value enclosures, then Krawczyk. The
/// tests run on the box widened by 5%: a steady motion on the edge of a box (the centre of a
/// face, on the first split, is one) can never map into the interior of that box, but it does
/// into the interior of the wider one. A verdict on the wider box holds for the box.
fn test_box(ev: &mut Evaluator<'_>, b: &ChartBox) -> Verdict {
    let b = &ChartBox {
        face: b.face,
        u: inflate(b.u),
        v: inflate(b.v),
    };
    let field = ev.field(b, true);
    if field.f.iter().any(|&x| excludes_zero(x)) {
        return Verdict::Excluded;
    }
    let Some(df) = field.df else {
        return Verdict::Split(f64::INFINITY);
    };
    if df.iter().flatten().any(|x| !x.is_bounded()) {
        return Verdict::Split(f64::INFINITY);
    }
    let (mu, mv) = (b.u.mid(), b.v.mid());
    let centre = ChartBox {
        face: b.face,
        u: Interval::point(mu),
        v: Interval::point(mv),
    };
    let fm = ev.field(&centre, false).f;
    if fm.iter().any(|x| !x.is_bounded()) {
        return Verdict::Split(f64::INFINITY);
    }
    let d = [b.u - centre.u, b.v - centre.v];
    // Mean-value form: F(X) ⊆ F(m) + F'(X)(X − m).
    for i in 0..2 {
        let mv_form = fm[i] + df[i][0] * d[0] + df[i][1] * d[1];
        if excludes_zero(mv_form) {
            return Verdict::Excluded;
        }
    }
    // Y ≈ F'(m)⁻¹ from the midpoints (any real matrix keeps Krawczyk valid).
    let m = [
        [df[0][0].mid(), df[0][1].mid()],
        [df[1][0].mid(), df[1][1].mid()],
    ];
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    let scale = m.iter().flatten().fold(0.0f64, |s, x| s.max(x.abs()));
    if !det.is_finite() || det.abs() <= 1e-14 * scale * scale {
        return Verdict::Split(f64::INFINITY);
    }
    let y = [
        [m[1][1] / det, -m[0][1] / det],
        [-m[1][0] / det, m[0][0] / det],
    ];
    let yp = |i: usize, j: usize| Interval::point(y[i][j]);
    let mut k = [centre.u, centre.v];
    let mut q = 0.0f64;
    for (i, ki) in k.iter_mut().enumerate() {
        let yf = yp(i, 0) * fm[0] + yp(i, 1) * fm[1];
        let mut acc = *ki - yf;
        let mut row = 0.0;
        for j in 0..2 {
            // (I − Y F'(X))_ij
            let ydf = yp(i, 0) * df[0][j] + yp(i, 1) * df[1][j];
            let e = if i == j {
                Interval::point(1.0)
            } else {
                Interval::point(0.0)
            };
            let c = e - ydf;
            row += c.mag();
            acc = acc + c * d[j];
        }
        q = q.max(row);
        *ki = acc;
    }
    let x = [b.u, b.v];
    if k[0].intersect(x[0]).is_none() || k[1].intersect(x[1]).is_none() {
        return Verdict::Excluded;
    }
    if k[0].interior_of(x[0]) && k[1].interior_of(x[1]) {
        return Verdict::Unique(k[0], k[1]);
    }
    Verdict::Split(q)
}

/// A certified zero: its chart, the box where it is unique, and a tight enclosure in γ.
struct Found {
    face: Face,
    unique: (Interval, Interval),
    gamma: [Interval; 3],
}

fn overlaps(a: &[Interval; 3], b: &[Interval; 3]) -> bool {
    (0..3).all(|i| a[i].intersect(b[i]).is_some())
}

/// Whether the motion enclosed by `inner` is the one unique in `outer`'s box.
fn same_motion(inner: &Found, outer: &Found) -> bool {
    match outer.face.coordinates(&inner.gamma) {
        Some((u, v)) => u.subset_of(outer.unique.0) && v.subset_of(outer.unique.1),
        None => false,
    }
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
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

    // The same motion certified in two boxes (a box edge or a chart edge through it).
    let mut parent: Vec<usize> = (0..found.len()).collect();
    let mut ambiguous_pairs = 0;
    for i in 0..found.len() {
        for j in i + 1..found.len() {
            if !overlaps(&found[i].gamma, &found[j].gamma) {
                continue;
            }
            if same_motion(&found[j], &found[i]) || same_motion(&found[i], &found[j]) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[b] = a;
            } else {
                ambiguous_pairs += 1;
            }
        }
    }
    let mut motions = Vec::new();
    for (i, f) in found.iter().enumerate() {
        if find(&mut parent, i) != i {
            continue;
        }
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

/// Widest enclosure (per component of γ) of a certified motion; a motion that cannot be
/// enclosed tighter is reported undecided.
const MAX_ENCLOSURE: f64 = 1e-10;

/// A tight enclosure of the zero certified unique in `unique` (found in `k`): Newton's method
/// in floating point from the centre of `k`, then Krawczyk on boxes of half-width `1e−14` to
/// `1e−11` around the Newton point; the first one certified (it lies in `unique`, so it holds
/// the same zero) is the enclosure. `None` when Newton leaves `unique` or no small box is
/// certified.
fn tighten(
    ev: &mut Evaluator<'_>,
    face: Face,
    unique: (Interval, Interval),
    k: (Interval, Interval),
) -> Option<(Interval, Interval)> {
    let (mut u, mut v) = (k.0.mid(), k.1.mid());
    for _ in 0..40 {
        let at = ChartBox {
            face,
            u: Interval::point(u),
            v: Interval::point(v),
        };
        let field = ev.field(&at, true);
        let df = field.df?;
        let (f0, f1) = (field.f[0].mid(), field.f[1].mid());
        let m = [
            [df[0][0].mid(), df[0][1].mid()],
            [df[1][0].mid(), df[1][1].mid()],
        ];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        if !(det.is_finite() && det != 0.0) {
            return None;
        }
        let du = (m[1][1] * f0 - m[0][1] * f1) / det;
        let dv = (-m[1][0] * f0 + m[0][0] * f1) / det;
        if !(du.is_finite() && dv.is_finite()) {
            return None;
        }
        u -= du;
        v -= dv;
        if !(unique.0.lo <= u && u <= unique.0.hi && unique.1.lo <= v && v <= unique.1.hi) {
            return None;
        }
        if du.abs().max(dv.abs()) <= 1e-16 * (1.0 + u.abs().max(v.abs())) {
            break;
        }
    }
    for r in [1e-14, 1e-13, 1e-12, 1e-11] {
        let small = ChartBox {
            face,
            u: Interval::new(u - r, u + r),
            v: Interval::new(v - r, v + r),
        };
        // The box the test really uses is 5% wider; it must lie in the uniqueness box.
        let wide = (inflate(small.u), inflate(small.v));
        if !(wide.0.interior_of(unique.0) && wide.1.interior_of(unique.1)) {
            return None;
        }
        if let Verdict::Unique(ku, kv) = test_box(ev, &small) {
            if let (Some(a), Some(b)) = (ku.intersect(wide.0), kv.intersect(wide.1)) {
                return Some((a, b));
            }
        }
    }
    None
}

/// Shrinks the enclosure of a certified zero by Krawczyk steps (every zero of the box stays in
/// `K ∩ X`).
fn refine(
    ev: &mut Evaluator<'_>,
    face: Face,
    mut x: (Interval, Interval),
    iterations: usize,
) -> (Interval, Interval) {
    for _ in 0..iterations {
        let b = ChartBox {
            face,
            u: x.0,
            v: x.1,
        };
        let before = x.0.width() + x.1.width();
        match test_box(ev, &b) {
            Verdict::Unique(ku, kv) => match (ku.intersect(x.0), kv.intersect(x.1)) {
                (Some(u), Some(v)) => x = (u, v),
                _ => break,
            },
            _ => break,
        }
        if x.0.width() + x.1.width() >= 0.5 * before {
            break;
        }
    }
    x
}

/// Groups undecided chart boxes into connected regions of the sphere (boxes whose γ-hulls meet).
fn regions(boxes: &[ChartBox]) -> Vec<UndecidedRegion> {
    let hulls: Vec<[Interval; 3]> = boxes.iter().map(|b| b.face.gamma(b.u, b.v).0).collect();
    let mut parent: Vec<usize> = (0..hulls.len()).collect();
    // Sweep along γ₁: only boxes whose γ₁-ranges overlap can meet.
    let mut order: Vec<usize> = (0..hulls.len()).collect();
    order.sort_by(|&a, &b| hulls[a][0].lo.total_cmp(&hulls[b][0].lo));
    for (pos, &i) in order.iter().enumerate() {
        for &j in &order[pos + 1..] {
            if hulls[j][0].lo > hulls[i][0].hi {
                break;
            }
            if overlaps(&hulls[i], &hulls[j]) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[b] = a;
            }
        }
    }
    let mut out: Vec<UndecidedRegion> = Vec::new();
    let mut index = vec![usize::MAX; hulls.len()];
    for (i, h) in hulls.iter().enumerate() {
        let r = find(&mut parent, i);
        if index[r] == usize::MAX {
            index[r] = out.len();
            out.push(UndecidedRegion { hull: *h, boxes: 0 });
        }
        let reg = &mut out[index[r]];
        reg.boxes += 1;
        for (acc, x) in reg.hull.iter_mut().zip(h) {
            *acc = acc.hull(*x);
        }
    }
    out
}
