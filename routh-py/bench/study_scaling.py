"""The scaling of `routh.study` on this machine (docs/python.md, "Studies on a cluster"): a
serial loop, then the same study on a LocalCluster of 1 and of 2 worker processes (one thread
each), over N = n x n points (default n = 100: 10⁴ points) of the sleeping Lagrange top's
verdict over (mgl, p_psi).

    python routh-py/bench/study_scaling.py [n]

Prints the wall times, the speed-up of 2 workers over 1, and the overhead per point of a study
against the serial loop (the cluster's start is timed apart: the study is given the client).
"""

import os
import sys
import time

import distributed
import psutil
import numpy as np

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


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    top = routh.Model(TOP, {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    grid = {"mgl": np.linspace(0.5, 2.0, n), "p_psi": np.linspace(0.5, 5.0, n)}
    N = n * n
    print(f"N = {N} points; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    t, c = time.perf_counter(), time.process_time()
    serial = [serial_verdict(top, m, p) for m in grid["mgl"] for p in grid["p_psi"]]
    ts, cs = time.perf_counter() - t, time.process_time() - c
    print(f"serial loop: {ts:.2f} s wall, {cs:.2f} s CPU ({1e6 * cs / N:.0f} us/point)")
    times = {}
    for workers in (1, 2):
        t = time.perf_counter()
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, \
                distributed.Client(cluster) as client:
            start = time.perf_counter() - t
            pids = list(client.run(os.getpid).values())
            cpu0 = sum(sum(psutil.Process(p).cpu_times()[:2]) for p in pids)
            t, c = time.perf_counter(), time.process_time()
            df = routh.study(sleeping, top, grid, client=client, progress=False)
            tw, cd = time.perf_counter() - t, time.process_time() - c
            cw = sum(sum(psutil.Process(p).cpu_times()[:2]) for p in pids) - cpu0
        got = [None if e is not None and not isinstance(e, float) else v
               for v, e in zip(df["verdict"], df["error"])]
        assert got == serial, sum(a != b for a, b in zip(got, serial))
        times[workers] = tw
        print(f"{workers} worker(s): study {tw:.2f} s wall (cluster start {start:.2f} s apart), "
              f"CPU: workers {cw:.2f} s + driver {cd:.2f} s, "
              f"overhead {1e6 * (cw + cd - cs) / N:+.0f} us/point CPU, "
              f"{1e6 * (tw - ts / workers) / N:+.0f} us/point wall against serial/{workers}")
    print(f"speed-up 2 workers / 1 worker: {times[1] / times[2]:.2f}; "
          f"2 workers / serial loop: {ts / times[2]:.2f}")
    print(f"load average after: {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
