//! Runtime property test of routh-core on the hand-written models (the closed-form
//! `test_models::HeavyTop` and the num-dual `test_models::Gyrostat`), and the regression cases:
//! every public runtime function on random and extreme inputs must never panic, never hang, name
//! what failed on `Err` and return finite values on `Ok`. The harness, its properties and its
//! inputs are in `test_models::runtime_properties`; the cases that draw the gyrostat declared with
//! `#[derive(Lagrangian)]` run in the facade's `tests/runtime_properties.rs` (the derive needs the
//! facade, which routh-core's tests do not depend on).
//!
//! Replay one case: `ROUTH_PROPTEST_SEED=S ROUTH_PROPTEST_CASE=C cargo test -p routh-core --test
//! runtime_properties -- --nocapture`.

use test_models::runtime_properties::{run, Part};

#[test]
fn runtime_functions_never_panic_hang_or_return_non_finite() {
    run(Part::Hand);
}
