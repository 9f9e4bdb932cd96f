//! The SVG figures of `routh::plot`, on diagrams and atlases built by hand.
#![cfg(feature = "plot")]

use std::collections::HashSet;
use std::path::PathBuf;

use routh::plot::{
    bifurcation_diagram_svg, energy_momentum_svg, stability_atlas_svg, DiagramAxis, PlotError,
    PlotOptions,
};
use routh::style::look;
use routh::{
    BifurcationDiagram, BoundaryCurve, Branch, BranchEvent, BranchSample, Complex, EventKind,
    Stability, StabilityAtlas, StabilityReport, SteadyMotion, Vector3,
};

/// The colour of a look of the style (`routh::style`), as the SVGs write it.
fn c(group: &str, name: &str) -> &'static str {
    look(group, name).unwrap().color
}

/// The ink of the atlas's hatching and dots.
const HATCH: &str = "#8C8C8C";

fn out(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-plot-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

fn read_svg(path: &PathBuf) -> String {
    let svg = std::fs::read_to_string(path).unwrap();
    assert!(!svg.is_empty());
    assert!(
        svg.trim_start().starts_with("<svg"),
        "{}",
        &svg[..80.min(svg.len())]
    );
    assert!(svg.trim_end().ends_with("</svg>"));
    svg
}

/// The contents of the `<text>` elements, trimmed.
fn texts(svg: &str) -> Vec<String> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let body = &t[t.find('>')? + 1..];
            let text = body[..body.find("</text>")?].trim();
            Some(
                text.replace("&lt;", "<")
                    .replace("&gt;", ">")
                    .replace("&amp;", "&"),
            )
        })
        .collect()
}

fn has_text(svg: &str, text: &str) -> bool {
    texts(svg).iter().any(|t| t == text)
}

/// Number of path elements (`<polyline>` or `<line>`) drawn with the given colour and width.
fn strokes(svg: &str, color: &str, width: u32) -> usize {
    svg.lines()
        .filter(|l| l.starts_with("<polyline") || l.starts_with("<line"))
        .filter(|l| l.contains(&format!("stroke=\"{color}\"")))
        .filter(|l| l.contains(&format!("stroke-width=\"{width}\"")))
        .count()
}

fn point(s: f64, p_psi: f64, tilt: f64, verdict: Stability, isolated: bool) -> BranchSample {
    let gamma = Vector3::new(tilt.sin(), 0.0, tilt.cos());
    let energy = 1.0 + 0.5 * p_psi * p_psi / (1.0 + tilt.sin().powi(2)) + gamma.z;
    BranchSample {
        s,
        steady: SteadyMotion {
            p_psi,
            gamma,
            psi_dot: -p_psi,
            mu: 0.0,
            amended_potential: energy,
            energy,
            isolated,
        },
        report: StabilityReport {
            restricted_hessian_eigenvalues: [0.0; 2],
            degree_of_instability: 0,
            f2_roots: [Complex::new(0.0, 0.0); 4],
            verdict,
        },
    }
}

/// A diagram over `s = p_ψ` with every verdict and every event kind: the upright branch
/// (unstable, then gyroscopic past a Hamiltonian–Hopf, secular past a branch point), a branch of
/// tilted circles born at the branch point, and a fold with a degenerate point at its nose.
fn full_diagram() -> BifurcationDiagram {
    use Stability::*;
    let upright = Branch {
        points: (0..=60)
            .map(|i| {
                let s = 0.1 * i as f64;
                let v = if s < 2.0 {
                    Unstable
                } else if s < 4.0 {
                    GyroscopicallyStabilized
                } else {
                    SecularlyStable
                };
                point(s, s, 0.0, v, true)
            })
            .collect(),
        isolated: true,
    };
    let circles = Branch {
        points: (0..=40)
            .map(|i| {
                let s = 0.1 * i as f64;
                point(s, s, (s / 4.0).min(1.0).acos(), SecularlyStable, false)
            })
            .collect(),
        isolated: false,
    };
    // A fold at s = 5: θ = 2.0 ± sqrt(5 − s), unstable on one side, stable on the other.
    let fold = Branch {
        points: (-20..=20)
            .map(|i| {
                let u = 0.05 * i as f64;
                let s = 5.0 - u * u;
                // Degenerate on a short stretch through the fold, long enough to be seen.
                let v = match i {
                    -2..=2 => Degenerate,
                    i if i < 0 => Unstable,
                    _ => SecularlyStable,
                };
                point(s, s, 2.0 + u, v, true)
            })
            .collect(),
        isolated: true,
    };
    let event = |kind, s: f64, tilt: f64, branch, before, after| BranchEvent {
        kind,
        s,
        gamma: Vector3::new(tilt.sin(), 0.0, tilt.cos()),
        branch,
        before,
        after,
        nonlinear: None,
    };
    BifurcationDiagram {
        branches: vec![upright, circles, fold],
        events: vec![
            event(
                EventKind::HamiltonianHopf,
                2.0,
                0.0,
                0,
                Unstable,
                GyroscopicallyStabilized,
            ),
            event(
                EventKind::BranchPoint,
                4.0,
                0.0,
                0,
                GyroscopicallyStabilized,
                SecularlyStable,
            ),
            event(EventKind::Fold, 5.0, 2.0, 2, Unstable, SecularlyStable),
        ],
        ..Default::default()
    }
}

fn all_verdicts_atlas() -> StabilityAtlas {
    let x: Vec<f64> = (0..=30).map(|i| i as f64 / 10.0).collect();
    let y: Vec<f64> = (0..=20).map(|j| j as f64 / 10.0).collect();
    let verdicts = y
        .iter()
        .map(|&y| {
            x.iter()
                .map(|&x| {
                    if x > 2.5 && y > 1.5 {
                        None
                    } else if (y - 1.0).abs() < 0.01 && x < 1.0 {
                        Some(Stability::Degenerate)
                    } else if y > x * x / 4.0 + 0.3 {
                        Some(Stability::SecularlyStable)
                    } else if y > x / 2.0 {
                        Some(Stability::GyroscopicallyStabilized)
                    } else {
                        Some(Stability::Unstable)
                    }
                })
                .collect()
        })
        .collect();
    let parabola = (0..=60)
        .map(|i| {
            let x = i as f64 / 20.0;
            (x, x * x / 4.0 + 0.3)
        })
        .collect();
    BoundaryCurveSet::new()
        .with(EventKind::Fold, parabola)
        .with(EventKind::HamiltonianHopf, vec![(0.0, 0.0), (3.0, 1.5)])
        .with(
            EventKind::BranchPoint,
            vec![(2.5, 2.0), (2.5, 1.5), (3.0, 1.5)],
        )
        .into_atlas(x, y, verdicts)
}

struct BoundaryCurveSet(Vec<BoundaryCurve>);

impl BoundaryCurveSet {
    fn new() -> Self {
        BoundaryCurveSet(Vec::new())
    }
    fn with(mut self, kind: EventKind, points: Vec<(f64, f64)>) -> Self {
        self.0.push(BoundaryCurve { kind, points });
        self
    }
    fn into_atlas(
        self,
        x: Vec<f64>,
        y: Vec<f64>,
        verdicts: Vec<Vec<Option<Stability>>>,
    ) -> StabilityAtlas {
        StabilityAtlas {
            x,
            y,
            verdicts,
            boundaries: self.0,
            ..Default::default()
        }
    }
}

/// The verdicts named in the legend are those whose style's colour strokes a line in the
/// figure besides the legend's own swatch: each listed verdict's colour is drawn (at least two
/// strokes), each verdict not listed is not drawn at all.
fn assert_legend_is_what_is_drawn(svg: &str) {
    let keys = [
        (Stability::SecularlyStable, "secularly_stable"),
        (
            Stability::GyroscopicallyStabilized,
            "gyroscopically_stabilized",
        ),
        (Stability::Unstable, "unstable"),
        (Stability::Degenerate, "degenerate"),
    ];
    for (v, key) in keys {
        let color = c("verdict", key);
        let n = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") || l.starts_with("<line"))
            .filter(|l| l.contains(&format!("stroke=\"{color}\"")))
            .count();
        if has_text(svg, &v.to_string()) {
            assert!(n >= 2, "{v} is listed but drawn {n} times");
        } else {
            assert_eq!(n, 0, "{v} is drawn but not listed");
        }
    }
}

const VERDICTS: [Stability; 4] = [
    Stability::SecularlyStable,
    Stability::GyroscopicallyStabilized,
    Stability::Unstable,
    Stability::Degenerate,
];

#[test]
fn bifurcation_diagram_has_every_style_marker_and_label() {
    let path = out("bifurcation.svg");
    let opts = PlotOptions {
        title: "Test diagram".into(),
        x_label: "cyclic momentum p_ψ".into(),
        y: DiagramAxis::Tilt,
        ..PlotOptions::default()
    };
    bifurcation_diagram_svg(&full_diagram(), &path, &opts).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "Test diagram"));
    assert!(has_text(&svg, "cyclic momentum p_ψ"));
    assert!(has_text(&svg, DiagramAxis::Tilt.label()));
    for v in VERDICTS {
        assert!(has_text(&svg, &v.to_string()), "legend lacks {v}");
    }
    assert_legend_is_what_is_drawn(&svg);
    for k in [
        EventKind::Fold,
        EventKind::BranchPoint,
        EventKind::HamiltonianHopf,
    ] {
        assert!(has_text(&svg, &k.to_string()), "legend lacks {k}");
    }
    assert!(has_text(&svg, "circle of steady motions"));
    // Unstable runs are dashed: many short red segments, not one polyline per run.
    let dashes = strokes(&svg, c("verdict", "unstable"), 2);
    assert!(dashes > 20, "{dashes} unstable segments");
    // Stable runs are one polyline each: thick for secular, thin for gyroscopic.
    assert!(strokes(&svg, c("verdict", "secularly_stable"), 4) >= 3);
    // Smooth at print resolution: the curves are written in fractional pixels, not rounded to
    // whole ones, and the circles' branch (few samples, bending) in many short pieces.
    let runs = polylines(&svg, c("verdict", "secularly_stable"), 4);
    assert!(runs
        .iter()
        .flatten()
        .any(|p| p.0.fract() != 0.0 || p.1.fract() != 0.0));
    assert!(runs.iter().map(Vec::len).max().unwrap() > 2 * 41);
    assert!(strokes(&svg, c("verdict", "gyroscopically_stabilized"), 2) >= 1);
    // The event markers: a triangle (polygon), a circle, a square (rect).
    assert!(svg.contains("<polygon"));
    assert!(svg.contains("<circle"));
    assert!(svg.contains("<rect"));
}

#[test]
fn monochrome_keeps_the_line_styles() {
    let path = out("bifurcation-mono.svg");
    let opts = PlotOptions {
        monochrome: true,
        ..PlotOptions::default()
    };
    bifurcation_diagram_svg(&full_diagram(), &path, &opts).unwrap();
    let svg = read_svg(&path);
    assert!(
        !svg.contains(c("verdict", "unstable")) && !svg.contains(c("verdict", "secularly_stable"))
    );
    assert!(strokes(&svg, "#000000", 2) > 20, "dashes and dots");
    assert!(strokes(&svg, "#000000", 4) >= 3, "thick secular runs");
    // Default labels: the parameter "s" and the axis of the default `y`.
    assert!(has_text(&svg, "s"));
    assert!(has_text(&svg, DiagramAxis::GammaZ.label()));
}

#[test]
fn a_verdict_seen_at_one_sample_under_a_marker_is_neither_drawn_nor_listed() {
    // The fold's own sample is degenerate (the test is inconclusive exactly there): a stretch of
    // a pixel or two, under the fold's marker. The legend lists only what the figure shows.
    let mut d = full_diagram();
    for (i, p) in d.branches[2].points.iter_mut().enumerate() {
        p.report.verdict = match i {
            20 => Stability::Degenerate,
            i if i < 20 => Stability::Unstable,
            _ => Stability::SecularlyStable,
        };
    }
    let path = out("bifurcation-one-degenerate.svg");
    bifurcation_diagram_svg(&d, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(!has_text(&svg, &Stability::Degenerate.to_string()));
    assert!(!svg.contains(c("verdict", "degenerate")));
    assert!(has_text(&svg, &Stability::Unstable.to_string()));
}

#[test]
fn legend_names_only_what_occurs() {
    let mut d = full_diagram();
    d.branches.truncate(2);
    for p in &mut d.branches[0].points {
        p.report.verdict = Stability::SecularlyStable;
    }
    d.events.retain(|e| e.kind == EventKind::BranchPoint);
    let path = out("bifurcation-partial.svg");
    bifurcation_diagram_svg(&d, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, &Stability::SecularlyStable.to_string()));
    assert!(has_text(&svg, &EventKind::BranchPoint.to_string()));
    for absent in [
        Stability::Unstable.to_string(),
        Stability::GyroscopicallyStabilized.to_string(),
        Stability::Degenerate.to_string(),
        EventKind::Fold.to_string(),
        EventKind::HamiltonianHopf.to_string(),
    ] {
        assert!(!has_text(&svg, &absent), "legend names {absent}");
    }
}

#[test]
fn every_diagram_axis_draws() {
    for y in [
        DiagramAxis::GammaZ,
        DiagramAxis::GammaX,
        DiagramAxis::GammaY,
        DiagramAxis::Tilt,
        DiagramAxis::AmendedPotential,
        DiagramAxis::Energy,
        DiagramAxis::PsiDot,
    ] {
        let path = out(&format!("axis-{y:?}.svg"));
        let opts = PlotOptions {
            y,
            ..PlotOptions::default()
        };
        bifurcation_diagram_svg(&full_diagram(), &path, &opts).unwrap();
        let svg = read_svg(&path);
        assert!(has_text(&svg, y.label()), "{y:?}");
        assert!(has_text(&svg, &EventKind::Fold.to_string()), "{y:?}");
    }
}

#[test]
fn energy_momentum_diagram() {
    let path = out("energy-momentum.svg");
    energy_momentum_svg(&full_diagram(), &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "p_ψ"));
    assert!(has_text(&svg, "energy E"));
    assert_legend_is_what_is_drawn(&svg);
    assert!(has_text(&svg, &EventKind::HamiltonianHopf.to_string()));
    // Each event is named beside its marker, besides the legend's entry for its kind.
    let named = |kind: EventKind| {
        texts(&svg)
            .iter()
            .filter(|t| **t == kind.to_string())
            .count()
    };
    for kind in [
        EventKind::Fold,
        EventKind::BranchPoint,
        EventKind::HamiltonianHopf,
    ] {
        let events = full_diagram()
            .events
            .iter()
            .filter(|e| e.kind == kind)
            .count();
        if events > 0 {
            assert_eq!(named(kind), events + 1, "{kind}");
        }
    }
    assert!(strokes(&svg, c("verdict", "unstable"), 2) > 10);

    let opts = PlotOptions {
        x_label: "momentum".into(),
        y_label: "E (J)".into(),
        ..PlotOptions::default()
    };
    energy_momentum_svg(&full_diagram(), &path, &opts).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "momentum") && has_text(&svg, "E (J)"));
}

#[test]
fn stability_atlas_has_every_shading_curve_and_label() {
    let path = out("atlas.svg");
    let opts = PlotOptions {
        title: "Test atlas".into(),
        x_label: "mgl".into(),
        y_label: "asymmetry".into(),
        ..PlotOptions::default()
    };
    stability_atlas_svg(&all_verdicts_atlas(), &path, &opts).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "Test atlas") && has_text(&svg, "mgl") && has_text(&svg, "asymmetry"));
    for v in VERDICTS {
        assert!(has_text(&svg, &v.to_string()), "legend lacks {v}");
    }
    assert!(has_text(&svg, "no steady motion"));
    for k in [
        EventKind::Fold,
        EventKind::BranchPoint,
        EventKind::HamiltonianHopf,
    ] {
        assert!(has_text(&svg, &format!("{k} boundary")), "legend lacks {k}");
    }
    // Hatching (thin dark lines) and dots (small circles).
    assert!(strokes(&svg, HATCH, 1) > 50);
    assert!(svg.matches("<circle").count() > 50);

    // The same in greys: every verdict still has its own pattern.
    let path = out("atlas-full-mono.svg");
    let mono = PlotOptions {
        monochrome: true,
        ..opts
    };
    stability_atlas_svg(&all_verdicts_atlas(), &path, &mono).unwrap();
    let svg = read_svg(&path);
    assert!(strokes(&svg, HATCH, 1) > 50);
    assert!(svg.matches("<circle").count() > 50);
    assert!(
        !svg.contains(look("verdict", "unstable").unwrap().fill.unwrap()),
        "no tint in monochrome"
    );
}

#[test]
fn atlas_of_one_verdict_and_monochrome() {
    let atlas = StabilityAtlas {
        x: vec![0.0, 1.0],
        y: vec![0.0, 1.0, 2.0],
        verdicts: vec![vec![Some(Stability::Unstable); 2]; 3],
        boundaries: vec![],
        ..Default::default()
    };
    let path = out("atlas-mono.svg");
    let opts = PlotOptions {
        monochrome: true,
        ..PlotOptions::default()
    };
    stability_atlas_svg(&atlas, &path, &opts).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, &Stability::Unstable.to_string()));
    assert!(!has_text(&svg, &Stability::SecularlyStable.to_string()));
    assert!(!svg.contains("boundary"));
    assert!(has_text(&svg, "y"));
    // The atlas knows no names of its parameters: the default x label is "x", not the "s" of a
    // bifurcation diagram's parameter.
    assert!(has_text(&svg, "x") && !has_text(&svg, "s"));
}

#[test]
fn atlas_legend_tells_a_lost_motion_from_no_steady_motion() {
    let verdicts = vec![
        vec![Some(Stability::Unstable), None],
        vec![Some(Stability::Unstable), None],
    ];
    let atlas = |lost: Vec<Vec<bool>>| StabilityAtlas {
        x: vec![0.0, 1.0],
        y: vec![0.0, 1.0],
        verdicts: verdicts.clone(),
        lost,
        ..Default::default()
    };
    let path = out("atlas-lost.svg");
    let opts = PlotOptions::default();
    // The upper cell lost along its row, the lower one beyond a fold.
    stability_atlas_svg(
        &atlas(vec![vec![false; 2], vec![false, true]]),
        &path,
        &opts,
    )
    .unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "motion lost"));
    assert!(has_text(&svg, "no steady motion"));
    // Only beyond a fold (and without the flags at all).
    for lost in [vec![vec![false; 2]; 2], vec![]] {
        stability_atlas_svg(&atlas(lost), &path, &opts).unwrap();
        let svg = read_svg(&path);
        assert!(!has_text(&svg, "motion lost"));
        assert!(has_text(&svg, "no steady motion"));
    }
}

#[test]
fn errors() {
    let path = out("never.svg");
    let opts = PlotOptions::default();
    assert!(matches!(
        bifurcation_diagram_svg(&BifurcationDiagram::default(), &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    let hollow = BifurcationDiagram {
        branches: vec![Branch {
            points: vec![],
            isolated: true,
        }],
        events: vec![],
        ..Default::default()
    };
    assert!(matches!(
        energy_momentum_svg(&hollow, &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    let mut nan = full_diagram();
    for b in &mut nan.branches {
        for p in &mut b.points {
            p.s = f64::NAN;
        }
    }
    assert!(matches!(
        bifurcation_diagram_svg(&nan, &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    assert!(matches!(
        stability_atlas_svg(&StabilityAtlas::default(), &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    let mut ragged = all_verdicts_atlas();
    ragged.verdicts[3].pop();
    assert!(matches!(
        stability_atlas_svg(&ragged, &path, &opts),
        Err(PlotError::InvalidData(_))
    ));
    let mut descending = all_verdicts_atlas();
    descending.x.reverse();
    assert!(matches!(
        stability_atlas_svg(&descending, &path, &opts),
        Err(PlotError::InvalidData(_))
    ));
    let tiny = PlotOptions {
        width: 100,
        ..PlotOptions::default()
    };
    assert!(matches!(
        bifurcation_diagram_svg(&full_diagram(), &path, &tiny),
        Err(PlotError::InvalidOptions(_))
    ));
    assert!(!path.exists(), "no file is written on error");

    let unwritable = std::env::temp_dir()
        .join(format!("routh-plot-no-such-dir-{}", std::process::id()))
        .join("x.svg");
    let err = bifurcation_diagram_svg(&full_diagram(), &unwritable, &opts).unwrap_err();
    assert!(matches!(err, PlotError::Io(_)), "{err}");
    assert!(err.to_string().contains("cannot write"));
    assert!(matches!(
        stability_atlas_svg(&all_verdicts_atlas(), &unwritable, &opts),
        Err(PlotError::Io(_))
    ));
}

#[test]
fn overlays_are_drawn_and_named() {
    let overlays = vec![routh::plot::Overlay {
        label: "closed form p² = 4A₁mgl".into(),
        points: (0..50)
            .map(|k| (0.5 + 0.03 * k as f64, 1.0 + 0.05 * k as f64))
            .collect(),
    }];
    let opts = PlotOptions {
        overlays,
        ..PlotOptions::default()
    };
    let path = out("overlay_atlas.svg");
    routh::plot::stability_atlas_svg(&all_verdicts_atlas(), &path, &opts).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "closed form p² = 4A₁mgl"));
    let path = out("overlay_diagram.svg");
    routh::plot::bifurcation_diagram_svg(&full_diagram(), &path, &opts).unwrap();
    assert!(has_text(&read_svg(&path), "closed form p² = 4A₁mgl"));
    // Outside the axes it is clipped away, and so is its legend entry.
    let far = PlotOptions {
        overlays: vec![routh::plot::Overlay {
            label: "far away".into(),
            points: vec![(1e6, 1e6), (2e6, 2e6)],
        }],
        ..PlotOptions::default()
    };
    let path = out("overlay_far.svg");
    routh::plot::stability_atlas_svg(&all_verdicts_atlas(), &path, &far).unwrap();
    assert!(!has_text(&read_svg(&path), "far away"));
}

/// The sample type's former name still names the same type (code written against it compiles).
#[test]
#[allow(deprecated)]
fn branch_point_is_the_deprecated_name_of_branch_sample() {
    let old: routh::BranchPoint = point(1.0, 1.0, 0.0, Stability::SecularlyStable, true);
    let new: BranchSample = old.clone();
    assert_eq!(old, new);
}

/// The nonlinear events of a diagram (as `ContinuationOptions::nonlinear` adds them) are marked
/// ○ and ✕, named in the legend, and each carries its name beside it (`1:2`, `1:3`, `D = 0`).
#[test]
fn nonlinear_events_are_marked_and_named() {
    use routh::{NonlinearEventVerdicts, NonlinearVerdict, Resonance};
    use Stability::GyroscopicallyStabilized as G;
    let mut d = full_diagram();
    let verdicts = |resonance| NonlinearEventVerdicts {
        resonance,
        before: NonlinearVerdict::LyapunovStable,
        at: NonlinearVerdict::Undecided,
        after: NonlinearVerdict::LyapunovStable,
    };
    for (kind, s, res) in [
        (EventKind::Resonance, 2.5, Some(Resonance::OneToTwo)),
        (EventKind::Resonance, 3.0, Some(Resonance::OneToThree)),
        (EventKind::ArnoldDegenerate, 3.5, None),
    ] {
        d.events.push(BranchEvent {
            kind,
            s,
            gamma: Vector3::z(),
            branch: 0,
            before: G,
            after: G,
            nonlinear: Some(verdicts(res)),
        });
    }
    d.events.sort_by(|a, b| a.s.total_cmp(&b.s));
    let path = out("nonlinear-events.svg");
    bifurcation_diagram_svg(&d, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    for name in ["1:2", "1:3", "D = 0"] {
        assert!(has_text(&svg, name), "{name}");
    }
    assert!(has_text(&svg, &EventKind::Resonance.to_string()));
    assert!(has_text(&svg, &EventKind::ArnoldDegenerate.to_string()));
    // Without them: no such names.
    let path = out("no-nonlinear-events.svg");
    bifurcation_diagram_svg(&full_diagram(), &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(!has_text(&svg, "1:2") && !has_text(&svg, &EventKind::Resonance.to_string()));
}

/// The nonlinear curves of an atlas are stroked (dashed, one pattern each), named in the
/// legend and labelled on the curve (so that they read without colour), in colour and in
/// monochrome.
#[test]
fn atlas_nonlinear_curves_are_drawn_and_named() {
    use routh::{NonlinearCurve, Resonance};
    let mut atlas = all_verdicts_atlas();
    let curve = |resonance: Option<Resonance>, y0: f64| {
        let pts: Vec<(f64, f64)> = (0..=10)
            .map(|i| (1.0 + 0.1 * i as f64, y0 + 0.02 * i as f64))
            .collect();
        NonlinearCurve {
            kind: if resonance.is_some() {
                EventKind::Resonance
            } else {
                EventKind::ArnoldDegenerate
            },
            resonance,
            segments: pts.windows(2).map(|w| [w[0], w[1]]).collect(),
            crossings: pts,
        }
    };
    atlas.nonlinear = vec![
        curve(Some(Resonance::OneToTwo), 0.6),
        curve(Some(Resonance::OneToThree), 0.8),
        curve(None, 1.0),
    ];
    for mono in [false, true] {
        let path = out(&format!("atlas-nonlinear-{mono}.svg"));
        let opts = PlotOptions {
            monochrome: mono,
            ..PlotOptions::default()
        };
        stability_atlas_svg(&atlas, &path, &opts).unwrap();
        let svg = read_svg(&path);
        for (legend, label) in [
            ("1:2 resonance", "1:2"),
            ("1:3 resonance", "1:3"),
            ("D = 0 (Arnold-degenerate)", "D = 0"),
        ] {
            assert!(has_text(&svg, legend), "{legend}");
            assert!(has_text(&svg, label), "{label}");
        }
        // Dashed: many short pieces (plotters writes each dash as a polyline).
        if !mono {
            assert!(
                strokes(&svg, c("boundary", "arnold_degenerate"), 2) > 60,
                "{}",
                strokes(&svg, c("boundary", "arnold_degenerate"), 2)
            );
        }
    }
}

// --- Figures of periodic orbits ------------------------------------------------------------------

use routh::periodic::SectionOrbit;
use routh::plot::{
    orbit_family_svg, orbit_periods_svg, orbits_on_sphere_svg, poincare_section_svg,
    stability_index_axis,
};
use routh::{
    OrbitEvent, OrbitEventKind, OrbitFamily, OrbitStability, PeriodicOrbit, PoincareSection,
    Trajectory,
};

/// An orbit of a made-up family: energy `e`, index `k`, period `t`.
fn orbit(e: f64, k: f64, t: f64) -> PeriodicOrbit {
    PeriodicOrbit {
        omega0: Vector3::zeros(),
        gamma0: -Vector3::z(),
        period: t,
        energy: e,
        p_psi: 0.0,
        precession: 0.0,
        body_turn: 0.0,
        multipliers: PeriodicOrbit::multipliers_from_index(k),
        stability_index: k,
        stability: OrbitStability::from_index(k, 1e-9),
        degenerate: false,
        amplitude: e,
    }
}

fn orbit_event(kind: OrbitEventKind, o: PeriodicOrbit) -> OrbitEvent {
    OrbitEvent {
        kind,
        energy: o.energy,
        orbit: o,
        before: OrbitStability::Elliptic,
        after: OrbitStability::Hyperbolic,
    }
}

/// The index of the swing family below: linear, through `k = −1` at `E = 0.5` (a period
/// doubling), back through `−1` near `E = 1`, through `k = 1` at `E = 1.5` (a branch point), then
/// up to `k ≈ 300` (`10^E`) past `E = 2.2`.
fn swing_index(e: f64) -> f64 {
    if e < 1.0 {
        0.9 - 3.8 * e
    } else if e <= 2.2 {
        -0.8 + 3.6 * (e - 1.0)
    } else {
        10f64.powf(e)
    }
}

fn swing_family() -> OrbitFamily {
    let orbits = (0..50)
        .map(|i| {
            let e = 0.03 + 0.05 * i as f64;
            orbit(e, swing_index(e), 6.0 + e * e)
        })
        .collect();
    OrbitFamily {
        orbits,
        events: vec![
            orbit_event(OrbitEventKind::PeriodDoubling, orbit(0.5, -1.0, 6.25)),
            orbit_event(OrbitEventKind::BranchPoint, orbit(1.5, 1.0, 8.25)),
        ],
        stop: None,
    }
}

/// `(x, y)` pairs of an SVG `points` attribute.
fn points_attr(line: &str) -> Vec<(f64, f64)> {
    let Some(i) = line.find("points=\"") else {
        return vec![];
    };
    let rest = &line[i + 8..];
    rest[..rest.find('"').unwrap()]
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The value of attribute `name` of an SVG element's line.
fn attr(line: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let i = line.find(&key)? + key.len();
    let rest = &line[i..];
    Some(rest[..rest.find('"')?].to_string())
}

/// The polylines drawn with this colour and width, as point lists.
fn polylines(svg: &str, color: &str, width: u32) -> Vec<Vec<(f64, f64)>> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline"))
        .filter(|l| l.contains(&format!("stroke=\"{color}\"")))
        .filter(|l| l.contains(&format!("stroke-width=\"{width}\"")))
        .map(points_attr)
        .collect()
}

/// The centres (vertex means) of the filled polygons of this colour with `n` vertices.
fn polygon_centres(svg: &str, fill: &str, n: usize) -> Vec<(f64, f64)> {
    svg.lines()
        .filter(|l| l.starts_with("<polygon"))
        .filter(|l| l.contains(&format!("fill=\"{fill}\"")))
        .map(points_attr)
        .filter(|p| p.len() == n)
        .map(|p| {
            let k = p.len() as f64;
            (
                p.iter().map(|q| q.0).sum::<f64>() / k,
                p.iter().map(|q| q.1).sum::<f64>() / k,
            )
        })
        .collect()
}

/// The y of the two long horizontal grey lines `k = ±1`, top first (the legend's short swatch
/// left out).
fn parabolic_lines(svg: &str) -> Vec<f64> {
    let mut ys: Vec<f64> = polylines(svg, "#646464", 1)
        .into_iter()
        .filter(|p| p.len() == 2 && p[0].1 == p[1].1 && (p[1].0 - p[0].0).abs() > 200.0)
        .map(|p| p[0].1)
        .collect();
    ys.sort_by(f64::total_cmp);
    ys
}

#[test]
fn stability_index_axis_is_linear_then_one_unit_a_decade() {
    assert_eq!(stability_index_axis(0.5), 0.5);
    assert_eq!(stability_index_axis(-1.0), -1.0);
    assert!((stability_index_axis(10.0) - 2.0).abs() < 1e-15);
    assert!((stability_index_axis(-1e6) + 7.0).abs() < 1e-12);
    assert!(stability_index_axis(f64::NAN).is_nan());
    let ks = [
        -1e6, -100.0, -10.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 1.0001, 2.0, 10.0, 1e6,
    ];
    assert!(ks
        .windows(2)
        .all(|w| stability_index_axis(w[0]) < stability_index_axis(w[1])));
}

/// The stability diagram: both lines k = ±1, elliptic runs thick solid and unstable ones dashed
/// or dotted, the events on the lines where the family crosses them, named, and the axis in
/// decades beyond ±1.
#[test]
fn orbit_family_diagram_marks_the_lines_runs_and_events() {
    let path = out("orbit_family.svg");
    orbit_family_svg(&swing_family(), &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    for label in [
        "E",
        "k",
        "k = 1",
        "k = −1",
        "k = ±1 (log scale beyond)",
        "elliptic, |k| < 1",
        "hyperbolic, k > 1",
        "inverse hyperbolic, k < −1",
        "period doubling",
        "branch point",
        "0",
        "10",
        "100",
        "−1",
    ] {
        assert!(
            has_text(&svg, label),
            "{label:?} missing: {:?}",
            texts(&svg)
        );
    }
    assert!(!has_text(&svg, "fold"), "no fold in this family");
    assert!(!has_text(&svg, "parabolic, k = ±1"));
    // The lines k = 1 (above) and k = −1.
    let lines = parabolic_lines(&svg);
    assert_eq!(lines.len(), 2, "{lines:?}");
    let (y_plus, y_minus) = (lines[0], lines[1]);
    assert!(y_plus < y_minus);
    // Two elliptic runs (thick green) and the legend's swatch; hyperbolic dashes (red) and
    // inverse-hyperbolic long dashes (orange).
    let elliptic = polylines(&svg, c("orbit_verdict", "elliptic"), 4);
    assert_eq!(elliptic.len(), 3, "{elliptic:?}");
    assert!(strokes(&svg, c("orbit_verdict", "hyperbolic"), 2) > 5);
    assert!(strokes(&svg, c("orbit_verdict", "inverse_hyperbolic"), 3) > 5);
    // The first elliptic run ends on k = −1 where the period doubling is marked (◆, 4 vertices,
    // black on a white halo); the second ends on k = 1 at the branch point (●).
    let mut runs = elliptic;
    runs.sort_by(|a, b| a[0].0.total_cmp(&b[0].0));
    let (first, second) = (&runs[0], &runs[1]);
    let end1 = *first.last().unwrap();
    let end2 = *second.last().unwrap();
    assert!(
        (end1.1 - y_minus).abs() <= 1.0,
        "{end1:?} vs k = −1 at {y_minus}"
    );
    assert!(
        (end2.1 - y_plus).abs() <= 1.0,
        "{end2:?} vs k = 1 at {y_plus}"
    );
    let diamonds = polygon_centres(&svg, "#000000", 4);
    assert_eq!(diamonds.len(), 2, "marker and legend swatch: {diamonds:?}");
    let pd = diamonds
        .iter()
        .copied()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap();
    assert!(
        (pd.0 - end1.0).abs() <= 1.5 && (pd.1 - y_minus).abs() <= 1.5,
        "period doubling marked at {pd:?}, the family crosses k = −1 at {end1:?}"
    );
    let dots: Vec<(f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with("<circle") && l.contains("fill=\"#000000\""))
        .filter(|l| attr(l, "r").as_deref() == Some("5"))
        .map(|l| {
            (
                attr(l, "cx").unwrap().parse().unwrap(),
                attr(l, "cy").unwrap().parse().unwrap(),
            )
        })
        .collect();
    assert!(
        dots.iter()
            .any(|c| (c.0 - end2.0).abs() <= 1.0 && (c.1 - y_plus).abs() <= 1.0),
        "branch point not at {end2:?}: {dots:?}"
    );
    // Monochrome keeps the strokes, loses the colours.
    let path = out("orbit_family_mono.svg");
    let mono = PlotOptions {
        monochrome: true,
        ..PlotOptions::default()
    };
    orbit_family_svg(&swing_family(), &path, &mono).unwrap();
    let svg = read_svg(&path);
    assert!(
        !svg.contains(c("orbit_verdict", "elliptic"))
            && !svg.contains(c("orbit_verdict", "hyperbolic"))
    );
    assert_eq!(polylines(&svg, "#000000", 4).len(), 3);
}

/// A family turning back in energy: the fold is marked at its largest energy, on k = 1.
#[test]
fn orbit_family_fold_is_marked_at_the_turn() {
    // E(s) = 1 − (s − 1)², k(s) = s: the fold at s = 1, E = 1, k = 1.
    let orbits: Vec<PeriodicOrbit> = (0..40)
        .map(|i| {
            let s = 0.025 + 0.05 * i as f64;
            orbit(1.0 - (s - 1.0).powi(2), s, 5.0 + s)
        })
        .collect();
    let family = OrbitFamily {
        orbits,
        events: vec![orbit_event(OrbitEventKind::Fold, orbit(1.0, 1.0, 6.0))],
        stop: None,
    };
    let path = out("orbit_fold.svg");
    orbit_family_svg(&family, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "fold"));
    let y_plus = parabolic_lines(&svg)[0];
    // The elliptic run (s < 1) ends at the turn, where k = 1 (the legend's swatch left out).
    let right = polylines(&svg, c("orbit_verdict", "elliptic"), 4)
        .into_iter()
        .filter(|p| p.len() > 2)
        .flatten()
        .map(|p| p.0)
        .fold(f64::MIN, f64::max);
    let triangles = polygon_centres(&svg, "#000000", 3);
    assert!(
        triangles
            .iter()
            .any(|c| (c.0 - right).abs() <= 2.0 && (c.1 - y_plus).abs() <= 2.0),
        "fold not at the turn ({right}, {y_plus}): {triangles:?}"
    );

    // The periods: T up, E across, the same marker.
    let path = out("orbit_fold_periods.svg");
    orbit_periods_svg(&family, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "T") && has_text(&svg, "E") && has_text(&svg, "fold"));
    assert!(
        parabolic_lines(&svg).is_empty(),
        "no k = ±1 in a period figure"
    );
    assert_eq!(polygon_centres(&svg, "#000000", 3).len(), 2);
}

#[test]
fn orbit_periods_follow_the_family() {
    let path = out("orbit_periods.svg");
    let opts = PlotOptions {
        title: "swings".into(),
        x_label: "energy".into(),
        y_label: "period".into(),
        ..PlotOptions::default()
    };
    orbit_periods_svg(&swing_family(), &path, &opts).unwrap();
    let svg = read_svg(&path);
    for label in [
        "swings",
        "energy",
        "period",
        "period doubling",
        "branch point",
    ] {
        assert!(has_text(&svg, label), "{label:?}");
    }
    // T = 6 + E² rises: along each elliptic run, y (pixels, downwards) falls with x.
    for run in polylines(&svg, c("orbit_verdict", "elliptic"), 4)
        .into_iter()
        .filter(|r| r.len() > 2)
    {
        assert!(run.windows(2).all(|w| w[1].0 > w[0].0 && w[1].1 <= w[0].1));
    }
}

fn ring_section() -> PoincareSection {
    let ring = |r: f64, phase: f64| SectionOrbit {
        omega0: Vector3::zeros(),
        gamma0: Vector3::y(),
        points: (0..50)
            .map(|i| {
                let a = phase + std::f64::consts::TAU * i as f64 / 50.0;
                [r * a.cos(), 2.0 * r * a.sin()]
            })
            .collect(),
        stop: None,
    };
    PoincareSection {
        p_psi: 0.25,
        energy: -1.5,
        normal: Vector3::x(),
        orbits: vec![ring(0.5, 0.0), ring(1.0, 0.1), ring(1.5, 0.2)],
    }
}

/// The section: one small dot a crossing, one colour an orbit, the fixed point as a large mark
/// at its place, the axes θ and M_n.
#[test]
fn poincare_section_draws_every_crossing_and_the_fixed_points() {
    let path = out("section.svg");
    poincare_section_svg(
        &ring_section(),
        &[[0.0, 0.0]],
        &path,
        &PlotOptions::default(),
    )
    .unwrap();
    let svg = read_svg(&path);
    for label in [
        "θ",
        "M_n",
        "150 crossings of 3 orbits",
        "periodic orbits (fixed points)",
        "p_ψ = 0.25, E = −1.5",
        "plane γ·n = 0, n = (1, 0, 0)",
    ] {
        assert!(has_text(&svg, label), "{label:?}: {:?}", texts(&svg));
    }
    let dots: Vec<(String, f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("1"))
        .map(|l| {
            (
                attr(l, "fill").unwrap(),
                attr(l, "cx").unwrap().parse().unwrap(),
                attr(l, "cy").unwrap().parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        dots.len(),
        150,
        "one dot a crossing (all on distinct pixels)"
    );
    let colours: HashSet<&str> = dots.iter().map(|d| d.0.as_str()).collect();
    assert_eq!(colours.len(), 3, "one colour an orbit");
    // The fixed point (0, 0) is the centre of the symmetric rings.
    let (x0, x1) = dots
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), d| (a.min(d.1), b.max(d.1)));
    let (y0, y1) = dots
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), d| (a.min(d.2), b.max(d.2)));
    let rings: Vec<(f64, f64)> = svg
        .lines()
        .filter(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("6"))
        .map(|l| {
            (
                attr(l, "cx").unwrap().parse().unwrap(),
                attr(l, "cy").unwrap().parse().unwrap(),
            )
        })
        .collect();
    assert_eq!(rings.len(), 2, "the fixed point and the legend's swatch");
    assert!(
        rings
            .iter()
            .any(|c| (c.0 - 0.5 * (x0 + x1)).abs() <= 1.5 && (c.1 - 0.5 * (y0 + y1)).abs() <= 1.5),
        "{rings:?} vs centre ({}, {})",
        0.5 * (x0 + x1),
        0.5 * (y0 + y1)
    );
    // Without fixed points: no mark, no legend row; monochrome: one colour.
    let path = out("section_mono.svg");
    let mono = PlotOptions {
        monochrome: true,
        ..PlotOptions::default()
    };
    poincare_section_svg(&ring_section(), &[], &path, &mono).unwrap();
    let svg = read_svg(&path);
    assert!(!has_text(&svg, "periodic orbits (fixed points)"));
    assert!(!svg
        .lines()
        .any(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("6")));
    let fills: HashSet<String> = svg
        .lines()
        .filter(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("1"))
        .map(|l| attr(l, "fill").unwrap())
        .collect();
    assert_eq!(fills.len(), 1, "{fills:?}");
}

/// A region of motion straddling θ = ±π is drawn in one piece (beyond π), not split to the two
/// edges of the figure.
#[test]
fn poincare_section_keeps_a_region_across_pi_together() {
    let mut section = ring_section();
    for o in &mut section.orbits {
        for p in &mut o.points {
            // Around θ = π: angles in (−π, π].
            let t = p[0] * 0.3 + std::f64::consts::PI;
            p[0] = if t > std::f64::consts::PI {
                t - std::f64::consts::TAU
            } else {
                t
            };
        }
    }
    assert!(section.points().any(|p| p[0] < -3.0) && section.points().any(|p| p[0] > 3.0));
    let path = out("section_wrapped.svg");
    let fixed = [[std::f64::consts::PI, 0.0]];
    poincare_section_svg(&section, &fixed, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    let mut xs: Vec<f64> = svg
        .lines()
        .filter(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("1"))
        .map(|l| attr(l, "cx").unwrap().parse().unwrap())
        .collect();
    xs.sort_by(f64::total_cmp);
    let widest = xs.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    assert!(
        widest < 30.0,
        "the crossings are split: a gap of {widest} px"
    );
    // The fixed point at θ = π sits in the middle of the rings.
    let ring = svg
        .lines()
        .find(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("6"))
        .unwrap();
    let cx: f64 = attr(ring, "cx").unwrap().parse().unwrap();
    let mid = 0.5 * (xs[0] + xs[xs.len() - 1]);
    assert!((cx - mid).abs() <= 2.0, "{cx} vs {mid}");
}

/// Swings about e₁ through the hanging position γ = −e₃ (in the plane γ₁ = 0).
fn swing_path(amplitude: f64) -> Trajectory {
    Trajectory {
        gamma: (0..=200)
            .map(|i| {
                let th = amplitude * (i as f64 / 200.0 * std::f64::consts::TAU).sin();
                Vector3::new(0.0, th.sin(), -th.cos())
            })
            .collect(),
        ..Trajectory::default()
    }
}

/// Orbits on the sphere: solid where they face the viewer, dotted behind, the body axes named
/// on the near side only.
#[test]
fn orbits_on_sphere_near_and_far() {
    let orbits = [swing_path(0.4), swing_path(1.2)];
    // From below, the swings face the viewer: the first orbit is solid (width 2) only.
    let path = out("sphere_below.svg");
    orbits_on_sphere_svg(&orbits, -Vector3::z(), &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    for label in [
        "first orbit",
        "last orbit (2 in all)",
        "−e₃",
        "e₁",
        "−e₁",
        "e₂",
        "−e₂",
    ] {
        assert!(has_text(&svg, label), "{label:?}: {:?}", texts(&svg));
    }
    assert!(!has_text(&svg, "e₃"), "e₃ is behind");
    let first = "#143CBE"; // ramp(0): (20, 60, 190)
    let last = "#D75F00"; // ramp(1): (215, 95, 0)
    let solid: Vec<_> = polylines(&svg, first, 2);
    assert!(
        solid.len() == 2 && solid.iter().any(|p| p.len() > 50),
        "the orbit and the legend swatch: {} polylines",
        solid.len()
    );
    assert_eq!(polylines(&svg, first, 1).len(), 0, "nothing behind");
    assert!(!polylines(&svg, last, 2).is_empty());
    // From above, the same swings are behind the sphere: only thin dots.
    let path = out("sphere_above.svg");
    orbits_on_sphere_svg(&orbits, Vector3::z(), &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "e₃") && !has_text(&svg, "−e₃"));
    assert_eq!(
        polylines(&svg, first, 2).len(),
        1,
        "the legend's swatch only"
    );
    assert!(polylines(&svg, first, 1).len() > 10, "dotted behind");
    // From the side (e₂), a wide swing crosses the limb: solid in front, dotted behind, the
    // parts joined on the limb.
    let path = out("sphere_side.svg");
    orbits_on_sphere_svg(
        &[swing_path(2.5)],
        Vector3::y(),
        &path,
        &PlotOptions::default(),
    )
    .unwrap();
    let svg = read_svg(&path);
    assert!(has_text(&svg, "orbit") && has_text(&svg, "γ seen from (0, 1, 0)"));
    let limb = svg
        .lines()
        .find(|l| {
            l.starts_with("<circle")
                && l.contains("fill=\"none\"")
                && l.contains("stroke=\"#000000\"")
        })
        .unwrap();
    let (cx, cy, r): (f64, f64, f64) = (
        attr(limb, "cx").unwrap().parse().unwrap(),
        attr(limb, "cy").unwrap().parse().unwrap(),
        attr(limb, "r").unwrap().parse().unwrap(),
    );
    let front: Vec<_> = polylines(&svg, first, 2)
        .into_iter()
        .filter(|p| p.len() > 10)
        .collect();
    assert!(!front.is_empty() && polylines(&svg, first, 1).len() > 10);
    for part in &front {
        for end in [part[0], part[part.len() - 1]] {
            let d = ((end.0 - cx).powi(2) + (end.1 - cy).powi(2)).sqrt();
            assert!(
                (d - r).abs() <= 1.5,
                "a front part ends at {end:?}, {d} from the centre, r = {r}"
            );
        }
    }
}

#[test]
fn orbit_figures_errors_and_whole_files() {
    let opts = PlotOptions::default();
    let path = out("orbit_never.svg");
    let empty = OrbitFamily {
        orbits: vec![],
        events: vec![],
        stop: None,
    };
    assert!(matches!(
        orbit_family_svg(&empty, &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    let nan = OrbitFamily {
        orbits: vec![orbit(f64::NAN, 0.0, 1.0)],
        ..empty.clone()
    };
    assert!(matches!(
        orbit_periods_svg(&nan, &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    let no_points = PoincareSection {
        orbits: vec![],
        ..ring_section()
    };
    assert!(matches!(
        poincare_section_svg(&no_points, &[], &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    assert!(matches!(
        poincare_section_svg(&ring_section(), &[[f64::NAN, 0.0]], &path, &opts),
        Err(PlotError::InvalidData(_))
    ));
    assert!(matches!(
        orbits_on_sphere_svg(&[], Vector3::z(), &path, &opts),
        Err(PlotError::EmptyData(_))
    ));
    assert!(matches!(
        orbits_on_sphere_svg(&[swing_path(0.3)], Vector3::zeros(), &path, &opts),
        Err(PlotError::InvalidData(_))
    ));
    let tiny = PlotOptions {
        height: 100,
        ..PlotOptions::default()
    };
    assert!(matches!(
        orbit_family_svg(&swing_family(), &path, &tiny),
        Err(PlotError::InvalidOptions(_))
    ));
    assert!(!path.exists(), "no file is written on error");

    // Whole or not at all: a directory in the way is an error and leaves nothing behind; a
    // second figure replaces the first.
    let dir = std::env::temp_dir().join(format!("routh-plot-whole-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("taken.svg")).unwrap();
    let err = orbit_family_svg(&swing_family(), dir.join("taken.svg"), &opts).unwrap_err();
    assert!(matches!(err, PlotError::Io(_)), "{err}");
    let listing = |d: &PathBuf| -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    };
    assert_eq!(listing(&dir), ["taken.svg"], "no temporary file left");
    let file = dir.join("family.svg");
    orbit_family_svg(&swing_family(), &file, &opts).unwrap();
    orbit_periods_svg(&swing_family(), &file, &opts).unwrap();
    assert!(has_text(&read_svg(&file), "T"));
    assert_eq!(listing(&dir), ["family.svg", "taken.svg"]);
    let unwritable = dir.join("no-such-dir").join("x.svg");
    assert!(matches!(
        poincare_section_svg(&ring_section(), &[], &unwritable, &opts),
        Err(PlotError::Io(_))
    ));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The figures of a computed family, end to end: the off-axis heavy body's swings from the
/// hanging position (period doublings on the way), its orbits on the sphere, and a small section
/// with the fixed point of one of its orbits — one marker per event, one curve per orbit, one
/// mark per crossing of the orbit.
#[test]
fn figures_of_a_computed_family() {
    use routh::{
        lyapunov_family, orbit_crossings, orbit_path, poincare_section, steady_motions, Matrix3,
        OrbitOptions, SectionOptions,
    };
    let body = test_models::HeavyTop {
        j: Matrix3::from_diagonal(&Vector3::new(1.0, 3.0, 6.0)),
        mgr: Vector3::new(0.4, 0.3, 1.5),
    };
    let hang = steady_motions(&body, 0.0)
        .unwrap()
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .unwrap();
    let family = lyapunov_family(
        &body,
        &hang,
        0,
        &OrbitOptions::default().with_max_orbits(40),
    )
    .unwrap();
    let doublings = family
        .events
        .iter()
        .filter(|e| e.kind == OrbitEventKind::PeriodDoubling)
        .count();
    assert!(doublings >= 1, "{:?}", family.events);
    let path = out("computed_family.svg");
    orbit_family_svg(&family, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert_eq!(
        polygon_centres(&svg, "#000000", 4).len(),
        doublings + 1,
        "one ◆ per period doubling, and the legend's"
    );
    assert_eq!(parabolic_lines(&svg).len(), 2);
    // Every period doubling sits on k = −1. The ◆ of the axes are those left of the right end of
    // the lines k = ±1 (the legend's is to the right of the axes, wherever the legend's width
    // puts it).
    let y_minus = parabolic_lines(&svg)[1];
    let right = polylines(&svg, "#646464", 1)
        .into_iter()
        .filter(|p| p.len() == 2 && p[0].1 == p[1].1 && (p[1].0 - p[0].0).abs() > 200.0)
        .map(|p| p[0].0.max(p[1].0))
        .fold(f64::MIN, f64::max);
    let in_axes: Vec<_> = polygon_centres(&svg, "#000000", 4)
        .into_iter()
        .filter(|c| c.0 < right)
        .collect();
    assert_eq!(in_axes.len(), doublings);
    assert!(in_axes.iter().all(|c| (c.1 - y_minus).abs() <= 1.5));

    let orbits: Vec<_> = family
        .orbits
        .iter()
        .skip(5)
        .step_by(10)
        .map(|o| orbit_path(&body, o, 200).unwrap())
        .collect();
    let path = out("computed_sphere.svg");
    orbits_on_sphere_svg(&orbits, hang.gamma, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    assert!(has_text(
        &svg,
        &format!("last orbit ({} in all)", orbits.len())
    ));

    let o = &family.orbits[10];
    let opts = SectionOptions::default()
        .with_normal(Vector3::y())
        .with_size(6, 20);
    let fixed = orbit_crossings(&body, o, &opts).unwrap();
    assert!(!fixed.is_empty());
    let section = poincare_section(&body, o.p_psi, o.energy, &opts).unwrap();
    let path = out("computed_section.svg");
    poincare_section_svg(&section, &fixed, &path, &PlotOptions::default()).unwrap();
    let svg = read_svg(&path);
    let rings = svg
        .lines()
        .filter(|l| l.starts_with("<circle") && attr(l, "r").as_deref() == Some("6"))
        .count();
    assert_eq!(
        rings,
        fixed.len() + 1,
        "one mark per fixed point, and the legend's"
    );
}

// --- Event labels: placed without overlap, with values on request -------------------------------

/// The boxes of the event labels (the `DejaVu Sans` texts of the annotation size, `7.5 pt` at
/// 2 px a point, which plotters writes 1.24 times smaller as all its fonts): top-left corner at
/// (x, y), width 0.58 em a character (DejaVu Sans averages less), one em high.
fn label_boxes(svg: &str) -> Vec<(String, [f64; 4])> {
    // Written at its size in points at 2 px a point, or at most a pixel more (plotters takes
    // whole pixels of 1.24 times the size written).
    let pt = look_font_annotation();
    svg.split("<text")
        .skip(1)
        .filter(|t| t.contains("font-family=\"DejaVu Sans\""))
        .filter_map(|t| {
            let attr = |name: &str| -> Option<f64> {
                let i = t.find(&format!(" {name}=\""))? + name.len() + 3;
                t[i..].split('"').next()?.parse().ok()
            };
            let (x, y, fs) = (attr("x")?, attr("y")?, attr("font-size")?);
            assert!(
                fs >= 2.0 * pt && fs < 2.0 * pt + 1.0,
                "annotation at {fs} px, not {pt} pt"
            );
            let body = &t[t.find('>')? + 1..];
            let text = body[..body.find("</text>")?].trim().to_string();
            let w = 0.58 * fs * text.chars().count() as f64;
            Some((text, [x, y, x + w, y + fs]))
        })
        .collect()
}

fn look_font_annotation() -> f64 {
    routh::style::FONT.annotation_pt
}

#[test]
fn event_labels_do_not_overlap_and_carry_their_values() {
    // Six events within a few pixels of one another on the upright branch: the old names stacked
    // in one column over their markers and overlapped.
    let mut d = full_diagram();
    let base = d.events[1].clone();
    for k in 0..5 {
        let mut e = base.clone();
        e.s = 4.0 + 0.02 * (k + 1) as f64;
        d.events.push(e);
    }
    // A mirror image of the fold (the same kind at the same point): named once.
    let fold = d.events[2].clone();
    d.events.push(fold);
    d.events.sort_by(|a, b| a.s.total_cmp(&b.s));
    let path = out("labels.svg");
    let opts = PlotOptions {
        event_values: true,
        ..PlotOptions::default()
    };
    energy_momentum_svg(&d, &path, &opts).unwrap();
    let svg = read_svg(&path);
    let boxes = label_boxes(&svg);
    assert_eq!(boxes.len(), d.events.len() - 1, "{boxes:?}");
    for (i, (ta, a)) in boxes.iter().enumerate() {
        for (tb, b) in &boxes[i + 1..] {
            let apart = a[2] <= b[0] || b[2] <= a[0] || a[3] <= b[1] || b[3] <= a[1];
            assert!(apart, "{ta} {a:?} overlaps {tb} {b:?}");
        }
    }
    // Each carries its value: the branch point at s = 4 and the fold at s = 5.
    let texts: Vec<&str> = boxes.iter().map(|b| b.0.as_str()).collect();
    assert!(texts.contains(&"branch point at 4"), "{texts:?}");
    assert!(texts.contains(&"fold at 5"), "{texts:?}");
    assert!(texts.contains(&"branch point at 4.1"), "{texts:?}");
    // Without `event_values` the bifurcation diagram writes no label at all (the legend names
    // the markers).
    bifurcation_diagram_svg(&d, &path, &PlotOptions::default()).unwrap();
    assert!(label_boxes(&read_svg(&path)).is_empty());
}

/// The figures as PNG (feature `png`): the atlas rasterised at a column's 600 dpi, its pixels
/// in the style's tints where the regions are.
#[cfg(feature = "png")]
#[test]
fn figures_as_png_at_column_width() {
    use routh::plot::png_from_svg;

    let svg = out("atlas-png.svg");
    stability_atlas_svg(&all_verdicts_atlas(), &svg, &PlotOptions::default()).unwrap();
    let png = out("atlas.png");
    png_from_svg(&svg, &png, 2100).unwrap();
    let bytes = std::fs::read(&png).unwrap();
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"));
    // The IHDR chunk: width and height, big-endian, after the 8-byte signature and 8 bytes of
    // chunk length and type.
    let be = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    assert_eq!(be(16), 2100);
    assert_eq!(be(20), 2100 * 600 / 900);
    // The text is drawn (the fonts found): the PNG of a figure without its legend's and axes'
    // text is smaller. Drawn again with every text element taken out of the SVG.
    let bare = std::fs::read_to_string(&svg).unwrap();
    let bare: String = bare
        .split("<text")
        .enumerate()
        .map(|(k, part)| {
            if k == 0 {
                part.to_string()
            } else {
                part.split_once("</text>")
                    .map_or(String::new(), |p| p.1.to_string())
            }
        })
        .collect();
    let bare_svg = out("atlas-bare.svg");
    std::fs::write(&bare_svg, bare).unwrap();
    png_from_svg(&bare_svg, out("atlas-bare.png"), 2100).unwrap();
    let bare_len = std::fs::metadata(out("atlas-bare.png")).unwrap().len();
    assert!(
        bytes.len() as u64 > bare_len + 2000,
        "{} vs {bare_len}: no text drawn",
        bytes.len()
    );
    assert!(matches!(
        png_from_svg(&svg, &png, 0),
        Err(PlotError::InvalidOptions(_))
    ));
    let not_svg = out("not.svg");
    std::fs::write(&not_svg, "plain text").unwrap();
    assert!(matches!(
        png_from_svg(&not_svg, out("not.png"), 100),
        Err(PlotError::InvalidData(_))
    ));
}

// The figures as printed: measured in the SVG written, at a journal's column and page width.

/// A `<text>` element as drawn: its text, its box `[x0, y0, x1, y1]` in the SVG's pixels and its
/// `font-size`; rotated texts (the vertical axis's name) have no box.
struct Drawn {
    text: String,
    size: f64,
    rect: Option<[f64; 4]>,
}

/// Every `<text>` of the SVG with its box: advance 0.55 em a character (DejaVu Sans's average
/// is more, so that a box found overlapping overlaps in fact), from 0.73 em above the baseline
/// (capitals) to 0.2 em below it (descenders); the baseline from `y` and `dy` as plotters
/// writes them (`0.76em` top, `0.5ex` centre, `-0.5ex` bottom; ex = 0.55 em).
fn drawn_texts(svg: &str) -> Vec<Drawn> {
    svg.split("<text")
        .skip(1)
        .filter_map(|t| {
            let head = &t[..t.find('>')?];
            let get = |name: &str| attr(&format!(" {head}"), name);
            let size: f64 = get("font-size")?.parse().ok()?;
            let x: f64 = get("x")?.parse().ok()?;
            let y: f64 = get("y")?.parse().ok()?;
            let body = &t[t.find('>')? + 1..];
            let text = body[..body.find("</text>")?]
                .trim()
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&amp;", "&");
            let baseline = match get("dy").as_deref() {
                Some("0.76em") => y + 0.76 * size,
                Some("0.5ex") => y + 0.275 * size,
                Some("-0.5ex") => y - 0.275 * size,
                _ => y,
            };
            let w = 0.55 * size * text.chars().count() as f64;
            let x0 = match get("text-anchor").as_deref() {
                Some("end") => x - w,
                Some("middle") => x - 0.5 * w,
                _ => x,
            };
            let rect = (get("transform").is_none()).then_some([
                x0,
                baseline - 0.73 * size,
                x0 + w,
                baseline + 0.2 * size,
            ]);
            Some(Drawn { text, size, rect })
        })
        .collect()
}

/// The `(width, height)` attributes of the `<svg>` element and its view box's size.
fn svg_size(svg: &str) -> (String, String, (f64, f64)) {
    let head = &svg[..svg.find('>').unwrap()];
    let vb: Vec<f64> = attr(head, "viewBox")
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    (
        attr(head, "width").unwrap(),
        attr(head, "height").unwrap(),
        (vb[2], vb[3]),
    )
}

/// Every kind of figure of `routh::plot` drawn with `opts` into files named after `stem`: their
/// names and contents.
fn every_figure(stem: &str, opts: &PlotOptions) -> Vec<(String, String)> {
    let mut figures = Vec::new();
    let mut keep = |name: &str, draw: &dyn Fn(&PathBuf) -> Result<(), PlotError>| {
        let path = out(&format!("{stem}-{name}.svg"));
        draw(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
        figures.push((name.to_string(), read_svg(&path)));
    };
    let diagram = full_diagram();
    keep("bifurcation", &|p| {
        bifurcation_diagram_svg(&diagram, p, opts)
    });
    keep("energy_momentum", &|p| {
        energy_momentum_svg(&diagram, p, opts)
    });
    keep("atlas", &|p| {
        stability_atlas_svg(&all_verdicts_atlas(), p, opts)
    });
    keep("orbit_family", &|p| {
        orbit_family_svg(&swing_family(), p, opts)
    });
    keep("orbit_periods", &|p| {
        orbit_periods_svg(&swing_family(), p, opts)
    });
    keep("section", &|p| {
        poincare_section_svg(&ring_section(), &[[0.0, 0.0]], p, opts)
    });
    keep("sphere", &|p| {
        orbits_on_sphere_svg(
            &[swing_path(0.3), swing_path(0.9)],
            Vector3::new(1.0, 0.3, -1.0),
            p,
            opts,
        )
    });
    figures
}

#[test]
fn figures_at_column_and_page_width_print_their_texts_at_size_and_apart() {
    for (opts, inches) in [
        (PlotOptions::column(), "3.4in"),
        (PlotOptions::page(), "7in"),
    ] {
        let w_in = opts.width_in.unwrap();
        for (name, svg) in every_figure(inches, &opts) {
            // The size in inches, the view box at 144 pixels an inch.
            let (w, h, (vw, vh)) = svg_size(&svg);
            assert_eq!(w, inches, "{name}");
            assert_eq!(vw, (w_in * 144.0).round(), "{name}");
            let h_in: f64 = h.trim_end_matches("in").parse().unwrap();
            assert!(
                (h_in / w_in - vh / vw).abs() < 2e-3,
                "{name}: {h} for {vh} of {vw}"
            );
            // Every text at 7 pt or more when printed at the width.
            let pt_per_px = 72.0 * w_in / vw;
            let texts = drawn_texts(&svg);
            assert!(texts.len() > 5, "{name}");
            for t in &texts {
                let pt = t.size * pt_per_px;
                assert!(pt >= 7.0 - 1e-9, "{name}: {:?} at {pt:.2} pt", t.text);
            }
            // No title unless asked.
            assert!(
                !texts.iter().any(|t| t.size * pt_per_px > 9.9),
                "{name}: a title"
            );
            // The texts do not overlap one another, and stay inside the figure.
            let boxes: Vec<(&str, [f64; 4])> = texts
                .iter()
                .filter_map(|t| Some((t.text.as_str(), t.rect?)))
                .collect();
            for (i, (ta, a)) in boxes.iter().enumerate() {
                assert!(
                    a[0] >= -0.5 && a[2] <= vw + 0.5 && a[1] >= -0.5 && a[3] <= vh + 0.5,
                    "{name}: {ta:?} at {a:?} leaves the {vw} × {vh} figure"
                );
                for (tb, b) in &boxes[i + 1..] {
                    let apart = a[2] <= b[0] + 0.5
                        || b[2] <= a[0] + 0.5
                        || a[3] <= b[1] + 0.5
                        || b[3] <= a[1] + 0.5;
                    assert!(apart, "{name}: {ta:?} {a:?} overlaps {tb:?} {b:?}");
                }
            }
            // Minus signs are true minus signs.
            assert!(
                !texts.iter().any(|t| t.text.starts_with('-')),
                "{name}: a hyphen for a minus"
            );
        }
    }
}

#[test]
fn a_title_only_when_asked() {
    let titled = PlotOptions {
        title: "Lagrange top".into(),
        ..PlotOptions::column()
    };
    for (name, svg) in every_figure("titled", &titled) {
        let n = texts(&svg).iter().filter(|t| *t == "Lagrange top").count();
        assert_eq!(n, 1, "{name}");
    }
    for (name, svg) in every_figure("untitled", &PlotOptions::default()) {
        assert!(!has_text(&svg, "Lagrange top"), "{name}");
        // Without units, in pixels as before.
        let (w, h, _) = svg_size(&svg);
        assert!(!w.ends_with("in") && !h.ends_with("in"), "{name}: {w} {h}");
    }
    // A larger font: every text grows with it.
    let big = PlotOptions {
        font_pt: 10.0,
        ..PlotOptions::column()
    };
    for (name, svg) in every_figure("big", &big) {
        let (_, _, (vw, _)) = svg_size(&svg);
        let smallest = drawn_texts(&svg)
            .iter()
            .map(|t| t.size * 72.0 * 3.4 / vw)
            .fold(f64::MAX, f64::min);
        assert!(smallest >= 7.0 * 10.0 / 8.0 - 1e-9, "{name}: {smallest} pt");
    }
    // Bad sizes are errors, not panics.
    let path = out("bad-size.svg");
    for bad in [
        PlotOptions {
            width_in: Some(1.0),
            ..PlotOptions::default()
        },
        PlotOptions {
            width_in: Some(f64::NAN),
            ..PlotOptions::default()
        },
        PlotOptions {
            font_pt: 0.0,
            ..PlotOptions::default()
        },
        PlotOptions {
            font_pt: f64::INFINITY,
            ..PlotOptions::column()
        },
    ] {
        let err = bifurcation_diagram_svg(&full_diagram(), &path, &bad).unwrap_err();
        assert!(matches!(err, PlotError::InvalidOptions(_)), "{err}");
    }
}

/// The colours `#RRGGBB` of the SVG's strokes and fills.
fn colours(svg: &str) -> HashSet<String> {
    let mut out = HashSet::new();
    for key in ["stroke=\"#", "fill=\"#"] {
        for part in svg.split(key).skip(1) {
            out.insert(part[..6].to_uppercase());
        }
    }
    out
}

#[test]
fn monochrome_figures_are_grey_and_keep_every_style_apart() {
    let grey = PlotOptions {
        monochrome: true,
        ..PlotOptions::column()
    };
    for (name, svg) in every_figure("grey", &grey) {
        for c in colours(&svg) {
            let (r, g, b) = (&c[0..2], &c[2..4], &c[4..6]);
            assert!(r == g && g == b, "{name}: colour #{c}");
        }
    }
    // Each verdict listed in the legend is drawn in its stroke along a curve (a smoothed
    // polyline in fractional pixels, round joins), not only in its swatch: the strokes differ
    // in width or dash, so in black they still tell the verdicts apart.
    let svg = every_figure("grey-legend", &grey)
        .into_iter()
        .find(|f| f.0 == "orbit_family")
        .unwrap()
        .1;
    let curve_widths: HashSet<String> = svg
        .lines()
        .filter(|l| l.starts_with("<polyline") && l.contains("stroke-linejoin=\"round\""))
        .filter_map(|l| attr(l, "stroke-width"))
        .collect();
    for (key, label) in [
        ("elliptic", "elliptic, |k| < 1"),
        ("hyperbolic", "hyperbolic, k > 1"),
        ("inverse_hyperbolic", "inverse hyperbolic, k < −1"),
    ] {
        assert!(has_text(&svg, label), "{label}");
        let w = (look("orbit_verdict", key).unwrap().width_pt * 2.0).round();
        assert!(
            curve_widths.contains(&format!("{w}")),
            "{key}: {curve_widths:?}"
        );
    }
    let stroke = |key: &str| {
        let l = look("orbit_verdict", key).unwrap();
        (
            l.width_pt.to_bits(),
            l.dash_pt.map(|d| (d.0.to_bits(), d.1.to_bits())),
        )
    };
    let keys = ["elliptic", "parabolic", "hyperbolic", "inverse_hyperbolic"];
    for (i, a) in keys.iter().enumerate() {
        for b in &keys[i + 1..] {
            assert_ne!(stroke(a), stroke(b), "{a} and {b} differ in colour only");
        }
    }
    // Inverse hyperbolic runs end on k = −1: their dashes are not the reference line's.
    let line = look("reference", "parabolic_line").unwrap();
    let inverse = look("orbit_verdict", "inverse_hyperbolic").unwrap();
    assert!(inverse.dash_pt.is_some() && inverse.width_pt > line.width_pt);
    assert_ne!(
        inverse.dash_pt,
        Some((1.0, 2.0)),
        "dotted like the k = −1 line"
    );
}

#[test]
fn mirror_branches_are_drawn_once_so_that_dashes_stay_dashes() {
    // Two mirror images of an unstable branch (γ₁ ↦ −γ₁), the same curve in (s, γ₃), sampled
    // at different points: each drawn, their dashes would fill each other's gaps.
    let branch = |offset: f64, sign: f64| Branch {
        points: (0..=40)
            .map(|i| {
                let s = offset + 0.1 * i as f64;
                let mut p = point(s, s, 0.3 + 0.1 * s, Stability::Unstable, true);
                p.steady.gamma.x *= sign;
                p
            })
            .collect(),
        isolated: true,
    };
    let one = BifurcationDiagram {
        branches: vec![branch(0.0, 1.0)],
        ..Default::default()
    };
    let two = BifurcationDiagram {
        branches: vec![branch(0.0, 1.0), branch(0.05, -1.0)],
        ..Default::default()
    };
    let red = c("verdict", "unstable");
    let dashes = |d: &BifurcationDiagram, name: &str| {
        let path = out(name);
        bifurcation_diagram_svg(d, &path, &PlotOptions::column()).unwrap();
        polylines(&read_svg(&path), red, 2).len()
    };
    let (n1, n2) = (
        dashes(&one, "mirror-one.svg"),
        dashes(&two, "mirror-two.svg"),
    );
    assert!(n1 > 10, "{n1}");
    // The second branch adds at most the dash or two where it runs beyond the first.
    assert!(n2 <= n1 + 2, "{n1} dashes for one branch, {n2} for the two");
}
