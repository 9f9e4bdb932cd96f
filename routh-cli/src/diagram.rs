//! `routh diagram`: bifurcation diagrams over the momentum or over a parameter (paper §6).

use crate::args;
use crate::cli::Diagram;
use crate::commands::{describe, load};
use crate::error::CliError;
use crate::options::options;
use crate::table::{num, vec3, Table};
use routh::plot::{
    bifurcation_diagram_svg, energy_momentum_svg, with_circle_verdicts, PlotOptions,
};
use routh::{bifurcation_diagram, BifurcationDiagram, ContinuationOptions, ModelError};
use serde_json::json;
use std::cell::RefCell;

/// Runs `routh diagram` and returns what it prints.
pub fn diagram(d: &Diagram) -> Result<String, CliError> {
    let model = load(&d.model)?;
    let bar = crate::progress::Bar::start("seeds of the diagram");
    let mut opts: ContinuationOptions =
        options([("nonlinear", d.nonlinear.then_some(json!(true)))], &d.opts)?;
    opts.control = bar.control();
    let bad = |e: String| CliError::Input(format!("--momentum: {e}"));
    let (result, x_label) = match &d.parameter {
        None => {
            let range = args::range(&d.momentum).map_err(bad)?;
            let diagram = bifurcation_diagram(|p| (model.clone(), p), range, &opts)?;
            (diagram, "p_ψ".to_string())
        }
        Some(par) => {
            let p = args::finite(&d.momentum)
                .map_err(|e| bad(format!("{e} (with --parameter, a single momentum P)")))?;
            // Check the name and shape once, up front: bad input, exit code 2.
            model
                .with(&par.name, par.range.0)
                .map_err(|e| CliError::Input(format!("--parameter: {}", describe(&e, None))))?;
            let failure: RefCell<Option<ModelError>> = RefCell::new(None);
            let family = |s: f64| match model.with(&par.name, s) {
                Ok(m) => (m, p),
                Err(e) => {
                    failure.borrow_mut().get_or_insert(e);
                    (model.clone(), p)
                }
            };
            let diagram = bifurcation_diagram(family, par.range, &opts)?;
            if let Some(e) = failure.into_inner() {
                return Err(CliError::Compute(format!(
                    "{}: {}",
                    par.name,
                    describe(&e, None)
                )));
            }
            (diagram, par.name.clone())
        }
    };
    // The figures' diagram: the circles with their verdict modulo the symmetry when asked.
    let drawn = match d.circles {
        None => result.clone(),
        Some(_) if d.svg.is_none() && d.energy_momentum_svg.is_none() => {
            return Err(CliError::Input(
                "--circles draws the circles' verdicts in a figure: give --svg or \
                 --energy-momentum-svg"
                    .into(),
            ))
        }
        Some(axis) => {
            let axis = routh::Vector3::from(axis);
            if !(axis.norm() > 0.0 && axis.norm().is_finite()) {
                return Err(CliError::Input(format!(
                    "--circles {axis:?}: the symmetry axis must be a non-zero vector"
                )));
            }
            match &d.parameter {
                None => with_circle_verdicts(&result, |p| (model.clone(), p), axis.normalize()),
                Some(par) => {
                    let p = args::finite(&d.momentum).map_err(bad)?;
                    let member = |s: f64| {
                        (
                            model.with(&par.name, s).unwrap_or_else(|_| model.clone()),
                            p,
                        )
                    };
                    with_circle_verdicts(&result, member, axis.normalize())
                }
            }
        }
    };
    let mut files = crate::files::Outputs::new();
    if let Some(path) = &d.svg {
        let axis = match &d.parameter {
            None => args::axis_name("momentum", model.latex_symbols()),
            Some(par) => args::axis_name(&par.name, model.latex_symbols()),
        };
        let opts = d.figure.apply(PlotOptions {
            x_label: axis,
            ..PlotOptions::default()
        });
        files.write(path, |tmp| bifurcation_diagram_svg(&drawn, tmp, &opts))?;
    }
    if let Some(path) = &d.energy_momentum_svg {
        let opts = d.figure.apply(PlotOptions {
            x_label: args::axis_name("momentum", model.latex_symbols()),
            ..PlotOptions::default()
        });
        files.write(path, |tmp| energy_momentum_svg(&drawn, tmp, &opts))?;
    }
    let text = if d.output.json {
        serde_json::to_string_pretty(&result)? + "\n"
    } else if d.output.csv {
        result.to_csv()
    } else {
        render(&result, &x_label)
    };
    files.commit()?;
    Ok(text)
}

/// The diagram as two tables: its branches, then its events.
fn render(d: &BifurcationDiagram, x_label: &str) -> String {
    let mut branches = Table::new(&["branch", "points", "from", "to", "turns at", "kind"]);
    for (i, b) in d.branches.iter().enumerate() {
        let (from, to) = match (b.points.first(), b.points.last()) {
            (Some(f), Some(l)) => (num(f.s), num(l.s)),
            _ => ("-".into(), "-".into()),
        };
        let s: Vec<f64> = b.points.iter().map(|p| p.s).collect();
        let turns = turning_values(&s);
        branches.row(vec![
            i.to_string(),
            b.points.len().to_string(),
            from,
            to,
            if turns.is_empty() {
                "-".into()
            } else {
                turns.iter().map(|&t| num(t)).collect::<Vec<_>>().join(", ")
            },
            if b.isolated { "isolated" } else { "family" }.to_string(),
        ]);
    }
    let mut events = Table::new(&["event", x_label, "gamma", "branch", "before", "after"]);
    for e in &d.events {
        // A nonlinear event names its resonance and its nonlinear verdicts (before → after).
        let kind = match &e.nonlinear {
            Some(n) => format!(
                "{}{} ({} -> {})",
                e.kind,
                n.resonance.map_or(String::new(), |r| format!(" {r}")),
                n.before,
                n.after
            ),
            None => e.kind.to_string(),
        };
        events.row(vec![
            kind,
            format!("{:.9}", e.s),
            vec3(&e.gamma),
            e.branch.to_string(),
            e.before.to_string(),
            e.after.to_string(),
        ]);
    }
    format!(
        "{} branch(es) over {x_label}\n{}\n{} event(s)\n{}",
        d.branches.len(),
        branches.render(),
        d.events.len(),
        events.render()
    )
}

/// The values of the parameter where a branch turns back (a fold: `s` rises then falls, or
/// falls then rises), in order along the branch; empty for a branch monotone in `s`.
fn turning_values(s: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    let mut dir = 0.0f64; // the sign of the last non-zero step
    for w in s.windows(2) {
        let step = w[1] - w[0];
        if step == 0.0 || !step.is_finite() {
            continue;
        }
        if dir != 0.0 && step.signum() != dir {
            out.push(w[0]);
        }
        dir = step.signum();
    }
    out
}

#[cfg(test)]
mod tests {
    use super::turning_values;

    #[test]
    fn a_branch_that_turns_names_its_turning_value() {
        assert!(turning_values(&[0.0, 1.0, 2.0]).is_empty());
        assert!(turning_values(&[5.0, 4.0, 4.0, 3.0]).is_empty());
        assert_eq!(turning_values(&[5.0, 3.0, 2.5, 3.0, 5.0]), vec![2.5]);
        assert_eq!(turning_values(&[0.0, 2.0, 1.0, 3.0]), vec![2.0, 1.0]);
    }
}
