//! Joining branches at their branch points: the branches born at a branch point pass through
//! the event point located on the branch it lies on, so that counting and drawing their
//! polylines is right next to it.

use nalgebra::Vector3;

use super::builder::Builder;
use crate::families::continuation::Node;
use crate::families::{BranchEvent, EventKind};
use crate::model::Routhian;

/// How far (in `s`, in γ) a point of a branch may be from a branch point to be joined to it:
/// `1e−4·max(1, |s|)` and `1e−2` for a pitchfork's tip (located to `event_tol` in `s`); for the end
/// of a branch of circles next to its axis (where the continuation stops before the circle
/// direction is lost) `1e−2` of the range and `0.1` rad: along such a branch `s` is monotone up to
/// the axis (the circles shrink as `√|s − s*|`), so the segment to the axis counts right.
pub(super) fn join_tolerances(isolated: bool, s: f64, len: f64) -> (f64, f64) {
    if isolated {
        (1e-4 * s.abs().max(1.0), 1e-2)
    } else {
        (1e-2 * len, 0.1)
    }
}

/// Below this distance in γ a node of a branch is the branch point itself (up to how well a
/// turning point is located) and is replaced by it.
const SAME_POINT: f64 = 1e-4;

/// Where a branch point goes in the polyline of another branch.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Join {
    /// Replace node `k`.
    Replace(usize),
    /// Insert before node `k` (`k = len` appends).
    Insert(usize),
}

/// The interior node of `nodes` that is the tip of a pitchfork born at `e`: a local extremum of
/// `s`, closer to `e` in γ than a step to its neighbours (or `1e−2`), such that the event lies
/// beyond both its neighbours in `s` (the tip is the extreme `s` of the branch there) but beyond
/// the node by at most the rise from it to its neighbours (plus `1e−4·max(1, |s|)`). A node that
/// coincides with `e` in γ is replaced: a turning point located on a step across the other
/// branch can slide onto that branch (where the two meet, the pseudo-arclength hyperplane cuts
/// both). Otherwise `e` is inserted next to the node, on the side of the neighbour nearer in γ.
/// Nodes in `fixed` (other events' points) are left alone.
fn tip_join(nodes: &[Node], e: &BranchEvent, fixed: &[(f64, Vector3<f64>)]) -> Option<Join> {
    let tol = 1e-4 * e.s.abs().max(1.0);
    let mut best: Option<(f64, Join)> = None;
    for k in 1..nodes.len().saturating_sub(1) {
        let (sp, sk, sn) = (nodes[k - 1].s, nodes[k].s, nodes[k + 1].s);
        if fixed.iter().any(|(s, g)| *s == sk && *g == nodes[k].gamma) {
            continue;
        }
        let dg = (nodes[k].gamma - e.gamma).norm();
        let step = (nodes[k - 1].gamma - nodes[k].gamma)
            .norm()
            .max((nodes[k + 1].gamma - nodes[k].gamma).norm());
        if dg > step.max(1e-2) {
            continue;
        }
        // The tip lies beyond the extreme node by at most the rise to its neighbours (three
        // samples of a parabola whose vertex lies between the outer two).
        let span = (sp - sk).abs().max((sn - sk).abs()) + tol;
        let same = dg <= SAME_POINT;
        let valid = if sk <= sp && sk <= sn {
            e.s < sp.min(sn) && e.s >= sk - span
        } else if sk >= sp && sk >= sn {
            e.s > sp.max(sn) && e.s <= sk + span
        } else {
            false
        };
        if !valid || best.is_some_and(|(d, _)| d <= dg) {
            continue;
        }
        let join = if same {
            Join::Replace(k)
        } else {
            let dp = (nodes[k - 1].gamma - e.gamma).norm();
            let dn = (nodes[k + 1].gamma - e.gamma).norm();
            Join::Insert(if dp <= dn { k } else { k + 1 })
        };
        best = Some((dg, join));
    }
    best.map(|(_, j)| j)
}

impl<'a, M: Routhian, F: Fn(f64) -> (M, f64)> Builder<'a, M, F> {
    /// Joins the branches born at a branch point to the located event point. On each other
    /// branch, the tip of the pitchfork (the extremum of `s` there, see [`tip_join`]) is replaced
    /// by the event point or gets it inserted; failing a tip, the node nearest to it within
    /// [`join_tolerances`] is replaced by it (when it is the same point), or a branch that ends
    /// next to it (a branch of circles next to its axis) gets it as its end.
    pub(super) fn join_at_branch_points(&mut self) {
        let fixed: Vec<(f64, Vector3<f64>)> = self.events.iter().map(|e| (e.s, e.gamma)).collect();
        for e in &self.events {
            if e.kind != EventKind::BranchPoint {
                continue;
            }
            let Some(event_node) = self
                .branches
                .iter()
                .flat_map(|(nodes, _)| nodes.iter())
                .find(|n| n.s == e.s && n.gamma == e.gamma)
                .cloned()
            else {
                continue;
            };
            let len = self.range.1 - self.range.0;
            for (i, (nodes, isolated)) in self.branches.iter_mut().enumerate() {
                if i == e.branch || nodes.is_empty() {
                    continue;
                }
                let exact = |n: &Node| n.s == e.s && n.gamma == e.gamma;
                if nodes.iter().any(exact) {
                    continue;
                }
                if *isolated {
                    match tip_join(nodes, e, &fixed) {
                        Some(Join::Replace(k)) => {
                            nodes[k] = event_node.clone();
                            continue;
                        }
                        Some(Join::Insert(k)) => {
                            nodes.insert(k, event_node.clone());
                            continue;
                        }
                        None => {}
                    }
                }
                let (ds_tol, dg_tol) = join_tolerances(*isolated, e.s, len);
                let near =
                    |n: &Node| (n.s - e.s).abs() <= ds_tol && (n.gamma - e.gamma).norm() <= dg_tol;
                let Some((k, _)) =
                    nodes
                        .iter()
                        .enumerate()
                        .filter(|(_, n)| near(n))
                        .min_by(|x, y| {
                            let dx = (x.1.gamma - e.gamma).norm();
                            let dy = (y.1.gamma - e.gamma).norm();
                            dx.total_cmp(&dy)
                        })
                else {
                    continue;
                };
                let last = nodes.len() - 1;
                let close = (nodes[k].gamma - e.gamma).norm() <= SAME_POINT;
                if (k == 0 || k == last) && !close {
                    // An end next to the point: extend the branch to it.
                    if k == 0 {
                        nodes.insert(0, event_node.clone());
                    } else {
                        nodes.push(event_node.clone());
                    }
                } else if close {
                    nodes[k] = event_node.clone();
                }
            }
        }
    }
}
