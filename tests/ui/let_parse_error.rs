use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    let j = inertia mass,
    kinetic = 0.5 * omega.dot(j * omega),
    potential = mass * g * com.dot(gamma),
)]
struct M {
    inertia: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {}
