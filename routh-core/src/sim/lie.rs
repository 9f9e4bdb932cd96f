//! A Lie-group (Munthe-Kaas) Runge–Kutta method of order 4 for systems on `ℝᵐ × S²` of the form
//! `v' = F(v, γ)`, `γ' = w(v, γ) × γ` — the shape of (8) (`v = ω`, `w = −ω`) and of (13)
//! (`v = (Ω, ψ)`, `w = −Ω`). γ is only ever moved by exact rotations (Rodrigues' formula), so
//! `|γ|` is preserved to round-off however long the run.
//!
//! The method is RKMK4 with the minimal set of commutators (Hairer, Lubich & Wanner, *Geometric
//! Numerical Integration*, 2nd ed., IV.8.2), on the group `ℝᵐ × SO(3)` acting by translation on
//! `v` and by rotation on `γ`; in `so(3) ≅ ℝ³` the commutator is the cross product:
//!
//! ```text
//! k1 = h ξ(y0)
//! k2 = h ξ(exp(k1/2) y0)
//! k3 = h ξ(exp(k2/2 − [k1, k2]/8) y0)
//! k4 = h ξ(exp(k3) y0)
//! y1 = exp((k1 + 2k2 + 2k3 + k4)/6 − [k1, k4]/12) y0
//! ```
//!
//! On the translation part this is the classical RK4.

use nalgebra::{SVector, Vector3};

use crate::RouthError;

/// Index of γ's first component in the state vector; the other components are translational.
pub(crate) const GAMMA: usize = 3;

/// `exp([w]×) γ` by Rodrigues' formula, `γ + a w×γ + b w×(w×γ)` with `a = sin θ/θ` and
/// `b = (1 − cos θ)/θ² = ½ (sin(θ/2)/(θ/2))²`, `θ = |w|` (no cancellation for small θ).
pub(crate) fn rotate(w: &Vector3<f64>, gamma: &Vector3<f64>) -> Vector3<f64> {
    let theta = w.norm();
    let sinc = |x: f64| {
        if x.abs() < 1e-4 {
            1.0 - x * x / 6.0
        } else {
            x.sin() / x
        }
    };
    let a = sinc(theta);
    let half = sinc(0.5 * theta);
    let b = 0.5 * half * half;
    let wg = w.cross(gamma);
    gamma + wg * a + w.cross(&wg) * b
}

/// The group action `exp(u)·y`: translation by `u_v` of every component but γ, rotation of γ by
/// `u_w`.
fn act<const N: usize>(
    u_v: &SVector<f64, N>,
    u_w: &Vector3<f64>,
    y: &SVector<f64, N>,
) -> SVector<f64, N> {
    let mut out = y + u_v;
    let g = rotate(u_w, &y.fixed_rows::<3>(GAMMA).into_owned());
    out.fixed_rows_mut::<3>(GAMMA).copy_from(&g);
    out
}

/// One RKMK4 step of size `h` from `y`. `field(y)` returns `(ẏ, w)`: the rates of every
/// component (those of γ are ignored) and the angular velocity `w` with `γ' = w × γ`.
///
/// Returns the new state and the rotation vector `u` of the step: `γ₁ = exp([u]×) γ₀`, an
/// order-4 approximation of the flow of the lifted equation `Ẏ = [w]× Y` on SO(3), which moves
/// any attitude `Rᵀ` with `(Rᵀ)˙ = [w]× Rᵀ` exactly as it moves γ.
pub(crate) fn step<const N: usize, F>(
    field: &mut F,
    y: &SVector<f64, N>,
    h: f64,
) -> Result<(SVector<f64, N>, Vector3<f64>), RouthError>
where
    F: FnMut(&SVector<f64, N>) -> Result<(SVector<f64, N>, Vector3<f64>), RouthError>,
{
    let mut eval = |u_v: &SVector<f64, N>, u_w: &Vector3<f64>| {
        field(&act(u_v, u_w, y)).map(|(v, w)| (v * h, w * h))
    };
    let (k1v, k1w) = eval(&SVector::zeros(), &Vector3::zeros())?;
    let (k2v, k2w) = eval(&(k1v * 0.5), &(k1w * 0.5))?;
    let (k3v, k3w) = eval(&(k2v * 0.5), &(k2w * 0.5 - k1w.cross(&k2w) / 8.0))?;
    let (k4v, k4w) = eval(&k3v, &k3w)?;
    let u_v = (k1v + (k2v + k3v) * 2.0 + k4v) / 6.0;
    let u_w = (k1w + (k2w + k3w) * 2.0 + k4w) / 6.0 - k1w.cross(&k4w) / 12.0;
    Ok((act(&u_v, &u_w, y), u_w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_is_exact() {
        let g = Vector3::new(0.3, -0.4, 0.5).normalize();
        // Quarter turn about z.
        let w = Vector3::new(0.0, 0.0, std::f64::consts::FRAC_PI_2);
        let r = rotate(&w, &g);
        assert!((r - Vector3::new(0.4, 0.3, 0.5).normalize()).amax() < 1e-15);
        // Tiny and zero rotations.
        assert_eq!(rotate(&Vector3::zeros(), &g), g);
        let r = rotate(&Vector3::new(1e-9, 2e-9, 0.0), &g);
        assert!((r - (g + Vector3::new(1e-9, 2e-9, 0.0).cross(&g))).amax() < 1e-17);
        // Norm kept over many random rotations.
        let mut x = g;
        for i in 0..10_000 {
            let w = Vector3::new((i as f64).sin(), (1.3 * i as f64).cos(), 0.7) * 0.05;
            x = rotate(&w, &x);
        }
        assert!(
            (x.norm_squared() - 1.0).abs() < 1e-13,
            "{:e}",
            x.norm_squared() - 1.0
        );
    }

    type Rates = (SVector<f64, 6>, Vector3<f64>);

    /// ω' = γ × (a ⊙ γ) − ω/10 (a pendulum-like torque with damping), γ' = γ × ω.
    fn field(y: &SVector<f64, 6>) -> Result<Rates, RouthError> {
        let a = Vector3::new(1.0, 2.0, 3.0);
        let w = y.fixed_rows::<3>(0).into_owned();
        let g = y.fixed_rows::<3>(3).into_owned();
        let wdot = g.cross(&a.component_mul(&g)) - w * 0.1;
        let gdot = g.cross(&w);
        let mut d = SVector::<f64, 6>::zeros();
        d.fixed_rows_mut::<3>(0).copy_from(&wdot);
        d.fixed_rows_mut::<3>(3).copy_from(&gdot);
        Ok((d, -w))
    }

    /// `n` steps over `[0, 2]`.
    fn run(n: usize) -> SVector<f64, 6> {
        let h = 2.0 / n as f64;
        let mut y = SVector::<f64, 6>::from_column_slice(&[0.5, -1.0, 2.0, 0.6, 0.0, 0.8]);
        for _ in 0..n {
            y = step(&mut field, &y, h).unwrap().0;
        }
        y
    }

    /// Order 4 on a coupled nonlinear system.
    #[test]
    fn order_four() {
        let reference = run(4096);
        let e1 = (run(64) - reference).norm();
        let e2 = (run(128) - reference).norm();
        let ratio = e1 / e2;
        assert!(
            ratio > 13.0 && ratio < 19.0,
            "ratio {ratio}, e1 {e1:e}, e2 {e2:e}"
        );
        let g = run(64).fixed_rows::<3>(3).into_owned();
        assert!((g.norm_squared() - 1.0).abs() < 1e-14);
    }
}
