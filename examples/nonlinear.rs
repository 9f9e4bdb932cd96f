//! Nonlinear stability of the sleeping asymmetric prolate top over the cyclic momentum: its
//! linear verdict (gyroscopic stabilisation, sections 4–5) and its nonlinear verdict (Birkhoff
//! normal form, Arnold–Moser, Markeev's resonance criteria; docs/method.md §10) side by side, and
//! the 1:2, 1:3 resonances and zeros of Arnold's determinant located along the branch.
//!
//! Run with `cargo run --release --example nonlinear`. The figure goes to `out/nonlinear/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;

use routh::nonlinear::{nonlinear_events, Jet};
use routh::plot::{self, DiagramAxis, PlotOptions};
use routh::{
    bifurcation_diagram, classify, nonlinear_stability_with, ContinuationOptions, Lagrangian,
    NonlinearOptions, SteadyMotion, Vector3,
};

/// A heavy asymmetric top, prolate (the axis of the centre of mass has the smallest moment).
#[derive(Lagrangian, Clone)]
#[lagrangian(kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z)]
struct Top {
    inertia: Vector3<f64>,
    mgl: f64,
}

/// The Routh function (39) of `Top` at jets: `R = ½ΩᵀIΩ − mgl γ₃ − ½(p_ψ − (IΩ)·γ)²/(γᵀIγ)`.
/// (Until the derive emits R as a tape, the nonlinear test is given R this way.)
fn routhian_jet(top: &Top, w: &[Jet; 3], g: &[Jet; 3], p: f64) -> Jet {
    let i = top.inertia;
    let iw = [w[0] * i.x, w[1] * i.y, w[2] * i.z];
    let ig = [g[0] * i.x, g[1] * i.y, g[2] * i.z];
    let dot = |a: &[Jet; 3], b: &[Jet; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let q = -dot(&iw, g) + p;
    dot(&iw, w) * 0.5 - g[2] * top.mgl - q * q / dot(&ig, g) * 0.5
}

fn main() -> Result<(), Box<dyn Error>> {
    let top = Top {
        inertia: Vector3::new(2.0, 2.5, 1.5),
        mgl: 1.0,
    };
    let range = (2.0, 14.0);
    let out = common::out_dir("nonlinear")?;
    println!("Sleeping asymmetric prolate top, I = diag(2, 2.5, 1.5), mgl = 1, over p_ψ");
    println!(
        "\n  {:>6}  {:<26}  {:<18}  {:>9}  {:>10}  {:>10}  {:>10}",
        "p_ψ", "linear", "nonlinear", "ω₁/ω₂", "c₂₀", "c₁₁", "D"
    );
    let r = |w: &[Jet; 3], g: &[Jet; 3], p: f64| routhian_jet(&top, w, g, p);
    let opts = NonlinearOptions::default();
    for k in 0..=24 {
        let p = range.0 + (range.1 - range.0) * f64::from(k) / 24.0;
        let s = SteadyMotion::at(&top, Vector3::z(), p, true)?;
        let rep = nonlinear_stability_with(&top, &s, &r, &opts)?;
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

    let family = |p: f64| (top.clone(), p);
    let copts = ContinuationOptions {
        verify_counts: false,
        ..Default::default()
    };
    let mut diagram = bifurcation_diagram(family, range, &copts)?;
    let events = nonlinear_events(family, routhian_jet, &diagram, &opts, 1e-10)?;
    println!("\nNonlinear events on gyroscopically stabilised stretches (|Δp_ψ| ≤ 1e−10·p_ψ):");
    for e in &events {
        let what = match e.resonance {
            Some(r) => format!("{r} resonance"),
            None => "D = 0".to_string(),
        };
        println!(
            "  {what:<14} at p_ψ = {:.10}: {} | at the point: {} | {}",
            e.s, e.before, e.at, e.after
        );
        diagram.events.push(e.to_branch_event());
    }
    diagram.events.sort_by(|a, b| a.s.total_cmp(&b.s));
    let path = out.join("sleeping_top_nonlinear.svg");
    plot::bifurcation_diagram_svg(
        &diagram,
        &path,
        &PlotOptions {
            title: "Asymmetric prolate top: steady motions, with resonances (✕) and D = 0 (○)"
                .into(),
            x_label: "cyclic momentum p_ψ".into(),
            y: DiagramAxis::Tilt,
            ..PlotOptions::default()
        },
    )?;
    println!("\nwrote {}", path.display());
    Ok(())
}
