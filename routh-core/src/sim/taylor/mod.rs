//! Taylor's method for the full equations (8) (docs/method.md §2c): the Taylor coefficients in
//! time of the solution, computed from the model's flow tape by the recurrences of automatic
//! differentiation ([`recur`]), with the order and the step of Jorba & Zou, "A software
//! package for the numerical integration of ODEs by means of high-order Taylor methods",
//! *Experimental Mathematics* 14 (2005), §3.2 — the scheme of heyoka.
//!
//! **The implicit ω.** The state is `(ω, γ)`, and (8) gives `ω̇` only through `J(γ)`. The
//! coefficients are taken instead from the momentum form of (8), with `m = ∂L/∂ω`:
//!
//! ```text
//! ṁ = m × ω + (∂L/∂γ) × γ,      γ̇ = γ × ω,
//! ```
//!
//! (differentiating `m(ω(t), γ(t))` gives back `J ω̇ + N γ̇`, the left side of (8) plus the term
//! `N(γ × ω)` it moves to the right). From the coefficients `0…k` of every node, the right sides
//! give `m_{k+1}` and `γ_{k+1}` directly (Cauchy products of series, divided by `k + 1`). Every
//! node's coefficient of order `k + 1` is affine in `ω_{k+1}`, with slope `∂m/∂ω = J` at the
//! step's start for `m`: so order `k + 1` is evaluated once with `ω_{k+1} = 0`, `ω_{k+1}` is
//! solved from `J₀ ω_{k+1} = m_{k+1} − m_{k+1}|_{ω_{k+1}=0}` (one Cholesky factor a step), and the
//! slope times `ω_{k+1}` is added to every node that reads ω. This is exact (no series of `J⁻¹`
//! is formed, nothing is iterated), and costs one evaluation of the recurrences a step.
//!
//! **Order and step** (Jorba & Zou §3.2). For each 3-vector block `x` of the state (ω; γ; the
//! attitude quaternion when integrated) with its absolute tolerance `a` (`rate_atol` for ω,
//! `atol` for the others) and `rtol`: when `rtol‖x₀‖∞ ≤ a` the block is controlled absolutely
//! (`ε = a`, scale 1), else relatively (`ε = rtol`, scale `‖x₀‖∞`). The order is
//! `p = ⌈−ln(ε)/2 + 1⌉` for the smallest `ε` (at most [`MAX_ORDER`]); the step is
//! `h = min ρ · e⁻² · e^{−0.7/(p−1)}` with `ρ = min((scale/‖x_{p−1}‖∞)^{1/(p−1)},
//! (scale/‖x_p‖∞)^{1/p})` over the blocks: the last two terms of the series are then about
//! `ε` (times the scale), and the factor `e^{−0.7/(p−1)}` is heyoka's safety factor. Steps are
//! never rejected.
//!
//! **Dense output.** The Taylor polynomial of the step is the solution inside it: output
//! times are evaluated on it by Horner's scheme, to the accuracy of the step's end.

pub(crate) mod recur;
#[cfg(test)]
mod tests;

use nalgebra::{Matrix3, Quaternion, Vector3};
use routh_tape::FlowTape;

use super::{Output, SimOptions, SimStats};
use crate::validate::{gamma_array, min_eigenvalue};
use crate::RouthError;
use recur::{Program, GAMMA, OMEGA};

/// The largest order used (the order asked by a tolerance below about 1e−25 is cut to it).
pub(crate) const MAX_ORDER: usize = 30;

/// The order of Jorba & Zou for the tolerance `eps`: `⌈−ln(ε)/2 + 1⌉`, between 2 and
/// [`MAX_ORDER`].
pub(crate) fn order_for(eps: f64) -> usize {
    let p = (-eps.ln() / 2.0 + 1.0).ceil();
    if p.is_nan() {
        MAX_ORDER
    } else {
        (p as usize).clamp(2, MAX_ORDER)
    }
}

/// The Taylor expansion of the flow of (8) about one state, on a compiled flow tape.
pub(crate) struct Expansion {
    prog: Program,
    /// Coefficients of the attitude quaternion (when integrated).
    q: Vec<Quaternion<f64>>,
    /// Coefficients of ψ (for the reduced equations) and of ψ̇ = (ω·γ − s)/|γ|².
    psi: Vec<f64>,
    psi_dot: Vec<f64>,
    /// The order of the last expansion.
    order: usize,
    /// The last `J` and its inverse.
    j_inv: Option<(Matrix3<f64>, Matrix3<f64>)>,
}

/// `Σ_{i=0}^{k} a_i b_{k−i}`.
#[inline(always)]
fn dot_rev(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b.iter().rev()).map(|(x, y)| x * y).sum()
}

/// The coefficient `k` of `a × b`, `a` and `b` series of 3-vectors (slots).
#[inline(always)]
fn cross_k(prog: &Program, a: [u32; 3], b: [u32; 3], k: usize) -> [f64; 3] {
    let a = [
        prog.series(a[0], k),
        prog.series(a[1], k),
        prog.series(a[2], k),
    ];
    let b = [
        prog.series(b[0], k),
        prog.series(b[1], k),
        prog.series(b[2], k),
    ];
    [
        dot_rev(a[1], b[2]) - dot_rev(a[2], b[1]),
        dot_rev(a[2], b[0]) - dot_rev(a[0], b[2]),
        dot_rev(a[0], b[1]) - dot_rev(a[1], b[0]),
    ]
}

/// The coefficients `k` of `γ × ω` and `m × ω` in one pass over the coefficients of ω.
#[inline(always)]
fn crosses_with_omega(prog: &Program, m: [u32; 3], k: usize) -> ([f64; 3], [f64; 3]) {
    let s = |slot: u32| prog.series(slot, k);
    let (w0, w1, w2) = (s(OMEGA[0]), s(OMEGA[1]), s(OMEGA[2]));
    let (g0, g1, g2) = (s(GAMMA[0]), s(GAMMA[1]), s(GAMMA[2]));
    let (m0, m1, m2) = (s(m[0]), s(m[1]), s(m[2]));
    let (mut a, mut b) = ([0.0; 3], [0.0; 3]);
    for i in 0..=k {
        let j = k - i;
        let (x0, x1, x2) = (w0[j], w1[j], w2[j]);
        a[0] += g1[i] * x2 - g2[i] * x1;
        a[1] += g2[i] * x0 - g0[i] * x2;
        a[2] += g0[i] * x1 - g1[i] * x0;
        b[0] += m1[i] * x2 - m2[i] * x1;
        b[1] += m2[i] * x0 - m0[i] * x2;
        b[2] += m0[i] * x1 - m1[i] * x0;
    }
    (a, b)
}

impl Expansion {
    pub(crate) fn new(tape: &FlowTape, max_order: usize) -> Self {
        Expansion {
            prog: Program::new(tape, max_order),
            q: vec![Quaternion::identity(); max_order + 1],
            psi: vec![0.0; max_order + 1],
            psi_dot: vec![0.0; max_order + 1],
            order: 0,
            j_inv: None,
        }
    }

    fn vec3(&self, s: [u32; 3], k: usize) -> [f64; 3] {
        [
            self.prog.coef(s[0], k),
            self.prog.coef(s[1], k),
            self.prog.coef(s[2], k),
        ]
    }

    /// The coefficient `k` of ω.
    pub(crate) fn omega(&self, k: usize) -> [f64; 3] {
        self.vec3(OMEGA, k)
    }

    /// The coefficient `k` of γ.
    pub(crate) fn gamma(&self, k: usize) -> [f64; 3] {
        self.vec3(GAMMA, k)
    }

    /// Expands the solution through `(ω, γ)` (and the attitude `q`) to order `p`.
    ///
    /// Errors: [`RouthError::KineticNotPositiveDefinite`] when `J` at the state has no
    /// Cholesky factor.
    pub(crate) fn expand(
        &mut self,
        omega: [f64; 3],
        gamma: [f64; 3],
        q: Option<Quaternion<f64>>,
        p: usize,
    ) -> Result<(), RouthError> {
        let p = p.min(self.prog.max_order());
        self.order = p;
        let prog = &mut self.prog;
        prog.order_zero(omega, gamma);
        let m = prog.m;
        let lg = prog.lg;
        let j = Matrix3::from_fn(|r, c| prog.tangent(m[r])[c]);
        // J⁻¹ once a step (by its Cholesky factor; kept while J is bitwise the same, as for a
        // body whose J does not depend on γ): each order then solves by a product, with no
        // division on the chain of dependent orders.
        let j_inv = match self.j_inv {
            Some((key, inv)) if key == j => inv,
            _ => {
                let inv = j
                    .cholesky()
                    .ok_or_else(|| {
                        let g = Vector3::from(gamma);
                        RouthError::KineticNotPositiveDefinite {
                            gamma: gamma_array(&g),
                            min_eigenvalue: min_eigenvalue(&j),
                        }
                    })?
                    .inverse();
                self.j_inv = Some((j, inv));
                inv
            }
        };
        if let Some(q) = q {
            self.q[0] = q;
        }
        for k in 0..p {
            // The order-k coefficients of γ × ω, m × ω and (∂L/∂γ) × γ (Cauchy products).
            let prog = &self.prog;
            let (gd, mut md) = crosses_with_omega(prog, m, k);
            if prog.lg_varies {
                let c = cross_k(prog, lg, GAMMA, k);
                md = [md[0] + c[0], md[1] + c[1], md[2] + c[2]];
            } else {
                // A constant ∂L/∂γ (a potential linear in γ): one term.
                let c = Vector3::from(self.vec3(lg, 0)).cross(&Vector3::from(self.vec3(GAMMA, k)));
                md = [md[0] + c[0], md[1] + c[1], md[2] + c[2]];
            }
            if q.is_some() {
                let mut s = Quaternion::new(0.0, 0.0, 0.0, 0.0);
                for i in 0..=k {
                    s += self.q[i] * Quaternion::from_imag(Vector3::from(self.vec3(OMEGA, k - i)));
                }
                self.q[k + 1] = s * (0.5 / (k + 1) as f64);
            }
            let inv = 1.0 / (k + 1) as f64;
            let prog = &mut self.prog;
            for r in 0..3 {
                prog.set(GAMMA[r], k + 1, gd[r] * inv);
                prog.set(OMEGA[r], k + 1, 0.0);
            }
            prog.order(k + 1);
            let rhs = Vector3::from_fn(|r, _| md[r] * inv - prog.coef(m[r], k + 1));
            let w = j_inv * rhs;
            prog.correct(k + 1, [w.x, w.y, w.z]);
        }
        Ok(())
    }

    /// The series of the rotation angle ψ of the frame rotating about the vertical, after
    /// [`Expansion::expand`]: in the gauge `Ω·γ = s` of the reduced equations (13) (errata E4),
    /// `ω = Ω + ψ̇γ` (7) gives `ψ̇ = (ω·γ − s)/|γ|²`, a quotient of series; `ψ_{k+1} = ψ̇_k/(k + 1)`.
    pub(crate) fn expand_psi(&mut self, psi0: f64, s: f64) {
        let p = self.order;
        let prog = &self.prog;
        let dot = |a: [u32; 3], b: [u32; 3], k: usize| {
            (0..3)
                .map(|r| dot_rev(prog.series(a[r], k), prog.series(b[r], k)))
                .sum::<f64>()
        };
        let n0 = dot(GAMMA, GAMMA, 0);
        self.psi[0] = psi0;
        for k in 0..p {
            let mut x = dot(OMEGA, GAMMA, k) - if k == 0 { s } else { 0.0 };
            for j in 0..k {
                x -= self.psi_dot[j] * dot(GAMMA, GAMMA, k - j);
            }
            self.psi_dot[k] = x / n0;
            self.psi[k + 1] = self.psi_dot[k] / (k + 1) as f64;
        }
    }

    /// ψ at `τ` from the expansion's point.
    pub(crate) fn eval_psi(&self, tau: f64) -> f64 {
        (0..=self.order)
            .rev()
            .fold(0.0, |acc, k| acc * tau + self.psi[k])
    }

    /// The largest absolute value of the block's coefficient `k`.
    fn block_norm(&self, block: usize, k: usize) -> f64 {
        let v = match block {
            0 => self.omega(k),
            1 => self.gamma(k),
            _ => {
                let q = self.q[k];
                return q.w.abs().max(q.i.abs()).max(q.j.abs()).max(q.k.abs());
            }
        };
        v[0].abs().max(v[1].abs()).max(v[2].abs())
    }

    /// `(ω, γ, q)` at `τ` from the expansion's point (Horner's scheme).
    pub(crate) fn eval(&self, tau: f64) -> ([f64; 3], [f64; 3], Quaternion<f64>) {
        let p = self.order;
        let (mut w, mut g, mut q) = (self.omega(p), self.gamma(p), self.q[p]);
        for k in (0..p).rev() {
            let (wk, gk) = (self.omega(k), self.gamma(k));
            for r in 0..3 {
                w[r] = w[r] * tau + wk[r];
                g[r] = g[r] * tau + gk[r];
            }
            q = q * tau + self.q[k];
        }
        (w, g, q)
    }
}

/// The tolerance of one block: `(ε, scale)` (see the module's doc).
fn block_tolerance(norm0: f64, rtol: f64, atol: f64) -> (f64, f64) {
    if rtol * norm0 <= atol {
        (atol, 1.0)
    } else {
        (rtol, norm0)
    }
}

/// The start of [`integrate`]: `ω₀`, `γ₀`, the attitude `q₀` (when integrated) and the gauge
/// `s = Ω₀·γ₀` of the reduced equations (when ψ is wanted).
pub(crate) struct Start {
    pub(crate) omega0: Vector3<f64>,
    pub(crate) gamma0: Vector3<f64>,
    pub(crate) q0: Option<Quaternion<f64>>,
    pub(crate) gauge: Option<f64>,
}

/// Integrates (8) from `(ω₀, γ₀)` (and the attitude `q₀`) at `t = 0` to `t_end` by Taylor's
/// method, calling `record(t, ω, γ, q, ψ)` at `t = 0` and the end of every step
/// ([`Output::Steps`]) or at the output times. `q` is `None` unless `q0` is given; `ψ` is `None`
/// unless `gauge` is: then it is the angle of the frame rotating about the vertical, from
/// `ψ(0) = 0`, in the gauge `Ω·γ = gauge` ([`Expansion::expand_psi`]; it is a quadrature along
/// the solution and takes no part in the choice of the step).
pub(crate) fn integrate<R>(
    tape: &FlowTape,
    start: Start,
    t_end: f64,
    opts: &SimOptions,
    mut record: R,
) -> Result<SimStats, RouthError>
where
    R: FnMut(f64, Vector3<f64>, Vector3<f64>, Option<Quaternion<f64>>, Option<f64>),
{
    let rtol = opts.rtol;
    let atols = [opts.rate_atol.unwrap_or(opts.atol), opts.atol, opts.atol];
    let max_order = order_for(rtol.min(opts.atol).min(atols[0]));
    let mut ex = Expansion::new(tape, max_order);
    let blocks = if start.q0.is_some() { 3 } else { 2 };
    let h_max = opts.h_max.unwrap_or(f64::INFINITY);
    let times: Option<&[f64]> = match &opts.output {
        Output::Steps => None,
        Output::Times(ts) => Some(ts),
    };
    let mut next = 0;
    let Start {
        omega0,
        gamma0,
        q0,
        gauge,
    } = start;
    let (mut w, mut g, mut q, mut psi) = (omega0, gamma0, q0, gauge.map(|_| 0.0));
    match times {
        None => record(0.0, w, g, q, psi),
        Some(ts) => {
            while next < ts.len() && ts[next] <= 0.0 {
                record(ts[next], w, g, q, psi);
                next += 1;
            }
        }
    }
    let mut stats = SimStats::default();
    let mut t = 0.0;
    while t < t_end {
        if stats.accepted_steps >= opts.max_steps {
            return Err(RouthError::TooManySteps {
                t,
                steps: stats.accepted_steps,
            });
        }
        // The tolerance of each block at the step's start, and the order.
        let norms0 = [w.amax(), g.amax(), q.map_or(0.0, |q| q.coords.amax())];
        let tols: [(f64, f64); 3] =
            std::array::from_fn(|b| block_tolerance(norms0[b], rtol, atols[b]));
        let tols = &tols[..blocks];
        let eps = tols.iter().map(|t| t.0).fold(f64::INFINITY, f64::min);
        let p = order_for(eps).min(max_order);
        ex.expand(w.into(), g.into(), q, p)?;
        if let (Some(s), Some(psi0)) = (gauge, psi) {
            ex.expand_psi(psi0, s);
        }
        stats.rhs_evaluations += 1;
        // ρ = min over the blocks and k ∈ {p − 1, p} of (scale/‖x_k‖)^{1/k}: the largest
        // ‖x_k‖/scale over the blocks for each k, then one root each.
        let mut rho = f64::INFINITY;
        for k in [p - 1, p] {
            let r = (tols.iter().enumerate())
                .map(|(b, &(_, scale))| ex.block_norm(b, k) / scale)
                .fold(0.0, f64::max);
            if r > 0.0 {
                rho = rho.min(r.powf(-1.0 / k as f64));
            }
        }
        let safety = (-2.0 - 0.7 / (p - 1) as f64).exp();
        let mut h = (rho * safety).min(h_max);
        if !h.is_finite() && rho.is_finite() {
            return Err(RouthError::NonFiniteState { t });
        }
        if h.is_nan() {
            return Err(RouthError::NonFiniteState { t });
        }
        let last = t + h >= t_end;
        if last {
            h = t_end - t;
        } else if t + h == t {
            return Err(RouthError::StepSizeUnderflow { t, h });
        }
        let t1 = if last { t_end } else { t + h };
        if let Some(ts) = times {
            while next < ts.len() && ts[next] <= t1 {
                let (wn, gn, qn) = ex.eval(ts[next] - t);
                let tau = ts[next] - t;
                let psi_n = psi.map(|_| ex.eval_psi(tau));
                record(ts[next], wn.into(), gn.into(), q.map(|_| qn), psi_n);
                next += 1;
            }
        }
        let (w1, g1, q1) = ex.eval(h);
        let finite = w1.iter().chain(&g1).all(|x| x.is_finite())
            && q.is_none_or(|_| q1.coords.iter().all(|x| x.is_finite()));
        if !finite {
            return Err(RouthError::NonFiniteState { t });
        }
        w = w1.into();
        g = g1.into();
        if q.is_some() {
            q = Some(q1);
        }
        if psi.is_some() {
            let psi1 = ex.eval_psi(h);
            if !psi1.is_finite() {
                return Err(RouthError::NonFiniteState { t });
            }
            psi = Some(psi1);
        }
        t = t1;
        stats.accepted_steps += 1;
        if times.is_none() {
            record(t, w, g, q, psi);
        }
    }
    Ok(stats)
}
