//! `routh atlas`: stability atlases over two quantities (paper §6).

use crate::cli::Atlas;
use crate::commands::{describe, load};
use crate::error::CliError;
use crate::options::options;
use crate::table::Table;
use routh::export::verdict_name;
use routh::plot::{stability_atlas_svg, PlotOptions};
use routh::{stability_atlas, AtlasOptions, Model, ModelError, StabilityAtlas, Vector3};
use serde_json::Value;
use std::cell::RefCell;

/// The model and momentum at `(x, y)`: each axis is `momentum` or a scalar parameter.
fn point(
    model: &Model,
    names: [&str; 2],
    values: [f64; 2],
    momentum: f64,
) -> Result<(Model, f64), ModelError> {
    let mut m = model.clone();
    let mut p = momentum;
    for (name, v) in names.into_iter().zip(values) {
        if name == "momentum" {
            p = v;
        } else {
            m.set(name, v)?;
        }
    }
    Ok((m, p))
}

/// Runs `routh atlas` and returns what it prints.
pub fn atlas(a: &Atlas) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let names = [a.x.name.as_str(), a.y.name.as_str()];
    if names[0] == names[1] {
        return Err(CliError::Input(format!(
            "--x and --y are both `{}`",
            names[0]
        )));
    }
    let momentum = match (a.momentum, names.contains(&"momentum")) {
        (Some(p), false) => p,
        (None, true) => 0.0,
        (Some(_), true) => {
            return Err(CliError::Input(
                "--momentum is given but one axis is already `momentum`".into(),
            ))
        }
        (None, false) => {
            return Err(CliError::Input(
                "neither axis is `momentum`: give the momentum with --momentum P".into(),
            ))
        }
    };
    // Check both names and shapes up front: bad input, exit code 2.
    point(&model, names, [a.x.range.0, a.y.range.0], momentum)
        .map_err(|e| CliError::Input(format!("--x/--y: {}", describe(&e, None))))?;
    let gamma = Vector3::from(a.gamma);
    if gamma.norm() == 0.0 {
        return Err(CliError::Input(
            "--gamma must not be the zero vector".into(),
        ));
    }
    let bar = crate::progress::Bar::start("rows of the grid");
    let mut opts: AtlasOptions = options(
        [("nx", a.nx.map(Value::from)), ("ny", a.ny.map(Value::from))],
        &a.opts,
    )?;
    opts.control = bar.control();
    let failure: RefCell<Option<ModelError>> = RefCell::new(None);
    let family = |x: f64, y: f64| match point(&model, names, [x, y], momentum) {
        Ok(mp) => mp,
        Err(e) => {
            failure.borrow_mut().get_or_insert(e);
            (model.clone(), momentum)
        }
    };
    let result = stability_atlas(family, gamma.normalize(), a.x.range, a.y.range, &opts)?;
    if let Some(e) = failure.into_inner() {
        return Err(CliError::Compute(describe(&e, None)));
    }
    let mut files = crate::files::Outputs::new();
    if let Some(path) = &a.svg {
        let opts = a.figure.apply(PlotOptions {
            x_label: crate::args::axis_name(names[0], model.latex_symbols()),
            y_label: crate::args::axis_name(names[1], model.latex_symbols()),
            ..PlotOptions::default()
        });
        files.write(path, |tmp| stability_atlas_svg(&result, tmp, &opts))?;
    }
    let text = render(a, &result, &names)?;
    files.commit()?;
    Ok(text)
}

/// The atlas as asked: JSON, CSV or two tables (the verdicts tallied, the boundary curves).
fn render(a: &Atlas, result: &StabilityAtlas, names: &[&str]) -> Result<String, CliError> {
    if a.output.json {
        return Ok(serde_json::to_string_pretty(result)? + "\n");
    }
    if a.output.csv {
        return Ok(result.to_csv());
    }
    let mut counts = Table::new(&["verdict", "cells"]);
    let lost = result
        .lost
        .iter()
        .flatten()
        .chain(std::iter::repeat(&false));
    let mut tally: Vec<(String, usize)> = Vec::new();
    for (v, &gone) in result.verdicts.iter().flatten().zip(lost) {
        let name = match v {
            Some(v) => verdict_name(*v),
            // The continuation stalled away from a fold: nothing is known there.
            None if gone => "lost",
            None => "no steady motion",
        }
        .to_string();
        match tally.iter_mut().find(|(n, _)| *n == name) {
            Some((_, k)) => *k += 1,
            None => tally.push((name, 1)),
        }
    }
    for (n, k) in tally {
        counts.row(vec![n, k.to_string()]);
    }
    let mut curves = Table::new(&["boundary", "points", "x from", "x to", "y from", "y to"]);
    for b in &result.boundaries {
        let fmt = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.6}"));
        curves.row(vec![
            b.kind.to_string(),
            b.points.len().to_string(),
            fmt(b.points.iter().map(|p| p.0).reduce(f64::min)),
            fmt(b.points.iter().map(|p| p.0).reduce(f64::max)),
            fmt(b.points.iter().map(|p| p.1).reduce(f64::min)),
            fmt(b.points.iter().map(|p| p.1).reduce(f64::max)),
        ]);
    }
    let stop = result
        .stop
        .as_ref()
        .map_or(String::new(), |r| format!("stopped early: {r}\n"));
    Ok(format!(
        "atlas over {} × {} ({} × {} cells)\n{stop}{}\n{} boundary curve(s)\n{}",
        names[0],
        names[1],
        result.x.len(),
        result.y.len(),
        counts.render(),
        result.boundaries.len(),
        curves.render()
    ))
}
