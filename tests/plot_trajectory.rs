//! The figures of one motion (apex locus, time histories) as a reader sees them: every curve
//! named in a legend that sits clear of the axes, the apex locus's markers explained, tick labels
//! without a `-0`.
#![cfg(feature = "plot")]

use derived_models::LagrangeTop;
use routh::plot::{apex_locus_svg, time_histories_svg, PlotOptions};
use routh::{simulate_full, SimOptions, Vector3};

/// The texts of an SVG with their x coordinates.
fn texts(svg: &str) -> Vec<(f64, String)> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let x = t.split("x=\"").nth(1)?.split('"').next()?.parse().ok()?;
            let body = t.split('>').nth(1)?.split('<').next()?.trim().to_string();
            Some((x, body))
        })
        .collect()
}

fn looping_top() -> routh::Trajectory {
    let top = LagrangeTop::example();
    let g0 = Vector3::new(0.5f64.sin(), 0.0, 0.5f64.cos());
    simulate_full(
        &top,
        Vector3::new(0.0, -1.0, 6.0),
        g0,
        6.0,
        &SimOptions::default().with_attitude(),
    )
    .unwrap()
}

#[test]
fn time_histories_name_every_curve_beside_the_axes() {
    let tr = looping_top();
    let path = std::env::temp_dir().join(format!("routh-th-{}.svg", std::process::id()));
    let opts = PlotOptions::default();
    time_histories_svg(&tr, &path, &opts).unwrap();
    let svg = std::fs::read_to_string(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    let t = texts(&svg);
    // The legend column is right of every tick label: its names start right of the right-most
    // tick label's anchor.
    let column = t
        .iter()
        .filter(|(_, s)| s.replace('−', "-").parse::<f64>().is_ok())
        .map(|(x, _)| *x)
        .fold(f64::MIN, f64::max)
        + 1.0;
    for name in [
        "γ₁",
        "γ₂",
        "γ₃",
        "ω₁",
        "ω₂",
        "ω₃",
        "|E − E₀|",
        "|p_ψ − p_ψ₀|",
    ] {
        let (x, _) = t
            .iter()
            .find(|(_, s)| s == name)
            .unwrap_or_else(|| panic!("{name} not in the legend"));
        assert!(*x >= column, "{name} at x = {x}, inside the axes");
    }
    for (x, s) in &t {
        // Tick labels with a true minus sign (U+2212), never a hyphen.
        assert!(!s.starts_with('-'), "tick label {s} with a hyphen");
        if let Ok(v) = s.replace('−', "-").parse::<f64>() {
            assert!(*x < column, "tick {s} at x = {x}");
            assert!(v != 0.0 || s == "0", "tick label {s}");
        }
    }
    assert!(t.iter().any(|(_, s)| s == "log₁₀ max drift"));
}

#[test]
fn apex_locus_explains_its_markers_and_has_no_negative_zero() {
    let tr = looping_top();
    let path = std::env::temp_dir().join(format!("routh-apex-{}.svg", std::process::id()));
    apex_locus_svg(&tr.attitude, Vector3::z(), &path, &PlotOptions::default()).unwrap();
    let svg = std::fs::read_to_string(&path).unwrap();
    let _ = std::fs::remove_file(&path);
    let t = texts(&svg);
    assert!(t.iter().any(|(_, s)| s.contains("○ start, ● end")), "{t:?}");
    for (_, s) in &t {
        assert!(!s.starts_with('-'), "tick label {s} with a hyphen");
        if let Ok(v) = s.replace('−', "-").parse::<f64>() {
            assert!(v != 0.0 || s == "0", "tick label {s}");
        }
    }
}
