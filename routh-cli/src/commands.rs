//! `steady`, `classify` and `formulas`: the analyses at one momentum, and the model's formulas.

use crate::cli::{AtMomentum, ClassifyArgs, Formulas};
use crate::error::CliError;
use crate::table::{num, vec3, Table};
use routh::{
    classified_steady_motions, classify_circle, steady_motions, CircleReport, CircleStability,
    LatexFormulas, Model, ModelError, SympyFormulas, Vector3,
};
use std::collections::HashSet;
use std::path::Path;

/// Reads a model file; any failure (missing file, TOML or DSL error, with its position) is bad
/// input.
pub fn load(path: &Path) -> Result<Model, CliError> {
    Model::from_file(path).map_err(|e| CliError::Input(describe(&e, Some(path))))
}

/// A model error as one message: with its position, source line and caret when it has one (and
/// the file's name), else its message alone.
pub fn describe(e: &ModelError, path: Option<&Path>) -> String {
    let full = e.to_string();
    if full.lines().count() <= 2 && e.line() <= 1 && e.column() <= 1 {
        return match path {
            Some(p) if !e.message().contains(&*p.to_string_lossy()) => {
                format!("{}: {}", p.display(), e.message())
            }
            _ => e.message().to_string(),
        };
    }
    let full = full.strip_prefix("error: ").unwrap_or(&full).to_string();
    match path {
        Some(p) => full.replacen(" --> line", &format!(" --> {}: line", p.display()), 1),
        None => full,
    }
}

/// `routh steady`: the steady motions at `p_ψ = P` (paper §4, (36)–(38)).
pub fn steady(a: &AtMomentum) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let motions = steady_motions(&model, a.momentum)?;
    if a.output.json {
        return Ok(serde_json::to_string_pretty(&motions)? + "\n");
    }
    let mut t = Table::new(&[
        "#", "gamma1", "gamma2", "gamma3", "psi_dot", "mu", "U_r", "E",
    ]);
    for (i, m) in motions.iter().enumerate() {
        t.row(vec![
            i.to_string(),
            format!("{:+.9}", m.gamma.x),
            format!("{:+.9}", m.gamma.y),
            format!("{:+.9}", m.gamma.z),
            num(m.psi_dot),
            num(m.mu),
            num(m.amended_potential),
            num(m.energy),
        ]);
    }
    if a.output.csv {
        let mut s =
            String::from("p_psi,gamma1,gamma2,gamma3,psi_dot,mu,amended_potential,energy\n");
        for m in &motions {
            s.push_str(&format!(
                "{},{},{},{},{},{},{},{}\n",
                m.p_psi,
                m.gamma.x,
                m.gamma.y,
                m.gamma.z,
                m.psi_dot,
                m.mu,
                m.amended_potential,
                m.energy
            ));
        }
        return Ok(s);
    }
    Ok(format!(
        "{} steady motion(s) at p_psi = {}\n{}",
        motions.len(),
        a.momentum,
        t.render()
    ))
}

/// `routh classify`: the steady motions at `p_ψ = P` with their stability reports (§5); with
/// `--axis`, every circle of steady motions also decided modulo the symmetry
/// (`routh::classify_circle`).
pub fn classify(c: &ClassifyArgs) -> Result<String, CliError> {
    let a = &c.at;
    let model = load(&a.model)?;
    let all = classified_steady_motions(&model, a.momentum)?;
    // The circle's report for each motion that is not isolated, when an axis is given.
    let circles: Vec<Option<CircleReport>> = all
        .iter()
        .map(|m| match c.axis {
            Some(e) if !m.motion.isolated => {
                classify_circle(&model, &m.motion, &Vector3::from(e)).map(Some)
            }
            _ => Ok(None),
        })
        .collect::<Result<_, _>>()?;
    if a.output.json {
        // `Classified` has no `Serialize` of its own: its two parts have.
        let items: Vec<serde_json::Value> = all
            .iter()
            .zip(&circles)
            .map(|(m, circle)| {
                let mut v =
                    serde_json::json!({ "p_psi": m.p_psi, "motion": m.motion, "report": m.report });
                if let Some(circle) = circle {
                    v["circle"] = serde_json::json!({
                        "axis": circle.axis,
                        "verdict": circle.verdict,
                        "curvature": circle.curvature,
                        "across": circle.across,
                        "momentum_term": circle.momentum_term,
                        "axis_momentum": circle.axis_momentum,
                    });
                }
                v
            })
            .collect();
        return Ok(serde_json::to_string_pretty(&items)? + "\n");
    }
    let circle_verdict = |c: &Option<CircleReport>| match c {
        Some(c) => circle_name(c.verdict).to_string(),
        None => String::new(),
    };
    if a.output.csv {
        let mut s = String::from(
            "p_psi,gamma1,gamma2,gamma3,psi_dot,verdict,kappa1,kappa2,degree_of_instability",
        );
        if c.axis.is_some() {
            s.push_str(",circle_verdict,circle_curvature");
        }
        s.push('\n');
        for (m, circle) in all.iter().zip(&circles) {
            let [k1, k2] = m.report.restricted_hessian_eigenvalues;
            s.push_str(&format!(
                "{},{},{},{},{},{},{},{},{}",
                m.p_psi,
                m.motion.gamma.x,
                m.motion.gamma.y,
                m.motion.gamma.z,
                m.motion.psi_dot,
                routh::export::verdict_name(m.report.verdict),
                k1,
                k2,
                m.report.degree_of_instability
            ));
            if c.axis.is_some() {
                let v = circle
                    .as_ref()
                    .map_or(String::new(), |c| c.curvature.to_string());
                s.push_str(&format!(",{},{}", circle_verdict(circle), v));
            }
            s.push('\n');
        }
        return Ok(s);
    }
    let mut head = vec![
        "#", "gamma", "psi_dot", "verdict", "kappa1", "kappa2", "degree",
    ];
    if c.axis.is_some() {
        head.extend(["modulo the axis", "V''"]);
    }
    let mut t = Table::new(&head);
    for (i, (m, circle)) in all.iter().zip(&circles).enumerate() {
        let [k1, k2] = m.report.restricted_hessian_eigenvalues;
        let mut row = vec![
            i.to_string(),
            vec3(&m.motion.gamma),
            num(m.motion.psi_dot),
            m.report.verdict.to_string(),
            num(k1),
            num(k2),
            m.report.degree_of_instability.to_string(),
        ];
        if c.axis.is_some() {
            row.push(
                circle
                    .as_ref()
                    .map_or(String::new(), |c| c.verdict.to_string()),
            );
            row.push(circle.as_ref().map_or(String::new(), |c| num(c.curvature)));
        }
        t.row(row);
    }
    let circle_note = if c.axis.is_some() {
        "; modulo the axis: circles of steady motions decided by the doubly amended potential V"
    } else {
        ""
    };
    Ok(format!(
        "{} steady motion(s) at p_psi = {} (kappa: eigenvalues of the restricted second variation \
         of U_r; degree: degree of instability{circle_note})\n{}",
        all.len(),
        a.momentum,
        t.render()
    ))
}

/// The machine name of a circle's verdict in CSV (as `routh::export::verdict_name`).
fn circle_name(v: CircleStability) -> &'static str {
    match v {
        CircleStability::Stable => "stable",
        CircleStability::Unstable => "unstable",
        CircleStability::Degenerate => "degenerate",
    }
}

/// `routh formulas`: the derived Lagrangian, amended potential (34) and ψ̇ (38), as plain text.
pub fn formulas(f: &Formulas) -> Result<String, CliError> {
    let model = load(&f.model)?;
    if f.latex {
        let title = f.model.file_stem().map(|s| s.to_string_lossy());
        let title = format!(
            "Derived formulas of {}",
            title.as_deref().unwrap_or("the model")
        );
        let document = f.document.then_some(title.as_str());
        return latex(&model.latex(), f.json, document);
    }
    if f.sympy {
        return sympy(&model.sympy(), f.json);
    }
    let [lagrangian, amended, psi_dot] = model.formulas();
    if f.json {
        let v = serde_json::json!({
            "lagrangian": lagrangian,
            "amended_potential": amended,
            "psi_dot_at_rest": psi_dot,
        });
        return Ok(serde_json::to_string_pretty(&v)? + "\n");
    }
    Ok(format!(
        "L(ω, γ) = {lagrangian}\nU_r(γ, p_ψ) = {amended}\nψ̇(0, γ, p_ψ) = {psi_dot}\n"
    ))
}

/// `routh formulas --latex`: the seven formulas of [`LatexFormulas`] as display blocks to
/// paste into a document with amsmath ([`LatexFormulas::display`]: an `align*` each, under a
/// LaTeX comment with its field name and meaning, lines broken to fit a page); with `document`,
/// a complete LaTeX document ([`LatexFormulas::document`], titled by the model file's name);
/// with `json`, the `LatexFormulas` object itself.
fn latex(l: &LatexFormulas, json: bool, document: Option<&str>) -> Result<String, CliError> {
    if json {
        return Ok(serde_json::to_string_pretty(l)? + "\n");
    }
    Ok(match document {
        Some(title) => l.document(title),
        None => l.display(),
    })
}

/// `routh formulas --sympy`: the seven formulas of [`SympyFormulas`] in SymPy's syntax, as a
/// Python script: `from sympy import *`, each symbol defined as a real
/// `Symbol` under its identifier ([`SympyFormulas::symbols`]: `lambda_ = Symbol("lambda",
/// real=True)` for a parameter `lambda`), the named subexpressions, if any, and each formula
/// under a Python comment with its meaning as `name = formula`; a formula's name that is also a
/// symbol's identifier gets `_` appended (`g_` for G when the model has a parameter `g`), so
/// that no line rebinds a symbol a later line uses. With `json`, the `SympyFormulas` object.
fn sympy(f: &SympyFormulas, json: bool) -> Result<String, CliError> {
    if json {
        return Ok(serde_json::to_string_pretty(f)? + "\n");
    }
    // Every name the text uses besides its symbols is SymPy's (`sqrt`, `Matrix`, `nan`), and
    // no symbol's identifier is one of them.
    let mut out = String::from("from sympy import *\n\n");
    let mut bound: HashSet<&str> = HashSet::new();
    for (ident, name) in &f.symbols {
        out.push_str(&format!(
            "{ident} = Symbol({}, real=True)\n",
            python_str(name)
        ));
        bound.insert(ident);
    }
    out.push('\n');
    for (name, value) in &f.definitions {
        out.push_str(&format!("{name} = {value}\n"));
        bound.insert(name);
    }
    if !f.definitions.is_empty() {
        out.push('\n');
    }
    let items = [
        ("lagrangian", "L(omega, gamma)", &f.lagrangian),
        (
            "psi_dot",
            "psi dot of (12)/(38), in Omega, gamma, p_psi",
            &f.psi_dot,
        ),
        (
            "routhian",
            "the Routh function R(Omega, gamma, p_psi) (14)",
            &f.routhian,
        ),
        (
            "amended_potential",
            "the amended potential U_r(gamma, p_psi) (34)",
            &f.amended_potential,
        ),
        ("a", "A = d2R/dOmega2 at Omega = 0 (64)", &f.a),
        ("g", "the gyroscopic matrix G of (64) at Omega = 0", &f.g),
        ("c", "the stiffness matrix C of (64) at Omega = 0", &f.c),
    ];
    let lines: Vec<String> = items
        .iter()
        .map(|(name, what, formula)| {
            let mut name = name.to_string();
            while bound.contains(name.as_str()) {
                name.push('_');
            }
            format!("# {what}\n{name} = {formula}\n")
        })
        .collect();
    out.push_str(&lines.join("\n"));
    Ok(out)
}

/// `s` as a Python string literal.
fn python_str(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}
