//! Shared by the stability and steady-motion tests: the closed-form heavy top now lives in the
//! shared models crate (`test_models::HeavyTop`).
#![allow(unused_imports)]

pub use test_models::HeavyTop;

use routh_core::{
    simulate_full, steady_motions, Matrix3, PeriodicOrbit, SimOptions, SteadyMotion, Vector3,
};

/// A heavy body `J = diag(a, b, c)` with its centre of mass on the third axis (`U = mgl γ₃`).
pub fn heavy_body(a: f64, b: f64, c: f64, mgl: f64) -> HeavyTop {
    HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(a, b, c)),
        mgr: Vector3::new(0.0, 0.0, mgl),
    }
}

/// The complete elliptic integral `K(m) = π / (2 AGM(1, √(1 − m)))` (the pendulum's period is
/// `4K(sin²(θ₀/2))/ω₀`).
pub fn elliptic_k(m: f64) -> f64 {
    let (mut a, mut g) = (1.0f64, (1.0 - m).sqrt());
    for _ in 0..60 {
        let (an, gn) = (0.5 * (a + g), (a * g).sqrt());
        a = an;
        g = gn;
    }
    std::f64::consts::PI / (2.0 * a)
}

/// How far an orbit is from closing under `simulate_full` (another integrator than the
/// corrector's, no corrector): `|ω(T) − Rω₀| + |γ(T) − Rγ₀|` with `R = Rot(e₃, −Δφ)` the body
/// turn back (the identity on a body without the axial symmetry).
pub fn closure_gap(m: &HeavyTop, o: &PeriodicOrbit) -> f64 {
    let tr = simulate_full(
        m,
        o.omega0,
        o.gamma0,
        o.period,
        &SimOptions::with_tolerances(1e-12, 1e-13),
    )
    .unwrap();
    let n = tr.t.len() - 1;
    let r = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), -o.body_turn);
    (tr.omega[n] - r * o.omega0).norm() + (tr.gamma[n] - r * o.gamma0).norm()
}

/// An Euler–Poisson integrator written out here, independent of the crate's vector field,
/// integrator and corrector: `Jω̇ = Jω × ω − mgl e₃ × γ`, `γ̇ = γ × ω` for `J = diag(j)`, with
/// the variational equations of the columns of `Φ` (state: ω, γ, then 6 columns of 6).
fn euler_poisson(j: [f64; 3], mgl: f64, y: &[f64; 42]) -> [f64; 42] {
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let w = [y[0], y[1], y[2]];
    let g = [y[3], y[4], y[5]];
    let jw = [j[0] * w[0], j[1] * w[1], j[2] * w[2]];
    let e3 = [0.0, 0.0, mgl];
    let mut out = [0.0; 42];
    let (t, u, gd) = (cross(jw, w), cross(e3, g), cross(g, w));
    for i in 0..3 {
        out[i] = (t[i] - u[i]) / j[i];
        out[3 + i] = gd[i];
    }
    for c in 0..6 {
        let o = 6 + 6 * c;
        let dw = [y[o], y[o + 1], y[o + 2]];
        let dg = [y[o + 3], y[o + 4], y[o + 5]];
        let jdw = [j[0] * dw[0], j[1] * dw[1], j[2] * dw[2]];
        let (a, b, u) = (cross(jdw, w), cross(jw, dw), cross(e3, dg));
        let (p, q) = (cross(dg, w), cross(g, dw));
        for i in 0..3 {
            out[o + i] = (a[i] + b[i] - u[i]) / j[i];
            out[o + 3 + i] = p[i] + q[i];
        }
    }
    out
}

/// The stability index `k = (tr Φ(T) − 4)/2` of the planar swing of `J = diag(j)`, centre of
/// mass on `e₃` at `mgl`, about the principal axis `axis` (0 or 1) with amplitude `theta0`,
/// over its closed-form period `4K(sin²(θ₀/2))/√(mgl/J_axis)`, by `n` classical RK4 steps of
/// [`euler_poisson`] from the turning point (ω = 0, γ in the plane normal to the axis).
pub fn swing_index(j: [f64; 3], mgl: f64, axis: usize, theta0: f64, n: usize) -> f64 {
    let period = 4.0 * elliptic_k((0.5 * theta0).sin().powi(2)) / (mgl / j[axis]).sqrt();
    let mut y = [0.0; 42];
    y[3 + (1 - axis)] = theta0.sin();
    y[5] = -theta0.cos();
    for c in 0..6 {
        y[6 + 7 * c] = 1.0;
    }
    let h = period / n as f64;
    let add = |y: &[f64; 42], k: &[f64; 42], s: f64| {
        let mut z = *y;
        for i in 0..42 {
            z[i] += s * k[i];
        }
        z
    };
    for _ in 0..n {
        let k1 = euler_poisson(j, mgl, &y);
        let k2 = euler_poisson(j, mgl, &add(&y, &k1, 0.5 * h));
        let k3 = euler_poisson(j, mgl, &add(&y, &k2, 0.5 * h));
        let k4 = euler_poisson(j, mgl, &add(&y, &k3, h));
        for i in 0..42 {
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    }
    let trace: f64 = (0..6).map(|c| y[6 + 7 * c]).sum();
    0.5 * (trace - 4.0)
}

/// The trace of a monodromy built by central differences of `simulate_full` over `t`.
pub fn fd_trace<M: routh_core::Lagrangian>(m: &M, w: Vector3<f64>, g: Vector3<f64>, t: f64) -> f64 {
    let opts = SimOptions::with_tolerances(1e-12, 1e-13);
    let end = |w: Vector3<f64>, g: Vector3<f64>| {
        let tr = simulate_full(m, w, g, t, &opts).unwrap();
        let n = tr.t.len() - 1;
        [tr.omega[n], tr.gamma[n]]
    };
    let h = 1e-6;
    let mut trace = 0.0;
    for i in 0..6 {
        let (mut wp, mut gp, mut wm, mut gm) = (w, g, w, g);
        if i < 3 {
            wp[i] += h;
            wm[i] -= h;
        } else {
            gp[i - 3] += h;
            gm[i - 3] -= h;
        }
        // simulate_full wants a unit γ: a γ column is taken along the perturbation projected
        // on the tangent plane (normalised), which gives `e_iᵀΦ_γγ(I − γγᵀ)e_i`.
        let (p, q) = if i < 3 {
            (end(wp, gp), end(wm, gm))
        } else {
            (end(wp, gp.normalize()), end(wm, gm.normalize()))
        };
        let d = if i < 3 {
            (p[0][i] - q[0][i]) / (2.0 * h)
        } else {
            (p[1][i - 3] - q[1][i - 3]) / (2.0 * h)
        };
        trace += d;
    }
    // The missing `γᵀΦ_γγγ` is 1: `|γ|²` is a Casimir, so `(0, γ)` is a left eigenvector of Φ
    // with eigenvalue 1 on an orbit (`γ(T) = γ₀`).
    trace + 1.0
}

/// The hanging steady motion of a heavy body with its centre of mass on `e₃` at `p_ψ`
/// (`γ₃ < −0.9`).
pub fn hanging(m: &HeavyTop, p_psi: f64) -> SteadyMotion {
    steady_motions(m, p_psi)
        .unwrap()
        .into_iter()
        .find(|s| s.gamma.z < -0.9)
        .expect("the hanging steady motion")
}
