//! Code shared by the paper's examples (`heavy_top`, `gyrostat`, `ellipsoid_on_plane`,
//! `body_in_fluid`): number and table formatting, figures, and one analysis (the `p_ψ` where a
//! steady motion becomes stable). Each example declares its own body with
//! `#[derive(Lagrangian)]`; `tests/examples_facts.rs` checks the facts they print. Each example
//! uses only part of this module, hence the `allow(dead_code)`.
#![allow(dead_code)]

pub mod plot;

use std::path::PathBuf;

use routh::{Classified, Stability, Vector3};

/// A number with at most `digits` decimals, trailing zeros removed (`0.5`, `9.81`, `-2`).
pub fn num(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// `n` equally spaced points from `a` to `b` inclusive.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    match n {
        0 => vec![],
        1 => vec![a],
        _ => (0..n)
            .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
            .collect(),
    }
}

/// `out/NAME/` under the workspace root, created if missing.
pub fn out_dir(name: &str) -> std::io::Result<PathBuf> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("out")
        .join(name);
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

/// A short label of a verdict, for tables.
pub fn verdict_label(v: Stability) -> &'static str {
    match v {
        Stability::SecularlyStable => "secularly stable",
        Stability::GyroscopicallyStabilized => "gyroscopically stabilised",
        Stability::Unstable => "unstable",
        Stability::Degenerate => "degenerate",
    }
}

/// All verdicts, in the order used by legends.
pub const VERDICTS: [Stability; 4] = [
    Stability::SecularlyStable,
    Stability::GyroscopicallyStabilized,
    Stability::Unstable,
    Stability::Degenerate,
];

/// `γ` as `(+0.123456, −0.000000, +0.992345)`.
pub fn fmt_vec(v: &Vector3<f64>) -> String {
    let c = |x: f64| {
        let s = format!("{x:+.6}");
        if s == "-0.000000" {
            "+0.000000".to_string()
        } else {
            s
        }
    };
    format!("({}, {}, {})", c(v.x), c(v.y), c(v.z))
}

/// The angle between the unit vector `gamma` and the body axis `axis` (a unit vector), in
/// degrees.
pub fn angle_deg(gamma: &Vector3<f64>, axis: &Vector3<f64>) -> f64 {
    gamma.dot(axis).clamp(-1.0, 1.0).acos().to_degrees()
}

/// Display width of `s`: characters other than combining marks (so that `ψ̇` counts as one).
pub fn display_width(s: &str) -> usize {
    s.chars()
        .filter(|c| !('\u{300}'..='\u{36f}').contains(c))
        .count()
}

/// `s` right-aligned in `width` display columns.
pub fn rpad(s: &str, width: usize) -> String {
    format!("{}{s}", " ".repeat(width.saturating_sub(display_width(s))))
}

/// `s` left-aligned in `width` display columns.
pub fn lpad(s: &str, width: usize) -> String {
    format!("{s}{}", " ".repeat(width.saturating_sub(display_width(s))))
}

/// Prints a table of classified steady motions: one row per motion, with the angle between γ
/// and `axis` (named `axis_name`), ψ̇, U_r, E, whether isolated, the eigenvalues of the
/// restricted second variation, the degree of instability and the verdict.
pub fn print_steady_table(rows: &[Classified], axis: &Vector3<f64>, axis_name: &str) {
    println!(
        "  {}  {}  {}  {}  {}  {}  {}  {}  verdict",
        rpad("p_ψ", 8),
        lpad("γ (body frame)", 33),
        rpad(axis_name, 8),
        rpad("ψ̇", 10),
        rpad("U_r", 11),
        rpad("E", 11),
        rpad("restricted Hessian eigs", 23),
        rpad("deg", 3),
    );
    for r in rows {
        let [k1, k2] = r.report.restricted_hessian_eigenvalues;
        println!(
            "  {:>8.4}  {:<33}  {:>7.2}°  {:>+10.5}  {:>+11.5}  {:>+11.5}  {:>+11.5} {:>+11.5}  {:>3}  {}{}",
            r.p_psi,
            fmt_vec(&r.motion.gamma),
            angle_deg(&r.motion.gamma, axis),
            r.motion.psi_dot,
            r.motion.amended_potential,
            r.motion.energy,
            k1,
            k2,
            r.report.degree_of_instability,
            verdict_label(r.report.verdict),
            if r.motion.isolated { "" } else { " (one of a circle)" }
        );
    }
}
