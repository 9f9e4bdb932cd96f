//! The attitude of the body: the rotation `R` from body to space coordinates, integrated as a
//! unit quaternion alongside (8) or (13) when [`SimOptions::attitude`](super::SimOptions) is set,
//! and its z-x-z Euler angles (ψ, θ, φ).
//!
//! Conventions (docs/method.md §2): `x_space = R x_body`, `Ṙ = R[ω]×` with ω the body angular
//! velocity, and γ, the body coordinates of the upward vertical `e₃`, is `γ = Rᵀe₃`. The Euler
//! angles are those of `R = R_z(ψ) R_x(θ) R_z(φ)`: ψ the precession (azimuth of the line of
//! nodes about the vertical), θ the nutation (angle between the vertical and the body axis
//! `e₃`), φ the proper rotation; then `γ = (sin θ sin φ, sin θ cos φ, cos θ)`.
//!
//! The initial attitude is the one with ψ(0) = 0 and `R(0)ᵀe₃ = γ₀`: `R(0) = R_x(θ₀) R_z(φ₀)`
//! (the attitude about the vertical is a symmetry, so any other start differs by a constant
//! rotation about `e₃`: rotate with `UnitQuaternion::from_axis_angle(&Vector3::z_axis(), ψ₀)`
//! on the left).

use nalgebra::{Quaternion, SVector, UnitQuaternion, Vector3};

/// `R(0) = R_x(θ₀) R_z(φ₀)` with `γ₀ = (sin θ₀ sin φ₀, sin θ₀ cos φ₀, cos θ₀)`: the attitude
/// with Euler angle ψ = 0 whose `Rᵀe₃` is `γ₀` (normalised).
pub(crate) fn initial_attitude(gamma0: &Vector3<f64>) -> UnitQuaternion<f64> {
    let g = gamma0.normalize();
    let theta = g.xy().norm().atan2(g.z);
    let phi = g.x.atan2(g.y);
    UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta)
        * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi)
}

/// `R_z(ψ)`, the rotation by ψ about the vertical.
pub(crate) fn about_vertical(psi: f64) -> UnitQuaternion<f64> {
    UnitQuaternion::from_axis_angle(&Vector3::z_axis(), psi)
}

/// `exp([u]×)` as a unit quaternion, `u` a rotation vector (exact for every angle).
pub(super) fn exp(u: &Vector3<f64>) -> UnitQuaternion<f64> {
    UnitQuaternion::from_scaled_axis(*u)
}

/// The quaternion stored at `y[at..at + 4]` as `(w, x, y, z)`.
pub(super) fn read<const N: usize>(y: &SVector<f64, N>, at: usize) -> Quaternion<f64> {
    Quaternion::new(y[at], y[at + 1], y[at + 2], y[at + 3])
}

/// Stores `q` at `y[at..at + 4]` as `(w, x, y, z)`.
pub(super) fn write<const N: usize>(y: &mut SVector<f64, N>, at: usize, q: &Quaternion<f64>) {
    y[at] = q.w;
    y[at + 1] = q.i;
    y[at + 2] = q.j;
    y[at + 3] = q.k;
}

/// `q̇ = ½ q ⊗ (0, ω)`, the quaternion form of `Ṙ = R[ω]×` (ω in body coordinates).
pub(super) fn rate(q: &Quaternion<f64>, omega: &Vector3<f64>) -> Quaternion<f64> {
    q * Quaternion::from_imag(*omega) * 0.5
}

/// The attitude recorded from the quaternion `q` of the adaptive integration: normalised, then
/// turned by the smallest body rotation that maps its `Rᵀe₃` onto the integrated γ (a correction
/// of the size of the integration error), so that `γ = Rᵀe₃` holds to round-off at every
/// recorded point. The integration itself carries on with its own `q`.
pub(super) fn aligned(q: &Quaternion<f64>, gamma: &Vector3<f64>) -> UnitQuaternion<f64> {
    let r = UnitQuaternion::from_quaternion(*q);
    let g_of_r = r.inverse_transform_vector(&Vector3::z());
    let g = gamma.normalize();
    // R' = R C with C the rotation taking g onto g_of_r (then R'ᵀe₃ = Cᵀ g_of_r = g). The angle
    // by atan2, accurate for tiny angles (nalgebra's `rotation_between` takes acos of the dot
    // product, which loses the ~1e-8 corrections met here).
    let axis = g.cross(&g_of_r);
    let angle = axis.norm().atan2(g.dot(&g_of_r));
    match nalgebra::Unit::try_new(axis, 0.0) {
        Some(axis) => r * UnitQuaternion::from_axis_angle(&axis, angle),
        None => r,
    }
}

/// z-x-z Euler angles `(ψ, θ, φ)` of each attitude, `R = R_z(ψ) R_x(θ) R_z(φ)`, with ψ and φ
/// unwrapped (continuous from one point to the next, the first in `(−π, π]`) and `θ ∈ [0, π]`.
///
/// At θ = 0 or π (the body axis vertical) ψ and φ are not separately defined; there ψ + φ (or
/// ψ − φ) is, and the split returned is the one atan2 gives.
pub fn euler_angles(attitude: &[UnitQuaternion<f64>]) -> Vec<[f64; 3]> {
    let mut out: Vec<[f64; 3]> = Vec::with_capacity(attitude.len());
    for q in attitude {
        let r = q.to_rotation_matrix();
        let m = r.matrix();
        // R₁₃ = sin ψ sin θ, R₂₃ = −cos ψ sin θ, R₃₁ = sin θ sin φ, R₃₂ = sin θ cos φ, R₃₃ = cos θ.
        let s13 = (m[(0, 2)] * m[(0, 2)] + m[(1, 2)] * m[(1, 2)]).sqrt();
        let s31 = (m[(2, 0)] * m[(2, 0)] + m[(2, 1)] * m[(2, 1)]).sqrt();
        let theta = (0.5 * (s13 + s31)).atan2(m[(2, 2)]);
        let (mut psi, mut phi) = if s13 > 1e-12 {
            (m[(0, 2)].atan2(-m[(1, 2)]), m[(2, 0)].atan2(m[(2, 1)]))
        } else {
            // θ ≈ 0 or π: R ≈ R_z(ψ ± φ) up to the flip; put it all in ψ.
            (m[(1, 0)].atan2(m[(0, 0)]), 0.0)
        };
        if let Some(prev) = out.last() {
            psi = unwrap(prev[0], psi);
            phi = unwrap(prev[2], phi);
        }
        out.push([psi, theta, phi]);
    }
    out
}

/// `x + 2πk` closest to `prev`.
fn unwrap(prev: f64, x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    x + ((prev - x) / tau).round() * tau
}

/// The shape of a top's apex locus between its nutation bounds, from the sign of the
/// precession rate ψ̇ (the classical classification of the heavy symmetric top).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum ApexLocus {
    /// ψ̇ changes sign: the apex makes loops.
    Looping,
    /// ψ̇ vanishes at the upper turning points without changing sign: cusps.
    Cuspidal,
    /// ψ̇ keeps one sign: waves.
    Wavy,
}

impl std::fmt::Display for ApexLocus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ApexLocus::Looping => "looping",
            ApexLocus::Cuspidal => "cuspidal",
            ApexLocus::Wavy => "wavy",
        })
    }
}

/// Classifies an apex locus from the Euler angles of a simulation (e.g.
/// [`Trajectory::euler_angles`](super::Trajectory::euler_angles)) at the times `t`: the
/// precession rate ψ̇ is taken by finite differences of the unwrapped ψ; with `lo`, `hi` its
/// extreme values and `m = max(|lo|, |hi|)`, the locus is looping when ψ̇ takes both signs
/// beyond `tol·m`, cuspidal when the smaller of `|lo|`, `|hi|` is below `tol·m`, wavy otherwise.
/// `tol = 0.02` suits runs sampled finely enough to resolve the turning points (a few hundred
/// samples per nutation period). `None` for fewer than three points or ψ̇ ≡ 0.
pub fn classify_apex_locus(t: &[f64], euler: &[[f64; 3]], tol: f64) -> Option<ApexLocus> {
    if t.len() < 3 || t.len() != euler.len() {
        return None;
    }
    let rates = t
        .windows(2)
        .zip(euler.windows(2))
        .filter(|(w, _)| w[1] > w[0])
        .map(|(w, e)| (e[1][0] - e[0][0]) / (w[1] - w[0]));
    let (lo, hi) = rates.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), r| {
        (a.min(r), b.max(r))
    });
    let m = lo.abs().max(hi.abs());
    if !(m.is_finite() && m > 0.0) {
        return None;
    }
    Some(if lo < -tol * m && hi > tol * m {
        ApexLocus::Looping
    } else if lo.abs().min(hi.abs()) < tol * m || lo * hi <= 0.0 {
        ApexLocus::Cuspidal
    } else {
        ApexLocus::Wavy
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn initial_attitude_maps_e3_to_gamma() {
        let g = Vector3::new(0.3, -0.4, 0.5).normalize();
        let r = initial_attitude(&g);
        assert!((r.inverse_transform_vector(&Vector3::z()) - g).amax() < 1e-15);
        let e = euler_angles(&[r])[0];
        assert!(e[0].abs() < 1e-15);
        assert!((e[1] - g.z.acos()).abs() < 1e-15);
    }

    #[test]
    fn euler_angles_invert_the_product() {
        let (psi, theta, phi) = (2.5, 0.7, -1.2);
        let r = about_vertical(psi)
            * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), theta)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi);
        let e = euler_angles(&[r])[0];
        assert!((e[0] - psi).abs() < 1e-14 && (e[1] - theta).abs() < 1e-14);
        assert!((e[2] - phi).abs() < 1e-14);
    }
}
