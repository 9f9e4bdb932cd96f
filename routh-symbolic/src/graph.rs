//! The hash-consed expression DAG.
//!
//! Every node lives once in a [`Graph`] and is named by an [`Id`]; a node's children always have
//! smaller ids than the node (as in egg's `RecExpr`), so walking ids in increasing order is a
//! topological order, and emitting the nodes reachable from a set of outputs in that order
//! computes every shared subexpression exactly once.
//!
//! Nodes are only ever built through the simplifying constructors ([`Graph::add`],
//! [`Graph::mul`], …), which fold constants, apply the 0/1 identities, put the operands of
//! commutative operations in a canonical order and merge integer powers, so structurally equal
//! expressions get equal ids.

use std::collections::HashMap;
use std::fmt;

/// The name of a node in a [`Graph`].
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Debug)]
pub struct Id(pub(crate) u32);

impl Id {
    /// The index of the node (children have smaller indices than their parents).
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The id of the node at `index` (for walking a graph's nodes in order).
    pub fn from_index(index: usize) -> Self {
        Id(index as u32)
    }
}

/// Unary elementary functions.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub enum Func {
    Sqrt,
    Sin,
    Cos,
    Tan,
    Exp,
    Ln,
    Abs,
    /// The sign function (derivative of `abs`); `signum` with `sign(0) = 0`.
    Sign,
}

impl Func {
    /// The function applied to a number.
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Func::Sqrt => x.sqrt(),
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Exp => x.exp(),
            Func::Ln => x.ln(),
            Func::Abs => x.abs(),
            Func::Sign => {
                if x == 0.0 {
                    0.0
                } else {
                    x.signum()
                }
            }
        }
    }

    /// The method name in Rust's `f64` API (`sign` is emitted specially).
    pub fn name(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Exp => "exp",
            Func::Ln => "ln",
            Func::Abs => "abs",
            Func::Sign => "sign",
        }
    }
}

/// One node of the DAG. Children are [`Id`]s of earlier nodes.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub enum Node {
    /// A constant, stored as the bits of an `f64` (`-0.0` is normalised to `0.0`).
    Const(u64),
    /// An input slot.
    Var(u32),
    /// `a + b`, operands in canonical order.
    Add(Id, Id),
    /// `a * b`, operands in canonical order.
    Mul(Id, Id),
    /// `-a`.
    Neg(Id),
    /// `1 / a`.
    Recip(Id),
    /// `a^n` for an integer `n ∉ {0, 1}`.
    Powi(Id, i32),
    /// `a^b` for a non-constant or non-integer exponent.
    Powf(Id, Id),
    /// `f(a)`.
    Func(Func, Id),
}

impl Node {
    /// The constant value, if this is a constant.
    pub fn as_const(&self) -> Option<f64> {
        match *self {
            Node::Const(bits) => Some(f64::from_bits(bits)),
            _ => None,
        }
    }

    /// The children of the node.
    pub fn children(&self) -> impl Iterator<Item = Id> {
        let (a, b) = match *self {
            Node::Const(_) | Node::Var(_) => (None, None),
            Node::Add(a, b) | Node::Mul(a, b) | Node::Powf(a, b) => (Some(a), Some(b)),
            Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Func(_, a) => (Some(a), None),
        };
        a.into_iter().chain(b)
    }
}

/// A hash-consed expression DAG with simplifying constructors.
#[derive(Clone, Default)]
pub struct Graph {
    nodes: Vec<Node>,
    memo: HashMap<Node, Id>,
    var_names: Vec<String>,
    diff_memo: HashMap<(Id, u32), Id>,
}

impl fmt::Debug for Graph {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Graph")
            .field("nodes", &self.nodes.len())
            .field("vars", &self.var_names)
            .finish()
    }
}

impl Graph {
    /// An empty graph.
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the graph has no nodes.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The node named `id`.
    pub fn node(&self, id: Id) -> Node {
        self.nodes[id.index()]
    }

    /// All nodes, children before parents.
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// Number of input slots created with [`Graph::var`].
    pub fn num_vars(&self) -> usize {
        self.var_names.len()
    }

    /// The name given to input slot `v`.
    pub fn var_name(&self, v: u32) -> &str {
        &self.var_names[v as usize]
    }

    /// The constant value of `id`, if it is a constant.
    pub fn as_const(&self, id: Id) -> Option<f64> {
        self.node(id).as_const()
    }

    /// Whether `id` is the constant `c`.
    pub fn is_const(&self, id: Id, c: f64) -> bool {
        self.as_const(id) == Some(c)
    }

    fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.memo.get(&node) {
            return id;
        }
        let id = Id(u32::try_from(self.nodes.len()).expect("expression graph exceeds u32 nodes"));
        debug_assert!(node.children().all(|c| c < id));
        self.nodes.push(node);
        self.memo.insert(node, id);
        id
    }

    /// A new input slot called `name` (names need not be unique; each call is a new slot).
    pub fn var(&mut self, name: impl Into<String>) -> Id {
        let v = self.var_names.len() as u32;
        self.var_names.push(name.into());
        self.intern(Node::Var(v))
    }

    /// The input slot index of `id`, if it is a variable.
    pub fn as_var(&self, id: Id) -> Option<u32> {
        match self.node(id) {
            Node::Var(v) => Some(v),
            _ => None,
        }
    }

    /// A constant.
    pub fn constant(&mut self, c: f64) -> Id {
        let c = if c == 0.0 { 0.0 } else { c };
        self.intern(Node::Const(c.to_bits()))
    }

    /// `0`.
    pub fn zero(&mut self) -> Id {
        self.constant(0.0)
    }

    /// `1`.
    pub fn one(&mut self) -> Id {
        self.constant(1.0)
    }

    /// Canonical order of commutative operands: constants first, then by id.
    fn order(&self, a: Id, b: Id) -> (Id, Id) {
        match (self.as_const(a).is_some(), self.as_const(b).is_some()) {
            (false, true) => (b, a),
            (true, false) => (a, b),
            _ => (a.min(b), a.max(b)),
        }
    }

    /// `a + b`.
    pub fn add(&mut self, a: Id, b: Id) -> Id {
        let (a, b) = self.order(a, b);
        match (self.node(a), self.node(b)) {
            (Node::Const(x), Node::Const(y)) => {
                return self.constant(f64::from_bits(x) + f64::from_bits(y))
            }
            (Node::Const(x), _) if f64::from_bits(x) == 0.0 => return b,
            // c1 + (c2 + x) = (c1 + c2) + x
            (Node::Const(x), Node::Add(c, rest)) if self.as_const(c).is_some() => {
                let s = self.constant(f64::from_bits(x) + self.as_const(c).unwrap_or(0.0));
                return self.add(s, rest);
            }
            (_, Node::Neg(nb)) if nb == a => return self.zero(),
            (Node::Neg(na), _) if na == b => return self.zero(),
            (Node::Neg(na), Node::Neg(nb)) => {
                let s = self.add(na, nb);
                return self.neg(s);
            }
            // c1·x + c2·x = (c1 + c2)·x: `neg` turns −(c·x) into (−c)·x, so this is what makes
            // c·x − c·x fold to 0.
            (Node::Mul(c1, x), Node::Mul(c2, y)) if x == y => {
                if let (Some(c1), Some(c2)) = (self.as_const(c1), self.as_const(c2)) {
                    let c = self.constant(c1 + c2);
                    return self.mul(c, x);
                }
            }
            _ => {}
        }
        if a == b {
            let two = self.constant(2.0);
            return self.mul(two, a);
        }
        if let Some(s) = self.collect_like_terms(a, b) {
            return s;
        }
        self.intern(Node::Add(a, b))
    }

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
    fn collect_like_terms(&mut self, a: Id, b: Id) -> Option<Id> {
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
        let konst = |c: f64| {
            self.memo
                .get(&Node::Const(if c == 0.0 { 0.0f64 } else { c }.to_bits()))
                .copied()
        };
        let mut new = 0;
        let mut acc: Option<Option<Id>> = if k != 0.0 { Some(konst(k)) } else { None };
        for &(x, c) in merged {
            let c = c / common;
            let term = if c == 1.0 {
                Some(x)
            } else if c == -1.0 {
                self.memo.get(&Node::Neg(x)).copied()
            } else {
                konst(c).and_then(|c| {
                    let (a, b) = self.order(c, x);
                    self.memo.get(&Node::Mul(a, b)).copied()
                })
            };
            if term.is_none() {
                new += 1;
            }
            acc = Some(match (acc, term) {
                (None, t) => t,
                (Some(Some(s)), Some(t)) => {
                    let (a, b) = self.order(s, t);
                    let found = self.memo.get(&Node::Add(a, b)).copied();
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
    fn add_plain(&mut self, a: Id, b: Id) -> Id {
        let (a, b) = self.order(a, b);
        if self.is_const(a, 0.0) {
            return b;
        }
        self.intern(Node::Add(a, b))
    }

    /// `a - b`.
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        let nb = self.neg(b);
        self.add(a, nb)
    }

    /// `-a`.
    pub fn neg(&mut self, a: Id) -> Id {
        match self.node(a) {
            Node::Const(x) => self.constant(-f64::from_bits(x)),
            Node::Neg(x) => x,
            // -(c * x) = (-c) * x
            Node::Mul(c, x) if self.as_const(c).is_some() => {
                let nc = self.constant(-self.as_const(c).unwrap_or(0.0));
                self.mul(nc, x)
            }
            _ => self.intern(Node::Neg(a)),
        }
    }

    /// `a * b`.
    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        let (a, b) = self.order(a, b);
        match (self.node(a), self.node(b)) {
            (Node::Const(x), Node::Const(y)) => {
                return self.constant(f64::from_bits(x) * f64::from_bits(y))
            }
            (Node::Const(x), _) => {
                let x = f64::from_bits(x);
                if x == 0.0 {
                    return a;
                }
                if x == 1.0 {
                    return b;
                }
                if x == -1.0 {
                    return self.neg(b);
                }
                match self.node(b) {
                    // c1 * (c2 * y) = (c1 c2) * y
                    Node::Mul(c, y) if self.as_const(c).is_some() => {
                        let p = self.constant(x * self.as_const(c).unwrap_or(0.0));
                        return self.mul(p, y);
                    }
                    Node::Neg(y) => {
                        let p = self.constant(-x);
                        return self.mul(p, y);
                    }
                    _ => {}
                }
            }
            (Node::Neg(x), _) => {
                let p = self.mul(x, b);
                return self.neg(p);
            }
            (_, Node::Neg(y)) => {
                let p = self.mul(a, y);
                return self.neg(p);
            }
            _ => {}
        }
        // Merge integer powers of the same base (before pulling constants out, so that
        // e·e = e² and e·(1/e) = 1 also when e = c·x).
        let (ba, ea) = self.base_exp(a);
        let (bb, eb) = self.base_exp(b);
        if ba == bb {
            if let Some(e) = ea
                .checked_add(eb)
                .filter(|e| e.unsigned_abs() <= Self::MAX_POW)
            {
                return self.powi(ba, e);
            }
        }
        // Pull constant factors to the front: x * (c * y) = c * (x * y).
        if let Node::Mul(c, y) = self.node(b) {
            if let Some(cv) = self.as_const(c) {
                let p = self.mul(a, y);
                let c = self.constant(cv);
                return self.mul(c, p);
            }
        }
        if let Node::Mul(c, x) = self.node(a) {
            if let Some(cv) = self.as_const(c) {
                let p = self.mul(x, b);
                let c = self.constant(cv);
                return self.mul(c, p);
            }
        }
        self.intern(Node::Mul(a, b))
    }

    /// `(base, n)` with `id = base^n` (`n = 1` for anything that is not a power).
    fn base_exp(&self, id: Id) -> (Id, i32) {
        match self.node(id) {
            Node::Powi(b, n) => (b, n),
            Node::Recip(b) => match self.node(b) {
                Node::Powi(bb, n) => (bb, -n),
                _ => (b, -1),
            },
            _ => (id, 1),
        }
    }

    /// `1 / a`.
    pub fn recip(&mut self, a: Id) -> Id {
        match self.node(a) {
            Node::Const(x) => self.constant(1.0 / f64::from_bits(x)),
            Node::Recip(x) => x,
            Node::Neg(x) => {
                let r = self.recip(x);
                self.neg(r)
            }
            Node::Powi(x, n) => self.powi(x, -n),
            _ => self.intern(Node::Recip(a)),
        }
    }

    /// `a / b`.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        let rb = self.recip(b);
        self.mul(a, rb)
    }

    /// Largest |n| kept as an integer power; larger exponents become `powf` with a constant
    /// exponent, so that exponent arithmetic can never overflow.
    pub const MAX_POW: u32 = 1 << 16;

    /// `a^n` for an integer `n`.
    pub fn powi(&mut self, a: Id, n: i32) -> Id {
        if n.unsigned_abs() > Self::MAX_POW {
            if let Some(x) = self.as_const(a) {
                return self.constant(x.powi(n));
            }
            let e = self.constant(f64::from(n));
            return self.intern(Node::Powf(a, e));
        }
        match n {
            0 => return self.one(),
            1 => return a,
            _ => {}
        }
        match self.node(a) {
            Node::Const(x) => return self.constant(f64::from_bits(x).powi(n)),
            Node::Powi(_, _) | Node::Recip(_) => {
                let (b, e) = self.base_exp(a);
                if let Some(m) = e
                    .checked_mul(n)
                    .filter(|m| m.unsigned_abs() <= Self::MAX_POW)
                {
                    return self.powi(b, m);
                }
            }
            Node::Neg(x) => {
                let p = self.powi(x, n);
                return if n % 2 == 0 { p } else { self.neg(p) };
            }
            _ => {}
        }
        match n {
            -1 => self.intern(Node::Recip(a)),
            _ if n < 0 => {
                let p = self.powi(a, -n);
                self.intern(Node::Recip(p))
            }
            _ => self.intern(Node::Powi(a, n)),
        }
    }

    /// `a^b`: an integer constant exponent becomes [`Graph::powi`], `½` becomes `sqrt`.
    pub fn powf(&mut self, a: Id, b: Id) -> Id {
        if let Some(e) = self.as_const(b) {
            if e.fract() == 0.0 && e.abs() <= 64.0 {
                return self.powi(a, e as i32);
            }
            if e == 0.5 {
                return self.func(Func::Sqrt, a);
            }
            if let Some(x) = self.as_const(a) {
                return self.constant(x.powf(e));
            }
        }
        self.intern(Node::Powf(a, b))
    }

    /// `f(a)`.
    pub fn func(&mut self, f: Func, a: Id) -> Id {
        if let Some(x) = self.as_const(a) {
            return self.constant(f.apply(x));
        }
        match (f, self.node(a)) {
            (Func::Abs, Node::Neg(x)) => return self.func(Func::Abs, x),
            (Func::Abs, Node::Func(Func::Abs | Func::Sqrt | Func::Exp, _)) => return a,
            (Func::Sign, Node::Neg(x)) => {
                let s = self.func(Func::Sign, x);
                return self.neg(s);
            }
            // ln(exp x) = x (but exp(ln x) ≠ x for x < 0).
            (Func::Ln, Node::Func(Func::Exp, x)) => return x,
            (Func::Sqrt, Node::Powi(x, 2)) => return self.func(Func::Abs, x),
            _ => {}
        }
        self.intern(Node::Func(f, a))
    }

    /// Sum of many terms (`0` for none).
    pub fn sum(&mut self, terms: impl IntoIterator<Item = Id>) -> Id {
        let mut acc: Option<Id> = None;
        for t in terms {
            acc = Some(match acc {
                None => t,
                Some(s) => self.add(s, t),
            });
        }
        acc.unwrap_or_else(|| self.zero())
    }

    /// `∂f/∂x` for a variable `x`, memoised.
    ///
    /// Returns `None` if `x` is not a variable.
    pub fn diff(&mut self, f: Id, x: Id) -> Option<Id> {
        let v = self.as_var(x)?;
        Some(self.diff_var(f, v))
    }

    fn diff_var(&mut self, f: Id, v: u32) -> Id {
        // Iterative post-order so that deep expressions cannot overflow the stack.
        let mut stack = vec![(f, false)];
        while let Some((id, ready)) = stack.pop() {
            if self.diff_memo.contains_key(&(id, v)) {
                continue;
            }
            if !ready {
                stack.push((id, true));
                for c in self.node(id).children() {
                    if !self.diff_memo.contains_key(&(c, v)) {
                        stack.push((c, false));
                    }
                }
                continue;
            }
            let d = self.diff_node(id, v);
            self.diff_memo.insert((id, v), d);
        }
        self.diff_memo[&(f, v)]
    }

    fn diff_node(&mut self, id: Id, v: u32) -> Id {
        let d = |g: &Self, c: Id| g.diff_memo[&(c, v)];
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

    /// Replaces variables by expressions (`map[v]` for slot `v`, `None` keeps the variable).
    /// Returns the images of `roots`.
    pub fn substitute(&mut self, roots: &[Id], map: &HashMap<u32, Id>) -> Vec<Id> {
        let Some(max) = roots.iter().max() else {
            return Vec::new();
        };
        let mut image: Vec<Id> = Vec::with_capacity(max.index() + 1);
        for i in 0..=max.index() {
            let node = self.nodes[i];
            let m = |c: Id| image[c.index()];
            let new = match node {
                Node::Const(_) => Id(i as u32),
                Node::Var(v) => map.get(&v).copied().unwrap_or(Id(i as u32)),
                Node::Add(a, b) => {
                    let (a, b) = (m(a), m(b));
                    self.add(a, b)
                }
                Node::Mul(a, b) => {
                    let (a, b) = (m(a), m(b));
                    self.mul(a, b)
                }
                Node::Neg(a) => {
                    let a = m(a);
                    self.neg(a)
                }
                Node::Recip(a) => {
                    let a = m(a);
                    self.recip(a)
                }
                Node::Powi(a, n) => {
                    let a = m(a);
                    self.powi(a, n)
                }
                Node::Powf(a, b) => {
                    let (a, b) = (m(a), m(b));
                    self.powf(a, b)
                }
                Node::Func(f, a) => {
                    let a = m(a);
                    self.func(f, a)
                }
            };
            image.push(new);
        }
        roots.iter().map(|r| image[r.index()]).collect()
    }

    /// For every node up to `root`, whether it depends on any of `vars`.
    pub fn depends_on(&self, root: Id, vars: &[u32]) -> bool {
        let mut dep = vec![false; root.index() + 1];
        for i in 0..=root.index() {
            dep[i] = match self.nodes[i] {
                Node::Var(v) => vars.contains(&v),
                n => n.children().any(|c| dep[c.index()]),
            };
        }
        dep[root.index()]
    }

    /// Evaluates `roots` with variable slot `v` set to `inputs[v]`.
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
                Node::Var(v) => inputs[v as usize],
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
