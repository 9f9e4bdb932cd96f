//! `routh certify`: the steady motions at one momentum with an interval certificate.

use crate::cli::Certify;
use crate::commands::load;
use crate::error::CliError;
use crate::table::{num, vec3, Table};
use routh::{steady_motions_certified, CertifyOptions};

/// Runs `routh certify` and returns what it prints.
pub fn certify(c: &Certify) -> Result<String, CliError> {
    let model = load(&c.model)?;
    let _spinner = crate::progress::Spinner::start("certifying");
    let cert = steady_motions_certified(&model, c.momentum, &CertifyOptions::default())?;
    if c.json {
        let v = serde_json::json!({
            "p_psi": cert.p_psi,
            "complete": cert.complete,
            "motions": cert.motions.iter().map(|m| &m.steady).collect::<Vec<_>>(),
            "undecided_regions": cert.undecided.len(),
            "ambiguous_pairs": cert.ambiguous_pairs,
            "boxes": cert.boxes,
            "excluded": cert.excluded,
            "seconds": cert.elapsed.as_secs_f64(),
        });
        return Ok(serde_json::to_string_pretty(&v)? + "\n");
    }
    let mut t = Table::new(&["#", "gamma", "psi_dot", "U_r"]);
    for (i, m) in cert.motions.iter().enumerate() {
        t.row(vec![
            i.to_string(),
            vec3(&m.steady.gamma),
            num(m.steady.psi_dot),
            num(m.steady.amended_potential),
        ]);
    }
    Ok(format!(
        "{} certified steady motion(s) at p_psi = {}; {} ({} boxes, {} excluded, {} undecided \
         region(s), {:.3} s)\n{}",
        cert.motions.len(),
        cert.p_psi,
        if cert.complete {
            "complete: no other steady motion exists"
        } else {
            "NOT complete: undecided regions remain"
        },
        cert.boxes,
        cert.excluded,
        cert.undecided.len(),
        cert.elapsed.as_secs_f64(),
        t.render()
    ))
}
