//! Paper Example 2: a heavy ellipsoid on a smooth horizontal plane, with `C₃` the support function
//! (errata E6), `U = +m g C₃` (errata E2) and the ½ of (51) restored (errata E1). Steady motions of
//! a spheroid and of a triaxial body, and the spin needed to stand on the end of the long axis,
//! found numerically and compared with the hand-derived formulas of
//! `test-models/derived/src/ellipsoid.rs` (crate `derived-models`).
//!
//! Run with `cargo run --release --example ellipsoid_on_plane`. Figures go to
//! `out/ellipsoid_on_plane/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::time::Instant;

use common::plot::{verdict_series, Figure};
use common::{linspace, verdict_label};
use derived_models::ellipsoid::uniform_inertia;
use derived_models::Ellipsoid;
use derived_models::{classified_steady_motions, report_at, stability_threshold};
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use routh::plot::{self, Overlay, PlotOptions};
use routh::{stability_atlas, AtlasOptions, Routhian, Stability, Vector3};

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
        derived_models::num(i[(0, 0)], 4),
        derived_models::num(i[(1, 1)], 4),
        derived_models::num(i[(2, 2)], 4),
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
            let r = report_at(body, gamma, p)?;
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
