//! The one style of routh's figures, for both renderers: the colour, line width, dash pattern and
//! marker of each verdict, event and boundary ([`STYLE`]), and the fonts ([`FONT`]). The SVGs of
//! `routh::plot` draw with it, and the Python package's matplotlib figures read the same table
//! from the extension module (`routh.plot_style()`), so that there is no second copy.
//!
//! The colours are the Okabe–Ito palette (told apart by readers with any common colour-vision
//! deficiency); every verdict has its own stroke too (thick solid, thin solid, dashed, dotted), and
//! every event its own marker, so that a figure reads in monochrome
//! (`PlotOptions::monochrome` draws all in black).
//!
//! ```
//! use routh::style::{look, FONT, STYLE};
//!
//! let stable = look("verdict", "secularly_stable").unwrap();
//! assert_eq!(stable.color, "#009E73");
//! assert_eq!(stable.dash_pt, None); // solid
//! assert!(look("verdict", "unstable").unwrap().dash_pt.is_some());
//! // Each verdict its own colour.
//! let verdicts: Vec<_> = STYLE.iter().filter(|l| l.group == "verdict").collect();
//! assert_eq!(verdicts.len(), 4);
//! assert!(FONT.tick_pt < FONT.label_pt);
//! ```

/// How one thing is drawn: a verdict's line, an event's marker, a boundary curve, an atlas cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Look {
    /// `"verdict"`, `"event"`, `"boundary"`, `"orbit_verdict"`, `"orbit_event"`, `"orbit_curve"`
    /// (the curves of an orbit chart) or `"reference"`.
    pub group: &'static str,
    /// The key within the group: the names of the Python package (`"secularly_stable"`,
    /// `"branch_point"`, …).
    pub name: &'static str,
    /// The text of the legend.
    pub label: &'static str,
    /// The colour, `#RRGGBB` (of the line, or of the marker's ink).
    pub color: &'static str,
    /// The line width in points (1/72 in).
    pub width_pt: f64,
    /// Dash and gap in points; `None`: solid.
    pub dash_pt: Option<(f64, f64)>,
    /// The marker, in matplotlib's letters: `"^"` ▲, `"o"` ●, `"s"` ■, `"O"` ○ (open circle),
    /// `"x"` ✕, `"D"` ◆, `"@"` ◎ (an open circle with a dot); `None` for a line.
    pub marker: Option<&'static str>,
    /// The light tint of an atlas region of this verdict, `#RRGGBB`.
    pub fill: Option<&'static str>,
    /// The pattern over an atlas region: `""` plain, `"."` dots, `"/"` hatching, `"x"`
    /// cross-hatching (matplotlib's hatch letters).
    pub hatch: Option<&'static str>,
}

const fn line(
    group: &'static str,
    name: &'static str,
    label: &'static str,
    color: &'static str,
    width_pt: f64,
    dash_pt: Option<(f64, f64)>,
) -> Look {
    Look {
        group,
        name,
        label,
        color,
        width_pt,
        dash_pt,
        marker: None,
        fill: None,
        hatch: None,
    }
}

const fn verdict(
    name: &'static str,
    label: &'static str,
    color: &'static str,
    width_pt: f64,
    dash_pt: Option<(f64, f64)>,
    fill: &'static str,
    hatch: &'static str,
) -> Look {
    Look {
        fill: Some(fill),
        hatch: Some(hatch),
        ..line("verdict", name, label, color, width_pt, dash_pt)
    }
}

const fn marker(
    group: &'static str,
    name: &'static str,
    label: &'static str,
    m: &'static str,
) -> Look {
    Look {
        marker: Some(m),
        ..line(group, name, label, "#000000", 1.0, None)
    }
}

/// The Okabe–Ito colours used: bluish green, blue, vermillion, reddish purple, orange, sky blue.
pub const OKABE_ITO: [&str; 8] = [
    "#000000", "#E69F00", "#56B4E9", "#009E73", "#F0E442", "#0072B2", "#D55E00", "#CC79A7",
];

/// The colours of several orbits drawn together (a Poincaré section's, in turn): the Okabe–Ito
/// colours but yellow, too light on white.
pub const PALETTE: [&str; 7] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000",
];

/// Pixels of an SVG per point of [`Look::width_pt`] and [`FONT`] (an 800-pixel-wide SVG is a
/// figure 5.6 in wide).
pub const PX_PER_PT: f64 = 2.0;

/// Every look, by group and name.
pub const STYLE: &[Look] = &[
    verdict(
        "secularly_stable",
        "secularly stable",
        "#009E73",
        2.0,
        None,
        "#CCECE3",
        "",
    ),
    verdict(
        "gyroscopically_stabilized",
        "gyroscopically stabilised",
        "#0072B2",
        1.0,
        None,
        "#CCE3F0",
        ".",
    ),
    verdict(
        "unstable",
        "unstable",
        "#D55E00",
        1.0,
        Some((4.5, 3.0)),
        "#F7DFCC",
        "/",
    ),
    verdict(
        "degenerate",
        "degenerate (test inconclusive)",
        "#CC79A7",
        1.0,
        Some((1.0, 2.0)),
        "#F5E4ED",
        "x",
    ),
    marker("event", "fold", "fold", "^"),
    marker("event", "branch_point", "branch point", "o"),
    marker("event", "hamiltonian_hopf", "Hamiltonian–Hopf", "s"),
    marker(
        "event",
        "arnold_degenerate",
        "Arnold-degenerate (D = 0)",
        "O",
    ),
    marker("event", "resonance", "resonance", "x"),
    line("boundary", "fold", "fold boundary", "#000000", 1.5, None),
    line(
        "boundary",
        "branch_point",
        "branch point boundary",
        "#000000",
        1.5,
        Some((6.0, 2.5)),
    ),
    line(
        "boundary",
        "hamiltonian_hopf",
        "Hamiltonian–Hopf boundary",
        "#000000",
        1.5,
        Some((1.5, 2.0)),
    ),
    line(
        "boundary",
        "arnold_degenerate",
        "D = 0 (Arnold-degenerate)",
        "#0072B2",
        1.0,
        Some((1.0, 1.5)),
    ),
    line(
        "boundary",
        "resonance",
        "resonance",
        "#0072B2",
        1.0,
        Some((3.5, 2.0)),
    ),
    line(
        "orbit_verdict",
        "elliptic",
        "elliptic, |k| < 1",
        "#009E73",
        2.0,
        None,
    ),
    line(
        "orbit_verdict",
        "parabolic",
        "parabolic, k = ±1",
        "#CC79A7",
        1.0,
        None,
    ),
    line(
        "orbit_verdict",
        "hyperbolic",
        "hyperbolic, k > 1",
        "#D55E00",
        1.0,
        Some((4.5, 3.0)),
    ),
    line(
        "orbit_verdict",
        "inverse_hyperbolic",
        "inverse hyperbolic, k < −1",
        "#E69F00",
        1.5,
        Some((7.0, 2.0)),
    ),
    marker("orbit_event", "fold", "fold", "^"),
    marker("orbit_event", "branch_point", "branch point", "o"),
    marker("orbit_event", "period_doubling", "period doubling", "D"),
    marker("orbit_event", "twist_degenerate", "twist zero", "s"),
    marker("orbit_event", "third_order_resonance", "resonance 1/3", "O"),
    marker(
        "orbit_event",
        "fourth_order_resonance",
        "resonance 1/4",
        "@",
    ),
    line("orbit_curve", "fold", "fold", "#000000", 1.5, None),
    line(
        "orbit_curve",
        "branch_point",
        "k = 1 (branch point)",
        "#000000",
        1.5,
        Some((6.0, 2.5)),
    ),
    line(
        "orbit_curve",
        "period_doubling",
        "k = −1 (period doubling)",
        "#000000",
        1.5,
        Some((1.5, 2.0)),
    ),
    line(
        "orbit_curve",
        "third_order_resonance",
        "resonance 1/3 (k = −1/2)",
        "#0072B2",
        1.0,
        Some((3.5, 2.0)),
    ),
    line(
        "orbit_curve",
        "fourth_order_resonance",
        "resonance 1/4 (k = 0)",
        "#0072B2",
        1.0,
        Some((7.0, 2.0)),
    ),
    line(
        "orbit_curve",
        "twist_degenerate",
        "twist zero (τ = 0)",
        "#CC79A7",
        1.5,
        Some((1.0, 1.5)),
    ),
    line(
        "reference",
        "overlay",
        "reference curve",
        "#000000",
        1.0,
        Some((6.0, 2.0)),
    ),
    line(
        "reference",
        "parabolic_line",
        "k = ±1",
        "#646464",
        0.5,
        None,
    ),
    line("reference", "grid", "grid", "#DDDDDD", 0.5, None),
];

/// The look of `name` in `group`, if there is one.
pub fn look(group: &str, name: &str) -> Option<&'static Look> {
    STYLE.iter().find(|l| l.group == group && l.name == name)
}

/// The fonts of a figure: one sans-serif family (DejaVu Sans, which matplotlib ships and which
/// draws γ, ψ, ₃ and −), sizes in points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fonts {
    /// The family, as CSS and matplotlib name it.
    pub family: &'static str,
    /// Tick labels.
    pub tick_pt: f64,
    /// Axis labels.
    pub label_pt: f64,
    /// Legend rows.
    pub legend_pt: f64,
    /// Names and values beside event markers.
    pub annotation_pt: f64,
    /// The title.
    pub title_pt: f64,
}

/// The fonts of every figure.
pub const FONT: Fonts = Fonts {
    family: "DejaVu Sans",
    tick_pt: 8.0,
    label_pt: 9.5,
    legend_pt: 8.5,
    annotation_pt: 7.5,
    title_pt: 10.0,
};

/// The default width of a figure in inches: a journal's single column (3.4 in, 86 mm).
pub const COLUMN_WIDTH_IN: f64 = 3.4;

/// The width of a figure across a journal's page, in inches.
pub const PAGE_WIDTH_IN: f64 = 7.0;

/// `n` in superscript digits (and a superscript minus): `⁻¹²`.
fn superscript(n: i64) -> String {
    const SUP: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits: String = n
        .unsigned_abs()
        .to_string()
        .chars()
        .map(|c| SUP[c.to_digit(10).unwrap_or(0) as usize])
        .collect();
    if n < 0 {
        format!("⁻{digits}")
    } else {
        digits
    }
}

/// The label of the power of ten `10ⁿ`, as every tick of both renderers writes it: `1`, `10`,
/// `100`, then `10³`, `10⁴`, … (and `10⁻¹`, `10⁻²`, … below 1), with a true minus sign (U+2212)
/// when `negative`.
///
/// ```
/// use routh::style::decade_label;
///
/// assert_eq!(decade_label(2, false), "100");
/// assert_eq!(decade_label(7, true), "−10⁷");
/// assert_eq!(decade_label(-3, false), "10⁻³");
/// ```
pub fn decade_label(n: i64, negative: bool) -> String {
    let body = match n {
        0 => "1".to_string(),
        1 => "10".to_string(),
        2 => "100".to_string(),
        _ => format!("10{}", superscript(n)),
    };
    if negative {
        format!("−{body}")
    } else {
        body
    }
}

/// The label of the tick at `v` on an axis whose ticks are about `step` apart and whose values
/// reach `scale` in magnitude, as both renderers write it: a decimal with as many digits as the
/// step needs (`0.25`, `−1.5`, `1200`) while `scale` is between 10⁻³ and 10⁵, else the mantissa
/// times a power of ten (`2.5×10⁷`, `10⁻⁴`); a true minus sign (U+2212), never a hyphen; `0`
/// for zero.
///
/// ```
/// use routh::style::tick_label;
///
/// assert_eq!(tick_label(-0.5, 0.1, 2.0), "−0.5");
/// assert_eq!(tick_label(1200.0, 100.0, 5000.0), "1200");
/// assert_eq!(tick_label(2.5e7, 1e6, 3e7), "2.5×10⁷");
/// assert_eq!(tick_label(1e7, 1e6, 3e7), "10⁷");
/// assert_eq!(tick_label(-2e-4, 1e-5, 5e-4), "−2×10⁻⁴");
/// assert_eq!(tick_label(1e-9, 0.1, 1.0), "0");
/// ```
pub fn tick_label(v: f64, step: f64, scale: f64) -> String {
    let step = step.abs().max(f64::MIN_POSITIVE);
    if !v.is_finite() {
        return v.to_string();
    }
    if v.abs() < step * 1e-6 {
        return "0".into();
    }
    let trim = |s: String| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    let scale = scale.abs();
    let s = if scale.is_finite() && (1e-3..1e5).contains(&scale) {
        let digits = ((-step.log10()).ceil().max(0.0) as usize + 1).min(12);
        trim(format!("{:.*}", digits, v))
    } else {
        let n = v.abs().log10().floor() as i64;
        let mantissa = v.abs() / 10f64.powi(n as i32);
        let digits = ((n as f64 - step.log10()).ceil().max(0.0) as usize + 1).min(12);
        let m = trim(format!("{:.*}", digits, mantissa));
        // A mantissa rounded up to 10 is the next power.
        let (m, n) = if m == "10" {
            ("1".to_string(), n + 1)
        } else {
            (m, n)
        };
        let power = format!("10{}", superscript(n));
        let body = if m == "1" {
            power
        } else {
            format!("{m}×{power}")
        };
        if v < 0.0 {
            format!("-{body}")
        } else {
            body
        }
    };
    s.replacen('-', "−", 1)
}
