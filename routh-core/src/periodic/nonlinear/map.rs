//! The isoenergetic Poincaré map of a periodic orbit as a Taylor jet of order three
//! (docs/method.md §12.1): the flow of (8) integrated at jets of its initial conditions, the
//! equations evaluated on the model's flow tape (exact derivatives, no finite differences).
//!
//! **Section.** At the orbit's start `x₀` with `f₀ = F(x₀)`, the monodromy `Φ` has the real
//! invariant plane `V = ker(Φ² − 2kΦ + I)` of the pair `μ, 1/μ`; `V` lies in the level of the
//! energy and of both Casimirs (`dE·Φ = dE`, so `μ dE(v) = dE(v)`). With the basis
//! `B = (f₀, v₁, v₂, ∇E, ∇p_ψ, ∇|γ|²)`, the section is the hyperplane `ℓ·(x − x₀) = 0`, `ℓ` the
//! first row of `B⁻¹` (plus an optional tilt), on the level of `(E, p_ψ, |γ|²)`; a point of it
//! has the coordinates `ξ = (rows 2, 3 of B⁻¹)·(x − x₀)`.
//!
//! **Symplectic form.** `(8)` is Hamiltonian for the Lie–Poisson structure of `se(3)*` in
//! `(M, γ)`, `M = ∂L/∂ω`: `ẏ = Π(y)∇H`, `Π = [[M]×, [γ]×; [γ]×, 0]`, `H = E`. On a symplectic
//! leaf `Ω(Πα, Πβ) = α·Πβ`, so that `ι_{X_H}Ω = dH` (the convention of a canonical chart
//! `Ω = dq∧dp`). `v₂` is scaled so that `Ω(v₁, v₂) = 1`: `ξ` is then canonical at the fixed
//! point.
//!
//! **Jets.** `x(ξ) = x₀ + v₁ξ₁ + v₂ξ₂ + Σⱼ∇Cⱼ hⱼ(ξ)`, the `hⱼ = O(ξ²)` solved on jets so that
//! `E`, `p_ψ`, `|γ|²` keep their values to order three; the flow maps it to `Y(ξ) = φ_T(x(ξ))`;
//! the return time `T + δ(ξ)` solves `ℓ·(φ_δ(Y) − x₀) = 0` on jets (a classical Runge–Kutta
//! step of jet length `δ = O(ξ)`, exact to order four); `P(ξ)` reads the coordinates there.

use nalgebra::{Matrix3, Matrix6, SVector, Vector3, Vector6};
use routh_tape::FlowTape;

use super::jet::{MapJet, Series, N};
use super::OrbitNonlinearOptions;
use crate::periodic::flow::{field, integrals, join, shoot, split};
use crate::periodic::{OrbitOptions, PeriodicOrbit};
use crate::sim::dop853::{self, Accepted, Config};
use crate::{Lagrangian, RouthError};

/// A state `(ω, γ)` of jets.
pub(crate) type JetState = [MapJet; 6];

/// A choice of section and of coordinates on it, for the invariance tests: the tilt is added to
/// `ℓ`, `(v₁, v₂)` are replaced by `(v₁ + shear·v₂, v₂)`, and the directions of the level
/// correction are `complement` instead of the gradients.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SectionChart {
    /// Added to the section's normal `ℓ` (0: the section whose tangent plane is `V`).
    pub tilt: Vector6<f64>,
    /// Shear of the linear coordinates.
    pub shear: f64,
    /// Directions along which a point is put back onto the level (`None`: `∇E, ∇p_ψ, ∇|γ|²`).
    pub complement: Option<[Vector6<f64>; 3]>,
}

/// The jet of the Poincaré map and what it was built from.
pub(crate) struct SectionMap {
    /// `P(ξ) = (P₁, P₂)` in coordinates with `Ω = dξ₁∧dξ₂` at the fixed point.
    pub map: [MapJet; 2],
}

fn cross(a: &[MapJet; 3], b: &[MapJet; 3]) -> [MapJet; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: &[MapJet; 3], b: &[MapJet; 3]) -> MapJet {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn parts(x: &JetState) -> ([MapJet; 3], [MapJet; 3]) {
    ([x[0], x[1], x[2]], [x[3], x[4], x[5]])
}

/// `F(x)` of (8) at jets: `J ω̇ = ∂L/∂ω × ω + ∂L/∂γ × γ − N(γ × ω)`, `γ̇ = γ × ω`, with `J⁻¹` by
/// its adjugate.
pub(crate) fn field_jet(
    tape: &FlowTape,
    x: &JetState,
    slots: &mut Vec<MapJet>,
) -> Result<JetState, RouthError> {
    let (w, g) = parts(x);
    let t = tape.eval(&w, &g, slots);
    let gd = cross(&g, &w);
    let a = cross(&t.dl_domega, &w);
    let b = cross(&t.dl_dgamma, &g);
    let n = &t.d2l_domega_dgamma;
    let rhs: [MapJet; 3] = std::array::from_fn(|i| {
        a[i] + b[i] - (n[i][0] * gd[0] + n[i][1] * gd[1] + n[i][2] * gd[2])
    });
    let j = &t.d2l_domega2;
    let cof =
        |r0: usize, r1: usize, c0: usize, c1: usize| j[r0][c0] * j[r1][c1] - j[r0][c1] * j[r1][c0];
    // adj(J)ᵢₖ = cofactor (k, i); J symmetric.
    let adj = [
        [cof(1, 2, 1, 2), -cof(0, 2, 1, 2), cof(0, 1, 1, 2)],
        [-cof(1, 2, 0, 2), cof(0, 2, 0, 2), -cof(0, 1, 0, 2)],
        [cof(1, 2, 0, 1), -cof(0, 2, 0, 1), cof(0, 1, 0, 1)],
    ];
    let det = j[0][0] * adj[0][0] + j[0][1] * adj[1][0] + j[0][2] * adj[2][0];
    if det.value().is_nan() || det.value() <= 0.0 {
        return Err(RouthError::KineticNotPositiveDefinite {
            gamma: [g[0].value(), g[1].value(), g[2].value()],
            min_eigenvalue: f64::NAN,
        });
    }
    let inv = routh_tape::TapeScalar::recip(det);
    let wd: [MapJet; 3] = std::array::from_fn(|i| {
        (adj[i][0] * rhs[0] + adj[i][1] * rhs[1] + adj[i][2] * rhs[2]) * inv
    });
    Ok([wd[0], wd[1], wd[2], gd[0], gd[1], gd[2]])
}

/// `(E, p_ψ, |γ|²)` at jets.
fn levels(tape: &FlowTape, x: &JetState, slots: &mut Vec<MapJet>) -> [MapJet; 3] {
    let (w, g) = parts(x);
    let t = tape.eval(&w, &g, slots);
    [
        dot(&t.dl_domega, &w) - t.lagrangian,
        dot(&t.dl_domega, &g),
        dot(&g, &g),
    ]
}

/// `Ω(u, v)` on the symplectic leaf through `x` (see the module's doc).
pub fn symplectic_form<M: Lagrangian + ?Sized>(
    model: &M,
    x: &Vector6<f64>,
    u: &Vector6<f64>,
    v: &Vector6<f64>,
) -> f64 {
    let (w, g) = split(x);
    let j = model.d2l_domega2(&g);
    let n: Matrix3<f64> = model.d2l_domega_dgamma(&w, &g);
    let m = model.dl_domega(&w, &g);
    // Tangent vectors in (M, γ).
    let lift = |u: &Vector6<f64>| -> (Vector3<f64>, Vector3<f64>) {
        let (du, dg) = split(u);
        (j * du + n * dg, dg)
    };
    let (am, ag) = lift(u);
    let (bm, bg) = lift(v);
    let g2 = g.norm_squared();
    let alpha_m = ag.cross(&g) / g2;
    let r = am - m.cross(&alpha_m);
    let alpha_g = r.cross(&g) / g2;
    alpha_m.dot(&bm) + alpha_g.dot(&bg)
}

fn to_flat(x: &JetState) -> SVector<f64, 60> {
    SVector::<f64, 60>::from_fn(|i, _| x[i / N].c[i % N])
}

fn from_flat(y: &SVector<f64, 60>) -> JetState {
    std::array::from_fn(|i| Series {
        c: std::array::from_fn(|k| y[i * N + k]),
    })
}

fn lin(x0: &Vector6<f64>, terms: &[(Vector6<f64>, MapJet)]) -> JetState {
    std::array::from_fn(|i| {
        let mut s = MapJet::constant(x0[i]);
        for (v, c) in terms {
            s = s + c.scale(v[i]);
        }
        s
    })
}

/// `Σᵢ rᵢ (xᵢ − x₀ᵢ)` at jets.
fn read(r: &Vector6<f64>, x: &JetState, x0: &Vector6<f64>) -> MapJet {
    let mut s = MapJet::constant(0.0);
    for i in 0..6 {
        s = s + (x[i] - MapJet::constant(x0[i])).scale(r[i]);
    }
    s
}

/// The Poincaré map of `orbit` as a jet of order three (see the module's doc).
pub(crate) fn section_map<M: crate::Routhian + ?Sized>(
    model: &M,
    tape: &FlowTape,
    orbit: &PeriodicOrbit,
    chart: &SectionChart,
    integ: &OrbitNonlinearOptions,
    monodromy: Option<&Matrix6<f64>>,
) -> Result<SectionMap, RouthError> {
    let x0 = join(&orbit.omega0, &orbit.gamma0);
    let t_end = orbit.period;
    // The monodromy's invariant plane fixes the section: the corrector's own when given (a
    // family's orbit), else one more integration of the variational equations.
    let phi: Matrix6<f64> = match monodromy {
        Some(m) => *m,
        None => {
            let shot_opts = OrbitOptions {
                rtol: integ.rtol,
                atol: integ.atol,
                max_steps: integ.max_steps,
                control: integ.control.clone(),
                ..OrbitOptions::default()
            };
            shoot(model, &x0, t_end, &shot_opts)?.monodromy
        }
    };
    let k = (phi.trace() - 4.0) / 2.0;
    let q = phi * phi - phi * (2.0 * k) + Matrix6::identity();
    let svd = q.svd(false, true);
    let vt = svd
        .v_t
        .ok_or_else(|| numerical("the monodromy's invariant plane"))?;
    let mut order: Vec<usize> = (0..6).collect();
    order.sort_by(|&a, &b| svd.singular_values[a].total_cmp(&svd.singular_values[b]));
    let mut v1: Vector6<f64> = vt.row(order[0]).transpose();
    let mut v2: Vector6<f64> = vt.row(order[1]).transpose();
    v1 += v2 * chart.shear;
    let omega12 = symplectic_form(model, &x0, &v1, &v2);
    if !omega12.is_finite() || omega12.abs() <= 1e-12 * v1.norm() * v2.norm() {
        return Err(numerical(
            "a symplectic basis of the section (Ω(v₁, v₂) = 0)",
        ));
    }
    v2 /= omega12;
    let f0 = field(model, &x0)?;
    let (_, de, _, dp) = integrals(model, &x0);
    let (_, g0) = split(&x0);
    let dg = join(&Vector3::zeros(), &(g0 * 2.0));
    let grads = [de, dp, dg];
    let comp = chart.complement.unwrap_or(grads);
    let b = Matrix6::from_columns(&[f0, v1, v2, comp[0], comp[1], comp[2]]);
    let binv = b
        .try_inverse()
        .ok_or_else(|| numerical("the section's basis (f₀, v₁, v₂, ∇E, ∇p_ψ, ∇|γ|²)"))?;
    let ell: Vector6<f64> = binv.row(0).transpose() + chart.tilt;
    let r1: Vector6<f64> = binv.row(1).transpose();
    let r2: Vector6<f64> = binv.row(2).transpose();
    // With a tilt, the section's tangent plane is V projected along f₀ onto ker ℓ.
    let denom = ell.dot(&f0);
    if !denom.is_finite() || denom.abs() <= 1e-12 * ell.norm() * f0.norm() {
        return Err(numerical("a section transverse to the flow"));
    }
    let (p1, p2) = (
        v1 - f0 * (ell.dot(&v1) / denom),
        v2 - f0 * (ell.dot(&v2) / denom),
    );
    let (xi1, xi2) = (MapJet::variable(0), MapJet::variable(1));

    // The start on the level: Newton on the jets with the constant matrix G = dC·comp.
    let mut slots = Vec::new();
    let c0 = levels(tape, &lin(&x0, &[]), &mut slots).map(|c| c.value());
    let g = nalgebra::Matrix3::from_fn(|i, j| grads[i].dot(&comp[j]));
    let ginv = g
        .try_inverse()
        .ok_or_else(|| numerical("the level's correction directions"))?;
    let mut h = [MapJet::constant(0.0); 3];
    // And along f₀ onto the section (a tilted ℓ is not zero on the correction directions).
    let mut along = MapJet::constant(0.0);
    let start = |h: &[MapJet; 3], along: &MapJet| {
        lin(
            &x0,
            &[
                (p1, xi1),
                (p2, xi2),
                (comp[0], h[0]),
                (comp[1], h[1]),
                (comp[2], h[2]),
                (f0, *along),
            ],
        )
    };
    for _ in 0..6 {
        let c = levels(tape, &start(&h, &along), &mut slots);
        let res: [MapJet; 3] = std::array::from_fn(|i| c[i] - MapJet::constant(c0[i]));
        for (i, hi) in h.iter_mut().enumerate() {
            *hi = *hi
                - (res[0].scale(ginv[(i, 0)])
                    + res[1].scale(ginv[(i, 1)])
                    + res[2].scale(ginv[(i, 2)]));
        }
        along = along - read(&ell, &start(&h, &along), &x0).scale(1.0 / denom);
    }
    let x_start = start(&h, &along);

    // The flow at jets over [0, T]: error control on the values, the coefficients ride along.
    let weights = move |a: &SVector<f64, 60>, b: &SVector<f64, 60>| {
        SVector::<f64, 60>::from_fn(|i, _| {
            if i % N == 0 {
                // RMS over the 6 controlled of 60 components.
                (6.0f64 / 60.0).sqrt() * (integ.atol + integ.rtol * a[i].abs().max(b[i].abs()))
            } else {
                f64::INFINITY
            }
        })
    };
    let cfg = Config {
        weights: &weights,
        h_max: f64::INFINITY,
        h_init: None,
        max_steps: integ.max_steps,
        dense: false,
        control: Some(&integ.control),
    };
    let mut slots_rhs = Vec::new();
    let rhs = |_t: f64, y: &SVector<f64, 60>| -> Result<SVector<f64, 60>, RouthError> {
        Ok(to_flat(&field_jet(tape, &from_flat(y), &mut slots_rhs)?))
    };
    let y0 = to_flat(&x_start);
    let mut last = y0;
    dop853::integrate(rhs, 0.0, y0, t_end, &cfg, |s: &Accepted<'_, 60>| {
        last = *s.y;
        Ok(())
    })?;
    let y_end = from_flat(&last);

    // The return to the section: δ(ξ) on jets.
    let mut delta = MapJet::constant(0.0);
    let mut z = y_end;
    for _ in 0..6 {
        z = rk4_jet(tape, &y_end, &delta, &mut slots)?;
        let s = read(&ell, &z, &x0);
        delta = delta - s.scale(1.0 / denom);
    }
    let mut map = [read(&r1, &z, &x0), read(&r2, &z, &x0)];
    // The fixed point is the origin (its displacement is the orbit's closure defect).
    for m in map.iter_mut() {
        m.c[0] = 0.0;
    }
    // With a tilted section, the coordinates of P(ξ) are read along f₀ as the start was built.
    Ok(SectionMap { map })
}

/// One classical Runge–Kutta step of jet length `h` from `y`.
fn rk4_jet(
    tape: &FlowTape,
    y: &JetState,
    h: &MapJet,
    slots: &mut Vec<MapJet>,
) -> Result<JetState, RouthError> {
    let add = |a: &JetState, k: &JetState, s: f64| -> JetState {
        std::array::from_fn(|i| a[i] + k[i] * h.scale(s))
    };
    let k1 = field_jet(tape, y, slots)?;
    let k2 = field_jet(tape, &add(y, &k1, 0.5), slots)?;
    let k3 = field_jet(tape, &add(y, &k2, 0.5), slots)?;
    let k4 = field_jet(tape, &add(y, &k3, 1.0), slots)?;
    Ok(std::array::from_fn(|i| {
        y[i] + (k1[i] + k2[i].scale(2.0) + k3[i].scale(2.0) + k4[i]) * h.scale(1.0 / 6.0)
    }))
}

fn numerical(what: &str) -> RouthError {
    RouthError::InvalidModel {
        what: "orbit_nonlinear_stability",
        reason: format!("could not build {what} at this orbit"),
    }
}
