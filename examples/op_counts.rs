//! Prints the operation counts of the code `#[derive(Lagrangian)]` generates for the benchmark
//! models M1 (gyrostat) and M2 (ellipsoid on a plane), method by method, and the time the code
//! generator takes for each model.
//!
//! `cargo run --release --example op_counts`

use routh_symbolic::{op_counts, Id};
use std::time::Instant;

const M1: &str = r#"
#[derive(Lagrangian)]
#[lagrangian(
    kinetic = 0.5 * omega.dot(inertia * omega),
    linear = (rotor + coupling * gamma).dot(omega),
    potential = mass * g * com.dot(gamma),
)]
pub struct Gyrostat {
    #[lagrangian(symmetric)]
    pub inertia: Matrix3<f64>,
    pub rotor: Vector3<f64>,
    pub coupling: Matrix3<f64>,
    pub com: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}
"#;

const M2: &str = r#"
#[derive(Lagrangian)]
#[lagrangian(
    let d = diag(semi_axes.component_mul(semi_axes)),
    let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
    let n = grad(c3, gamma),
    kinetic = 0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2)),
    potential = mass * g * c3,
)]
pub struct Ellipsoid {
    pub inertia: Vector3<f64>,
    pub semi_axes: Vector3<f64>,
    pub offset: Vector3<f64>,
    pub mass: f64,
    pub g: f64,
}
"#;

fn main() {
    for (name, src) in [("M1 gyrostat", M1), ("M2 ellipsoid", M2)] {
        let di: syn::DeriveInput = syn::parse_str(src).expect("model parses");
        let t0 = Instant::now();
        let runs = 20;
        for _ in 0..runs {
            let _ = routh_codegen::expand(&di).expect("model expands");
        }
        let per = t0.elapsed() / runs;
        let model = routh_codegen::analyse(&di).expect("model is valid");
        let o = &model.outputs;
        let g = &model.lowered.sym.graph;
        let bundle = o.bundle_ids();
        let mut gyro: Vec<Id> = vec![];
        for m in [&o.gyro_a, &o.gyro_g, &o.gyro_c] {
            gyro.extend(m.iter().flatten());
        }
        println!(
            "{name}: expansion {per:?} per run, graph of {} nodes",
            g.len()
        );
        println!("  bundle             {}", op_counts(g, &bundle));
        println!("  gyroscopic_system  {}", op_counts(g, &gyro));
        println!("  routhian           {}", op_counts(g, &[o.routhian]));
        println!("  lagrangian         {}", op_counts(g, &[o.lagrangian]));
    }
}
