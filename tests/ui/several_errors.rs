use routh::{Lagrangian, Matrix3, Vector3};

#[derive(Lagrangian)]
#[lagrangian(
    let j = inertia + mass,
    kinetic = 0.5 * omega.dot(j * omega),
    linear = rotr.dot(omega),
    potential = mass * g * com.dot(gamma) + omega.x,
    potential = mass,
    frobnicate = 1,
)]
struct M {
    inertia: Matrix3<f64>,
    com: Vector3<f64>,
    mass: f64,
    g: f64,
}

fn main() {
    let m = M {
        inertia: Matrix3::identity(),
        com: Vector3::zeros(),
        mass: 1.0,
        g: 9.81,
    };
    let w = Vector3::new(0.0, 0.0, 1.0);
    let g = Vector3::new(0.0, 0.0, 1.0);
    let _ = routh::Lagrangian::energy(&m, &w, &g);
    let _ = routh::Routhian::bundle(&m, &w, &g, 1.0);
}
