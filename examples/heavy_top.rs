//! The heavy symmetric (Lagrange) top: its steady motions, their stability, and Maievskii's bound
//! `p_ψ² > 4A₁mgl` for the sleeping top found numerically.
//!
//! Run with `cargo run --release --example heavy_top`. Figures go to `out/heavy_top/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::time::Instant;

use common::plot::{verdict_series, Figure, Series, Style};
use common::{linspace, verdict_label};
use derived_models::LagrangeTop;
use derived_models::{classified_steady_motions, instability_threshold, report_at};
use plotters::prelude::{RGBColor, SeriesLabelPosition, BLACK};
use routh::{simulate_full, Routhian, SimOptions, Vector3};

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

    // --- Maievskii's bound --------------------------------------------------------------------
    let formula = top.maievskii_p();
    let found = instability_threshold(&top, e3, 0.5 * formula, 1.5 * formula, 1e-13)?
        .ok_or("the verdict of the sleeping top does not change in the bracket")?;
    println!("\nSleeping top γ = e₃ (ω = ψ̇γ, ψ̇ = p_ψ/C)");
    println!("------------------------------------------");
    println!(
        "Maievskii threshold, bisection on the verdict:  p_ψ = {found:.12}   (p_ψ² = {:.12})",
        found * found
    );
    println!(
        "Formula p_ψ² = 4A₁mgl:                          p_ψ = {formula:.12}   (p_ψ² = {:.12})",
        formula * formula
    );
    println!(
        "Relative difference in p_ψ: {:.2e}",
        (found - formula).abs() / formula
    );
    if let Some(ps) = top.secular_p() {
        // Where the restricted second variation changes sign: there the verdict goes from
        // gyroscopically stabilised to secularly stable (through `Degenerate` exactly at the
        // boundary, within classify's zero-eigenvalue tolerance).
        let found_s = derived_models::bisect(formula * 1.001, 3.0 * ps, 1e-13, |p| {
            Ok(report_at(&top, e3, p)?.restricted_hessian_eigenvalues[0] > 0.0)
        })?
        .ok_or("no secular-stability boundary found")?;
        println!(
            "Secular stability (U_r minimal) from:          p_ψ = {found_s:.12}   (formula p_ψ² = mglC²/(C − A₁): p_ψ = {ps:.12})"
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

    // --- Figure 1: families of steady motions --------------------------------------------------
    let ps = linspace(0.0, 5.0, 101);
    let mut pts = Vec::new();
    let mut counts = [0usize; 4];
    for &p in &ps {
        for r in classified_steady_motions(&top, p)? {
            let tilt = r.motion.gamma.z.clamp(-1.0, 1.0).acos().to_degrees();
            pts.push((r.report.verdict, p, tilt));
            counts[common::VERDICTS
                .iter()
                .position(|&v| v == r.report.verdict)
                .unwrap_or(0)] += 1;
        }
    }
    let mut fig = Figure::new(
        "Lagrange top: steady motions (A₁ = 1, C = 1.25, mgl = 1)",
        "cyclic momentum p_ψ",
        "tilt of the symmetry axis arccos γ₃ (degrees)",
    );
    fig.x_range = Some(0.0..5.0);
    fig.y_range = Some(-5.0..185.0);
    let analytic: Vec<(f64, f64)> = linspace(0.02, 1.0, 200)
        .into_iter()
        .filter_map(|z| top.tilted_family_p(z).map(|p| (p, z.acos().to_degrees())))
        .filter(|&(p, _)| p <= 5.0)
        .collect();
    fig.series.push(Series::new(
        "tilted family, closed form",
        BLACK,
        Style::Line(1),
        analytic,
    ));
    fig.series.extend(verdict_series(&pts, 3));
    fig.vlines.push((
        formula,
        format!("Maievskii p² = 4A₁mgl ({formula:.3})"),
        RGBColor(30, 90, 220),
    ));
    if let Some(p) = top.secular_p() {
        fig.vlines.push((
            p,
            format!("p² = mglC²/(C − A₁) ({p:.3})"),
            RGBColor(0, 140, 60),
        ));
    }
    fig.legend = SeriesLabelPosition::Coordinate(470, 45);
    let path1 = out.join("steady_motions.svg");
    fig.save(&path1, 900, 560)?;
    println!(
        "\nFamilies of steady motions over p_ψ ∈ [0, 5] ({} values): {} secularly stable, {} \
         gyroscopically stabilised, {} unstable, {} degenerate (the circles of tilted steady motions, and the sleeping top exactly on a boundary).",
        ps.len(),
        counts[0],
        counts[1],
        counts[2],
        counts[3]
    );

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
    for (factor, color) in [(0.95, RGBColor(210, 30, 30)), (1.05, RGBColor(30, 90, 220))] {
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
            Style::Line(2),
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
    println!("\nFigures:");
    println!("  {}", path1.display());
    println!("  {}", path2.display());
    println!("Done in {:.2} s.", start.elapsed().as_secs_f64());
    Ok(())
}
