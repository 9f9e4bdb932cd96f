//! Runtime property test of routh-core on generated code: the cases of
//! `test_models::runtime_properties` that draw the gyrostat declared with `#[derive(Lagrangian)]`
//! (`derived_models::Gyrostat`, built from the same random parameters as its num-dual twin; the
//! only kind of model the certified search accepts). The cases on the hand-written models run in
//! routh-core's `tests/runtime_properties.rs`; together the two tests run every case once.
//!
//! Replay one case: `ROUTH_PROPTEST_SEED=S ROUTH_PROPTEST_CASE=C cargo test -p routh --test
//! runtime_properties -- --nocapture`.

use test_models::runtime_properties::{run, run_case, Part};

#[test]
fn derived_gyrostat_runtime_functions_never_panic_hang_or_return_non_finite() {
    run(Part::Derived(&|h, rng, twin, pick| {
        run_case(h, rng, &derived_models::Gyrostat::from(twin), pick)
    }));
}
