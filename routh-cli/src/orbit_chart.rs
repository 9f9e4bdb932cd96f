//! `routh orbit-chart`: the chart of a mode's Lyapunov family over a parameter and the energy
//! above the steady motion (docs/method.md §12).
//!
//! Table: one row per curve (its kind, number of points, the range of x and h). CSV: the curves'
//! points, `curve,kind,parameter_name,x,h`. JSON: the serde form of `routh::OrbitChart` as a
//! Python document (`"routh": "OrbitChart"`) with `parameter_name`. `--svg FILE`: the figure
//! of `routh::plot::orbit_chart_svg`, with the figure options of every command.

use crate::cli::OrbitChartArgs;
use crate::commands::{describe, load};
use crate::error::CliError;
use crate::options::options;
use crate::orbit_out::Document;
use crate::table::{num, Table};
use routh::plot::{orbit_chart_svg, PlotOptions};
use routh::{orbit_chart as chart_of, OrbitChartOptions, Param, Vector3};
use serde::Serialize;
use serde_json::Value;

#[derive(Serialize)]
struct ChartDocument<'a> {
    #[serde(flatten)]
    chart: Document<'a, routh::OrbitChart>,
    parameter_name: &'a str,
}

/// Runs `routh orbit-chart` and returns what it prints.
pub fn orbit_chart(a: &OrbitChartArgs) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let (name, (lo, hi)) = (a.parameter.name.as_str(), a.parameter.range);
    // The parameter must be a scalar of the model: bad input (exit code 2) before any work.
    model
        .with(name, lo)
        .map_err(|e| CliError::Input(format!("--parameter: {}", describe(&e, None))))?;
    if !matches!(model.get(name), Some(Param::Scalar(_))) {
        return Err(CliError::Input(format!(
            "--parameter: `{name}` is not a scalar parameter of the model"
        )));
    }
    let (h_lo, h_hi) = a.excess_energy;
    if h_lo < 0.0 {
        return Err(CliError::Input(format!(
            "--excess-energy {h_lo}..{h_hi}: energies above the steady motion start at 0"
        )));
    }
    let bar = crate::progress::Bar::start("parameter values of the chart");
    // The defaults are the library's, written once there.
    let mut opts: OrbitChartOptions = options(
        [
            ("max_orbits", a.max_orbits.map(Value::from)),
            ("nx", a.nx.map(Value::from)),
        ],
        &a.opts,
    )?;
    opts.orbit.control = bar.control();
    let p = a.momentum;
    // A parameter value the model refuses gives a model that cannot be evaluated: its steady
    // motion fails, recorded in the chart's failures.
    let member = |x: f64| (model.with(name, x).unwrap_or_else(|_| model.clone()), p);
    let chart = chart_of(
        member,
        Vector3::from(a.gamma),
        usize::from(a.mode),
        (lo, hi),
        (h_lo, h_hi),
        &opts,
    )?;
    drop(bar);
    let mut files = crate::files::Outputs::new();
    if let Some(path) = &a.svg {
        let opts = a.figure.apply(PlotOptions {
            x_label: crate::args::axis_name(name, model.latex_symbols()),
            ..PlotOptions::default()
        });
        files.write(path, |tmp| orbit_chart_svg(&chart, tmp, &opts))?;
    }
    let text = render(a, &chart, name)?;
    files.commit()?;
    Ok(text)
}

/// What `routh orbit-chart` prints: the table, the CSV of the curves' points or the JSON.
fn render(a: &OrbitChartArgs, chart: &routh::OrbitChart, name: &str) -> Result<String, CliError> {
    let (lo, hi) = a.parameter.range;
    let (h_lo, h_hi) = a.excess_energy;
    let p = a.momentum;
    if a.output.json {
        let doc = ChartDocument {
            chart: Document::new("OrbitChart", chart),
            parameter_name: name,
        };
        return Ok(serde_json::to_string_pretty(&doc)? + "\n");
    }
    if a.output.csv {
        let mut s = String::from("curve,kind,parameter_name,x,h\n");
        for (i, c) in chart.curves.iter().enumerate() {
            for [x, h] in &c.points {
                s.push_str(&format!("{i},{},{name},{x},{h}\n", c.kind.as_str()));
            }
        }
        return Ok(s);
    }
    let mut t = Table::new(&["#", "curve", "points", name, "h = E - E_s"]);
    for (i, c) in chart.curves.iter().enumerate() {
        let span = |k: usize| {
            let (a, b) = c
                .points
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |m, p| {
                    (m.0.min(p[k]), m.1.max(p[k]))
                });
            format!("{} .. {}", num(a), num(b))
        };
        t.row(vec![
            i.to_string(),
            c.kind.to_string(),
            c.points.len().to_string(),
            span(0),
            span(1),
        ]);
    }
    let failed = chart.failures.iter().filter(|f| f.is_some()).count();
    let mut out = format!(
        "orbit chart of mode {} over {name} in [{lo}, {hi}] ({} values) and h in [{h_lo}, {h_hi}] \
         at p_psi = {p}: {} curve(s)\n{}",
        a.mode,
        chart.x.len(),
        chart.curves.len(),
        t.render()
    );
    if failed > 0 {
        out.push_str(&format!("{failed} parameter value(s) without a family:\n"));
        for (x, f) in chart.x.iter().zip(&chart.failures) {
            if let Some(f) = f {
                out.push_str(&format!("  {name} = {}: {f}\n", num(*x)));
            }
        }
    }
    Ok(out)
}
