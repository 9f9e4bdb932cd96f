//! The hash-cons table: the id of every node of a graph, found by the node.
//!
//! Open addressing with linear probing over the nodes' ids (the nodes themselves are the
//! graph's `Vec`), with a hand-written multiply-rotate hash. The derive runs unoptimised in a
//! user's debug build, where a `HashMap` (SipHash first; then, with a fast hasher, hashbrown's
//! generic probing and the debug checks of its unsafe code) was the largest single cost of
//! building the graph. The keys are small nodes made by the derive itself, so there is nothing
//! to defend against.

use super::{Id, Node};

/// A slot holding no id ([`Id::NONE`] is never a node's id).
const EMPTY: u32 = Id::NONE.0;

/// The multiplier of rustc's `FxHasher`.
const K: u64 = 0xf135_7aea_2e62_a9c5;

/// The ids of a graph's nodes, hashed by node: at most half the slots are used.
#[derive(Clone, Default)]
pub(crate) struct Table {
    slots: Vec<u32>,
}

/// The hash of a node: its kind and operands, two multiply-rotates.
fn hash(node: &Node) -> u64 {
    let (kind, a, b): (u64, u64, u64) = match *node {
        Node::Const(bits) => (0, bits, 0),
        Node::Var(v) => (1, u64::from(v.0), 0),
        Node::Add(a, b) => (2, u64::from(a.0), u64::from(b.0)),
        Node::Mul(a, b) => (3, u64::from(a.0), u64::from(b.0)),
        Node::Neg(a) => (4, u64::from(a.0), 0),
        Node::Recip(a) => (5, u64::from(a.0), 0),
        Node::Powi(a, n) => (6, u64::from(a.0), u64::from(n as u32)),
        Node::Powf(a, b) => (7, u64::from(a.0), u64::from(b.0)),
        Node::Func(f, a) => (8 + ((f as u64) << 8), u64::from(a.0), 0),
    };
    let h = (kind.wrapping_mul(K).rotate_left(5) ^ a).wrapping_mul(K);
    (h.rotate_left(5) ^ b).wrapping_mul(K)
}

impl Table {
    /// The slot of `node` in a table of `len` slots (a power of two): the hash's high bits.
    fn first_slot(node: &Node, len: usize) -> usize {
        (hash(node) >> 32) as usize & (len - 1)
    }

    /// The id of `node` among `nodes`, if it is one of them.
    pub(crate) fn get(&self, nodes: &[Node], node: &Node) -> Option<Id> {
        if self.slots.is_empty() {
            return None;
        }
        let mask = self.slots.len() - 1;
        let mut i = Self::first_slot(node, self.slots.len());
        loop {
            let s = self.slots[i];
            if s == EMPTY {
                return None;
            }
            if nodes[s as usize] == *node {
                return Some(Id(s));
            }
            i = (i + 1) & mask;
        }
    }

    /// The id of `node` among `nodes`, pushed onto them if it is new.
    pub(crate) fn intern(&mut self, nodes: &mut Vec<Node>, node: Node) -> Id {
        if 2 * (nodes.len() + 1) > self.slots.len() {
            self.grow(nodes);
        }
        let mask = self.slots.len() - 1;
        let mut i = Self::first_slot(&node, self.slots.len());
        loop {
            let s = self.slots[i];
            if s == EMPTY {
                break;
            }
            if nodes[s as usize] == node {
                return Id(s);
            }
            i = (i + 1) & mask;
        }
        let id = u32::try_from(nodes.len())
            .ok()
            .filter(|&i| i != EMPTY)
            .expect("expression graph exceeds u32 nodes");
        debug_assert!(node.children().all(|c| c.0 < id));
        nodes.push(node);
        self.slots[i] = id;
        Id(id)
    }

    /// Doubles the slots (at least 1024) and puts every node back.
    fn grow(&mut self, nodes: &[Node]) {
        let mut len = self.slots.len().max(512) * 2;
        while 2 * (nodes.len() + 1) > len {
            len *= 2;
        }
        let mut slots = vec![EMPTY; len];
        for (k, node) in nodes.iter().enumerate() {
            let mut i = Self::first_slot(node, len);
            while slots[i] != EMPTY {
                i = (i + 1) & (len - 1);
            }
            slots[i] = k as u32;
        }
        self.slots = slots;
    }
}
