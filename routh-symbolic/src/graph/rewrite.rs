//! The simplifying constructors: every node is built through one of these, which fold constants,
//! apply the 0/1 identities, put the operands of commutative operations in a canonical order and
//! merge integer powers, so that structurally equal expressions get equal ids. Sums go on to
//! [`collect`](super::collect) for like terms; [`Graph::substitute`] rebuilds through them.

use super::{Func, Graph, Id, Node, Var};
use std::collections::HashMap;

impl Graph {
    /// Canonical order of commutative operands: constants first, then by id.
    pub(super) fn order(&self, a: Id, b: Id) -> (Id, Id) {
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
        if let Some(s) = self.reassociate(a, b) {
            return s;
        }
        self.intern(Node::Add(a, b))
    }

    /// `(x + y) + b = (x + b) + y` (and `2x + b = (x + b) + x`) when the partial sum `x + b`
    /// already exists: the sum then costs no more than before and reuses a node that other
    /// expressions compute anyway, so the partial sum `x + y` may drop out of the generated
    /// code (e.g. `(B + Bᵀ)ᵢⱼ + ψ̇Iᵢⱼ` becomes `(Bᵢⱼ + ψ̇Iᵢⱼ) + Bⱼᵢ`, reusing an entry of
    /// `∂²R/∂Ω∂γ` in `∂²R/∂γ²`). Exact up to the rounding of a reordered sum.
    fn reassociate(&mut self, a: Id, b: Id) -> Option<Id> {
        for (s, other) in [(a, b), (b, a)] {
            if self.as_const(other).is_some() {
                continue;
            }
            let (x, y) = match self.node(s) {
                Node::Add(x, y) if self.as_const(x).is_none() => (x, y),
                Node::Mul(c, x) if self.is_const(c, 2.0) => (x, x),
                _ => continue,
            };
            for (part, rest) in [(x, y), (y, x)] {
                let (m, n) = self.order(part, other);
                if let Some(found) = self.find(&Node::Add(m, n)) {
                    // Written as is: like-term collection (which found nothing to cancel in
                    // `a + b`) would only undo it.
                    return Some(self.add_plain(found, rest));
                }
            }
        }
        None
    }

    /// `c · s` for a sum `s` every term of which carries a constant factor, `Σ kᵢxᵢ`, written as
    /// `Σ (c kᵢ) xᵢ` when `c` is a power of two: then every `c kᵢ` is exact and scaling by `c`
    /// commutes with rounding, so the value is bit for bit that of `c · s` (barring over- and
    /// underflow), with one multiplication fewer, or none at all where `c kᵢ = 1`. This is how
    /// `½(2Iω + 2m u v)`, the derivative of a kinetic energy written as `½(…)`, becomes
    /// `Iω + m u v`. `None` when a term has no constant factor (nothing would be saved), or the
    /// sum is deeper than `depth`.
    fn scale_sum(&mut self, c: f64, s: Id, depth: u32) -> Option<Id> {
        // A normal number with a zero mantissa is a power of two.
        let power_of_two = c.is_normal() && c.to_bits() & ((1u64 << 52) - 1) == 0;
        (power_of_two && self.all_terms_scaled(c, s, depth)).then(|| self.scale_terms(c, s))
    }

    /// `Σ (c kᵢ) xᵢ` for a sum [`Graph::all_terms_scaled`] accepted.
    fn scale_terms(&mut self, c: f64, s: Id) -> Id {
        match self.node(s) {
            Node::Add(p, q) => {
                let p = self.scale_terms(c, p);
                let q = self.scale_terms(c, q);
                self.add(p, q)
            }
            Node::Mul(k, x) => {
                let ck = self.constant(c * self.as_const(k).unwrap_or(1.0));
                self.mul(ck, x)
            }
            // Not reached (every term is a product with a constant); `c · s` as it is.
            _ => {
                let c = self.constant(c);
                self.mul(c, s)
            }
        }
    }

    /// Whether every term of the sum `s` (at most `depth` sums deep) has a constant factor `k`
    /// with `c k` a normal number (so that `c k` is exact for a power of two `c`).
    fn all_terms_scaled(&self, c: f64, s: Id, depth: u32) -> bool {
        match self.node(s) {
            Node::Mul(k, _) => self.as_const(k).is_some_and(|k| (c * k).is_normal()),
            Node::Add(p, q) if depth > 0 => {
                self.all_terms_scaled(c, p, depth - 1) && self.all_terms_scaled(c, q, depth - 1)
            }
            _ => false,
        }
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
                    Node::Add(..) => {
                        if let Some(s) = self.scale_sum(x, b, 8) {
                            return s;
                        }
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

    /// `late · (c · early)`: the value of `mul(c, mul(late, early))`, but with the constant
    /// scaling `early` rather than the product. [`Graph::mul`] pulls constant factors to the
    /// front (`x · (c · y) = c · (x · y)`), which is what lets equal products share a node; this
    /// keeps `c · early` as an operand instead, for a caller that knows `early` long before
    /// `late` (a value that waits for a division, say): the straight-line code can then form
    /// `c · early` beforehand and apply one multiplication once `late` is known, where
    /// `c · (late · early)` needs two. The node is not merged with its normal form;
    /// [`Graph::substitute`] keeps it where its operands are their own images and rebuilds it
    /// with `mul` elsewhere.
    pub fn mul_scaled(&mut self, late: Id, c: f64, early: Id) -> Id {
        let c = self.constant(c);
        let scaled = self.mul(c, early);
        match self.node(scaled) {
            Node::Mul(k, _) if self.as_const(k).is_some() && self.as_const(late).is_none() => {
                let (a, b) = self.order(late, scaled);
                self.intern(Node::Mul(a, b))
            }
            _ => self.mul(late, scaled),
        }
    }

    /// `(base, n)` with `id = base^n` (`n = 1` for anything that is not a power).
    fn base_exp(&self, id: Id) -> (Id, i32) {
        match self.node(id) {
            Node::Powi(b, n) => match self.node(b) {
                // (1/bb)ⁿ, the form of a negative power.
                Node::Recip(bb) => (bb, -n),
                _ => (b, n),
            },
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
            // a⁻ⁿ as (1/a)ⁿ, not 1/aⁿ: the reciprocal 1/a is then shared with every other
            // power of it (the derivative of 1/a is −a′(1/a)², which reuses the one division
            // instead of adding 1/a²). Exact up to rounding.
            _ if n < 0 => {
                let r = self.intern(Node::Recip(a));
                self.intern(Node::Powi(r, -n))
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

    /// Replaces variables by expressions (`map[v]` for slot `v`; a slot not in `map` stays) and
    /// rebuilds every node through the simplifying constructors, so the images are simplified
    /// too. Returns the images of `roots`.
    ///
    /// Every node up to the largest root is rebuilt, reachable or not (so which nodes this adds,
    /// and in which order, depends only on the largest root); a node that is provably its own
    /// image is kept without calling its constructor, which would add nothing and return it.
    pub fn substitute(&mut self, roots: &[Id], map: &HashMap<Var, Id>) -> Vec<Id> {
        self.substitute_impl(roots, map, true)
    }

    /// [`Graph::substitute`]; `skip` keeps a node that is provably its own image without calling
    /// its constructor (`false`: the plain rebuild, which the tests compare it with).
    fn substitute_impl(&mut self, roots: &[Id], map: &HashMap<Var, Id>, skip: bool) -> Vec<Id> {
        let Some(max) = roots.iter().max() else {
            return Vec::new();
        };
        let mut image: Vec<Id> = Vec::with_capacity(max.index() + 1);
        for i in 0..=max.index() {
            let node = self.nodes[i];
            let m = |c: Id| image[c.index()];
            // A node other than a sum whose children are their own images is its own image:
            // its constructor's rewrites depend only on the structure below it, none of them
            // applied when it was made, and it would find the node in the table without adding
            // any. (A sum is rebuilt regardless: whether like terms are collected also depends
            // on the sums that exist, which may have changed since.)
            let same = skip
                && match node {
                    Node::Const(_) | Node::Var(_) | Node::Add(..) => false,
                    Node::Mul(a, b) | Node::Powf(a, b) => m(a) == a && m(b) == b,
                    Node::Neg(a) | Node::Recip(a) | Node::Powi(a, _) | Node::Func(_, a) => {
                        m(a) == a
                    }
                };
            if same {
                image.push(Id(i as u32));
                continue;
            }
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
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (no dependency needed).
    struct Lcg(u64);

    impl Lcg {
        fn below(&mut self, n: usize) -> usize {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((self.0 >> 33) as usize) % n
        }
    }

    /// A random graph over `vars` built through the constructors, with sums that share terms
    /// (so that like-term collection is exercised).
    fn random_graph(rng: &mut Lcg, vars: usize, ops: usize) -> (Graph, Vec<Var>) {
        let mut g = Graph::new();
        let vs: Vec<Var> = (0..vars).map(|i| g.new_var(format!("x{i}"))).collect();
        let mut pool: Vec<Id> = vs.iter().map(|&v| g.var_id(v)).collect();
        for c in [0.5, 2.0, -1.0, 3.0] {
            pool.push(g.constant(c));
        }
        for _ in 0..ops {
            let a = pool[rng.below(pool.len())];
            let b = pool[rng.below(pool.len())];
            let id = match rng.below(10) {
                0..=2 => g.add(a, b),
                3 => g.sub(a, b),
                4..=6 => g.mul(a, b),
                7 => g.div(a, b),
                8 => g.powi(a, [2, 3, -2][rng.below(3)]),
                _ => g.func([Func::Sqrt, Func::Sin, Func::Abs][rng.below(3)], a),
            };
            pool.push(id);
        }
        (g, vs)
    }

    /// Skipping the nodes that are their own image changes nothing: same images, and the same
    /// nodes added in the same order, as rebuilding every node.
    #[test]
    fn skipping_unchanged_nodes_is_exact() {
        let mut rng = Lcg(0x5EED);
        for _ in 0..200 {
            let (mut g, vs) = random_graph(&mut rng, 4, 60);
            let n = g.len();
            // Roots anywhere in the graph, a map of one or two variables (to constants, other
            // variables or expressions).
            let roots: Vec<Id> = (0..4).map(|_| Id(rng.below(n) as u32)).collect();
            let mut map = HashMap::new();
            for _ in 0..1 + rng.below(2) {
                let v = vs[rng.below(vs.len())];
                map.insert(v, Id(rng.below(n) as u32));
            }
            let mut h = g.clone();
            let fast = g.substitute_impl(&roots, &map, true);
            let full = h.substitute_impl(&roots, &map, false);
            assert_eq!(fast, full);
            assert_eq!(g.nodes(), h.nodes());
        }
    }
}
