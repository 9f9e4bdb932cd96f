//! The SVG figures of `routh::plot`, on diagrams and atlases built by hand.
#![cfg(feature = "plot")]

use std::path::PathBuf;

use routh::plot::{
    bifurcation_diagram_svg, energy_momentum_svg, stability_atlas_svg, DiagramAxis, PlotError,
    PlotOptions,
};
use routh::{
    BifurcationDiagram, BoundaryCurve, Branch, BranchEvent, BranchSample, Complex, EventKind,
    Stability, StabilityAtlas, StabilityReport, SteadyMotion, Vector3,
};

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
            Some(body[..body.find("</text>")?].trim().to_string())
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
                let v = match i {
                    0 => Degenerate,
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
    for k in [
        EventKind::Fold,
        EventKind::BranchPoint,
        EventKind::HamiltonianHopf,
    ] {
        assert!(has_text(&svg, &k.to_string()), "legend lacks {k}");
    }
    assert!(has_text(&svg, "circle of steady motions"));
    // Unstable runs are dashed: many short red segments, not one polyline per run.
    let dashes = strokes(&svg, "#CD1E1E", 2);
    assert!(dashes > 20, "{dashes} unstable segments");
    // Stable runs are one polyline each: thick for secular, thin for gyroscopic.
    assert!(strokes(&svg, "#008237", 4) >= 3);
    assert!(strokes(&svg, "#1950D2", 1) >= 1);
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
    assert!(!svg.contains("#CD1E1E") && !svg.contains("#008237"));
    assert!(strokes(&svg, "#000000", 2) > 20, "dashes and dots");
    assert!(strokes(&svg, "#000000", 4) >= 3, "thick secular runs");
    // Default labels: the parameter "s" and the axis of the default `y`.
    assert!(has_text(&svg, "s"));
    assert!(has_text(&svg, DiagramAxis::GammaZ.label()));
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
    for v in VERDICTS {
        assert!(has_text(&svg, &v.to_string()), "legend lacks {v}");
    }
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
    assert!(strokes(&svg, "#CD1E1E", 2) > 10);

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
    assert!(strokes(&svg, "#282828", 1) > 50);
    assert!(svg.matches("<circle").count() > 50);

    // The same in greys: every verdict still has its own pattern.
    let path = out("atlas-full-mono.svg");
    let mono = PlotOptions {
        monochrome: true,
        ..opts
    };
    stability_atlas_svg(&all_verdicts_atlas(), &path, &mono).unwrap();
    let svg = read_svg(&path);
    assert!(strokes(&svg, "#282828", 1) > 50);
    assert!(svg.matches("<circle").count() > 50);
    assert!(!svg.contains("#EEB2AC"), "no tint in monochrome");
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
                strokes(&svg, "#005A96", 2) > 60,
                "{}",
                strokes(&svg, "#005A96", 2)
            );
        }
    }
}
