//! How each verdict, event kind and overlay is drawn: strokes, colours and fills. Every style
//! reads without colour; the colour of [`verdict_color`] and [`boundary_color`] is added on top
//! (black with [`PlotOptions::monochrome`](super::PlotOptions::monochrome)).

use plotters::style::{RGBColor, BLACK};

use crate::{EventKind, OrbitEventKind, OrbitStability, Resonance, Stability};

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

/// How a polyline is stroked.
#[derive(Debug, Clone, Copy)]
pub(super) enum Stroke {
    Solid(u32),
    /// Width, dash, gap (pixels).
    Dashed(u32, u32, u32),
}

/// The white band under a boundary curve of an atlas, so that it stands out of the shading.
pub(super) const BOUNDARY_UNDERLAY: Stroke = Stroke::Solid(7);

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
    match v {
        Stability::SecularlyStable => Stroke::Solid(4),
        Stability::GyroscopicallyStabilized => Stroke::Solid(1),
        Stability::Unstable => Stroke::Dashed(2, 9, 6),
        Stability::Degenerate => Stroke::Dashed(2, 2, 4),
    }
}

pub(super) fn verdict_color(v: Stability, mono: bool) -> RGBColor {
    let color = match v {
        Stability::SecularlyStable => RGBColor(0, 130, 55),
        Stability::GyroscopicallyStabilized => RGBColor(25, 80, 210),
        Stability::Unstable => RGBColor(205, 30, 30),
        Stability::Degenerate => RGBColor(110, 110, 110),
    };
    ink(color, mono)
}

/// The stroke of a boundary curve of an atlas: solid, dashed, dotted.
pub(super) fn boundary_stroke(k: EventKind) -> Stroke {
    match k {
        EventKind::Fold => Stroke::Solid(3),
        EventKind::BranchPoint => Stroke::Dashed(3, 12, 5),
        EventKind::HamiltonianHopf => Stroke::Dashed(3, 3, 4),
        EventKind::ArnoldDegenerate | EventKind::Resonance => Stroke::Dashed(2, 2, 2),
    }
}

/// The stroke of a nonlinear curve of an atlas ([`StabilityAtlas::nonlinear`]): thin, with dashes
/// of its own for D = 0 (dots), 1:2 (medium dashes) and 1:3 (long dashes), and a label on it.
///
/// [`StabilityAtlas::nonlinear`]: crate::StabilityAtlas::nonlinear
pub(super) fn nonlinear_stroke(resonance: Option<Resonance>) -> Stroke {
    match resonance {
        None => Stroke::Dashed(2, 2, 3),
        Some(Resonance::OneToTwo) => Stroke::Dashed(2, 7, 4),
        Some(_) => Stroke::Dashed(2, 16, 4),
    }
}

pub(super) fn boundary_color(k: EventKind, mono: bool) -> RGBColor {
    let color = match k {
        EventKind::Fold => BLACK,
        EventKind::BranchPoint => RGBColor(90, 0, 130),
        EventKind::HamiltonianHopf => RGBColor(150, 50, 0),
        EventKind::ArnoldDegenerate | EventKind::Resonance => RGBColor(0, 90, 150),
    };
    ink(color, mono)
}

/// The pattern over the background of an atlas cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Pattern {
    Plain,
    Dots,
    Hatch,
    CrossHatch,
}

/// Fill of an atlas cell: background colour (a grey level in a monochrome figure) and pattern.
pub(super) fn cell_fill(v: Stability, mono: bool) -> (RGBColor, Pattern) {
    let (grey, tint, pattern) = match v {
        Stability::SecularlyStable => (240, RGBColor(228, 244, 228), Pattern::Plain),
        Stability::GyroscopicallyStabilized => (212, RGBColor(200, 214, 240), Pattern::Dots),
        Stability::Unstable => (180, RGBColor(238, 178, 172), Pattern::Hatch),
        Stability::Degenerate => (150, RGBColor(160, 160, 160), Pattern::CrossHatch),
    };
    (
        if mono {
            RGBColor(grey, grey, grey)
        } else {
            tint
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
/// solid where elliptic (stable), dashed where hyperbolic, dotted where inverse hyperbolic, and a
/// medium solid line where parabolic (along a whole run only in degenerate families).
pub(super) fn orbit_stroke(v: OrbitStability) -> Stroke {
    match v {
        OrbitStability::Elliptic => Stroke::Solid(4),
        OrbitStability::Parabolic => Stroke::Solid(2),
        OrbitStability::Hyperbolic => Stroke::Dashed(2, 9, 6),
        OrbitStability::InverseHyperbolic => Stroke::Dashed(2, 2, 4),
    }
}

pub(super) fn orbit_color(v: OrbitStability, mono: bool) -> RGBColor {
    let color = match v {
        OrbitStability::Elliptic => RGBColor(0, 130, 55),
        OrbitStability::Parabolic => RGBColor(90, 0, 130),
        OrbitStability::Hyperbolic => RGBColor(205, 30, 30),
        OrbitStability::InverseHyperbolic => RGBColor(200, 110, 0),
    };
    ink(color, mono)
}

/// The legend text of a verdict of periodic orbits.
pub(super) fn orbit_verdict_name(v: OrbitStability) -> &'static str {
    match v {
        OrbitStability::Elliptic => "elliptic, |k| < 1",
        OrbitStability::Parabolic => "parabolic, k = ±1",
        OrbitStability::Hyperbolic => "hyperbolic, k > 1",
        OrbitStability::InverseHyperbolic => "inverse hyperbolic, k < −1",
    }
}

/// The name of an event of a family of periodic orbits, in the legend and beside its marker.
pub(super) fn orbit_event_name(k: OrbitEventKind) -> &'static str {
    match k {
        OrbitEventKind::Fold => "fold",
        OrbitEventKind::BranchPoint => "branch point",
        OrbitEventKind::PeriodDoubling => "period doubling",
    }
}

/// The grey of the reference lines `k = ±1` of a stability diagram of periodic orbits.
pub(super) const PARABOLIC_LINE: RGBColor = RGBColor(100, 100, 100);

/// Colours told apart on white, for one curve or cloud of points per orbit (in turn); black in a
/// monochrome figure.
const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(188, 189, 34),
];

/// The colour of the `k`-th of several orbits, in turn.
pub(super) fn palette(k: usize, mono: bool) -> RGBColor {
    ink(PALETTE[k % PALETTE.len()], mono)
}

/// The colour of the `k`-th of `n` orbits in order (a family by energy): from dark blue through
/// purple to dark orange; black in a monochrome figure.
pub(super) fn ramp(k: usize, n: usize, mono: bool) -> RGBColor {
    let t = if n > 1 {
        k as f64 / (n - 1) as f64
    } else {
        0.0
    };
    let mix = |a: f64, b: f64| (a + (b - a) * t).round().clamp(0.0, 255.0) as u8;
    ink(
        RGBColor(mix(20.0, 215.0), mix(60.0, 95.0), mix(190.0, 0.0)),
        mono,
    )
}
