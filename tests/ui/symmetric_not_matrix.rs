use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    potential = mass * g * com.dot(gamma),
)]
struct M {
    #[lagrangian(symmetric)]
    inertia: Matrix3<f64>,
    #[lagrangian(symmetric)]
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {}
