//! Simple SVG figures (plotters' SVG backend): scatter and line series on one pair of axes,
//! with a title, axis labels, a legend and optional vertical marker lines.

use std::error::Error;
use std::ops::Range;
use std::path::Path;

use plotters::prelude::*;
use routh::Stability;

use super::verdict_label;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Style {
    /// Filled dots of the given radius (pixels).
    Points(u32),
    /// A polyline of the given width (pixels).
    Line(u32),
    /// A dashed polyline of the given width (pixels).
    Dashed(u32),
}

/// One series of a [`Figure`].
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend entry (an empty name is left out of the legend).
    pub name: String,
    /// Colour.
    pub color: RGBColor,
    /// Drawing style.
    pub style: Style,
    /// The data.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A new series.
    pub fn new(
        name: impl Into<String>,
        color: RGBColor,
        style: Style,
        points: Vec<(f64, f64)>,
    ) -> Self {
        Series {
            name: name.into(),
            color,
            style,
            points,
        }
    }
}

/// A figure: series on one pair of axes.
#[derive(Debug, Clone)]
pub struct Figure {
    /// Caption above the plot.
    pub title: String,
    /// Label of the horizontal axis.
    pub x_label: String,
    /// Label of the vertical axis.
    pub y_label: String,
    /// Horizontal range (`None`: from the data, padded).
    pub x_range: Option<Range<f64>>,
    /// Vertical range (`None`: from the data, padded).
    pub y_range: Option<Range<f64>>,
    /// The series, drawn in order.
    pub series: Vec<Series>,
    /// Vertical marker lines `(x, legend name, colour)`, drawn dashed across the plot.
    pub vlines: Vec<(f64, String, RGBColor)>,
    /// Where the legend goes.
    pub legend: SeriesLabelPosition,
}

impl Figure {
    /// An empty figure with a title and axis labels.
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Figure {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_range: None,
            y_range: None,
            series: Vec::new(),
            vlines: Vec::new(),
            legend: SeriesLabelPosition::UpperRight,
        }
    }

    fn data_range(&self, pick: impl Fn(&(f64, f64)) -> f64, extra: &[f64]) -> Range<f64> {
        let vals = self
            .series
            .iter()
            .flat_map(|s| s.points.iter().map(&pick))
            .chain(extra.iter().copied())
            .filter(|v| v.is_finite());
        let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        if !lo.is_finite() {
            return 0.0..1.0;
        }
        let pad = if hi > lo {
            0.05 * (hi - lo)
        } else {
            0.5 * lo.abs().max(1.0)
        };
        (lo - pad)..(hi + pad)
    }

    /// Writes the figure as an SVG of `width × height` pixels.
    pub fn save(&self, path: &Path, width: u32, height: u32) -> Result<(), Box<dyn Error>> {
        let vx: Vec<f64> = self.vlines.iter().map(|v| v.0).collect();
        let xr = self
            .x_range
            .clone()
            .unwrap_or_else(|| self.data_range(|p| p.0, &vx));
        let yr = self
            .y_range
            .clone()
            .unwrap_or_else(|| self.data_range(|p| p.1, &[]));

        let root = SVGBackend::new(path, (width, height)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&self.title, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(65)
            .build_cartesian_2d(xr.clone(), yr.clone())?;
        chart
            .configure_mesh()
            .x_desc(self.x_label.as_str())
            .y_desc(self.y_label.as_str())
            .axis_desc_style(("sans-serif", 16))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()?;

        for (x, name, color) in &self.vlines {
            let color = *color;
            let anno = chart.draw_series(DashedLineSeries::new(
                vec![(*x, yr.start), (*x, yr.end)],
                6,
                4,
                color.stroke_width(1),
            ))?;
            if !name.is_empty() {
                anno.label(name.as_str()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(1))
                });
            }
        }
        for s in &self.series {
            let color = s.color;
            let anno = match s.style {
                Style::Points(r) => {
                    let pts = s
                        .points
                        .iter()
                        .filter(|p| xr.contains(&p.0) && yr.contains(&p.1))
                        .map(|&p| Circle::new(p, r, color.filled()));
                    let a = chart.draw_series(pts)?;
                    if s.name.is_empty() {
                        continue;
                    }
                    a.label(s.name.as_str())
                        .legend(move |(x, y)| Circle::new((x + 10, y), r + 1, color.filled()));
                    continue;
                }
                Style::Line(w) => chart.draw_series(LineSeries::new(
                    s.points.iter().copied(),
                    color.stroke_width(w),
                ))?,
                Style::Dashed(w) => chart.draw_series(DashedLineSeries::new(
                    s.points.iter().copied(),
                    8,
                    5,
                    color.stroke_width(w),
                ))?,
            };
            if !s.name.is_empty() {
                let w = match s.style {
                    Style::Line(w) | Style::Dashed(w) => w,
                    Style::Points(_) => 1,
                };
                anno.label(s.name.as_str()).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(w))
                });
            }
        }
        chart
            .configure_series_labels()
            .position(self.legend.clone())
            .label_font(("sans-serif", 14))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
        Ok(())
    }
}

/// The colour of a verdict in every figure.
pub fn verdict_color(v: Stability) -> RGBColor {
    match v {
        Stability::SecularlyStable => RGBColor(0, 140, 60),
        Stability::GyroscopicallyStabilized => RGBColor(30, 90, 220),
        Stability::Unstable => RGBColor(210, 30, 30),
        Stability::Degenerate => RGBColor(150, 150, 150),
    }
}

/// One point series per verdict (empty ones left out), from `(verdict, x, y)` triples.
pub fn verdict_series(points: &[(Stability, f64, f64)], radius: u32) -> Vec<Series> {
    super::VERDICTS
        .iter()
        .filter_map(|&v| {
            let pts: Vec<(f64, f64)> = points
                .iter()
                .filter(|p| p.0 == v)
                .map(|p| (p.1, p.2))
                .collect();
            (!pts.is_empty()).then(|| {
                Series::new(
                    verdict_label(v),
                    verdict_color(v),
                    Style::Points(radius),
                    pts,
                )
            })
        })
        .collect()
}
