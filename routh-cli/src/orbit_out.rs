//! Periodic orbits out: one JSON schema, CSV columns and tables for `routh orbit` and
//! `routh orbits`.
//!
//! JSON. A periodic orbit is the serde form of `routh::PeriodicOrbit` and a family the serde form
//! of `routh::OrbitFamily`, each with two more keys, `"routh"` (the class name) and `"format"`:
//! the document of Python's `to_json()`, so that `routh.from_json(text)` (and
//! `routh.PeriodicOrbit.from_json`, `routh.OrbitFamily.from_json`) reads what the CLI prints, and
//! Rust reads it with `serde_json::from_str::<routh::PeriodicOrbit>` (the two keys are ignored).
//! A family of `routh orbits` also says where it comes from: `origin` (`"lyapunov"`,
//! `"continued"`, `"period_doubled"`, `"switched"`), and `motion` (the steady motion, a
//! `SteadyMotion` document) and `mode` of a Lyapunov family, `parent` (the index of the family in
//! the same output) and `event` (the index of the period doubling or branch point among the
//! parent's events) of a period-doubled or switched one; `null` where they do not apply. A
//! family of `--continue --parameter NAME=LO..HI` (at a fixed energy, through a parameter) has
//! three keys more: `parameter_name` (NAME), `parameter` (NAME at each orbit, in the order of
//! `orbits`) and `event_parameter` (NAME at each event, in the order of `events`); the other
//! families do not have them.
//!
//! CSV. The columns of Python's `PeriodicOrbit.to_pandas()` (docs/python.md, "Export"):
//! `period, energy, p_psi, precession, body_turn, degenerate, stability_index, stability,
//! amplitude, omega1..3, gamma1..3` (the initial conditions `omega0`, `gamma0`),
//! `multiplier1_re, multiplier1_im, multiplier2_re, multiplier2_im`. A family adds in front `family, origin, parent, mode,
//! steady_gamma1..3, kind` and at the end `before, after`, as Python's `OrbitFamily.to_pandas()`
//! (`kind` is `orbit` for an orbit, else the event's kind): every orbit of every family, then
//! every event (their own section of rows, same columns). With `--parameter NAME=LO..HI`, two
//! columns at the end: `parameter_name` (NAME) and `parameter` (NAME at the orbit or the event).
//! Numbers in Rust's shortest round-trip form; an empty field where a column does not apply.

use crate::table::{num, vec3, Table};
use routh::{OrbitEvent, OrbitFamily, OrbitNonlinearReport, PeriodicOrbit, SteadyMotion};
use serde::Serialize;

/// The `"format"` of Python's JSON documents (`routh._export.FORMAT`).
pub const FORMAT: u32 = 1;

/// A result as a Python JSON document: `{"routh": CLASS, "format": 1, <its serde fields>}`.
#[derive(Serialize)]
pub struct Document<'a, T: Serialize> {
    routh: &'static str,
    format: u32,
    #[serde(flatten)]
    value: &'a T,
}

impl<'a, T: Serialize> Document<'a, T> {
    pub fn new(class: &'static str, value: &'a T) -> Self {
        Document {
            routh: class,
            format: FORMAT,
            value,
        }
    }
}

/// Where a family of `routh orbits` starts.
pub enum Origin {
    /// Born at a steady motion, of a mode.
    Lyapunov { motion: SteadyMotion, mode: usize },
    /// Continued through an orbit corrected from a guess.
    Continued,
    /// Born at the period doubling `event` (an index into its events) of the family `parent`.
    PeriodDoubled { parent: usize, event: usize },
    /// Crossing the family `parent` at its branch point `event` (an index into its events).
    Switched { parent: usize, event: usize },
}

impl Origin {
    pub fn name(&self) -> &'static str {
        match self {
            Origin::Lyapunov { .. } => "lyapunov",
            Origin::Continued => "continued",
            Origin::PeriodDoubled { .. } => "period_doubled",
            Origin::Switched { .. } => "switched",
        }
    }

    /// The family and event it was born at, for a period-doubled or switched family.
    pub fn parent(&self) -> Option<(usize, usize)> {
        match self {
            Origin::PeriodDoubled { parent, event } | Origin::Switched { parent, event } => {
                Some((*parent, *event))
            }
            Origin::Lyapunov { .. } | Origin::Continued => None,
        }
    }
}

/// A family of `routh orbits` with its origin.
pub struct Family {
    pub origin: Origin,
    pub family: OrbitFamily,
    /// For a family through a parameter (`--continue --parameter`): the parameter's name and
    /// values.
    pub along: Option<Along>,
}

/// The parameter along a family at a fixed energy (`routh orbits --continue --parameter`).
pub struct Along {
    /// NAME of `--parameter NAME=LO..HI` (a parameter of the model, or `momentum`).
    pub name: String,
    /// NAME at each orbit of the family, in the same order.
    pub parameter: Vec<f64>,
    /// NAME at each event of the family, in the same order.
    pub event_parameter: Vec<f64>,
}

/// The JSON document of a family of `routh orbits`.
#[derive(Serialize)]
struct FamilyDocument<'a> {
    routh: &'static str,
    format: u32,
    #[serde(flatten)]
    family: &'a OrbitFamily,
    origin: &'static str,
    motion: Option<Document<'a, SteadyMotion>>,
    mode: Option<usize>,
    parent: Option<usize>,
    event: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    parameter_name: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    parameter: Option<&'a [f64]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    event_parameter: Option<&'a [f64]>,
}

/// `routh orbit --json`.
pub fn orbit_json(o: &PeriodicOrbit) -> Result<String, serde_json::Error> {
    Ok(serde_json::to_string_pretty(&Document::new("PeriodicOrbit", o))? + "\n")
}

/// `routh orbit --nonlinear --json`: the report's serde form as a Python document.
pub fn nonlinear_json(r: &OrbitNonlinearReport) -> Result<String, serde_json::Error> {
    Ok(serde_json::to_string_pretty(&Document::new("OrbitNonlinearReport", r))? + "\n")
}

/// The columns `routh orbit --nonlinear --csv` adds to the orbit's.
const NONLINEAR_COLUMNS: &str = "rotation_number,twist,resonance,nonlinear,area_defect";

/// `routh orbit --nonlinear --csv`: the orbit's columns and the report's.
pub fn nonlinear_csv(r: &OrbitNonlinearReport) -> String {
    format!(
        "{ORBIT_COLUMNS},{NONLINEAR_COLUMNS}\n{},{},{},{},{},{}\n",
        orbit_fields(&r.orbit),
        r.rotation_number,
        r.twist,
        r.resonance.map_or("", |x| x.as_str()),
        r.verdict.as_str(),
        r.area_defect
    )
}

/// `routh orbit --nonlinear`: the orbit's table, then the verdict beyond the linear test.
pub fn nonlinear_table(r: &OrbitNonlinearReport) -> String {
    let mut t = Table::new(&["quantity", "value"]);
    for (name, value) in [
        ("rotation_number", format!("{:.12}", r.rotation_number)),
        ("twist", format!("{:+.9e}", r.twist)),
        (
            "resonance",
            r.resonance.map_or("none".to_string(), |x| x.to_string()),
        ),
        ("verdict", r.verdict.to_string()),
        ("why", r.reason.clone()),
    ] {
        t.row(vec![name.to_string(), value]);
    }
    format!(
        "{}\nbeyond linear (the Poincaré map's Birkhoff normal form to order three)\n{}",
        orbit_table(&r.orbit),
        t.render()
    )
}

/// `routh orbits --json`: an array of family documents.
pub fn families_json(families: &[Family]) -> Result<String, serde_json::Error> {
    let docs: Vec<FamilyDocument> = families
        .iter()
        .map(|f| {
            let (motion, mode) = match &f.origin {
                Origin::Lyapunov { motion, mode } => {
                    (Some(Document::new("SteadyMotion", motion)), Some(*mode))
                }
                _ => (None, None),
            };
            let (parent, event) = f.origin.parent().unzip();
            FamilyDocument {
                routh: "OrbitFamily",
                format: FORMAT,
                family: &f.family,
                origin: f.origin.name(),
                motion,
                mode,
                parent,
                event,
                parameter_name: f.along.as_ref().map(|a| a.name.as_str()),
                parameter: f.along.as_ref().map(|a| a.parameter.as_slice()),
                event_parameter: f.along.as_ref().map(|a| a.event_parameter.as_slice()),
            }
        })
        .collect();
    Ok(serde_json::to_string_pretty(&docs)? + "\n")
}

/// The columns of one orbit (Python's `PeriodicOrbit.to_pandas()`).
const ORBIT_COLUMNS: &str = "period,energy,p_psi,precession,body_turn,degenerate,\
stability_index,stability,amplitude,\
omega1,omega2,omega3,gamma1,gamma2,gamma3,\
multiplier1_re,multiplier1_im,multiplier2_re,multiplier2_im";

/// The fields of one orbit, in [`ORBIT_COLUMNS`].
fn orbit_fields(o: &PeriodicOrbit) -> String {
    let [m1, m2] = o.multipliers;
    format!(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
        o.period,
        o.energy,
        o.p_psi,
        o.precession,
        o.body_turn,
        o.degenerate,
        o.stability_index,
        o.stability,
        o.amplitude,
        o.omega0.x,
        o.omega0.y,
        o.omega0.z,
        o.gamma0.x,
        o.gamma0.y,
        o.gamma0.z,
        m1.re,
        m1.im,
        m2.re,
        m2.im
    )
}

/// `routh orbit --csv`: a header and one row.
pub fn orbit_csv(o: &PeriodicOrbit) -> String {
    format!("{ORBIT_COLUMNS}\n{}\n", orbit_fields(o))
}

/// `routh orbits --csv`: every orbit of every family, then every event (with
/// `parameter_name, parameter` at the end when a family is through a parameter).
pub fn families_csv(families: &[Family]) -> String {
    let swept = families.iter().any(|f| f.along.is_some());
    let mut s = format!(
        "family,origin,parent,mode,steady_gamma1,steady_gamma2,steady_gamma3,kind,{ORBIT_COLUMNS},before,after{}\n",
        if swept { ",parameter_name,parameter" } else { "" }
    );
    // `,NAME,value` of the orbit or event `j` of family `f` (empty fields for a family not
    // through a parameter), nothing when no family is.
    let tail = |f: &Family, values: fn(&Along) -> &[f64], j: usize| -> String {
        match &f.along {
            Some(a) => format!(",{},{}", a.name, values(a)[j]),
            None if swept => ",,".to_string(),
            None => String::new(),
        }
    };
    let prefix = |i: usize, f: &Family| -> String {
        match &f.origin {
            Origin::Lyapunov { motion, mode } => {
                let g = motion.gamma;
                format!("{i},lyapunov,,{mode},{},{},{}", g.x, g.y, g.z)
            }
            Origin::Continued => format!("{i},continued,,,,,"),
            Origin::PeriodDoubled { parent, .. } | Origin::Switched { parent, .. } => {
                format!("{i},{},{parent},,,,", f.origin.name())
            }
        }
    };
    for (i, f) in families.iter().enumerate() {
        let p = prefix(i, f);
        for (j, o) in f.family.orbits.iter().enumerate() {
            s.push_str(&format!(
                "{p},orbit,{},,{}\n",
                orbit_fields(o),
                tail(f, |a| &a.parameter, j)
            ));
        }
    }
    for (i, f) in families.iter().enumerate() {
        let p = prefix(i, f);
        for (j, e) in f.family.events.iter().enumerate() {
            s.push_str(&format!(
                "{p},{},{},{},{}{}\n",
                e.kind,
                orbit_fields(&e.orbit),
                e.before,
                e.after,
                tail(f, |a| &a.event_parameter, j)
            ));
        }
    }
    s
}

/// `routh orbit`'s table: the orbit's numbers, one per line.
pub fn orbit_table(o: &PeriodicOrbit) -> String {
    let mut t = Table::new(&["quantity", "value"]);
    let complex = |z: &routh::Complex<f64>| format!("{:+.9}{:+.9}i", z.re, z.im);
    for (name, value) in [
        ("period", format!("{:.12}", o.period)),
        ("energy", format!("{:.12}", o.energy)),
        ("p_psi", num(o.p_psi)),
        ("precession", num(o.precession)),
        ("body_turn", num(o.body_turn)),
        ("stability_index", format!("{:+.9}", o.stability_index)),
        ("stability", stability(o)),
        ("multiplier1", complex(&o.multipliers[0])),
        ("multiplier2", complex(&o.multipliers[1])),
        ("amplitude", num(o.amplitude)),
        ("omega0", vec3(&o.omega0)),
        ("gamma0", vec3(&o.gamma0)),
    ] {
        t.row(vec![name.to_string(), value]);
    }
    format!(
        "periodic orbit at p_psi = {}, E = {}\n{}",
        num(o.p_psi),
        num(o.energy),
        t.render()
    )
}

/// One family's block in `routh orbits`'s table: a title, at most `rows` orbits evenly spread
/// (the first and the last included), its events (`followed[j]`: the family started at event
/// `j`, if any).
pub fn family_table(i: usize, f: &Family, rows: usize, followed: &[(usize, usize)]) -> String {
    let fam = &f.family;
    let from = match &f.origin {
        Origin::Lyapunov { motion, mode } => format!(
            "from {} (E = {}), mode {mode}",
            vec3(&motion.gamma),
            num(motion.energy)
        ),
        Origin::Continued => match &f.along {
            Some(a) => format!(
                "continued through the corrected orbit over {} at E = {}",
                a.name,
                num(fam.orbits.first().map_or(f64::NAN, |o| o.energy))
            ),
            None => "continued through the corrected orbit".to_string(),
        },
        Origin::PeriodDoubled { parent, event } => format!(
            "period-doubled, born at event {event} of family {parent} (E = {})",
            num(fam.orbits.first().map_or(f64::NAN, |o| o.energy))
        ),
        Origin::Switched { parent, event } => {
            format!("switched, crossing family {parent} at its branch point (event {event})")
        }
    };
    let mut out = format!(
        "family {i}: {from}: {} orbits{}\n",
        fam.orbits.len(),
        fam.stop
            .as_ref()
            .map_or(String::new(), |s| format!(", ended: {s}"))
    );
    let step = fam.orbits.len().div_ceil(rows.max(1)).max(1);
    // The turn about the body axis only where it can be other than 0 (an axially symmetric
    // body: its orbits turn about e3, or are degenerate).
    let turns = fam
        .orbits
        .iter()
        .any(|o| o.body_turn != 0.0 || o.degenerate);
    let mut header = vec!["#"];
    if let Some(a) = &f.along {
        header.push(a.name.as_str());
    }
    header.extend(["E", "T", "precession"]);
    if turns {
        header.push("body_turn");
    }
    header.extend(["k", "stability"]);
    let mut t = Table::new(&header);
    for (j, o) in fam.orbits.iter().enumerate() {
        if j % step == 0 || j + 1 == fam.orbits.len() {
            let mut row = vec![j.to_string()];
            if let Some(a) = &f.along {
                row.push(num(a.parameter[j]));
            }
            row.extend([num(o.energy), num(o.period), num(o.precession)]);
            if turns {
                row.push(num(o.body_turn));
            }
            row.extend([num(o.stability_index), stability(o)]);
            t.row(row);
        }
    }
    out.push_str(&t.render());
    for (j, e) in fam.events.iter().enumerate() {
        out.push_str(&format!(
            "  {}{}\n",
            event_line(
                e,
                f.along
                    .as_ref()
                    .map(|a| (a.name.as_str(), a.event_parameter[j]))
            ),
            followed_note(j, followed)
        ));
    }
    out
}

/// The orbit's stability, "(degenerate)" after it when it is not isolated on its energy level
/// (its `k = 1` comes from the theorem, not from the monodromy).
fn stability(o: &PeriodicOrbit) -> String {
    if o.degenerate {
        format!("{} (degenerate)", o.stability)
    } else {
        o.stability.to_string()
    }
}

/// The event as `OrbitEvent`'s `Display` says it, or along a parameter `(NAME, s)` where it is:
/// `fold at NAME = s (E = …, T = …): before -> after`.
fn event_line(e: &OrbitEvent, at: Option<(&str, f64)>) -> String {
    match at {
        None => e.to_string(),
        Some((name, s)) => format!(
            "{} at {name} = {s:.12} (E = {:.12}, T = {:.10}): {} -> {}",
            e.kind, e.energy, e.orbit.period, e.before, e.after
        ),
    }
}

fn followed_note(j: usize, followed: &[(usize, usize)]) -> String {
    followed
        .iter()
        .find(|(event, _)| *event == j)
        .map_or(String::new(), |(_, fam)| {
            format!(" (followed: family {fam})")
        })
}
