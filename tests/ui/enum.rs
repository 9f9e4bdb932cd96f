use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(omega),
)]
enum M {
    A(Matrix3<f64>),
    B(Vector3<f64>),
}

fn main() {}
