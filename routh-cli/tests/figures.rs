//! The figure options of every command that writes a figure (`--width`, `--font-size`,
//! `--title`, `--grey`), checked in the SVG written: its size, its texts' sizes when printed,
//! its title or none, its colours, its axis names.

mod common;

use common::{routh, stderr, stdout, ASYMMETRIC, BODY_141, TOP};
use std::collections::HashSet;
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-cli-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// The value of attribute `name` in an element's text.
fn attr(element: &str, name: &str) -> Option<String> {
    let key = format!(" {name}=\"");
    let i = element.find(&key)? + key.len();
    let rest = &element[i..];
    Some(rest[..rest.find('"')?].to_string())
}

/// A figure as written: the `<svg>` element's width and height attributes, its view box's
/// width, every text with its `font-size`, and the colours of its strokes and fills.
struct Figure {
    width: String,
    height: String,
    view_width: f64,
    texts: Vec<(String, f64)>,
    colours: HashSet<String>,
}

impl Figure {
    fn read(path: &PathBuf) -> Figure {
        let svg = std::fs::read_to_string(path).expect("the SVG was written");
        let head = &svg[..svg.find('>').unwrap()];
        let view: Vec<f64> = attr(head, "viewBox")
            .unwrap()
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        let texts = svg
            .split("<text")
            .skip(1)
            .filter_map(|t| {
                let size = attr(t, "font-size")?.parse().ok()?;
                let body = &t[t.find('>')? + 1..];
                Some((body[..body.find("</text>")?].trim().to_string(), size))
            })
            .collect();
        let mut colours = HashSet::new();
        for key in ["stroke=\"#", "fill=\"#"] {
            for part in svg.split(key).skip(1) {
                colours.insert(part[..6].to_uppercase());
            }
        }
        Figure {
            width: attr(head, "width").unwrap(),
            height: attr(head, "height").unwrap(),
            view_width: view[2],
            texts,
            colours,
        }
    }

    /// The printed width in inches (`3.4in`), if the SVG gives one.
    fn inches(&self) -> Option<f64> {
        self.width.strip_suffix("in")?.parse().ok()
    }

    /// The smallest text, in points, printed at the SVG's width.
    fn smallest_pt(&self) -> f64 {
        let pt_per_px = 72.0 * self.inches().expect("a width in inches") / self.view_width;
        self.texts
            .iter()
            .map(|t| t.1 * pt_per_px)
            .fold(f64::MAX, f64::min)
    }

    fn has(&self, text: &str) -> bool {
        self.texts.iter().any(|t| t.0 == text)
    }

    fn grey(&self) -> bool {
        self.colours
            .iter()
            .all(|c| c[0..2] == c[2..4] && c[2..4] == c[4..6])
    }
}

fn ok(args: &[&str]) {
    let o = routh(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
}

#[test]
fn diagram_figures_take_width_font_title_and_grey() {
    let svg = scratch("diagram-column.svg");
    let em = scratch("em-column.svg");
    ok(&[
        "diagram",
        TOP,
        "-p",
        "0..5",
        "--width",
        "column",
        "--svg",
        svg.to_str().unwrap(),
        "--energy-momentum-svg",
        em.to_str().unwrap(),
    ]);
    for path in [&svg, &em] {
        let f = Figure::read(path);
        assert_eq!(f.width, "3.4in", "{path:?}");
        assert!(f.height.ends_with("in"), "{}", f.height);
        assert_eq!(f.view_width, 490.0);
        // Ticks at 8 pt, nothing under 7 pt at the column's width.
        assert!(f.smallest_pt() >= 7.0, "{path:?}: {} pt", f.smallest_pt());
        // No title: no text names the model's file.
        assert!(
            !f.texts.iter().any(|t| t.0.contains("heavy_top")),
            "{:?}",
            f.texts
        );
        assert!(f.has("cyclic momentum p_ψ"), "{:?}", f.texts);
        // In colour by default.
        assert!(!f.grey());
    }

    let svg = scratch("diagram-page.svg");
    ok(&[
        "diagram",
        TOP,
        "-p",
        "0..5",
        "--width",
        "page",
        "--font-size",
        "9",
        "--title",
        "The Lagrange top",
        "--grey",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let f = Figure::read(&svg);
    assert_eq!(f.width, "7in");
    assert_eq!(f.view_width, 1008.0);
    assert!(f.has("The Lagrange top"), "{:?}", f.texts);
    // The ticks at 9 pt: every text at 9 × 7.5/8 pt (the event names, the smallest) or more.
    assert!(
        f.smallest_pt() >= 9.0 * 7.5 / 8.0 - 1e-9,
        "{}",
        f.smallest_pt()
    );
    assert!(f.grey(), "{:?}", f.colours);

    // Without options: 900 × 600 pixels, no unit, no title.
    let svg = scratch("diagram-default.svg");
    ok(&["diagram", TOP, "-p", "0..5", "--svg", svg.to_str().unwrap()]);
    let f = Figure::read(&svg);
    assert_eq!((f.width.as_str(), f.height.as_str()), ("900", "600"));
    assert!(!f.texts.iter().any(|t| t.0.contains("heavy_top")));
}

#[test]
fn atlas_axes_are_named_by_the_models_symbols() {
    let svg = scratch("atlas.svg");
    ok(&[
        "atlas",
        TOP,
        "--x",
        "mass=0.5..1.5",
        "--y",
        "momentum=0..5",
        "--gamma",
        "0,0,1",
        "--nx",
        "7",
        "--ny",
        "7",
        "--width",
        "3.5",
        "--grey",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let f = Figure::read(&svg);
    assert_eq!(f.width, "3.5in");
    // heavy_top.toml's [latex] table: mass = "m".
    assert!(f.has("m"), "{:?}", f.texts);
    assert!(!f.texts.iter().any(|t| t.0.contains("parameter mass")));
    assert!(f.has("cyclic momentum p_ψ"));
    assert!(f.smallest_pt() >= 7.0);
    assert!(f.grey(), "{:?}", f.colours);
}

#[test]
fn orbit_and_section_figures_take_the_options() {
    let k = scratch("k.svg");
    let t = scratch("t.svg");
    ok(&[
        "orbits",
        ASYMMETRIC,
        "-p",
        "0",
        "--mode",
        "1",
        "--gamma",
        "-0.25,-0.19,-0.95",
        "--max-orbits",
        "8",
        "--width",
        "column",
        "--grey",
        "--svg",
        k.to_str().unwrap(),
        "--periods-svg",
        t.to_str().unwrap(),
    ]);
    for path in [&k, &t] {
        let f = Figure::read(path);
        assert_eq!(f.width, "3.4in");
        assert!(f.smallest_pt() >= 7.0, "{path:?}");
        assert!(f.grey(), "{path:?}: {:?}", f.colours);
        assert!(!f.texts.iter().any(|t| t.0.contains("asymmetric_top")));
    }
    let s = scratch("s.svg");
    ok(&[
        "section",
        ASYMMETRIC,
        "-p",
        "0",
        "-e",
        "-1",
        "--orbits",
        "3",
        "--crossings",
        "20",
        "--width",
        "column",
        "--title",
        "A section",
        "--svg",
        s.to_str().unwrap(),
    ]);
    let f = Figure::read(&s);
    assert_eq!(f.width, "3.4in");
    assert!(f.has("A section"));
    assert!(f.smallest_pt() >= 7.0);
}

/// The orbit chart's figure draws what the chart has: a legend row for each kind of curve the
/// chart's JSON holds and for none other, the elliptic and hyperbolic regions, at column width
/// in greys with texts of at least 7 pt, the parameter named by the model's symbol.
#[test]
fn orbit_chart_figure_draws_its_curves_and_regions() {
    let path = scratch("chart.svg");
    let o = routh(&[
        "orbit-chart",
        BODY_141,
        "--parameter",
        "alpha=0.5..1.0",
        "--excess-energy",
        "0..1.9",
        "--gamma",
        "0,0,-1",
        "--nx",
        "3",
        "--json",
        "--width",
        "column",
        "--grey",
        "--svg",
        path.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let chart: routh::OrbitChart = serde_json::from_str(&stdout(&o)).unwrap();
    let f = Figure::read(&path);
    assert_eq!(f.width, "3.4in");
    assert!(f.smallest_pt() >= 7.0);
    assert!(f.grey(), "{:?}", f.colours);
    assert!(f.has("α"), "{:?}", f.texts);
    for kind in [
        routh::OrbitEventKind::Fold,
        routh::OrbitEventKind::BranchPoint,
        routh::OrbitEventKind::PeriodDoubling,
        routh::OrbitEventKind::ThirdOrderResonance,
        routh::OrbitEventKind::FourthOrderResonance,
        routh::OrbitEventKind::TwistDegenerate,
    ] {
        let label = routh::style::look("orbit_curve", kind.as_str())
            .unwrap()
            .label;
        let drawn = chart
            .curves
            .iter()
            .any(|c| c.kind == kind && c.points.len() > 1);
        assert_eq!(f.has(label), drawn, "{label}: {:?}", f.texts);
    }
    assert!(chart
        .curves
        .iter()
        .any(|c| c.kind == routh::OrbitEventKind::BranchPoint));
    assert!(f.has("elliptic, |k| &lt; 1") && f.has("hyperbolic, k &gt; 1"));
}

/// `--circles`: the Lagrange top's circles of steady motions (its tilted precessions), whose
/// points the classification of single steady motions leaves degenerate, are drawn with their
/// verdict as circles; without it the legend lists the degenerate runs. No figure: exit code 2.
#[test]
fn diagram_draws_circle_verdicts_when_asked() {
    let legend = |circles: bool| {
        let path = scratch(if circles { "circles.svg" } else { "points.svg" });
        let mut args = vec![
            "diagram",
            TOP,
            "--momentum",
            "0..5",
            "--svg",
            path.to_str().unwrap(),
        ];
        if circles {
            args.extend(["--circles", "0,0,1"]);
        }
        ok(&args);
        Figure::read(&path)
    };
    let (points, circles) = (legend(false), legend(true));
    assert!(
        points.has("degenerate (test inconclusive)"),
        "{:?}",
        points.texts
    );
    assert!(
        !circles.has("degenerate (test inconclusive)"),
        "{:?}",
        circles.texts
    );
    assert!(circles.has("secularly stable") && circles.has("circle of steady motions"));
    let o = routh(&["diagram", TOP, "--momentum", "0..5", "--circles", "0,0,1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--circles"));
}

#[test]
fn bad_figure_options_are_usage_errors() {
    let svg = scratch("bad.svg");
    for (flag, value) in [
        ("--width", "1"),
        ("--width", "wide"),
        ("--width", "NaN"),
        ("--font-size", "100"),
        ("--font-size", "-3"),
    ] {
        let o = routh(&[
            "diagram",
            TOP,
            "-p",
            "0..5",
            flag,
            value,
            "--svg",
            svg.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(2), "{flag} {value}: {}", stderr(&o));
        assert!(stderr(&o).contains(flag), "{}", stderr(&o));
    }
    assert!(!svg.exists());
}
