//! Pseudo-arclength continuation of one branch of steady motions, with event detection and
//! location.
//!
//! The unknowns are `(γ, σ)`, `σ = s/L` with `L` the length of the range, so that steps mix
//! comparable quantities. The steps are those of the crate's one predictor–corrector
//! ([`crate::solve::path`], [`PathOptions::diagram`]): a step `h` along the unit tangent `τ` of the curve
//! `{F = 0}` (the null vector of the 2×3 Jacobian `[∂F/∂ξ | ∂F/∂σ]`), then Newton
//! ([`Ctx::correct`]) in the chart around the predicted point on `F = 0` and
//! `τ·(x − x_pred) = 0`. For a branch of circles
//! of steady motions (`isolated: false`) the Jacobian has rank one along the whole branch (the
//! circle direction `c`, the kernel of `K`, is a direction of solutions at fixed `s`); the
//! corrector then also keeps `c·ξ = 0` (it stays in the meridian plane) and solves in the least
//! squares sense, and the tangent is the null vector orthogonal to `c`.

use std::cell::Cell;

use nalgebra::{Matrix2x3, Matrix4, Vector2, Vector3, Vector4};

use super::equations::{chart_eval, member, relative_discriminant, restricted_eigen, ChartEval};
use super::{BranchSample, ContinuationOptions};
use crate::error::RouthError;
use crate::model::Routhian;
use crate::solve::locate::{locate, End};
use crate::solve::newton::{Linearised, Newton};
use crate::solve::path::row::LinearRow;
use crate::solve::path::{sphere_head, Corrected, Failure, Path, PathOptions, Point, Prediction};
use crate::solve::zero::{ZeroTest, DOUBLE_REL, EIGEN_REL};
use crate::sphere::local::Local;
use crate::sphere::{tangent_basis, NOISE};
use crate::stability::{classify_with, ClassifyOptions, Stability};
use crate::steady::record;

/// Evaluations of `F` by the corrector before it gives up ([`Newton::continuation`] takes one
/// step fewer).
pub(crate) const CORRECTOR_MAX_ITER: usize = 16;

/// Re-solves of the event locator on one step before it returns the better end so far.
const LOCATE_BUDGET: usize = 200;

/// The largest change of `s` on one step, relative to the local scale of the parameter
/// `max(1, |s|)` (the scale events are located in): a quarter. Steps sized for the range alone
/// (`max_step` of its length) are as long as 50 on [0, 1000], and two events 0.1 apart near
/// p = 1.7 fall in one step with a test function that is zero at its start (the double root of
/// `f₂` of a sleeping top at p = 0): no sign change shows them. With the default `max_step`
/// (5 % of the range) the bound never binds on a range of length 5 or less.
const STEP_S_REL: f64 = 0.25;

/// A converged point of a branch with its tangent and test functions.
#[derive(Debug, Clone)]
pub(crate) struct Node {
    pub gamma: Vector3<f64>,
    pub s: f64,
    /// Unit tangent in `(γ, σ)`, γ part (tangent to the sphere).
    pub tau_g: Vector3<f64>,
    /// σ part of the unit tangent.
    pub tau_s: f64,
    /// Eigenvalues of `K`, ascending, relative to [`Node::scale`].
    pub eig: [f64; 2],
    /// The tangential scale at the point itself ([`Local::scale`]; the branch's where it is not
    /// positive and finite), to which `eig` and the zero tests on `jac` are relative. Not the
    /// branch's scale (set at its first point): over a wide range that point can be a seed
    /// where the Routh function is 10⁵ times larger than at the events, and eigenvalues relative
    /// to it look zero long before they are.
    pub scale: f64,
    /// Relative discriminant of `f₂` in `λ²`.
    pub disc: f64,
    pub point: BranchSample,
    /// The 2×3 Jacobian `[∂F/∂ξ | ∂F/∂σ]` at the point (chart at the point itself).
    pub jac: Matrix2x3<f64>,
}

impl Node {
    pub fn verdict(&self) -> Stability {
        self.point.report.verdict
    }
    /// Degree of instability 2 with no zero eigenvalue: where gyroscopic stabilisation is decided
    /// by `f₂`.
    pub fn degree_two(&self) -> bool {
        self.point.report.degree_of_instability == 2 && self.verdict() != Stability::Degenerate
    }
    /// How many eigenvalues of `K` are zero: below [`EIGEN_REL`] relative to the tangential
    /// scale at the point (`eig` is already divided by it; docs/method.md §5).
    pub fn eig_zeros(&self) -> usize {
        ZeroTest::relative(EIGEN_REL, 1.0).count(&self.eig)
    }
    pub fn dot_tangent(&self, g: &Vector3<f64>, s: f64) -> f64 {
        self.tau_g.dot(g) + self.tau_s * s
    }
    /// The point `(γ, σ = s/len)` on the path of the branch.
    pub fn on_path(&self, len: f64) -> Vector4<f64> {
        Vector4::new(self.gamma.x, self.gamma.y, self.gamma.z, self.s / len)
    }
    /// The unit tangent `(τ_γ, τ_σ)`.
    pub fn tangent(&self) -> Vector4<f64> {
        Vector4::new(self.tau_g.x, self.tau_g.y, self.tau_g.z, self.tau_s)
    }
}

/// A corrected point of a branch on its path, with `(γ, s)`.
pub(crate) type BranchCorrected = Corrected<4, (Vector3<f64>, f64)>;

/// The continuation context of one family over one range.
pub(crate) struct Ctx<'a, M, F> {
    pub family: &'a F,
    pub len: f64,
    pub opts: &'a ContinuationOptions,
    /// Residual scale of the branch (set from its first point).
    pub scale: f64,
    pub isolated: bool,
    /// The smallest relative residual `|F|/scale` that the last failed correction reached (NaN
    /// when it was rejected for another reason: a jump to another branch, a non-finite step):
    /// reported when a branch cannot be continued.
    pub failed_residual: Cell<f64>,
    pub _model: std::marker::PhantomData<fn() -> M>,
}

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Ctx<'a, M, F> {
    pub fn new(family: &'a F, range: (f64, f64), opts: &'a ContinuationOptions) -> Self {
        Ctx {
            family,
            len: range.1 - range.0,
            opts,
            scale: 1.0,
            isolated: true,
            failed_residual: Cell::new(f64::NAN),
            _model: std::marker::PhantomData,
        }
    }

    fn ds(&self) -> f64 {
        1e-6 * self.len
    }

    /// The kernel direction of `K` (the circle direction) at γ, in ℝ³.
    fn circle_direction(&self, gamma: &Vector3<f64>, s: f64) -> Result<Vector3<f64>, RouthError> {
        let (m, p) = member(self.family, s)?;
        let l = Local::at(&m, gamma, p).map_err(|e| super::equations::at(s, e))?;
        Ok(restricted_eigen(&l).1)
    }

    /// Newton's method from `(gamma_p, sigma_p)` on `F = 0` plus `row` (plus `c·ξ = 0` for a
    /// branch of circles), the row `n_γ·(γ − γ_p) + n_σ(σ − σ_p) = c` in `(γ, σ)` relative to
    /// the predicted point. `Ok(None)` when it does not converge, with the smallest residual
    /// reached in [`Ctx::failed_residual`].
    pub fn correct(
        &self,
        gamma_p: &Vector3<f64>,
        sigma_p: f64,
        row: &LinearRow<4>,
        circle: Option<Vector3<f64>>,
    ) -> Result<Option<(Vector3<f64>, f64, usize)>, RouthError> {
        let basis = tangent_basis(gamma_p);
        let circle = match (self.isolated, circle) {
            (true, _) => None,
            (false, Some(c)) => Some(basis.transpose() * c),
            (false, None) => {
                Some(basis.transpose() * self.circle_direction(gamma_p, sigma_p * self.len)?)
            }
        };
        let a_g: Vector3<f64> = row.normal.fixed_rows::<3>(0).into_owned();
        let a_xi = basis.transpose() * a_g;
        // The row is linear in (ξ, σ) around the predicted point; the unknowns are
        // w = (ξ, σ − σ_p).
        let c = circle.unwrap_or_default();
        let rows = [
            LinearRow::new(Vector4::new(a_xi.x, a_xi.y, row.normal[3], 0.0), row.rhs),
            LinearRow::new(Vector4::new(c.x, c.y, 0.0, 0.0), 0.0),
        ];
        let rows = &rows[..1 + usize::from(circle.is_some())];
        // F and its Jacobian relative to the residual scale; the round-off floor of `F` is that
        // of a difference of terms of the size of `|∇U_r|` (radial part included: a constant
        // `k|γ|²` on the sphere adds `2kγ` to it).
        let eval = |w: &Vector4<f64>| -> Result<Option<(ChartEval, Linearised)>, RouthError> {
            let xi = Vector2::new(w[0], w[1]);
            let sigma = sigma_p + w[2];
            // The chart around the predicted point is trusted within 0.5 rad.
            if xi.norm() > 0.5 || !sigma.is_finite() {
                return Ok(None);
            }
            let e = chart_eval(
                self.family,
                gamma_p,
                &basis,
                &xi,
                sigma * self.len,
                self.ds(),
            )?;
            let sc = self.scale.max(e.local.scale()).max(f64::MIN_POSITIVE);
            let mut jac = Matrix4::zeros();
            for i in 0..2 {
                jac[(i, 0)] = e.jac[(i, 0)] / sc;
                jac[(i, 1)] = e.jac[(i, 1)] / sc;
                jac[(i, 2)] = e.jac[(i, 2)] * self.len / sc;
            }
            let f = Vector4::new(e.f.x / sc, e.f.y / sc, 0.0, 0.0);
            let l = Linearised::new(f, jac, NOISE * e.local.grad().norm() / sc);
            Ok(Some((e, l)))
        };
        let failed = |best: f64| {
            self.failed_residual.set(best);
            Ok(None)
        };
        let Some(start) = eval(&Vector4::zeros())? else {
            return failed(f64::NAN);
        };
        let out = Newton::continuation(self.opts.newton_tol).solve(
            Vector4::zeros(),
            rows,
            start,
            |p| p.1,
            |_, w, _| eval(w),
            |_| false,
        )?;
        match out {
            Ok(s) => Ok(Some((
                s.point.0.gamma,
                (sigma_p + s.w[2]) * self.len,
                s.iterations,
            ))),
            Err(stop) => failed(stop.best_residual),
        }
    }

    /// The node at a converged `(gamma, s)`: tangent oriented along `prev` (if any), test
    /// functions and the classification.
    pub fn node(
        &self,
        gamma: &Vector3<f64>,
        s: f64,
        prev: Option<(&Vector3<f64>, f64)>,
    ) -> Result<Option<Node>, RouthError> {
        let basis = tangent_basis(gamma);
        let e = chart_eval(self.family, gamma, &basis, &Vector2::zeros(), s, self.ds())?;
        let mut jac = e.jac;
        jac.column_mut(2).scale_mut(self.len);
        let r1 = Vector3::new(jac[(0, 0)], jac[(0, 1)], jac[(0, 2)]);
        let r2 = Vector3::new(jac[(1, 0)], jac[(1, 1)], jac[(1, 2)]);
        let (eig, kernel) = restricted_eigen(&e.local);
        let mut t = if self.isolated {
            r1.cross(&r2)
        } else {
            // The circle direction: across the previous tangent (robust at folds, where both
            // eigenvalues of K vanish), else the kernel of K.
            let c3 = prev
                .and_then(|(g, _)| meridian_normal(gamma, g))
                .unwrap_or(kernel);
            let c = basis.transpose() * c3;
            let r = if r1.norm() >= r2.norm() { r1 } else { r2 };
            r.cross(&Vector3::new(c.x, c.y, 0.0))
        };
        let big = if self.isolated {
            r1.norm() * r2.norm()
        } else {
            r1.norm().max(r2.norm())
        };
        if t.norm().is_nan() || t.norm() <= 1e-12 * big {
            // Singular: keep the previous direction if there is one.
            match prev {
                Some((g, ts)) => {
                    let tp = basis.transpose() * g;
                    t = Vector3::new(tp.x, tp.y, ts);
                }
                None => return Ok(None),
            }
        }
        let t = t.normalize();
        let mut tau_g = basis * Vector2::new(t.x, t.y);
        let mut tau_s = t.z;
        if let Some((g, ts)) = prev {
            if tau_g.dot(g) + tau_s * ts < 0.0 {
                tau_g = -tau_g;
                tau_s = -tau_s;
            }
        } else if tau_s < 0.0 {
            tau_g = -tau_g;
            tau_s = -tau_s;
        }
        let (m, p) = member(self.family, s)?;
        let at = |e| super::equations::at(s, e);
        let steady = record(&m, gamma, p, self.isolated).map_err(at)?;
        // The corrector has solved (33) to `newton_tol` relative to the size of the derivatives.
        // Next to an event `K` nearly vanishes, and the distance estimate `|K⁻¹g|` with which
        // `classify` checks (33) grows beyond its `steady_tol` although the point is as
        // converged as any other: classify it on the corrector's word.
        let report = match classify_with(&m, &steady, &self.opts.classify) {
            Err(RouthError::NotASteadyMotion { .. }) => {
                let relaxed = ClassifyOptions {
                    steady_tol: 0.5,
                    ..self.opts.classify.clone()
                };
                classify_with(&m, &steady, &relaxed).map_err(at)?
            }
            r => r.map_err(at)?,
        };
        let disc = relative_discriminant(&m, gamma, p).map_err(at)?;
        let own = e.local.scale();
        let sc = if own > 0.0 && own.is_finite() {
            own
        } else {
            self.scale.max(f64::MIN_POSITIVE)
        };
        Ok(Some(Node {
            gamma: *gamma,
            s,
            tau_g,
            tau_s,
            eig: [eig[0] / sc, eig[1] / sc],
            scale: sc,
            disc,
            point: BranchSample { s, steady, report },
            jac,
        }))
    }

    /// The predictor–corrector of the branches ([`PathOptions::diagram`], γ retracted to the
    /// sphere) with at most `budget` attempts, starting with `initial_step`.
    pub fn path(&self, budget: usize) -> Path<4> {
        let o = self.opts;
        Path::new(PathOptions::diagram(o.min_step, o.max_step), o.initial_step)
            .with_retraction(sphere_head)
            .with_budget(budget)
    }

    /// The corrector of a step from `a`: [`Ctx::correct`] on `F = 0` and the row of the path
    /// through the prediction (plus `c·ξ = 0` on a branch of circles); the value is `(γ, s)`.
    pub fn corrector<'b>(
        &'b self,
        a: &'b Node,
    ) -> impl FnMut(&Prediction<4>) -> Result<Option<BranchCorrected>, RouthError> + 'b {
        move |p| {
            let g_p = p.point.fixed_rows::<3>(0).into_owned();
            // The path's row through the prediction, relative to it: `n·(w − w_pred) = 0`.
            let n = p.row.map_or_else(Vector4::zeros, |r| r.normal);
            let row = LinearRow::new(n, 0.0);
            let circle = meridian_normal(&g_p, &a.tau_g);
            Ok(self
                .correct(&g_p, p.point[3], &row, circle)?
                .map(|(g, s, it)| Corrected {
                    point: Vector4::new(g.x, g.y, g.z, s / self.len),
                    iterations: it,
                    value: (g, s),
                }))
        }
    }

    /// The completion of a corrected point after a step from `a`: its [`Node`] (tangent oriented
    /// along `a`'s, test functions, classification).
    pub fn completer<'b>(
        &'b self,
        a: &'b Node,
    ) -> impl FnMut(BranchCorrected) -> Result<Option<Point<4, Node>>, RouthError> + 'b {
        move |c| {
            let (g, s) = c.value;
            let node = self.node(&g, s, Some((&a.tau_g, a.tau_s)))?;
            Ok(node.map(|n| Point {
                point: c.point,
                tangent: Some(n.tangent()),
                iterations: c.iterations,
                value: n,
            }))
        }
    }

    /// Records why a step failed: a corrector that jumped to another branch leaves no residual
    /// to report.
    pub fn failed(&self, f: Failure) {
        if f == Failure::Moved {
            self.failed_residual.set(f64::NAN);
        }
    }

    /// The point at arclength `h` from `a` along its tangent: one attempt of [`Ctx::path`] (a
    /// corrector that moves further than `h/2` from the prediction jumped to another branch).
    pub fn advance(&self, a: &Node, h: f64) -> Result<Option<Node>, RouthError> {
        let w = a.on_path(self.len);
        match self
            .path(usize::MAX)
            .attempt(&w, &a.tangent(), h, false, &mut self.corrector(a))?
        {
            Ok(c) => Ok(self.completer(a)(c)?.map(|p| p.value)),
            Err(f) => {
                self.failed(f);
                Ok(None)
            }
        }
    }

    /// The point of the branch at exactly `s = target`, from `a` towards `b`.
    pub fn at_parameter(
        &self,
        a: &Node,
        b: &Node,
        target: f64,
    ) -> Result<Option<Node>, RouthError> {
        let t = ((target - a.s) / (b.s - a.s)).clamp(0.0, 1.0);
        let g_p = (a.gamma + t * (b.gamma - a.gamma)).normalize();
        let row = LinearRow::fixed(3, 0.0);
        let circle = meridian_normal(&g_p, &a.tau_g);
        let Some((g, s, _)) = self.correct(&g_p, target / self.len, &row, circle)? else {
            return Ok(None);
        };
        self.node(&g, s, Some((&a.tau_g, a.tau_s)))
    }

    /// Locates the zero of `phi` on the step from `a` (arclength 0) to `b` (arclength `h`) with
    /// the crate's event locator ([`crate::solve::locate`]), to `|Δs| ≤ event_tol·max(1, |s|)` (and the
    /// arclength to `1e−6·h`: at a fold `s` is stationary). Returns the node at the zero.
    ///
    /// The points re-solved on the step are corrected relative to the tangential scale at the
    /// event ([`Local::scale`] at `a`), not the branch's (set at its first point, possibly at the
    /// far end of a wide range where the Routh function is a thousandfold larger): at a fold an
    /// error `r` in the residual moves the point by `r/|∂F/∂s|` in `s`, so a residual relative
    /// to a larger scale places the event further off. The test functions of every node are
    /// relative to its own scale ([`Node::scale`]) already.
    pub fn locate(
        &self,
        a: &Node,
        b: &Node,
        h: f64,
        phi: &dyn Fn(&Node) -> f64,
    ) -> Result<Node, RouthError> {
        let local = Ctx {
            family: self.family,
            len: self.len,
            opts: self.opts,
            scale: self.own_scale(a)?,
            isolated: self.isolated,
            failed_residual: Cell::new(f64::NAN),
            _model: std::marker::PhantomData,
        };
        let lo = End::new(0.0, phi(a), a.clone());
        let hi = End::new(h, phi(b), b.clone());
        let found = locate(
            lo,
            hi,
            LOCATE_BUDGET,
            |t, _, _| Ok::<_, RouthError>(local.advance(a, t)?.map(|n| (phi(&n), n))),
            |lo, hi| {
                let tol = self.opts.event_tol * 1f64.max(lo.point.s.abs());
                (hi.point.s - lo.point.s).abs() <= tol && (hi.at - lo.at) <= 1e-6 * h.max(1e-12)
            },
        )?;
        Ok(found.best.point)
    }

    /// The tangential scale at `n` ([`Local::scale`]), or the branch's where it is not positive
    /// and finite.
    fn own_scale(&self, n: &Node) -> Result<f64, RouthError> {
        let (m, p) = member(self.family, n.s)?;
        let l = Local::at(&m, &n.gamma, p).map_err(|e| super::equations::at(n.s, e))?;
        let sc = l.scale();
        Ok(if sc > 0.0 && sc.is_finite() {
            sc
        } else {
            self.scale.max(f64::MIN_POSITIVE)
        })
    }

    /// The longest step from `a` (an arclength in `(γ, σ)`): the one along its tangent whose
    /// change of `s` is [`STEP_S_REL`]` · max(1, |s|)`; unbounded where the branch does not
    /// move in `s`.
    pub fn longest_step(&self, a: &Node) -> f64 {
        let ds = STEP_S_REL * 1f64.max(a.s.abs());
        // ds/dh along the tangent: σ = s/len moves by τ_σ per unit of arclength.
        let rate = a.tau_s.abs() * self.len;
        if rate > 0.0 && rate.is_finite() {
            ds * rate.recip()
        } else {
            f64::INFINITY
        }
    }

    /// Whether the Jacobian `[∂F/∂ξ | ∂F/∂σ]` at `n` has rank below 2 (a branch point rather
    /// than a fold).
    pub fn is_branch_point(&self, n: &Node) -> bool {
        if !self.isolated {
            // Along a branch of circles the Jacobian always has the circle direction in its
            // kernel; the branch meets another one only where it vanishes altogether (the
            // circle shrinks to its axis), relative to the scale at the point.
            return n.jac.norm() <= 1e-6 * n.scale;
        }
        let sv = n.jac.svd(false, false).singular_values;
        let (big, small) = (sv.max(), sv.min());
        small.is_nan()
            || ZeroTest::relative(1e-6, big).is_zero(small)
            || ZeroTest::relative(DOUBLE_REL, 1.0).count(&n.eig) == 2
    }
}

/// The unit normal `γ × τ` of the meridian plane spanned by γ and the tangent direction `tau`
/// (the direction along a circle of steady motions), if `tau` has a tangential part.
pub(crate) fn meridian_normal(gamma: &Vector3<f64>, tau: &Vector3<f64>) -> Option<Vector3<f64>> {
    let g = gamma.normalize();
    let n = g.cross(tau);
    (n.norm() > 1e-6 * tau.norm().max(1e-300)).then(|| n.normalize())
}

/// Which test function changed sign on a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Change {
    /// An eigenvalue of `K` (index 0 or 1), or the trace of `K` on a branch of circles (2).
    Eigen(usize),
    /// The discriminant of `f₂` with degree of instability 2 on both sides.
    Discriminant,
    /// The σ component of the tangent (a turning point in `s`).
    Turn,
}

/// The test functions that change sign between `a` and `b`.
pub(crate) fn changes(a: &Node, b: &Node, isolated: bool) -> Vec<Change> {
    let mut out = Vec::new();
    if isolated {
        for i in 0..2 {
            if a.eig[i] * b.eig[i] < 0.0 {
                out.push(Change::Eigen(i));
            }
        }
        // Both eigenvalues through zero together: a double zero when they are equal on both
        // sides (a symmetric body), else two events in one step, which the caller separates.
        let equal =
            |n: &Node| (n.eig[1] - n.eig[0]).abs() <= 1e-9 * n.eig[0].abs().max(n.eig[1].abs());
        if out.len() == 2 && equal(a) && equal(b) {
            out.truncate(1);
        }
    } else if (a.eig[0] + a.eig[1]) * (b.eig[0] + b.eig[1]) < 0.0 {
        out.push(Change::Eigen(2));
    }
    // With degree 2 on one side only, an eigenvalue event shares the step: the caller shortens
    // the step until the two are apart.
    if (a.degree_two() || b.degree_two()) && a.disc * b.disc < 0.0 {
        out.push(Change::Discriminant);
    }
    if a.tau_s * b.tau_s < 0.0 {
        out.push(Change::Turn);
    }
    out
}

/// Whether a test function that is not zero at `a` is exactly zero at `b` (an eigenvalue of
/// `K`, their sum on a branch of circles, the discriminant of `f₂`, the σ component of the
/// tangent): a node on an event hides it from the sign tests of [`changes`] (`a·b < 0`) on both
/// of its steps, and its verdict is that of the event. A symmetric body's closed forms land
/// exactly on such nodes: the secular bound p = 2.5 of the Lagrange top (1, 1.25, 1) after steps
/// of 1 and 1.5. (A function zero all along, as the discriminant of a spherical body's double
/// roots, is no event.)
pub(crate) fn lands_on_a_zero(a: &Node, b: &Node, isolated: bool) -> bool {
    let tests = |n: &Node| {
        let eig = if isolated {
            n.eig
        } else {
            [n.eig[0] + n.eig[1]; 2]
        };
        [eig[0], eig[1], n.disc, n.tau_s]
    };
    tests(a)
        .iter()
        .zip(tests(b))
        .any(|(x, y)| *x != 0.0 && y == 0.0)
}

/// The value of the test function of `change` at `n`.
pub(crate) fn test_value(change: Change, n: &Node) -> f64 {
    match change {
        Change::Eigen(2) => n.eig[0] + n.eig[1],
        Change::Eigen(i) => n.eig[i],
        Change::Discriminant => n.disc,
        Change::Turn => n.tau_s,
    }
}
