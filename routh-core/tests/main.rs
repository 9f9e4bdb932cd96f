//! The integration tests of `routh-core` in one test binary: each file of `tests/` is a module of
//! it, so that `cargo test` builds and links one binary for them instead of one per file. Run one
//! file's tests with `cargo test -p routh-core --test main <file>::`.
//!
//! A new test file is a new `mod` line below; `every_test_file_is_a_module`, in the facade's
//! tests/main.rs at the workspace root, fails until it is.

mod atlas;
mod attitude;
mod common;
mod export;
mod families;
mod families_robust;
mod families_smooth;
mod families_sweep;
mod invariance;
mod nonlinear;
mod periodic;
mod periodic_bodies;
mod periodic_events;
mod periodic_param;
mod run_control;
mod runtime_properties;
mod simulation;
mod stability;
mod steady_motions;
mod tolerance;
mod trust;
mod units;
mod zero_invariance;
