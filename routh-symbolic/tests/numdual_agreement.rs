//! Property test: symbolic first and second derivatives agree with forward-mode automatic
//! differentiation (num-dual) of the *same* graph, evaluated generically.
//!
//! Random expression trees (depth 3–6 counted in generator levels, over 3 or 4 variables, using
//! every operation of the engine) are generated from fixed ChaCha8 seeds, so the run is
//! deterministic. Domain restrictions are enforced structurally: roots, logarithms, real powers
//! and negative integer powers only see arguments that are positive (or non-zero) by
//! construction, `tan` only sees arguments in (−1.3, 1.3), `exp` only bounded arguments, and
//! variables are sampled with |x| ∈ [0.3, 1.6]. The sample points are drawn before the
//! expression, and any subexpression exceeding `LIMIT` in magnitude at them is squashed, so the
//! comparison at 1e-12 measures the engine, not the conditioning of a random formula.
//!
//! Each case compares, at one point: `Graph::eval` with the generic evaluator at `f64` (exactly),
//! the value, the 4 symbolic first derivatives and the 16 second derivatives (diff of diff)
//! with `num_dual::hessian`, and the symmetry of the symbolic mixed partials.

use num_dual::DualNum;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_symbolic::{Func, Graph, Id, Node, Var};
use test_models::compare::close_to;

const NVARS: usize = 4;
const SEEDS: [u64; 4] = [0x5eed_0001, 0x5eed_0002, 0xdead_beef, 2024];
const EXPRS_PER_SEED: usize = 500;
const POINTS_PER_EXPR: usize = 2;
const TOL: f64 = 1e-12;
const HUGE: f64 = 1e12;

/// Evaluates `root` over any dual-number type by walking the graph's nodes in order.
fn eval_generic<D: DualNum<f64>>(g: &Graph, root: Id, x: &[D]) -> D {
    let nodes = &g.nodes()[..=root.index()];
    let mut val: Vec<D> = Vec::with_capacity(nodes.len());
    for node in nodes {
        let v = |c: Id| val[c.index()].clone();
        let r = match *node {
            Node::Const(bits) => D::from(f64::from_bits(bits)),
            Node::Var(i) => x[i.index()].clone(),
            Node::Add(a, b) => v(a) + v(b),
            Node::Mul(a, b) => v(a) * v(b),
            Node::Neg(a) => -v(a),
            Node::Recip(a) => v(a).recip(),
            Node::Powi(a, n) => v(a).powi(n),
            Node::Powf(a, b) => match g.as_const(b) {
                Some(e) => v(a).powf(e),
                None => v(a).powd(v(b)),
            },
            Node::Func(f, a) => {
                let a = v(a);
                match f {
                    Func::Sqrt => a.sqrt(),
                    Func::Sin => a.sin(),
                    Func::Cos => a.cos(),
                    Func::Tan => a.tan(),
                    Func::Exp => a.exp(),
                    Func::Ln => a.ln(),
                    Func::Abs => {
                        let s = Func::Sign.apply(a.re());
                        a * D::from(s)
                    }
                    Func::Sign => D::from(Func::Sign.apply(a.re())),
                }
            }
        };
        val.push(r);
    }
    val.pop().expect("root exists")
}

/// Random expression generator over a graph with `NVARS` variables.
struct Gen<'a> {
    g: &'a mut Graph,
    rng: &'a mut ChaCha8Rng,
    vars: Vec<Id>,
    /// The points the expression will be checked at: every generated subexpression whose
    /// magnitude exceeds `LIMIT` at one of them is squashed by `r ↦ r / sqrt(1 + r²)` (which
    /// keeps the sign and non-zeroness), so that no subexpression is so large that rounding
    /// alone (e.g. `sin` of a huge argument) would break a 1e-12 comparison.
    pts: Vec<[f64; NVARS]>,
}

const LIMIT: f64 = 20.0;

impl Gen<'_> {
    fn magnitude(&self, id: Id) -> f64 {
        self.pts
            .iter()
            .map(|p| self.g.eval(&[id], p)[0].abs())
            .map(|m| if m.is_nan() { f64::INFINITY } else { m })
            .fold(0.0, f64::max)
    }

    fn tame(&mut self, r: Id) -> Id {
        if self.magnitude(r) <= LIMIT {
            return r;
        }
        let r2 = self.g.powi(r, 2);
        let one = self.g.one();
        let s = self.g.add(one, r2);
        let e = self.g.constant(-0.5);
        let p = self.g.powf(s, e);
        self.g.mul(r, p)
    }

    fn any(&mut self, d: u32) -> Id {
        let r = self.any_raw(d);
        self.tame(r)
    }

    fn pos(&mut self, d: u32) -> Id {
        let r = self.pos_raw(d);
        self.tame(r)
    }

    fn nonzero(&mut self, d: u32) -> Id {
        let r = self.nonzero_raw(d);
        self.tame(r)
    }

    fn constant(&mut self) -> Id {
        let c = match self.rng.gen_range(0..4) {
            0 => [0.0, 1.0, -1.0, 2.0, 0.5, -2.0, 3.0][self.rng.gen_range(0..7)],
            _ => (self.rng.gen_range(-2.0..2.0f64) * 8.0).round() / 8.0 + 0.0625,
        };
        self.g.constant(c)
    }

    fn var(&mut self) -> Id {
        self.vars[self.rng.gen_range(0..self.vars.len())]
    }

    fn leaf(&mut self) -> Id {
        if self.rng.gen_bool(0.75) {
            self.var()
        } else {
            self.constant()
        }
    }

    fn child_depth(&mut self, d: u32) -> u32 {
        if d == 0 {
            0
        } else if self.rng.gen_bool(0.9) {
            d - 1
        } else {
            self.rng.gen_range(0..d)
        }
    }

    /// Any expression (no domain guarantee beyond finiteness).
    fn any_raw(&mut self, d: u32) -> Id {
        if d == 0 {
            return self.leaf();
        }
        let d1 = self.child_depth(d);
        let d2 = self.child_depth(d);
        match self.rng.gen_range(0..28) {
            0 | 1 | 20..=22 => {
                let (a, b) = (self.any(d1), self.any(d2));
                self.g.add(a, b)
            }
            2 | 23 => {
                let (a, b) = (self.any(d1), self.any(d2));
                self.g.sub(a, b)
            }
            3 | 4 | 24..=26 => {
                let (a, b) = (self.any(d1), self.any(d2));
                self.g.mul(a, b)
            }
            5 | 27 => {
                let (a, b) = (self.any(d1), self.nonzero(d2));
                self.g.div(a, b)
            }
            6 => {
                let a = self.any(d1);
                self.g.neg(a)
            }
            7 => {
                let a = self.nonzero(d1);
                self.g.recip(a)
            }
            8 => {
                let n = self.rng.gen_range(-3..=4);
                let a = if n < 0 {
                    self.nonzero(d1)
                } else {
                    self.any(d1)
                };
                self.g.powi(a, n)
            }
            9 => {
                // Real power with a constant exponent on a positive base.
                let a = self.pos(d1);
                let e = self.real_exponent();
                let e = self.g.constant(e);
                self.g.powf(a, e)
            }
            10 => {
                // Real power with a variable exponent on a positive base.
                let a = self.pos(d1);
                let e = self.bounded(d2);
                self.g.powf(a, e)
            }
            11 => {
                let a = self.pos(d1);
                self.g.func(Func::Sqrt, a)
            }
            12 => {
                let a = self.any(d1);
                self.g.func(Func::Sin, a)
            }
            13 => {
                let a = self.any(d1);
                self.g.func(Func::Cos, a)
            }
            14 => {
                let a = self.tan_arg(d1);
                self.g.func(Func::Tan, a)
            }
            15 => {
                let a = self.bounded(d1);
                self.g.func(Func::Exp, a)
            }
            16 => {
                let a = self.pos(d1);
                self.g.func(Func::Ln, a)
            }
            17 => {
                let a = self.nonzero(d1);
                self.g.func(Func::Abs, a)
            }
            18 => {
                // sign(nonzero) · any: piecewise constant factor.
                let a = self.nonzero(d1);
                let s = self.g.func(Func::Sign, a);
                let b = self.any(d2);
                self.g.mul(s, b)
            }
            19 => {
                let (c, a) = (self.constant(), self.any(d1));
                self.g.mul(c, a)
            }
            _ => {
                let (a, b) = (self.any(d1), self.any(d2));
                self.g.add(a, b)
            }
        }
    }

    fn real_exponent(&mut self) -> f64 {
        match self.rng.gen_range(0..5) {
            0 => [0.5, -0.5, 1.5, 2.0, -1.0, 1.0 / 3.0][self.rng.gen_range(0..6)],
            _ => self.rng.gen_range(-2.5..2.5),
        }
    }

    /// A positive expression, bounded away from 0.
    fn pos_raw(&mut self, d: u32) -> Id {
        if d == 0 {
            // c + x² or a positive constant.
            return if self.rng.gen_bool(0.7) {
                let x = self.var();
                let x2 = self.g.powi(x, 2);
                let c = self.g.constant(self.rng.gen_range(0.2..2.0));
                self.g.add(c, x2)
            } else {
                self.g.constant(self.rng.gen_range(0.3..3.0))
            };
        }
        let d1 = self.child_depth(d);
        let d2 = self.child_depth(d);
        match self.rng.gen_range(0..11) {
            0 | 1 => {
                // c + e²  (e.g. 1 + x², the classic ln / sqrt argument)
                let e = self.any(d1);
                let e2 = self.g.mul(e, e);
                let c = self.g.constant(self.rng.gen_range(0.2..2.0));
                self.g.add(e2, c)
            }
            2 => {
                let a = self.bounded(d1);
                self.g.func(Func::Exp, a)
            }
            3 => {
                let a = self.pos(d1);
                self.g.func(Func::Sqrt, a)
            }
            4 => {
                // c + k sin(e) with c > |k|
                let e = self.any(d1);
                let s = self.g.func(Func::Sin, e);
                let k = self.rng.gen_range(-1.5..1.5f64);
                let c = k.abs() + self.rng.gen_range(0.3..1.5);
                let (k, c) = (self.g.constant(k), self.g.constant(c));
                let ks = self.g.mul(k, s);
                self.g.add(c, ks)
            }
            5 => {
                let (a, b) = (self.pos(d1), self.pos(d2));
                self.g.mul(a, b)
            }
            6 => {
                let (a, b) = (self.pos(d1), self.pos(d2));
                self.g.add(a, b)
            }
            7 => {
                let a = self.pos(d1);
                self.g.recip(a)
            }
            8 => {
                let a = self.pos(d1);
                let e = self.real_exponent();
                let e = self.g.constant(e);
                self.g.powf(a, e)
            }
            9 => {
                let a = self.nonzero(d1);
                self.g.func(Func::Abs, a)
            }
            _ => {
                let a = self.nonzero(d1);
                let n = [2, -2, 4][self.rng.gen_range(0..3)];
                self.g.powi(a, n)
            }
        }
    }

    /// An expression bounded away from 0 (either sign).
    fn nonzero_raw(&mut self, d: u32) -> Id {
        if d == 0 {
            return self.var();
        }
        let d1 = self.child_depth(d);
        match self.rng.gen_range(0..6) {
            0 => self.var(),
            1 => self.pos(d1),
            2 => {
                let a = self.pos(d1);
                self.g.neg(a)
            }
            3 => {
                let (x, a) = (self.var(), self.pos(d1));
                self.g.mul(x, a)
            }
            4 => {
                // c − e² with c < 0
                let e = self.any(d1);
                let e2 = self.g.powi(e, 2);
                let c = self.g.constant(-self.rng.gen_range(0.2..2.0));
                self.g.sub(c, e2)
            }
            _ => {
                let a = self.nonzero(d1);
                let n = self.rng.gen_range(-3..=3);
                self.g.powi(a, n)
            }
        }
    }

    /// An expression with |value| ≤ ~2.
    fn bounded(&mut self, d: u32) -> Id {
        if d == 0 {
            return self.leaf();
        }
        let d1 = self.child_depth(d);
        match self.rng.gen_range(0..5) {
            0 => {
                let e = self.any(d1);
                let s = self.g.func(Func::Sin, e);
                let k = self.g.constant(self.rng.gen_range(-2.0..2.0));
                self.g.mul(k, s)
            }
            1 => {
                let e = self.any(d1);
                self.g.func(Func::Cos, e)
            }
            2 => {
                // e / (1 + e²) ∈ [−½, ½]
                let e = self.any(d1);
                let e2 = self.g.powi(e, 2);
                let one = self.g.one();
                let den = self.g.add(one, e2);
                self.g.div(e, den)
            }
            3 => self.tan_arg(d1),
            _ => self.leaf(),
        }
    }

    /// An argument for `tan`, in (−1.3, 1.3).
    fn tan_arg(&mut self, d: u32) -> Id {
        let k = self.g.constant(self.rng.gen_range(-1.3..1.3));
        if d == 0 || self.rng.gen_bool(0.3) {
            let x = self.var();
            let k = self.g.constant(self.rng.gen_range(-0.8..0.8));
            return self.g.mul(k, x);
        }
        let e = self.any(d - 1);
        let f = if self.rng.gen_bool(0.5) {
            Func::Sin
        } else {
            Func::Cos
        };
        let s = self.g.func(f, e);
        self.g.mul(k, s)
    }
}

/// Agreement to `TOL` relative to the larger magnitude (floor 1), by the project's one rule.
fn close(a: f64, b: f64) -> bool {
    close_to(a, b, TOL, a.abs().max(b.abs()))
}

fn sample_point(rng: &mut ChaCha8Rng) -> [f64; NVARS] {
    std::array::from_fn(|_| {
        let m = rng.gen_range(0.3..1.6);
        if rng.gen_bool(0.5) {
            m
        } else {
            -m
        }
    })
}

#[derive(Default, Debug)]
struct Stats {
    exprs: usize,
    checked: usize,
    skipped: usize,
    max_nodes: usize,
    f_ops: usize,
    max_f_ops: usize,
    constant_exprs: usize,
    first_derivs: usize,
    second_derivs: usize,
}

fn run_seed(seed: u64, st: &mut Stats) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    for k in 0..EXPRS_PER_SEED {
        let mut g = Graph::new();
        let vars: Vec<Id> = (0..NVARS).map(|i| g.var(format!("x{i}"))).collect();
        // Expressions over 3 or 4 of the variables (derivatives in an unused one must be 0).
        let used = rng.gen_range(3..=NVARS);
        let depth = rng.gen_range(3..=6);
        let pts: Vec<[f64; NVARS]> = (0..POINTS_PER_EXPR)
            .map(|_| sample_point(&mut rng))
            .collect();
        let f = Gen {
            g: &mut g,
            rng: &mut rng,
            vars: vars[..used].to_vec(),
            pts: pts.clone(),
        }
        .any(depth);
        st.exprs += 1;
        let f_ops = routh_symbolic::schedule(&g, &[f]).len();
        st.f_ops += f_ops;
        st.max_f_ops = st.max_f_ops.max(f_ops);
        st.constant_exprs += usize::from(g.as_const(f).is_some());

        // Symbolic derivatives: gradient and the full matrix of diff-of-diff.
        let by: Vec<Var> = vars.iter().map(|&x| g.as_var(x).unwrap()).collect();
        let grad: Vec<Id> = by.iter().map(|&v| g.diff(f, v)).collect();
        let hess: Vec<Vec<Id>> = grad
            .iter()
            .map(|&gi| by.iter().map(|&v| g.diff(gi, v)).collect())
            .collect();
        st.max_nodes = st.max_nodes.max(g.len());
        let mut roots = vec![f];
        roots.extend(&grad);
        roots.extend(hess.iter().flatten());

        for x in pts {
            let ctx = || {
                format!(
                    "seed {seed:#x}, expr {k}, x = {x:?}\n f = {}",
                    routh_symbolic::to_infix(&g, f)
                )
            };

            // The interpreter agrees with the generic evaluator at f64 (same operations).
            let direct = g.eval(&[f], &x)[0];
            let generic = eval_generic::<f64>(&g, f, &x);
            assert!(
                direct == generic || (direct.is_nan() && generic.is_nan()),
                "eval {direct} vs generic {generic}: {}",
                ctx()
            );

            let (v, dv, h) = num_dual::hessian(|xd| eval_generic(&g, f, xd.as_slice()), x.into());
            let all_ok = std::iter::once(v)
                .chain(dv.iter().copied())
                .chain(h.iter().copied())
                .all(|t| t.is_finite() && t.abs() <= HUGE);
            if !all_ok {
                st.skipped += 1;
                continue;
            }

            let s = g.eval(&roots, &x);
            assert!(close(s[0], v), "value {} vs num-dual {v}: {}", s[0], ctx());
            for i in 0..NVARS {
                let a = s[1 + i];
                assert!(
                    close(a, dv[i]),
                    "∂f/∂x{i}: symbolic {a} vs num-dual {}: {}\n df = {}",
                    dv[i],
                    ctx(),
                    routh_symbolic::to_infix(&g, grad[i])
                );
                st.first_derivs += 1;
            }
            for i in 0..NVARS {
                for j in 0..NVARS {
                    let a = s[1 + NVARS + i * NVARS + j];
                    assert!(
                        close(a, h[(i, j)]),
                        "∂²f/∂x{i}∂x{j}: symbolic {a} vs num-dual {}: {}",
                        h[(i, j)],
                        ctx()
                    );
                    // Symmetry of the symbolic mixed partials.
                    let b = s[1 + NVARS + j * NVARS + i];
                    assert!(
                        close(a, b),
                        "∂²f/∂x{i}∂x{j} = {a} but ∂²f/∂x{j}∂x{i} = {b}: {}",
                        ctx()
                    );
                    st.second_derivs += 1;
                }
            }
            st.checked += 1;
        }
    }
}

#[test]
fn symbolic_derivatives_match_num_dual() {
    let mut st = Stats::default();
    for seed in SEEDS {
        run_seed(seed, &mut st);
    }
    println!(
        "numdual_agreement: {} expressions, {} (expression, point) cases checked, {} skipped \
         (non-finite or > 1e12), {} first and {} second derivatives compared, largest graph {} nodes; \
         operations per expression: mean {:.1}, max {}; {} folded to constants",
        st.exprs,
        st.checked,
        st.skipped,
        st.first_derivs,
        st.second_derivs,
        st.max_nodes,
        st.f_ops as f64 / st.exprs as f64,
        st.max_f_ops,
        st.constant_exprs
    );
    assert!(st.exprs >= 600);
    assert!(
        st.checked >= 500,
        "only {} cases checked: {st:?}",
        st.checked
    );
}

/// The generator really exercises every kind of node.
#[test]
fn generator_covers_every_operation() {
    let mut rng = ChaCha8Rng::seed_from_u64(SEEDS[0]);
    let mut g = Graph::new();
    let vars: Vec<Id> = (0..NVARS).map(|i| g.var(format!("x{i}"))).collect();
    for _ in 0..EXPRS_PER_SEED {
        let depth = rng.gen_range(3..=6);
        let pts = vec![sample_point(&mut rng)];
        Gen {
            g: &mut g,
            rng: &mut rng,
            vars: vars.clone(),
            pts,
        }
        .any(depth);
    }
    let mut seen = [false; 16];
    for node in g.nodes() {
        let k = match *node {
            Node::Const(_) => 0,
            Node::Var(_) => 1,
            Node::Add(..) => 2,
            Node::Mul(..) => 3,
            Node::Neg(_) => 4,
            Node::Recip(_) => 5,
            Node::Powi(_, n) => 6 + usize::from(n > 2),
            Node::Powf(_, b) => 8 + usize::from(g.as_const(b).is_none()),
            Node::Func(f, _) => match f {
                Func::Sqrt | Func::Sin | Func::Cos => 10,
                Func::Tan => 11,
                Func::Exp => 12,
                Func::Ln => 13,
                Func::Abs => 14,
                Func::Sign => 15,
            },
        };
        seen[k] = true;
    }
    assert!(seen.iter().all(|&s| s), "missing node kinds: {seen:?}");
    for f in [Func::Sqrt, Func::Sin, Func::Cos] {
        assert!(
            g.nodes()
                .iter()
                .any(|n| matches!(*n, Node::Func(h, _) if h == f)),
            "{f:?}"
        );
    }
}
