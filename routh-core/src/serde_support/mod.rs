//! serde support that a `derive` alone does not give (feature `serde`): floats that may be NaN
//! or infinite ([`float`]), and [`RouthError`](crate::RouthError) as a tagged value with its
//! message ([`error`]).

pub(crate) mod error;
pub(crate) mod float;
