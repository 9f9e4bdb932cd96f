//! The integration tests of `routh-symbolic` in one test binary: each file of `tests/` is a module of
//! it, so that `cargo test` builds and links one binary for them instead of one per file. Run one
//! file's tests with `cargo test -p routh-symbolic --test main <file>::`.
//!
//! A new test file is a new `mod` line below; `every_test_file_is_a_module`, in the facade's
//! tests/main.rs at the workspace root, fails until it is.

mod numdual_agreement;
mod simplify;
mod tape;
