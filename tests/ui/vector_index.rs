use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega) + 0.0 * omega[3] * omega[0],
    potential = mass * g * com[mass],
)]
struct M {
    inertia: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {}
