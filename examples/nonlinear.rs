//! Nonlinear stability of the sleeping asymmetric prolate top over the cyclic momentum: its
//! linear verdict (gyroscopic stabilisation, sections 4–5) and its nonlinear verdict (Birkhoff
//! normal form, Arnold–Moser, Markeev's resonance criteria; docs/method.md §10) side by side; the
//! bifurcation diagram with the 1:2, 1:3 resonances and the zeros of Arnold's determinant located
//! as events (`ContinuationOptions::nonlinear`), and a stability atlas over (mgl, p_ψ) with the
//! curves of those points (`AtlasOptions::nonlinear`).
//!
//! Run with `cargo run --release --example nonlinear`. The figures go to `out/nonlinear/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::time::Instant;

use routh::plot::{self, DiagramAxis, PlotOptions};
use routh::{
    bifurcation_diagram, classify, nonlinear_stability, stability_atlas, AtlasOptions,
    ContinuationOptions, EventKind, Lagrangian, NonlinearOptions, SteadyMotion, Vector3,
};

/// A heavy asymmetric top, prolate (the axis of the centre of mass has the smallest moment).
/// The derive gives it its Routh function as an expression tape, which the nonlinear test
/// evaluates at Taylor jets.
#[derive(Lagrangian, Clone)]
#[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
struct Top {
    inertia: Vector3<f64>,
    mgl: f64,
}

fn main() -> Result<(), Box<dyn Error>> {
    let top = Top {
        inertia: Vector3::new(2.0, 2.5, 1.5),
        mgl: 1.0,
    };
    let range = (2.0, 14.0);
    let out = common::out_dir("nonlinear")?;
    let opts = NonlinearOptions::default();

    println!("Sleeping asymmetric prolate top, I = diag(2, 2.5, 1.5), mgl = 1, over p_ψ");
    println!(
        "\n  {:>6}  {:<26}  {:<18}  {:>9}  {:>10}  {:>10}  {:>10}",
        "p_ψ", "linear", "nonlinear", "ω₁/ω₂", "c₂₀", "c₁₁", "D"
    );
    for k in 0..=24 {
        let p = range.0 + (range.1 - range.0) * f64::from(k) / 24.0;
        let s = SteadyMotion::at(&top, Vector3::z(), p, true)?;
        let rep = nonlinear_stability(&top, &s, &opts)?;
        let lin = classify(&top, &s)?;
        println!(
            "  {:>6.2}  {:<26}  {:<18}  {:>9.4}  {:>+10.3e}  {:>+10.3e}  {:>+10.3e}",
            p,
            lin.verdict.to_string(),
            rep.verdict.to_string(),
            rep.frequencies[0] / rep.frequencies[1],
            rep.normal_form[0],
            rep.normal_form[1],
            rep.arnold_determinant
        );
    }

    // The diagram, with the nonlinear events located along the branches.
    let family = |p: f64| (top.clone(), p);
    let copts = ContinuationOptions {
        verify_counts: false,
        nonlinear: Some(opts.clone()),
        ..Default::default()
    };
    let t0 = Instant::now();
    let diagram = bifurcation_diagram(family, range, &copts)?;
    let took = t0.elapsed().as_secs_f64();
    let t0 = Instant::now();
    let linear_only = ContinuationOptions {
        nonlinear: None,
        ..copts.clone()
    };
    bifurcation_diagram(family, range, &linear_only)?;
    let took_linear = t0.elapsed().as_secs_f64();
    println!(
        "\nNonlinear events on gyroscopically stabilised stretches (|Δp_ψ| ≤ 1e−10·p_ψ; \
         diagram in {took:.3} s, {took_linear:.3} s without them):"
    );
    print_nonlinear_events(&diagram);
    let path = out.join("sleeping_top_nonlinear.svg");
    plot::bifurcation_diagram_svg(
        &diagram,
        &path,
        &PlotOptions {
            title: "Asymmetric prolate top: steady motions, resonances (✕) and D = 0 (○)".into(),
            x_label: "cyclic momentum p_ψ".into(),
            y: DiagramAxis::Tilt,
            ..PlotOptions::default()
        },
    )?;
    println!("\nwrote {}", path.display());

    // An oblate Lagrange top, whose D vanishes once on its gyroscopic stretch (docs/method.md
    // §10.8): the point is marked ○ on its diagram.
    let lagrange = Top {
        inertia: Vector3::new(1.0, 1.0, 1.25),
        mgl: 1.0,
    };
    let diagram = bifurcation_diagram(|p: f64| (lagrange.clone(), p), (1.5, 3.0), &copts)?;
    println!("\nOblate Lagrange top A = 1, C = 1.25, mgl = 1 (gyroscopic for 2 < p_ψ < 2.5):");
    print_nonlinear_events(&diagram);
    let path = out.join("oblate_lagrange_top_nonlinear.svg");
    plot::bifurcation_diagram_svg(
        &diagram,
        &path,
        &PlotOptions {
            title: "Oblate Lagrange top: resonances (✕) and D = 0 (○) on the sleeping top".into(),
            x_label: "cyclic momentum p_ψ".into(),
            y: DiagramAxis::Tilt,
            ..PlotOptions::default()
        },
    )?;
    println!("wrote {}", path.display());

    // The atlas of the sleeping top over (mgl, p_ψ), with the curves of the nonlinear test.
    let aopts = AtlasOptions {
        nx: 21,
        ny: 25,
        nonlinear: Some(opts),
        ..Default::default()
    };
    let t0 = Instant::now();
    let atlas = stability_atlas(
        |mgl, p| (Top { mgl, ..top.clone() }, p),
        Vector3::z(),
        (0.5, 2.0),
        range,
        &aopts,
    )?;
    let took = t0.elapsed().as_secs_f64();
    let t0 = Instant::now();
    let linear_only = AtlasOptions {
        nonlinear: None,
        ..aopts.clone()
    };
    stability_atlas(
        |mgl, p| (Top { mgl, ..top.clone() }, p),
        Vector3::z(),
        (0.5, 2.0),
        range,
        &linear_only,
    )?;
    let took_linear = t0.elapsed().as_secs_f64();
    println!(
        "\nAtlas of the sleeping top over (mgl, p_ψ), 21 × 25 nodes, in {took:.2} s ({took_linear:.2} s \
         without the nonlinear curves):"
    );
    for c in &atlas.nonlinear {
        let kind = if c.kind == EventKind::Resonance {
            "resonance"
        } else {
            "Arnold-degenerate"
        };
        println!(
            "  {:<6} ({kind}): {} edge crossings, {} segments",
            c.label(),
            c.crossings.len(),
            c.segments.len()
        );
    }
    let path = out.join("sleeping_top_nonlinear_atlas.svg");
    plot::stability_atlas_svg(
        &atlas,
        &path,
        &PlotOptions {
            title: "Asymmetric prolate top γ = e₃: verdicts, with 1:2, 1:3 and D = 0".into(),
            x_label: "mgl".into(),
            y_label: "p_ψ".into(),
            ..PlotOptions::default()
        },
    )?;
    println!("wrote {}", path.display());
    Ok(())
}

/// The nonlinear events of a diagram, one a line.
fn print_nonlinear_events(diagram: &routh::BifurcationDiagram) {
    println!("  (nonlinear verdicts: at the branch point before | at the event | after)");
    for e in &diagram.events {
        let Some(n) = &e.nonlinear else { continue };
        println!(
            "  p_ψ = {:.10} (branch {}, γ = ({:+.4}, {:+.4}, {:+.4})): {n}",
            e.s, e.branch, e.gamma.x, e.gamma.y, e.gamma.z
        );
    }
}
