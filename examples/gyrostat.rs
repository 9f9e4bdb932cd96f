//! Paper Example 1: a heavy body about a fixed point with gyroscopic forces, (35)–(40): a Kelvin
//! gyrostat (`a = K`) and a body with `a(γ) = Bγ`. Prints the amended potential (40), the steady
//! motions and their verdicts, and draws energy–momentum diagrams.
//!
//! Run with `cargo run --release --example gyrostat`. Figures go to `out/gyrostat/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::path::Path;
use std::time::Instant;

use common::verdict_label;
use derived_models::Gyrostat;
use derived_models::{classified_steady_motions, report_at};
use routh::families::bifurcation_diagram_checked;
use routh::plot::{self, PlotOptions};
use routh::{continue_branch, ContinuationOptions, DerivedFormulas, EventKind, Routhian, Vector3};

/// Unit vectors spread over the sphere (deterministic), for the formula check.
fn sample_directions(n: usize) -> Vec<Vector3<f64>> {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    (0..n)
        .map(|i| {
            let z = 1.0 - (2.0 * i as f64 + 1.0) / n as f64;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * i as f64;
            Vector3::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
}

fn describe(name: &str, body: &Gyrostat) {
    println!("\n{name}");
    println!("{}", "-".repeat(name.chars().count()));
    let i = body.inertia;
    println!(
        "I = diag({}, {}, {}), K = ({}, {}, {}), m g r_c = ({}, {}, {})",
        i[(0, 0)],
        i[(1, 1)],
        i[(2, 2)],
        body.rotor.x,
        body.rotor.y,
        body.rotor.z,
        derived_models::num(body.mass * body.g * body.com.x, 6),
        derived_models::num(body.mass * body.g * body.com.y, 6),
        derived_models::num(body.mass * body.g * body.com.z, 6)
    );
    let b = body.coupling;
    if b != routh::Matrix3::zeros() {
        println!(
            "B = [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]]  (a(γ) = Bγ; only its symmetric part \
             enters (40))",
            b[(0, 0)],
            b[(0, 1)],
            b[(0, 2)],
            b[(1, 0)],
            b[(1, 1)],
            b[(1, 2)],
            b[(2, 0)],
            b[(2, 1)],
            b[(2, 2)]
        );
    }
    println!("Amended potential (34) as the derive derived it, in the model's parameters:");
    println!(
        "  U_r = {}",
        <Gyrostat as DerivedFormulas>::AMENDED_POTENTIAL
    );
    println!("The same, (40) with this body's numbers:");
    println!("  {}", body.amended_potential_formula());
    // The derive's U_r = −R(0, γ, p_ψ) against the closed form (40) evaluated directly.
    let mut max_err = 0.0f64;
    let mut max_val = 0.0f64;
    let dirs = sample_directions(200);
    for p in [-3.0, 0.0, 1.7, 5.0] {
        for g in &dirs {
            let derived = body.amended_potential(g, p);
            let closed = body.amended_potential_closed_form(g, p);
            max_err = max_err.max((derived - closed).abs());
            max_val = max_val.max(closed.abs());
        }
    }
    println!(
        "  derive's amended_potential vs (40) at {} points (4 values of p_ψ × {} directions): \
         max |difference| = {max_err:.1e} (values up to {max_val:.2})",
        4 * dirs.len(),
        dirs.len()
    );
}

/// Smale's energy–momentum diagram of `body` over `range` of p_ψ: every branch of steady motions
/// by continuation ([`bifurcation_diagram_checked`]), its events, and the figure.
fn energy_momentum(
    body: &Gyrostat,
    title: &str,
    path: &Path,
    range: (f64, f64),
) -> Result<(), Box<dyn Error>> {
    let checked = bifurcation_diagram_checked(
        |p| (body.clone(), p),
        range,
        &ContinuationOptions::default(),
    )?;
    let d = &checked.diagram;
    println!(
        "\nEnergy–momentum diagram over p_ψ ∈ [{}, {}]: {} branches, {} points; events:",
        range.0,
        range.1,
        d.branches.len(),
        d.branches.iter().map(|b| b.points.len()).sum::<usize>()
    );
    for e in &d.events {
        println!("  {e}");
    }
    println!(
        "  count checks against global searches between events: {}",
        if checked.consistent() {
            "all agree"
        } else {
            "MISMATCH"
        }
    );
    for c in checked
        .checks
        .iter()
        .filter(|c| c.on_branches != c.searched)
    {
        println!(
            "    p_ψ = {:.4}: {} steady motions on the branches, {} found by steady_motions",
            c.s, c.on_branches, c.searched
        );
    }
    plot::energy_momentum_svg(
        d,
        path,
        &PlotOptions {
            title: title.into(),
            x_label: "cyclic momentum p_ψ".into(),
            y_label: "energy E of the steady motion".into(),
            ..PlotOptions::default()
        },
    )?;
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let start = Instant::now();
    let out = common::out_dir("gyrostat")?;
    let e3 = Vector3::z();

    println!(
        "Example 1 — heavy body with gyroscopic forces, L = ½(Iω, ω) + (a(γ), ω) − U(γ)  (35)"
    );
    println!(
        "===================================================================================="
    );
    println!(
        "U(γ) = m g (r_c, γ); amended potential (40): U_r = ½(p_ψ − (a(γ), γ))² / (Iγ, γ) + U(γ)"
    );

    let kelvin = Gyrostat::kelvin();
    let coupled = Gyrostat::coupled();
    let mut figures = Vec::new();

    // --- Kelvin gyrostat -----------------------------------------------------------------------
    describe("1. Kelvin gyrostat, a(γ) = K", &kelvin);
    for p in [0.0, kelvin.rotor.z, 6.0] {
        println!("\n p_ψ = {p}:");
        common::print_steady_table(&classified_steady_motions(&kelvin, p)?, &e3, "∠(γ,e₃)");
    }
    let k_formula = kelvin.rest_rotor_threshold();
    // The gyrostat at rest upright: γ = e₃, ω = 0, hence p_ψ = K₃. Follow that steady motion
    // over the rotor's K₃: it is gyroscopically stabilised from a Hamiltonian–Hopf point on.
    let along_rotor = continue_branch(
        |k3| {
            let body = Gyrostat {
                rotor: Vector3::new(0.0, 0.0, k3),
                ..kelvin.clone()
            };
            (body, k3)
        },
        e3,
        0.5 * k_formula,
        (0.2 * k_formula, 3.0 * k_formula),
        &ContinuationOptions::default(),
    )?;
    let k_found = along_rotor
        .events
        .iter()
        .find(|e| e.kind == EventKind::HamiltonianHopf && (e.gamma - e3).norm() < 1e-9)
        .map(|e| e.s)
        .ok_or("no Hamiltonian–Hopf point on the upright gyrostat at rest")?;
    let rest = report_at(&kelvin, e3, kelvin.rotor.z)?;
    println!(
        "\nAt rest upright (γ = e₃, ω = 0, p_ψ = K₃ = {}, ψ̇ = {:.1e}): {} (degree of instability {}).",
        kelvin.rotor.z,
        kelvin.psi_dot(&routh::Vector3::zeros(), &e3, kelvin.rotor.z),
        verdict_label(rest.verdict),
        rest.degree_of_instability
    );
    println!("Smallest rotor momentum that stabilises the upright body at rest:");
    println!("  continuation in K₃, Hamiltonian–Hopf point:            K₃ = {k_found:.12}");
    println!("  formula √(mgl)(√I₁ + √I₂):                           K₃ = {k_formula:.12}");
    println!(
        "  relative difference {:.1e}",
        (k_found - k_formula).abs() / k_formula
    );

    let path = out.join("kelvin_energy_momentum.svg");
    energy_momentum(
        &kelvin,
        "Kelvin gyrostat (a = K = 3.5e₃): energy–momentum diagram of steady motions",
        &path,
        (-6.0, 9.0),
    )?;
    figures.push(path);

    // --- a(γ) = Bγ -----------------------------------------------------------------------------
    describe("2. Body with a(γ) = Bγ", &coupled);
    for p in [0.0, 2.0, 4.5] {
        println!("\n p_ψ = {p}:");
        common::print_steady_table(&classified_steady_motions(&coupled, p)?, &e3, "∠(γ,e₃)");
    }
    let path = out.join("coupled_energy_momentum.svg");
    energy_momentum(
        &coupled,
        "Body with a(γ) = Bγ: energy–momentum diagram of steady motions",
        &path,
        (-6.0, 6.0),
    )?;
    figures.push(path);

    println!("\nFigures:");
    for f in &figures {
        println!("  {}", f.display());
    }
    println!("Done in {:.2} s.", start.elapsed().as_secs_f64());
    Ok(())
}
