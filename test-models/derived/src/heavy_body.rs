//! The heavy body of `examples/periodic.rs` (its planar swings, a body with the centre of mass
//! off the axes, a Poincaré section), declared as there (`tests/examples_models.rs` keeps the two
//! in step), and the helpers the example prints with, for `tests/examples_facts.rs`.

use std::error::Error;
use std::f64::consts::PI;

use routh::{steady_motions, Lagrangian, OrbitFamily, OrbitStability, SteadyMotion, Vector3};

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
    pub fn on_axis(a: f64, b: f64, c: f64, mgl: f64) -> Self {
        HeavyBody {
            inertia: Vector3::new(a, b, c),
            mgr: Vector3::new(0.0, 0.0, mgl),
        }
    }
}

/// The hanging position at `p_ψ = 0`: the steady motion of least energy.
pub fn hanging(body: &HeavyBody) -> Result<SteadyMotion, Box<dyn Error>> {
    steady_motions(body, 0.0)?
        .into_iter()
        .min_by(|a, b| a.energy.total_cmp(&b.energy))
        .ok_or_else(|| "no steady motion at p_ψ = 0".into())
}

/// The complete elliptic integral `K(m)` by the arithmetic–geometric mean.
pub fn elliptic_k(m: f64) -> f64 {
    let (mut a, mut g) = (1.0f64, (1.0 - m).sqrt());
    for _ in 0..40 {
        (a, g) = (0.5 * (a + g), (a * g).sqrt());
    }
    PI / (2.0 * a)
}

/// The runs of equal stability along a family, `(E_from, E_to, verdict)`, their ends at the
/// family's events (or half-way between orbits where none was located).
pub fn stability_intervals(f: &OrbitFamily) -> Vec<(f64, f64, OrbitStability)> {
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
