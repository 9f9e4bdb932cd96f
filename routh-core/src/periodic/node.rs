//! An accepted orbit of a family (`Node`) and the test that two of them lie on one family
//! (`same_family`), used by the follower (`family.rs`) and by the event location (`events.rs`).

use super::shoot::{Solved, W};
use super::PeriodicOrbit;

/// An accepted orbit of a family with its tangent.
#[derive(Clone)]
pub(super) struct Node {
    pub solved: Solved,
    pub tangent: W,
    pub orbit: PeriodicOrbit,
    /// The twist of the Poincaré map when the family looks for nonlinear events
    /// ([`super::OrbitOptions::nonlinear`]) and the orbit is elliptic; NaN otherwise.
    pub twist: f64,
}

/// Whether `b` continues the family of `a`: the tangents at both ends make about the same angle
/// with the chord between them, as on one smooth curve (an arc turns by as much at either end);
/// a corrector that landed on a family crossing at a branch point has the other family's
/// tangent there, at the crossing angle to the chord. Allowed: twice the larger of the angles at
/// `a` plus 0.02 rad (families crossing at less than that are not told apart).
pub(super) fn same_family(a: &Node, b: &Node) -> bool {
    let chord = b.solved.w - a.solved.w;
    let len = chord.norm();
    if len.is_nan() || len <= 0.0 {
        return true;
    }
    let c = chord / len;
    let angle = |t: &W| t.dot(&c).abs().min(1.0).acos();
    let (ta, tb) = (angle(&a.tangent), angle(&b.tangent));
    tb <= 2.0 * ta + 0.02 && ta <= 2.0 * tb + 0.02
}
