//! Paper Example 3 (52)–(61): steady translations and screw motions of a rigid body in an ideal fluid.
//! Run: `cargo run --release --example body_in_fluid` (figures in `out/body_in_fluid/`).
//!
//! Kirchhoff's equations (52) become (8) with the Lagrangian of errata E3
//! (`routh::fluid::kirchhoff_lagrangian`), declared below with `#[derive(Lagrangian)]`; its steady
//! motions are classified by the Routh machinery.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::time::Instant;

use common::plot::{verdict_series, Figure, Series, Style};
use common::{linspace, lpad, rpad, verdict_label};
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use routh::fluid::{kirchhoff_lagrangian, FluidParameters};
use routh::plot::{self, Overlay, PlotOptions};
use routh::stability_threshold;
use routh::{
    classified_steady_motions, classify_at, simulate_full, stability_atlas, AtlasOptions,
    Lagrangian, Matrix3, RouthError, SimOptions, Vector3,
};

/// A rigid body in an ideal fluid as a body with a fixed point (errata E3, E7):
/// `L(ω, γ) = ½(Aω, ω) + (Λγ, ω) − ½(Πγ, γ)` with the matrices of [`kirchhoff_lagrangian`],
/// γ the body-frame unit vector along the impulse.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(a_kin * omega),
    linear = (lin * gamma).dot(omega),
    potential = 0.5 * gamma.dot(pot * gamma),
)]
pub struct FluidBody {
    /// `A = a − bᵀc⁻¹b`.
    pub a_kin: Matrix3<f64>,
    /// `Λ = k bᵀc⁻¹`.
    pub lin: Matrix3<f64>,
    /// `Π = k²c⁻¹`.
    pub pot: Matrix3<f64>,
}

impl From<&FluidParameters> for FluidBody {
    fn from(f: &FluidParameters) -> Self {
        FluidBody {
            a_kin: f.kinetic,
            lin: f.linear,
            pot: f.potential,
        }
    }
}

/// The matrices `a`, `b`, `c` of Kirchhoff's kinetic energy (53) of a body (with its added
/// masses).
#[derive(Debug, Clone, Copy)]
pub struct Kirchhoff {
    /// Rotational block `a`.
    pub a: Matrix3<f64>,
    /// Coupling block `b` (`(bω, v)`).
    pub b: Matrix3<f64>,
    /// Translational block `c`.
    pub c: Matrix3<f64>,
}

impl Kirchhoff {
    /// An elongated body of revolution about `e₃` with three planes of symmetry (`b = 0`):
    /// `a = diag(1, 1, 0.4)`, `c = diag(3, 3, 1.5)` — less added mass along the axis than
    /// across it.
    pub fn body_of_revolution() -> Self {
        Kirchhoff {
            a: Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 0.4)),
            b: Matrix3::zeros(),
            c: Matrix3::from_diagonal(&Vector3::new(3.0, 3.0, 1.5)),
        }
    }

    /// A body without symmetry (a screw-like body, `b ≠ 0` and not symmetric).
    pub fn chiral() -> Self {
        Kirchhoff {
            a: Matrix3::new(1.2, 0.05, 0.0, 0.05, 1.0, 0.02, 0.0, 0.02, 0.5),
            b: Matrix3::new(0.2, 0.05, 0.0, 0.0, 0.1, 0.03, 0.02, 0.0, 0.3),
            c: Matrix3::new(3.0, 0.1, 0.0, 0.1, 2.5, 0.0, 0.0, 0.0, 1.5),
        }
    }

    /// The reduced Lagrangian's matrices at impulse magnitude `k`.
    pub fn parameters(&self, k: f64) -> Result<FluidParameters, RouthError> {
        kirchhoff_lagrangian(self.a, self.b, self.c, k)
    }

    /// `T(ω, v)` of (53).
    pub fn energy(&self, omega: &Vector3<f64>, v: &Vector3<f64>) -> f64 {
        0.5 * (omega.dot(&(self.a * omega)) + 2.0 * v.dot(&(self.b * omega)) + v.dot(&(self.c * v)))
    }

    /// Kirchhoff's stability bound for the spinning body of revolution moving along its axis
    /// (`b = 0`, `a = diag(A₁, A₁, A₃)`, `c = diag(c₁, c₁, c₃)`). On the sphere the potential
    /// `½k²(c⁻¹γ, γ)` is `const + ½k²(1/c₃ − 1/c₁)γ₃²`, whose second variation at `γ = e₃` is
    /// `−k²(1/c₃ − 1/c₁)`: the same as the Lagrange top's `−m g l`. The top's analysis then
    /// carries over (the quartic `f₂` of the example `ellipsoid_on_plane`): the motion along the axis is stable iff
    /// `p_ψ² > 4A₁k²(1/c₃ − 1/c₁)`, Maievskii's bound with `m g l → k²(1/c₃ − 1/c₁)`.
    pub fn axial_threshold(&self, k: f64) -> f64 {
        let (a1, c1, c3) = (self.a[(0, 0)], self.c[(0, 0)], self.c[(2, 2)]);
        (4.0 * a1 * k * k * (1.0 / c3 - 1.0 / c1)).sqrt()
    }
}

/// The state `(ω₀, γ₀)` of the body moving along its axis `e₃`, its axis tilted by `tilt` radians
/// away from the impulse, spinning so that the cyclic momentum (9) is `p_psi`
/// (`b = 0`, diagonal `A`).
pub fn perturbed_axial(f: &FluidParameters, p_psi: f64, tilt: f64) -> (Vector3<f64>, Vector3<f64>) {
    let gamma0 = Vector3::new(tilt.sin(), 0.0, tilt.cos());
    let omega0 = Vector3::new(0.0, 0.0, p_psi / (f.kinetic[(2, 2)] * tilt.cos()));
    (omega0, gamma0)
}

/// Prints `label` followed by the three rows of `m`, aligned under each other.
fn print_mat(label: &str, m: &Matrix3<f64>) {
    let indent = " ".repeat(common::display_width(label));
    for i in 0..3 {
        println!(
            "{}[{:+.5}, {:+.5}, {:+.5}]",
            if i == 0 { label } else { indent.as_str() },
            m[(i, 0)],
            m[(i, 1)],
            m[(i, 2)]
        );
    }
}

fn describe(name: &str, body: &Kirchhoff, f: &FluidParameters) {
    println!("\n{name}");
    println!("{}", "-".repeat(name.chars().count()));
    print_mat("  a = ", &body.a);
    print_mat("  b = ", &body.b);
    print_mat("  c = ", &body.c);
    println!("kirchhoff_lagrangian(a, b, c, k = {}) (errata E3):", f.k);
    print_mat("  A = a − bᵀc⁻¹b = ", &f.kinetic);
    print_mat("  Λ = k bᵀc⁻¹    = ", &f.linear);
    print_mat("  Π = k² c⁻¹     = ", &f.potential);
    // E3 identities at a sample state: L = T − (p, v), ∂L/∂ω = ∂T/∂ω, ∂L/∂γ = −k v.
    let model = FluidBody::from(f);
    let (w, g) = (Vector3::new(0.3, -0.7, 1.1), Vector3::new(0.48, -0.6, 0.64));
    let v = f.velocity(&w, &g);
    let t = body.energy(&w, &v);
    let e1 = (model.lagrangian(&w, &g) - (t - f.impulse(&g).dot(&v))).abs();
    let e2 = (model.dl_domega(&w, &g) - (body.a * w + body.b.transpose() * v)).norm();
    let e3 = (model.dl_dgamma(&w, &g) + f.k * v).norm();
    println!(
        "  checks at a sample (ω, γ): |L − (T − (p, v))| = {e1:.1e}, |∂L/∂ω − ∂T/∂ω| = {e2:.1e}, \
         |∂L/∂γ + k v| = {e3:.1e}"
    );
}

/// Table of steady motions with the body's linear and angular velocities.
fn table(model: &FluidBody, f: &FluidParameters, p: f64) -> Result<(), Box<dyn Error>> {
    println!(
        "\n p_ψ = {p} (Kirchhoff's constant (55) (∂T/∂ω, ∂T/∂v) = k·p_ψ = {}):",
        f.kirchhoff_constant(p)
    );
    println!(
        "  {}  {}  {}  {}  {}  verdict",
        lpad("γ = p/k (body frame)", 33),
        rpad("ψ̇", 9),
        lpad("v (body frame)", 33),
        rpad("∠(v,γ)", 8),
        rpad("deg", 3),
    );
    for r in classified_steady_motions(model, p)? {
        let g = r.motion.gamma;
        let omega = r.motion.psi_dot * g;
        let v = f.velocity(&omega, &g);
        println!(
            "  {:<33}  {:>+9.5}  {:<33}  {:>7.2}°  {:>3}  {}{}",
            common::fmt_vec(&g),
            r.motion.psi_dot,
            common::fmt_vec(&v),
            common::angle_deg(&v.normalize(), &g),
            r.report.degree_of_instability,
            verdict_label(r.report.verdict),
            if r.motion.isolated {
                ""
            } else {
                " (one of a circle)"
            }
        );
    }
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let start = Instant::now();
    let out = common::out_dir("body_in_fluid")?;
    let e3 = Vector3::z();
    println!("Example 3 — rigid body in an ideal fluid (Kirchhoff's equations (52) as (8))");
    println!("============================================================================");
    println!("T(ω, v) = ½((aω, ω) + 2(bω, v) + (cv, v)),  p = bω + cv = kγ,  v = c⁻¹(kγ − bω)");
    println!("L(ω, γ) = ½(Aω, ω) + (Λγ, ω) − ½(Πγ, γ)   (errata E3)");
    println!(
        "Steady motions: ω = ψ̇γ — the body turns about its impulse while translating (a screw"
    );
    println!(
        "motion; a pure translation when ψ̇ = 0). p_ψ = (∂L/∂ω, γ) is the reduced cyclic momentum;"
    );
    println!("Kirchhoff's constant (55) is k·p_ψ (errata E7).");

    // --- 1. Elongated body of revolution -------------------------------------------------------
    let k = 1.0;
    let rev = Kirchhoff::body_of_revolution();
    let f = rev.parameters(k)?;
    let model = FluidBody::from(&f);
    describe("1. Elongated body of revolution (b = 0)", &rev, &f);
    for p in [0.0, 0.3] {
        table(&model, &f, p)?;
    }
    let formula = rev.axial_threshold(k);
    let found = stability_threshold(&model, e3, 0.2 * formula, 3.0 * formula)?
        .ok_or("no change of verdict for the axial motion")?;
    println!("\nMotion along the axis (γ = e₃) spinning about it: stability threshold");
    println!("  continuation, event on the branch: p_ψ = {found:.12}");
    println!("  formula p_ψ² = 4A₁k²(1/c₃ − 1/c₁): p_ψ = {formula:.12}");
    println!(
        "  relative difference {:.1e};  Kirchhoff's constant k·p_ψ = {:.6}, spin ω₃ = p_ψ/A₃ = {:.6}",
        (found - formula).abs() / formula,
        f.kirchhoff_constant(formula),
        formula / f.kinetic[(2, 2)]
    );
    for factor in [0.9, 1.1] {
        let r = classify_at(&model, e3, factor * formula)?;
        println!(
            "  p_ψ = {factor} × threshold: {} (degree {}, roots of f₂ {})",
            verdict_label(r.verdict),
            r.degree_of_instability,
            r.f2_roots
                .iter()
                .map(|z| format!("{:+.4}{:+.4}i", z.re, z.im))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }

    // Figure 1: steady motions against p_ψ.
    let ps = linspace(0.0, 3.0, 61);
    let mut pts = Vec::new();
    for &p in &ps {
        for r in classified_steady_motions(&model, p)? {
            pts.push((r.report.verdict, p, common::angle_deg(&r.motion.gamma, &e3)));
        }
    }
    let mut fig = Figure::new(
        "Body of revolution in a fluid: steady motions",
        "reduced cyclic momentum p_ψ (Kirchhoff's constant is k·p_ψ, k = 1)",
        "angle between the impulse γ and the axis e₃ (degrees)",
    );
    fig.x_range = Some(0.0..3.0);
    fig.y_range = Some(-5.0..185.0);
    fig.series.extend(verdict_series(&pts, 3));
    fig.vlines.push((
        found,
        format!("p² = 4A₁k²(1/c₃ − 1/c₁) ({found:.3})"),
        RGBColor(30, 90, 220),
    ));
    fig.legend = SeriesLabelPosition::Coordinate(420, 40);
    let path1 = out.join("steady_motions.svg");
    fig.save(&path1, 900, 560)?;

    // Figure 2: motion along the axis, slightly tilted, below and above the threshold.
    let t_end = 80.0;
    let times = linspace(0.0, t_end, 1601);
    let tilt = 0.01;
    let mut fig2 = Figure::new(
        format!("Body moving along its axis, tilted by {tilt} rad from the impulse"),
        "time t",
        "angle between the axis e₃ and the impulse (degrees)",
    );
    println!("\nAxis tilted by {tilt} rad from the impulse (simulate_full), t ∈ [0, {t_end}]:");
    println!(
        "  {}  {}  {}  {}  {}",
        rpad("p_ψ/threshold", 13),
        lpad("verdict at e₃", 26),
        rpad("max angle (deg)", 15),
        rpad("|ΔE|", 9),
        rpad("|Δp_ψ|", 9)
    );
    for (factor, color) in [(0.9, RGBColor(210, 30, 30)), (1.1, RGBColor(30, 90, 220))] {
        let p = factor * formula;
        let (w0, g0) = perturbed_axial(&f, p, tilt);
        let traj = simulate_full(
            &model,
            w0,
            g0,
            t_end,
            &SimOptions::with_tolerances(1e-11, 1e-13).at_times(times.clone()),
        )?;
        let angle: Vec<(f64, f64)> = traj
            .t
            .iter()
            .zip(&traj.gamma)
            .map(|(&t, g)| (t, common::angle_deg(&g.normalize(), &e3)))
            .collect();
        let max = angle.iter().fold(0.0f64, |m, a| m.max(a.1));
        let verdict = classify_at(&model, e3, p)?.verdict;
        println!(
            "  {:>13.2}  {:<26}  {:>15.3}  {:>9.1e}  {:>9.1e}",
            factor,
            verdict_label(verdict),
            max,
            traj.energy_drift(),
            traj.p_psi_drift()
        );
        fig2.series.push(Series::new(
            format!("p_ψ = {factor} × threshold: {}", verdict_label(verdict)),
            color,
            Style::Line(2),
            angle,
        ));
    }
    let y_max = fig2
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(0.0f64, f64::max);
    fig2.y_range = Some(0.0..1.3 * y_max);
    let path2 = out.join("axial_motion_tilt.svg");
    fig2.save(&path2, 900, 500)?;

    // --- Atlas of the axial motion over (added mass c₃ along the axis, p_ψ) ---------------------
    let (c3_range, p_range) = ((0.8, 2.8), (0.0, 2.5));
    let body_with = |c3: f64| Kirchhoff {
        c: Matrix3::from_diagonal(&Vector3::new(rev.c[(0, 0)], rev.c[(1, 1)], c3)),
        ..rev
    };
    let atlas = stability_atlas(
        |c3, p| {
            let f = body_with(c3)
                .parameters(k)
                .expect("c stays positive definite over the range");
            (FluidBody::from(&f), p)
        },
        e3,
        c3_range,
        p_range,
        &AtlasOptions {
            nx: 41,
            ny: 41,
            ..AtlasOptions::default()
        },
    )?;
    println!(
        "\nStability atlas of the motion along the axis over (c₃, p_ψ) ∈ [{}, {}] × [{}, {}]:",
        c3_range.0, c3_range.1, p_range.0, p_range.1
    );
    let closed = |c3: f64| body_with(c3).axial_threshold(k);
    for b in &atlas.boundaries {
        let worst = b
            .points
            .iter()
            .map(|&(c3, p)| (p - closed(c3)).abs() / closed(c3).max(1e-300))
            .fold(0.0f64, f64::max);
        println!(
            "  {} boundary: {} traced points, largest relative distance to p_ψ² = 4A₁k²(1/c₃ − 1/c₁): {worst:.1e}",
            b.kind,
            b.points.len()
        );
    }
    let path3 = out.join("axial_motion_atlas.svg");
    plot::stability_atlas_svg(
        &atlas,
        &path3,
        &PlotOptions {
            title: "Body of revolution moving along its axis: verdict over (c₃, p_ψ)".into(),
            x_label: "added mass along the axis c₃".into(),
            y_label: "cyclic momentum p_ψ".into(),
            overlays: vec![Overlay {
                label: "closed form p_ψ² = 4A₁k²(1/c₃ − 1/c₁)".into(),
                points: linspace(c3_range.0, c3_range.1, 200)
                    .into_iter()
                    .map(|c3| (c3, closed(c3)))
                    .filter(|p| p.1.is_finite())
                    .collect(),
            }],
            ..PlotOptions::default()
        },
    )?;

    // --- 2. A body without symmetry -------------------------------------------------------------
    let chiral = Kirchhoff::chiral();
    let f2 = chiral.parameters(k)?;
    let model2 = FluidBody::from(&f2);
    describe("2. Screw-like body without symmetry (b ≠ 0)", &chiral, &f2);
    for p in [0.0, 0.5, 1.5] {
        table(&model2, &f2, p)?;
    }

    println!("\nFigures:");
    println!("  {}", path1.display());
    println!("  {}", path2.display());
    println!("  {}", path3.display());
    println!("Done in {:.2} s.", start.elapsed().as_secs_f64());
    Ok(())
}
