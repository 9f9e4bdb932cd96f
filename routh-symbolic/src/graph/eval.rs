//! Walks that compute one value per node: numerical evaluation (the interpreter tests use) and
//! dependence on a set of variables.

use super::{Graph, Id, Node, Var};

impl Graph {
    /// Whether `root` depends on any of `vars` (structurally: through any of its descendants).
    pub fn depends_on(&self, root: Id, vars: &[Var]) -> bool {
        self.dependence(root, vars)[root.index()]
    }

    /// For every node up to `root` (by index), whether it depends on any of `vars`: one walk
    /// that answers [`Graph::depends_on`] for all of them.
    pub fn dependence(&self, root: Id, vars: &[Var]) -> Vec<bool> {
        let mut dep = vec![false; root.index() + 1];
        for i in 0..=root.index() {
            dep[i] = match self.nodes[i] {
                Node::Var(v) => vars.contains(&v),
                n => n.children().any(|c| dep[c.index()]),
            };
        }
        dep
    }

    /// Evaluates `roots` with variable `v` set to `inputs[v.index()]`.
    ///
    /// # Panics
    /// If `inputs` is shorter than the number of variable slots used.
    pub fn eval(&self, roots: &[Id], inputs: &[f64]) -> Vec<f64> {
        let Some(max) = roots.iter().max() else {
            return Vec::new();
        };
        let mut val = Vec::with_capacity(max.index() + 1);
        for i in 0..=max.index() {
            let x = |c: Id| -> f64 { val[c.index()] };
            let r = match self.nodes[i] {
                Node::Const(b) => f64::from_bits(b),
                Node::Var(v) => inputs[v.index()],
                Node::Add(a, b) => x(a) + x(b),
                Node::Mul(a, b) => x(a) * x(b),
                Node::Neg(a) => -x(a),
                Node::Recip(a) => 1.0 / x(a),
                Node::Powi(a, n) => x(a).powi(n),
                Node::Powf(a, b) => x(a).powf(x(b)),
                Node::Func(f, a) => f.apply(x(a)),
            };
            val.push(r);
        }
        roots.iter().map(|r| val[r.index()]).collect()
    }
}
