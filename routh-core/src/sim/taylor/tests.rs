//! The recurrences against closed-form Taylor series: every operation of the tape applied to a
//! known series (`a + b t`), its coefficients compared with the function's own series
//! (`exp`, `sin`, `(1 + t)^r` by the binomial series, `ln(1 + t)`, `tan t`, …).

use routh_tape::{FlowTape, Func, Op, Output, Tape, FLOW_OUTPUTS};

use super::recur::{Program, GAMMA, OMEGA};

const P: usize = 12;

/// A flow tape whose `∂L/∂γ₀` is the node `expr` of `ops` (and `∂L/∂ω = ω`, the rest 0).
fn tape_with(mut ops: Vec<Op>, expr: u32) -> FlowTape {
    let w = ops.len() as u32;
    ops.extend([Op::Omega(0), Op::Omega(1), Op::Omega(2), Op::constant(0.0)]);
    let zero = w + 3;
    let slot = |name: &str| match name {
        "dl_domega[0]" => w,
        "dl_domega[1]" => w + 1,
        "dl_domega[2]" => w + 2,
        "dl_dgamma[0]" => expr,
        _ => zero,
    };
    let outputs = FLOW_OUTPUTS
        .iter()
        .map(|&name| Output {
            name,
            slot: slot(name),
        })
        .collect();
    FlowTape::new(Tape::new(ops, outputs, 0).unwrap(), vec![]).unwrap()
}

/// The series of `expr` when `γ₀(t) = x`, `γ₁(t) = y` (polynomials, coefficients given).
fn series(ops: Vec<Op>, expr: u32, x: &[f64], y: &[f64]) -> Vec<f64> {
    let tape = tape_with(ops, expr);
    let mut prog = Program::new(&tape, P);
    let at = |c: &[f64], k: usize| c.get(k).copied().unwrap_or(0.0);
    prog.order_zero([0.0; 3], [at(x, 0), at(y, 0), 0.0]);
    for k in 1..=P {
        prog.set(GAMMA[0], k, at(x, k));
        prog.set(GAMMA[1], k, at(y, k));
        prog.set(GAMMA[2], k, 0.0);
        for s in OMEGA {
            prog.set(s, k, 0.0);
        }
        prog.order(k);
    }
    prog.series(prog.lg[0], P).to_vec()
}

fn factorial(k: usize) -> f64 {
    (1..=k).map(|i| i as f64).product()
}

/// `C(r, k)`, the coefficient of `tᵏ` in `(1 + t)^r`.
fn binomial(r: f64, k: usize) -> f64 {
    (0..k).map(|i| (r - i as f64) / (i + 1) as f64).product()
}

fn assert_series(got: &[f64], want: impl Fn(usize) -> f64, what: &str) {
    for (k, &g) in got.iter().enumerate() {
        let w = want(k);
        assert!(
            (g - w).abs() <= 1e-13 * (1.0 + w.abs()),
            "{what}: coefficient {k} is {g}, the closed form {w}"
        );
    }
}

#[test]
fn exp_sin_cos_of_a_line() {
    // γ₀ = 0.3 + 2t.
    let x = [0.3, 2.0];
    let e = series(vec![Op::Gamma(0), Op::Func(Func::Exp, 0)], 1, &x, &[]);
    assert_series(
        &e,
        |k| 0.3f64.exp() * 2f64.powi(k as i32) / factorial(k),
        "exp",
    );
    let d = |k: usize, phase: f64| {
        2f64.powi(k as i32) / factorial(k)
            * (0.3 + phase + k as f64 * std::f64::consts::FRAC_PI_2).sin()
    };
    let s = series(vec![Op::Gamma(0), Op::Func(Func::Sin, 0)], 1, &x, &[]);
    assert_series(&s, |k| d(k, 0.0), "sin");
    let c = series(vec![Op::Gamma(0), Op::Func(Func::Cos, 0)], 1, &x, &[]);
    assert_series(&c, |k| d(k, std::f64::consts::FRAC_PI_2), "cos");
    // sin² + cos² = 1, both from one pair.
    let ops = vec![
        Op::Gamma(0),
        Op::Func(Func::Sin, 0),
        Op::Func(Func::Cos, 0),
        Op::Mul(1, 1),
        Op::Mul(2, 2),
        Op::Add(3, 4),
    ];
    let one = series(ops, 5, &x, &[]);
    assert_series(&one, |k| if k == 0 { 1.0 } else { 0.0 }, "sin² + cos²");
}

#[test]
fn binomial_series_of_powers_roots_and_reciprocals() {
    // γ₀ = 1 + t.
    let x = [1.0, 1.0];
    let g = Op::Gamma(0);
    let sqrt = series(vec![g, Op::Func(Func::Sqrt, 0)], 1, &x, &[]);
    assert_series(&sqrt, |k| binomial(0.5, k), "sqrt");
    let recip = series(vec![g, Op::Recip(0)], 1, &x, &[]);
    assert_series(&recip, |k| binomial(-1.0, k), "1/x");
    let cube = series(vec![g, Op::Powi(0, -3)], 1, &x, &[]);
    assert_series(&cube, |k| binomial(-3.0, k), "x⁻³");
    let big = series(vec![g, Op::Powi(0, 20)], 1, &x, &[]);
    assert_series(&big, |k| binomial(20.0, k), "x²⁰");
    let pow = series(vec![g, Op::constant(2.5), Op::Powf(0, 1)], 2, &x, &[]);
    assert_series(&pow, |k| binomial(2.5, k), "x^2.5");
    let ln = series(vec![g, Op::Func(Func::Ln, 0)], 1, &x, &[]);
    let want_ln = |k: usize| {
        if k == 0 {
            0.0
        } else {
            -(-1f64).powi(k as i32) / k as f64
        }
    };
    assert_series(&ln, want_ln, "ln");
    // (1 + t)(1 − t) = 1 − t².
    let ops = vec![
        g,
        Op::constant(2.0),
        Op::Neg(0),
        Op::Add(1, 2),
        Op::Mul(0, 3),
    ];
    let prod = series(ops, 4, &x, &[]);
    assert_series(
        &prod,
        |k| [1.0, 0.0, -1.0].get(k).copied().unwrap_or(0.0),
        "(1+t)(1−t)",
    );
    // |−1 − t| = 1 + t, sign(−1 − t) = −1.
    let abs = series(vec![g, Op::Neg(0), Op::Func(Func::Abs, 1)], 2, &x, &[]);
    assert_series(&abs, |k| if k < 2 { 1.0 } else { 0.0 }, "abs");
    let sign = series(vec![g, Op::Neg(0), Op::Func(Func::Sign, 1)], 2, &x, &[]);
    assert_series(&sign, |k| if k == 0 { -1.0 } else { 0.0 }, "sign");
}

#[test]
fn powers_at_zero_tangent_and_variable_exponents() {
    // t³ where the value is 0: repeated products, not the power recurrence (0/0).
    let t3 = series(vec![Op::Gamma(0), Op::Powi(0, 3)], 1, &[0.0, 1.0], &[]);
    assert_series(&t3, |k| if k == 3 { 1.0 } else { 0.0 }, "t³");
    // tan t = t + t³/3 + 2t⁵/15 + 17t⁷/315 + 62t⁹/2835 + 1382t¹¹/155925.
    let tan = series(
        vec![Op::Gamma(0), Op::Func(Func::Tan, 0)],
        1,
        &[0.0, 1.0],
        &[],
    );
    let want = [
        0.0,
        1.0,
        0.0,
        1.0 / 3.0,
        0.0,
        2.0 / 15.0,
        0.0,
        17.0 / 315.0,
        0.0,
    ]
    .into_iter()
    .chain([62.0 / 2835.0, 0.0, 1382.0 / 155925.0, 0.0]);
    let want: Vec<f64> = want.collect();
    assert_series(&tan, |k| want[k], "tan");
    // (eᵗ)^y with y = γ₁ = 2 (an input, so exp(y ln x)): e^{2t}.
    let ops = vec![
        Op::Gamma(0),
        Op::Func(Func::Exp, 0),
        Op::Gamma(1),
        Op::Powf(1, 2),
    ];
    let e2 = series(ops, 3, &[0.0, 1.0], &[2.0]);
    assert_series(&e2, |k| 2f64.powi(k as i32) / factorial(k), "(eᵗ)^y");
}

/// The order-`k` coefficients evaluated with `ω_k = 0` and corrected by the tangent equal those
/// evaluated with the true `ω_k`: the step the integrator takes for the implicit ω.
#[test]
fn correction_by_the_tangent_is_the_true_coefficient() {
    // sin(ω₀ γ₀) · exp(ω₁) / (1 + ω₀²) + √(2 + ω₂ γ₁).
    let ops = vec![
        Op::Omega(0),
        Op::Gamma(0),
        Op::Mul(0, 1),
        Op::Func(Func::Sin, 2),
        Op::Omega(1),
        Op::Func(Func::Exp, 4),
        Op::Mul(3, 5),
        Op::Mul(0, 0),
        Op::constant(1.0),
        Op::Add(7, 8),
        Op::Recip(9),
        Op::Mul(6, 10),
        Op::Omega(2),
        Op::Gamma(1),
        Op::Mul(12, 13),
        Op::constant(2.0),
        Op::Add(14, 15),
        Op::Func(Func::Sqrt, 16),
        Op::Add(11, 17),
    ];
    let tape = tape_with(ops, 18);
    let w: [[f64; 3]; 5] = [
        [0.4, -0.3, 0.8],
        [0.2, 0.5, -0.1],
        [-0.7, 0.1, 0.3],
        [0.05, -0.2, 0.6],
        [0.3, 0.3, -0.4],
    ];
    let g: [[f64; 3]; 5] = [
        [0.6, 0.0, 0.8],
        [0.1, -0.4, 0.2],
        [0.3, 0.2, -0.5],
        [-0.2, 0.1, 0.1],
        [0.05, 0.4, 0.0],
    ];
    let run = |corrected: bool| {
        let mut prog = Program::new(&tape, 4);
        prog.order_zero(w[0], g[0]);
        for k in 1..=4 {
            for i in 0..3 {
                prog.set(GAMMA[i], k, g[k][i]);
                prog.set(OMEGA[i], k, if corrected { 0.0 } else { w[k][i] });
            }
            prog.order(k);
            if corrected {
                prog.correct(k, w[k]);
            }
        }
        prog.series(prog.lg[0], 4).to_vec()
    };
    let (a, b) = (run(false), run(true));
    for k in 0..=4 {
        assert!(
            (a[k] - b[k]).abs() <= 1e-14 * (1.0 + a[k].abs()),
            "{k}: {a:?} {b:?}"
        );
    }
    assert!(
        a[4].abs() > 1e-3,
        "the test reads a non-trivial coefficient: {a:?}"
    );
}

/// A small tape builder: pushes an op, returns its slot.
struct Ops(Vec<Op>);

impl Ops {
    fn op(&mut self, op: Op) -> u32 {
        self.0.push(op);
        (self.0.len() - 1) as u32
    }
    fn c(&mut self, x: f64) -> u32 {
        self.op(Op::constant(x))
    }
}

/// A flow tape with `∂L/∂ω = m` and `∂L/∂γ = l` (slots of `ops`), the rest 0.
fn flow_tape(mut ops: Ops, m: [u32; 3], l: [u32; 3]) -> FlowTape {
    let zero = ops.c(0.0);
    let slot = |name: &str| match name {
        "dl_domega[0]" => m[0],
        "dl_domega[1]" => m[1],
        "dl_domega[2]" => m[2],
        "dl_dgamma[0]" => l[0],
        "dl_dgamma[1]" => l[1],
        "dl_dgamma[2]" => l[2],
        _ => zero,
    };
    let outputs = FLOW_OUTPUTS
        .iter()
        .map(|&name| Output {
            name,
            slot: slot(name),
        })
        .collect();
    FlowTape::new(Tape::new(ops.0, outputs, 0).unwrap(), vec![]).unwrap()
}

/// The expansion of the whole flow against the flow itself computed without recurrences: the
/// tape evaluated in `f64` by its interpreter, `J = ∂m/∂ω` and `N = ∂m/∂γ` by central
/// differences, `ω̇ = J⁻¹(m × ω + l × γ − N(γ × ω))`, `γ̇ = γ × ω`; the second coefficient
/// against the central difference of that field along itself. `J` depends on γ and ω (a term
/// `ω₀³`), and the tape has products, `sin`, `cos`, `tan`, `exp`, `√`, `1/x` and a power.
#[test]
fn expansion_of_the_flow_matches_its_field() {
    use super::Expansion;
    use nalgebra::{Matrix3, Vector3};
    let mut o = Ops(Vec::new());
    let w: Vec<u32> = (0..3).map(|i| o.op(Op::Omega(i))).collect();
    let g: Vec<u32> = (0..3).map(|i| o.op(Op::Gamma(i))).collect();
    // m₀ = (1 + γ₀²) ω₀ + 0.1 ω₀³ + 0.2 γ₂ ω₁, m₁ = (2 + sin γ₁) ω₁ + 0.2 γ₂ ω₀,
    // m₂ = √(4 + γ₂) ω₂.
    let one = o.c(1.0);
    let g00 = o.op(Op::Mul(g[0], g[0]));
    let a0 = o.op(Op::Add(one, g00));
    let t0 = o.op(Op::Mul(a0, w[0]));
    let w03 = o.op(Op::Powi(w[0], 3));
    let k01 = o.c(0.1);
    let t1 = o.op(Op::Mul(k01, w03));
    let k02 = o.c(0.2);
    let c2 = o.op(Op::Mul(k02, g[2]));
    let t2 = o.op(Op::Mul(c2, w[1]));
    let s0 = o.op(Op::Add(t0, t1));
    let m0 = o.op(Op::Add(s0, t2));
    let two = o.c(2.0);
    let sg1 = o.op(Op::Func(Func::Sin, g[1]));
    let a1 = o.op(Op::Add(two, sg1));
    let u1 = o.op(Op::Mul(a1, w[1]));
    let u2 = o.op(Op::Mul(c2, w[0]));
    let m1 = o.op(Op::Add(u1, u2));
    let four = o.c(4.0);
    let q = o.op(Op::Add(four, g[2]));
    let a2 = o.op(Op::Func(Func::Sqrt, q));
    let m2 = o.op(Op::Mul(a2, w[2]));
    // l₀ = γ₀ ω₀², l₁ = tan(0.3 γ₁) cos(γ₁) ω₁, l₂ = −exp(γ₂) / (1 + γ₀²).
    let w00 = o.op(Op::Mul(w[0], w[0]));
    let l0 = o.op(Op::Mul(g[0], w00));
    let k3 = o.c(0.3);
    let x = o.op(Op::Mul(k3, g[1]));
    let tn = o.op(Op::Func(Func::Tan, x));
    let cg1 = o.op(Op::Func(Func::Cos, g[1]));
    let tc = o.op(Op::Mul(tn, cg1));
    let l1 = o.op(Op::Mul(tc, w[1]));
    let e = o.op(Op::Func(Func::Exp, g[2]));
    let r = o.op(Op::Recip(a0));
    let er = o.op(Op::Mul(e, r));
    let l2 = o.op(Op::Neg(er));
    let tape = flow_tape(o, [m0, m1, m2], [l0, l1, l2]);

    let terms = |w: &Vector3<f64>, g: &Vector3<f64>| {
        let t = tape.eval(&[w.x, w.y, w.z], &[g.x, g.y, g.z], &mut Vec::new());
        (Vector3::from(t.dl_domega), Vector3::from(t.dl_dgamma))
    };
    let field = |w: &Vector3<f64>, g: &Vector3<f64>| {
        let h = 1e-6;
        let (mut j, mut n) = (Matrix3::zeros(), Matrix3::zeros());
        for k in 0..3 {
            let mut e = Vector3::zeros();
            e[k] = h;
            j.set_column(
                k,
                &((terms(&(w + e), g).0 - terms(&(w - e), g).0) / (2.0 * h)),
            );
            n.set_column(
                k,
                &((terms(w, &(g + e)).0 - terms(w, &(g - e)).0) / (2.0 * h)),
            );
        }
        let (m, l) = terms(w, g);
        let gd = g.cross(w);
        let wd = j.try_inverse().unwrap() * (m.cross(w) + l.cross(g) - n * gd);
        (wd, gd)
    };
    let (w0, g0) = (Vector3::new(0.7, -0.4, 1.1), Vector3::new(0.3, 0.5, 0.81));
    let mut ex = Expansion::new(&tape, 4);
    ex.expand(w0.into(), g0.into(), None, 4).unwrap();
    let (wd, gd) = field(&w0, &g0);
    let (w1, g1) = (Vector3::from(ex.omega(1)), Vector3::from(ex.gamma(1)));
    assert!((w1 - wd).amax() < 1e-8, "ω₁ {w1} against {wd}");
    assert!((g1 - gd).amax() < 1e-15, "γ₁ {g1} against {gd}");
    // ω₂ = ½ d/dt ω̇ along the flow.
    let h = 1e-4;
    let (wp, _) = field(&(w0 + wd * h), &(g0 + gd * h));
    let (wm, _) = field(&(w0 - wd * h), &(g0 - gd * h));
    let w2 = (wp - wm) / (4.0 * h);
    let w2_ex = Vector3::from(ex.omega(2));
    assert!((w2_ex - w2).amax() < 1e-6, "ω₂ {w2_ex} against {w2}");
    assert!(w2.amax() > 0.1, "a non-trivial second coefficient: {w2}");
}
