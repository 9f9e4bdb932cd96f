//! Shared by the stability and steady-motion tests: the closed-form heavy top now lives in the
//! shared models crate (`test_models::HeavyTop`).
#![allow(unused_imports)]

pub use test_models::HeavyTop;
