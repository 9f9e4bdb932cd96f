//! Certified completeness on the paper's bodies: the global search next to the interval proof.
//! Run: `cargo run --release --example certify`.
//!
//! For each body, `steady_motions` and `certify::steady_motions_certified` side by side, with what
//! the proof cost. A body with a symmetry has circles of steady motions, which no interval Newton
//! can isolate: there the certificate names the undecided tubes instead of claiming a count. The
//! certified search needs the interval tape that `#[derive(Lagrangian)]` emits: the six bodies are
//! declared below.

use routh::certify::{steady_motions_certified, CertifyOptions};
use routh::fluid::kirchhoff_lagrangian;
use routh::{steady_motions, Lagrangian, Matrix3, Routhian, Vector3};
use std::error::Error;
use std::time::Instant;

/// A heavy rigid body about a fixed point with principal moments `inertia` and its centre of mass
/// `com` off the axes: an asymmetric heavy top, `L = ½(diag(I)ω, ω) − m g (r_c, γ)`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(diag(inertia) * omega),
    potential = mass * g * com.dot(gamma),
)]
pub struct AsymmetricTop {
    /// Principal moments of inertia about the fixed point.
    pub inertia: Vector3<f64>,
    /// Centre of mass in the body frame.
    pub com: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}

/// The Lagrange top about its fixed point: `L = ½(A₁(ω₁² + ω₂²) + Cω₃²) − m g l γ₃`, the centre
/// of mass at distance `l` from the fixed point on the symmetry axis `e₃`.
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * (a1 * (omega.x * omega.x + omega.y * omega.y) + c * omega.z * omega.z),
    potential = mass * g * l * gamma.z,
)]
pub struct LagrangeTop {
    /// Transverse moment of inertia about the fixed point, `A₁`.
    pub a1: f64,
    /// Axial moment of inertia, `C`.
    pub c: f64,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
    /// Distance `l` from the fixed point to the centre of mass.
    pub l: f64,
}

/// A heavy gyrostat, paper Example 1: `L = ½(Iω, ω) + (K + Bγ, ω) − m g (r_c, γ)` (35).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    linear = (rotor + coupling * gamma).dot(omega),
    potential = mass * g * com.dot(gamma),
)]
pub struct Gyrostat {
    /// Inertia tensor `I` about the fixed point (symmetric: only its upper triangle is read).
    #[lagrangian(symmetric)]
    pub inertia: Matrix3<f64>,
    /// Constant part `K` of `a(γ)` (the rotor's momentum).
    pub rotor: Vector3<f64>,
    /// Linear part `B` of `a(γ) = K + Bγ`.
    pub coupling: Matrix3<f64>,
    /// Centre of mass `r_c` in the body frame.
    pub com: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}

impl Gyrostat {
    /// The Kelvin gyrostat of the example `gyrostat`: `I = diag(2, 2.5, 1.5)`, `K = 3.5 e₃`,
    /// centre of mass `0.1 e₃`, `m = 1`, `g = 9.81`.
    pub fn kelvin() -> Self {
        Gyrostat {
            inertia: Matrix3::from_diagonal(&Vector3::new(2.0, 2.5, 1.5)),
            rotor: Vector3::new(0.0, 0.0, 3.5),
            coupling: Matrix3::zeros(),
            com: Vector3::new(0.0, 0.0, 0.1),
            mass: 1.0,
            g: 9.81,
        }
    }

    /// The same body with `a(γ) = Bγ`, `B` not symmetric.
    pub fn coupled() -> Self {
        Gyrostat {
            rotor: Vector3::zeros(),
            coupling: Matrix3::new(1.0, 0.8, 0.0, -0.8, 0.4, 0.0, 0.0, 0.0, 2.0),
            ..Gyrostat::kelvin()
        }
    }
}

/// A heavy ellipsoid on a smooth horizontal plane, paper Example 2: `C₃` is the support function
/// (errata E6), `U = +m g C₃` (errata E2), the kinetic energy (49).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    /// Central inertia tensor `I` (principal axes along the semi-axes).
    pub inertia: Matrix3<f64>,
    /// Semi-axes `(a₁, a₂, a₃)`.
    pub semi_axes: Vector3<f64>,
    /// Position `c₀` of the ellipsoid's centre relative to the centre of mass.
    pub offset: Vector3<f64>,
    /// Mass `m`.
    pub mass: f64,
    /// Gravity `g`.
    pub g: f64,
}

impl Ellipsoid {
    /// A uniform solid ellipsoid of mass 1 with semi-axes `a` (`g = 9.81`), its centre at `offset`
    /// from the centre of mass.
    pub fn uniform(a: Vector3<f64>, offset: Vector3<f64>) -> Self {
        let (a1, a2, a3) = (a.x * a.x, a.y * a.y, a.z * a.z);
        Ellipsoid {
            inertia: Matrix3::from_diagonal(&(1.0 / 5.0 * Vector3::new(a2 + a3, a1 + a3, a1 + a2))),
            semi_axes: a,
            offset,
            mass: 1.0,
            g: 9.81,
        }
    }
}

/// A rigid body in an ideal fluid, paper Example 3: `L(ω, γ) = ½(Aω, ω) + (Λγ, ω) − ½(Πγ, γ)`
/// with the matrices of [`kirchhoff_lagrangian`] (errata E3).
#[derive(Lagrangian, Debug, Clone)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(a_kin * omega),
    linear = (lin * gamma).dot(omega),
    potential = 0.5 * gamma.dot(pot * gamma),
)]
pub struct FluidBody {
    /// `A = a − bᵀc⁻¹b`.
    pub a_kin: Matrix3<f64>,
    /// `Λ = k bᵀc⁻¹`.
    pub lin: Matrix3<f64>,
    /// `Π = k²c⁻¹`.
    pub pot: Matrix3<f64>,
}

fn row<M: Routhian>(name: &str, model: &M, p: f64) -> Result<(), Box<dyn Error>> {
    let t0 = Instant::now();
    let searched = steady_motions(model, p)?;
    let t_search = t0.elapsed();
    let cert = steady_motions_certified(model, p, &CertifyOptions::default())?;
    let circles = searched.iter().filter(|s| !s.isolated).count();
    println!(
        "{name:<34} {p:>5} {:>8} {:>9} {:>9} {:>8} {:>8} {:>10.2} {:>10.2}",
        format!("{}+{}c", searched.len() - circles, circles),
        if cert.complete { "yes" } else { "no" },
        cert.motions.len(),
        cert.undecided.len(),
        cert.boxes,
        t_search.as_secs_f64() * 1e3,
        cert.elapsed.as_secs_f64() * 1e3,
    );
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    println!(
        "{:<34} {:>5} {:>8} {:>9} {:>9} {:>8} {:>8} {:>10} {:>10}",
        "body",
        "p_ψ",
        "searched",
        "complete",
        "certified",
        "undecided",
        "boxes",
        "search ms",
        "proof ms"
    );
    let asymmetric = AsymmetricTop {
        inertia: Vector3::new(1.0, 2.0, 3.0),
        com: Vector3::new(0.0, 0.0, 1.0),
        mass: 1.0,
        g: 1.0,
    };
    for p in [0.5, 2.5, 3.5] {
        row("heavy asymmetric top (1, 2, 3)", &asymmetric, p)?;
    }
    let lagrange = LagrangeTop {
        a1: 1.0,
        c: 1.25,
        mass: 1.0,
        g: 1.0,
        l: 1.0,
    };
    for p in [1.0, 1.55, 3.0] {
        row("Lagrange top (1, 1.25), mgl = 1", &lagrange, p)?;
    }
    for p in [0.0, 1.0, 3.0] {
        row("Kelvin gyrostat (Example 1)", &Gyrostat::kelvin(), p)?;
        row("gyrostat a(γ) = Bγ (Example 1)", &Gyrostat::coupled(), p)?;
    }
    // An egg (centre of mass 0.2 below the geometric centre) and a centred triaxial body.
    let spheroid = Ellipsoid::uniform(Vector3::new(1.0, 1.0, 2.0), Vector3::new(0.0, 0.0, 0.2));
    let triaxial = Ellipsoid::uniform(Vector3::new(0.8, 1.2, 2.0), Vector3::zeros());
    for p in [0.0, 1.0, 4.0] {
        row("triaxial ellipsoid (Example 2)", &triaxial, p)?;
        row("spheroid (Example 2)", &spheroid, p)?;
    }
    // A screw-like body without symmetry: Kirchhoff's matrices a, b, c (53), impulse k = 1.
    let f = kirchhoff_lagrangian(
        Matrix3::new(1.2, 0.05, 0.0, 0.05, 1.0, 0.02, 0.0, 0.02, 0.5),
        Matrix3::new(0.2, 0.05, 0.0, 0.0, 0.1, 0.03, 0.02, 0.0, 0.3),
        Matrix3::new(3.0, 0.1, 0.0, 0.1, 2.5, 0.0, 0.0, 0.0, 1.5),
        1.0,
    )?;
    let chiral = FluidBody {
        a_kin: f.kinetic,
        lin: f.linear,
        pot: f.potential,
    };
    for p in [0.0, 1.0] {
        row("chiral body in a fluid (Example 3)", &chiral, p)?;
    }
    println!(
        "\nsearched: isolated + circles (c) from the global search; complete: the proof covers"
    );
    println!("the sphere, so the certified motions are all of them; undecided: regions (tubes");
    println!("around circles, degenerate points) the proof could not decide.");
    Ok(())
}
