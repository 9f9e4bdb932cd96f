use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    potential = mass * g * com.dot(gamma),
    potential = mass * g * gamma.z,
)]
struct M {
    inertia: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {}
