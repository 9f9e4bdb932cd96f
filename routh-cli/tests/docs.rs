//! The commands shown in docs/cli.md and README.md, run as written: each prints what its sample
//! in the doc shows, in shape. A `console` block of docs/cli.md is `$ routh …` followed by the
//! sample output; the run's output must have the same blocks (separated by blank lines), each
//! with the same title line (`…` in the doc stands for any text), the same column header, the
//! same number of rows, and in each row the same words and integers (counts, indices, verdicts,
//! point numbers) in the same places, floats only as floats (their last digits are round-off).
//! README.md shows commands without output: they must succeed and print something.

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The run of `routh args` from the repository's root (the docs name files from there), with
/// every figure written under `scratch` instead of the working tree.
fn run(line: &str, scratch: &Path) -> (Option<i32>, String, String) {
    let mut args: Vec<String> = line.split_whitespace().skip(1).map(String::from).collect();
    for i in 1..args.len() {
        if args[i - 1].ends_with("svg") && args[i - 1].starts_with("--") {
            let name = Path::new(&args[i])
                .file_name()
                .expect("a file name")
                .to_owned();
            args[i] = scratch.join(name).to_string_lossy().into_owned();
        }
    }
    let o = Command::new(env!("CARGO_BIN_EXE_routh"))
        .args(&args)
        .current_dir(root())
        .output()
        .expect("the routh binary runs");
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// The `$ routh …` commands of the ```console blocks of a markdown text, each with the sample
/// output lines shown under it.
fn console_samples(md: &str) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    let mut inside = false;
    for line in md.lines() {
        if line.starts_with("```") {
            inside = line == "```console";
            continue;
        }
        if !inside {
            continue;
        }
        if let Some(cmd) = line.strip_prefix("$ ") {
            out.push((cmd.to_string(), Vec::new()));
        } else if let Some(last) = out.last_mut() {
            last.1.push(line.to_string());
        }
    }
    out
}

/// The `routh …` lines of the ```sh blocks (comments dropped).
fn sh_commands(md: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut inside = false;
    for line in md.lines() {
        if line.starts_with("```") {
            inside = line == "```sh";
            continue;
        }
        if inside && line.starts_with("routh ") {
            out.push(line.split(" #").next().unwrap_or(line).trim().to_string());
        }
    }
    out
}

/// Blocks of non-blank lines.
fn blocks(lines: &[String]) -> Vec<Vec<String>> {
    let mut out: Vec<Vec<String>> = vec![Vec::new()];
    for l in lines {
        if l.trim().is_empty() {
            if !out.last().is_some_and(Vec::is_empty) {
                out.push(Vec::new());
            }
        } else {
            out.last_mut()
                .expect("one block")
                .push(l.trim_end().to_string());
        }
    }
    out.retain(|b| !b.is_empty());
    out
}

/// A token that is a float (a decimal point or an exponent), with its brackets and commas off.
fn is_float(t: &str) -> bool {
    let t = t.trim_matches(|c| c == '(' || c == ')' || c == ',');
    (t.contains('.') || t.contains('e')) && t.parse::<f64>().is_ok()
}

/// The shape of a row: its tokens, each float replaced by `<f>`.
fn shape(row: &str) -> Vec<String> {
    row.split_whitespace()
        .map(|t| {
            if is_float(t) {
                "<f>".to_string()
            } else {
                t.to_string()
            }
        })
        .collect()
}

/// Whether `actual` is `doc` with each `…` of the doc standing for any text.
fn matches_elided(doc: &str, actual: &str) -> bool {
    let parts: Vec<&str> = doc.split('…').collect();
    if parts.len() == 1 {
        return shape(doc) == shape(actual);
    }
    let mut rest = actual;
    for (i, p) in parts.iter().enumerate() {
        match rest.find(p) {
            Some(k) if i > 0 || k == 0 => rest = &rest[k + p.len()..],
            _ => return false,
        }
    }
    parts.last().is_some_and(|p| p.is_empty()) || rest.is_empty()
}

/// Why `actual` does not have the shape of the doc's `sample`, or None when it does.
fn mismatch(sample: &[String], actual: &str) -> Option<String> {
    let doc = blocks(sample);
    let run: Vec<String> = actual.lines().map(String::from).collect();
    let run = blocks(&run);
    if doc.len() != run.len() {
        return Some(format!(
            "{} blocks in the doc, {} printed",
            doc.len(),
            run.len()
        ));
    }
    for (d, r) in doc.iter().zip(&run) {
        if !matches_elided(&d[0], &r[0]) {
            return Some(format!("title {:?} in the doc, {:?} printed", d[0], r[0]));
        }
        if d.len() != r.len() {
            return Some(format!(
                "{:?}: {} lines in the doc, {} printed",
                d[0],
                d.len(),
                r.len()
            ));
        }
        for (dl, rl) in d.iter().zip(r).skip(1) {
            if shape(dl) != shape(rl) {
                return Some(format!("line {dl:?} in the doc, {rl:?} printed"));
            }
        }
    }
    None
}

fn scratch(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("routh-docs-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch directory");
    dir
}

#[test]
fn the_shape_check_tells_a_row_count_and_a_count_apart() {
    // The harness itself: a sample equal in shape passes; a different point count, a missing
    // row, another header or title fails.
    let doc: Vec<String> = [
        "2 branch(es) over p_ψ",
        "branch  points  from         to",
        "     0      24  +0.000000e0  +5.000000e0",
        "     1      24  +0.000000e0  +5.000000e0",
        "",
        "0 event(s)",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let ok = "2 branch(es) over p_ψ\nbranch points from to\n 0 24 -1.5e-3 +5.000001e0\n 1 24 +0.0e0 +5.0e0\n\n0 event(s)\n";
    assert_eq!(mismatch(&doc, ok), None);
    for bad in [
        ok.replace(" 1 24", " 1 33"),
        ok.replace(" 1 24 +0.0e0 +5.0e0\n", ""),
        ok.replace("points", "pts"),
        ok.replace("0 event(s)", "1 event(s)"),
        ok.replace("\n\n0 event(s)\n", "\n"),
    ] {
        assert!(mismatch(&doc, &bad).is_some(), "{bad}");
    }
    assert!(matches_elided(
        "3 motions (…; modulo V)",
        "3 motions (kappa: x; modulo V)"
    ));
    assert!(!matches_elided(
        "3 motions (…; modulo V)",
        "3 motions (kappa: x)"
    ));
}

#[test]
fn every_console_sample_of_cli_md_is_what_the_command_prints() {
    let md = std::fs::read_to_string(root().join("docs/cli.md")).expect("docs/cli.md");
    let samples = console_samples(&md);
    assert!(samples.len() >= 5, "{samples:?}");
    let dir = scratch("cli-md");
    let mut failures = Vec::new();
    for (cmd, sample) in &samples {
        let (code, out, err) = run(cmd, &dir);
        if code != Some(0) {
            failures.push(format!("{cmd}: exit code {code:?}, stderr {err}"));
            continue;
        }
        if sample.iter().all(|l| l.trim().is_empty()) {
            // No sample shown: the command runs, and --json prints JSON.
            if cmd.contains("--json") && serde_json::from_str::<serde_json::Value>(&out).is_err() {
                failures.push(format!("{cmd}: not JSON"));
            }
            continue;
        }
        if let Some(why) = mismatch(sample, &out) {
            failures.push(format!("{cmd}: {why}\n--- printed:\n{out}"));
        }
    }
    // Every figure named went to the scratch directory, not into the tree.
    for f in ["diagram.svg", "atlas.svg"] {
        assert!(
            dir.join(f).exists(),
            "{f} not written to the scratch directory"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn every_command_of_the_readme_runs() {
    let md = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let commands = sh_commands(&md);
    assert!(commands.len() >= 5, "{commands:?}");
    let dir = scratch("readme");
    for cmd in &commands {
        let (code, out, err) = run(cmd, &dir);
        assert_eq!(code, Some(0), "{cmd}: stderr {err}");
        assert!(!out.trim().is_empty(), "{cmd}: printed nothing");
        if cmd.contains("--csv") {
            // A CSV: a header and rows of as many fields.
            let mut lines = out.lines();
            let n = lines.next().map_or(0, |h| h.split(',').count());
            assert!(n > 1, "{cmd}: {out}");
            assert!(lines.all(|l| l.split(',').count() == n), "{cmd}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
