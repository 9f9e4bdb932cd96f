//! The one style of the figures ([`crate::style`]) mapped onto plotters' colours and strokes: how
//! each verdict, event kind and overlay is drawn. Every style reads without colour; the colour is
//! added on top (black with [`PlotOptions::monochrome`](super::PlotOptions::monochrome)).

pub(super) use crate::style::{look, Look, FONT, PX_PER_PT, STYLE};

use plotters::style::{RGBColor, BLACK};

use crate::{EventKind, OrbitEventKind, OrbitStability, Resonance, Stability};

// What follows maps the table onto plotters' colours and strokes for the SVGs.

/// The colour of `#RRGGBB`.
pub(super) const fn rgb(hex: &str) -> RGBColor {
    const fn digit(c: u8) -> u8 {
        match c {
            b'0'..=b'9' => c - b'0',
            b'a'..=b'f' => c - b'a' + 10,
            b'A'..=b'F' => c - b'A' + 10,
            _ => 0,
        }
    }
    let b = hex.as_bytes();
    if b.len() != 7 {
        return BLACK;
    }
    RGBColor(
        digit(b[1]) * 16 + digit(b[2]),
        digit(b[3]) * 16 + digit(b[4]),
        digit(b[5]) * 16 + digit(b[6]),
    )
}

/// The look of `name` in `group`; every key used below is in [`STYLE`] (a test checks them).
fn the(group: &str, name: &str) -> &'static Look {
    look(group, name).unwrap_or(&STYLE[STYLE.len() - 1])
}

/// Points to whole pixels, at least one.
fn px(pt: f64) -> u32 {
    (pt * PX_PER_PT).round().max(1.0) as u32
}

/// The size to ask plotters for so that it writes `font-size` `px` or a little more (it
/// divides by 1.24, and its axes take whole pixels): `⌈1.24 px⌉`.
pub(super) fn asked_size(px: f64) -> f64 {
    (px * 1.24 - 1e-9).ceil()
}

/// The sizes of a figure's texts in the SVG's pixels, as written (`font-size`): each text at
/// its size in points of [`FONT`] times [`PX_PER_PT`], all scaled so that the tick labels are
/// [`PlotOptions::font_pt`](super::PlotOptions::font_pt). Ask plotters for
/// [`asked_size`] of these.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Sizes {
    pub(super) tick: f64,
    pub(super) label: f64,
    pub(super) legend: f64,
    pub(super) annotation: f64,
    pub(super) title: f64,
}

impl Sizes {
    pub(super) fn of(opts: &super::PlotOptions) -> Sizes {
        let k = if opts.font_pt.is_finite() && opts.font_pt > 0.0 {
            opts.font_pt / FONT.tick_pt
        } else {
            1.0
        };
        let px = |pt: f64| pt * k * PX_PER_PT;
        Sizes {
            tick: px(FONT.tick_pt),
            label: px(FONT.label_pt),
            legend: px(FONT.legend_pt),
            annotation: px(FONT.annotation_pt),
            title: px(FONT.title_pt),
        }
    }
}

/// The stroke of a look, in pixels.
fn stroke_of(l: &Look) -> Stroke {
    match l.dash_pt {
        None => Stroke::Solid(px(l.width_pt)),
        Some((dash, gap)) => Stroke::Dashed(px(l.width_pt), px(dash), px(gap)),
    }
}

/// The verdicts in the order of the legend (and the reverse of the drawing order).
pub(super) const VERDICTS: [Stability; 4] = [
    Stability::SecularlyStable,
    Stability::GyroscopicallyStabilized,
    Stability::Unstable,
    Stability::Degenerate,
];

/// The event kinds in the order of the legend (the last two, the nonlinear events, only when
/// [`ContinuationOptions::nonlinear`](crate::ContinuationOptions::nonlinear) asked for them).
pub(super) const KINDS: [EventKind; 5] = [
    EventKind::Fold,
    EventKind::BranchPoint,
    EventKind::HamiltonianHopf,
    EventKind::ArnoldDegenerate,
    EventKind::Resonance,
];

/// The key of a verdict in [`STYLE`] (and in the Python package).
pub(super) fn verdict_key(v: Stability) -> &'static str {
    match v {
        Stability::SecularlyStable => "secularly_stable",
        Stability::GyroscopicallyStabilized => "gyroscopically_stabilized",
        Stability::Unstable => "unstable",
        Stability::Degenerate => "degenerate",
    }
}

/// The key of an event kind in [`STYLE`].
pub(super) fn event_key(k: EventKind) -> &'static str {
    match k {
        EventKind::Fold => "fold",
        EventKind::BranchPoint => "branch_point",
        EventKind::HamiltonianHopf => "hamiltonian_hopf",
        EventKind::ArnoldDegenerate => "arnold_degenerate",
        EventKind::Resonance => "resonance",
    }
}

fn orbit_key(v: OrbitStability) -> &'static str {
    match v {
        OrbitStability::Elliptic => "elliptic",
        OrbitStability::Parabolic => "parabolic",
        OrbitStability::Hyperbolic => "hyperbolic",
        OrbitStability::InverseHyperbolic => "inverse_hyperbolic",
    }
}

/// How a polyline is stroked.
#[derive(Debug, Clone, Copy)]
pub(super) enum Stroke {
    Solid(u32),
    /// Width, dash, gap (pixels).
    Dashed(u32, u32, u32),
}

/// The white band under a boundary curve of an atlas, so that it stands out of the shading.
/// A pixel either side of the boundary's 3 pixels: wider bands read as white gaps between the
/// regions.
pub(super) const BOUNDARY_UNDERLAY: Stroke = Stroke::Solid(5);

/// The strokes of [`Overlay`](super::Overlay) curves, in turn: long dashes, short dashes, a thin
/// line.
const OVERLAY_STROKES: [Stroke; 3] = [
    Stroke::Dashed(2, 12, 4),
    Stroke::Dashed(2, 4, 6),
    Stroke::Solid(1),
];

/// The stroke of the `k`-th overlay.
pub(super) fn overlay_stroke(k: usize) -> Stroke {
    OVERLAY_STROKES[k % OVERLAY_STROKES.len()]
}

/// `color`, or black in a monochrome figure.
fn ink(color: RGBColor, mono: bool) -> RGBColor {
    if mono {
        BLACK
    } else {
        color
    }
}

/// The stroke of a run of a branch: thick solid, thin solid, dashed, dotted.
pub(super) fn verdict_stroke(v: Stability) -> Stroke {
    stroke_of(the("verdict", verdict_key(v)))
}

pub(super) fn verdict_color(v: Stability, mono: bool) -> RGBColor {
    ink(rgb(the("verdict", verdict_key(v)).color), mono)
}

/// The stroke of a boundary curve of an atlas: solid, dashed, dotted.
pub(super) fn boundary_stroke(k: EventKind) -> Stroke {
    stroke_of(the("boundary", event_key(k)))
}

/// The stroke of a nonlinear curve of an atlas ([`StabilityAtlas::nonlinear`]): thin, with dashes
/// of its own for D = 0 (dots), 1:2 (medium dashes) and 1:3 (long dashes), and a label on it.
///
/// [`StabilityAtlas::nonlinear`]: crate::StabilityAtlas::nonlinear
pub(super) fn nonlinear_stroke(resonance: Option<Resonance>) -> Stroke {
    match resonance {
        None => stroke_of(the("boundary", "arnold_degenerate")),
        Some(Resonance::OneToTwo) => stroke_of(the("boundary", "resonance")),
        Some(_) => Stroke::Dashed(2, 16, 4),
    }
}

pub(super) fn boundary_color(k: EventKind, mono: bool) -> RGBColor {
    ink(rgb(the("boundary", event_key(k)).color), mono)
}

/// The pattern over the background of an atlas cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Pattern {
    Plain,
    Dots,
    Hatch,
    CrossHatch,
}

/// The ink of the atlas's patterns: a light grey, so that the hatching does not crowd the
/// boundary curves.
pub(super) const HATCH_INK: RGBColor = RGBColor(140, 140, 140);
/// The spacing of the atlas's patterns, in pixels.
pub(super) const HATCH_SPACING: i32 = 12;

/// Fill of an atlas cell: background colour (a grey level in a monochrome figure) and pattern.
pub(super) fn cell_fill(v: Stability, mono: bool) -> (RGBColor, Pattern) {
    let l = the("verdict", verdict_key(v));
    let grey = match v {
        Stability::SecularlyStable => 245,
        Stability::GyroscopicallyStabilized => 225,
        Stability::Unstable => 205,
        Stability::Degenerate => 185,
    };
    let pattern = match l.hatch {
        Some(".") => Pattern::Dots,
        Some("/") => Pattern::Hatch,
        Some("x") => Pattern::CrossHatch,
        _ => Pattern::Plain,
    };
    (
        if mono {
            RGBColor(grey, grey, grey)
        } else {
            rgb(l.fill.unwrap_or("#FFFFFF"))
        },
        pattern,
    )
}

/// The verdicts of periodic orbits in the order of the legend (and the reverse of the drawing
/// order).
pub(super) const ORBIT_VERDICTS: [OrbitStability; 4] = [
    OrbitStability::Elliptic,
    OrbitStability::Parabolic,
    OrbitStability::Hyperbolic,
    OrbitStability::InverseHyperbolic,
];

/// The events of families of periodic orbits in the order of the legend.
pub(super) const ORBIT_KINDS: [OrbitEventKind; 3] = [
    OrbitEventKind::Fold,
    OrbitEventKind::BranchPoint,
    OrbitEventKind::PeriodDoubling,
];

/// The stroke of a run of a family of periodic orbits, as the verdicts of steady motions: thick
/// solid where elliptic (stable), dashed where hyperbolic, long dashes (wider) where inverse
/// hyperbolic, and a medium solid line where parabolic (along a whole run only in degenerate
/// families).
pub(super) fn orbit_stroke(v: OrbitStability) -> Stroke {
    stroke_of(the("orbit_verdict", orbit_key(v)))
}

pub(super) fn orbit_color(v: OrbitStability, mono: bool) -> RGBColor {
    ink(rgb(the("orbit_verdict", orbit_key(v)).color), mono)
}

/// The legend text of a verdict of periodic orbits.
pub(super) fn orbit_verdict_name(v: OrbitStability) -> &'static str {
    the("orbit_verdict", orbit_key(v)).label
}

/// The name of an event of a family of periodic orbits, in the legend and beside its marker.
pub(super) fn orbit_event_name(k: OrbitEventKind) -> &'static str {
    match k {
        OrbitEventKind::Fold => "fold",
        OrbitEventKind::BranchPoint => "branch point",
        OrbitEventKind::PeriodDoubling => "period doubling",
        OrbitEventKind::TwistDegenerate => "twist zero",
        OrbitEventKind::ThirdOrderResonance => "resonance 1/3",
        OrbitEventKind::FourthOrderResonance => "resonance 1/4",
    }
}

/// The key of an event kind of periodic orbits in [`STYLE`] (`orbit_event`, `orbit_curve`).
fn orbit_event_key(k: OrbitEventKind) -> &'static str {
    match k {
        OrbitEventKind::Fold => "fold",
        OrbitEventKind::BranchPoint => "branch_point",
        OrbitEventKind::PeriodDoubling => "period_doubling",
        OrbitEventKind::TwistDegenerate => "twist_degenerate",
        OrbitEventKind::ThirdOrderResonance => "third_order_resonance",
        OrbitEventKind::FourthOrderResonance => "fourth_order_resonance",
    }
}

/// The stroke, colour and legend text of a curve of an orbit chart (the table's
/// `orbit_curve`, which the Python figure reads too).
pub(super) fn orbit_curve_look(k: OrbitEventKind, mono: bool) -> (Stroke, RGBColor, &'static str) {
    let l = the("orbit_curve", orbit_event_key(k));
    (stroke_of(l), ink(rgb(l.color), mono), l.label)
}

/// The light fill of the region of a verdict in an orbit chart: the verdict's colour at a
/// fifth of its strength on white (in greys, a lighter grey the more stable).
pub(super) fn orbit_region_fill(v: OrbitStability, mono: bool) -> RGBColor {
    if mono {
        let g = match v {
            OrbitStability::Elliptic => 235,
            OrbitStability::Parabolic => 215,
            OrbitStability::Hyperbolic => 190,
            OrbitStability::InverseHyperbolic => 165,
        };
        return RGBColor(g, g, g);
    }
    let c = rgb(the("orbit_verdict", orbit_key(v)).color);
    let tint = |x: u8| (255.0 - 0.3 * (255.0 - f64::from(x))).round() as u8;
    RGBColor(tint(c.0), tint(c.1), tint(c.2))
}

/// The grey of the reference lines `k = ±1` of a stability diagram of periodic orbits.
pub(super) const PARABOLIC_LINE: RGBColor = rgb("#646464");

/// [`crate::style::PALETTE`] as plotters' colours; black in a monochrome figure.
const PALETTE: [RGBColor; 7] = {
    let p = crate::style::PALETTE;
    [
        rgb(p[0]),
        rgb(p[1]),
        rgb(p[2]),
        rgb(p[3]),
        rgb(p[4]),
        rgb(p[5]),
        rgb(p[6]),
    ]
};

/// The colour of the `k`-th of several orbits, in turn.
pub(super) fn palette(k: usize, mono: bool) -> RGBColor {
    ink(PALETTE[k % PALETTE.len()], mono)
}

/// The colour of the `k`-th of `n` orbits in order (a family by energy): from dark blue through
/// purple to dark orange; in a monochrome figure from black to a mid grey, so that the first
/// and the last orbit differ without colour too.
pub(super) fn ramp(k: usize, n: usize, mono: bool) -> RGBColor {
    let t = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        0.0
    };
    let mix = |a: f64, b: f64| (a + (b - a) * t).round().clamp(0.0, 255.0) as u8;
    if mono {
        let g = mix(0.0, 150.0);
        RGBColor(g, g, g)
    } else {
        RGBColor(mix(20.0, 215.0), mix(60.0, 95.0), mix(190.0, 0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::style::OKABE_ITO;

    #[test]
    fn every_key_the_figures_use_is_in_the_table() {
        for v in VERDICTS {
            assert!(look("verdict", verdict_key(v)).is_some(), "{v:?}");
        }
        for k in KINDS {
            assert!(look("event", event_key(k)).is_some(), "{k:?}");
            assert!(look("boundary", event_key(k)).is_some(), "{k:?}");
        }
        for v in ORBIT_VERDICTS {
            assert!(look("orbit_verdict", orbit_key(v)).is_some(), "{v:?}");
        }
        assert_eq!(rgb("#0072B2"), RGBColor(0, 114, 178));
    }

    #[test]
    fn the_verdicts_differ_in_colour_and_in_stroke() {
        let vs: Vec<_> = STYLE.iter().filter(|l| l.group == "verdict").collect();
        for (i, a) in vs.iter().enumerate() {
            for b in &vs[i + 1..] {
                assert_ne!(a.color, b.color);
                assert!(
                    a.dash_pt != b.dash_pt || a.width_pt != b.width_pt,
                    "{a:?} {b:?}"
                );
                assert_ne!(a.hatch, b.hatch);
            }
            assert!(OKABE_ITO.contains(&a.color), "{a:?}");
        }
    }
}
