//! Certified completeness on the paper's bodies: for each, the global search (`steady_motions`)
//! next to the interval proof (`certify::steady_motions_certified`), with what the proof cost.
//! A body with a symmetry has circles of steady motions, which no interval Newton can isolate:
//! there the certificate names the undecided tubes instead of claiming a count.
//!
//! `cargo run --release --example certify`

use derived_models::{AsymmetricTop, Ellipsoid, FluidBody, Gyrostat, Kirchhoff, LagrangeTop};
use routh::certify::{steady_motions_certified, CertifyOptions};
use routh::{steady_motions, Routhian, Vector3};
use std::error::Error;
use std::time::Instant;

fn row<M: Routhian>(name: &str, model: &M, p: f64) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let searched = steady_motions(model, p)?;
    let t_search = t0.elapsed();
    let cert = steady_motions_certified(model, p, &CertifyOptions::default())?;
    let circles = searched.iter().filter(|s| !s.isolated).count();
    println!(
        "{name:<34} {p:>5} {:>8} {:>9} {:>9} {:>8} {:>8} {:>10.2} {:>10.2}",
        format!("{}+{}c", searched.len() - circles, circles),
        if cert.complete { "yes" } else { "no" },
        cert.motions.len(),
        cert.undecided.len(),
        cert.boxes,
        t_search.as_secs_f64() * 1e3,
        cert.elapsed.as_secs_f64() * 1e3,
    );
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    println!(
        "{:<34} {:>5} {:>8} {:>9} {:>9} {:>8} {:>8} {:>10} {:>10}",
        "body",
        "p_ψ",
        "searched",
        "complete",
        "certified",
        "undecided",
        "boxes",
        "search ms",
        "proof ms"
    );
    let asymmetric = AsymmetricTop {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        com: Vector3::new(0.0, 0.0, 1.0),
        mass: 1.0,
        g: 1.0,
    };
    for p in [0.5, 2.5, 3.5] {
        row("heavy asymmetric top (1, 2, 3)", &asymmetric, p)?;
    }
    let lagrange = LagrangeTop::example();
    for p in [1.0, 1.55, 3.0] {
        row("Lagrange top (1, 1.25), mgl = 1", &lagrange, p)?;
    }
    for p in [0.0, 1.0, 3.0] {
        row("Kelvin gyrostat (Example 1)", &Gyrostat::kelvin(), p)?;
        row("gyrostat a(γ) = Bγ (Example 1)", &Gyrostat::coupled(), p)?;
    }
    for p in [0.0, 1.0, 4.0] {
        row("triaxial ellipsoid (Example 2)", &Ellipsoid::triaxial(), p)?;
        row("spheroid (Example 2)", &Ellipsoid::spheroid(), p)?;
    }
    let chiral = FluidBody::from(&Kirchhoff::chiral().parameters(1.0)?);
    for p in [0.0, 1.0] {
        row("chiral body in a fluid (Example 3)", &chiral, p)?;
    }
    println!(
        "\nsearched: isolated + circles (c) from the global search; complete: the proof covers"
    );
    println!("the sphere, so the certified motions are all of them; undecided: regions (tubes");
    println!("around circles, degenerate points) the proof could not decide.");
    Ok(())
}
