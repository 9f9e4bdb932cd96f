//! The JIT (routh-jit, Cranelift) against the interpreter and the tape's own generic evaluation
//! ([`Tape::eval`]), on random tapes: random DAGs of every operation, every function, integer
//! powers from −9 to 9 and the extremes, constants that fold and inputs that do not, at random
//! points and at special values (±0, ±∞, NaN, negatives under `sqrt` and `ln`).
//!
//! The three do the same IEEE operations in the same order (squares as `x·x`, `xⁿ` by the
//! repeated squaring of `f64::powi`, `1/x` by a division, `sqrt` and `abs` correctly rounded,
//! the transcendental functions by the same Rust functions), so they must agree bit for bit;
//! two NaNs count as equal (their payloads are not specified).
#![cfg(feature = "jit")]

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_jit::JitFunction;
use routh_runtime::kernel::{Interpreter, Jit, Kernel, INPUTS};
use routh_tape::{Func, Inputs, Op, Output, Tape};

/// A value worth testing: mostly ordinary, sometimes special.
fn value(rng: &mut ChaCha8Rng) -> f64 {
    match rng.gen_range(0..20) {
        0 => 0.0,
        1 => -0.0,
        2 => f64::INFINITY,
        3 => f64::NEG_INFINITY,
        4 => f64::NAN,
        5 => f64::from(rng.gen_range(-4i32..5)),
        6 => rng.gen_range(-1e-3..1e-3),
        7 => rng.gen_range(-1e3..1e3),
        _ => rng.gen_range(-3.0..3.0),
    }
}

/// An operand: usually one of the last few slots (deep chains), sometimes any earlier one
/// (sharing).
fn operand(rng: &mut ChaCha8Rng, i: usize) -> u32 {
    let k = if rng.gen_bool(0.7) {
        i - 1 - rng.gen_range(0..i.min(4))
    } else {
        rng.gen_range(0..i)
    };
    k as u32
}

/// A random tape of `n` ops reading `params` parameters, with a few outputs.
fn random_tape(rng: &mut ChaCha8Rng, n: usize, params: u32) -> Tape {
    let mut ops = Vec::with_capacity(n);
    for i in 0..n {
        let leaf = i < 3 || rng.gen_bool(0.2);
        let op = if leaf {
            match rng.gen_range(0..5) {
                0 => Op::constant(value(rng)),
                1 => Op::Omega(rng.gen_range(0..3)),
                2 => Op::Gamma(rng.gen_range(0..3)),
                3 => Op::PPsi,
                _ if params > 0 => Op::Param(rng.gen_range(0..params)),
                _ => Op::constant(f64::from(rng.gen_range(1..4))),
            }
        } else {
            let a = operand(rng, i);
            let b = operand(rng, i);
            match rng.gen_range(0..10) {
                0 | 1 => Op::Add(a, b),
                2 | 3 => Op::Mul(a, b),
                4 => Op::Mul(a, a),
                5 => Op::Neg(a),
                6 => Op::Recip(a),
                7 => Op::Powi(
                    a,
                    match rng.gen_range(0..20) {
                        0 => i32::MIN,
                        1 => i32::MAX,
                        2 => rng.gen_range(-100..100),
                        _ => rng.gen_range(-9..10),
                    },
                ),
                8 => Op::Powf(a, b),
                _ => Op::Func(Func::ALL[rng.gen_range(0..Func::ALL.len())], a),
            }
        };
        ops.push(op);
    }
    let outputs = (0..rng.gen_range(1..12))
        .map(|_| Output {
            name: "y",
            slot: rng.gen_range(0..n) as u32,
        })
        .collect();
    Tape::new(ops, outputs, params).expect("a valid tape")
}

fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

fn inputs(rng: &mut ChaCha8Rng) -> [f64; INPUTS] {
    std::array::from_fn(|_| value(rng))
}

fn generic(tape: &Tape, x: &[f64; INPUTS], params: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; tape.outputs().len()];
    let at = Inputs {
        omega: [x[0], x[1], x[2]],
        gamma: [x[3], x[4], x[5]],
        p_psi: x[6],
    };
    tape.eval(&at, params, &mut Vec::new(), &mut out);
    out
}

#[test]
fn jit_equals_interpreter_and_tape_on_random_tapes() {
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    let mut compared = 0usize;
    for case in 0..300 {
        let n = rng.gen_range(1..120);
        let tape = random_tape(&mut rng, n, 0);
        let jit = JitFunction::compile(&tape).expect("compiles");
        let interp = Interpreter::new(&tape);
        assert_eq!(jit.outputs(), tape.outputs().len());
        for _ in 0..8 {
            let x = inputs(&mut rng);
            let mut a = vec![0.0; tape.outputs().len()];
            jit.eval(&x, &mut a).expect("buffers of the right length");
            let mut b = vec![0.0; tape.outputs().len()];
            interp.eval(&x, &mut b);
            let c = generic(&tape, &x, &[]);
            for k in 0..a.len() {
                assert!(
                    same(a[k], b[k]) && same(a[k], c[k]),
                    "case {case}, output {k} at {x:?}: jit {} interpreter {} tape {}\n{:?}",
                    a[k],
                    b[k],
                    c[k],
                    tape.ops()
                );
                compared += 1;
            }
        }
    }
    println!("{compared} outputs compared");
}

/// Parameters passed at run time (`inputs[7 + k]`) instead of folded in: the same bits as the
/// tape evaluated with them, and as the JIT of the tape with the values bound.
#[test]
fn jit_with_parameters_by_pointer_equals_bound() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for case in 0..100 {
        let np = rng.gen_range(1..5);
        let n = rng.gen_range(4..80);
        let tape = random_tape(&mut rng, n, np);
        let params: Vec<f64> = (0..np).map(|_| value(&mut rng)).collect();
        let open = JitFunction::compile(&tape).expect("compiles");
        let bound = JitFunction::compile(&tape.bind(&params).expect("binds")).expect("compiles");
        assert_eq!(open.inputs(), INPUTS + np as usize);
        for _ in 0..4 {
            let x = inputs(&mut rng);
            let mut buf = x.to_vec();
            buf.extend_from_slice(&params);
            let mut a = vec![0.0; tape.outputs().len()];
            open.eval(&buf, &mut a).expect("ok");
            let mut b = vec![0.0; tape.outputs().len()];
            bound.eval(&x, &mut b).expect("ok");
            let c = generic(&tape, &x, &params);
            for k in 0..a.len() {
                assert!(
                    same(a[k], c[k]) && same(b[k], c[k]),
                    "case {case}, output {k}: by pointer {}, bound {}, tape {}",
                    a[k],
                    b[k],
                    c[k]
                );
            }
        }
    }
}

/// Every function of the DSL, on an input and on a constant (folded at compile time), at
/// ordinary and special values.
#[test]
fn every_func_equals_the_interpreter() {
    let xs = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.3,
        -2.5,
        1e-300,
        -1e-310,
        7.5e10,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        std::f64::consts::FRAC_PI_2,
    ];
    for f in Func::ALL {
        for &c in &xs {
            let tape = Tape::new(
                vec![
                    Op::Gamma(1),
                    Op::Func(f, 0),
                    Op::constant(c),
                    Op::Func(f, 2),
                ],
                vec![Output { name: "x", slot: 1 }, Output { name: "c", slot: 3 }],
                0,
            )
            .expect("valid");
            let jit = Jit(JitFunction::compile(&tape).expect("compiles"));
            let interp = Interpreter::new(&tape);
            let x = [0.0, 0.0, 0.0, 0.0, c, 0.0, 0.0];
            let (mut a, mut b) = ([0.0; 2], [0.0; 2]);
            jit.eval(&x, &mut a);
            interp.eval(&x, &mut b);
            let want = f.apply(c);
            for k in 0..2 {
                assert!(
                    same(a[k], want) && same(b[k], want),
                    "{}({c}): jit {} interpreter {} f64 {want}",
                    f.name(),
                    a[k],
                    b[k]
                );
            }
        }
    }
}

/// A kernel given a buffer shorter than its outputs writes the first ones, like the
/// interpreter, and never more.
#[test]
fn short_output_buffers_get_the_first_outputs() {
    let tape = Tape::new(
        vec![Op::Gamma(0), Op::Omega(0), Op::Add(0, 1), Op::Mul(0, 1)],
        vec![
            Output { name: "a", slot: 2 },
            Output { name: "b", slot: 3 },
            Output { name: "c", slot: 0 },
        ],
        0,
    )
    .expect("valid");
    let jit = Jit(JitFunction::compile(&tape).expect("compiles"));
    let x = [2.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0];
    let mut one = [0.0; 1];
    jit.eval(&x, &mut one);
    assert_eq!(one, [5.0]);
    let mut more = [-1.0; 5];
    jit.eval(&x, &mut more);
    assert_eq!(more, [5.0, 6.0, 3.0, -1.0, -1.0]);
    let mut none: [f64; 0] = [];
    jit.eval(&x, &mut none);
}

/// Unbound tapes, as a `Model` evaluates them: the JIT's and the interpreter's kernels given
/// the parameter values with the inputs ([`Kernel::eval_params`]) equal the tape's own
/// evaluation bit for bit, for several sets of values through the same compiled code.
#[test]
fn kernels_with_parameter_slices_equal_the_tape() {
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    for case in 0..150 {
        let np = rng.gen_range(1..6);
        let n = rng.gen_range(4..100);
        let tape = random_tape(&mut rng, n, np);
        let jit = Jit(JitFunction::compile(&tape).expect("compiles"));
        let interp = Interpreter::new(&tape);
        for _ in 0..4 {
            let params: Vec<f64> = (0..np).map(|_| value(&mut rng)).collect();
            let x = inputs(&mut rng);
            let (mut a, mut b) = (vec![0.0; jit.outputs()], vec![0.0; interp.outputs()]);
            jit.eval_params(&x, &params, &mut a);
            interp.eval_params(&x, &params, &mut b);
            let c = generic(&tape, &x, &params);
            for k in 0..c.len() {
                assert!(
                    same(a[k], c[k]) && same(b[k], c[k]),
                    "case {case}, output {k}: jit {} interpreter {} tape {}",
                    a[k],
                    b[k],
                    c[k]
                );
            }
            // Missing parameters read NaN, in both.
            let (mut a, mut b) = (vec![0.0; jit.outputs()], vec![0.0; interp.outputs()]);
            jit.eval(&x, &mut a);
            interp.eval(&x, &mut b);
            let c = generic(&tape, &x, &[]);
            for k in 0..c.len() {
                assert!(
                    same(a[k], c[k]) && same(b[k], c[k]),
                    "case {case}: no parameters"
                );
            }
        }
    }
}
