//! `routh nonlinear`: the nonlinear (Lyapunov) stability of the steady motions at one momentum,
//! from the Birkhoff normal form to order four (Arnold–Moser; Markeev at 1:2 and 1:3).

use crate::cli::AtMomentum;
use crate::commands::load;
use crate::error::CliError;
use crate::table::{num, vec3, Table};
use routh::export::{nonlinear_verdict_name, verdict_name};
use routh::{nonlinear_stability, steady_motions, NonlinearOptions, NonlinearReport, SteadyMotion};

/// Runs `routh nonlinear` and returns what it prints.
pub fn nonlinear(a: &AtMomentum) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let opts = NonlinearOptions::default();
    let all: Vec<(SteadyMotion, NonlinearReport)> = steady_motions(&model, a.momentum)?
        .into_iter()
        .map(|m| nonlinear_stability(&model, &m, &opts).map(|r| (m, r)))
        .collect::<Result<_, _>>()?;
    if a.output.json {
        let items: Vec<serde_json::Value> = all
            .iter()
            .map(|(m, r)| serde_json::json!({ "motion": m, "report": r }))
            .collect();
        return Ok(serde_json::to_string_pretty(&items)? + "\n");
    }
    let resonance = |r: &NonlinearReport| r.resonance.map_or(String::new(), |x| x.to_string());
    if a.output.csv {
        let mut s = String::from(
            "p_psi,gamma1,gamma2,gamma3,linear,nonlinear,omega1,omega2,c20,c11,c02,\
             arnold_determinant,resonance\n",
        );
        for (m, r) in &all {
            let [w1, w2] = r.frequencies;
            let [c20, c11, c02] = r.normal_form;
            s.push_str(&format!(
                "{},{},{},{},{},{},{w1},{w2},{c20},{c11},{c02},{},{}\n",
                m.p_psi,
                m.gamma.x,
                m.gamma.y,
                m.gamma.z,
                verdict_name(r.linear.verdict),
                nonlinear_verdict_name(r.verdict),
                r.arnold_determinant,
                resonance(r)
            ));
        }
        return Ok(s);
    }
    let mut t = Table::new(&["#", "gamma", "linear", "nonlinear", "D", "resonance", "why"]);
    for (i, (m, r)) in all.iter().enumerate() {
        t.row(vec![
            i.to_string(),
            vec3(&m.gamma),
            r.linear.verdict.to_string(),
            r.verdict.to_string(),
            num(r.arnold_determinant),
            resonance(r),
            r.reason.clone(),
        ]);
    }
    Ok(format!(
        "{} steady motion(s) at p_psi = {}: nonlinear stability (Birkhoff normal form, \
         Arnold–Moser)\n{}",
        all.len(),
        a.momentum,
        t.render()
    ))
}
