//! The models of `routh`'s tests, benches and examples declared with `#[derive(Lagrangian)]`,
//! each beside its hand-written twin of the `test-models` crate (`From<&twin>` or `twin()`), and
//! the analyses that the examples print and `tests/examples_facts.rs` checks.
//!
//! Why a second crate: the derive expands to code that names the facade `routh`, so these models
//! need `routh` (and through it the code generator). `test-models` is a dev-dependency of
//! `routh-core`, whose own tests must not pull in the facade and the proc-macro stack (nor see a
//! second path to routh-core's types), so it stays routh-core-only, and the derived half lives
//! here, used only by the facade's tests, benches and examples.
//!
//! The bench models are declared through `model!` so that their source text is kept too
//! ([`GYROSTAT_SRC`], [`DIAGONAL_ELLIPSOID_SRC`]): `benches/expand.rs` times the expansion of
//! exactly the models that `benches/bundle.rs` evaluates.
#![forbid(unsafe_code)]

/// Declares the item and a `&str` constant holding its source tokens.
macro_rules! model {
    ($src:ident: $($item:tt)*) => {
        $($item)*
        /// The declaration above, as source text (for the expansion bench).
        pub const $src: &str = stringify!($($item)*);
    };
}

mod analysis;
pub mod ellipsoid;
pub mod fluid_body;
pub mod gyrostat;
pub mod heavy_body;
pub mod top;

pub use analysis::{
    bisect, classified_steady_motions, instability_threshold, report_at, stability_threshold,
    verdict_at, Classified,
};
pub use ellipsoid::{DiagonalEllipsoid, Ellipsoid, DIAGONAL_ELLIPSOID_SRC};
pub use fluid_body::{FluidBody, Kirchhoff};
pub use gyrostat::{Gyrostat, GYROSTAT_SRC};
pub use heavy_body::HeavyBody;
pub use top::{AsymmetricTop, LagrangeTop};

/// A number with at most `digits` decimals, trailing zeros removed (`0.5`, `9.81`, `-2`).
pub fn num(x: f64, digits: usize) -> String {
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}
