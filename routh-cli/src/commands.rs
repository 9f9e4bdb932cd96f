//! `steady`, `classify` and `formulas`: the analyses at one momentum, and the model's formulas.

use crate::cli::{AtMomentum, Formulas};
use crate::error::CliError;
use crate::table::{num, vec3, Table};
use routh::{classified_steady_motions, steady_motions, LatexFormulas, Model, ModelError};
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

/// `routh classify`: the steady motions at `p_ψ = P` with their stability reports (§5).
pub fn classify(a: &AtMomentum) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let all = classified_steady_motions(&model, a.momentum)?;
    if a.output.json {
        // `Classified` has no `Serialize` of its own: its two parts have.
        let items: Vec<serde_json::Value> = all
            .iter()
            .map(
                |c| serde_json::json!({ "p_psi": c.p_psi, "motion": c.motion, "report": c.report }),
            )
            .collect();
        return Ok(serde_json::to_string_pretty(&items)? + "\n");
    }
    if a.output.csv {
        let mut s = String::from(
            "p_psi,gamma1,gamma2,gamma3,psi_dot,verdict,kappa1,kappa2,degree_of_instability\n",
        );
        for c in &all {
            let [k1, k2] = c.report.restricted_hessian_eigenvalues;
            s.push_str(&format!(
                "{},{},{},{},{},{},{},{},{}\n",
                c.p_psi,
                c.motion.gamma.x,
                c.motion.gamma.y,
                c.motion.gamma.z,
                c.motion.psi_dot,
                routh::export::verdict_name(c.report.verdict),
                k1,
                k2,
                c.report.degree_of_instability
            ));
        }
        return Ok(s);
    }
    let mut t = Table::new(&[
        "#", "gamma", "psi_dot", "verdict", "kappa1", "kappa2", "degree",
    ]);
    for (i, c) in all.iter().enumerate() {
        let [k1, k2] = c.report.restricted_hessian_eigenvalues;
        t.row(vec![
            i.to_string(),
            vec3(&c.motion.gamma),
            num(c.motion.psi_dot),
            c.report.verdict.to_string(),
            num(k1),
            num(k2),
            c.report.degree_of_instability.to_string(),
        ]);
    }
    Ok(format!(
        "{} steady motion(s) at p_psi = {} (kappa: eigenvalues of the restricted second variation \
         of U_r; degree: degree of instability)\n{}",
        all.len(),
        a.momentum,
        t.render()
    ))
}

/// `routh formulas`: the derived Lagrangian, amended potential (34) and ψ̇ (38), as plain text.
pub fn formulas(f: &Formulas) -> Result<String, CliError> {
    let model = load(&f.model)?;
    if f.latex {
        return latex(&model.latex(), f.json);
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

/// `routh formulas --latex`: the seven formulas of [`LatexFormulas`], each under a LaTeX comment
/// with its field name and its meaning, as `name = formula` (math mode, no delimiters); with
/// `json`, the `LatexFormulas` object itself.
fn latex(l: &LatexFormulas, json: bool) -> Result<String, CliError> {
    if json {
        return Ok(serde_json::to_string_pretty(l)? + "\n");
    }
    let items = [
        (
            "lagrangian",
            "the Lagrangian",
            "L(\\omega, \\gamma)",
            &l.lagrangian,
        ),
        (
            "psi_dot",
            "ψ̇ of (12)/(38)",
            "\\dot\\psi(\\Omega, \\gamma, p_\\psi)",
            &l.psi_dot,
        ),
        (
            "routhian",
            "the Routh function (14)",
            "R(\\Omega, \\gamma, p_\\psi)",
            &l.routhian,
        ),
        (
            "amended_potential",
            "the amended potential (34), −R(0, γ, p_ψ)",
            "U_r(\\gamma, p_\\psi)",
            &l.amended_potential,
        ),
        ("a", "∂²R/∂Ω² at Ω = 0 (64)", "A", &l.a),
        ("g", "the gyroscopic matrix of (64) at Ω = 0", "G", &l.g),
        ("c", "the stiffness matrix of (64) at Ω = 0", "C", &l.c),
    ];
    Ok(items
        .iter()
        .map(|(name, what, lhs, formula)| format!("% {name}: {what}\n{lhs} = {formula}\n"))
        .collect::<Vec<_>>()
        .join("\n"))
}
