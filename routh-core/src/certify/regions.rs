//! Certified motions found twice and undecided boxes, grouped by union–find: the distinct
//! motions, and the connected undecided regions of the sphere.

use super::chart::{ChartBox, Face};
use super::interval::Interval;
use super::UndecidedRegion;

/// A certified zero: its chart, the box where it is unique, and a tight enclosure in γ.
pub(super) struct Found {
    pub(super) face: Face,
    pub(super) unique: (Interval, Interval),
    pub(super) gamma: [Interval; 3],
}

pub(super) fn overlaps(a: &[Interval; 3], b: &[Interval; 3]) -> bool {
    (0..3).all(|i| a[i].intersect(b[i]).is_some())
}

/// Whether the motion enclosed by `inner` is the one unique in `outer`'s box.
pub(super) fn same_motion(inner: &Found, outer: &Found) -> bool {
    match outer.face.coordinates(&inner.gamma) {
        Some((u, v)) => u.subset_of(outer.unique.0) && v.subset_of(outer.unique.1),
        None => false,
    }
}

pub(super) fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

/// Groups undecided chart boxes into connected regions of the sphere (boxes whose γ-hulls meet).
pub(super) fn regions(boxes: &[ChartBox]) -> Vec<UndecidedRegion> {
    let hulls: Vec<[Interval; 3]> = boxes.iter().map(|b| b.face.gamma(b.u, b.v).0).collect();
    let mut parent: Vec<usize> = (0..hulls.len()).collect();
    // Sweep along γ₁: only boxes whose γ₁-ranges overlap can meet.
    let mut order: Vec<usize> = (0..hulls.len()).collect();
    order.sort_by(|&a, &b| hulls[a][0].lo.total_cmp(&hulls[b][0].lo));
    for (pos, &i) in order.iter().enumerate() {
        for &j in &order[pos + 1..] {
            if hulls[j][0].lo > hulls[i][0].hi {
                break;
            }
            if overlaps(&hulls[i], &hulls[j]) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[b] = a;
            }
        }
    }
    let mut out: Vec<UndecidedRegion> = Vec::new();
    let mut index = vec![usize::MAX; hulls.len()];
    for (i, h) in hulls.iter().enumerate() {
        let r = find(&mut parent, i);
        if index[r] == usize::MAX {
            index[r] = out.len();
            out.push(UndecidedRegion { hull: *h, boxes: 0 });
        }
        let reg = &mut out[index[r]];
        reg.boxes += 1;
        for (acc, x) in reg.hull.iter_mut().zip(h) {
            *acc = acc.hull(*x);
        }
    }
    out
}

/// The motions of `found` once each (the same motion certified in two boxes, a box edge or a
/// chart edge through it, is kept once), and the number of pairs of enclosures that meet without
/// a proof that they hold the same motion.
pub(super) fn distinct(found: &[Found]) -> (Vec<&Found>, usize) {
    let mut parent: Vec<usize> = (0..found.len()).collect();
    let mut ambiguous_pairs = 0;
    for i in 0..found.len() {
        for j in i + 1..found.len() {
            if !overlaps(&found[i].gamma, &found[j].gamma) {
                continue;
            }
            if same_motion(&found[j], &found[i]) || same_motion(&found[i], &found[j]) {
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                parent[b] = a;
            } else {
                ambiguous_pairs += 1;
            }
        }
    }
    let mut out = Vec::new();
    for (i, f) in found.iter().enumerate() {
        if find(&mut parent, i) == i {
            out.push(f);
        }
    }
    (out, ambiguous_pairs)
}
