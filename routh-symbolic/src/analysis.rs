//! Analyses of expressions: polynomial degree in a set of variables, scheduling of outputs,
//! operation counts and a plain-text printer.

use crate::graph::{Func, Graph, Id, Node};

/// The degree of an expression in a set of variables.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Degree {
    /// A homogeneous polynomial of this degree in the variables (degree 0: free of them).
    Homogeneous(u32),
    /// A polynomial in the variables, but not homogeneous.
    Mixed,
    /// Not a polynomial in the variables (a quotient, root or elementary function of them).
    NotPolynomial,
}

/// The degree of `root` in the variable slots `vars` (constants and other variables count as
/// coefficients).
///
/// The analysis is structural on the simplified DAG: `ω·ω − ω·ω` has already folded to `0`
/// (degree 0 here), while an expression that is polynomial only after cancellations it cannot
/// see (e.g. `sqrt(ω·ω)²` written through a root) is reported as not polynomial.
pub fn degree(g: &Graph, root: Id, vars: &[u32]) -> Degree {
    use Degree::*;
    let mut deg: Vec<Degree> = Vec::with_capacity(root.index() + 1);
    for i in 0..=root.index() {
        let d = |c: Id| deg[c.index()];
        let node = g.nodes()[i];
        let r = match node {
            Node::Const(_) => Homogeneous(0),
            Node::Var(v) => Homogeneous(u32::from(vars.contains(&v))),
            Node::Add(a, b) => match (d(a), d(b)) {
                (NotPolynomial, _) | (_, NotPolynomial) => NotPolynomial,
                (Homogeneous(x), Homogeneous(y)) if x == y => Homogeneous(x),
                _ => Mixed,
            },
            Node::Mul(a, b) => match (d(a), d(b)) {
                (NotPolynomial, _) | (_, NotPolynomial) => NotPolynomial,
                (Homogeneous(x), Homogeneous(y)) => Homogeneous(x.saturating_add(y)),
                _ => Mixed,
            },
            Node::Neg(a) => d(a),
            Node::Powi(a, n) => match d(a) {
                Homogeneous(0) => Homogeneous(0),
                Homogeneous(x) if n > 0 => Homogeneous(x.saturating_mul(n.unsigned_abs())),
                Mixed if n > 0 => Mixed,
                _ => NotPolynomial,
            },
            Node::Recip(a) | Node::Func(_, a) => match d(a) {
                Homogeneous(0) => Homogeneous(0),
                _ => NotPolynomial,
            },
            Node::Powf(a, b) => match (d(a), d(b)) {
                (Homogeneous(0), Homogeneous(0)) => Homogeneous(0),
                _ => NotPolynomial,
            },
        };
        deg.push(r);
    }
    deg[root.index()]
}

/// The non-leaf nodes needed to compute `outputs`, children before parents (increasing id):
/// emitting them in this order computes each shared subexpression once.
pub fn schedule(g: &Graph, outputs: &[Id]) -> Vec<Id> {
    let Some(max) = outputs.iter().max() else {
        return Vec::new();
    };
    let mut need = vec![false; max.index() + 1];
    for o in outputs {
        need[o.index()] = true;
    }
    for i in (0..=max.index()).rev() {
        if need[i] {
            for c in g.nodes()[i].children() {
                need[c.index()] = true;
            }
        }
    }
    (0..=max.index())
        .filter(|&i| need[i] && !matches!(g.nodes()[i], Node::Const(_) | Node::Var(_)))
        .map(Id::from_index)
        .collect()
}

/// What straight-line code for a set of outputs computes: the nodes to emit (children before
/// parents) and how each is written. A negation feeding a sum is written as a subtraction, a
/// reciprocal used once as a division; such folded nodes are not emitted on their own.
#[derive(Clone, Debug)]
pub struct Plan {
    /// Number of uses of each node by the nodes the outputs need (outputs count one more).
    pub uses: Vec<u32>,
    /// Whether each node is emitted as a statement (constants and variables included).
    pub emit: Vec<bool>,
}

impl Plan {
    /// The plan for `outputs`.
    pub fn new(g: &Graph, outputs: &[Id]) -> Plan {
        let n = outputs.iter().max().map_or(0, |m| m.index() + 1);
        let mut needed = vec![false; n];
        for o in outputs {
            needed[o.index()] = true;
        }
        for i in (0..n).rev() {
            if needed[i] {
                for c in g.nodes()[i].children() {
                    needed[c.index()] = true;
                }
            }
        }
        let mut uses = vec![0u32; n];
        for i in (0..n).filter(|&i| needed[i]) {
            for c in g.nodes()[i].children() {
                uses[c.index()] += 1;
            }
        }
        for o in outputs {
            uses[o.index()] += 1;
        }
        let mut plan = Plan {
            uses,
            emit: vec![false; n],
        };
        for o in outputs {
            plan.emit[o.index()] = true;
        }
        for i in (0..n).rev() {
            if plan.emit[i] {
                for c in plan.operands(g, Id::from_index(i)) {
                    plan.emit[c.index()] = true;
                }
            }
        }
        plan
    }

    /// Whether `child`, an operand of `parent`, is folded into it (written as `a - x` for
    /// `a + (−x)`, or `a / x` for `a · (1/x)` when the reciprocal is used once).
    pub fn folds(&self, g: &Graph, parent: Id, child: Id) -> Option<Id> {
        match (g.node(parent), g.node(child)) {
            (Node::Add(..), Node::Neg(x)) => Some(x),
            (Node::Mul(..), Node::Recip(x)) if self.uses[child.index()] == 1 => Some(x),
            _ => None,
        }
    }

    /// The values a node reads when written out (folded children replaced by their operand).
    pub fn operands(&self, g: &Graph, id: Id) -> Vec<Id> {
        g.node(id)
            .children()
            .map(|c| self.folds(g, id, c).unwrap_or(c))
            .collect()
    }

    /// The emitted non-leaf nodes, in order.
    pub fn statements<'a>(&'a self, g: &'a Graph) -> impl Iterator<Item = Id> + 'a {
        self.emit
            .iter()
            .enumerate()
            .filter(|(_, &e)| e)
            .map(|(i, _)| Id::from_index(i))
            .filter(|&id| !matches!(g.node(id), Node::Const(_) | Node::Var(_)))
    }
}

/// The number of operation nodes `candidate` needs beyond those `base` already needs: what
/// computing `candidate` next to `base` adds. Used to choose the cheaper of two exactly equal
/// formulations.
pub fn extra_cost(g: &Graph, candidate: Id, base: &[Id]) -> usize {
    let mut roots = base.to_vec();
    roots.push(candidate);
    let with = schedule(g, &roots).len();
    with - schedule(g, base).len()
}

/// Floating-point operations of the straight-line code written for a [`Plan`]: a subtraction
/// counts as an addition, an integer power `x^n` (n = 2, 3) as `n − 1` multiplications and a
/// larger one as a call.
#[derive(Copy, Clone, Default, PartialEq, Eq, Debug)]
pub struct OpCounts {
    pub add: usize,
    pub mul: usize,
    pub neg: usize,
    pub div: usize,
    pub func: usize,
}

impl OpCounts {
    /// Every operation counted once.
    pub fn total(&self) -> usize {
        self.add + self.mul + self.neg + self.div + self.func
    }
}

impl std::fmt::Display for OpCounts {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} ops ({} add/sub, {} mul, {} neg, {} div, {} calls)",
            self.total(),
            self.add,
            self.mul,
            self.neg,
            self.div,
            self.func
        )
    }
}

/// Counts the operations of the code written for `outputs`.
pub fn op_counts(g: &Graph, outputs: &[Id]) -> OpCounts {
    let plan = Plan::new(g, outputs);
    let mut c = OpCounts::default();
    for id in plan.statements(g) {
        match g.node(id) {
            Node::Add(..) => c.add += 1,
            Node::Mul(a, b) => {
                if plan.folds(g, id, a).is_some() || plan.folds(g, id, b).is_some() {
                    c.div += 1
                } else {
                    c.mul += 1
                }
            }
            Node::Neg(_) => c.neg += 1,
            Node::Recip(_) => c.div += 1,
            Node::Powi(_, n) if (2..=3).contains(&n) => c.mul += n as usize - 1,
            Node::Powi(..) | Node::Powf(..) | Node::Func(..) => c.func += 1,
            Node::Const(_) | Node::Var(_) => {}
        }
    }
    c
}

/// Prints `root` as an infix formula, with variables named by `Graph::var_name`.
/// Shared subexpressions are printed in full, so keep this for small expressions.
pub fn to_infix(g: &Graph, root: Id) -> String {
    fn prec(n: &Node) -> u8 {
        match n {
            Node::Add(..) => 1,
            Node::Mul(..) | Node::Recip(_) => 2,
            Node::Neg(_) => 3,
            Node::Powi(..) | Node::Powf(..) => 4,
            Node::Const(b) if f64::from_bits(*b) < 0.0 => 3,
            _ => 5,
        }
    }
    fn go(g: &Graph, id: Id, out: &mut String, parent: u8) {
        let node = g.node(id);
        let p = prec(&node);
        let paren = p < parent;
        if paren {
            out.push('(');
        }
        match node {
            Node::Const(b) => out.push_str(&format!("{}", f64::from_bits(b))),
            Node::Var(v) => out.push_str(g.var_name(v)),
            Node::Add(a, b) => {
                go(g, a, out, 1);
                if let Node::Neg(nb) = g.node(b) {
                    out.push_str(" - ");
                    go(g, nb, out, 2);
                } else {
                    out.push_str(" + ");
                    go(g, b, out, 1);
                }
            }
            Node::Mul(a, b) => {
                if let Node::Recip(d) = g.node(b) {
                    go(g, a, out, 2);
                    out.push_str(" / ");
                    go(g, d, out, 3);
                } else {
                    go(g, a, out, 2);
                    out.push('·');
                    go(g, b, out, 2);
                }
            }
            Node::Neg(a) => {
                out.push('-');
                go(g, a, out, 3);
            }
            Node::Recip(a) => {
                out.push_str("1 / ");
                go(g, a, out, 3);
            }
            Node::Powi(a, n) => {
                go(g, a, out, 5);
                out.push_str(&format!("^{n}"));
            }
            Node::Powf(a, b) => {
                go(g, a, out, 5);
                out.push('^');
                go(g, b, out, 5);
            }
            Node::Func(f, a) => {
                out.push_str(match f {
                    Func::Sign => "sign",
                    f => f.name(),
                });
                out.push('(');
                go(g, a, out, 0);
                out.push(')');
            }
        }
        if paren {
            out.push(')');
        }
    }
    let mut s = String::new();
    go(g, root, &mut s, 0);
    s
}
