"""Long work releases the GIL, the family callable re-acquires it, and `progress=True` shows the
count of evaluations (tqdm when installed, else a line on stderr)."""

import re
import sys
import threading
import time
import types

import routh


def ticks_during(work):
    """Timestamps of a Python thread that fall strictly inside `work()`."""
    ticks, stop = [], threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            stop.wait(0.001)

    t = threading.Thread(target=ticker)
    t.start()
    time.sleep(0.01)
    t0 = time.perf_counter()
    out = work()
    t1 = time.perf_counter()
    stop.set()
    t.join()
    return out, [x for x in ticks if t0 < x < t1]


def test_family_reacquires_the_gil_and_others_run(top):
    calls = []

    def family(s):
        calls.append(threading.get_ident())  # Python runs here: the GIL is held
        return top, s

    d, inside = ticks_during(lambda: routh.bifurcation_diagram(family, (0.0, 5.0)))
    assert len(d.events) == 2 and len(calls) > 10
    assert inside, "no other Python thread ran during the continuation"


def test_atlas_and_simulation_release_the_gil(top):
    _, inside = ticks_during(lambda: routh.stability_atlas(
        lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1], (0.5, 2.0), (0.5, 5.0),
        nx=8, ny=8))
    assert inside
    # ~64 000 steps: long enough for the ticker to be scheduled on a loaded machine.
    _, inside = ticks_during(lambda: top.simulate([0, 0.3, 5], [0.6, 0, 0.8], 5000.0))
    assert inside


class FakeTqdm:
    """Records what a tqdm bar is told."""

    made = []

    def __init__(self, **kw):
        self.kw, self.total, self.closed = kw, 0, 0
        FakeTqdm.made.append(self)

    def update(self, n):
        self.total += n

    def close(self):
        self.closed += 1


def test_progress_uses_tqdm_when_installed(top, monkeypatch):
    FakeTqdm.made = []
    monkeypatch.setitem(sys.modules, "tqdm", types.SimpleNamespace(tqdm=FakeTqdm))
    monkeypatch.setitem(sys.modules, "tqdm.auto", types.SimpleNamespace(tqdm=FakeTqdm))
    calls = []

    def family(s):
        calls.append(s)
        return top, s

    routh.bifurcation_diagram(family, (0.0, 5.0), progress=True)
    (bar,) = FakeTqdm.made
    assert bar.total == len(calls) and bar.closed == 1
    top.bifurcation_diagram((0.0, 5.0), progress=True)
    assert len(FakeTqdm.made) == 2 and FakeTqdm.made[1].total > 0 and FakeTqdm.made[1].closed == 1
    routh.bifurcation_diagram(family, (0.0, 5.0))  # progress=False: no bar
    assert len(FakeTqdm.made) == 2


def test_progress_without_tqdm_writes_stderr(top, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, "tqdm", None)  # `import tqdm` raises ImportError
    monkeypatch.setitem(sys.modules, "tqdm.auto", None)
    calls = []

    def family(x, y):
        calls.append((x, y))
        return top.with_params(mgl=x), y

    routh.stability_atlas(family, [0, 0, 1], (0.5, 2.0), (0.5, 5.0), nx=4, ny=4, progress=True)
    err = capsys.readouterr().err
    last = re.findall(r"routh: family evaluations: (\d+) done", err)
    assert last == [str(len(calls))], err
    top.bifurcation_diagram((0.0, 5.0))
    assert capsys.readouterr().err == ""  # silent unless asked


CTRL_C = r'''
import os, signal, sys, threading, time, routh
m = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
                {"inertia": [1.0, 1.3, 1.7], "mgl": 1.0})
work = {
    "simulate": lambda: m.simulate([0.3, 1.0, 5.0], [0.6, 0.0, 0.8], 1e9, max_steps=2**62),
    "atlas": lambda: routh.stability_atlas(lambda x, y: (m.with_params(mgl=x), y), [0, 0, 1],
                                           (0.5, 2.0), (0.5, 5.0), nx=2000, ny=2000),
    "diagram": lambda: m.bifurcation_diagram((0.0, 1e6), initial_step=1e-6, min_step=1e-9,
                                              max_step=1e-5, max_steps=2**62),
    "family": lambda: routh.bifurcation_diagram(lambda s: (m, s), (0.0, 1e6), initial_step=1e-6,
                                                min_step=1e-9, max_step=1e-5, max_steps=2**62),
}[sys.argv[1]]
threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
t0 = time.perf_counter()
try:
    work()
    print("finished")
except KeyboardInterrupt:
    print(f"interrupted after {time.perf_counter() - t0:.3f}")
sys.stdout.flush()
os._exit(0)
'''


def test_ctrl_c_interrupts_long_work_within_half_a_second():
    import subprocess

    for name in ["simulate", "atlas", "diagram", "family"]:
        r = subprocess.run([sys.executable, "-c", CTRL_C, name], capture_output=True, text=True,
                           timeout=120)
        assert r.returncode == 0, (name, r.stderr)
        out = r.stdout.strip()
        assert out.startswith("interrupted after"), (name, out, r.stderr)
        # The signal comes at 0.5 s; KeyboardInterrupt within another 0.5 s.
        assert float(out.split()[-1]) < 1.0, (name, out)
