//! Graph → tape → eval equals the graph's own interpreter, bit for bit, at random points of
//! random graphs (every node kind, shared subexpressions, all input kinds).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use routh_symbolic::{Func, Graph, Id, Var};
use routh_tape::{Inputs, Op};

/// A random graph over 10 variables (ω, γ, p_ψ, 3 parameters) built through the constructors.
fn random_graph(rng: &mut ChaCha8Rng, ops: usize) -> (Graph, Vec<Var>, Vec<Id>) {
    let mut g = Graph::new();
    let vs: Vec<Var> = (0..10).map(|i| g.new_var(format!("x{i}"))).collect();
    let mut pool: Vec<Id> = vs.iter().map(|&v| g.var_id(v)).collect();
    for c in [0.5, 2.0, -1.0, 3.0, 0.1] {
        pool.push(g.constant(c));
    }
    for _ in 0..ops {
        let a = pool[rng.gen_range(0..pool.len())];
        let b = pool[rng.gen_range(0..pool.len())];
        let id = match rng.gen_range(0..12) {
            0..=2 => g.add(a, b),
            3 => g.sub(a, b),
            4..=6 => g.mul(a, b),
            7 => g.div(a, b),
            8 => g.powi(a, [2, 3, -2, 5][rng.gen_range(0..4)]),
            9 => {
                let base = g_abs(&mut g, a);
                g.powf(base, b)
            }
            _ => g.func(Func::ALL[rng.gen_range(0..Func::ALL.len())], a),
        };
        pool.push(id);
    }
    (g, vs, pool)
}

fn g_abs(g: &mut Graph, a: Id) -> Id {
    g.func(Func::Abs, a)
}

#[test]
fn tape_equals_graph_eval_bit_for_bit() {
    let mut rng = ChaCha8Rng::seed_from_u64(21);
    let names = ["a", "b", "c", "d"];
    let mut compared = 0;
    for _ in 0..300 {
        let (g, vs, pool) = random_graph(&mut rng, 60);
        let outs: Vec<(&'static str, Id)> = names
            .iter()
            .map(|&n| (n, pool[rng.gen_range(0..pool.len())]))
            .collect();
        let input = |v: Var| match vs.iter().position(|&x| x == v).unwrap_or(0) {
            i @ 0..=2 => Op::Omega(i as u8),
            i @ 3..=5 => Op::Gamma(i as u8 - 3),
            6 => Op::PPsi,
            i => Op::Param(i as u32 - 7),
        };
        let tape = g.to_tape(&outs, &input, 3).expect("a valid tape");
        let mut slots = Vec::new();
        for _ in 0..5 {
            let x: Vec<f64> = (0..10).map(|_| rng.gen_range(-2.0..2.0)).collect();
            let want = g.eval(&outs.iter().map(|o| o.1).collect::<Vec<_>>(), &x);
            let at = Inputs {
                omega: [x[0], x[1], x[2]],
                gamma: [x[3], x[4], x[5]],
                p_psi: x[6],
            };
            let mut got = [0.0; 4];
            tape.eval(&at, &x[7..], &mut slots, &mut got);
            for (w, o) in want.iter().zip(got) {
                assert!(
                    w.to_bits() == o.to_bits() || (w.is_nan() && o.is_nan()),
                    "{w} vs {o}"
                );
                compared += 1;
            }
            // Binding the parameters as constants changes nothing.
            let bound = tape.bind(&x[7..]).expect("3 parameters");
            let mut again = [0.0; 4];
            bound.eval(&at, &[], &mut slots, &mut again);
            for (a, b) in got.iter().zip(again) {
                assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()));
            }
        }
    }
    assert_eq!(compared, 300 * 5 * 4);
}
