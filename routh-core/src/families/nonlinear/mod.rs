//! The nonlinear events of a family (docs/method.md §10.7): where, on linearly stable
//! stretches of a branch or over an atlas, Arnold's determinant vanishes or the frequencies are in
//! 1:2 or 1:3 resonance. Per point the verdict is [`crate::nonlinear`]'s; this module locates
//! where it changes.

mod atlas;
mod events;

pub use atlas::NonlinearCurve;
pub(crate) use atlas::{atlas_curves, atlas_curves_parallel, GridNode};
pub(crate) use events::add_to_diagram;
pub use events::{nonlinear_events, NonlinearEvent, NonlinearEventVerdicts};
