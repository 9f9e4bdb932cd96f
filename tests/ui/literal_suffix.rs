use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    potential = mass * 9.81f32 * gamma.z + 2u8 * gamma.x,
)]
struct M {
    inertia: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {}
