//! Paper Example 2 (43)–(51): steady motions and spin thresholds of ellipsoids on a smooth plane.
//! Run: `cargo run --release --example ellipsoid_on_plane` (figures in `out/ellipsoid_on_plane/`).
//!
//! The body is declared below with `#[derive(Lagrangian)]`, with `C₃` the support function
//! (errata E6), `U = +m g C₃` (errata E2) and the ½ of (51) restored (errata E1). The spin needed
//! to stand on the end of the long axis is found numerically (continuation) and compared with the
//! hand-derived formulas of [`Ellipsoid::spheroid_threshold`] and [`Ellipsoid::spin_threshold`]:
//!
//! # The spin threshold about a vertical principal axis, by hand
//!
//! Let the body spin about the principal axis `e₃` held vertical, `γ = σe₃` (`σ = ±1`: standing on
//! the end `−σa₃e₃`), the semi-axes `a₁, a₂, a₃` along the principal axes of `I = diag(I₁, I₂, I₃)`
//! and the ellipsoid's centre at `c₀ = h e₃` from the centre of mass. At `Ω = 0`, by E6,
//! `γᵀJγ = γᵀIγ`, so the amended potential (34) is
//!
//! ```text
//! U_r(γ) = ½ p² / (γᵀIγ) + m g C₃(γ),    C₃(γ) = √(γᵀDγ) − h γ₃,   D = diag(a₁², a₂², a₃²).
//! ```
//!
//! Near the pole take `γ = (ε₁, ε₂, σ√(1 − ε₁² − ε₂²))`; the chart is orthonormal at `ε = 0`,
//! so the second-order terms give the restricted second variation (62)–(63) directly:
//! - `γᵀIγ = I₃ + (I₁ − I₃)ε₁² + (I₂ − I₃)ε₂²` exactly, so
//!   `½p²/(γᵀIγ) = p²/(2I₃) − ½ Σ p²(Iᵢ − I₃)/I₃² εᵢ² + O(ε⁴)`;
//! - `√(γᵀDγ) = √(a₃² + Σ (aᵢ² − a₃²)εᵢ²) = a₃ + ½ Σ (aᵢ² − a₃²)/a₃ εᵢ² + O(ε⁴)`;
//! - `−hγ₃ = −σh + ½ σh Σ εᵢ² + O(ε⁴)`.
//!
//! Hence `U_r = const + ½ Σ kᵢ εᵢ²` with
//!
//! ```text
//! kᵢ = −m g ℓᵢ − p² (Iᵢ − I₃)/I₃²,     ℓᵢ = a₃ − σh − aᵢ²/a₃   (i = 1, 2),
//! ```
//!
//! `ℓᵢ` being the height of the centre of mass above the centre of curvature of the contact
//! point's normal section in the plane `(eᵢ, e₃)`. (The vertical-motion term of the kinetic energy
//! (49) is quadratic in `(∂C₃/∂γ, γ × ω)`, which vanishes at the pole, so it adds nothing to the
//! linearisation.) The gyroscopic matrix of section 5 at the pole is, by E6,
//! `2G₁₂ = p(I₃ − I₁ − I₂)/I₃`, and the kinetic matrix on the tangent plane is `diag(I₁, I₂)`.
//! In the coordinates `δγ = (ε₁, ε₂)` (moved by rotations about `e₂` and `e₁` respectively),
//! `f₂(λ) = c₄λ⁴ + c₂λ² + c₀` with
//!
//! ```text
//! c₄ = I₁I₂,   c₂ = I₁k₁ + I₂k₂ + p²(I₁ + I₂ − I₃)²/I₃²,   c₀ = k₁k₂.
//! ```
//!
//! (Check: for a free body, `ℓᵢ = 0`, this gives `λ² = −Ω²` and Euler's
//! `λ² = (I₂ − I₃)(I₃ − I₁)Ω²/(I₁I₂)` with `p = I₃Ω`.)
//!
//! Standing on the end of its longest axis with `ℓᵢ > 0` and `Iᵢ > I₃`, both `kᵢ < 0`: degree 2, so
//! the spin is gyroscopically stabilised iff `c₂ > 0` and `c₂² − 4c₄c₀ > 0`. Write `P = p²`,
//! `αᵢ = m g ℓᵢ`, `βᵢ = (Iᵢ − I₃)/I₃²`, so `kᵢ = −αᵢ − βᵢP` and `c₂ = uP − v` with
//! `u = (I₁ + I₂ − I₃)²/I₃² − I₁β₁ − I₂β₂`, `v = I₁α₁ + I₂α₂`. The discriminant is the quadratic
//!
//! ```text
//! Δ(P) = (u² − 4I₁I₂β₁β₂) P² − (2uv + 4I₁I₂(α₁β₂ + α₂β₁)) P + (I₁α₁ − I₂α₂)²,
//! ```
//!
//! and the threshold is its largest root `P*` (where also `c₂ > 0`): [`Ellipsoid::spin_threshold`].
//!
//! For a spheroid (`a₁ = a₂ = a`, `I₁ = I₂ = I`) this factorises:
//! `u² − 4I²β² = (2I − I₃)²/I₃²`, `2uv + 8I²αβ = 4Iα(2I − I₃)²/I₃²`, constant `0`, so
//! `Δ = P (2I − I₃)²/I₃² (P − 4Iα)`, and the spin about the axis is stable iff
//!
//! ```text
//! p_ψ² > 4 I m g ℓ,   ℓ = a₃ − σh − a²/a₃,
//! ```
//!
//! the analogue of Maievskii's `p² > 4A₁mgl` with the centre of curvature of the contact point in
//! place of the fixed point: [`Ellipsoid::spheroid_threshold`].

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::time::Instant;

use common::plot::{verdict_series, Figure};
use common::{linspace, num, verdict_label};
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use routh::plot::{self, Overlay, PlotOptions};
use routh::stability_threshold;
use routh::{
    classified_steady_motions, classify_at, stability_atlas, AtlasOptions, Lagrangian, Matrix3,
    Routhian, Stability, Vector3,
};

/// A heavy ellipsoid on a smooth horizontal plane (paper Example 2). The height of the centre of
/// mass is the support function `C₃(γ) = √(γᵀDγ) − c₀·γ` (errata E6), the potential is
/// `U = +m g C₃` (errata E2) and the kinetic energy is (49): the rotation plus the vertical motion
/// of the centre of mass, `m (n, γ × ω)²` with `n = ∂C₃/∂γ`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    /// Central inertia tensor `I` (principal axes along the semi-axes).
    pub inertia: Matrix3<f64>,
    /// Semi-axes `(a₁, a₂, a₃)`.
    pub semi_axes: Vector3<f64>,
    /// Position `c₀` of the ellipsoid's centre relative to the centre of mass.
    pub offset: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}

/// Central inertia of a uniform solid ellipsoid of mass `m` and semi-axes `a`.
fn uniform_inertia(m: f64, a: &Vector3<f64>) -> Matrix3<f64> {
    let (a1, a2, a3) = (a.x * a.x, a.y * a.y, a.z * a.z);
    Matrix3::from_diagonal(&(m / 5.0 * Vector3::new(a2 + a3, a1 + a3, a1 + a2)))
}

impl Ellipsoid {
    /// A prolate spheroid `a = (1, 1, 2)`, `m = 1`, `g = 9.81`, with the inertia of the uniform
    /// body and its centre of mass `h = 0.2` below the geometric centre along `e₃`
    /// (`c₀ = 0.2 e₃`): an egg, heavier at the `−e₃` end.
    pub fn spheroid() -> Self {
        let a = Vector3::new(1.0, 1.0, 2.0);
        Ellipsoid {
            inertia: uniform_inertia(1.0, &a),
            semi_axes: a,
            offset: Vector3::new(0.0, 0.0, 0.2),
            mass: 1.0,
            g: 9.81,
        }
    }

    /// A uniform triaxial ellipsoid `a = (0.8, 1.2, 2)`, `m = 1`, `g = 9.81`.
    pub fn triaxial() -> Self {
        let a = Vector3::new(0.8, 1.2, 2.0);
        Ellipsoid {
            inertia: uniform_inertia(1.0, &a),
            semi_axes: a,
            offset: Vector3::zeros(),
            mass: 1.0,
            g: 9.81,
        }
    }

    /// `C₃(γ)`, the height of the centre of mass above the plane.
    pub fn height(&self, gamma: &Vector3<f64>) -> f64 {
        let d = Matrix3::from_diagonal(&self.semi_axes.component_mul(&self.semi_axes));
        gamma.dot(&(d * gamma)).sqrt() - self.offset.dot(gamma)
    }

    /// `ℓᵢ = a₃ − σh − aᵢ²/a₃` for the spin with `γ = σe₃` (see the module documentation).
    fn ell(&self, sigma: f64, i: usize) -> f64 {
        let a = &self.semi_axes;
        a.z - sigma * self.offset.z - a[i] * a[i] / a.z
    }

    /// The restricted second variation `(k₁, k₂)` at `γ = σe₃` by the hand formula.
    pub fn pole_hessian(&self, sigma: f64, p_psi: f64) -> (f64, f64) {
        let i3 = self.inertia[(2, 2)];
        let k = |i: usize| {
            -self.mass * self.g * self.ell(sigma, i)
                - p_psi * p_psi * (self.inertia[(i, i)] - i3) / (i3 * i3)
        };
        (k(0), k(1))
    }

    /// Hand formula for a spheroid (`a₁ = a₂`, `I₁ = I₂`): the spin with `γ = σe₃` is stable iff
    /// `p_ψ² > 4 I₁ m g ℓ`, `ℓ = a₃ − σh − a₁²/a₃`. Returns that `p_ψ` (`None` if `ℓ ≤ 0`).
    pub fn spheroid_threshold(&self, sigma: f64) -> Option<f64> {
        let l = self.ell(sigma, 0);
        (l > 0.0).then(|| (4.0 * self.inertia[(0, 0)] * self.mass * self.g * l).sqrt())
    }

    /// Hand formula for a triaxial body: the largest root `P*` of the discriminant `Δ(P)` of the
    /// module documentation, as `p_ψ = √P*` (`None` when the spin is not of degree 2 for large
    /// `p_ψ` or `Δ` has no positive root with `c₂ > 0`).
    pub fn spin_threshold(&self, sigma: f64) -> Option<f64> {
        let (i1, i2, i3) = (
            self.inertia[(0, 0)],
            self.inertia[(1, 1)],
            self.inertia[(2, 2)],
        );
        let mg = self.mass * self.g;
        let (al1, al2) = (mg * self.ell(sigma, 0), mg * self.ell(sigma, 1));
        let (be1, be2) = ((i1 - i3) / (i3 * i3), (i2 - i3) / (i3 * i3));
        if al1 <= 0.0 || al2 <= 0.0 || be1 <= 0.0 || be2 <= 0.0 {
            return None;
        }
        let s = i1 + i2 - i3;
        let u = s * s / (i3 * i3) - i1 * be1 - i2 * be2;
        let v = i1 * al1 + i2 * al2;
        let qa = u * u - 4.0 * i1 * i2 * be1 * be2;
        let qb = -(2.0 * u * v + 4.0 * i1 * i2 * (al1 * be2 + al2 * be1));
        let qc = (i1 * al1 - i2 * al2).powi(2);
        let disc = qb * qb - 4.0 * qa * qc;
        if qa <= 0.0 || disc < 0.0 {
            return None;
        }
        let big = (-qb + disc.sqrt()) / (2.0 * qa);
        (big > 0.0 && u * big > v).then(|| big.sqrt())
    }
}

const DSL: &str = r#"    #[derive(Lagrangian)]
    #[lagrangian(
        let d = diag(semi_axes.component_mul(semi_axes)),
        let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
        let n = grad(c3, gamma),
        kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
        potential = mass * g * c3,
    )]
    pub struct Ellipsoid { inertia: Matrix3<f64>, semi_axes: Vector3<f64>, offset: Vector3<f64>, mass: f64, g: f64 }"#;

/// One body: description, steady motions, spin thresholds, figure. Returns the figure's path.
fn study(
    name: &str,
    file: &str,
    body: &Ellipsoid,
    spheroid: bool,
    p_table: &[f64],
    p_max: f64,
) -> Result<std::path::PathBuf, Box<dyn Error>> {
    let e3 = Vector3::z();
    let i = body.inertia;
    println!("\n{name}");
    println!("{}", "-".repeat(name.chars().count()));
    println!(
        "semi-axes a = ({}, {}, {}), centre c₀ = ({}, {}, {}) from the centre of mass, \
         I = diag({}, {}, {}), m = {}, g = {}",
        body.semi_axes.x,
        body.semi_axes.y,
        body.semi_axes.z,
        body.offset.x,
        body.offset.y,
        body.offset.z,
        num(i[(0, 0)], 4),
        num(i[(1, 1)], 4),
        num(i[(2, 2)], 4),
        body.mass,
        body.g
    );
    println!("∠ = angle between the long axis e₃ and the upward vertical γ (0°: standing on the −e₃ end)");
    for &p in p_table {
        println!("\n p_ψ = {p}:");
        common::print_steady_table(&classified_steady_motions(body, p)?, &e3, "∠(γ,e₃)");
    }

    // Spins about the long axis held vertical, standing on either end (σ = ±1).
    println!("\nSpin about the vertical long axis, γ = σe₃ (ω = ψ̇γ): threshold of stability");
    let mut thresholds = Vec::new();
    // A centred body (c₀ = 0) is symmetric under γ → −γ: both ends give the same threshold.
    let sigmas: &[f64] = if body.offset == Vector3::zeros() {
        println!("  (c₀ = 0: standing on either end is the same by the symmetry γ → −γ)");
        &[1.0]
    } else {
        &[1.0, -1.0]
    };
    for &sigma in sigmas {
        let gamma = sigma * e3;
        let found = stability_threshold(body, gamma, 0.5, 40.0)?
            .ok_or("the verdict of the spin does not change in [0.5, 40]")?;
        let formula = if spheroid {
            body.spheroid_threshold(sigma)
        } else {
            body.spin_threshold(sigma)
        }
        .ok_or("no hand formula for this spin")?;
        let which = if spheroid {
            "p² = 4I₁mgℓ, ℓ = a₃ − σh − a₁²/a₃"
        } else {
            "largest root of Δ(p²)"
        };
        println!(
            "  σ = {:+}: C₃ = {:.3}; continuation: p_ψ = {found:.12}; hand formula \
             ({which}): p_ψ = {formula:.12}; rel. diff {:.1e}",
            sigma,
            body.height(&gamma),
            (found - formula).abs() / formula
        );
        for factor in [0.98, 1.02] {
            let p = factor * formula;
            let r = classify_at(body, gamma, p)?;
            let (k1, k2) = body.pole_hessian(sigma, p);
            let mut hand = [k1, k2];
            hand.sort_by(f64::total_cmp);
            println!(
                "      p_ψ = {:>6.3} × threshold: {:<26} restricted Hessian eigs {:+.6} {:+.6} \
                 (hand kᵢ {:+.6} {:+.6})",
                factor,
                verdict_label(r.verdict),
                r.restricted_hessian_eigenvalues[0],
                r.restricted_hessian_eigenvalues[1],
                hand[0],
                hand[1]
            );
        }
        thresholds.push((sigma, found));
    }

    // Figure: the families of steady motions coloured by verdict.
    let ps = linspace(0.0, p_max, 71);
    let mut pts = Vec::new();
    for &p in &ps {
        for r in classified_steady_motions(body, p)? {
            pts.push((r.report.verdict, p, body.height(&r.motion.gamma)));
        }
    }
    let mut fig = Figure::new(
        format!("{name}: steady motions"),
        "cyclic momentum p_ψ",
        "height of the centre of mass C₃(γ)",
    );
    fig.x_range = Some(0.0..p_max);
    fig.y_range = Some(0.0..2.5);
    fig.series.extend(verdict_series(&pts, 3));
    for (sigma, p) in thresholds {
        fig.vlines.push((
            p,
            format!(
                "spin threshold, standing on the {} end ({p:.3})",
                if sigmas.len() == 1 {
                    "±e₃"
                } else if sigma > 0.0 {
                    "−e₃"
                } else {
                    "+e₃"
                }
            ),
            if sigma > 0.0 {
                RGBColor(30, 90, 220)
            } else {
                RGBColor(120, 60, 160)
            },
        ));
    }
    fig.legend = SeriesLabelPosition::LowerRight;
    let path = common::out_dir("ellipsoid_on_plane")?.join(file);
    fig.save(&path, 900, 560)?;
    Ok(path)
}

fn main() -> Result<(), Box<dyn Error>> {
    let start = Instant::now();
    println!("Example 2 — heavy ellipsoid on a smooth horizontal plane");
    println!("========================================================");
    println!("The model (C₃ is the support function, errata E6; U = +m g C₃, errata E2):\n{DSL}");
    println!(
        "Amended potential (34): U_r(γ) = ½ p_ψ² / (γᵀIγ) + m g C₃(γ)   ((Jγ, γ) = (Iγ, γ) by E6)"
    );

    let spheroid = Ellipsoid::spheroid();
    let triaxial = Ellipsoid::triaxial();
    let mut figures = vec![
        study(
            "1. Prolate spheroid (egg)",
            "spheroid_steady_motions.svg",
            &spheroid,
            true,
            &[0.0, 9.0],
            14.0,
        )?,
        study(
            "2. Triaxial ellipsoid",
            "triaxial_steady_motions.svg",
            &triaxial,
            false,
            &[0.0, 9.0],
            14.0,
        )?,
    ];

    // errata E2: at rest the body lies stably on its flattest side (the minimum of C₃).
    let at_rest = classified_steady_motions(&triaxial, 0.0)?;
    let stable: Vec<_> = at_rest
        .iter()
        .filter(|r| r.report.verdict == Stability::SecularlyStable)
        .collect();
    println!("\nerrata E2 check (triaxial body, p_ψ = 0): secularly stable rest positions:");
    for r in &stable {
        println!(
            "  γ = {}, C₃ = {:.6} (smallest semi-axis a₁ = {}), U_r = {:.6}",
            common::fmt_vec(&r.motion.gamma),
            triaxial.height(&r.motion.gamma),
            triaxial.semi_axes.x,
            triaxial.amended_potential(&r.motion.gamma, 0.0)
        );
    }

    // --- Atlas of the spin on the end of a spheroid over (its semi-axis a₃, p_ψ) -----------------
    let spheroid_with = |a3: f64| {
        let a = Vector3::new(1.0, 1.0, a3);
        Ellipsoid {
            inertia: uniform_inertia(spheroid.mass, &a),
            semi_axes: a,
            ..spheroid.clone()
        }
    };
    let (a3_range, p_range) = ((1.3, 3.0), (0.0, 16.0));
    let atlas = stability_atlas(
        |a3, p| (spheroid_with(a3), p),
        Vector3::z(),
        a3_range,
        p_range,
        &AtlasOptions {
            nx: 41,
            ny: 41,
            ..AtlasOptions::default()
        },
    )?;
    let closed = |a3: f64| {
        spheroid_with(a3)
            .spheroid_threshold(1.0)
            .unwrap_or(f64::NAN)
    };
    println!(
        "\nStability atlas of the spin on the end (γ = e₃) over (a₃, p_ψ) ∈ [{}, {}] × [{}, {}] \
         (a₁ = a₂ = 1, uniform density):",
        a3_range.0, a3_range.1, p_range.0, p_range.1
    );
    for b in &atlas.boundaries {
        let worst = b
            .points
            .iter()
            .map(|&(a3, p)| (p - closed(a3)).abs() / closed(a3))
            .fold(0.0f64, f64::max);
        println!(
            "  {} boundary: {} traced points, largest relative distance to p² = 4I₁mgℓ: {worst:.1e}",
            b.kind,
            b.points.len()
        );
    }
    let path = common::out_dir("ellipsoid_on_plane")?.join("spheroid_atlas.svg");
    plot::stability_atlas_svg(
        &atlas,
        &path,
        &PlotOptions {
            title: "Spheroid spinning on its end: verdict over (a₃, p_ψ)".into(),
            x_label: "semi-axis along the symmetry axis a₃".into(),
            y_label: "cyclic momentum p_ψ".into(),
            overlays: vec![Overlay {
                label: "closed form p² = 4I₁mgℓ, ℓ = a₃ − h − a₁²/a₃".into(),
                points: linspace(a3_range.0, a3_range.1, 200)
                    .into_iter()
                    .map(|a3| (a3, closed(a3)))
                    .filter(|q| q.1.is_finite())
                    .collect(),
            }],
            ..PlotOptions::default()
        },
    )?;
    figures.push(path);

    println!("\nFigures:");
    for f in &figures {
        println!("  {}", f.display());
    }
    println!("Done in {:.2} s.", start.elapsed().as_secs_f64());
    Ok(())
}
