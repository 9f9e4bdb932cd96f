//! Unit tests of the simplifying constructors, the shape operations and the analyses.

use std::collections::HashMap;

use routh_symbolic::shape::{self, Value};
use routh_symbolic::{degree, op_counts, schedule, to_infix, Degree, Func, Graph, Id, Node, Var};
use test_models::compare::close_to;

/// Agreement to 1e−13 relative to the larger magnitude (floor 1), by the project's one rule.
fn close(a: f64, b: f64) -> bool {
    close_to(a, b, 1e-13, a.abs().max(b.abs()))
}

/// A graph with variables `x, y, z` (slots 0, 1, 2).
fn xyz() -> (Graph, Id, Id, Id) {
    let mut g = Graph::new();
    let x = g.var("x");
    let y = g.var("y");
    let z = g.var("z");
    (g, x, y, z)
}

/// The variable `x` is (panics if it is not one).
fn var(g: &Graph, x: Id) -> Var {
    g.as_var(x).expect("a variable")
}

/// A handful of non-constant expressions of different node kinds in `x, y`.
fn samples(g: &mut Graph, x: Id, y: Id) -> Vec<Id> {
    let two = g.constant(2.0);
    let mut v = vec![x];
    v.push(g.mul(x, y)); // x·y
    v.push(g.mul(two, x)); // 2·x
    let m = g.constant(-0.75);
    let xy = g.mul(x, y);
    v.push(g.mul(m, xy)); // −0.75·x·y
    v.push(g.add(x, y)); // x + y
    v.push(g.add(two, x)); // 2 + x
    v.push(g.neg(x)); // −x
    v.push(g.recip(x)); // 1/x
    v.push(g.powi(x, 3)); // x³
    v.push(g.powi(y, -2)); // y⁻²
    v.push(g.func(Func::Sin, x));
    v.push(g.func(Func::Sqrt, y));
    v.push(g.powf(x, y));
    let c = g.constant(1.5);
    v.push(g.powf(y, c));
    v
}

// ---------------------------------------------------------------- constant folding

#[test]
fn constant_folding() {
    let mut g = Graph::new();
    let c = |g: &mut Graph, v: f64| g.constant(v);
    let (two, three, four) = (c(&mut g, 2.0), c(&mut g, 3.0), c(&mut g, 4.0));
    let s = g.add(two, three);
    assert_eq!(g.as_const(s), Some(5.0));
    let p = g.mul(two, three);
    assert_eq!(g.as_const(p), Some(6.0));
    let d = g.sub(two, three);
    assert_eq!(g.as_const(d), Some(-1.0));
    let n = g.neg(two);
    assert_eq!(g.as_const(n), Some(-2.0));
    let r = g.recip(four);
    assert_eq!(g.as_const(r), Some(0.25));
    let q = g.div(three, four);
    assert_eq!(g.as_const(q), Some(0.75));
    let p3 = g.powi(two, 3);
    assert_eq!(g.as_const(p3), Some(8.0));
    let pm = g.powi(two, -2);
    assert_eq!(g.as_const(pm), Some(0.25));
    let half = c(&mut g, 0.5);
    let sq = g.powf(four, half);
    assert_eq!(g.as_const(sq), Some(2.0));
    let e = c(&mut g, 1.5);
    let pf = g.powf(four, e);
    assert_eq!(g.as_const(pf), Some(8.0));
    for f in [
        Func::Sqrt,
        Func::Sin,
        Func::Cos,
        Func::Tan,
        Func::Exp,
        Func::Ln,
        Func::Abs,
        Func::Sign,
    ] {
        let r = g.func(f, three);
        assert_eq!(g.as_const(r), Some(f.apply(3.0)), "{f:?}");
    }
    // Nested constants are collected: (x + 2) + 3 = 5 + x and 3·(2·x) = 6·x.
    let x = g.var("x");
    let x2 = g.add(x, two);
    let s = g.add(x2, three);
    let five = c(&mut g, 5.0);
    assert_eq!(s, g.add(five, x));
    let tx = g.mul(two, x);
    let p = g.mul(three, tx);
    let six = c(&mut g, 6.0);
    assert_eq!(p, g.mul(six, x));
    // −0.0 is normalised.
    assert_eq!(g.constant(-0.0), g.zero());
    // A graph of constants only has no non-leaf node to schedule.
    assert!(schedule(&g, &[s])
        .iter()
        .all(|&id| g.as_const(id).is_none()));
}

#[test]
fn zero_and_one_identities() {
    let (mut g, x, y, _) = xyz();
    let (zero, one) = (g.zero(), g.one());
    let m1 = g.constant(-1.0);
    for e in samples(&mut g, x, y) {
        assert_eq!(g.add(e, zero), e);
        assert_eq!(g.add(zero, e), e);
        assert_eq!(g.sub(e, zero), e);
        assert_eq!(g.mul(e, one), e);
        assert_eq!(g.mul(one, e), e);
        assert_eq!(g.mul(e, zero), zero);
        assert_eq!(g.mul(zero, e), zero);
        assert_eq!(g.div(e, one), e);
        assert_eq!(g.div(zero, e), zero);
        assert_eq!(g.powi(e, 0), one);
        assert_eq!(g.powi(e, 1), e);
        assert_eq!(g.powf(e, one), e);
        assert_eq!(g.powf(e, zero), one);
        let ne = g.neg(e);
        assert_eq!(g.mul(m1, e), ne);
        assert_eq!(g.sub(zero, e), ne);
    }
}

#[test]
fn difference_of_equal_expressions_is_zero() {
    let (mut g, x, y, _) = xyz();
    for e in samples(&mut g, x, y) {
        let d = g.sub(e, e);
        assert!(
            g.is_const(d, 0.0),
            "{} − itself = {}",
            to_infix(&g, e),
            to_infix(&g, d)
        );
        let ne = g.neg(e);
        let s = g.add(ne, e);
        assert!(g.is_const(s, 0.0), "−{} + itself", to_infix(&g, e));
    }
    // Like terms with constant coefficients combine.
    let two = g.constant(2.0);
    let three = g.constant(3.0);
    let five = g.constant(5.0);
    let (tx, hx) = (g.mul(two, x), g.mul(three, x));
    let s = g.add(tx, hx);
    assert_eq!(s, g.mul(five, x));
}

#[test]
fn products_of_equal_bases_become_integer_powers() {
    let (mut g, x, y, _) = xyz();
    let xx = g.mul(x, x);
    assert_eq!(g.node(xx), Node::Powi(x, 2));
    let xxx = g.mul(xx, x);
    assert_eq!(g.node(xxx), Node::Powi(x, 3));
    let x2 = g.powi(x, 2);
    let x3 = g.powi(x, 3);
    let x5 = g.mul(x2, x3);
    assert_eq!(x5, g.powi(x, 5));
    assert_eq!(g.div(x3, x), x2);
    let xm2 = g.powi(x, -2);
    // x⁻² is (1/x)², sharing the reciprocal with every other power of x.
    let rx = g.recip(x);
    assert_eq!(g.node(rx), Node::Recip(x));
    assert_eq!(g.node(xm2), Node::Powi(rx, 2));
    assert_eq!(g.div(x, x3), xm2);
    assert_eq!(g.recip(x2), xm2);
    let t = g.div(x2, x2);
    assert!(g.is_const(t, 1.0));
    assert_eq!(g.powi(x2, 3), g.powi(x, 6));
    assert_eq!(g.powi(xm2, -2), g.powi(x, 4));
    assert_eq!(g.powi(rx, 2), xm2);
    assert_eq!(g.mul(rx, rx), xm2);
    assert_eq!(g.mul(x2, xm2), g.one());
    let three = g.constant(3.0);
    assert_eq!(g.powf(x, three), x3);
    let half = g.constant(0.5);
    let sqrt_x = g.func(Func::Sqrt, x);
    assert_eq!(g.powf(x, half), sqrt_x);
    // sqrt(x²) = |x|.
    let ax = g.func(Func::Abs, x);
    assert_eq!(g.func(Func::Sqrt, x2), ax);
    // For every kind of expression: e·e = e², e²·e = e³.
    for e in samples(&mut g, x, y) {
        let ee = g.mul(e, e);
        assert_eq!(ee, g.powi(e, 2), "{}", to_infix(&g, e));
        let e3 = g.mul(ee, e);
        assert_eq!(e3, g.powi(e, 3), "{}", to_infix(&g, e));
    }
}

#[test]
fn product_with_reciprocal_is_one() {
    let (mut g, x, y, _) = xyz();
    let rx = g.recip(x);
    let t = g.mul(x, rx);
    assert!(g.is_const(t, 1.0));
    let t = g.mul(rx, x);
    assert!(g.is_const(t, 1.0));
    let t = g.div(x, x);
    assert!(g.is_const(t, 1.0));
    for e in samples(&mut g, x, y) {
        let r = g.recip(e);
        let p = g.mul(e, r);
        assert!(
            g.is_const(p, 1.0),
            "{} · 1/itself = {}",
            to_infix(&g, e),
            to_infix(&g, p)
        );
        let q = g.div(e, e);
        assert!(
            g.is_const(q, 1.0),
            "{} / itself = {}",
            to_infix(&g, e),
            to_infix(&g, q)
        );
        assert_eq!(g.recip(r), e, "1/(1/{})", to_infix(&g, e));
    }
}

#[test]
fn commutative_operands_are_ordered_canonically() {
    let (mut g, x, y, z) = xyz();
    let mut all = samples(&mut g, x, y);
    all.push(z);
    all.push(g.constant(2.5));
    all.push(g.constant(-1.0));
    for &a in &all {
        for &b in &all {
            assert_eq!(
                g.add(a, b),
                g.add(b, a),
                "{} + {}",
                to_infix(&g, a),
                to_infix(&g, b)
            );
            assert_eq!(
                g.mul(a, b),
                g.mul(b, a),
                "{} · {}",
                to_infix(&g, a),
                to_infix(&g, b)
            );
        }
    }
    // Constants come first.
    let c = g.constant(3.0);
    let s = g.add(x, c);
    assert_eq!(g.node(s), Node::Add(c, x));
    let p = g.mul(y, c);
    assert_eq!(g.node(p), Node::Mul(c, y));
}

#[test]
fn negation_rules() {
    let (mut g, x, y, _) = xyz();
    let nx = g.neg(x);
    assert_eq!(g.node(nx), Node::Neg(x));
    assert_eq!(g.neg(nx), x);
    for e in samples(&mut g, x, y) {
        let n = g.neg(e);
        assert_eq!(g.neg(n), e, "−(−{})", to_infix(&g, e));
    }
    let two = g.constant(2.0);
    let tx = g.mul(two, x);
    let m2 = g.constant(-2.0);
    assert_eq!(g.neg(tx), g.mul(m2, x));
    let ny = g.neg(y);
    assert_eq!(g.mul(nx, ny), g.mul(x, y));
    assert_eq!(g.powi(nx, 2), g.powi(x, 2));
    let x3 = g.powi(x, 3);
    assert_eq!(g.powi(nx, 3), g.neg(x3));
    let rx = g.recip(x);
    assert_eq!(g.recip(nx), g.neg(rx));
    let ax = g.func(Func::Abs, x);
    assert_eq!(g.func(Func::Abs, nx), ax);
    let sx = g.func(Func::Sign, x);
    assert_eq!(g.func(Func::Sign, nx), g.neg(sx));
    assert_eq!(g.sub(nx, ny), g.sub(y, x));
    let ex = g.func(Func::Exp, x);
    assert_eq!(g.func(Func::Ln, ex), x);
    assert_eq!(g.func(Func::Abs, ex), ex);
    // exp(ln x) is *not* x (ln x is undefined for x < 0).
    let lx = g.func(Func::Ln, x);
    let el = g.func(Func::Exp, lx);
    assert_eq!(g.node(el), Node::Func(Func::Exp, lx));
}

#[test]
fn hash_consing_gives_equal_ids_for_equal_structure() {
    let (mut g, x, y, z) = xyz();
    let build = |g: &mut Graph| {
        let s = g.func(Func::Sin, x);
        let xy = g.mul(x, y);
        let t = g.add(xy, s);
        let c = g.constant(0.5);
        let w = g.powf(z, c);
        let q = g.div(t, w);
        g.sub(q, y)
    };
    let a = build(&mut g);
    let n = g.len();
    let b = build(&mut g);
    assert_eq!(a, b);
    assert_eq!(g.len(), n, "rebuilding an existing expression adds no node");
    // Built in another order, from the other operand order, with the same result.
    let xy = g.mul(y, x);
    let s = g.func(Func::Sin, x);
    let t = g.add(s, xy);
    assert_eq!(g.len(), n);
    let c = g.constant(0.5);
    let w = g.powf(z, c);
    let q = g.div(t, w);
    assert_eq!(g.sub(q, y), a);
    assert_eq!(g.len(), n);
    // Every node is stored once and children precede parents.
    let distinct: std::collections::HashSet<Node> = g.nodes().iter().copied().collect();
    assert_eq!(distinct.len(), g.len());
    for (i, node) in g.nodes().iter().enumerate() {
        assert!(node.children().all(|c| c.index() < i));
    }
    // `var` always makes a new slot, even with a repeated name.
    let x_again = g.var("x");
    assert_ne!(x_again, x);
    assert_eq!(g.num_vars(), 4);
    let v = var(&g, x_again);
    assert_eq!(v.index(), 3);
    assert_eq!(g.var_name(v), "x");
    assert_eq!(g.var_id(v), x_again);
}

// ---------------------------------------------------------------- differentiation

#[test]
fn derivative_of_expression_free_of_the_variable_is_the_zero_node() {
    let (mut g, x, y, z) = xyz();
    let vx = var(&g, x);
    let zero = g.zero();
    let mut free = samples(&mut g, y, z);
    let c = g.constant(4.0);
    free.push(c);
    let sz = g.func(Func::Sin, z);
    let e = g.func(Func::Exp, sz);
    free.push(e);
    let l = g.func(Func::Ln, y);
    free.push(g.powf(l, z));
    free.push(g.func(Func::Abs, y));
    free.push(g.func(Func::Sign, y));
    free.push(g.func(Func::Tan, z));
    for f in free {
        assert_eq!(g.diff(f, vx), zero, "∂({})/∂x", to_infix(&g, f));
    }
    let t = g.diff(x, vx);
    assert!(g.is_const(t, 1.0));
    assert_eq!(g.diff(y, vx), zero);
    // Only variables can be differentiated by: `diff` takes a `Var`, and `as_var` is the check.
    let x2 = g.powi(x, 2);
    assert_eq!(g.as_var(x2), None);
    assert_eq!(g.as_var(c), None);
}

#[test]
fn derivatives_have_the_expected_forms() {
    let (mut g, x, y, _) = xyz();
    let (vx, vy) = (var(&g, x), var(&g, y));
    let sx = g.func(Func::Sin, x);
    let cx = g.func(Func::Cos, x);
    assert_eq!(g.diff(sx, vx), cx);
    let nsx = g.neg(sx);
    assert_eq!(g.diff(cx, vx), nsx);
    let ex = g.func(Func::Exp, x);
    assert_eq!(g.diff(ex, vx), ex);
    let lx = g.func(Func::Ln, x);
    let rx = g.recip(x);
    assert_eq!(g.diff(lx, vx), rx);
    let ax = g.func(Func::Abs, x);
    let sg = g.func(Func::Sign, x);
    assert_eq!(g.diff(ax, vx), sg);
    assert_eq!(g.diff(sg, vx), g.zero());
    // d(c·x³)/dx = 3c·x²
    let c = g.constant(1.5);
    let x3 = g.powi(x, 3);
    let f = g.mul(c, x3);
    let x2 = g.powi(x, 2);
    let c45 = g.constant(4.5);
    assert_eq!(g.diff(f, vx), g.mul(c45, x2));
    // d(1/x)/dx = −1/x²
    let xm2 = g.powi(x, -2);
    assert_eq!(g.diff(rx, vx), g.neg(xm2));
    // d(x·y)/dx = y, d²(x·y)/dxdy = 1
    let xy = g.mul(x, y);
    assert_eq!(g.diff(xy, vx), y);
    let dxy = g.diff(xy, vx);
    let t = g.diff(dxy, vy);
    assert!(g.is_const(t, 1.0));
    // Memoised: asking again adds nothing.
    let n = g.len();
    g.diff(f, vx);
    assert_eq!(g.len(), n);
    // Numerical spot checks of trickier rules.
    let h = g.constant(0.5);
    let sq = g.powf(x, h); // sqrt(x)
    let pf = g.powf(x, y); // x^y
    let t = g.func(Func::Tan, x);
    let d: Vec<Id> = [sq, pf, t].iter().map(|&f| g.diff(f, vx)).collect();
    let dy = g.diff(pf, vy);
    let (xv, yv) = (0.7f64, 1.3f64);
    let v = g.eval(&[d[0], d[1], d[2], dy], &[xv, yv, 0.0]);
    assert!(close(v[0], 0.5 / xv.sqrt()));
    assert!(close(v[1], yv * xv.powf(yv - 1.0)));
    assert!(close(v[2], 1.0 + xv.tan().powi(2)));
    assert!(close(v[3], xv.powf(yv) * xv.ln()));
}

#[test]
fn deep_expressions_differentiate_without_stack_overflow() {
    let mut g = Graph::new();
    let vx = g.new_var("x");
    let x = g.var_id(vx);
    let mut f = x;
    for i in 0..20_000 {
        let s = g.func(if i % 2 == 0 { Func::Sin } else { Func::Cos }, f);
        f = g.add(s, x);
    }
    let d = g.diff(f, vx);
    assert!(g.eval(&[d], &[0.3])[0].is_finite());
}

#[test]
fn substitute_replaces_variables() {
    let (mut g, x, y, z) = xyz();
    // f = x² + sin(x)·z
    let x2 = g.powi(x, 2);
    let sx = g.func(Func::Sin, x);
    let szx = g.mul(sx, z);
    let f = g.add(x2, szx);
    // x ↦ y + 1
    let one = g.one();
    let y1 = g.add(y, one);
    let (vx, vy, vz) = (var(&g, x), var(&g, y), var(&g, z));
    let map = HashMap::from([(vx, y1)]);
    let out = g.substitute(&[f, x, z], &map);
    assert_eq!(out[1], y1);
    assert_eq!(out[2], z, "unmapped variables stay");
    let p = [0.4, -1.2, 0.9];
    let v = g.eval(&[out[0]], &p)[0];
    let xv = p[1] + 1.0;
    assert!(close(v, xv * xv + xv.sin() * p[2]));
    // Substituting the same expression builds the same nodes.
    let y1sq = g.powi(y1, 2);
    let sy1 = g.func(Func::Sin, y1);
    let t = g.mul(sy1, z);
    assert_eq!(out[0], g.add(y1sq, t));
    assert!(!g.depends_on(out[0], &[vx]));
    assert!(g.depends_on(out[0], &[vy]));
    // Substituting constants folds: x·z with z ↦ 0 is 0; and x ↦ 2 gives 4 + sin(2)·z.
    let xz = g.mul(x, z);
    let zero = g.zero();
    assert_eq!(
        g.substitute(&[xz], &HashMap::from([(vz, zero)])),
        vec![zero]
    );
    let two = g.constant(2.0);
    let r = g.substitute(&[f], &HashMap::from([(vx, two)]))[0];
    let s2 = g.constant(2f64.sin());
    let four = g.constant(4.0);
    let t = g.mul(s2, z);
    assert_eq!(r, g.add(four, t));
    assert!(g.substitute(&[], &map).is_empty());
    // The identity substitution changes nothing.
    assert_eq!(g.substitute(&[f], &HashMap::new()), vec![f]);
}

// ---------------------------------------------------------------- shapes

fn vec_vars(g: &mut Graph, name: &str) -> [Id; 3] {
    std::array::from_fn(|i| g.var(format!("{name}{i}")))
}

fn eval_value(g: &Graph, v: &Value, inputs: &[f64]) -> Vec<f64> {
    g.eval(&v.ids(), inputs)
}

/// nalgebra's 3×3 matrix and 3-vector types, reached through num-dual's API (nalgebra is not a
/// direct dependency of this crate): a Hessian and gradient in three variables have those types.
macro_rules! na_templates {
    () => {{
        let x0: [f64; 3] = [0.0; 3];
        let (_, v, m) = num_dual::hessian(|v| v[0].clone() * v[1].clone(), x0.into());
        (v, m)
    }};
}

fn inputs(n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| ((i as f64 + 1.0) * 0.7361).sin() * 1.7 + 0.1)
        .collect()
}

#[test]
fn skew_times_vector_is_the_cross_product() {
    let mut g = Graph::new();
    let (v, w) = (vec_vars(&mut g, "v"), vec_vars(&mut g, "w"));
    let (v, w) = (Value::Vector(v), Value::Vector(w));
    let s = shape::skew(&mut g, &v).unwrap();
    let sw = shape::mul(&mut g, &s, &w).unwrap();
    let c = shape::cross(&mut g, &v, &w).unwrap();
    assert_eq!(sw.shape(), routh_symbolic::Shape::Vector);
    let x = inputs(6);
    let (a, b) = (eval_value(&g, &sw, &x), eval_value(&g, &c, &x));
    let (tv, _) = na_templates!();
    let (mut nv, mut nw) = (tv, tv);
    for i in 0..3 {
        nv[i] = x[i];
        nw[i] = x[3 + i];
    }
    let nc = nv.cross(&nw);
    for i in 0..3 {
        assert!(close(a[i], b[i]), "{a:?} vs {b:?}");
        assert!(close(a[i], nc[i]), "{a:?} vs nalgebra {nc:?}");
    }
    // v × v = 0 symbolically, and skew is antisymmetric.
    let vv = shape::cross(&mut g, &v, &v).unwrap();
    assert!(vv.ids().iter().all(|&id| g.is_const(id, 0.0)));
    let st = shape::transpose(&mut g, &s).unwrap();
    let ns = shape::neg(&mut g, &s);
    assert_eq!(st, ns);
}

#[test]
fn diag_transpose_trace_dot_norm() {
    let mut g = Graph::new();
    let (v, w) = (vec_vars(&mut g, "v"), vec_vars(&mut g, "w"));
    let (v, w) = (Value::Vector(v), Value::Vector(w));
    let d = shape::diag(&mut g, &v).unwrap();
    let dw = shape::mul(&mut g, &d, &w).unwrap();
    let cw = shape::component_mul(&mut g, &v, &w).unwrap();
    assert_eq!(dw, cw, "diag(v)·w = v ∘ w structurally");
    let m = d.matrix("").unwrap();
    for (i, row) in m.iter().enumerate() {
        for (j, &e) in row.iter().enumerate() {
            if i != j {
                assert!(g.is_const(e, 0.0));
            }
        }
    }
    assert_eq!(shape::transpose(&mut g, &d).unwrap(), d);
    let tr = shape::trace(&mut g, &d).unwrap();
    let ones = [g.one(); 3];
    let s = shape::dot(&mut g, &v, &Value::Vector(ones)).unwrap();
    assert_eq!(tr, s);
    let x = inputs(6);
    let dot = shape::dot(&mut g, &v, &w).unwrap();
    let n2 = shape::norm_squared(&mut g, &v).unwrap();
    let n = shape::norm(&mut g, &v).unwrap();
    let r = g.eval(
        &[
            dot.scalar("").unwrap(),
            n2.scalar("").unwrap(),
            n.scalar("").unwrap(),
        ],
        &x,
    );
    let dv: f64 = (0..3).map(|i| x[i] * x[3 + i]).sum();
    let nv: f64 = (0..3).map(|i| x[i] * x[i]).sum();
    assert!(close(r[0], dv) && close(r[1], nv) && close(r[2], nv.sqrt()));
    // Frobenius norm of a matrix.
    let fro = shape::norm_squared(&mut g, &d).unwrap();
    assert_eq!(fro, n2);
    // Components and entries.
    assert_eq!(shape::component(&v, 2).unwrap(), Value::Scalar(v.ids()[2]));
    assert_eq!(shape::entry(&d, 1, 1).unwrap(), Value::Scalar(v.ids()[1]));
}

#[test]
fn matrix_products_match_nalgebra() {
    let mut g = Graph::new();
    let a: [[Id; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| g.var(format!("a{i}{j}"))));
    let b: [[Id; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| g.var(format!("b{i}{j}"))));
    let v = vec_vars(&mut g, "v");
    // Make one factor non-trivial: entries sin(a_ij) + a_ij².
    let a2 = Value::Matrix(a).map(&mut g, |g, e| {
        let s = g.func(Func::Sin, e);
        let q = g.powi(e, 2);
        g.add(s, q)
    });
    let bm = Value::Matrix(b);
    let ab = shape::mul(&mut g, &a2, &bm).unwrap();
    let bt = shape::transpose(&mut g, &bm).unwrap();
    let abt = shape::mul(&mut g, &a2, &bt).unwrap();
    let av = shape::mul(&mut g, &a2, &Value::Vector(v)).unwrap();
    let two = Value::Scalar(g.constant(2.0));
    let a_twice = shape::mul(&mut g, &two, &a2).unwrap();
    let a_half = shape::div(&mut g, &a2, &two).unwrap();
    let a_sum = shape::add(&mut g, &a_half, &a_half).unwrap();
    let a_diff = shape::sub(&mut g, &a_twice, &a2).unwrap();

    let x = inputs(21);
    let (tv, tm) = na_templates!();
    let (mut na, mut nb, mut nv) = (tm, tm, tv);
    for i in 0..3 {
        for j in 0..3 {
            let e = x[3 * i + j];
            na[(i, j)] = e.sin() + e * e;
            nb[(i, j)] = x[9 + 3 * i + j];
        }
        nv[i] = x[18 + i];
    }
    let (nab, nabt, nav) = (na * nb, na * nb.transpose(), na * nv);
    let (e_ab, e_abt, e_av) = (
        eval_value(&g, &ab, &x),
        eval_value(&g, &abt, &x),
        eval_value(&g, &av, &x),
    );
    let (e_sum, e_diff) = (eval_value(&g, &a_sum, &x), eval_value(&g, &a_diff, &x));
    for i in 0..3 {
        for j in 0..3 {
            assert!(close(e_ab[3 * i + j], nab[(i, j)]), "AB[{i}{j}]");
            assert!(close(e_abt[3 * i + j], nabt[(i, j)]), "ABᵀ[{i}{j}]");
            assert!(close(e_sum[3 * i + j], na[(i, j)]), "A/2 + A/2");
            assert!(close(e_diff[3 * i + j], na[(i, j)]), "2A − A");
        }
        assert!(close(e_av[i], nav[i]), "Av[{i}]");
    }
    // (AB)ᵀ = BᵀAᵀ
    let abt2 = shape::transpose(&mut g, &ab).unwrap();
    let at = shape::transpose(&mut g, &a2).unwrap();
    let btat = shape::mul(&mut g, &bt, &at).unwrap();
    let (l, r) = (eval_value(&g, &abt2, &x), eval_value(&g, &btat, &x));
    assert!(l.iter().zip(&r).all(|(p, q)| close(*p, *q)));
}

#[test]
fn shape_mismatches_are_errors_not_panics() {
    let mut g = Graph::new();
    let s = Value::Scalar(g.var("s"));
    let v = Value::Vector(vec_vars(&mut g, "v"));
    let m = Value::Matrix(std::array::from_fn(|i| {
        std::array::from_fn(|j| g.var(format!("m{i}{j}")))
    }));
    let checks: Vec<(&str, Result<Value, routh_symbolic::ShapeError>)> = vec![
        ("scalar + vector", shape::add(&mut g, &s, &v)),
        ("vector + matrix", shape::add(&mut g, &v, &m)),
        ("matrix - scalar", shape::sub(&mut g, &m, &s)),
        ("vector * vector", shape::mul(&mut g, &v, &v)),
        ("vector * matrix", shape::mul(&mut g, &v, &m)),
        ("vector / vector", shape::div(&mut g, &v, &v)),
        ("scalar / matrix", shape::div(&mut g, &s, &m)),
        ("scalar.dot(vector)", shape::dot(&mut g, &s, &v)),
        ("vector.dot(matrix)", shape::dot(&mut g, &v, &m)),
        ("matrix.cross(vector)", shape::cross(&mut g, &m, &v)),
        ("scalar.norm()", shape::norm(&mut g, &s)),
        ("scalar.norm_squared()", shape::norm_squared(&mut g, &s)),
        ("vector.transpose()", shape::transpose(&mut g, &v)),
        (
            "scalar.component_mul(scalar)",
            shape::component_mul(&mut g, &s, &s),
        ),
        (
            "vector.component_mul(matrix)",
            shape::component_mul(&mut g, &v, &m),
        ),
        ("vector.trace()", shape::trace(&mut g, &v)),
        ("diag(matrix)", shape::diag(&mut g, &m)),
        ("skew(scalar)", shape::skew(&mut g, &s)),
        (
            "sin(vector)",
            shape::scalar_func(&mut g, "sin", &v, |g, x| g.func(Func::Sin, x)),
        ),
        ("scalar[0]", shape::component(&s, 0)),
        ("vector[3]", shape::component(&v, 3)),
        ("vector(0, 0)", shape::entry(&v, 0, 0)),
        ("matrix(3, 0)", shape::entry(&m, 3, 0)),
        ("matrix(0, 7)", shape::entry(&m, 0, 7)),
        (
            "grad(vector, x)",
            shape::grad(&mut g, &v, &v.vector("").unwrap()),
        ),
    ];
    for (what, r) in checks {
        let e = r.expect_err(what);
        assert!(!e.to_string().is_empty(), "{what}: empty message");
    }
    // grad with respect to something that is not a variable.
    let vv = v.vector("").unwrap();
    let two = g.constant(2.0);
    let not_vars = [vv[0], vv[1], g.mul(two, vv[2])];
    assert!(shape::grad(&mut g, &s, &not_vars).is_err());
    assert!(s.vector("x").is_err() && v.matrix("x").is_err() && m.scalar("x").is_err());
    // The good cases.
    assert!(shape::mul(&mut g, &m, &s).is_ok() && shape::mul(&mut g, &s, &v).is_ok());
    let n = shape::norm_squared(&mut g, &v).unwrap();
    let gr = shape::grad(&mut g, &n, &vv).unwrap();
    let twice = shape::mul(&mut g, &Value::Scalar(two), &v).unwrap();
    assert_eq!(gr, twice, "grad |v|² = 2v");
}

// ---------------------------------------------------------------- degree

#[test]
fn degree_in_omega() {
    let mut g = Graph::new();
    let w = vec_vars(&mut g, "omega");
    let gamma = g.var("gamma");
    let a = g.var("a");
    let om = w.map(|x| var(&g, x));
    // ½ ωᵀ I(γ) ω with a symmetric inertia depending on γ.
    let i: [[Id; 3]; 3] = std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let k = g.constant(1.0 + (r + c) as f64);
            let s = g.func(Func::Sin, gamma);
            let ks = g.mul(k, s);
            g.add(k, ks)
        })
    });
    let iw = shape::mul(&mut g, &Value::Matrix(i), &Value::Vector(w)).unwrap();
    let q = shape::dot(&mut g, &Value::Vector(w), &iw)
        .unwrap()
        .scalar("")
        .unwrap();
    let h = g.constant(0.5);
    let t = g.mul(h, q);
    assert_eq!(degree(&g, t, &om), Degree::Homogeneous(2));
    let aw = g.add(a, w[0]);
    assert_eq!(degree(&g, aw, &om), Degree::Mixed);
    let rw = g.recip(w[0]);
    assert_eq!(degree(&g, rw, &om), Degree::NotPolynomial);
    let sg = g.func(Func::Sin, gamma);
    let sw = g.mul(sg, w[0]);
    assert_eq!(degree(&g, sw, &om), Degree::Homogeneous(1));
    // More cases.
    let c = g.constant(3.0);
    assert_eq!(degree(&g, c, &om), Degree::Homogeneous(0));
    assert_eq!(degree(&g, gamma, &om), Degree::Homogeneous(0));
    let eg = g.func(Func::Exp, gamma);
    let rg = g.recip(eg);
    let gp = g.powf(gamma, h);
    let free = g.mul(rg, gp);
    assert_eq!(degree(&g, free, &om), Degree::Homogeneous(0));
    let w1w2 = g.mul(w[1], w[2]);
    let w0sq = g.powi(w[0], 2);
    let quad = g.add(w0sq, w1w2);
    assert_eq!(degree(&g, quad, &om), Degree::Homogeneous(2));
    let w0c = g.powi(w[0], 3);
    let cub = g.mul(w0c, gamma);
    assert_eq!(degree(&g, cub, &om), Degree::Homogeneous(3));
    let nw = g.neg(w[1]);
    assert_eq!(degree(&g, nw, &om), Degree::Homogeneous(1));
    let wg = g.div(w[0], gamma);
    assert_eq!(degree(&g, wg, &om), Degree::Homogeneous(1));
    let wpg = g.add(w[0], gamma);
    let wpg2 = g.powi(wpg, 2);
    assert_eq!(degree(&g, wpg2, &om), Degree::Mixed);
    let ww = g.add(w[0], w[1]);
    let ww2 = g.powi(ww, 2);
    assert_eq!(degree(&g, ww2, &om), Degree::Homogeneous(2));
    let mixed_prod = g.mul(aw, w[1]);
    assert_eq!(degree(&g, mixed_prod, &om), Degree::Mixed);
    for f in [Func::Sqrt, Func::Sin, Func::Abs] {
        let e = g.func(f, w[0]);
        assert_eq!(degree(&g, e, &om), Degree::NotPolynomial, "{f:?}");
    }
    let wpow = g.powf(w[0], gamma);
    assert_eq!(degree(&g, wpow, &om), Degree::NotPolynomial);
    let inv2 = g.powi(w[0], -2);
    assert_eq!(degree(&g, inv2, &om), Degree::NotPolynomial);
    let bad = g.add(quad, rw);
    assert_eq!(degree(&g, bad, &om), Degree::NotPolynomial);
    // Cancellations the constructors see: ½ωᵀIω − ½ωᵀIω = 0 has degree 0.
    let zero = g.sub(t, t);
    assert!(g.is_const(zero, 0.0));
    assert_eq!(degree(&g, zero, &om), Degree::Homogeneous(0));
    // The variables in the set matter: in γ, ½ωᵀI(γ)ω is not a polynomial.
    assert_eq!(degree(&g, t, &[var(&g, gamma)]), Degree::NotPolynomial);
}

// ---------------------------------------------------------------- schedule, op counts, printing

#[test]
fn schedule_puts_children_first_and_shares_subexpressions() {
    let (mut g, x, y, z) = xyz();
    // An unrelated expression that must not be scheduled.
    let unrelated = g.func(Func::Exp, z);
    let s = g.func(Func::Sin, x); // shared
    let xy = g.mul(x, y);
    let a = g.add(s, xy);
    let b = g.mul(s, z);
    let c = g.powi(s, 2);
    let out = [a, b, c];
    let sch = schedule(&g, &out);
    assert_eq!(
        sch.iter().filter(|&&id| id == s).count(),
        1,
        "shared sin(x) computed once"
    );
    assert!(!sch.contains(&unrelated));
    assert!(
        sch.windows(2).all(|w| w[0] < w[1]),
        "increasing ids, no duplicates"
    );
    for (k, &id) in sch.iter().enumerate() {
        assert!(!matches!(g.node(id), Node::Const(_) | Node::Var(_)));
        for ch in g.node(id).children() {
            if !matches!(g.node(ch), Node::Const(_) | Node::Var(_)) {
                assert!(sch[..k].contains(&ch), "child scheduled before parent");
            }
        }
    }
    for o in out {
        assert!(sch.contains(&o));
    }
    assert_eq!(sch.len(), 5); // sin x, x·y, a, b, c
                              // Evaluating the schedule in order reproduces `eval`.
    let p = [0.3, -0.8, 1.1];
    let mut val: HashMap<Id, f64> = HashMap::new();
    let get = |val: &HashMap<Id, f64>, id: Id| match g.node(id) {
        Node::Const(bits) => f64::from_bits(bits),
        Node::Var(v) => p[v.index()],
        _ => val[&id],
    };
    for &id in &sch {
        let r = match g.node(id) {
            Node::Add(a, b) => get(&val, a) + get(&val, b),
            Node::Mul(a, b) => get(&val, a) * get(&val, b),
            Node::Powi(a, n) => get(&val, a).powi(n),
            Node::Func(f, a) => f.apply(get(&val, a)),
            n => panic!("unexpected {n:?}"),
        };
        val.insert(id, r);
    }
    let want = g.eval(&out, &p);
    for (o, w) in out.iter().zip(want) {
        assert_eq!(val[o], w);
    }
    assert!(schedule(&g, &[]).is_empty());
    assert!(schedule(&g, &[x]).is_empty(), "leaves need no code");
}

#[test]
fn scaled_products_keep_the_constant_on_the_early_factor() {
    let (mut g, x, y, _) = xyz();
    let two = g.constant(2.0);
    let xy = g.mul(x, y);
    let normal = g.mul(two, xy); // 2·(x·y)
    let scaled = g.mul_scaled(x, 2.0, y); // x·(2·y)
    let two_y = g.mul(two, y);
    assert_ne!(scaled, normal);
    let (a, b) = match g.node(scaled) {
        Node::Mul(a, b) => (a, b),
        n => panic!("not a product: {n:?}"),
    };
    assert!((a, b) == (x, two_y) || (a, b) == (two_y, x));
    let p = [0.7, -1.3, 0.0];
    assert_eq!(g.eval(&[scaled], &p), g.eval(&[normal], &p));
    // Its derivative is that of 2xy, and substitution rebuilds it in normal form.
    let dx = g.diff(scaled, var(&g, x));
    let dy = g.diff(scaled, var(&g, y));
    assert!(close(g.eval(&[dx], &p)[0], 2.0 * p[1]));
    assert!(close(g.eval(&[dy], &p)[0], 2.0 * p[0]));
    let three = g.constant(3.0);
    let map: HashMap<Var, Id> = [(var(&g, x), three)].into_iter().collect();
    let sub = g.substitute(&[scaled], &map)[0];
    let six = g.constant(6.0);
    assert_eq!(sub, g.mul(six, y));
    // A unit scale, or a constant `late`, is an ordinary product.
    assert_eq!(g.mul_scaled(x, 1.0, y), xy);
    assert_eq!(g.mul_scaled(two, 2.0, y), g.mul(two, two_y));
}

#[test]
fn op_counts_follow_the_schedule() {
    let (mut g, x, y, _) = xyz();
    let x3 = g.powi(x, 3); // 2 mul
    let ry = g.recip(y); // 1 div
    let p = g.mul(x3, ry); // 1 mul
    let s = g.func(Func::Sin, x); // 1 call
    let n = g.neg(s); // 1 neg
    let f = g.add(p, n); // 1 add
    let c = op_counts(&g, &[f, f]);
    // As written out: x·x·x (2 mul), x³ / y (the once-used reciprocal folds into 1 div),
    // sin x (1 call), x³/y − sin x (the negation folds into 1 subtraction).
    assert_eq!((c.add, c.mul, c.neg, c.div, c.func), (1, 2, 0, 1, 1));
    assert_eq!(c.total(), 5);
    assert!(c.to_string().starts_with("5 ops"));
}

#[test]
fn infix_printing() {
    let (mut g, x, y, z) = xyz();
    let s = g.add(x, y);
    let sx = g.func(Func::Sin, x);
    let f = g.mul(s, sx);
    assert_eq!(to_infix(&g, f), "(x + y)·sin(x)");
    let d = g.sub(x, y);
    assert_eq!(to_infix(&g, d), "x - y");
    let q = g.div(x, y);
    assert_eq!(to_infix(&g, q), "x / y");
    let two = g.constant(2.0);
    let one = g.one();
    let tx = g.mul(two, x);
    let l = g.add(tx, one);
    assert_eq!(to_infix(&g, l), "1 + 2·x");
    let x2 = g.powi(x, 2);
    assert_eq!(to_infix(&g, x2), "x^2");
    let s2 = g.powi(s, 2);
    assert_eq!(to_infix(&g, s2), "(x + y)^2");
    let r = g.recip(s);
    assert_eq!(to_infix(&g, r), "1 / (x + y)");
    let zs = g.sub(z, s);
    assert_eq!(to_infix(&g, zs), "z - (x + y)");
    let h = g.constant(-0.5);
    let p = g.powf(z, h);
    assert_eq!(to_infix(&g, p), "z^(-0.5)");
    let xy = g.mul(x, y);
    let nxy = g.neg(xy);
    assert_eq!(to_infix(&g, nxy), "-(x·y)");
    let ay = g.func(Func::Abs, y);
    let sg = g.func(Func::Sign, ay);
    assert_eq!(to_infix(&g, sg), "sign(abs(y))");
}

/// A power of two times a sum whose terms all carry constants is distributed (bit for bit the
/// same value: the scaled constants are exact), so that `½(2x + 2yz)` is `x + yz`; other
/// constants, or a term without a constant, leave the product as it is.
#[test]
fn powers_of_two_distribute_over_scaled_sums() {
    let (mut g, x, y, z) = xyz();
    let (two, half, three) = (g.constant(2.0), g.constant(0.5), g.constant(3.0));
    let yz = g.mul(y, z);
    let (tx, tyz) = (g.mul(two, x), g.mul(two, yz));
    let s = g.add(tx, tyz);
    let plain = g.add(x, yz);
    assert_eq!(g.mul(half, s), plain);
    // Nested sums, and a scale that leaves constants: ¼(2x + 2yz + 4z) = ½x + ½yz + z.
    let four = g.constant(4.0);
    let fz = g.mul(four, z);
    let s3 = g.add(s, fz);
    let quarter = g.constant(0.25);
    let q = g.mul(quarter, s3);
    let p = [0.3, -1.7, 2.9];
    assert_eq!(
        g.eval(&[q], &p),
        g.eval(&[s3], &p)
            .iter()
            .map(|v| 0.25 * v)
            .collect::<Vec<_>>()
    );
    assert!(matches!(g.node(q), Node::Add(..)));
    // Not a power of two: kept as a product (3 · (2x + 2yz)).
    let t = g.mul(three, s);
    assert_eq!(g.node(t), Node::Mul(three, s));
    // A term without a constant factor: nothing to save.
    let mixed = g.add(tx, yz);
    let m = g.mul(half, mixed);
    assert_eq!(g.node(m), Node::Mul(half, mixed));
}
