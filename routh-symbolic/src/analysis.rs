//! Analyses of expressions: polynomial degree in a set of variables, scheduling of outputs,
//! operation counts and a plain-text printer.

use crate::graph::{Graph, Id, Node, Var};

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

/// The degree of `root` in the variables `vars` (constants and other variables count as
/// coefficients).
///
/// The analysis is structural on the simplified DAG: `ω·ω − ω·ω` has already folded to `0`
/// (degree 0 here), while an expression that is polynomial only after cancellations it cannot
/// see (e.g. `sqrt(ω·ω)²` written through a root) is reported as not polynomial.
pub fn degree(g: &Graph, root: Id, vars: &[Var]) -> Degree {
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

/// The children of a node, as a pair.
fn kids(node: Node) -> (Option<Id>, Option<Id>) {
    match node {
        Node::Const(_) | Node::Var(_) => (None, None),
        Node::Add(a, b) | Node::Mul(a, b) | Node::Powf(a, b) => (Some(a), Some(b)),
        Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Func(_, a) => (Some(a), None),
    }
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
    /// The nodes [`Plan::emit`] marks, in increasing id: a generator walks these rather than
    /// the whole of `emit` (once per generated method, unoptimised in a user's debug build).
    pub emitted: Vec<Id>,
}

impl Plan {
    /// The plan for `outputs`.
    pub fn new(g: &Graph, outputs: &[Id]) -> Plan {
        // Plain loops over `kids`: this runs once per generated method, unoptimised in a
        // user's debug build.
        let nodes = g.nodes();
        let n = outputs.iter().max().map_or(0, |m| m.index() + 1);
        let mut needed = vec![false; n];
        for o in outputs {
            needed[o.index()] = true;
        }
        let mut uses = vec![0u32; n];
        // Backwards by hand, without `rev()` or `flatten()` (each a call per step unoptimised).
        let mut i = n;
        while i > 0 {
            i -= 1;
            if needed[i] {
                let (a, b) = kids(nodes[i]);
                if let Some(c) = a {
                    needed[c.index()] = true;
                    uses[c.index()] += 1;
                }
                if let Some(c) = b {
                    needed[c.index()] = true;
                    uses[c.index()] += 1;
                }
            }
        }
        for o in outputs {
            uses[o.index()] += 1;
        }
        let mut plan = Plan {
            uses,
            emit: vec![false; n],
            emitted: Vec::new(),
        };
        for o in outputs {
            plan.emit[o.index()] = true;
        }
        let mut i = n;
        while i > 0 {
            i -= 1;
            if plan.emit[i] {
                // Final: only the nodes after it (its users) mark it.
                let id = Id::from_index(i);
                plan.emitted.push(id);
                let (a, b) = kids(nodes[i]);
                if let Some(c) = a {
                    let c = plan.folds(g, id, c).unwrap_or(c);
                    plan.emit[c.index()] = true;
                }
                if let Some(c) = b {
                    let c = plan.folds(g, id, c).unwrap_or(c);
                    plan.emit[c.index()] = true;
                }
            }
        }
        plan.emitted.reverse();
        plan
    }

    /// Whether `child`, an operand of `parent`, is folded into it (written as `a - x` for
    /// `a + (−x)`, or `a / x` for `a · (1/x)` when the reciprocal is used once).
    ///
    /// At most one operand is folded: the second when both could be (`(−y) + (−x)` is written
    /// `a - x` with `a = −y` a statement of its own), none when both are the same node.
    pub fn folds(&self, g: &Graph, parent: Id, child: Id) -> Option<Id> {
        // Called for every operand of every statement, several times: the cheap tests first.
        let nodes = g.nodes();
        if !matches!(nodes[child.index()], Node::Neg(_) | Node::Recip(_)) {
            return None;
        }
        let (add, b) = match nodes[parent.index()] {
            Node::Add(a, b) if a != b => (true, b),
            Node::Mul(a, b) if a != b => (false, b),
            _ => return None,
        };
        let fold = |c: Id| match nodes[c.index()] {
            Node::Neg(x) if add => Some(x),
            Node::Recip(x) if !add && self.uses[c.index()] == 1 => Some(x),
            _ => None,
        };
        let x = fold(child)?;
        (child == b || fold(b).is_none()).then_some(x)
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
    let with = needed_operations(g, &roots);
    with - needed_operations(g, base)
}

/// `schedule(g, outputs).len()`, counted in plain loops (it runs on the whole graph for each
/// candidate form of R, unoptimised in a user's debug build).
fn needed_operations(g: &Graph, outputs: &[Id]) -> usize {
    let Some(max) = outputs.iter().max() else {
        return 0;
    };
    let nodes = g.nodes();
    let mut need = vec![false; max.index() + 1];
    for o in outputs {
        need[o.index()] = true;
    }
    let mut count = 0;
    let mut i = need.len();
    while i > 0 {
        i -= 1;
        if !need[i] {
            continue;
        }
        let (a, b) = kids(nodes[i]);
        if let Some(a) = a {
            need[a.index()] = true;
        }
        if let Some(b) = b {
            need[b.index()] = true;
        }
        if a.is_some() {
            count += 1;
        }
    }
    count
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

/// Prints `root` as an infix formula, with variables named by `Graph::var_name`: sums are
/// written with their signs (`a - 0.5·b`), products with their numerator and denominator
/// (`a·b / (c·d)`). Shared subexpressions are printed in full, so keep this for formulas of a
/// modest size (an amended potential, say).
pub fn to_infix(g: &Graph, root: Id) -> String {
    // Printing expands the DAG into a tree, which can be exponentially larger: refuse beyond a
    // size that is still readable.
    const MAX_TREE: u64 = 4000;
    let mut size = vec![0u64; root.index() + 1];
    for i in 0..=root.index() {
        size[i] = g.nodes()[i]
            .children()
            .fold(1u64, |acc, c| acc.saturating_add(size[c.index()]));
    }
    if size[root.index()] > MAX_TREE {
        return format!(
            "(a formula of more than {MAX_TREE} terms, not printed; {} distinct subexpressions)",
            schedule(g, &[root]).len()
        );
    }
    let mut s = String::new();
    write_expr(g, root, &mut s, 0);
    s
}

/// Binding strength: 1 sums, 2 products and quotients, 3 unary minus, 4 powers, 5 atoms.
fn write_expr(g: &Graph, id: Id, out: &mut String, parent: u8) {
    let (prec, text) = match g.node(id) {
        Node::Add(..) => (1, sum_text(g, id, false)),
        Node::Mul(..) | Node::Recip(_) => {
            let (negative, body) = product_text(g, id);
            if negative {
                (3, format!("-{body}"))
            } else {
                (2, body)
            }
        }
        Node::Neg(x) if matches!(g.node(x), Node::Add(..)) => (1, sum_text(g, x, true)),
        Node::Neg(x) => {
            let mut t = String::from("-");
            write_expr(g, x, &mut t, 3);
            (3, t)
        }
        Node::Const(b) => {
            let c = f64::from_bits(b);
            (if c < 0.0 { 3 } else { 5 }, format!("{c}"))
        }
        Node::Var(v) => (5, g.var_name(v).to_string()),
        Node::Powi(x, n) => {
            let mut t = String::new();
            write_expr(g, x, &mut t, 5);
            (4, format!("{t}^{n}"))
        }
        Node::Powf(x, e) => {
            let (mut t, mut u) = (String::new(), String::new());
            write_expr(g, x, &mut t, 5);
            write_expr(g, e, &mut u, 5);
            (4, format!("{t}^{u}"))
        }
        Node::Func(f, x) => {
            let mut t = String::new();
            write_expr(g, x, &mut t, 0);
            (5, format!("{}({t})", f.name()))
        }
    };
    if prec < parent {
        out.push('(');
        out.push_str(&text);
        out.push(')');
    } else {
        out.push_str(&text);
    }
}

/// The terms of a sum (negated if `negate`), each with its sign.
fn sum_text(g: &Graph, id: Id, negate: bool) -> String {
    fn terms(g: &Graph, id: Id, acc: &mut Vec<Id>) {
        match g.node(id) {
            Node::Add(a, b) => {
                terms(g, a, acc);
                terms(g, b, acc);
            }
            _ => acc.push(id),
        }
    }
    let mut ts = Vec::new();
    terms(g, id, &mut ts);
    let mut out = String::new();
    for (k, t) in ts.into_iter().enumerate() {
        let mut body = String::new();
        let negative = match g.node(t) {
            Node::Neg(x) => {
                write_expr(g, x, &mut body, 2);
                true
            }
            Node::Const(b) if f64::from_bits(b) < 0.0 => {
                body = format!("{}", -f64::from_bits(b));
                true
            }
            Node::Mul(..) => {
                let (negative, text) = product_text(g, t);
                body = text;
                negative
            }
            _ => {
                write_expr(g, t, &mut body, 2);
                false
            }
        };
        match (k, negative != negate) {
            (0, true) => out.push('-'),
            (0, false) => {}
            (_, true) => out.push_str(" - "),
            (_, false) => out.push_str(" + "),
        }
        out.push_str(&body);
    }
    out
}

/// A product as `(negative, "num / den")` with the constant factor in front.
fn product_text(g: &Graph, id: Id) -> (bool, String) {
    fn factors(g: &Graph, id: Id, coef: &mut f64, num: &mut Vec<Id>, den: &mut Vec<Id>) {
        match g.node(id) {
            Node::Mul(a, b) => {
                factors(g, a, coef, num, den);
                factors(g, b, coef, num, den);
            }
            Node::Neg(x) => {
                *coef = -*coef;
                factors(g, x, coef, num, den);
            }
            Node::Const(b) => *coef *= f64::from_bits(b),
            Node::Recip(x) => den.push(x),
            _ => num.push(id),
        }
    }
    let (mut coef, mut num, mut den) = (1.0, Vec::new(), Vec::new());
    factors(g, id, &mut coef, &mut num, &mut den);
    // Equal factors are written as a power: x·x → x^2.
    let join = |ids: &[Id], wrap_all: bool| {
        let mut t = String::new();
        let mut seen: Vec<Id> = Vec::new();
        for &f in ids {
            if seen.contains(&f) {
                continue;
            }
            seen.push(f);
            if seen.len() > 1 {
                t.push('·');
            }
            let n = ids.iter().filter(|&&x| x == f).count();
            if n > 1 {
                write_expr(g, f, &mut t, 5);
                t.push_str(&format!("^{n}"));
            } else {
                write_expr(g, f, &mut t, if wrap_all { 3 } else { 2 });
            }
        }
        t
    };
    let mut text = String::new();
    if coef.abs() != 1.0 || num.is_empty() {
        text.push_str(&format!("{}", coef.abs()));
        if !num.is_empty() {
            text.push('·');
        }
    }
    text.push_str(&join(&num, false));
    if !den.is_empty() {
        text.push_str(" / ");
        if den.len() == 1 {
            write_expr(g, den[0], &mut text, 3);
        } else {
            text.push('(');
            text.push_str(&join(&den, false));
            text.push(')');
        }
    }
    (coef < 0.0, text)
}
