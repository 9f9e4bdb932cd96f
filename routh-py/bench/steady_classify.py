"""Benchmark: a Python call of steady_motions + classify on the Kelvin
gyrostat (examples/models/gyrostat.toml) against the same work timed inside Rust.

    python routh-py/bench/steady_classify.py
"""

import pathlib
import time

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]
P = 4.0
N = 200


def python_call(m):
    return [m.classify(s) for s in m.steady_motions(P)]


def main():
    m = routh.Model.load(ROOT / "examples" / "models" / "gyrostat.toml")
    python_call(m)
    routh._routh._bench_rust(m, P, 5)  # warm up
    py, rs = [], []
    for _ in range(5):  # interleaved rounds, best of each (the machine is shared)
        t0 = time.perf_counter()
        for _ in range(N):
            python_call(m)
        py.append((time.perf_counter() - t0) / N)
        rs.append(routh._routh._bench_rust(m, P, N))
    print(f"motions per call: {len(m.steady_motions(P))}")
    print(f"Rust   steady_motions + classify: {min(rs) * 1e6:9.1f} us")
    print(f"Python steady_motions + classify: {min(py) * 1e6:9.1f} us")
    print(f"ratio Python / Rust: {min(py) / min(rs):.3f}")


if __name__ == "__main__":
    main()
