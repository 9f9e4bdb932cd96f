use routh::{Lagrangian, Matrix3, Routhian, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    linear = (rotor + coupling * gamma).dot(omega),
    potential = mass * g * com.dot(gamma),
)]
pub struct Gyrostat {
    pub inertia: Matrix3<f64>,
    pub rotor: Vector3<f64>,
    pub coupling: Matrix3<f64>,
    pub com: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}

#[derive(Lagrangian)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = (gamma.dot(d * gamma)).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(inertia * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    pub inertia: Matrix3<f64>,
    pub semi_axes: Vector3<f64>,
    pub offset: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}

fn main() {
    let m = Gyrostat {
        inertia: Matrix3::new(2.0, 0.1, 0.0, 0.1, 3.0, 0.2, 0.0, 0.2, 4.0),
        rotor: Vector3::new(0.1, 0.2, 0.3),
        coupling: Matrix3::identity() * 0.1,
        com: Vector3::new(0.0, 0.1, 1.0),
        mass: 1.0,
        g: 9.81,
    };
    let w = Vector3::new(0.3, -0.2, 1.0);
    let gm = Vector3::new(0.0, 0.6, 0.8);
    println!("L = {}", m.lagrangian(&w, &gm));
    println!("E = {}", m.energy(&w, &gm));
    println!("bundle = {:?}", m.bundle(&w, &gm, 1.5));
    let e = Ellipsoid {
        inertia: Matrix3::from_diagonal(&Vector3::new(1.0, 2.0, 3.0)),
        semi_axes: Vector3::new(1.0, 2.0, 3.0),
        offset: Vector3::new(0.0, 0.0, 0.1),
        mass: 1.0,
        g: 9.81,
    };
    println!(
        "Ell L = {} R = {}",
        e.lagrangian(&w, &gm),
        e.routhian(&w, &gm, 1.0)
    );
}
