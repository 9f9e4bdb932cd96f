//! The Taylor coefficients in time of every node of a [`FlowTape`], by the recurrences of
//! automatic differentiation (Jorba & Zou 2005, §2; Griewank & Walther, *Evaluating
//! Derivatives*, ch. 13): node by node, order by order, `O(p²)` operations a node for order `p`.
//!
//! The tape is compiled once into a [`Program`] of slots, each holding the coefficients
//! `x_0 … x_p` of a series `x(t₀ + τ) = Σ x_k τᵏ`. Only the nodes that `∂L/∂ω` and `∂L/∂γ` read
//! are kept (`J` and `N`, outputs of the tape, are not needed: see [`super`] for the implicit
//! `ω`). Nodes that read no input (numbers, bound parameters) have no coefficient beyond order
//! 0 and are skipped at every order `k ≥ 1`; a product by such a node is a scaling.
//!
//! The recurrences, for `k ≥ 1` (`a`, `b` the operands, `c` the result):
//!
//! | op | `c_k` |
//! |---|---|
//! | `a + b`, `−a` | `a_k + b_k`, `−a_k` |
//! | `a · b` | `Σ_{j=0}^{k} a_j b_{k−j}` |
//! | `1/a` | `−c_0 Σ_{j=1}^{k} a_j c_{k−j}` |
//! | `aⁿ`, `n` a small integer | repeated products (stable where `a_0 = 0`), then `1/·` if `n < 0` |
//! | `a^r`, `r` constant | `(1/(k a_0)) Σ_{j=1}^{k} (r j − (k − j)) a_j c_{k−j}` |
//! | `a^b` | `exp(b · ln a)` |
//! | `√a` | `(a_k − Σ_{j=1}^{k−1} c_j c_{k−j}) / (2 c_0)` |
//! | `sin a`, `cos a` (jointly) | `s_k = (1/k) Σ j a_j c_{k−j}`, `c_k = −(1/k) Σ j a_j s_{k−j}` |
//! | `tan a` (with `u = 1 + tan²a`) | `t_k = (1/k) Σ j a_j u_{k−j}`, `u_k = Σ_{j=0}^{k} t_j t_{k−j}` |
//! | `exp a` | `(1/k) Σ_{j=1}^{k} j a_j c_{k−j}` |
//! | `ln a` | `(a_k − (1/k) Σ_{j=1}^{k−1} j c_j a_{k−j}) / a_0` |
//! | `|a|`, `sign a` | `sign(a_0) a_k`, `0` (the sign of the step's start) |
//!
//! Every `c_k` is affine in the operands' order-`k` coefficients, with the operation's first
//! derivative at order 0 as slope. [`Program::tangent`] carries that slope, `∂c_0/∂ω_0`, for
//! every node: the driver evaluates order `k` with `ω_k = 0`, solves for `ω_k`, and adds
//! `(∂c_0/∂ω_0) ω_k` to each node ([`Program::correct`]), which is exactly the order-`k`
//! coefficient with the true `ω_k`.

use routh_tape::{sign, FlowTape, Func, Op};

/// The largest `|n|` of `xⁿ` computed by repeated products; beyond, by the power recurrence.
const MAX_CHAIN: i32 = 16;

/// One instruction: it writes slot `dst` (and `aux` for the joint ones).
#[derive(Clone, Copy, Debug)]
enum Instr {
    /// An input (`ω_i`, `γ_i`): its coefficients are set by the driver.
    Input,
    /// A number: order 0 only.
    Const(f64),
    Add(u32, u32),
    Neg(u32),
    Mul(u32, u32),
    /// `a · c`, `c` a constant slot.
    Scale(u32, u32),
    Recip(u32),
    /// `a^r`, `r` constant (not a small integer).
    Pow(u32, f64),
    Sqrt(u32),
    /// `sin a` to this slot, `cos a` to the other one (the next).
    Sin(u32, u32),
    /// `tan a` to this slot, `1 + tan² a` to the other one.
    Tan(u32, u32),
    /// `1 + tan² a`, written by its `Tan`.
    TanAux,
    /// Written by its `Sin` partner.
    Partner,
    Exp(u32),
    Ln(u32),
    Abs(u32),
    Sign(u32),
}

/// A [`FlowTape`] compiled for Taylor coefficients in time, with the storage of one step.
#[derive(Clone, Debug)]
pub(crate) struct Program {
    instrs: Vec<Instr>,
    /// The slots that read `ω` (their order-`k` coefficient is corrected by `ω_k`).
    omega_dep: Vec<u32>,
    /// The instructions run at orders `k ≥ 1`, in order.
    active: Vec<u32>,
    /// `∂L/∂ω`, `∂L/∂γ`.
    pub(crate) m: [u32; 3],
    pub(crate) lg: [u32; 3],
    /// Whether `∂L/∂γ` reads an input (else its coefficients beyond order 0 are 0).
    pub(crate) lg_varies: bool,
    /// Coefficients, slot-major: `c[slot · stride + k]`.
    c: Vec<f64>,
    stride: usize,
    /// `∂c_0/∂ω_0` of every slot.
    tangent: Vec<[f64; 3]>,
}

/// The slots of the inputs: `ω_i` is slot `i`, `γ_i` slot `3 + i`.
pub(crate) const OMEGA: [u32; 3] = [0, 1, 2];
pub(crate) const GAMMA: [u32; 3] = [3, 4, 5];

struct Builder {
    instrs: Vec<Instr>,
    varies: Vec<bool>,
    omega: Vec<bool>,
    /// `(sin a, cos a)` of every `a` met, so that `sin a` and `cos a` are one pair.
    trig: std::collections::HashMap<u32, (u32, u32)>,
}

impl Builder {
    fn push(&mut self, i: Instr, varies: bool, omega: bool) -> u32 {
        self.instrs.push(i);
        self.varies.push(varies);
        self.omega.push(omega);
        (self.instrs.len() - 1) as u32
    }
    fn constant(&mut self, x: f64) -> u32 {
        self.push(Instr::Const(x), false, false)
    }
    fn value(&self, s: u32) -> Option<f64> {
        match self.instrs[s as usize] {
            Instr::Const(x) => Some(x),
            _ => None,
        }
    }
    /// An instruction reading `ops`: it varies (reads ω) when one of them does.
    fn op(&mut self, i: Instr, ops: &[u32]) -> u32 {
        let v = ops.iter().any(|&a| self.varies[a as usize]);
        let w = ops.iter().any(|&a| self.omega[a as usize]);
        if !v {
            // Constant operands: fold to a number at build time (the f64 meaning of the op).
            let x = ops
                .iter()
                .map(|&a| self.value(a))
                .collect::<Option<Vec<f64>>>();
            if let Some(x) = x {
                let y = match i {
                    Instr::Add(..) => x[0] + x[1],
                    Instr::Neg(_) => -x[0],
                    Instr::Mul(..) => x[0] * x[1],
                    Instr::Recip(_) => 1.0 / x[0],
                    Instr::Pow(_, r) => x[0].powf(r),
                    Instr::Sqrt(_) => x[0].sqrt(),
                    Instr::Exp(_) => x[0].exp(),
                    Instr::Ln(_) => x[0].ln(),
                    Instr::Abs(_) => x[0].abs(),
                    Instr::Sign(_) => sign(x[0]),
                    _ => f64::NAN,
                };
                if !matches!(i, Instr::Sin(..) | Instr::Tan(..)) {
                    return self.constant(y);
                }
            }
        }
        self.push(i, v, w)
    }
    fn mul(&mut self, a: u32, b: u32) -> u32 {
        match (self.varies[a as usize], self.varies[b as usize]) {
            (true, false) => self.op(Instr::Scale(a, b), &[a, b]),
            (false, true) => self.op(Instr::Scale(b, a), &[a, b]),
            _ => self.op(Instr::Mul(a, b), &[a, b]),
        }
    }
    /// `sin a` and `cos a` as a pair; returns `(sin, cos)`.
    fn sin_cos(&mut self, a: u32) -> (u32, u32) {
        if let Some(&p) = self.trig.get(&a) {
            return p;
        }
        let p = self.sin_cos_new(a);
        self.trig.insert(a, p);
        p
    }
    fn sin_cos_new(&mut self, a: u32) -> (u32, u32) {
        if let (false, Some(x)) = (self.varies[a as usize], self.value(a)) {
            return (self.constant(x.sin()), self.constant(x.cos()));
        }
        let w = self.omega[a as usize];
        let s = self.push(Instr::Sin(a, 0), true, w);
        let c = self.push(Instr::Partner, true, w);
        self.instrs[s as usize] = Instr::Sin(a, c);
        (s, c)
    }
    fn tan(&mut self, a: u32) -> u32 {
        if let (false, Some(x)) = (self.varies[a as usize], self.value(a)) {
            return self.constant(x.tan());
        }
        let w = self.omega[a as usize];
        let t = self.push(Instr::Tan(a, 0), true, w);
        let u = self.push(Instr::TanAux, true, w);
        self.instrs[t as usize] = Instr::Tan(a, u);
        t
    }
    fn powi(&mut self, a: u32, n: i32) -> u32 {
        if n == 0 {
            return self.constant(1.0);
        }
        if n == 1 {
            return a;
        }
        if n.abs() > MAX_CHAIN {
            return self.op(Instr::Pow(a, f64::from(n)), &[a]);
        }
        let mut p = a;
        for _ in 1..n.abs() {
            p = self.mul(p, a);
        }
        if n < 0 {
            self.op(Instr::Recip(p), &[p])
        } else {
            p
        }
    }
}

impl Program {
    /// Compiles `tape` for series of order up to `max_order`.
    pub(crate) fn new(tape: &FlowTape, max_order: usize) -> Program {
        let ops = tape.tape().ops();
        // The nodes ∂L/∂ω and ∂L/∂γ read.
        let mut need = vec![false; ops.len()];
        let outs = tape.tape().outputs();
        for o in &outs[1..7] {
            need[o.slot as usize] = true;
        }
        for i in (0..ops.len()).rev() {
            if need[i] {
                for a in ops[i].operands() {
                    need[a as usize] = true;
                }
            }
        }
        let mut b = Builder {
            instrs: Vec::new(),
            varies: Vec::new(),
            omega: Vec::new(),
            trig: Default::default(),
        };
        for i in 0..6 {
            b.push(Instr::Input, true, i < 3);
        }
        let mut map = vec![u32::MAX; ops.len()];
        let params = tape.params();
        for (i, op) in ops.iter().enumerate() {
            if !need[i] {
                continue;
            }
            let s = |k: u32| map[k as usize];
            map[i] = match *op {
                Op::Const(bits) => b.constant(f64::from_bits(bits)),
                Op::Omega(k) => OMEGA[k as usize],
                Op::Gamma(k) => GAMMA[k as usize],
                // The flow tape is evaluated at p_ψ = 0 (it reads no p_ψ).
                Op::PPsi => b.constant(0.0),
                Op::Param(k) => b.constant(params.get(k as usize).copied().unwrap_or(f64::NAN)),
                Op::Add(x, y) => b.op(Instr::Add(s(x), s(y)), &[s(x), s(y)]),
                Op::Mul(x, y) => b.mul(s(x), s(y)),
                Op::Neg(x) => b.op(Instr::Neg(s(x)), &[s(x)]),
                Op::Recip(x) => b.op(Instr::Recip(s(x)), &[s(x)]),
                Op::Powi(x, n) => b.powi(s(x), n),
                Op::Powf(x, y) => match b.value(s(y)) {
                    Some(r) if r == r.trunc() && r.abs() <= f64::from(MAX_CHAIN) => {
                        b.powi(s(x), r as i32)
                    }
                    Some(0.5) => b.op(Instr::Sqrt(s(x)), &[s(x)]),
                    Some(r) => b.op(Instr::Pow(s(x), r), &[s(x)]),
                    None => {
                        // xʸ = exp(y ln x).
                        let l = b.op(Instr::Ln(s(x)), &[s(x)]);
                        let e = b.mul(s(y), l);
                        b.op(Instr::Exp(e), &[e])
                    }
                },
                Op::Func(f, x) => {
                    let a = s(x);
                    match f {
                        Func::Sqrt => b.op(Instr::Sqrt(a), &[a]),
                        Func::Sin => b.sin_cos(a).0,
                        Func::Cos => b.sin_cos(a).1,
                        Func::Tan => b.tan(a),
                        Func::Exp => b.op(Instr::Exp(a), &[a]),
                        Func::Ln => b.op(Instr::Ln(a), &[a]),
                        Func::Abs => b.op(Instr::Abs(a), &[a]),
                        Func::Sign => b.op(Instr::Sign(a), &[a]),
                    }
                }
            };
        }
        let out = |k: usize| map[outs[k].slot as usize];
        let n = b.instrs.len();
        let stride = max_order + 1;
        let active = (0..n as u32)
            .filter(|&i| b.varies[i as usize] && !matches!(b.instrs[i as usize], Instr::Input))
            .collect();
        let omega_dep = (0..n as u32).filter(|&i| b.omega[i as usize]).collect();
        let lg = [out(4), out(5), out(6)];
        let lg_varies = lg.iter().any(|&s| b.varies[s as usize]);
        Program {
            instrs: b.instrs,
            omega_dep,
            active,
            m: [out(1), out(2), out(3)],
            lg,
            lg_varies,
            c: vec![0.0; n * stride],
            stride,
            tangent: vec![[0.0; 3]; n],
        }
    }

    /// The largest order the storage holds.
    pub(crate) fn max_order(&self) -> usize {
        self.stride - 1
    }

    /// The coefficient `k` of slot `s`.
    #[inline(always)]
    pub(crate) fn coef(&self, s: u32, k: usize) -> f64 {
        self.c[s as usize * self.stride + k]
    }

    /// The coefficients `0..=p` of slot `s`.
    pub(crate) fn series(&self, s: u32, p: usize) -> &[f64] {
        let at = s as usize * self.stride;
        &self.c[at..=at + p]
    }

    /// Sets the coefficient `k` of an input slot.
    #[inline(always)]
    pub(crate) fn set(&mut self, s: u32, k: usize, x: f64) {
        self.c[s as usize * self.stride + k] = x;
    }

    /// `∂c_0/∂ω_0` of slot `s` (valid after [`Program::order_zero`]).
    pub(crate) fn tangent(&self, s: u32) -> [f64; 3] {
        self.tangent[s as usize]
    }

    /// Evaluates every slot at order 0 with the inputs `ω`, `γ`, and the tangents `∂/∂ω`.
    pub(crate) fn order_zero(&mut self, omega: [f64; 3], gamma: [f64; 3]) {
        let st = self.stride;
        for i in 0..3 {
            self.c[OMEGA[i] as usize * st] = omega[i];
            self.c[GAMMA[i] as usize * st] = gamma[i];
            let mut e = [0.0; 3];
            e[i] = 1.0;
            self.tangent[OMEGA[i] as usize] = e;
            self.tangent[GAMMA[i] as usize] = [0.0; 3];
        }
        for d in 6..self.instrs.len() {
            let v = |s: u32| self.c[s as usize * st];
            let g = |s: u32| self.tangent[s as usize];
            let sc = |x: f64, t: [f64; 3]| [x * t[0], x * t[1], x * t[2]];
            let (x, t) = match self.instrs[d] {
                Instr::Input | Instr::Partner | Instr::TanAux => continue,
                Instr::Const(x) => (x, [0.0; 3]),
                Instr::Add(a, b) => {
                    let (ga, gb) = (g(a), g(b));
                    (v(a) + v(b), [ga[0] + gb[0], ga[1] + gb[1], ga[2] + gb[2]])
                }
                Instr::Neg(a) => (-v(a), sc(-1.0, g(a))),
                Instr::Mul(a, b) => {
                    let (ga, gb) = (sc(v(b), g(a)), sc(v(a), g(b)));
                    let x = if a == b { v(a).powi(2) } else { v(a) * v(b) };
                    (x, [ga[0] + gb[0], ga[1] + gb[1], ga[2] + gb[2]])
                }
                Instr::Scale(a, c) => (v(a) * v(c), sc(v(c), g(a))),
                Instr::Recip(a) => {
                    let r = 1.0 / v(a);
                    (r, sc(-r * r, g(a)))
                }
                Instr::Pow(a, r) => {
                    let x = v(a).powf(r);
                    (x, sc(r * v(a).powf(r - 1.0), g(a)))
                }
                Instr::Sqrt(a) => {
                    let x = v(a).sqrt();
                    (x, sc(0.5 / x, g(a)))
                }
                Instr::Sin(a, p) => {
                    let (s, c) = v(a).sin_cos();
                    let (ts, tc) = (sc(c, g(a)), sc(-s, g(a)));
                    self.c[p as usize * st] = c;
                    self.tangent[p as usize] = tc;
                    (s, ts)
                }
                Instr::Tan(a, u) => {
                    let t = v(a).tan();
                    let u0 = 1.0 + t * t;
                    let tt = sc(u0, g(a));
                    self.c[u as usize * st] = u0;
                    self.tangent[u as usize] = sc(2.0 * t, tt);
                    (t, tt)
                }
                Instr::Exp(a) => {
                    let x = v(a).exp();
                    (x, sc(x, g(a)))
                }
                Instr::Ln(a) => (v(a).ln(), sc(1.0 / v(a), g(a))),
                Instr::Abs(a) => (v(a).abs(), sc(sign(v(a)), g(a))),
                Instr::Sign(a) => (sign(v(a)), [0.0; 3]),
            };
            self.c[d * st] = x;
            self.tangent[d] = t;
        }
    }

    /// Evaluates the coefficient `k ≥ 1` of every slot that varies, from the coefficients
    /// `0..k` of every slot and `k` of the inputs.
    pub(crate) fn order(&mut self, k: usize) {
        let st = self.stride;
        let kf = k as f64;
        for n in 0..self.active.len() {
            let d = self.active[n] as usize;
            let c = &mut self.c;
            let at = |s: u32, j: usize| s as usize * st + j;
            // Σ_{j=lo}^{hi} w(j) x_j y_{k−j}.
            let conv = |c: &[f64], x: u32, y: u32, lo: usize, hi: usize| {
                let (x, y) = (x as usize * st, y as usize * st);
                let mut s = 0.0;
                for j in lo..=hi {
                    s += c[x + j] * c[y + k - j];
                }
                s
            };
            let wconv = |c: &[f64], x: u32, y: u32, lo: usize, hi: usize| {
                let (x, y) = (x as usize * st, y as usize * st);
                let mut s = 0.0;
                for j in lo..=hi {
                    s += j as f64 * c[x + j] * c[y + k - j];
                }
                s
            };
            let x = match self.instrs[d] {
                Instr::Input | Instr::Const(_) | Instr::Partner | Instr::TanAux => continue,
                Instr::Add(a, b) => c[at(a, k)] + c[at(b, k)],
                Instr::Neg(a) => -c[at(a, k)],
                Instr::Mul(a, b) => conv(c, a, b, 0, k),
                Instr::Scale(a, s) => c[at(a, k)] * c[at(s, 0)],
                Instr::Recip(a) => {
                    let s = conv(c, a, d as u32, 1, k);
                    -c[at(d as u32, 0)] * s
                }
                Instr::Pow(a, r) => {
                    let (a0, d0) = (a as usize * st, d * st);
                    let mut s = 0.0;
                    for j in 1..=k {
                        s += (r * j as f64 - (k - j) as f64) * c[a0 + j] * c[d0 + k - j];
                    }
                    s / (kf * c[a0])
                }
                Instr::Sqrt(a) => {
                    let s = if k > 1 {
                        conv(c, d as u32, d as u32, 1, k - 1)
                    } else {
                        0.0
                    };
                    (c[at(a, k)] - s) / (2.0 * c[at(d as u32, 0)])
                }
                Instr::Sin(a, co) => {
                    let s = d as u32;
                    let sk = wconv(c, a, co, 1, k) / kf;
                    let ck = -wconv(c, a, s, 1, k) / kf;
                    c[at(s, k)] = sk;
                    c[at(co, k)] = ck;
                    continue;
                }
                Instr::Tan(a, u) => {
                    let tk = wconv(c, a, u, 1, k) / kf;
                    c[at(d as u32, k)] = tk;
                    c[at(u, k)] = conv(c, d as u32, d as u32, 0, k);
                    continue;
                }
                Instr::Exp(a) => wconv(c, a, d as u32, 1, k) / kf,
                Instr::Ln(a) => {
                    let s = if k > 1 {
                        wconv(c, d as u32, a, 1, k - 1) / kf
                    } else {
                        0.0
                    };
                    (c[at(a, k)] - s) / c[at(a, 0)]
                }
                Instr::Abs(a) => sign(c[at(a, 0)]) * c[at(a, k)],
                Instr::Sign(_) => 0.0,
            };
            c[d * st + k] = x;
        }
    }

    /// Adds `(∂c_0/∂ω_0) w` to the coefficient `k` of every slot that reads ω: the coefficients
    /// of order `k` evaluated with `ω_k = 0` become those with `ω_k = w`.
    pub(crate) fn correct(&mut self, k: usize, w: [f64; 3]) {
        let st = self.stride;
        for &s in &self.omega_dep {
            let t = self.tangent[s as usize];
            self.c[s as usize * st + k] += t[0] * w[0] + t[1] * w[1] + t[2] * w[2];
        }
    }
}
