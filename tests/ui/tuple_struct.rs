use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(omega),
)]
struct M(Matrix3<f64>, Vector3<f64>);

fn main() {}
