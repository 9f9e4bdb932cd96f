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
import numpy as np

import routh

TOP = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"


def sleeping(model, p_psi, **_):
    m = [s for s in model.steady_motions(p_psi) if abs(s.gamma[2] - 1) < 1e-9][0]
    return model.classify(m)


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    top = routh.Model(TOP, {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    grid = {"mgl": np.linspace(0.5, 2.0, n), "p_psi": np.linspace(0.1, 5.0, n)}
    N = n * n
    print(f"N = {N} points; load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    t = time.perf_counter()
    serial = [sleeping(top.with_params(mgl=m), p_psi=p).verdict
              for m in grid["mgl"] for p in grid["p_psi"]]
    ts = time.perf_counter() - t
    print(f"serial loop: {ts:.2f} s ({1e6 * ts / N:.0f} us/point)")
    times = {}
    for workers in (1, 2):
        t = time.perf_counter()
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, \
                distributed.Client(cluster) as client:
            start = time.perf_counter() - t
            t = time.perf_counter()
            df = routh.study(sleeping, top, grid, client=client, progress=False)
            tw = time.perf_counter() - t
        assert df["verdict"].tolist() == serial and df["error"].isna().all()
        times[workers] = tw
        print(f"{workers} worker(s): study {tw:.2f} s, cluster start {start:.2f} s, "
              f"overhead {1e6 * (workers * tw - ts) / N:+.0f} us/point (CPU-equivalent)")
    print(f"speed-up 2 workers / 1 worker: {times[1] / times[2]:.2f}; "
          f"2 workers / serial loop: {ts / times[2]:.2f}")
    print(f"load average after: {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
