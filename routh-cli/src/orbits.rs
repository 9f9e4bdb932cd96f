//! `routh orbits` and `routh section`: the Lyapunov families of periodic orbits born at the
//! linearly stable steady motions at one momentum (period, precession, stability index, events),
//! and Poincaré sections at one (p_ψ, E) (docs/method.md §11).

use crate::cli::{Orbits, Section};
use crate::commands::load;
use crate::error::CliError;
use crate::table::{num, vec3, Table};
use routh::{
    classify, lyapunov_family, poincare_section, steady_motions, OrbitFamily, OrbitOptions,
    SectionOptions, Stability, SteadyMotion, Vector3,
};

/// One family with where it starts.
#[derive(serde::Serialize)]
struct Started {
    motion: SteadyMotion,
    mode: usize,
    family: OrbitFamily,
}

/// Runs `routh orbits` and returns what it prints.
pub fn orbits(a: &Orbits) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let mut opts = OrbitOptions::default().with_max_orbits(usize::from(a.max_orbits));
    if let Some((lo, hi)) = a.energy {
        opts = opts.with_energy_bounds(lo, hi);
    }
    let mut motions = steady_motions(&model, a.momentum)?;
    if let Some(g) = a.gamma {
        let g = Vector3::from(g);
        motions.sort_by(|x, y| (x.gamma - g).norm().total_cmp(&(y.gamma - g).norm()));
        motions.truncate(1);
    }
    let modes: Vec<usize> = match a.mode {
        Some(m) if m > 1 => {
            return Err(CliError::Input(format!(
                "--mode must be 0 (the faster frequency) or 1 (the slower), got {m}"
            )))
        }
        Some(m) => vec![m],
        None => vec![0, 1],
    };
    let mut started = Vec::new();
    let mut skipped = Vec::new();
    for m in motions {
        let verdict = classify(&model, &m)?.verdict;
        if !matches!(
            verdict,
            Stability::SecularlyStable | Stability::GyroscopicallyStabilized
        ) {
            skipped.push(format!(
                "{} ({verdict}: no Lyapunov family)",
                vec3(&m.gamma)
            ));
            continue;
        }
        for &mode in &modes {
            match lyapunov_family(&model, &m, mode, &opts) {
                Ok(family) => started.push(Started {
                    motion: m.clone(),
                    mode,
                    family,
                }),
                Err(e) => skipped.push(format!("{} mode {mode}: {e}", vec3(&m.gamma))),
            }
        }
    }
    if a.output.json {
        return Ok(serde_json::to_string_pretty(&started)? + "\n");
    }
    if a.output.csv {
        let mut s = String::from(
            "family,gamma1,gamma2,gamma3,mode,energy,period,precession,stability_index,stability\n",
        );
        for (i, f) in started.iter().enumerate() {
            let g = f.motion.gamma;
            for o in &f.family.orbits {
                s.push_str(&format!(
                    "{i},{},{},{},{},{},{},{},{},{}\n",
                    g.x,
                    g.y,
                    g.z,
                    f.mode,
                    o.energy,
                    o.period,
                    o.precession,
                    o.stability_index,
                    o.stability
                ));
            }
        }
        return Ok(s);
    }
    let mut out = format!(
        "{} Lyapunov famil{} at p_psi = {}\n",
        started.len(),
        if started.len() == 1 { "y" } else { "ies" },
        a.momentum
    );
    for (i, f) in started.iter().enumerate() {
        let fam = &f.family;
        out.push_str(&format!(
            "\nfamily {i}: from {} (E = {}), mode {}: {} orbits{}\n",
            vec3(&f.motion.gamma),
            num(f.motion.energy),
            f.mode,
            fam.orbits.len(),
            fam.stop
                .as_ref()
                .map_or(String::new(), |s| format!(", ended: {s}"))
        ));
        let step = fam.orbits.len().div_ceil(a.rows.max(1)).max(1);
        let mut t = Table::new(&["#", "E", "T", "precession", "k", "stability"]);
        for (j, o) in fam.orbits.iter().enumerate() {
            if j % step == 0 || j + 1 == fam.orbits.len() {
                t.row(vec![
                    j.to_string(),
                    num(o.energy),
                    num(o.period),
                    num(o.precession),
                    num(o.stability_index),
                    o.stability.to_string(),
                ]);
            }
        }
        out.push_str(&t.render());
        for e in &fam.events {
            out.push_str(&format!("  {e}\n"));
        }
    }
    for s in &skipped {
        out.push_str(&format!("skipped: {s}\n"));
    }
    Ok(out)
}

/// Runs `routh section` and returns what it prints.
pub fn section(a: &Section) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let mut opts = SectionOptions::default().with_size(usize::from(a.orbits), a.crossings as usize);
    if let Some(n) = a.normal {
        opts = opts.with_normal(Vector3::from(n));
    }
    let sec = poincare_section(&model, a.momentum, a.energy, &opts)?;
    if a.output.json {
        return Ok(serde_json::to_string_pretty(&sec)? + "\n");
    }
    if a.output.csv {
        let mut s = String::from("orbit,theta,m_n\n");
        for (i, o) in sec.orbits.iter().enumerate() {
            for p in &o.points {
                s.push_str(&format!("{i},{},{}\n", p[0], p[1]));
            }
        }
        return Ok(s);
    }
    let mut t = Table::new(&["#", "omega0", "gamma0", "crossings", "stopped"]);
    for (i, o) in sec.orbits.iter().enumerate() {
        t.row(vec![
            i.to_string(),
            vec3(&o.omega0),
            vec3(&o.gamma0),
            o.points.len().to_string(),
            o.stop.clone().unwrap_or_default(),
        ]);
    }
    Ok(format!(
        "Poincaré section at p_psi = {}, E = {}: the plane gamma·n = 0, n = {}, {} orbits, {} crossings (theta, M_n: --csv)\n{}",
        a.momentum,
        a.energy,
        vec3(&sec.normal),
        sec.orbits.len(),
        sec.points().count(),
        t.render()
    ))
}
