//! The kinetic matrix as a constant plus a rank-one part, `J(γ) = J₀ + c(γ) v(γ) v(γ)ᵀ`
//! (docs/method.md §2a), found in the kinetic energy as written.
//!
//! A body on a smooth plane has `T = ½ωᵀIω + ½m ż²`, where the height's rate `ż = v(γ)·ω` is
//! linear in ω: its kinetic matrix is `I + m v vᵀ`. Solving with it by Sherman–Morrison from one
//! factorisation of `I` is what an expert writes by hand, and it takes one division per
//! evaluation where a fresh factorisation of `J` takes three in a chain. The generated code
//! hands the runtime `J₀` once (`Lagrangian::constant_inertia`) and `c`, `v` with every
//! evaluation of the equations (`rank_one`).
//!
//! The form is read off the expression, exactly: `T` is split into terms through sums,
//! negations and factors free of ω; every term must be free of γ (it goes to `J₀`), except
//! squares `f·w²` of one expression `w` homogeneous linear in ω, whose factors `f` add up to
//! `½c`. Anything else (two different squares, a γ-dependent quadratic form) leaves the model
//! without the form, and the runtime factorises `J` as before.

use crate::lower::Symbols;
use crate::nodes::{M3, V3};
use routh_symbolic::{degree, Degree, Graph, Id, Node};

/// `J = J₀ + c v vᵀ`, as nodes.
pub struct RankOne {
    /// `J₀`, free of ω and γ (parameters only).
    pub constant: M3,
    /// `c(γ)`.
    pub weight: Id,
    /// `v(γ) = ∂w/∂ω`.
    pub vector: V3,
}

/// The split of the kinetic energy `kinetic` (homogeneous quadratic in ω, as the DSL checks),
/// or `None` when it does not have the form (see the module documentation), or when its matrix
/// is constant (no γ-dependent square: the runtime keeps one factorisation of `J` anyway).
pub fn rank_one(sym: &mut Symbols, kinetic: Id) -> Option<RankOne> {
    let (omega, gamma) = (sym.omega, sym.gamma);
    let g = &mut sym.graph;
    let on_omega = g.dependence(kinetic, &omega);
    let on_gamma = g.dependence(kinetic, &gamma);
    // Read first, without adding a node to the graph: a model without the form leaves the
    // graph (and so its generated code) exactly as it was.
    let mut constant_terms = Vec::new();
    let mut square: Option<Id> = None;
    let mut square_factors = Vec::new();
    for term in terms(g, kinetic, &on_omega)? {
        if !on_gamma[term.node.index()] && !term.factors.iter().any(|f| on_gamma[f.index()]) {
            constant_terms.push(term);
            continue;
        }
        let w = squared(g, term.node)?;
        if square.is_some_and(|w0| w0 != w) || degree(g, w, &omega) != Degree::Homogeneous(1) {
            return None;
        }
        square = Some(w);
        square_factors.push(term);
    }
    let w = square?;
    let constant_terms: Vec<Id> = constant_terms.iter().map(|t| t.build(g)).collect();
    let base = g.sum(constant_terms);
    let factors: Vec<Id> = square_factors.iter().map(|t| t.factor(g)).collect();
    let factor = g.sum(factors);
    let gradient: V3 = omega.map(|x| g.diff(base, x));
    let constant: M3 =
        std::array::from_fn(|i| std::array::from_fn(|k| g.diff(gradient[i], omega[k])));
    let vector: V3 = omega.map(|x| g.diff(w, x));
    // J₀ must be free of ω and γ, v of ω: one walk per set of variables for all twelve.
    let last = constant.iter().flatten().chain(&vector).copied().max()?;
    let (on_omega, on_gamma) = (g.dependence(last, &omega), g.dependence(last, &gamma));
    let depends = |dep: &[bool], id: Id| dep[id.index()];
    if constant
        .iter()
        .flatten()
        .any(|&x| depends(&on_omega, x) || depends(&on_gamma, x))
        || vector.iter().any(|&x| depends(&on_omega, x))
    {
        return None;
    }
    let two = g.constant(2.0);
    let weight = g.mul(two, factor);
    Some(RankOne {
        constant,
        weight,
        vector,
    })
}

/// One term `±f₁·f₂·…·node` of the kinetic energy, the factors free of ω.
struct Term {
    negated: bool,
    factors: Vec<Id>,
    node: Id,
}

impl Term {
    /// `±f₁·f₂·…` as a node.
    fn factor(&self, g: &mut Graph) -> Id {
        let mut f = g.one();
        for &x in &self.factors {
            f = g.mul(f, x);
        }
        if self.negated {
            g.neg(f)
        } else {
            f
        }
    }

    /// The whole term as a node.
    fn build(&self, g: &mut Graph) -> Id {
        let f = self.factor(g);
        g.mul(f, self.node)
    }
}

/// `root` as a sum of [`Term`]s, through sums, negations and products with a factor free of ω
/// (`on_omega` tells, per node, which depend on ω); `None` if that takes too many terms.
fn terms(g: &Graph, root: Id, on_omega: &[bool]) -> Option<Vec<Term>> {
    /// More terms than any body's kinetic energy has: the walk stops rather than expand a
    /// product of sums term by term.
    const MAX_TERMS: usize = 64;
    let mut out = Vec::new();
    let mut stack = vec![Term {
        negated: false,
        factors: Vec::new(),
        node: root,
    }];
    while let Some(mut t) = stack.pop() {
        if stack.len() + out.len() > MAX_TERMS {
            return None;
        }
        match g.node(t.node) {
            Node::Add(a, b) => {
                let other = Term {
                    negated: t.negated,
                    factors: t.factors.clone(),
                    node: b,
                };
                t.node = a;
                stack.extend([t, other]);
            }
            Node::Neg(a) => {
                t.negated = !t.negated;
                t.node = a;
                stack.push(t);
            }
            Node::Mul(a, b) if !on_omega[a.index()] || !on_omega[b.index()] => {
                let (f, rest) = if on_omega[a.index()] { (b, a) } else { (a, b) };
                t.factors.push(f);
                t.node = rest;
                stack.push(t);
            }
            _ => out.push(t),
        }
    }
    Some(out)
}

/// `w` when `term` is `w²`.
fn squared(g: &Graph, term: Id) -> Option<Id> {
    match g.node(term) {
        Node::Powi(w, 2) => Some(w),
        Node::Mul(a, b) if a == b => Some(a),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lower::Symbols;

    /// `J₀ + c v vᵀ` equals the Hessian of the kinetic energy at random points, for a body on
    /// a plane (the form) written several ways; other kinetic energies have no split.
    #[test]
    fn splits_exactly_the_bodies_on_a_plane() {
        for kinetic in [
            // The ellipsoid of paper Example 2, as the test models write it.
            "0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2))",
            // The square first, a negated factor, the constant part in two terms.
            "mass * 0.5 * (n.dot(gamma.cross(omega)) * n.dot(gamma.cross(omega))) + 0.5 * inertia[0] * omega[0] * omega[0] + 0.5 * (inertia[1] * omega[1].powi(2) + inertia[2] * omega[2].powi(2))",
        ] {
            let (mut sym, t) = lowered(kinetic);
            let split = rank_one(&mut sym, t).expect(kinetic);
            check_split(&mut sym, t, &split);
        }
        for kinetic in [
            // Constant J: nothing to gain.
            "0.5 * omega.dot(diag(inertia) * omega)",
            // A γ-dependent quadratic form that is not a square.
            "0.5 * (omega.dot(diag(inertia) * omega) + mass * gamma[0] * omega[0] * omega[1])",
            // Two different squares (rank two).
            "0.5 * (omega.dot(diag(inertia) * omega) + mass * n.dot(gamma.cross(omega)).powi(2) + mass * gamma.dot(omega).powi(2))",
        ] {
            let (mut sym, t) = lowered(kinetic);
            assert!(rank_one(&mut sym, t).is_none(), "{kinetic}");
        }
    }

    /// Random kinetic energies built from terms free of γ, squares of one linear form
    /// `w = n·(γ × ω)` with factors that may depend on γ, a second square and a γ-dependent
    /// cross term, summed, scaled and negated in random nestings: the split is found exactly
    /// when the terms that depend on γ are squares of one form, and whenever it is found,
    /// `J₀ + c v vᵀ` is the Hessian.
    #[test]
    fn random_kinetic_energies() {
        const FREE: [&str; 4] = [
            "inertia[0] * omega[0] * omega[0]",
            "mass * omega[1] * omega[2]",
            "omega.dot(diag(inertia) * omega)",
            "(omega[0] + 2.0 * omega[1]).powi(2)",
        ];
        const W_FACTORS: [&str; 4] = ["mass", "0.5 * mass", "gamma[2].powi(2)", "(-0.25)"];
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = |n: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        let mut found = 0;
        for _ in 0..150 {
            let mut terms: Vec<String> = (0..1 + next(3)).map(|_| FREE[next(4)].into()).collect();
            let squares = next(3);
            for _ in 0..squares {
                let f = W_FACTORS[next(4)];
                terms.push(format!("{f} * n.dot(gamma.cross(omega)).powi(2)"));
            }
            // 0: nothing else; 1: a second square; 2: a γ-dependent cross term.
            let other = next(3);
            match other {
                1 => terms.push("mass * gamma.dot(omega).powi(2)".into()),
                2 => terms.push("gamma[0] * omega[0] * omega[1]".into()),
                _ => {}
            }
            // Random nesting: group neighbours, scale or negate the groups.
            while terms.len() > 1 {
                let i = next(terms.len() - 1);
                let (a, b) = (terms.remove(i), terms.remove(i));
                terms.insert(
                    i,
                    match next(3) {
                        0 => format!("{a} + {b}"),
                        1 => format!("0.5 * ({a} + {b})"),
                        _ => format!("{a} - (-({b}))"),
                    },
                );
            }
            let kinetic = terms.pop().expect("one term");
            let expected = match other {
                0 => squares > 0,
                1 => squares == 0,
                _ => false,
            };
            let (mut sym, t) = lowered(&kinetic);
            let split = rank_one(&mut sym, t);
            assert_eq!(split.is_some(), expected, "{kinetic}");
            if let Some(split) = split {
                check_split(&mut sym, t, &split);
                found += 1;
            }
        }
        assert!(found > 30, "only {found} splits");
    }

    /// The symbols and kinetic energy of an ellipsoid-like model with the given `kinetic`.
    fn lowered(kinetic: &str) -> (Symbols, Id) {
        let src = format!(
            "#[derive(Lagrangian)]
            #[lagrangian(
                let d = diag(semi_axes.component_mul(semi_axes)),
                let c3 = gamma.dot(d * gamma).sqrt() - offset.dot(gamma),
                let n = grad(c3, gamma),
                kinetic = {kinetic},
                potential = mass * g * c3,
            )]
            struct Body {{ inertia: Vector3<f64>, semi_axes: Vector3<f64>, offset: Vector3<f64>, mass: f64, g: f64 }}"
        );
        let di: syn::DeriveInput = syn::parse_str(&src).expect("parses");
        let m = crate::analyse(&di).expect("a valid model");
        (m.lowered.sym, m.lowered.kinetic)
    }

    /// Evaluates `J₀ + c v vᵀ` and the Hessian of `t` (by the graph's own `diff`, a path the
    /// split does not take: the Hessian of the whole, not of its parts) at random inputs.
    fn check_split(sym: &mut Symbols, t: Id, split: &RankOne) {
        let omega = sym.omega;
        let g = &mut sym.graph;
        let hessian: Vec<Id> = (0..3)
            .flat_map(|i| (0..3).map(move |k| (i, k)))
            .map(|(i, k)| {
                let d = g.diff(t, omega[i]);
                g.diff(d, omega[k])
            })
            .collect();
        let mut roots = hessian.clone();
        roots.extend(split.constant.iter().flatten());
        roots.push(split.weight);
        roots.extend(split.vector);
        let mut state = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..20 {
            let inputs: Vec<f64> = (0..g.num_vars())
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    0.5 + (state >> 11) as f64 / (1u64 << 53) as f64
                })
                .collect();
            let vals = g.eval(&roots, &inputs);
            let (h, rest) = vals.split_at(9);
            let (j0, rest) = rest.split_at(9);
            let (c, v) = (rest[0], &rest[1..4]);
            for i in 0..3 {
                for k in 0..3 {
                    let want = h[3 * i + k];
                    let got = j0[3 * i + k] + c * v[i] * v[k];
                    assert!(
                        (got - want).abs() <= 1e-13 * (1.0 + want.abs()),
                        "J[{i}][{k}]: {got} vs {want}"
                    );
                }
            }
        }
    }
}
