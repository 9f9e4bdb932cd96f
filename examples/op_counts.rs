//! Operation counts of the code `#[derive(Lagrangian)]` generates for the bench models M1 and M2.
//! Run: `cargo run --release --example op_counts`.
//!
//! Method by method, with the time the code generator takes for each model. A tool for the
//! generator's developers, not a user's example: it calls the unpublished `routh-codegen` and
//! `routh-symbolic` directly, and takes the models' source text from `derived-models` so that it
//! counts exactly what `benches/bundle.rs` evaluates.

use routh_symbolic::{op_counts, Id};
use std::time::Instant;

// The benchmark models M1 and M2, exactly as `benches/bundle.rs` evaluates them.
use derived_models::{DIAGONAL_ELLIPSOID_SRC, GYROSTAT_SRC};

fn main() {
    for (name, src) in [
        ("M1 gyrostat", GYROSTAT_SRC),
        ("M2 ellipsoid", DIAGONAL_ELLIPSOID_SRC),
    ] {
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
        let fused = o.bundle_and_system().flatten();
        println!("  bundle_and_system  {}", op_counts(g, &fused));
        println!("  routhian           {}", op_counts(g, &[o.routhian]));
        println!("  lagrangian         {}", op_counts(g, &[o.lagrangian]));
    }
}
