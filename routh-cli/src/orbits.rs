//! `routh orbits` and `routh section`: the Lyapunov families of periodic orbits born at the
//! linearly stable steady motions at one momentum (period, precession, stability index, events),
//! and Poincaré sections at one (p_ψ, E) (docs/method.md §11).

use crate::cli::{OrbitArgs, Orbits, Section};
use crate::commands::{describe, load};
use crate::error::CliError;
use crate::files::Outputs;
use crate::options::options;
use crate::orbit_out::{self, Along, Family, Origin};
use crate::table::{num, vec3, Table};
use routh::plot::{orbit_family_svg, orbit_periods_svg, poincare_section_svg, PlotOptions};
use routh::{
    classify, continue_orbit, continue_orbit_in, lyapunov_family, orbit_nonlinear_stability,
    period_doubled_family, periodic_orbit, poincare_section, steady_motions, switch_branch, Model,
    ModelError, OrbitEventKind, OrbitNonlinearOptions, OrbitOptions, Param, PeriodicOrbit,
    RouthError, SectionOptions, Stability, Vector3,
};
use serde_json::{json, Value};
use std::cell::RefCell;
use std::io::Write;

/// The orbit corrected from a guess; the library's refusals of the guess (not finite, γ not a
/// unit vector, T ≤ 0, a steady motion) are bad input, a corrector that does not converge a
/// failed computation.
fn correct(
    model: &Model,
    omega: [f64; 3],
    gamma: [f64; 3],
    period: f64,
    opts: &OrbitOptions,
) -> Result<PeriodicOrbit, CliError> {
    periodic_orbit(
        model,
        Vector3::from(omega),
        Vector3::from(gamma),
        period,
        opts,
    )
    .map_err(|e| match e {
        RouthError::NonFinite { .. }
        | RouthError::NonUnitGamma { .. }
        | RouthError::InvalidOption { .. } => {
            CliError::Input(format!("the guess (--omega, --gamma, --period): {e}"))
        }
        e => CliError::Compute(format!(
            "no periodic orbit from the guess: {e} (try a period guess nearer the orbit's, or \
             a guess nearer a periodic orbit)"
        )),
    })
}

/// Runs `routh orbit` and returns what it prints.
pub fn orbit(a: &OrbitArgs) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let mut opts: OrbitOptions = options([], &a.opts)?;
    opts.control = crate::interrupt::control();
    let o = correct(&model, a.omega, a.gamma, a.period, &opts)?;
    if a.nonlinear {
        let nl = OrbitNonlinearOptions {
            control: opts.control.clone(),
            ..OrbitNonlinearOptions::default()
        };
        let r = orbit_nonlinear_stability(&model, &o, &nl)?;
        return Ok(if a.output.json {
            orbit_out::nonlinear_json(&r)?
        } else if a.output.csv {
            orbit_out::nonlinear_csv(&r)
        } else {
            orbit_out::nonlinear_table(&r)
        });
    }
    if a.output.json {
        return Ok(orbit_out::orbit_json(&o)?);
    }
    if a.output.csv {
        return Ok(orbit_out::orbit_csv(&o));
    }
    Ok(orbit_out::orbit_table(&o))
}

/// The Lyapunov families at `p`: one per linearly stable steady motion (the one nearest
/// `--gamma`, if given) and mode; what could not start is described in `skipped`.
fn lyapunov_families(
    a: &Orbits,
    model: &Model,
    p: f64,
    opts: &OrbitOptions,
    skipped: &mut Vec<String>,
) -> Result<Vec<Family>, CliError> {
    let mut motions = steady_motions(model, p)?;
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
    let mut out = Vec::new();
    for m in motions {
        let verdict = classify(model, &m)?.verdict;
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
            match lyapunov_family(model, &m, mode, opts) {
                Ok(family) => out.push(Family {
                    origin: Origin::Lyapunov {
                        motion: m.clone(),
                        mode,
                    },
                    family,
                    along: None,
                }),
                Err(e) => skipped.push(format!("{} mode {mode}: {e}", vec3(&m.gamma))),
            }
        }
    }
    Ok(out)
}

/// `--doubling` and `--switch`: the family born at each period doubling (with `--doubling`) and
/// each branch point (with `--switch`) of the families computed so far, appended to `families`
/// (one generation: the new families' own events are listed, not followed). Returns, per family,
/// the events followed and the family each started; what could not start goes to `skipped`.
fn follow_events(
    a: &Orbits,
    model: &Model,
    opts: &OrbitOptions,
    families: &mut Vec<Family>,
    skipped: &mut Vec<String>,
) -> Vec<Vec<(usize, usize)>> {
    let mut followed: Vec<Vec<(usize, usize)>> = vec![Vec::new(); families.len()];
    let (mut doublings, mut branch_points) = (0, 0);
    for i in 0..families.len() {
        for j in 0..families[i].family.events.len() {
            let e = &families[i].family.events[j];
            let started = match e.kind {
                OrbitEventKind::PeriodDoubling if a.doubling => {
                    doublings += 1;
                    period_doubled_family(model, e, opts).map(|f| {
                        (
                            f,
                            Origin::PeriodDoubled {
                                parent: i,
                                event: j,
                            },
                        )
                    })
                }
                OrbitEventKind::BranchPoint if a.switch => {
                    branch_points += 1;
                    switch_branch(model, e, opts).map(|f| {
                        (
                            f,
                            Origin::Switched {
                                parent: i,
                                event: j,
                            },
                        )
                    })
                }
                _ => continue,
            };
            match started {
                Ok((family, origin)) => {
                    followed[i].push((j, families.len()));
                    families.push(Family {
                        origin,
                        family,
                        along: None,
                    });
                }
                Err(err) => {
                    skipped.push(format!("family {i}, {} at E = {}: {err}", e.kind, e.energy))
                }
            }
        }
    }
    if a.doubling && doublings == 0 {
        skipped.push("--doubling: no period doubling along the families computed".into());
    }
    if a.switch && branch_points == 0 {
        skipped.push("--switch: no branch point along the families computed".into());
    }
    followed.resize(families.len(), Vec::new());
    followed
}

/// `--continue --parameter NAME=LO..HI`: the guess corrected at the model file's value of NAME
/// (`momentum`: at the guess's p_ψ), then its family at its energy through NAME over LO..HI
/// (`continue_orbit_in`), with the table's title. A NAME that is not a scalar parameter of the
/// model, or a value of it outside LO..HI, is bad input; a family that fails is a failed
/// computation.
fn continued_in_parameter(
    a: &Orbits,
    model: &Model,
    opts: &OrbitOptions,
) -> Result<(Family, String), CliError> {
    let (Some(par), Some(omega), Some(gamma), Some(period)) =
        (&a.parameter, a.omega, a.gamma, a.period)
    else {
        return Err(CliError::Input(
            "--continue --parameter needs --omega X,Y,Z --gamma X,Y,Z --period T".into(),
        ));
    };
    let (name, (lo, hi)) = (par.name.as_str(), par.range);
    let momentum = name == "momentum";
    // The file's value of NAME (a scalar), checked before any work: bad input, exit code 2.
    let file_value = if momentum {
        None
    } else {
        model
            .with(name, lo)
            .map_err(|e| CliError::Input(format!("--parameter: {}", describe(&e, None))))?;
        match model.get(name) {
            Some(Param::Scalar(v)) => Some(v),
            _ => {
                return Err(CliError::Input(format!(
                    "--parameter: `{name}` is not a scalar parameter of the model"
                )))
            }
        }
    };
    let outside = |s0: f64, what: &str| {
        CliError::Input(format!(
            "--parameter {name}={lo}..{hi}: the orbit is corrected at {name} = {s0} ({what}), \
             outside the range: the range must contain it"
        ))
    };
    if let Some(v) = file_value {
        if !(lo..=hi).contains(&v) {
            return Err(outside(v, "the model file's value"));
        }
    }
    let start = correct(model, omega, gamma, period, opts)?;
    let s0 = file_value.unwrap_or(start.p_psi);
    if !(lo..=hi).contains(&s0) {
        return Err(outside(s0, "the guess's p_psi"));
    }
    let result = if momentum {
        continue_orbit_in(|s| (model.clone(), s), &start, s0, (lo, hi), opts)
    } else {
        // `with` cannot fail on a finite value of a scalar checked above; should it, the first
        // failure is reported (and a NaN p_ψ stops the family at once).
        let failure: RefCell<Option<ModelError>> = RefCell::new(None);
        let p = start.p_psi;
        let family = |s: f64| match model.with(name, s) {
            Ok(m) => (m, p),
            Err(e) => {
                failure.borrow_mut().get_or_insert(e);
                (model.clone(), f64::NAN)
            }
        };
        let r = continue_orbit_in(family, &start, s0, (lo, hi), opts);
        if let Some(e) = failure.into_inner() {
            return Err(CliError::Compute(format!("{name}: {}", describe(&e, None))));
        }
        r
    };
    let f = result.map_err(|e| {
        CliError::Compute(format!(
            "the family through {name} from {name} = {s0} failed: {e}"
        ))
    })?;
    let title = format!(
        "1 family through the orbit at p_psi = {}, E = {} (T = {}) at {name} = {s0} over {name} \
         in [{lo}, {hi}] at fixed energy",
        start.p_psi,
        num(start.energy),
        num(start.period)
    );
    let family = Family {
        origin: Origin::Continued,
        family: f.family,
        along: Some(Along {
            name: name.to_string(),
            parameter: f.parameter,
            event_parameter: f.event_parameter,
        }),
    };
    Ok((family, title))
}

/// "1 `what` family", "`n` `what` families".
fn count(n: usize, what: &str) -> String {
    format!("{n} {what} famil{}", if n == 1 { "y" } else { "ies" })
}

/// Runs `routh orbits` and returns what it prints.
pub fn orbits(a: &Orbits) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let mut opts: OrbitOptions = options(
        [
            ("max_orbits", a.max_orbits.map(Value::from)),
            ("nonlinear", a.nonlinear.then_some(Value::Bool(true))),
            ("energy_bounds", a.energy.map(|(lo, hi)| json!([lo, hi]))),
        ],
        &a.opts,
    )?;
    // One bar for the families one after another (each half of a family counts its orbits up
    // to the budget).
    let bar = crate::progress::Bar::start("orbits of the family");
    opts.control = bar.control();
    let mut skipped = Vec::new();
    // The families asked for, and the title of the table.
    let (mut families, mut title) = match (a.continue_orbit, a.momentum) {
        (true, _) if a.parameter.is_some() => {
            let (family, title) = continued_in_parameter(a, &model, &opts)?;
            (vec![family], title)
        }
        (true, _) => {
            let (Some(omega), Some(gamma), Some(period), Some((lo, hi))) =
                (a.omega, a.gamma, a.period, a.energy)
            else {
                return Err(CliError::Input(
                    "--continue needs --omega X,Y,Z --gamma X,Y,Z --period T and --energy \
                     LO..HI (or --parameter NAME=LO..HI, at the orbit's energy)"
                        .into(),
                ));
            };
            let start = correct(&model, omega, gamma, period, &opts)?;
            if !(lo..=hi).contains(&start.energy) {
                return Err(CliError::Input(format!(
                    "the corrected orbit has E = {} (the energy of the guess), outside --energy \
                     {lo}..{hi}: the range must contain it",
                    start.energy
                )));
            }
            let family = continue_orbit(&model, &start, (lo, hi), &opts)?;
            let title = format!(
                "1 family through the orbit at p_psi = {}, E = {} (T = {}) over E in [{lo}, {hi}]",
                start.p_psi,
                num(start.energy),
                num(start.period)
            );
            (
                vec![Family {
                    origin: Origin::Continued,
                    family,
                    along: None,
                }],
                title,
            )
        }
        (false, Some(p)) => {
            let fams = lyapunov_families(a, &model, p, &opts, &mut skipped)?;
            let n = fams.len();
            (fams, format!("{} at p_psi = {p}", count(n, "Lyapunov")))
        }
        (false, None) => {
            return Err(CliError::Input(
                "orbits needs --momentum P (or --continue with a guess)".into(),
            ))
        }
    };
    // --doubling, --switch: one generation of the families born at the events.
    let followed = follow_events(a, &model, &opts, &mut families, &mut skipped);
    for (on, name, what) in [
        (a.doubling, "period_doubled", "period-doubled"),
        (a.switch, "switched", "switched"),
    ] {
        if on {
            let n = families.iter().filter(|f| f.origin.name() == name).count();
            title.push_str(&format!(", {}", count(n, what)));
        }
    }
    let mut files = Outputs::new();
    if a.svg.is_some() || a.periods_svg.is_some() {
        let [one] = families.as_slice() else {
            return Err(CliError::Input(format!(
                "--svg and --periods-svg draw one family, and this run has {}: choose it with \
                 --mode and --gamma",
                families.len()
            )));
        };
        let opts = a.figure.apply(PlotOptions {
            x_label: "E".into(),
            ..PlotOptions::default()
        });
        if let Some(path) = &a.svg {
            files.write(path, |tmp| orbit_family_svg(&one.family, tmp, &opts))?;
        }
        if let Some(path) = &a.periods_svg {
            files.write(path, |tmp| orbit_periods_svg(&one.family, tmp, &opts))?;
        }
    }
    let text = if a.output.json || a.output.csv {
        // What could not start goes to stderr: stdout is data.
        for s in &skipped {
            // A stderr that cannot be written loses the note, not the run.
            let _ = writeln!(std::io::stderr(), "note: skipped: {s}");
        }
        if a.output.json {
            orbit_out::families_json(&families)?
        } else {
            orbit_out::families_csv(&families)
        }
    } else {
        let mut out = format!("{title}\n");
        for (i, f) in families.iter().enumerate() {
            out.push('\n');
            out.push_str(&orbit_out::family_table(i, f, a.rows, &followed[i]));
        }
        for s in &skipped {
            out.push_str(&format!("skipped: {s}\n"));
        }
        out
    };
    files.commit()?;
    Ok(text)
}

/// Runs `routh section` and returns what it prints.
pub fn section(a: &Section) -> Result<String, CliError> {
    let model = load(&a.model)?;
    let mut opts: SectionOptions = options(
        [
            ("orbits", a.orbits.map(Value::from)),
            ("crossings", a.crossings.map(Value::from)),
            ("normal", a.normal.map(|n| json!(n))),
        ],
        &a.opts,
    )?;
    let bar = crate::progress::Bar::start("orbits of the section");
    opts.control = bar.control();
    let sec = poincare_section(&model, a.momentum, a.energy, &opts)?;
    drop(bar);
    if let Some(path) = &a.svg {
        let opts = a.figure.apply(PlotOptions::default());
        let mut files = Outputs::new();
        files.write(path, |tmp| poincare_section_svg(&sec, &[], tmp, &opts))?;
        files.commit()?;
    }
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
