//! The order in which a method's statements are written: a list scheduler over the plan's DAG
//! by critical-path height, for latency.
//!
//! Any order with children before parents is a valid order for the straight-line body (every
//! shared value is still computed once). Increasing id is one; [`latency_order`] is another:
//! it simulates an in-order machine issuing [`ISSUE_WIDTH`] operations per cycle with the
//! latencies of [`latency`], and at each cycle writes, among the statements whose operands are
//! ready, the one with the longest latency-weighted path to an output. The division of `γᵀJγ`
//! and everything it needs come first; the work independent of it fills its latency.

use routh_symbolic::{Func, Graph, Id, Node, Plan};

/// Operations the simulated machine issues per cycle (two floating-point ports).
pub const ISSUE_WIDTH: u32 = 2;

/// Latency of a statement in cycles, as written (a product folding a reciprocal is a division):
/// roughly those of a current x86 core (add, mul 4; div 14; sqrt 18; a call 40).
pub fn latency(g: &Graph, plan: &Plan, id: Id) -> u32 {
    const DIV: u32 = 14;
    match g.node(id) {
        Node::Add(..) => 4,
        Node::Mul(a, b) => {
            if plan.folds(g, id, a).is_some() || plan.folds(g, id, b).is_some() {
                DIV
            } else {
                4
            }
        }
        Node::Neg(_) => 1,
        Node::Recip(_) => DIV,
        Node::Powi(_, 2) => 4,
        Node::Powi(_, 3) => 8,
        Node::Func(Func::Sqrt, _) => 18,
        Node::Func(Func::Abs | Func::Sign, _) => 2,
        Node::Powi(..) | Node::Powf(..) | Node::Func(..) => 40,
        Node::Const(_) | Node::Var(_) => 0,
    }
}

/// The plan's statements, grouped by part (the statements part `k` needs that no earlier part
/// needed), each group in latency order (see the module documentation). Every statement
/// appears once, after the statements it reads.
pub fn latency_order(g: &Graph, plan: &Plan, parts: &[&[Id]]) -> Vec<Vec<Id>> {
    // The statements, and the dense index of each (`usize::MAX` for leaves), in plain loops
    // over the emitted nodes only: this runs once per generated method, unoptimised in a
    // user's debug build, where walking the whole graph cost more than the scheduling itself.
    let n = plan.emit.len();
    let nodes = g.nodes();
    let mut stmts: Vec<Id> = Vec::with_capacity(plan.emitted.len());
    let mut slot = vec![usize::MAX; n];
    for &id in &plan.emitted {
        if !matches!(nodes[id.index()], Node::Const(_) | Node::Var(_)) {
            slot[id.index()] = stmts.len();
            stmts.push(id);
        }
    }
    // The statements each statement reads (at most two; `x * x` reads `x` once), and who reads
    // each, in flat arrays (a `Vec` per statement was most of the cost).
    let mut operands: Vec<[usize; 2]> = Vec::with_capacity(stmts.len());
    let mut arity: Vec<u8> = Vec::with_capacity(stmts.len());
    let mut readers = vec![0u32; stmts.len() + 1];
    for &id in &stmts {
        let mut ops = [usize::MAX; 2];
        let mut m = 0usize;
        let (a, b) = match nodes[id.index()] {
            Node::Const(_) | Node::Var(_) => (None, None),
            Node::Add(a, b) | Node::Mul(a, b) | Node::Powf(a, b) => (Some(a), Some(b)),
            Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Func(_, a) => (Some(a), None),
        };
        for c in [a, b] {
            let Some(c) = c else { break };
            let s = slot[plan.folds(g, id, c).unwrap_or(c).index()];
            if s != usize::MAX && (m == 0 || ops[m - 1] != s) {
                ops[m] = s;
                m += 1;
            }
        }
        for &o in &ops[..m] {
            readers[o + 1] += 1;
        }
        operands.push(ops);
        arity.push(m as u8);
    }
    let ops_of = |k: usize| &operands[k][..usize::from(arity[k])];
    // Users of statement `o`: `user_list[readers[o]..readers[o + 1]]`, in increasing order.
    for k in 0..stmts.len() {
        readers[k + 1] += readers[k];
    }
    let mut fill: Vec<u32> = readers[..stmts.len()].to_vec();
    let mut user_list = vec![0usize; readers[stmts.len()] as usize];
    for k in 0..stmts.len() {
        for &o in ops_of(k) {
            user_list[fill[o] as usize] = k;
            fill[o] += 1;
        }
    }
    let users = |k: usize| &user_list[readers[k] as usize..readers[k + 1] as usize];
    let mut lat: Vec<u32> = Vec::with_capacity(stmts.len());
    for &id in &stmts {
        lat.push(latency(g, plan, id));
    }
    // Height: the latency-weighted longest path from a statement to an output (users come
    // after their operands in id order, so one backward sweep).
    let mut height = vec![0u32; stmts.len()];
    let mut k = stmts.len();
    while k > 0 {
        k -= 1;
        let mut above = 0;
        for &u in users(k) {
            above = above.max(height[u]);
        }
        height[k] = lat[k] + above;
    }
    // Which part first needs each statement.
    let mut part_of = vec![usize::MAX; stmts.len()];
    for (p, outs) in parts.iter().enumerate() {
        let mut stack: Vec<usize> = outs
            .iter()
            .map(|o| slot.get(o.index()).copied().unwrap_or(usize::MAX))
            .filter(|&s| s != usize::MAX)
            .collect();
        while let Some(k) = stack.pop() {
            if part_of[k] != usize::MAX {
                continue;
            }
            part_of[k] = p;
            stack.extend(ops_of(k).iter().copied());
        }
    }
    // Statements no part claims (none, for a plan built from the parts' outputs) go last.
    let last = parts.len().saturating_sub(1);
    for p in &mut part_of {
        if *p == usize::MAX {
            *p = last;
        }
    }

    let mut waiting: Vec<u32> = Vec::with_capacity(stmts.len());
    for &m in &arity {
        waiting.push(u32::from(m));
    }
    // Cycle (in issue slots: ISSUE_WIDTH per cycle) at which each operand's value is ready.
    let mut ready_at = vec![0u64; stmts.len()];
    let mut groups = vec![Vec::new(); parts.len().max(1)];
    // Statements whose operands are all written, by part: (ready slot, statement), earliest
    // first, packed into one integer (see [`Key`]).
    let mut pending: Vec<Heap> = vec![Heap::default(); groups.len()];
    for (k, w) in waiting.iter().enumerate() {
        if *w == 0 {
            pending[part_of[k]].push(Key::earliest(0, k));
        }
    }
    let width = u64::from(ISSUE_WIDTH);
    let mut now = 0u64;
    for p in 0..groups.len() {
        // Ready statements of this part: highest first, then the smaller id.
        let mut ready = Heap::default();
        loop {
            while let Some(key) = pending[p].peek() {
                let (at, k) = key.of_earliest();
                if at > now {
                    break;
                }
                pending[p].pop();
                ready.push(Key::highest(height[k], k));
            }
            let Some(key) = ready.pop() else {
                match pending[p].peek() {
                    Some(key) => {
                        now = key.of_earliest().0;
                        continue;
                    }
                    None => break,
                }
            };
            let k = key.of_highest();
            groups[p].push(stmts[k]);
            let done = now + u64::from(lat[k]) * width;
            now += 1;
            for &u in users(k) {
                ready_at[u] = ready_at[u].max(done);
                waiting[u] -= 1;
                if waiting[u] == 0 {
                    // A later part's statement waits for its part (and is ready by then).
                    pending[part_of[u]].push(Key::earliest(ready_at[u], u));
                }
            }
        }
    }
    groups
}

/// A statement and its priority packed into one `u64`, the greatest first in a [`Heap`]:
/// unoptimised, comparing tuples (`(u32, Reverse<usize>)`) was most of the scheduler's cost.
/// Statement indices and issue slots are far below 2³² (a slot is at most the number of
/// statements times the longest latency, doubled).
#[derive(Clone, Copy)]
struct Key(u64);

const LOW: u64 = u32::MAX as u64;

impl Key {
    /// Ordered as `(height, Reverse(k))`: the highest statement, then the smaller index.
    fn highest(height: u32, k: usize) -> Key {
        Key(u64::from(height) << 32 | (LOW - k as u64))
    }

    fn of_highest(self) -> usize {
        (LOW - (self.0 & LOW)) as usize
    }

    /// Ordered as `Reverse((at, k))`: the earliest ready slot, then the smaller index.
    fn earliest(at: u64, k: usize) -> Key {
        Key(!(at << 32 | k as u64))
    }

    fn of_earliest(self) -> (u64, usize) {
        let v = !self.0;
        (v >> 32, (v & LOW) as usize)
    }
}

/// A max-heap of [`Key`]s, sifted by hand in safe code: unoptimised, `BinaryHeap` runs the
/// debug checks of its unsafe moves at every step. The keys of one heap are distinct (each
/// holds a statement index), so the order they come out in is the same as `BinaryHeap`'s.
#[derive(Clone, Default)]
struct Heap(Vec<u64>);

impl Heap {
    fn push(&mut self, key: Key) {
        let h = &mut self.0;
        let mut i = h.len();
        h.push(key.0);
        while i > 0 {
            let parent = (i - 1) / 2;
            if h[parent] >= key.0 {
                break;
            }
            h[i] = h[parent];
            i = parent;
        }
        h[i] = key.0;
    }

    fn peek(&self) -> Option<Key> {
        self.0.first().map(|&k| Key(k))
    }

    fn pop(&mut self) -> Option<Key> {
        let h = &mut self.0;
        let last = h.pop()?;
        let n = h.len();
        if n == 0 {
            return Some(Key(last));
        }
        let top = h[0];
        let mut i = 0;
        loop {
            let left = 2 * i + 1;
            if left >= n {
                break;
            }
            let right = left + 1;
            let c = if right < n && h[right] > h[left] {
                right
            } else {
                left
            };
            if h[c] <= last {
                break;
            }
            h[i] = h[c];
            i = c;
        }
        h[i] = last;
        Some(Key(top))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use routh_symbolic::Graph;

    /// Every statement once, after its operands; the division's chain first; parts in order.
    #[test]
    fn valid_order_with_the_division_first() {
        let mut g = Graph::new();
        let x = g.var("x");
        let y = g.var("y");
        let z = g.var("z");
        // s = x·x + y·y (the chain to the division), r = 1/s; independent work w = (y·z + z)·z.
        let xx = g.mul(x, x);
        let yy = g.mul(y, y);
        let s = g.add(xx, yy);
        let yz = g.mul(y, z);
        let w0 = g.add(yz, z);
        let w = g.mul(w0, z);
        let r = g.recip(s);
        let out = g.mul(r, w);
        let side = g.add(w, x);
        let plan = Plan::new(&g, &[out, side]);
        let groups = latency_order(&g, &plan, &[&[side], &[out]]);
        // `side` needs w0, yz, w: part 0; the rest part 1.
        let pos = |id: Id| {
            groups
                .iter()
                .flatten()
                .position(|&s| s == id)
                .expect("every statement written")
        };
        let all: Vec<Id> = groups.iter().flatten().copied().collect();
        let stmts: Vec<Id> = plan.statements(&g).collect();
        assert_eq!(all.len(), stmts.len());
        for &id in &all {
            for c in plan.operands(&g, id) {
                if stmts.contains(&c) {
                    assert!(pos(c) < pos(id), "operand after its user");
                }
            }
        }
        assert!(groups[0].contains(&side) && !groups[0].contains(&out));
        // Part 1 starts with the chain to the division, not with what is already done.
        assert_eq!(groups[1][0], xx.min(yy));
    }
}
