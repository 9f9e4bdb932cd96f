//! Axially symmetric bodies (docs/method.md §11a): the test [`axial_symmetry`], the action of
//! the turn about the body axis `e₃` on the state, its generator and its momentum, and what the
//! corrector and the families need of them.
//!
//! A turn of the body frame by a constant `α` about `e₃` maps the state `x = (ω, γ)` to
//! `S_α x = (Rot(e₃, α)ω, Rot(e₃, α)γ)`. When `L(S_α x) = L(x)` for every `α` the equations (8)
//! commute with `S_α`, the generator `ξ(x) = d/dα S_α x|₀ = (e₃ × ω, e₃ × γ)` is a symmetry of
//! the flow and its Noether integral is the momentum about the body axis,
//! `p_φ = e₃·∂L/∂ω` (`ṗ_φ = e₃·(∂L/∂ω × ω + ∂L/∂γ × γ) = −(∂L/∂ω·ξ_ω + ∂L/∂γ·ξ_γ) = 0` by the
//! invariance). A relative periodic orbit of such a body closes up to a turn `Δφ` about `e₃`:
//! `S_Δφ φ_T(x₀) = x₀`, which is `R(T) = Rot(e_z, Δψ)·R(0)·Rot(e₃, Δφ)` for the attitude.

use nalgebra::{Matrix3, UnitQuaternion, Vector3, Vector6};

use super::flow::{field, join, split};
use crate::{Lagrangian, RouthError, SteadyMotion};

/// The tolerance of [`axial_symmetry`]: `|L(S_α x) − L(x)|`, `|∂L/∂ω(S_α x) − R ∂L/∂ω(x)|`,
/// `|∂L/∂γ(S_α x) − R ∂L/∂γ(x)|` and `|J(Rγ) − R J(γ) Rᵀ|` (max-norms) at most this times the
/// scale `1 + |L| + |ω||∂L/∂ω| + |∂L/∂γ| + |J|` of the point. The models evaluate these to a
/// few units of round-off of that scale (1e−15); a body off the symmetry by 1e−9 of it (an
/// inertia `A₂ = A₁(1 + 1e−8)`, a centre of mass 1e−8 off the axis) is not symmetric.
pub const AXIAL_SYMMETRY_TOL: f64 = 1e-9;

/// The turns tried: neither is a rational multiple of π, so a body with an `n`-fold symmetry
/// only (a term `cos nφ`) fails both.
const ANGLES: [f64; 2] = [0.7, 2.3];

/// Fixed pseudo-random states `(ω, γ)`, `|γ| = 1`, no component special.
const POINTS: [([f64; 3], [f64; 3]); 3] = [
    ([0.31, -0.74, 0.52], [0.36, 0.48, 0.8]),
    ([-1.13, 0.27, -0.66], [-0.6, 0.64, -0.48]),
    ([0.58, 1.21, 0.09], [0.768, -0.224, -0.6]),
];

/// `Rot(e₃, a)`.
pub(crate) fn rot(a: f64) -> Matrix3<f64> {
    let (s, c) = a.sin_cos();
    Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0)
}

/// Whether `model` is axially symmetric: `L` (with its gradients and its mass matrix
/// `J = ∂²L/∂ω²`) unchanged by turns of the body frame about `e₃`,
/// `L(Rω, Rγ) = L(ω, γ)`, `∂L/∂ω(Rω, Rγ) = R ∂L/∂ω(ω, γ)`, `∂L/∂γ(Rω, Rγ) = R ∂L/∂γ(ω, γ)` and
/// `J(Rγ) = R J(γ) Rᵀ` for `R = Rot(e₃, α)`, checked at three fixed pseudo-random states and two
/// angles `α` (0.7 and 2.3 rad) to [`AXIAL_SYMMETRY_TOL`] of each state's scale. The Lagrange
/// top (`A₁ = A₂`, centre of mass on `e₃`) is; Kovalevskaya's and Goryachev–Chaplygin's bodies
/// (`A₁ = A₂` but the centre of mass off the axis) are not. Works alike for derived models,
/// run-time `Model`s and hand-written ones: it only evaluates the [`Lagrangian`] trait.
/// A non-finite value anywhere gives `false`.
///
/// Such a body has a second cyclic angle φ (docs/method.md §11a): [`periodic_orbit`](super::periodic_orbit)
/// and the families then correct orbits periodic modulo a turn `Δφ` about `e₃`
/// ([`PeriodicOrbit::body_turn`](super::PeriodicOrbit::body_turn)).
///
/// ```
/// use routh_core::{axial_symmetry, Matrix3, Vector3};
/// use test_models::HeavyTop;
/// assert!(axial_symmetry(&HeavyTop::lagrange(1.0, 0.6, 2.0)));
/// let kovalevskaya = HeavyTop {
///     j: Matrix3::from_diagonal(&Vector3::new(2.0, 2.0, 1.0)),
///     mgr: Vector3::new(1.0, 0.0, 0.0),
/// };
/// assert!(!axial_symmetry(&kovalevskaya));
/// ```
pub fn axial_symmetry<M: Lagrangian + ?Sized>(model: &M) -> bool {
    POINTS.iter().all(|(w, g)| {
        let (w, g) = (Vector3::from(*w), Vector3::from(*g));
        let l = model.lagrangian(&w, &g);
        let lw = model.dl_domega(&w, &g);
        let lg = model.dl_dgamma(&w, &g);
        let j = model.d2l_domega2(&g);
        let scale = 1.0 + l.abs() + w.norm() * lw.norm() + lg.norm() + j.amax();
        if !scale.is_finite() {
            return false;
        }
        let tol = AXIAL_SYMMETRY_TOL * scale;
        ANGLES.iter().all(|&a| {
            let r = rot(a);
            let (rw, rg) = (r * w, r * g);
            let dl = (model.lagrangian(&rw, &rg) - l).abs();
            let dlw = (model.dl_domega(&rw, &rg) - r * lw).amax();
            let dlg = (model.dl_dgamma(&rw, &rg) - r * lg).amax();
            let dj = (model.d2l_domega2(&rg) - r * j * r.transpose()).amax();
            // `<=` is false for NaN: a non-finite value is no symmetry.
            [dl, dlw, dlg, dj].iter().all(|d| *d <= tol)
        })
    })
}

/// `S_α x = (Rot(e₃, α)ω, Rot(e₃, α)γ)`.
pub(crate) fn act(a: f64, x: &Vector6<f64>) -> Vector6<f64> {
    let r = rot(a);
    let (w, g) = split(x);
    join(&(r * w), &(r * g))
}

/// `ξ(x) = d/dα S_α x|₀ = (e₃ × ω, e₃ × γ)`: the generator of the turn (linear in `x`).
pub(crate) fn generator(x: &Vector6<f64>) -> Vector6<f64> {
    Vector6::new(-x[1], x[0], 0.0, -x[4], x[3], 0.0)
}

/// The momentum about the body axis `p_φ = e₃·∂L/∂ω` (the Noether integral of the turn) and
/// its gradient `(J e₃, Nᵀe₃)`, `N = ∂²L/∂ω∂γ` (as `flow::integrals` for `p_ψ`).
pub(crate) fn body_momentum<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
) -> (f64, Vector6<f64>) {
    let (w, g) = split(x);
    let e3 = Vector3::z();
    let j = model.d2l_domega2(&g);
    let n = model.d2l_domega_dgamma(&w, &g);
    (model.dl_domega(&w, &g).z, join(&(j * e3), &n.tr_mul(&e3)))
}

/// The turn `α` that brings `S_α x` closest to `x_ref` (least squares over the six
/// components): `α = atan2(Σ (e₃ × a)·b, Σ a⊥·b⊥)` over the pairs `(a, b) = (ω, ω_ref)`,
/// `(γ, γ_ref)` (`⊥`: the part normal to `e₃`). 0 when both are on the axis.
pub(crate) fn align(x: &Vector6<f64>, x_ref: &Vector6<f64>) -> f64 {
    let (mut s, mut c) = (0.0, 0.0);
    for k in [0, 3] {
        let (a1, a2, b1, b2) = (x[k], x[k + 1], x_ref[k], x_ref[k + 1]);
        c += a1 * b1 + a2 * b2;
        s += a1 * b2 - a2 * b1;
    }
    if s == 0.0 && c == 0.0 {
        0.0
    } else {
        s.atan2(c)
    }
}

/// An angle in `(−π, π]`.
pub(crate) fn wrap(a: f64) -> f64 {
    use std::f64::consts::PI;
    let r = a.rem_euclid(2.0 * PI);
    if r > PI {
        r - 2.0 * PI
    } else {
        r
    }
}

/// The attitude turn `R(T)` (with `R(0) = I`) less the body turn: `R(T)·Rot(e₃, −Δφ)`, which is
/// the turn by `Δψ` about the vertical `γ₀` (docs/method.md §11a).
pub(crate) fn less_body_turn(turn: &UnitQuaternion<f64>, body_turn: f64) -> UnitQuaternion<f64> {
    turn * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), -body_turn)
}

/// A point is a relative equilibrium of the two turns (a regular precession: the flow is the
/// turn, `F(x) ∥ ξ(x)`) when the part of `F` normal to `ξ` is at most this of `|F|`.
pub(crate) const RELATIVE_EQUILIBRIUM_TOL: f64 = 1e-6;

/// What the corrector adds on an axially symmetric body (docs/method.md §11a): the gauge
/// plane through `x_ref` normal to the generator, and the momentum about the axis to keep.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Turn {
    /// `ξ(x_ref)/|ξ(x_ref)|`.
    pub xi_ref: Vector6<f64>,
    /// `p_φ(x_ref)`.
    pub p_phi: f64,
}

/// The [`Turn`] at `x` when `model` is axially symmetric and `x` is neither fixed by the turn
/// (`ξ(x) = 0`: ω and γ on the axis) nor a relative equilibrium of the two turns
/// (`F(x) ∥ ξ(x)` within [`RELATIVE_EQUILIBRIUM_TOL`]: a regular precession is a periodic orbit
/// of (8) in the ordinary sense, isolated, with `Δφ = 0`). `None`: the ordinary problem.
pub(crate) fn turn_at<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
) -> Result<Option<Turn>, RouthError> {
    if !axial_symmetry(model) {
        return Ok(None);
    }
    let xi = generator(x);
    let nxi = xi.norm();
    // NaN too.
    if nxi.is_nan() || nxi <= 1e-12 * 1f64.max(x.norm()) {
        return Ok(None);
    }
    let f = field(model, x)?;
    let xi = xi / nxi;
    let normal = f - xi * f.dot(&xi);
    if normal.norm() <= RELATIVE_EQUILIBRIUM_TOL * f.norm() {
        return Ok(None);
    }
    Ok(Some(Turn {
        xi_ref: xi,
        p_phi: body_momentum(model, x).0,
    }))
}

/// The start of the planar swings of an axially symmetric body resting on its axis (`γ_s = ±e₃`,
/// `ψ̇ = 0`, so `p_ψ = 0`): the two frequencies are equal (the symmetry), the linear modes a
/// plane of swings in every vertical plane, and mode 0 is the family of planar swings. Their
/// turning point `(0, γ_s + ε d)` with `d = e₁` (any `d ⊥ e₃` is as good: the gauge row keeps the
/// plane) is the mode vector `(0, e₁)`. `Ok(None)`: not this case. Mode 1 there is an error (the
/// same family).
pub(crate) fn rest_swing<M: Lagrangian + ?Sized>(
    model: &M,
    steady: &SteadyMotion,
    mode: usize,
) -> Result<Option<Vector6<f64>>, RouthError> {
    let g = steady.gamma;
    let on_axis = g.x.abs().max(g.y.abs()) <= 1e-9 * g.norm();
    let at_rest = steady.psi_dot.abs() <= 1e-12 && steady.p_psi.abs() <= 1e-12;
    if !(on_axis && at_rest && axial_symmetry(model)) {
        return Ok(None);
    }
    if mode != 0 {
        return Err(RouthError::InvalidOption {
            what: "mode",
            reason: "an axially symmetric body at rest on its axis has two equal frequencies \
                     and one family of small orbits, its planar swings: mode 0"
                .into(),
        });
    }
    Ok(Some(Vector6::new(0.0, 0.0, 0.0, 1.0, 0.0, 0.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `align` inverts `act`, `wrap` lands in (−π, π], `generator` is the derivative of `act`.
    #[test]
    fn the_turn_and_its_generator() {
        let x = Vector6::new(0.3, -0.2, 0.9, 0.1, 0.7, -0.4);
        for a in [-3.0, -0.4, 0.0, 1.1, 3.1] {
            assert!((align(&x, &act(a, &x)) - a).abs() < 1e-14);
        }
        let h = 1e-6;
        let fd = (act(h, &x) - act(-h, &x)) / (2.0 * h);
        assert!((fd - generator(&x)).amax() < 1e-10);
        use std::f64::consts::PI;
        assert_eq!(wrap(PI), PI);
        assert_eq!(wrap(-PI), PI);
        assert!((wrap(7.0) - (7.0 - 2.0 * PI)).abs() < 1e-15);
        assert!((wrap(-4.0) - (2.0 * PI - 4.0)).abs() < 1e-15);
    }
}
