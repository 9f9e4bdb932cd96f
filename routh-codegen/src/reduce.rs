//! The Routh reduction on the DAG: every output of the generated `Lagrangian` and `Routhian`
//! impls, derived symbolically from `L = kinetic + linear − potential` for any model the DSL
//! accepts (paper (8)–(19), section 5, with errata E4–E6).

use crate::layout::{Bundle, BundleAndSystem, Gyroscopic};
use crate::lower::Lowered;
pub use crate::nodes::{M3, V3};
use crate::system::gyroscopic;
use routh_symbolic::shape::dot3;
use routh_symbolic::{degree, extra_cost, Degree, Graph, Id, Var};
use std::collections::HashMap;

/// Every generated output, as nodes of one graph (so that everything is shared).
pub struct Outputs {
    pub lagrangian: Id,
    pub dl_domega: V3,
    pub dl_dgamma: V3,
    /// J(γ) = ∂²L/∂ω², free of ω.
    pub d2l_domega2: M3,
    pub d2l_domega_dgamma: M3,
    /// (3)
    pub energy: Id,
    /// (9)
    pub cyclic_momentum: Id,
    /// (38) generalised; the ω slots stand for Ω in every Routhian output.
    pub psi_dot: Id,
    /// (14)
    pub routhian: Id,
    pub dr_domega: V3,
    pub dr_dgamma: V3,
    /// (15)
    pub dr_dp: Id,
    pub d2r_domega2: M3,
    pub d2r_domega_dgamma: M3,
    pub d2r_dgamma2: M3,
    /// (34), a function of γ and p_ψ only.
    pub amended_potential: Id,
    /// ψ̇ at Ω = 0 (38).
    pub psi_dot_at_rest: Id,
    /// ∂R/∂γ at Ω = 0: the gradient whose tangential part vanishes at a steady motion (33).
    pub dr_dgamma_at_rest: V3,
    /// ∂²R/∂γ² at Ω = 0.
    pub d2r_dgamma2_at_rest: M3,
    /// A, G, C of (64) at Ω = 0.
    pub gyro_a: M3,
    pub gyro_g: M3,
    pub gyro_c: M3,
    /// `G` of (64) formed from the bundle's own nodes at `(Ω, γ, p_ψ)` (not substituted at
    /// rest): what `GyroscopicSystem::from_bundle` forms from `bundle`, for
    /// `bundle_and_system`. Its `A` is [`Outputs::d2r_domega2`].
    pub system_g: M3,
    /// `C` of (64) formed from the bundle's own nodes, as [`Outputs::system_g`].
    pub system_c: M3,
}

/// `∂f/∂x_i` for the three variables `x`.
fn grad(g: &mut Graph, f: Id, x: &[Var; 3]) -> V3 {
    x.map(|xi| g.diff(f, xi))
}

/// `∂f_i/∂x_j` for every i, j.
fn jacobian(g: &mut Graph, f: &V3, x: &[Var; 3]) -> M3 {
    f.map(|fi| grad(g, fi, x))
}

/// Hessian of the gradient `f = ∂φ/∂x`: computes the upper triangle and mirrors it, so the
/// result is exactly symmetric.
fn sym_jacobian(g: &mut Graph, f: &V3, x: &[Var; 3]) -> M3 {
    let mut h = [[f[0]; 3]; 3];
    for i in 0..3 {
        for j in i..3 {
            let d = g.diff(f[i], x[j]);
            h[i][j] = d;
            h[j][i] = d;
        }
    }
    h
}

fn subst_vec(g: &mut Graph, v: &[Id], map: &HashMap<Var, Id>) -> Vec<Id> {
    g.substitute(v, map)
}

/// How the cyclic momentum q = (∂L/∂ω, γ) of (9) is formed. Both are exact; which gives the
/// shorter code depends on the model, so [`reduce`] derives both and keeps the shorter.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub enum Momentum {
    /// `Σ γ_i ∂L/∂ω_i`, reusing the gradient.
    Contracted,
    /// `d/ds L(ω + sγ, γ)` at `s = 0`: terms such as `n·(γ × γ)` vanish by hash-consing instead
    /// of surviving as sums that cancel only numerically (errata E6, `(n × γ) ⊥ γ`).
    Directional,
}

impl Outputs {
    /// The outputs of `bundle`, by name.
    pub fn bundle(&self) -> Bundle<Id> {
        Bundle {
            routhian: self.routhian,
            psi_dot: self.psi_dot,
            dr_domega: self.dr_domega,
            dr_dgamma: self.dr_dgamma,
            dr_dp: self.dr_dp,
            d2r_domega2: self.d2r_domega2,
            d2r_domega_dgamma: self.d2r_domega_dgamma,
            d2r_dgamma2: self.d2r_dgamma2,
        }
    }

    /// The outputs of `bundle`, in the order of [`Bundle::flatten`].
    pub fn bundle_ids(&self) -> Vec<Id> {
        self.bundle().flatten()
    }

    /// The outputs of `bundle_and_system`, by name: the bundle, then `A`, `G`, `C` of (64)
    /// built from its nodes in the same graph.
    pub fn bundle_and_system(&self) -> BundleAndSystem<Id> {
        BundleAndSystem {
            bundle: self.bundle(),
            system: Gyroscopic {
                a: self.d2r_domega2,
                g: self.system_g,
                c: self.system_c,
            },
        }
    }

    /// The outputs of `gyroscopic_system`, by name.
    pub fn gyroscopic(&self) -> Gyroscopic<Id> {
        Gyroscopic {
            a: self.gyro_a,
            g: self.gyro_g,
            c: self.gyro_c,
        }
    }
}

/// Derives every output from the lowered model, choosing the formulation of (9) that gives the
/// shorter `bundle`.
pub fn reduce(m: &mut Lowered) -> Outputs {
    let a = reduce_with(m, Momentum::Contracted);
    let b = reduce_with(m, Momentum::Directional);
    let g = &m.sym.graph;
    let cost = |o: &Outputs| routh_symbolic::op_counts(g, &o.bundle_ids()).total();
    if cost(&a) <= cost(&b) {
        a
    } else {
        b
    }
}

/// Derives every output with the given formulation of the cyclic momentum.
pub fn reduce_with(m: &mut Lowered, momentum: Momentum) -> Outputs {
    let s = &mut m.sym;
    // The variables ω and γ (to differentiate and substitute by) and their nodes.
    let (w_vars, g_vars) = (s.omega, s.gamma);
    let (w, gm) = (s.ids(w_vars), s.ids(g_vars));
    let g = &mut s.graph;
    let p = g.var_id(s.p_psi);

    // L = T₂ + T₁ − U (35).
    let t1u = g.sub(m.linear, m.potential);
    let lagrangian = g.add(m.kinetic, t1u);
    let dl_domega = grad(g, lagrangian, &w_vars);
    let dl_dgamma = grad(g, lagrangian, &g_vars);
    let zero = g.zero();
    let at_rest: HashMap<Var, Id> = w_vars.iter().map(|&v| (v, zero)).collect();
    let j_full = sym_jacobian(g, &dl_domega, &w_vars);
    let j_flat: Vec<Id> = j_full.iter().flatten().copied().collect();
    let j_rest = subst_vec(g, &j_flat, &at_rest);
    let d2l_domega2: M3 = std::array::from_fn(|i| std::array::from_fn(|k| j_rest[3 * i + k]));
    let d2l_domega_dgamma = jacobian(g, &dl_domega, &g_vars);
    let e1 = dot3(g, &w, &dl_domega);
    let energy = g.sub(e1, lagrangian);
    let cyclic_momentum = match momentum {
        Momentum::Contracted => dot3(g, &dl_domega, &gm),
        Momentum::Directional => {
            let s_var = g.new_var("s");
            let s_dir = g.var_id(s_var);
            let along: HashMap<Var, Id> = w_vars
                .iter()
                .zip(w)
                .zip(gm)
                .map(|((&v, wi), gi)| {
                    let t = g.mul(s_dir, gi);
                    (v, g.add(wi, t))
                })
                .collect();
            let l_along = subst_vec(g, &[lagrangian], &along)[0];
            let dl_ds = g.diff(l_along, s_var);
            let s_zero: HashMap<Var, Id> = [(s_var, zero)].into_iter().collect();
            subst_vec(g, &[dl_ds], &s_zero)[0]
        }
    };

    // (12)/(38) with J(γ): ψ̇ = (p_ψ − (∂L/∂ω(Ω, γ), γ)) / (γᵀJγ), and γᵀJγ = 2 T₂(γ, γ).
    let on_gamma: HashMap<Var, Id> = w_vars.iter().zip(gm).map(|(&v, x)| (v, x)).collect();
    let t2_gamma = subst_vec(g, &[m.kinetic], &on_gamma)[0];
    let two = g.constant(2.0);
    let vertical_inertia = g.mul(two, t2_gamma);
    let slack = g.sub(p, cyclic_momentum);
    let psi_dot = g.div(slack, vertical_inertia);
    // (14): R = L(Ω) + ψ̇ (∂L/∂ω, γ) + ½ψ̇² γᵀJγ − ψ̇ p_ψ = L(Ω) − ½ ψ̇ (p_ψ − (∂L/∂ω(Ω), γ)).
    let half = g.constant(0.5);
    let hs = g.mul(half, slack);
    let corr = g.mul(psi_dot, hs);
    let routhian = g.sub(lagrangian, corr);
    let routhians = routhian_candidates(
        g,
        routhian,
        &dl_domega,
        [m.linear, m.potential],
        [slack, psi_dot, half],
        [&w_vars, &g_vars],
    );
    // The derivatives go through (10) and (36): with ψ̇ an independent slot,
    // 𝒜(Ω, γ, ψ̇) = L(Ω + ψ̇γ, γ) = L(Ω, γ) + ψ̇ q(Ω, γ) + ψ̇² d(γ), where q = (∂L/∂ω(Ω), γ) and
    // d = ½γᵀJγ (L is quadratic in ω, so the expansion is exact). Because ∂𝒜/∂ψ̇ = p_ψ on the
    // level set (12), the first derivatives of R are those of 𝒜 ((18)–(19)), and the Hessian of R
    // is the Schur complement R_xy = 𝒜_xy − 𝒜_xψ̇ 𝒜_ψ̇y / D (differentiate (12) implicitly).
    // Each piece stays as compact as L itself.
    //
    // 𝒜 is a quadratic polynomial in ψ̇ with coefficients L, q, d, so its derivatives are written
    // straight from theirs, in Horner form and with ψ̇ bound to (38) from the start: with
    // e_x = ψ̇ d_x and m_x = q_x + e_x,
    //   𝒜_x = L_x + ψ̇ m_x,   𝒜_xψ̇ = q_x + 2ψ̇ d_x = m_x + e_x,   𝒜_xy = L_xy + ψ̇(q_xy + ψ̇ d_xy).
    // The common factor ψ̇ is applied once per entry, the products ψ̇ d_x are shared by the
    // gradient and the Schur vector, and ψ̇ d_xy is the same node as ψ̇ q_x'y' wherever the
    // coefficients agree (ψ̇I in both the ΩΓ and the γγ block of a gyrostat).
    let hd = g.mul(half, vertical_inertia);
    let vars: Vec<Var> = w_vars.iter().chain(g_vars.iter()).copied().collect();
    let l_x: Vec<Id> = vars.iter().map(|&v| g.diff(lagrangian, v)).collect();
    let q_x: Vec<Id> = (0..6)
        .map(|i| match momentum {
            // The product rule on q = (∂L/∂ω, γ) written out, from the second derivatives of L
            // the outputs need anyway: ∂q/∂Ω_i = Σ_j γ_j ∂²L/∂ω_j∂ω_i and
            // ∂q/∂γ_i = ∂L/∂ω_i + Σ_j γ_j ∂²L/∂ω_j∂γ_i. Differentiating q node by node gives the
            // same terms but threads the first one through the sum ((γ₁B₁₁ + c₁) + γ₂B₂₁) + γ₃B₃₁
            // in an order that differs from one component to the next; the contraction kept
            // whole, c₁ + (γ₁B₁₁ + γ₂B₂₁ + γ₃B₃₁), costs as much and is the same expression in
            // every component.
            Momentum::Contracted if i < 3 => {
                let col = std::array::from_fn(|j| j_full[j][i]);
                dot3(g, &gm, &col)
            }
            Momentum::Contracted => {
                let col = std::array::from_fn(|j| d2l_domega_dgamma[j][i - 3]);
                let contracted = dot3(g, &gm, &col);
                g.add(dl_domega[i - 3], contracted)
            }
            Momentum::Directional => g.diff(cyclic_momentum, vars[i]),
        })
        .collect();
    let d_x: Vec<Id> = vars.iter().map(|&v| g.diff(hd, v)).collect();
    let e_x: Vec<Id> = d_x.iter().map(|&d| g.mul(psi_dot, d)).collect();
    let m_x: Vec<Id> = q_x.iter().zip(&e_x).map(|(&q, &e)| g.add(q, e)).collect();
    let grad_x: [Id; 6] = std::array::from_fn(|i| {
        let t = g.mul(psi_dot, m_x[i]);
        g.add(l_x[i], t)
    });
    // 𝒜_xψ̇ for x = (Ω, γ), and 𝒜_xψ̇ / D (one reciprocal of D for all of them).
    // 𝒜_xψ̇ = q_x + ψ̇ (2d_x) with 2d_x formed before ψ̇ is known: ψ̇ waits for the division by
    // D, and (q_x + e_x) + e_x would add two dependent steps after the product ψ̇ d_x where
    // this adds one (two more operations per coordinate, against a shorter critical path into
    // the Schur complement).
    let k: Vec<Id> = q_x
        .iter()
        .zip(&d_x)
        .zip(&m_x)
        .map(|((&q, &d), &m)| {
            if g.is_const(d, 0.0) {
                m
            } else {
                let e2 = g.mul_scaled(psi_dot, 2.0, d);
                g.add(q, e2)
            }
        })
        .collect();
    let r_d = g.recip(vertical_inertia);
    let kd: Vec<Id> = k.iter().map(|&x| g.mul(x, r_d)).collect();
    let mut hess_x = [[zero; 6]; 6];
    for i in 0..6 {
        for j in i..6 {
            let l_xy = g.diff(l_x[i], vars[j]);
            let q_xy = g.diff(q_x[i], vars[j]);
            let d_xy = g.diff(d_x[i], vars[j]);
            let inner = g.mul(psi_dot, d_xy);
            let inner = g.add(q_xy, inner);
            let a2 = g.mul(psi_dot, inner);
            let a_xy = g.add(l_xy, a2);
            let c = g.mul(kd[i], k[j]);
            let h = g.sub(a_xy, c);
            hess_x[i][j] = h;
            hess_x[j][i] = h;
        }
    }
    let mut bundle = Bundle {
        routhian,
        psi_dot,
        dr_domega: part(&grad_x, X_OMEGA),
        dr_dgamma: part(&grad_x, X_GAMMA),
        // (15)
        dr_dp: g.neg(psi_dot),
        d2r_domega2: block(&hess_x, X_OMEGA, X_OMEGA),
        d2r_domega_dgamma: block(&hess_x, X_OMEGA, X_GAMMA),
        d2r_dgamma2: block(&hess_x, X_GAMMA, X_GAMMA),
    };

    // Every output but R (its slot repeats ψ̇), to price each form of R by what it adds to them.
    let base = Bundle {
        routhian: bundle.psi_dot,
        ..bundle
    }
    .flatten();
    bundle.routhian = routhians
        .into_iter()
        .min_by_key(|&r| extra_cost(g, r, &base))
        .unwrap_or(routhian);

    // (34) and section 5 at Ω = 0. ∂R/∂p_ψ = −ψ̇ is not needed at rest, and it is left out
    // rather than substituted: it is the newest node, and `substitute` rebuilds every node up to
    // the largest root, so it would build nodes no output uses. Its place repeats ψ̇.
    let rest = Bundle {
        dr_dp: bundle.psi_dot,
        ..bundle
    };
    let Bundle {
        routhian: r0,
        psi_dot: psi_dot_at_rest,
        dr_domega: _,
        dr_dgamma: dg0,
        dr_dp: _,
        d2r_domega2: a0,
        d2r_domega_dgamma: mx0,
        d2r_dgamma2: h0,
    } = Bundle::from_flat(subst_vec(g, &rest.flatten(), &at_rest));
    let amended_potential = g.neg(r0);
    let (gyro_g, gyro_c) = gyroscopic(g, &gm, &dg0, &mx0, &h0);
    // The same formulas on the bundle itself, for `bundle_and_system` (17) and (64): built last,
    // so that the nodes of every other method keep their ids (and their generated text).
    let (system_g, system_c) = gyroscopic(
        g,
        &gm,
        &bundle.dr_dgamma,
        &bundle.d2r_domega_dgamma,
        &bundle.d2r_dgamma2,
    );

    Outputs {
        lagrangian,
        dl_domega,
        dl_dgamma,
        d2l_domega2,
        d2l_domega_dgamma,
        energy,
        cyclic_momentum,
        psi_dot,
        routhian: bundle.routhian,
        dr_domega: bundle.dr_domega,
        dr_dgamma: bundle.dr_dgamma,
        dr_dp: bundle.dr_dp,
        d2r_domega2: bundle.d2r_domega2,
        d2r_domega_dgamma: bundle.d2r_domega_dgamma,
        d2r_dgamma2: bundle.d2r_dgamma2,
        amended_potential,
        psi_dot_at_rest,
        dr_dgamma_at_rest: dg0,
        d2r_dgamma2_at_rest: h0,
        gyro_a: a0,
        gyro_g,
        gyro_c,
        system_g,
        system_c,
    }
}

/// Exactly equal formulations of R, (14) as derived (`routhian`) first; [`reduce_with`] keeps
/// the one that costs least next to the other outputs of `bundle` (ties keep (14)). By Euler's
/// theorem for the homogeneous terms (the DSL checks that `kinetic` has degree 2 and `linear`
/// degree 1 in ω), `Ω·∂L/∂Ω = 2T₂ + T₁`, so `L = ½ Ω·(∂L/∂Ω + ∂T₁/∂Ω) − U` and
///
/// `R = ½(Ω·(∂L/∂Ω + ∂T₁/∂Ω) − ψ̇ (p_ψ − q)) − U`,
///
/// which reuses the gradient `∂L/∂Ω` (needed for `∂R/∂Ω`) instead of forming `T₂` and `T₁`
/// (the gyrostat's `½(Ω·(c + a) − ψ̇ q) − m g r·γ` with `c = IΩ + a`). When `U` is homogeneous of
/// degree `k ≥ 1` in γ, `U = (1/k) γ·∂U/∂γ` may reuse the gradient `∂U/∂γ` of `∂R/∂γ` in turn
/// (`Σ (m g rᵢ) γᵢ` rather than `m g (r·γ)`).
///
/// They are built right after ψ̇, before the gradient and the Hessian, so that the one kept gets
/// the ids of a value known that early, rather than coming after everything else (the
/// straight-line code is written in latency order, `crate::order`, which breaks ties by id). `dl_domega` is `∂L/∂Ω`,
/// `[linear, potential]` are `T₁` and `U`, `[slack, psi_dot, half]` the nodes of `p_ψ − q`, ψ̇
/// and ½, and `[w_vars, g_vars]` the variables Ω and γ.
fn routhian_candidates(
    g: &mut Graph,
    routhian: Id,
    dl_domega: &V3,
    [linear, potential]: [Id; 2],
    [slack, psi_dot, half]: [Id; 3],
    [w_vars, g_vars]: [&[Var; 3]; 2],
) -> Vec<Id> {
    let w = w_vars.map(|v| g.var_id(v));
    let gm = g_vars.map(|v| g.var_id(v));
    let sum: V3 = std::array::from_fn(|i| {
        let t1w = g.diff(linear, w_vars[i]);
        g.add(dl_domega[i], t1w)
    });
    let euler = dot3(g, &w, &sum);
    let ps = g.mul(psi_dot, slack);
    let e = g.sub(euler, ps);
    let he = g.mul(half, e);
    let mut potentials = vec![potential];
    if let Degree::Homogeneous(k) = degree(g, potential, g_vars) {
        if k >= 1 {
            let du: V3 = g_vars.map(|v| g.diff(potential, v));
            let dot = dot3(g, &gm, &du);
            let inv = g.constant(1.0 / f64::from(k));
            potentials.push(g.mul(inv, dot));
        }
    }
    let mut candidates = vec![routhian];
    for u in potentials {
        candidates.push(g.sub(he, u));
    }
    candidates
}

/// Where Ω starts in the coordinates `x = (Ω, γ)` of the Schur complement.
const X_OMEGA: usize = 0;
/// Where γ starts in `x = (Ω, γ)`.
const X_GAMMA: usize = 3;

/// The three coordinates of `v` (a vector in `x = (Ω, γ)`) from `start` on.
fn part(v: &[Id; 6], start: usize) -> V3 {
    std::array::from_fn(|i| v[start + i])
}

/// The 3×3 block of `h` (a matrix in `x = (Ω, γ)`) whose rows start at `row` and columns at
/// `col`.
fn block(h: &[[Id; 6]; 6], row: usize, col: usize) -> M3 {
    std::array::from_fn(|i| part(&h[row + i], col))
}
