use routh::Lagrangian;

#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(omega),
)]
struct M;

fn main() {}
