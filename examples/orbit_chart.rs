//! The pendulum oscillations of a heavy body with principal moments 1 : 4 : 1 about the fixed
//! point (docs/method.md §12, docs/gallery.md): its centre of mass at the angle α from e₃ in the
//! plane of e₂ and e₃, the swings about e₁ (mode 0 of the hanging position at p_ψ = 0) charted
//! over α and the energy h above the hanging position: where they change linear stability
//! (k = 1), meet the resonances of order three (k = −1/2) and four (k = 0), and where the twist
//! of their Poincaré map vanishes. Everywhere else inside the elliptic region the swings are
//! orbitally stable (Moser's twist theorem).
//!
//! `cargo run --release --example orbit_chart` (about 10 s) prints the curves and writes
//! `target/orbit_chart_body141.csv` and the figure `target/orbit_chart_body141.svg`.

use routh::{
    lyapunov_family, orbit_chart, orbit_nonlinear_stability, steady_motion_near, Lagrangian,
    OrbitChartOptions, OrbitNonlinearOptions, OrbitOptions, Vector3,
};

/// The body: moments 1 : 4 : 1, centre of mass at distance `l` at the angle `alpha` from e₃.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * (omega.x * omega.x + 4.0 * omega.y * omega.y + omega.z * omega.z),
    potential = mgl * (alpha.sin() * gamma.y + alpha.cos() * gamma.z),
)]
struct Body141 {
    alpha: f64,
    mgl: f64,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let body = |alpha: f64| (Body141 { alpha, mgl: 1.0 }, 0.0);
    // One swing analysed: α = 0.8, half-way up the elliptic region.
    let (m, p) = body(0.8);
    let s = steady_motion_near(&m, -Vector3::z(), p)?;
    let fam = lyapunov_family(&m, &s, 0, &OrbitOptions::default().with_max_orbits(12))?;
    let o = &fam.orbits[fam.orbits.len() - 1];
    let r = orbit_nonlinear_stability(&m, o, &OrbitNonlinearOptions::default())?;
    println!(
        "α = 0.8, h = {:.4}: k = {:+.6}, ρ = {:.6}, τ = {:+.6e}: {} ({})",
        o.energy - s.energy,
        o.stability_index,
        r.rotation_number,
        r.twist,
        r.verdict,
        r.reason
    );
    // The chart.
    let opts = OrbitChartOptions {
        nx: 41,
        ..OrbitChartOptions::default()
    };
    let chart = orbit_chart(body, -Vector3::z(), 0, (0.2, 1.4), (0.0, 1.9), &opts)?;
    println!(
        "{} curves over α ∈ [0.2, 1.4], h ∈ [0, 1.9]:",
        chart.curves.len()
    );
    let mut csv = String::from("curve,kind,alpha,h\n");
    for (i, c) in chart.curves.iter().enumerate() {
        let (first, last) = (c.points[0], c.points[c.points.len() - 1]);
        println!(
            "  {:<24} {:>3} points, from (α, h) = ({:.3}, {:.4}) to ({:.3}, {:.4})",
            c.kind.as_str(),
            c.points.len(),
            first[0],
            first[1],
            last[0],
            last[1]
        );
        for [x, h] in &c.points {
            csv.push_str(&format!("{i},{},{x},{h}\n", c.kind.as_str()));
        }
    }
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/orbit_chart_body141.csv");
    routh::files::write_file(&path, csv.as_bytes())?;
    println!("wrote {}", path.display());
    let svg = path.with_extension("svg");
    let look = routh::plot::PlotOptions {
        x_label: "α".into(),
        ..routh::plot::PlotOptions::column()
    };
    routh::plot::orbit_chart_svg(&chart, &svg, &look)?;
    println!("wrote {}", svg.display());
    Ok(())
}
