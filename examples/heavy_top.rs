//! The heavy symmetric (Lagrange) top: its steady motions, their stability, and its bifurcation
//! diagram over the cyclic momentum, whose events sit on Maievskii's bound `p_ψ² = 4A₁mgl` and the
//! secular bound `p_ψ² = mglC²/(C − A₁)`.
//!
//! Last, the attitude of the body: the three classic apex loci of a top (looping, cuspidal,
//! wavy), started by the classical criterion and named from the simulated precession rate.
//!
//! Run with `cargo run --release --example heavy_top`. Figures go to `out/heavy_top/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::time::Instant;

use common::plot::{Figure, Series, Style};
use common::{linspace, verdict_label};
use derived_models::{classified_steady_motions, report_at};
use plotters::prelude::{RGBColor, SeriesLabelPosition};

use routh::plot::{self, DiagramAxis, Overlay, PlotOptions};
use routh::sim::attitude::{classify_apex_locus, ApexLocus};
use routh::{
    bifurcation_diagram, simulate_full, stability_atlas_parallel, AtlasOptions,
    ContinuationOptions, EventKind, Lagrangian, Routhian, SimOptions, Vector3,
};

// The body, declared here: `#[derive(Lagrangian)]` differentiates L at build time.
/// The Lagrange top about its fixed point: `L = ½(A₁(ω₁² + ω₂²) + Cω₃²) − m g l γ₃`, the centre
/// of mass at distance `l` from the fixed point on the symmetry axis `e₃`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = mass * g * l * gamma.z,
)]
struct LagrangeTop {
    /// Transverse moment of inertia about the fixed point, `A₁`.
    #[lagrangian(latex = "A_1")]
    a1: f64,
    /// Axial moment of inertia, `C`.
    #[lagrangian(latex = "C")]
    c: f64,
    /// Mass `m`.
    mass: f64,
    /// Gravity `g`.
    g: f64,
    /// Distance `l` from the fixed point to the centre of mass.
    l: f64,
}

impl LagrangeTop {
    /// The top of the example, in units where `A₁ = m = g = l = 1`: `C = 1.25`, an oblate top
    /// (`C > A₁`, still `C ≤ 2A₁`), chosen so that the sleeping top passes through all three
    /// verdicts: unstable, gyroscopically stabilised, secularly stable.
    fn example() -> Self {
        LagrangeTop {
            a1: 1.0,
            c: 1.25,
            mass: 1.0,
            g: 1.0,
            l: 1.0,
        }
    }

    /// The Lagrange top `(A₁, C, m g l)` in units where `m = g = 1`.
    fn with_mgl(a1: f64, c: f64, mgl: f64) -> Self {
        LagrangeTop {
            a1,
            c,
            mass: 1.0,
            g: 1.0,
            l: mgl,
        }
    }

    /// `m g l`.
    fn mgl(&self) -> f64 {
        self.mass * self.g * self.l
    }

    /// Maievskii's bound: the sleeping top is stable iff `p_ψ² > 4 A₁ m g l`.
    fn maievskii_p(&self) -> f64 {
        (4.0 * self.a1 * self.mgl()).sqrt()
    }

    /// The `p_ψ` above which the sleeping top is a minimum of the amended potential (secular
    /// stability), for an oblate top (`C > A₁`): the restricted second variation at `γ = e₃` is
    /// `p²(C − A₁)/C² − m g l` (twice), positive iff `p² > m g l C²/(C − A₁)`. `None` for
    /// `C ≤ A₁` (never secularly stable).
    fn secular_p(&self) -> Option<f64> {
        (self.c > self.a1).then(|| (self.mgl() * self.c * self.c / (self.c - self.a1)).sqrt())
    }

    /// The family of tilted steady motions: on the sphere with `z = γ₃`,
    /// `U_r = p²/(2(A₁ + (C − A₁)z²)) + m g l z`, and `dU_r/dz = 0` at
    /// `m g l (A₁ + (C − A₁)z²)² = p² (C − A₁) z`. Returns the `p_ψ ≥ 0` of the member at height
    /// `z` (`None` where there is none, i.e. `(C − A₁)z ≤ 0`).
    fn tilted_family_p(&self, z: f64) -> Option<f64> {
        let d = self.c - self.a1;
        let n = self.a1 + d * z * z;
        (d * z > 0.0).then(|| (self.mgl() * n * n / (d * z)).sqrt())
    }

    /// The initial state of a sleeping top tilted by `tilt` radians about `e₂` with the spin
    /// chosen so that the cyclic momentum (9) is exactly `p_psi`: `γ₀ = (sin ε, 0, cos ε)`,
    /// `ω₀ = (0, 0, p_ψ/(C cos ε))`. Returns `(ω₀, γ₀)`.
    fn perturbed_sleeping(&self, p_psi: f64, tilt: f64) -> (Vector3<f64>, Vector3<f64>) {
        let gamma0 = Vector3::new(tilt.sin(), 0.0, tilt.cos());
        let omega0 = Vector3::new(0.0, 0.0, p_psi / (self.c * tilt.cos()));
        (omega0, gamma0)
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let start = Instant::now();
    let top = LagrangeTop::example();
    let out = common::out_dir("heavy_top")?;
    let e3 = Vector3::z();

    println!("Heavy symmetric (Lagrange) top — Bourov & Chevallier, ZAMM 1998, with errata");
    println!("=========================================================================");
    println!(
        "L = ½(A₁(ω₁² + ω₂²) + Cω₃²) − m g l γ₃,  A₁ = {}, C = {}, m = {}, g = {}, l = {}",
        top.a1, top.c, top.mass, top.g, top.l
    );
    println!("Amended potential (34): U_r(γ) = ½ p_ψ² / (A₁(γ₁² + γ₂²) + Cγ₃²) + m g l γ₃");

    // --- Steady motions at a few values of p_ψ -------------------------------------------------
    println!("\nSteady motions (critical points of U_r on the sphere) and their verdicts");
    println!("tilt = angle between the symmetry axis e₃ and the upward vertical γ");
    for p in [1.0, 2.2, 3.0] {
        let rows = classified_steady_motions(&top, p)?;
        println!("\n p_ψ = {p}:");
        common::print_steady_table(&rows, &e3, "tilt");
    }

    // --- The bifurcation diagram over p_ψ ---------------------------------------------------------
    let formula = top.maievskii_p();
    let range = (0.0, 5.0);
    let checked =
        bifurcation_diagram(|p| (top.clone(), p), range, &ContinuationOptions::default())?;
    let diagram = &checked;
    println!(
        "\nBifurcation diagram over p_ψ ∈ [{}, {}] (pseudo-arclength continuation, events located \
         by their defining equations)",
        range.0, range.1
    );
    for (i, b) in diagram.branches.iter().enumerate() {
        let first = &b.points[0];
        let last = &b.points[b.points.len() - 1];
        println!(
            "  branch {i}: {} points, {}, p_ψ from {:.6} to {:.6}, tilt from {:.2}° to {:.2}°",
            b.points.len(),
            if b.isolated {
                "isolated steady motions"
            } else {
                "circles of tilted steady motions"
            },
            first.s,
            last.s,
            first.steady.gamma.z.clamp(-1.0, 1.0).acos().to_degrees(),
            last.steady.gamma.z.clamp(-1.0, 1.0).acos().to_degrees(),
        );
    }
    println!(
        "\n  {:<18}  {:>16}  {:<38}  {:>16}  {:>8}",
        "event", "p_ψ found", "closed form", "p_ψ closed form", "|Δp_ψ|"
    );
    for e in &diagram.events {
        let (name, exact) = match e.kind {
            EventKind::HamiltonianHopf => ("Maievskii p² = 4A₁mgl", Some(formula)),
            EventKind::BranchPoint => ("secular p² = mglC²/(C − A₁)", top.secular_p()),
            EventKind::Fold => ("fold of the tilted circles", None),
            EventKind::ArnoldDegenerate | EventKind::Resonance => ("nonlinear event", None),
        };
        let exact = exact.unwrap_or(f64::NAN);
        println!(
            "  {:<18}  {:>16.12}  {:<38}  {:>16.12}  {:>8.1e}",
            e.kind.to_string(),
            e.s,
            name,
            exact,
            (e.s - exact).abs()
        );
        println!("      on branch {}: {} → {}", e.branch, e.before, e.after);
    }
    println!(
        "  count checks against global searches between events: {}",
        if checked.consistent() {
            "all agree"
        } else {
            "MISMATCH"
        }
    );
    for c in &checked.checks {
        println!(
            "    p_ψ = {:.4}: {} steady motions on the branches, {} found by steady_motions",
            c.s, c.on_branches, c.searched
        );
    }
    println!(
        "\n  {}  {}  {}  {}  roots of f₂",
        common::rpad("p_ψ", 9),
        common::rpad("restricted Hessian eigs", 23),
        common::rpad("deg", 3),
        common::lpad("verdict", 26)
    );
    for factor in [0.5, 0.9, 0.999, 1.001, 1.1, 1.25, 1.5] {
        let p = factor * formula;
        let r = report_at(&top, e3, p)?;
        let roots: Vec<String> = r
            .f2_roots
            .iter()
            .map(|z| format!("{:+.4}{:+.4}i", z.re, z.im))
            .collect();
        println!(
            "  {:>9.5}  {:>+11.6} {:>+11.6}  {:>3}  {:<26}  {}",
            p,
            r.restricted_hessian_eigenvalues[0],
            r.restricted_hessian_eigenvalues[1],
            r.degree_of_instability,
            verdict_label(r.verdict),
            roots.join(", ")
        );
    }

    // --- Figure 1: the bifurcation diagram ------------------------------------------------------
    let tilted: Vec<(f64, f64)> = linspace(0.02, 1.0, 200)
        .into_iter()
        .filter_map(|z| top.tilted_family_p(z).map(|p| (p, z.acos().to_degrees())))
        .filter(|&(p, _)| p <= range.1)
        .collect();
    let path1 = out.join("bifurcation_diagram.svg");
    // The tilted circles drawn with their own verdict (stability modulo the symmetry about e₃),
    // not classify's "degenerate" along a circle.
    let drawn = plot::with_circle_verdicts(diagram, |p| (top.clone(), p), e3);
    plot::bifurcation_diagram_svg(
        &drawn,
        &path1,
        &PlotOptions {
            title: format!(
                "Lagrange top (A₁ = {}, C = {}, mgl = {}): steady motions against p_ψ",
                top.a1,
                top.c,
                top.mgl()
            ),
            x_label: "cyclic momentum p_ψ".into(),
            y: DiagramAxis::Tilt,
            event_values: true,
            overlays: vec![Overlay {
                label: "tilted circles, closed form".into(),
                points: tilted,
            }],
            ..PlotOptions::default()
        },
    )?;

    // --- Figure 2: the stability atlas of the sleeping top over (mgl, p_ψ) ----------------------
    let (mgl_range, p_range) = ((0.25, 2.0), (0.0, 5.0));
    let (a1, c) = (top.a1, top.c);
    let atlas = stability_atlas_parallel(
        |mgl, p| (LagrangeTop::with_mgl(a1, c, mgl), p),
        e3,
        mgl_range,
        p_range,
        &AtlasOptions {
            nx: 61,
            ny: 61,
            ..AtlasOptions::default()
        },
    )?;
    // The traced curves against the closed forms, in p_ψ at the traced mgl.
    let maievskii = |mgl: f64| (4.0 * a1 * mgl).sqrt();
    let secular = |mgl: f64| (mgl * c * c / (c - a1)).sqrt();
    println!(
        "\nStability atlas of the sleeping top over (mgl, p_ψ) ∈ [{}, {}] × [{}, {}], {} × {} grid",
        mgl_range.0,
        mgl_range.1,
        p_range.0,
        p_range.1,
        atlas.x.len(),
        atlas.y.len()
    );
    for b in &atlas.boundaries {
        let (name, exact): (&str, &dyn Fn(f64) -> f64) = match b.kind {
            EventKind::HamiltonianHopf => ("Maievskii p² = 4A₁mgl", &maievskii),
            _ => ("secular p² = mglC²/(C − A₁)", &secular),
        };
        let worst = b
            .points
            .iter()
            .map(|&(mgl, p)| (p - exact(mgl)).abs() / exact(mgl).max(1e-300))
            .fold(0.0f64, f64::max);
        println!(
            "  {} boundary: {} traced points, largest relative distance to {name}: {worst:.1e}",
            b.kind,
            b.points.len()
        );
    }
    let curve = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
        linspace(mgl_range.0, mgl_range.1, 100)
            .into_iter()
            .map(|m| (m, f(m)))
            .collect()
    };
    let path3 = out.join("sleeping_top_atlas.svg");
    plot::stability_atlas_svg(
        &atlas,
        &path3,
        &PlotOptions {
            title: "Sleeping Lagrange top: verdict over (mgl, p_ψ)".into(),
            x_label: "weight × distance mgl".into(),
            y_label: "cyclic momentum p_ψ".into(),
            overlays: vec![
                Overlay {
                    label: "closed form p² = 4A₁mgl".into(),
                    points: curve(&maievskii),
                },
                Overlay {
                    label: "closed form p² = mglC²/(C − A₁)".into(),
                    points: curve(&secular),
                },
            ],
            ..PlotOptions::default()
        },
    )?;

    // --- Figure 2: perturbed sleeping top below and above the bound -----------------------------
    let t_end = 60.0;
    let times = linspace(0.0, t_end, 1201);
    let eps = 0.01;
    let mut fig2 = Figure::new(
        format!("Sleeping top tilted by {eps} rad: just below and just above Maievskii's bound"),
        "time t",
        "tilt arccos γ₃ (degrees)",
    );
    println!(
        "\nPerturbed sleeping top (tilted by {eps} rad, simulate_full, DOP853, rtol = 1e-11), t ∈ [0, {t_end}]"
    );
    println!(
        "  {:>12}  {:>9}  {:<26}  {:>14}  {:>10}  {:>10}",
        "p_ψ/p_Maiev", "p_ψ", "verdict at e₃", "max tilt (deg)", "|ΔE|", "|Δp_ψ|"
    );
    // Told apart without colour too: the unstable run dashed, the stabilised one solid.
    for (factor, color, style) in [
        (0.95, RGBColor(210, 30, 30), Style::Dashed(2)),
        (1.05, RGBColor(30, 90, 220), Style::Line(2)),
    ] {
        let p = factor * formula;
        let (w0, g0) = top.perturbed_sleeping(p, eps);
        let opts = SimOptions::with_tolerances(1e-11, 1e-13).at_times(times.clone());
        let traj = simulate_full(&top, w0, g0, t_end, &opts)?;
        let tilt: Vec<(f64, f64)> = traj
            .t
            .iter()
            .zip(&traj.gamma)
            .map(|(&t, g)| (t, (g.z / g.norm()).clamp(-1.0, 1.0).acos().to_degrees()))
            .collect();
        let max_tilt = tilt.iter().fold(0.0f64, |m, p| m.max(p.1));
        let verdict = report_at(&top, e3, p)?.verdict;
        println!(
            "  {:>12.2}  {:>9.5}  {:<26}  {:>14.3}  {:>10.2e}  {:>10.2e}",
            factor,
            p,
            verdict_label(verdict),
            max_tilt,
            traj.energy_drift(),
            traj.p_psi_drift()
        );
        fig2.series.push(Series::new(
            format!("p_ψ = {factor} × √(4A₁mgl): {}", verdict_label(verdict)),
            color,
            style,
            tilt,
        ));
    }
    fig2.legend = SeriesLabelPosition::UpperRight;
    let y_max = fig2
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold(0.0f64, f64::max);
    fig2.y_range = Some(0.0..1.3 * y_max);
    let path2 = out.join("sleeping_top_tilt.svg");
    fig2.save(&path2, 900, 500)?;

    // Cross-check: E of a steady motion equals U_r (Theorem 2, E' = E at Ω = 0).
    let u = top.amended_potential(&e3, formula);
    println!(
        "\nCheck: U_r(e₃) at the bound = {u:.12}, closed form p²/(2C) + mgl = {:.12}",
        formula * formula / (2.0 * top.c) + top.mgl()
    );
    let mut figures = vec![path1, path2, path3];
    figures.extend(apex_loci(&out)?);
    // Every figure written, and only those.
    println!("\nFigures:");
    for path in &figures {
        println!("  {}", path.display());
    }
    println!("Done in {:.2} s.", start.elapsed().as_secs_f64());
    Ok(())
}

/// The three classic apex loci of a fast top (Klein & Sommerfeld; Goldstein §5.7), each started
/// at rest in θ at θ₀ = 0.5 with spin ω₃ and the precession rate ψ̇₀ chosen by the classical
/// criterion — ψ̇₀ against the spin's precession: loops; ψ̇₀ = 0: cusps; ψ̇₀ with it but slower
/// than the steady precession: waves — and named from the simulated ψ̇ (its sign changes), not
/// from ψ̇₀.
/// Returns the figures written.
fn apex_loci(out: &std::path::Path) -> Result<Vec<std::path::PathBuf>, Box<dyn Error>> {
    let mut written = Vec::new();
    let top = LagrangeTop::with_mgl(1.0, 0.6, 1.0);
    let (theta0, spin) = (0.5f64, 6.0);
    let slow = top.mgl() / (top.c * spin);
    println!("\nApex loci (attitude integrated with the motion, SimOptions::attitude)");
    println!(
        "top A₁ = {}, C = {}, mgl = {}, θ₀ = {theta0}, ω₃ = {spin}; slow precession ≈ {slow:.4}",
        top.a1,
        top.c,
        top.mgl()
    );
    for (name, psi_dot0, expected) in [
        ("looping", -slow, ApexLocus::Looping),
        ("cuspidal", 0.0, ApexLocus::Cuspidal),
        ("wavy", 0.6 * slow, ApexLocus::Wavy),
    ] {
        let gamma0 = Vector3::new(0.0, theta0.sin(), theta0.cos());
        let omega0 = Vector3::new(0.0, psi_dot0 * theta0.sin(), spin);
        let t_end = 6.0;
        let times = linspace(0.0, t_end, 6001);
        let opts = SimOptions::with_tolerances(1e-11, 1e-12)
            .with_attitude()
            .at_times(times);
        let tr = simulate_full(&top, omega0, gamma0, t_end, &opts)?;
        let euler = tr.euler_angles();
        let seen = classify_apex_locus(&tr.t, &euler, 0.02).ok_or("no precession")?;
        let (lo, hi) = euler
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), e| (a.min(e[1]), b.max(e[1])));
        println!(
            "  ψ̇₀ = {psi_dot0:+.4}: θ ∈ [{:.4}, {:.4}] rad, E drift {:.1e}, locus: {seen}{}",
            lo,
            hi,
            tr.energy_drift(),
            if seen == expected {
                ""
            } else {
                "  (NOT the expected one)"
            }
        );
        let path = out.join(format!("apex_locus_{name}.svg"));
        let opts = PlotOptions {
            title: format!("apex locus, ψ̇₀ = {psi_dot0:+.3}: {seen}"),
            width: 600,
            height: 600,
            ..PlotOptions::default()
        };
        plot::apex_locus_svg(&tr.attitude, Vector3::z(), &path, &opts)?;
        written.push(path);
        if name == "looping" {
            let path = out.join("looping_time_histories.svg");
            plot::time_histories_svg(&tr, &path, &PlotOptions::default())?;
            written.push(path);
        }
    }
    Ok(written)
}
