use routh::{Lagrangian, Matrix3, Vector3};

// All three terms have the wrong degree in omega: the three errors come out together, in source
// order, and the stub impl keeps `main` free of follow-on errors.
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega) * omega.x,
    linear = com.dot(omega) * omega.y,
    potential = mass * g * com.dot(gamma) + omega.z,
)]
struct M {
    inertia: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {
    let m = M { inertia: Matrix3::identity(), com: Vector3::z(), mass: 1.0, g: 9.81 };
    let _ = routh::Lagrangian::energy(&m, &Vector3::zeros(), &Vector3::z());
}
