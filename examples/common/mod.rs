//! Code shared by the paper's examples (`heavy_top`, `gyrostat`, `ellipsoid_on_plane`,
//! `body_in_fluid`): the models, the analyses they run, table formatting and figures.
//!
//! `tests/examples_facts.rs` compiles this module too (`#[path = "../examples/common/mod.rs"]`),
//! so that the facts the examples print are checked by `cargo test`. Each example uses only part
//! of it, hence the `allow(dead_code)`.
#![allow(dead_code)]

pub mod ellipsoid;
pub mod fluid_body;
pub mod gyrostat;
pub mod plot;
pub mod top;

use std::path::PathBuf;

use routh::{
    classify, steady_motions, RouthError, Routhian, Stability, StabilityReport, SteadyMotion,
    Vector3,
};

/// A steady motion at the cyclic momentum `p_psi` with its stability report.
#[derive(Debug, Clone)]
pub struct Classified {
    /// The cyclic momentum (9) of the family member.
    pub p_psi: f64,
    /// The steady motion, as found by [`steady_motions`].
    pub motion: SteadyMotion,
    /// Its classification by [`classify`].
    pub report: StabilityReport,
}

/// Every steady motion at `p_psi` (global search of [`steady_motions`]), each classified.
pub fn classified_steady_motions<M: Routhian>(
    model: &M,
    p_psi: f64,
) -> Result<Vec<Classified>, RouthError> {
    steady_motions(model, p_psi)?
        .into_iter()
        .map(|motion| {
            let report = classify(model, &motion)?;
            Ok(Classified {
                p_psi,
                motion,
                report,
            })
        })
        .collect()
}

/// The classification of the steady motion at the known critical point `gamma` (e.g. a spin
/// about a principal axis), without any search.
pub fn report_at<M: Routhian>(
    model: &M,
    gamma: Vector3<f64>,
    p_psi: f64,
) -> Result<StabilityReport, RouthError> {
    let motion = SteadyMotion::at(model, gamma, p_psi, true)?;
    classify(model, &motion)
}

/// The verdict of [`report_at`].
pub fn verdict_at<M: Routhian>(
    model: &M,
    gamma: Vector3<f64>,
    p_psi: f64,
) -> Result<Stability, RouthError> {
    Ok(report_at(model, gamma, p_psi)?.verdict)
}

/// Bisection for the point where the predicate `pred` changes value between `lo` and `hi`
/// (`pred(lo) != pred(hi)` is required, otherwise `None`). Stops when the bracket is shorter than
/// `rel_tol · |hi|`; returns the midpoint of the final bracket.
pub fn bisect<F>(
    mut lo: f64,
    mut hi: f64,
    rel_tol: f64,
    mut pred: F,
) -> Result<Option<f64>, RouthError>
where
    F: FnMut(f64) -> Result<bool, RouthError>,
{
    let at_lo = pred(lo)?;
    if pred(hi)? == at_lo {
        return Ok(None);
    }
    while (hi - lo).abs() > rel_tol * hi.abs().max(lo.abs()) {
        let mid = 0.5 * (lo + hi);
        if pred(mid)? == at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(0.5 * (lo + hi)))
}

/// The `p_ψ` in `[lo, hi]` where the verdict of the steady motion at the fixed critical point
/// `gamma` switches between `Unstable` and stable (secularly or gyroscopically), by bisection
/// on "is the verdict `Unstable`" to the relative tolerance `rel_tol`.
pub fn instability_threshold<M: Routhian>(
    model: &M,
    gamma: Vector3<f64>,
    lo: f64,
    hi: f64,
    rel_tol: f64,
) -> Result<Option<f64>, RouthError> {
    bisect(lo, hi, rel_tol, |p| {
        Ok(verdict_at(model, gamma, p)? == Stability::Unstable)
    })
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
