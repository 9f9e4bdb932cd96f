//! The LaTeX of the derived formulas compiled by a real LaTeX (issue 47, "LaTeX paste-ready"):
//! `LatexFormulas::document` of every example model (`examples/models/*.toml`, here, and the
//! paper's derive models, from tests/latex.rs) goes through `pdflatex`, which must report no
//! error and no overfull line wider than the text by more than [`SLACK_PT`]. Without `pdflatex`
//! on the PATH the compilation is skipped with a message (`.ci/run` installs it). Beside it,
//! one test per defect the compiled text showed: double subscripts, σ used undefined, like
//! terms uncollected, products out of the model's order.

use std::path::Path;
use std::process::Command;

/// How much wider than the text a line may come out (TeX's own `\hfuzz` is 0.1 pt).
const SLACK_PT: f64 = 1.0;

/// Whether `pdflatex` runs here; prints why the compilation is skipped when not.
fn have_pdflatex() -> bool {
    let ok = Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !ok {
        eprintln!(
            "SKIPPED: pdflatex is not installed, the LaTeX of the formulas is not compiled \
             (apt-get install texlive-latex-base; .ci/run installs it)"
        );
    }
    ok
}

/// The widest overfull `\hbox` of a pdflatex log, in points (0 without any).
fn worst_overfull(log: &str) -> f64 {
    log.lines()
        .filter_map(|l| l.strip_prefix("Overfull \\hbox ("))
        .filter_map(|l| l.split_once("pt too wide)"))
        .filter_map(|(n, _)| n.parse::<f64>().ok())
        .fold(0.0, f64::max)
}

/// Compiles `document` with pdflatex (when it is installed) and fails on any error or an
/// overfull line wider than the text by more than [`SLACK_PT`].
pub fn compiles(name: &str, document: &str) {
    if !have_pdflatex() {
        return;
    }
    let dir = std::env::temp_dir().join(format!(
        "routh-latex-{}-{}",
        std::process::id(),
        name.replace(|c: char| !c.is_ascii_alphanumeric(), "_")
    ));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("f.tex"), document).unwrap();
    let out = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "f.tex"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let log = std::fs::read_to_string(dir.join("f.log")).unwrap_or_default();
    let errors: Vec<&str> = log.lines().filter(|l| l.starts_with('!')).collect();
    assert!(
        out.status.success() && errors.is_empty(),
        "{name}: pdflatex failed: {errors:?} (in {})",
        dir.display()
    );
    let worst = worst_overfull(&log);
    assert!(
        worst <= SLACK_PT,
        "{name}: a line is {worst} pt wider than the text (in {})",
        dir.display()
    );
    eprintln!("{name}: compiled by pdflatex, widest overfull line {worst} pt");
    std::fs::remove_dir_all(&dir).ok();
}

/// The example models of `examples/models`, by file stem.
fn example_models() -> Vec<(String, routh::Model)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/models");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 5, "{files:?}");
    files
        .iter()
        .map(|p| {
            let name = p.file_stem().unwrap().to_string_lossy().to_string();
            (name, routh::Model::from_file(p).unwrap())
        })
        .collect()
}

/// Every example model's formulas compile, each line within the text width.
#[test]
fn every_example_model_compiles() {
    for (name, model) in example_models() {
        compiles(&name, &model.latex().document(&name));
    }
}

/// The `\sigma_{k}` of `text` in the order used, each paired with whether it was defined (on
/// the left of a `&=`) before that use.
fn sigma_uses(text: &str) -> Vec<(String, bool)> {
    let mut defined = std::collections::HashSet::new();
    let mut uses = Vec::new();
    for row in text.split(" \\\\\n").flat_map(|r| r.lines()) {
        let (lhs, rhs) = row.split_once(" &= ").unwrap_or(("", row));
        for piece in rhs.split("\\sigma_{").skip(1) {
            let k = piece.split('}').next().unwrap().to_string();
            uses.push((k.clone(), defined.contains(&k)));
        }
        if let Some(k) = lhs.strip_prefix("\\sigma_{") {
            defined.insert(k.trim_end_matches('}').to_string());
        }
    }
    uses
}

/// No `\sigma_{k}` is used before its definition in the display blocks or the document, and
/// each is defined once in the whole text (issue 47: the gyrostat's σ₁ … σ₂₅ were defined after
/// the formula, numbered from 1 in each formula).
#[test]
fn no_sigma_is_used_undefined() {
    for (name, model) in example_models() {
        let f = model.latex();
        for text in [f.display(), f.document(&name)] {
            let uses = sigma_uses(&text);
            let undefined: Vec<&String> = (uses.iter())
                .filter(|(_, ok)| !ok)
                .map(|(k, _)| k)
                .collect();
            assert!(
                undefined.is_empty(),
                "{name}: σ {undefined:?} used undefined"
            );
            let defs: Vec<&str> = (text.lines())
                .filter_map(|l| l.split_once(" &= "))
                .filter(|(l, _)| l.starts_with("\\sigma_{"))
                .map(|(l, _)| l)
                .collect();
            let distinct: std::collections::HashSet<_> = defs.iter().collect();
            assert_eq!(defs.len(), distinct.len(), "{name}: a σ defined twice");
        }
    }
}

/// The gyrostat's centre of mass `r_c` is indexed as `{r_c}_{1}` (issue 47: `r_c_{1}` was 12
/// "Double subscript" errors); the heavy top's products keep the Lagrangian's order `m g l`
/// (the parameters come sorted by name from the TOML table: it was `g l m`); its G has like
/// terms collected (it had `A_1 \dot\psi … + A_1 \dot\psi`).
#[test]
fn symbols_order_and_like_terms() {
    let models: std::collections::HashMap<String, routh::Model> =
        example_models().into_iter().collect();
    let gyrostat = models["gyrostat"].latex();
    assert!(
        gyrostat.lagrangian.contains("{r_c}_{1} \\gamma_1"),
        "{}",
        gyrostat.lagrangian
    );
    assert!(
        !gyrostat.lagrangian.contains("r_c_"),
        "{}",
        gyrostat.lagrangian
    );
    let top = models["heavy_top"].latex();
    assert!(
        top.lagrangian
            .ends_with("- m \\mathit{g} \\mathit{l} \\gamma_3"),
        "{}",
        top.lagrangian
    );
    assert!(!top.amended_potential.contains("\\mathit{g} \\mathit{l} m"));
    // The entry G₁₂ is −½γ₃ times a sum with `A_1 \dot\psi` once (as `2 {A_1} \dot\psi`).
    let g12 = top.g.split(" & ").nth(1).unwrap();
    assert_eq!(g12.matches("{A_1} \\dot\\psi -").count(), 1, "{g12}");
    assert!(g12.contains("2 {A_1} \\dot\\psi"), "{g12}");
    // No sum of constants left: `- 1 + 1` and the like.
    for s in [&top.g, &top.c, &gyrostat.c] {
        assert!(!s.contains("- 1 + 1") && !s.contains("+ 1 - 1"), "{s}");
    }
}
