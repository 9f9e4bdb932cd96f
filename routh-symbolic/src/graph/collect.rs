//! Like-term collection for sums: `c₁·x + c₂·x = (c₁ + c₂)·x` across whole sums, used by
//! [`Graph::add`] only where it cancels a term or reaches a sum that already exists.

use super::{Graph, Id, Node};

impl Graph {
    /// Most terms a sum is flattened into when looking for like terms.
    const MAX_TERMS: usize = 24;

    /// Appends the terms `coef · base` of `id` (through sums, negations and constant factors).
    /// Returns `false` when there are more than [`Self::MAX_TERMS`].
    fn terms(&self, id: Id, coef: f64, out: &mut Vec<(Id, f64)>, constant: &mut f64) -> bool {
        if out.len() > Self::MAX_TERMS {
            return false;
        }
        match self.node(id) {
            Node::Add(x, y) => {
                self.terms(x, coef, out, constant) && self.terms(y, coef, out, constant)
            }
            Node::Neg(x) => self.terms(x, -coef, out, constant),
            Node::Mul(c, x) if self.as_const(c).is_some() => {
                let c = self.as_const(c).unwrap_or(1.0);
                self.terms(x, coef * c, out, constant)
            }
            Node::Const(v) => {
                *constant += coef * f64::from_bits(v);
                true
            }
            _ => {
                out.push((id, coef));
                true
            }
        }
    }

    /// `a + b` with like terms collected, if the two sums share a term and collecting them
    /// cancels a term or lands on an existing sum: the terms are written in increasing id order
    /// (so the same set of terms always makes the same node, and a dot product built in that
    /// order is found again), with a common factor pulled out (`2x + 2y = 2(x + y)`). `None`
    /// otherwise, so that sums keep the structure (and the sharing) they were built with.
    pub(super) fn collect_like_terms(&mut self, a: Id, b: Id) -> Option<Id> {
        let (mut ta, mut tb) = (Vec::new(), Vec::new());
        let (mut ka, mut kb) = (0.0, 0.0);
        if !self.terms(a, 1.0, &mut ta, &mut ka) || !self.terms(b, 1.0, &mut tb, &mut kb) {
            return None;
        }
        let shared = ta.iter().any(|(x, _)| tb.iter().any(|(y, _)| x == y));
        if !shared {
            return None;
        }
        let mut all = ta;
        all.extend(tb);
        all.sort_by_key(|t| t.0);
        let mut merged: Vec<(Id, f64)> = Vec::with_capacity(all.len());
        for (x, c) in all {
            match merged.last_mut() {
                Some((y, d)) if *y == x => *d += c,
                _ => merged.push((x, c)),
            }
        }
        let before = merged.len();
        merged.retain(|t| t.1 != 0.0);
        let cancelled = merged.len() < before;
        let k = ka + kb;
        // A common factor of every term (and of no constant) is pulled out.
        let common = match merged.first() {
            Some(&(_, c)) if k == 0.0 && c != 1.0 && merged.iter().all(|t| t.1 == c) => c,
            _ => 1.0,
        };
        // Without a cancellation, collecting pays only if it reaches an existing sum (such as
        // 2·(IΩ)ᵢ from (IΩ)ᵢ + (IᵀΩ)ᵢ with I symmetric); a longer chain of new additions would
        // undo the sharing the operands had. A dry run over the hash-cons table decides.
        if !cancelled && self.new_nodes_for(&merged, k, common) > 2 {
            return None;
        }
        let mut acc: Option<Id> = if k != 0.0 {
            Some(self.constant(k))
        } else {
            None
        };
        for (x, c) in merged {
            let c = self.constant(c / common);
            let term = self.mul(c, x);
            acc = Some(match acc {
                None => term,
                Some(s) => self.add_plain(s, term),
            });
        }
        let sum = acc.unwrap_or_else(|| self.zero());
        let c = self.constant(common);
        Some(self.mul(c, sum))
    }

    /// How many nodes writing `k + Σ (c/common)·x`, times `common`, would add (an estimate that
    /// builds nothing: every step not already in the table counts as one).
    fn new_nodes_for(&self, merged: &[(Id, f64)], k: f64, common: f64) -> usize {
        let konst = |c: f64| self.find(&Node::Const(if c == 0.0 { 0.0f64 } else { c }.to_bits()));
        let mut new = 0;
        let mut acc: Option<Option<Id>> = if k != 0.0 { Some(konst(k)) } else { None };
        for &(x, c) in merged {
            let c = c / common;
            let term = if c == 1.0 {
                Some(x)
            } else if c == -1.0 {
                self.find(&Node::Neg(x))
            } else {
                konst(c).and_then(|c| {
                    let (a, b) = self.order(c, x);
                    self.find(&Node::Mul(a, b))
                })
            };
            if term.is_none() {
                new += 1;
            }
            acc = Some(match (acc, term) {
                (None, t) => t,
                (Some(Some(s)), Some(t)) => {
                    let (a, b) = self.order(s, t);
                    let found = self.find(&Node::Add(a, b));
                    new += usize::from(found.is_none());
                    found
                }
                (Some(_), _) => {
                    new += 1;
                    None
                }
            });
        }
        if common != 1.0 {
            new += 1;
        }
        new
    }

    /// `a + b` with only the canonical order and the identities that cannot recurse.
    pub(super) fn add_plain(&mut self, a: Id, b: Id) -> Id {
        let (a, b) = self.order(a, b);
        if self.is_const(a, 0.0) {
            return b;
        }
        self.intern(Node::Add(a, b))
    }
}
