//! Compile time of the JIT against the size of a tape: random straight-line tapes of `n`
//! arithmetic ops (finite values), compiled at each optimization level; prints the median of
//! 5 compilations. `cargo run --release -p routh-jit --example compile_time`.

use routh_jit::{JitFunction, OptLevel};
use routh_tape::{Func, Op, Output, Tape};
use std::time::Instant;

/// A deterministic pseudo-random tape of `n` ops with `outputs` outputs.
fn tape(n: usize, outputs: usize, calls: bool) -> Tape {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = |m: usize| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % m as u64) as usize
    };
    let mut ops = vec![Op::Gamma(0), Op::Gamma(1), Op::Omega(2), Op::PPsi];
    while ops.len() < n {
        let i = ops.len();
        let a = (i - 1 - next(i.min(6))) as u32;
        let b = next(i) as u32;
        ops.push(match next(8) {
            0..=2 => Op::Add(a, b),
            3..=5 => Op::Mul(a, b),
            6 => Op::Neg(a),
            _ if calls => Op::Func(Func::Sin, a),
            _ => Op::Func(Func::Sqrt, a),
        });
    }
    let outs = (0..outputs)
        .map(|k| Output {
            name: "y",
            slot: (n - 1 - k * (n / outputs.max(1)) / 2) as u32,
        })
        .collect();
    Tape::new(ops, outs, 0).expect("valid")
}

fn main() {
    for calls in [false, true] {
        for n in [50, 200, 500, 1000, 2000, 4000] {
            let t = tape(n, 36, calls);
            for opt in [OptLevel::None, OptLevel::Speed] {
                let mut times: Vec<f64> = (0..5)
                    .map(|_| {
                        let s = Instant::now();
                        let f = JitFunction::compile_all_with(&[&t], opt).expect("compiles");
                        std::hint::black_box(f);
                        s.elapsed().as_secs_f64() * 1e3
                    })
                    .collect();
                times.sort_by(f64::total_cmp);
                println!(
                    "n = {n:5} calls = {calls:5} {opt:?}: {:8.3} ms ({:.2} µs per op)",
                    times[2],
                    times[2] * 1e3 / n as f64
                );
            }
        }
    }
}
