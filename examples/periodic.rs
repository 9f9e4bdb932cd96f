//! Periodic motions of a heavy asymmetric body (docs/method.md §11): the planar swings of the body
//! hanging from a fixed point, their period against the energy (the pendulum's `4K(m)/ω₀`), and
//! the intervals of energy where a swing is stable against out-of-plane perturbations — the
//! classical stability diagram of planar oscillations, here the stability index `k` of the
//! Lyapunov family against `E`. Then the same family for a body whose centre of mass is off the
//! principal axes, which loses stability by period doubling, and a Poincaré section of the heavy
//! asymmetric top showing islands of regular motion around its stable periodic orbits.
//!
//! Run with `cargo run --release --example periodic`. Figures go to `out/periodic/`.

#[path = "common/mod.rs"]
mod common;

use std::error::Error;
use std::f64::consts::PI;
use std::time::Instant;

use common::{fmt_vec, num};

use routh::plot::{self, Overlay, PlotOptions};
use routh::{
    axial_symmetry, continue_orbit, lyapunov_family, orbit_crossings, orbit_path,
    period_doubled_family, poincare_section, steady_motions, switch_branch, Lagrangian,
    OrbitEventKind, OrbitFamily, OrbitOptions, OrbitStability, PeriodicOrbit, SectionOptions,
    SteadyMotion, Vector3,
};

// The body, declared here: `#[derive(Lagrangian)]` differentiates L at build time, the Jacobian
// of the equations of motion (the variational equations of the monodromy) included.
/// A heavy rigid body about a fixed point: principal moments `J = diag(A, B, C)` and the weight's
/// moment arm `m g r` (the centre of mass `r` in the body frame times `m g`),
/// `L = ½(Jω, ω) − m g (r, γ)`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = mgr.dot(gamma),
)]
pub struct HeavyBody {
    /// Principal moments of inertia about the fixed point, `(A, B, C)`.
    pub inertia: Vector3<f64>,
    /// `m g r`: weight times the centre of mass in the body frame.
    pub mgr: Vector3<f64>,
}

impl HeavyBody {
    /// `J = diag(a, b, c)` with the centre of mass on `e₃` at `m g l = mgl`.
    fn on_axis(a: f64, b: f64, c: f64, mgl: f64) -> Self {
        HeavyBody {
            inertia: Vector3::new(a, b, c),
            mgr: Vector3::new(0.0, 0.0, mgl),
        }
    }
}

/// The hanging position at `p_ψ = 0`: the steady motion of least energy.
fn hanging(body: &HeavyBody) -> Result<SteadyMotion, Box<dyn Error>> {
    steady_motions(body, 0.0)?
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .ok_or_else(|| "no steady motion at p_ψ = 0".into())
}

/// The complete elliptic integral `K(m)` by the arithmetic–geometric mean.
fn elliptic_k(m: f64) -> f64 {
    let (mut a, mut g) = (1.0f64, (1.0 - m).sqrt());
    for _ in 0..40 {
        (a, g) = (0.5 * (a + g), (a * g).sqrt());
    }
    PI / (2.0 * a)
}

/// The runs of equal stability along a family, `(E_from, E_to, verdict)`, their ends at the
/// family's events (or half-way between orbits where none was located).
fn stability_intervals(f: &OrbitFamily) -> Vec<(f64, f64, OrbitStability)> {
    let mut out: Vec<(f64, f64, OrbitStability)> = Vec::new();
    let mut start = f.orbits[0].energy;
    for w in f.orbits.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        if a.stability == b.stability {
            continue;
        }
        let (lo, hi) = (a.energy.min(b.energy), a.energy.max(b.energy));
        let at = f
            .events
            .iter()
            .map(|e| e.energy)
            .find(|&e| e >= lo - 1e-9 && e <= hi + 1e-9)
            .unwrap_or(0.5 * (a.energy + b.energy));
        out.push((start, at, a.stability));
        start = at;
    }
    let last = f.orbits.last().expect("a family has an orbit");
    out.push((start, last.energy, last.stability));
    out
}

/// Prints the family's events and its intervals of stability; `amplitude(E)` is the swing's
/// amplitude in degrees where known.
fn print_family(f: &OrbitFamily, amplitude: &dyn Fn(f64) -> Option<f64>) {
    let amp = |e: f64| amplitude(e).map_or_else(|| "—".into(), |a| format!("{a:.2}°"));
    println!(
        "  {} orbits, E from {:.6} to {:.6}, T from {:.6} to {:.6}; ended: {}",
        f.orbits.len(),
        f.orbits[0].energy,
        f.orbits.last().unwrap().energy,
        f.orbits[0].period,
        f.orbits.last().unwrap().period,
        f.stop
            .as_ref()
            .map_or_else(|| "range reached".into(), |s| s.to_string())
    );
    println!(
        "\n  {:<16} {:>14} {:>9} {:>12}  stability",
        "event", "E", "amplitude", "T"
    );
    for e in &f.events {
        println!(
            "  {:<16} {:>14.9} {:>9} {:>12.6}  {} → {}",
            e.kind.to_string(),
            e.energy,
            amp(e.energy),
            e.orbit.period,
            e.before,
            e.after
        );
    }
    let (kmin, kmax) = f
        .orbits
        .iter()
        .map(|o| o.stability_index)
        .fold((f64::MAX, f64::MIN), |(a, b), k| (a.min(k), b.max(k)));
    println!("\n  k from {kmin:.6} to {kmax:.3e}");
    println!("  intervals of the family (in the order of continuation):");
    for (a, b, v) in stability_intervals(f) {
        let what = match v {
            OrbitStability::Elliptic => "elliptic: stable against out-of-plane perturbations",
            OrbitStability::Hyperbolic => "hyperbolic: unstable",
            OrbitStability::InverseHyperbolic => "inverse hyperbolic: unstable",
            OrbitStability::Parabolic => "parabolic",
        };
        println!(
            "    E ∈ [{:>10.6}, {:>10.6}]  amplitude {:>9} … {:>9}  {what}",
            a,
            b,
            amp(a),
            amp(b)
        );
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let start = Instant::now();
    let out = common::out_dir("periodic")?;
    let mut written = Vec::new();

    // --- Planar swings of a body with its centre of mass on a principal axis ------------------
    let (a, b, c, mgl) = (1.0, 2.0, 3.0, 1.5);
    let body = HeavyBody::on_axis(a, b, c, mgl);
    println!("Periodic motions of a heavy asymmetric body — routh, docs/method.md §11");
    println!("======================================================================");
    println!(
        "L = ½(Jω, ω) − m g (r, γ),  J = diag({}, {}, {}),  m g r = {}",
        num(a, 3),
        num(b, 3),
        num(c, 3),
        fmt_vec(&body.mgr)
    );
    let hang = hanging(&body)?;
    println!(
        "\nHanging position at p_ψ = 0: γ = {}, E = {}",
        fmt_vec(&hang.gamma),
        num(hang.energy, 9)
    );
    // The swing about e₁ (the faster mode, A < B): a pendulum of frequency ω₀ = √(mgl/A) in the
    // plane γ₁ = 0, rest at amplitude θ₀ where E = −mgl cos θ₀, period 4K(sin²(θ₀/2))/ω₀.
    let w0 = (mgl / a).sqrt();
    let amplitude = |e: f64| {
        let c = -e / mgl;
        (c.abs() <= 1.0).then(|| c.acos().to_degrees())
    };
    let pendulum = |e: f64| 4.0 * elliptic_k(0.5 * (1.0 + e / mgl)) / w0;
    let opts = OrbitOptions::default()
        .with_energy_bounds(-mgl, 0.999 * mgl)
        .with_max_orbits(400)
        .with_max_step(0.05);
    let t = Instant::now();
    let swings = lyapunov_family(&body, &hang, 0, &opts)?;
    println!(
        "\nLyapunov family of the swing about e₁ (mode 0, ω₀ = {}), p_ψ = 0, computed in {:.2} s:",
        num(w0, 6),
        t.elapsed().as_secs_f64()
    );
    print_family(&swings, &amplitude);
    let worst = swings
        .orbits
        .iter()
        .map(|o| (o.period - pendulum(o.energy)).abs() / pendulum(o.energy))
        .fold(0.0f64, f64::max);
    let planar = swings
        .orbits
        .iter()
        .map(|o| o.gamma0.x.abs().max(o.omega0.y.abs()).max(o.omega0.z.abs()))
        .fold(0.0f64, f64::max);
    println!(
        "\n  check: the periods against the pendulum's 4K(m)/ω₀: largest relative difference {worst:.1e}; \
         out of the plane γ₁ = 0 by at most {planar:.1e}"
    );

    let title = format!(
        "planar swings about e₁, J = diag({}, {}, {}), mgl = {}",
        num(a, 3),
        num(b, 3),
        num(c, 3),
        num(mgl, 3)
    );
    let path = out.join("swing_e1_stability.svg");
    plot::orbit_family_svg(
        &swings,
        &path,
        &PlotOptions {
            title: format!("{title}: stability index"),
            x_label: "energy E".into(),
            y_label: "stability index k".into(),
            ..PlotOptions::default()
        },
    )?;
    written.push(path);
    let e_lo = swings.orbits[0].energy;
    let e_hi = swings
        .orbits
        .iter()
        .map(|o| o.energy)
        .fold(f64::MIN, f64::max);
    let closed: Vec<(f64, f64)> = (0..=300)
        .map(|i| {
            let e = e_lo + (e_hi - e_lo) * i as f64 / 300.0;
            (e, pendulum(e))
        })
        .collect();
    let path = out.join("swing_e1_periods.svg");
    plot::orbit_periods_svg(
        &swings,
        &path,
        &PlotOptions {
            title: format!("{title}: period"),
            x_label: "energy E".into(),
            y_label: "period T".into(),
            overlays: vec![Overlay {
                label: "pendulum 4K(m)/ω₀".into(),
                points: closed,
            }],
            ..PlotOptions::default()
        },
    )?;
    written.push(path);

    // The swing about e₂ (mode 1, the slower one): a pendulum of frequency √(mgl/B) in γ₂ = 0.
    let t = Instant::now();
    let swings2 = lyapunov_family(&body, &hang, 1, &opts)?;
    println!(
        "\nLyapunov family of the swing about e₂ (mode 1, ω₀ = {}), p_ψ = 0, computed in {:.2} s:",
        num((mgl / b).sqrt(), 6),
        t.elapsed().as_secs_f64()
    );
    print_family(&swings2, &amplitude);
    let (kmin, at) = swings2
        .orbits
        .iter()
        .map(|o| (o.stability_index, o.energy))
        .fold((f64::MAX, 0.0), |m, x| if x.0 < m.0 { x } else { m });
    println!(
        "  k comes down to {kmin:.6} near E = {at:.3} and turns back without crossing −1: a swing \
         about a principal axis is symmetric under a half-period shift and a reflection, so its \
         monodromy is a square, k = 2k½² − 1 ≥ −1, and it cannot double its period."
    );
    let path = out.join("swing_e2_stability.svg");
    plot::orbit_family_svg(
        &swings2,
        &path,
        &PlotOptions {
            title: format!(
                "planar swings about e₂, J = diag({}, {}, {}), mgl = {}: stability index",
                num(a, 3),
                num(b, 3),
                num(c, 3),
                num(mgl, 3)
            ),
            x_label: "energy E".into(),
            y_label: "stability index k".into(),
            ..PlotOptions::default()
        },
    )?;
    written.push(path);

    // --- The centre of mass off the principal axes: period doublings ----------------------------
    let off = HeavyBody {
        inertia: Vector3::new(1.0, 3.0, 6.0),
        mgr: Vector3::new(0.4, 0.3, 1.5),
    };
    println!(
        "\nThe centre of mass off the axes: J = diag(1, 3, 6), m g r = {}",
        fmt_vec(&off.mgr)
    );
    let hang_off = hanging(&off)?;
    let t = Instant::now();
    let opts_off = OrbitOptions::default().with_max_orbits(120);
    let wobbles = lyapunov_family(&off, &hang_off, 0, &opts_off)?;
    println!(
        "Lyapunov family of mode 0 from the hanging position γ = {}, computed in {:.2} s:",
        fmt_vec(&hang_off.gamma),
        t.elapsed().as_secs_f64()
    );
    print_family(&wobbles, &|_| None);
    let path = out.join("offaxis_stability.svg");
    plot::orbit_family_svg(
        &wobbles,
        &path,
        &PlotOptions {
            title: "centre of mass off the axes: stability index of mode 0".into(),
            x_label: "energy E".into(),
            y_label: "stability index k".into(),
            ..PlotOptions::default()
        },
    )?;
    written.push(path);
    // The family of orbits of twice the period born at the first period doubling.
    if let Some(pd) = wobbles
        .events
        .iter()
        .find(|e| e.kind == OrbitEventKind::PeriodDoubling)
    {
        let doubled = period_doubled_family(&off, pd, &OrbitOptions::default().with_max_orbits(6))?;
        let o = doubled.orbits.last().ok_or("no doubled orbit")?;
        println!(
            "\n  born at the period doubling at E = {:.6} (T = {:.6}): orbits of period {:.6} ≈ 2T, \
             the last at E = {:.6}, k = {:+.6} ({})",
            pd.energy, pd.orbit.period, o.period, o.energy, o.stability_index, o.stability
        );
    }
    // Some of its orbits on the sphere of γ, seen from outside the sphere above the hanging
    // position γ_s (the viewer on the ray through γ_s).
    // Seven orbits evenly spread in energy (the continuation crowds its orbits near the separatrix).
    let (e0, e1) = (
        wobbles.orbits[0].energy,
        wobbles
            .orbits
            .iter()
            .map(|o| o.energy)
            .fold(f64::MIN, f64::max),
    );
    let paths = (1..=7)
        .filter_map(|j| {
            let e = e0 + (e1 - e0) * j as f64 / 7.5;
            wobbles
                .orbits
                .iter()
                .min_by(|a, b| (a.energy - e).abs().total_cmp(&(b.energy - e).abs()))
        })
        .map(|o| orbit_path(&off, o, 400))
        .collect::<Result<Vec<_>, _>>()?;
    let path = out.join("offaxis_orbits_on_sphere.svg");
    plot::orbits_on_sphere_svg(
        &paths,
        hang_off.gamma,
        &path,
        &PlotOptions {
            title: "mode-0 orbits on the sphere of γ".into(),
            width: 800,
            height: 600,
            ..PlotOptions::default()
        },
    )?;
    written.push(path);

    // --- Branch switching: the family crossing the swings about e₁ ------------------------------
    if let Some(bp) = swings
        .events
        .iter()
        .find(|e| e.kind == OrbitEventKind::BranchPoint)
    {
        let crossing = switch_branch(&body, bp, &OrbitOptions::default().with_max_orbits(40))?;
        let off_plane = crossing
            .orbits
            .iter()
            .map(|o| o.gamma0.x.abs().max(o.omega0.y.abs()))
            .fold(0.0f64, f64::max);
        println!(
            "\n  switch_branch at the branch point at E = {:.9}: {} orbits of the crossing family, \
             E from {:.6} to {:.6}, out of the plane γ₁ = 0 by up to {:.3}",
            bp.energy,
            crossing.orbits.len(),
            crossing
                .orbits
                .iter()
                .map(|o| o.energy)
                .fold(f64::MAX, f64::min),
            crossing
                .orbits
                .iter()
                .map(|o| o.energy)
                .fold(f64::MIN, f64::max),
            off_plane
        );
    }

    lagrange_top(&out, &mut written)?;

    // --- A Poincaré section of the heavy asymmetric top ---------------------------------------
    // At E = 0.8 the swing about e₁ (amplitude 122°) is still elliptic: an island around it,
    // chains of smaller islands, and a chaotic sea. The plane γ₂ = 0 is crossed by that swing
    // (it lies in γ₁ = 0) once a period, upwards.
    let e_s = 0.8;
    let normal = Vector3::new(0.0, 1.0, 0.0);
    let sopts = SectionOptions::default()
        .with_normal(normal)
        .with_size(50, 200);
    let t = Instant::now();
    let section = poincare_section(&body, 0.0, e_s, &sopts)?;
    let crossings: usize = section.orbits.iter().map(|o| o.points.len()).sum();
    println!(
        "\nPoincaré section at p_ψ = 0, E = {} (plane γ₂ = 0): {} orbits, {crossings} crossings in {:.2} s",
        num(e_s, 6),
        section.orbits.len(),
        t.elapsed().as_secs_f64()
    );
    // The swing about e₁ at the section's energy: its crossings are fixed points of the map.
    let o = orbit_at(&body, &swings, e_s)?;
    let fixed = orbit_crossings(&body, &o, &sopts)?;
    let shown: Vec<String> = fixed
        .iter()
        .map(|p| format!("(θ, M_n) = ({:.6}, {:+.1e})", p[0], p[1]))
        .collect();
    println!(
        "  swing about e₁ at E = {}: T = {:.6}, k = {:+.6} ({}), fixed point {}",
        num(o.energy, 6),
        o.period,
        o.stability_index,
        o.stability,
        shown.join(", ")
    );
    let path = out.join("section.svg");
    plot::poincare_section_svg(
        &section,
        &fixed,
        &path,
        &PlotOptions {
            title: format!(
                "heavy asymmetric top J = diag({}, {}, {}), mgl = {}: Poincaré section",
                num(a, 3),
                num(b, 3),
                num(c, 3),
                num(mgl, 3)
            ),
            ..PlotOptions::default()
        },
    )?;
    written.push(path);

    println!("\nFigures:");
    for p in &written {
        println!("  {}", p.display());
    }
    println!("Done in {:.2} s.", start.elapsed().as_secs_f64());
    Ok(())
}

/// The README's Lagrange top (A₁ = A₂ = 1, C = 1.25, mgl = 1): an axially symmetric body, whose
/// periodic motions are periodic modulo both turns (docs/method.md §11a). At p_ψ = 0 hanging,
/// its Lyapunov family is its planar swings (the two frequencies are equal by the symmetry),
/// each a pendulum, degenerate (the body is integrable); at p_ψ = 3 the sleeping top's two modes
/// are regular precessions, isolated on their energy level, with a stability index.
fn lagrange_top(
    out: &std::path::Path,
    written: &mut Vec<std::path::PathBuf>,
) -> Result<(), Box<dyn Error>> {
    let (a1, c, mgl) = (1.0, 1.25, 1.0);
    let top = HeavyBody {
        inertia: Vector3::new(a1, a1, c),
        mgr: Vector3::new(0.0, 0.0, mgl),
    };
    println!(
        "\nThe Lagrange top A₁ = A₂ = {}, C = {}, mgl = {} (axially symmetric: {})",
        num(a1, 3),
        num(c, 3),
        num(mgl, 3),
        axial_symmetry(&top)
    );
    let hang = hanging(&top)?;
    let opts = OrbitOptions::default()
        .with_energy_bounds(-mgl, 0.95 * mgl)
        .with_max_orbits(200);
    let swings = lyapunov_family(&top, &hang, 0, &opts)?;
    let w0 = (mgl / a1).sqrt();
    let worst = swings
        .orbits
        .iter()
        .map(|o| {
            let exact = 4.0 * elliptic_k(0.5 * (1.0 + o.energy / mgl)) / w0;
            (o.period - exact).abs() / exact
        })
        .fold(0.0f64, f64::max);
    println!(
        "  p_ψ = 0, hanging: {} planar swings up to E = {:.4}, all degenerate: {}, events: {}; \
         periods against 4K(m)/ω₀: largest relative difference {worst:.1e}",
        swings.orbits.len(),
        swings.orbits.last().map_or(f64::NAN, |o| o.energy),
        swings.orbits.iter().all(|o| o.degenerate),
        swings.events.len()
    );
    let p_psi = 3.0;
    let sleeping = steady_motions(&top, p_psi)?
        .into_iter()
        .find(|s| s.gamma.z > 0.999)
        .ok_or("no sleeping top at p_ψ = 3")?;
    let mut families = Vec::new();
    for mode in 0..2 {
        let f = lyapunov_family(
            &top,
            &sleeping,
            mode,
            &OrbitOptions::default()
                .with_energy_bounds(sleeping.energy - 1.0, sleeping.energy + 1.0)
                .with_max_orbits(150),
        )?;
        let first = &f.orbits[0];
        println!(
            "  p_ψ = {p_psi}, sleeping (E = {:.6}), mode {mode}: {} orbits (regular precessions, \
             degenerate: {}), T from {:.6}, k from {:+.6}; events: {}; ended: {}",
            sleeping.energy,
            f.orbits.len(),
            f.orbits.iter().any(|o| o.degenerate),
            first.period,
            first.stability_index,
            f.events
                .iter()
                .map(|e| format!("{} at E = {:.9}", e.kind, e.energy))
                .collect::<Vec<_>>()
                .join(", "),
            f.stop
                .as_ref()
                .map_or_else(|| "range reached".into(), |s| s.to_string())
        );
        families.push(f);
    }
    for (mode, f) in families.iter().enumerate() {
        let path = out.join(format!("lagrange_top_p3_mode{mode}.svg"));
        plot::orbit_family_svg(
            f,
            &path,
            &PlotOptions {
                title: format!(
                    "sleeping Lagrange top, p_ψ = {p_psi}: mode {mode}, stability index"
                ),
                x_label: "energy E".into(),
                y_label: "stability index k".into(),
                ..PlotOptions::default()
            },
        )?;
        written.push(path);
    }
    Ok(())
}

/// The orbit of the family at energy `e`: the family's orbit nearest in energy, continued to `e`.
fn orbit_at(body: &HeavyBody, f: &OrbitFamily, e: f64) -> Result<PeriodicOrbit, Box<dyn Error>> {
    let near = f
        .orbits
        .iter()
        .min_by(|a, b| (a.energy - e).abs().total_cmp(&(b.energy - e).abs()))
        .ok_or("empty family")?;
    if (near.energy - e).abs() <= 1e-12 {
        return Ok(near.clone());
    }
    let (lo, hi) = if near.energy < e {
        (near.energy - 1e-3, e)
    } else {
        (e, near.energy + 1e-3)
    };
    let g = continue_orbit(body, near, (lo, hi), &OrbitOptions::default())?;
    g.orbits
        .iter()
        .min_by(|a, b| (a.energy - e).abs().total_cmp(&(b.energy - e).abs()))
        .cloned()
        .ok_or_else(|| "no orbit at the section's energy".into())
}
