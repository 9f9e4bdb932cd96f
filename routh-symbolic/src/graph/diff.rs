//! Symbolic differentiation, memoised per (node, variable) in the graph.

use super::{Func, Graph, Id, Node, Var};

impl Graph {
    /// `∂f/∂v`, memoised: asking again, or for a subexpression already differentiated by `v`,
    /// adds no nodes.
    ///
    /// `v` is a [`Var`], not any [`Id`]: a derivative is only defined with respect to a variable,
    /// and an `Option` result for "not a variable" let callers fall back to some other node (`f`
    /// itself, or zero) and carry on with a wrong derivative. Whether a node is a variable is
    /// decided once, by [`Graph::as_var`], where the caller has to handle `None`; after that,
    /// differentiation cannot fail.
    pub fn diff(&mut self, f: Id, v: Var) -> Id {
        if let Some(d) = self.diff_memoised(f, v) {
            return d;
        }
        // Iterative post-order so that deep expressions cannot overflow the stack.
        let mut stack = vec![(f, false)];
        while let Some((id, ready)) = stack.pop() {
            if self.diff_memoised(id, v).is_some() {
                continue;
            }
            if !ready {
                stack.push((id, true));
                for c in self.node(id).children() {
                    if self.diff_memoised(c, v).is_none() {
                        stack.push((c, false));
                    }
                }
                continue;
            }
            let d = self.diff_node(id, v);
            let memo = &mut self.diff_memo[v.index()];
            if memo.len() <= id.index() {
                memo.resize(id.index() + 1, Id::NONE);
            }
            memo[id.index()] = d;
        }
        self.diff_memo[v.index()][f.index()]
    }

    /// `∂f/∂v` if already computed.
    fn diff_memoised(&mut self, f: Id, v: Var) -> Option<Id> {
        if self.diff_memo.len() <= v.index() {
            self.diff_memo.resize_with(v.index() + 1, Vec::new);
        }
        match self.diff_memo[v.index()].get(f.index()) {
            Some(&d) if d != Id::NONE => Some(d),
            _ => None,
        }
    }

    /// The derivative of node `id` by `v`, its children's derivatives being memoised already.
    fn diff_node(&mut self, id: Id, v: Var) -> Id {
        let d = |g: &Self, c: Id| g.diff_memo[v.index()][c.index()];
        match self.node(id) {
            Node::Const(_) => self.zero(),
            Node::Var(w) => self.constant(if w == v { 1.0 } else { 0.0 }),
            Node::Add(a, b) => {
                let (da, db) = (d(self, a), d(self, b));
                self.add(da, db)
            }
            Node::Mul(a, b) => {
                let (da, db) = (d(self, a), d(self, b));
                let l = self.mul(da, b);
                let r = self.mul(a, db);
                self.add(l, r)
            }
            Node::Neg(a) => {
                let da = d(self, a);
                self.neg(da)
            }
            Node::Recip(a) => {
                // d(1/a) = -da / a² = -da · (1/a)²
                let da = d(self, a);
                if self.is_const(da, 0.0) {
                    return da;
                }
                let r2 = self.powi(id, 2);
                let p = self.mul(da, r2);
                self.neg(p)
            }
            Node::Powi(a, n) => {
                let da = d(self, a);
                if self.is_const(da, 0.0) {
                    return da;
                }
                let p = self.powi(a, n - 1);
                let c = self.constant(f64::from(n));
                let cp = self.mul(c, p);
                self.mul(cp, da)
            }
            Node::Powf(a, b) => {
                // d(a^b) = a^b (db ln a + b da / a)
                let (da, db) = (d(self, a), d(self, b));
                let ln_a = self.func(Func::Ln, a);
                let t1 = self.mul(db, ln_a);
                let bda = self.mul(b, da);
                let t2 = self.div(bda, a);
                let s = self.add(t1, t2);
                self.mul(id, s)
            }
            Node::Func(f, a) => {
                let da = d(self, a);
                if self.is_const(da, 0.0) {
                    return da;
                }
                let fp = match f {
                    Func::Sqrt => {
                        let half = self.constant(0.5);
                        let r = self.recip(id);
                        self.mul(half, r)
                    }
                    Func::Sin => self.func(Func::Cos, a),
                    Func::Cos => {
                        let s = self.func(Func::Sin, a);
                        self.neg(s)
                    }
                    Func::Tan => {
                        let one = self.one();
                        let t2 = self.powi(id, 2);
                        self.add(one, t2)
                    }
                    Func::Exp => id,
                    Func::Ln => self.recip(a),
                    Func::Abs => self.func(Func::Sign, a),
                    Func::Sign => return self.zero(),
                };
                self.mul(fp, da)
            }
        }
    }
}
