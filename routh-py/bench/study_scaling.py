"""The scaling of `routh.study` on this machine (docs/performance.md, "routh.study on a
LocalCluster"): a plain loop in one process, then the same study on a LocalCluster of 1, 2 and 4
worker processes (one thread each), over N = n x n points (default n = 100: 10⁴ points) of the
sleeping Lagrange top's verdict over (mgl, p_psi).

    python routh-py/bench/study_scaling.py [n] [workers, default 1,2,4]

Prints the wall times, the CPU of the workers and of the driver, the speed-up over 1 worker and
over the plain loop, and the overhead per point of a study against the plain loop (the
cluster's start is timed apart: the study is given the client). More worker processes than
cores oversubscribe the machine: the figures then show the cost of that, not a speed-up.
"""

import os
import sys
import time

import distributed
import numpy as np
import psutil

import routh

TOP = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"


def sleeping(model, p_psi, **_):
    m = min(model.steady_motions(p_psi), key=lambda s: abs(s.gamma[2] - 1))
    return model.classify(m)


def serial_verdict(model, mgl, p):
    try:
        return sleeping(model.with_params(mgl=mgl), p_psi=p).verdict
    except Exception:
        return None


def cpu(pids):
    return sum(sum(psutil.Process(p).cpu_times()[:2]) for p in pids)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    counts = [int(w) for w in sys.argv[2].split(",")] if len(sys.argv) > 2 else [1, 2, 4]
    top = routh.Model(TOP, {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    grid = {"mgl": np.linspace(0.5, 2.0, n), "p_psi": np.linspace(0.5, 5.0, n)}
    N = n * n
    cores = os.cpu_count()
    print(f"N = {N} points on {cores} cores; load average {os.getloadavg()[0]:.1f} at the start")
    t, c = time.perf_counter(), time.process_time()
    serial = [serial_verdict(top, m, p) for m in grid["mgl"] for p in grid["p_psi"]]
    ts, cs = time.perf_counter() - t, time.process_time() - c
    print(f"| plain loop | {ts:.2f} s | {cs:.2f} s ({1e6 * cs / N:.0f} µs/point) | | |")
    times = {}
    for workers in counts:
        t = time.perf_counter()
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, \
                distributed.Client(cluster) as client:
            start = time.perf_counter() - t
            pids = list(client.run(os.getpid).values())
            cpu0 = cpu(pids)
            t, c = time.perf_counter(), time.process_time()
            df = routh.study(sleeping, top, grid, client=client, progress=False)
            tw, cd = time.perf_counter() - t, time.process_time() - c
            cw = cpu(pids) - cpu0
        got = [None if e is not None else v for v, e in zip(df["verdict"], df["error"])]
        assert got == serial, sum(a != b for a, b in zip(got, serial))
        times[workers] = tw
        over = " (oversubscribed)" if workers > cores else ""
        print(f"| {workers} worker(s){over} | {tw:.2f} s (start {start:.2f} s apart) "
              f"| workers {cw:.2f} s + driver {cd:.2f} s "
              f"| {1e6 * (cw + cd - cs) / N:+.0f} µs/point CPU "
              f"| {1e6 * (tw - ts / min(workers, cores)) / N:+.0f} µs/point wall "
              f"against loop/{min(workers, cores)} "
              f"| speed-up {times[counts[0]] / tw:.2f} over {counts[0]}, {ts / tw:.2f} over the loop |")
    print(f"load average {os.getloadavg()[0]:.1f} at the end")


if __name__ == "__main__":
    main()
