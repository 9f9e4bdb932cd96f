//! The numerical engines of the crate, each written once and shared by the analyses
//! (docs/architecture.md, "Engines"):
//!
//! - [`newton`]: the one Newton corrector on the sphere (fixed-size 4 × 4, minimum-norm steps,
//!   optional damping), used by the search of steady motions, the continuation of branches and
//!   the atlas's grid and boundary curves;
//! - [`path`]: the one predictor–corrector along a curve `{F = 0}` with its step control, and
//!   its [`LinearRow`](path::row::LinearRow) `n·w = c` (the pseudo-arclength row or a fixed
//!   parameter), used by every curve the crate follows;
//! - [`locate`]: the one event locator (regula falsi with the Illinois modification) for the
//!   zero of a test function between two solved points;
//! - [`zero`]: the one zero test, relative to a local tangential scale;
//! - [`norm`]: the overflow- and underflow-safe Euclidean norm.
//!
//! The shooting corrector of periodic orbits (a Gauss–Newton on the flow's return map) stays
//! with the orbits, in `periodic/shoot.rs`; it uses [`locate`] and [`path::row`].

pub(crate) mod locate;
pub(crate) mod newton;
pub(crate) mod norm;
pub(crate) mod path;
pub(crate) mod zero;
