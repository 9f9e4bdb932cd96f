"""`routh.study` on a LocalCluster of 2 worker processes: the numbers of a serial loop, hostile
points (an exception, SystemExit, an unpicklable result, a killed worker, a hang) recorded in
`error` with the rest of the study kept and typed, bad arguments named before any work, and no
worker process left after a cancelled study."""

import math
import os
import pathlib
import re
import subprocess
import sys
import threading
import time
from collections import namedtuple

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")
pd = pytest.importorskip("pandas")
cloudpickle = pytest.importorskip("cloudpickle")
psutil = pytest.importorskip("psutil")

import routh  # noqa: E402

# The jobs below are defined in this test module, which the workers cannot import: ship them
# by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])


def sleeping(model, p_psi, **_):
    """The linear verdict of the sleeping top γ = e₃, and U_r there."""
    m = [s for s in model.steady_motions(p_psi) if abs(s.gamma[2] - 1) < 1e-9][0]
    r = model.classify(m)
    return {"verdict": r.verdict, "energy": m.energy, "u": m.amended_potential}


def failing(model, p_psi, mgl):
    if mgl == 2.0 and p_psi == 1.0:
        raise ValueError("this body is broken")
    return sleeping(model, p_psi)


def slow(model, p_psi, **_):
    time.sleep(2.0)
    return p_psi


GRID = {"mgl": [0.5, 1.0, 2.0], "p_psi": [0.5, 1.0, 1.5, 2.2, 3.5, 4.5]}


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster, distributed.Client(cluster) as c:
        yield c


def serial(job, model, grid):
    rows = []
    for mgl in grid["mgl"]:
        for p in grid["p_psi"]:
            rows.append({"mgl": mgl, "p_psi": p, **job(model.with_params(mgl=mgl), p_psi=p, mgl=mgl)})
    return pd.DataFrame(rows)


def test_study_equals_a_serial_loop_and_maievskii(client, top):
    df = routh.study(sleeping, top, GRID, client=client, chunk=4, progress=False)
    assert len(df) == 18 and df["error"].isna().all()
    assert list(df.columns[:2]) == ["mgl", "p_psi"]
    ref = serial(sleeping, top, GRID)
    pd.testing.assert_frame_equal(df.drop(columns="error"), ref)
    # Maievskii: the sleeping top (A = 1) is stable iff p² > 4·A·mgl.
    stable = df["p_psi"] ** 2 > 4 * df["mgl"]
    assert (df.loc[~stable, "verdict"] == "unstable").all()
    assert df.loc[stable, "verdict"].isin(["secularly_stable", "gyroscopically_stabilized"]).all()
    assert (df["verdict"] == "gyroscopically_stabilized").any()


def test_method_name_and_result_objects(client, top):
    grid = {"mgl": [1.0, 2.0], "p_psi": [1.0, 3.0]}
    # The address form: the study connects to the running scheduler (and leaves it running).
    df = routh.study("certify", top, grid, client=client.scheduler.address, progress=False)
    assert df["error"].isna().all()
    ref = [top.with_params(mgl=m).certify(p) for m in grid["mgl"] for p in grid["p_psi"]]
    assert df["boxes"].tolist() == [c.boxes for c in ref]
    assert df["complete"].tolist() == [c.complete for c in ref]
    assert client.status == "running"
    # A SteadyMotion's fields, p_psi (a coordinate too) kept apart as result_p_psi.
    df = routh.study(lambda m, p_psi: m.steady_motions(p_psi)[0], top, {"p_psi": [3.0]},
                     client=client, progress=False)
    first = top.steady_motions(3.0)[0]
    assert df["gamma_2"][0] == first.gamma[2] and df["result_p_psi"][0] == 3.0
    assert df["energy"][0] == first.energy and df["isolated"][0] == first.isolated


def test_a_failing_point_is_recorded_and_the_rest_complete(client, top):
    df = routh.study(failing, top, GRID, client=client, chunk=5, progress=False)
    bad = (df["mgl"] == 2.0) & (df["p_psi"] == 1.0)
    assert df.loc[bad, "error"].tolist() == ["ValueError: this body is broken"]
    assert df.loc[~bad, "error"].isna().all()
    ref = serial(sleeping, top, GRID)
    assert df.loc[~bad, "verdict"].tolist() == ref.loc[~bad, "verdict"].tolist()
    # An unknown parameter value is an error of its points too, not of the study.
    df = routh.study(sleeping, top, {"mgl": [1.0], "inertia": [[1, 1]], "p_psi": [3.0]},
                     client=client, progress=False)
    assert df["error"].str.contains("ModelError").all()


def test_studies_one_after_another_on_one_client(client, top):
    """The same model scattered by study after study on one client: each study's tasks find it
    (with the content's hash as key, the release of the previous study's copy could drop the
    next one's, and its tasks were cancelled for "lost dependencies" a few times in 40)."""
    ref = serial(sleeping, top, {"mgl": [1.0], "p_psi": [1.0, 3.0]})
    for _ in range(30):
        df = routh.study(sleeping, top, {"mgl": [1.0], "p_psi": [1.0, 3.0]}, client=client,
                         progress=False)
        pd.testing.assert_frame_equal(df.drop(columns="error"), ref)


def workers():
    """The live child processes (multiprocessing's resource tracker, which outlives any
    cluster by design, aside)."""
    out = []
    for p in psutil.Process().children(recursive=True):
        try:
            if p.status() != psutil.STATUS_ZOMBIE and "resource_tracker" not in " ".join(p.cmdline()):
                out.append(p)
        except psutil.NoSuchProcess:
            pass
    return out


def test_a_cancelled_study_leaves_no_worker(top):
    """The study's own cluster takes longer than its timeout to start: every point is marked
    unfinished (a table, no longer a TimeoutError), and the cluster is closed."""
    before = {p.pid for p in workers()}
    df = routh.study(slow, top, {"p_psi": [1.0, 2.0, 3.0, 4.0]}, chunk=1, timeout=1.0)
    assert df["p_psi"].tolist() == [1.0, 2.0, 3.0, 4.0]
    assert (df["error"] == "TimeoutError: not finished within 1 s").all()
    deadline = time.time() + 20
    while time.time() < deadline and {p.pid for p in workers()} - before:
        time.sleep(0.2)
    assert not {p.pid for p in workers()} - before


def test_local_cluster_by_default(top):
    before = {p.pid for p in workers()}
    df = routh.study(sleeping, top, {"mgl": [1.0], "p_psi": [1.0, 3.0]}, progress=False)
    assert df["verdict"].tolist() == ["unstable", "secularly_stable"]
    deadline = time.time() + 20
    while time.time() < deadline and {p.pid for p in workers()} - before:
        time.sleep(0.2)
    assert not {p.pid for p in workers()} - before


def test_without_dask_the_error_names_the_extra(top, monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)  # `import distributed` fails
    with pytest.raises(ImportError, match=r"routh\[dask\]"):
        routh.study(sleeping, top, {"p_psi": [1.0]})


# --- hostile points: one parametrised test over a table ------------------------------------
#
# Each job misbehaves at one point (or hangs there until the test sets a flag file, so that a
# hung worker thread of the shared cluster ends once the test is over). The study must keep
# every other point's result, typed, and record the bad point in `error`.


def exits(model, k, **_):
    if k == 5:
        raise SystemExit(3)
    return k * k


def unpicklable_field(model, k, **_):
    return {"value": k * k, "extra": (i for i in ()) if k == 5 else k}


def unpicklable_result(model, k, **_):
    return threading.Lock() if k == 5 else float(k * k)


def parity(model, k, **_):
    if k == 5:
        raise ValueError("no parity here")
    return k % 2 == 0


def killer(model, k, **_):
    time.sleep(0.05)
    if k == 6:
        os._exit(1)  # as a segfault or the OOM killer would end the worker process
    return k * k


def hangs(model, k, flag, at, **_):
    if k == at:
        deadline = time.time() + 60
        while time.time() < deadline and not os.path.exists(flag):
            time.sleep(0.05)
    return k * k


def product(model, a, b):
    return a * b


Case = namedtuple("Case", "job grid kwargs own bad unfinished dtype seconds restarts")
Case.__new__.__defaults__ = (False, {}, None, "Int64", 60.0, False)

HOSTILE = {
    # SystemExit at a point is that point's error (it lost its chunk).
    "system-exit": Case(exits, {"k": range(12)}, {"chunk": 4}, bad={5: r"SystemExit: 3"}),
    # A field that cannot be pickled (a generator) is that point's error (it lost its chunk).
    "unpicklable-field": Case(unpicklable_field, {"k": range(12)}, {"chunk": 4}, bad={
        5: r"TypeError: the result's field 'extra' \(generator\) cannot be sent back"}),
    "unpicklable-result": Case(unpicklable_result, {"k": range(12)}, {"chunk": 4}, bad={
        5: r"TypeError: the result's field 'value' \(lock\) cannot be sent back"},
        dtype="float64"),
    # Bools and ints stay bools and ints when a point fails (they turned float or object).
    "bools-with-a-failure": Case(parity, {"k": range(12)}, {"chunk": 4},
                                 bad={5: r"ValueError: no parity here"}, dtype="boolean"),
    "streamed-points": Case(exits, lambda flag: ({"k": k} for k in range(12)), {"chunk": 5},
                            bad={5: r"SystemExit: 3"}),
    # A worker killed by one point (os._exit) costs that point alone: the points it held are
    # retried once, each alone, and the one that kills again is reported (all 14 were lost).
    # Tasks of 1 point (the default chunk here), and chunks of 5 (the chunk split for the retry).
    "killed-worker": Case(killer, {"k": range(14)}, {}, own=True,
                          bad={6: r"KilledWorker: the worker process running this point died"}),
    "killed-worker-chunk-5": Case(killer, {"k": range(14)}, {"chunk": 5}, own=True,
                                  bad={6: r"KilledWorker: the worker process running this point died"}),
    # The study's timeout returns what finished, the hung point marked (TimeoutError, and the
    # 40 finished points with it, before).
    "timeout": Case(hangs, {"k": range(41), "at": [40]}, {"chunk": 1, "timeout": 4},
                    bad={40: r"TimeoutError: not finished within 4 s$"}, seconds=4 + 8),
    # A point over point_timeout is marked, the rest of its chunk is run again, and its worker
    # process (whose thread still runs the job) is restarted.
    "point-timeout": Case(hangs, {"k": range(12), "at": [5]}, {"chunk": 12, "point_timeout": 1.5},
                          bad={5: r"TimeoutError: point not finished within 1.5 s \(point_timeout\)"},
                          seconds=30, restarts=True),
    # 9·10⁶ points with a timeout of 3 s: the product is streamed, work starts at once, and the
    # table comes back with the points not reached marked (the grid's build hung the study).
    "huge-grid-timeout": Case(product, {"a": np.arange(3000), "b": np.linspace(0.0, 1.0, 3000)},
                              {"timeout": 3}, unfinished="TimeoutError: not finished within 3 s",
                              dtype="float64", seconds=3 + 20),
}


def expected_value(df, case):
    if case.job is product:
        return df["a"] * df["b"]
    if case.job is parity:
        return df["k"] % 2 == 0
    return df["k"] * df["k"]


@pytest.mark.parametrize("name", list(HOSTILE))
def test_hostile_points_cost_only_themselves(name, client, top, tmp_path):
    case = HOSTILE[name]
    flag = str(tmp_path / "release")
    grid = case.grid(flag) if callable(case.grid) else dict(case.grid)
    if case.job is hangs:
        grid["flag"] = [flag]
    before = {p.pid for p in workers()}
    pids = sorted(client.run(os.getpid).values())
    t = time.monotonic()
    try:
        df = routh.study(case.job, top, grid, client=None if case.own else client,
                         progress=False, **case.kwargs)
    finally:
        pathlib.Path(flag).touch()
    took = time.monotonic() - t
    assert took < case.seconds, took
    n = math.prod(len(v) for v in grid.values()) if isinstance(grid, dict) else 12
    assert len(df) == n
    bad = df["k"].isin(list(case.bad)) if case.bad else pd.Series(False, index=df.index)
    for k, pattern in case.bad.items():
        [error] = df.loc[df["k"] == k, "error"].tolist()
        assert re.match(pattern, error), error
    ok = ~bad & df["error"].isna()
    if case.unfinished is None:
        assert ok.sum() == n - len(case.bad), df[~ok & ~bad]
    else:
        late = ~bad & ~ok
        assert (df.loc[late, "error"] == case.unfinished).all()
        assert 0 < ok.sum() < n and late.sum() > 0
    assert str(df["value"].dtype) == case.dtype
    assert (df.loc[ok, "value"] == expected_value(df[ok], case)).all()
    assert df.loc[~ok, "value"].isna().all()
    if isinstance(grid, dict):
        for name_, axis in grid.items():  # the coordinates, typed as the axes
            assert df[name_].dtype == np.asarray(list(axis)).dtype or name_ == "flag"
    if case.restarts:
        # The worker whose thread ran the hung job was restarted (a new process).
        assert sorted(client.run(os.getpid).values()) != pids
    if case.own:
        deadline = time.time() + 20
        while time.time() < deadline and {p.pid for p in workers()} - before:
            time.sleep(0.2)
        assert not {p.pid for p in workers()} - before


# --- bad arguments: named, before any work -------------------------------------------------

def closed_client(client):
    c = distributed.Client(client.scheduler.address)
    c.close()
    return c


class Unpicklable:
    def __init__(self):
        self.lock = threading.Lock()

    def __call__(self, model, **point):
        return 1.0


BAD = {
    "model-None": (dict(model=None), TypeError, r"^model: expected a routh.Model, got NoneType"),
    "model-str": (dict(model="top"), TypeError, r"^model: "),
    "job-int": (dict(job=42), TypeError, r"^job: expected a callable"),
    "job-unknown-method": (dict(job="no_such_method"), ValueError, r"^job: 'no_such_method' is not"),
    "job-unpicklable": (dict(job=Unpicklable()), TypeError, r"^job: cannot be pickled"),
    "chunk-0": (dict(chunk=0), ValueError, r"^chunk: expected a positive int"),
    "chunk-negative": (dict(chunk=-3), ValueError, r"^chunk: "),
    "chunk-float": (dict(chunk=2.5), ValueError, r"^chunk: "),
    "chunk-str": (dict(chunk="4"), ValueError, r"^chunk: "),
    "chunk-bool": (dict(chunk=True), ValueError, r"^chunk: "),
    "client-closed": (dict(client=closed_client), ValueError, r"^client: the Client is closed"),
    "client-int": (dict(client=8786), TypeError, r"^client: expected"),
    "grid-int": (dict(grid=42), TypeError, r"^grid: expected"),
    "grid-str": (dict(grid="p_psi"), TypeError, r"^grid: expected"),
    "grid-not-dicts": (dict(grid=[{"p_psi": 1.0}, 2.0]), TypeError, r"^grid: point 1 is a float"),
    "grid-error-axis": (dict(grid={"error": [1.0]}), ValueError, r"^grid: an axis is named 'error'"),
    "timeout-0": (dict(timeout=0), ValueError, r"^timeout: expected a positive number"),
    "timeout-nan": (dict(timeout=float("nan")), ValueError, r"^timeout: "),
    "timeout-str": (dict(timeout="5"), ValueError, r"^timeout: "),
    "point-timeout-negative": (dict(point_timeout=-1), ValueError, r"^point_timeout: "),
    "n-workers-0": (dict(n_workers=0), ValueError, r"^n_workers: "),
}


@pytest.mark.parametrize("name", list(BAD))
def test_bad_arguments_are_named_before_any_work(name, client, top, monkeypatch):
    change, error, pattern = BAD[name]

    def no_cluster(*args, **kwargs):
        raise AssertionError("a LocalCluster was started before the arguments were checked")

    monkeypatch.setattr(distributed, "LocalCluster", no_cluster)
    args = dict(job=sleeping, model=top, grid={"mgl": [1.0], "p_psi": [3.0]}, progress=False)
    args.update({k: v(client) if k == "client" and callable(v) else v for k, v in change.items()})
    with pytest.raises(error, match=pattern):
        routh.study(**args)


def test_the_docs_study_runs_as_a_script(tmp_path):
    """The study of docs/python.md ("Studies on a cluster"), run as a script: the LocalCluster's
    worker processes import it, so it needs its `if __name__ == "__main__":` guard."""
    doc = (pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md").read_text()
    section = doc[doc.index("## Studies on a cluster"):]
    code = section[section.index("```py\n") + 6:]
    code = code[: code.index("```")]
    assert 'if __name__ == "__main__":' in code
    script = tmp_path / "doc_study.py"
    script.write_text(code)
    r = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                       timeout=180, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "unstable" in r.stdout


INTERRUPTED = r"""
import os, signal, sys, threading, time

import psutil

import routh


MARKS = os.path.abspath("marks")


def slow(model, p_psi, **_):
    # A mark per worker process that has started a task (the script's cwd is the test's tmp_path).
    open(os.path.join(MARKS, f"started-{os.getpid()}"), "w").close()
    time.sleep(2.0)
    return p_psi


def workers():
    out = []
    for p in psutil.Process().children(recursive=True):
        try:
            if p.status() != psutil.STATUS_ZOMBIE and "resource_tracker" not in " ".join(p.cmdline()):
                out.append(p)
        except psutil.NoSuchProcess:
            pass
    return out


if __name__ == "__main__":
    when = sys.argv[1]
    os.makedirs(MARKS)
    top = routh.Model(
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
        {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    before = {p.pid for p in workers()}
    stop = threading.Event()

    def interrupt():
        # "starting": Ctrl-C as soon as the first worker process of the study's cluster exists,
        # while LocalCluster(...) still waits for its workers to start. "waiting": Ctrl-C once
        # both workers run a task, while the study waits for the results.
        if when == "starting":
            while not stop.is_set() and not {p.pid for p in workers()} - before:
                time.sleep(0.02)
        else:
            while not stop.is_set() and len(os.listdir(MARKS)) < 2:
                time.sleep(0.1)
        if not stop.is_set():
            os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=interrupt, daemon=True).start()
    try:
        routh.study(slow, top, {"p_psi": [float(i) for i in range(30)]}, chunk=1, progress=False)
        print("the study ended without KeyboardInterrupt")
        sys.exit(3)
    except KeyboardInterrupt:
        pass
    finally:
        stop.set()
    deadline = time.time() + 20
    while time.time() < deadline and {p.pid for p in workers()} - before:
        time.sleep(0.2)
    left = {p.pid for p in workers()} - before
    print("left:", sorted(left))
    sys.exit(4 if left else 0)
"""


@pytest.mark.parametrize("when", ["starting", "waiting"])
def test_an_interrupted_study_leaves_no_worker(tmp_path, when):
    """Ctrl-C while the study's own cluster starts, or while the study waits for its tasks:
    KeyboardInterrupt reaches the caller, the tasks are cancelled and the cluster is closed, no
    worker process left. (A Ctrl-C that landed inside LocalCluster(...) once left the workers
    running, closed only by dask's exit hook.) Run in a child interpreter, so that the signal
    cannot land in pytest's own machinery and end the session."""
    import subprocess

    script = tmp_path / "interrupted.py"
    script.write_text(INTERRUPTED)
    r = subprocess.run([sys.executable, str(script), when], capture_output=True, text=True,
                       timeout=180, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr


HELD = r"""
import os, signal, time

from routh.study import _ctrl_c_held


def ctrl_c():
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(0.2)  # the handler runs in this (main) thread at the next bytecode


ran = []
try:
    with _ctrl_c_held():
        ctrl_c()
        ran.append("after one")
except KeyboardInterrupt:
    ran.append("raised at the end")
try:
    with _ctrl_c_held():
        ctrl_c()
        ctrl_c()
        ran.append("after two")
except KeyboardInterrupt:
    ran.append("raised at the second")
ran.append(signal.getsignal(signal.SIGINT) is signal.default_int_handler)
print(ran)
"""


def test_a_ctrl_c_while_the_cluster_starts_is_held_and_a_second_is_not(tmp_path):
    """The study's guard around LocalCluster(...): one Ctrl-C is raised when the block ends
    (the block runs to its end), a second one at once; the handler is restored after."""
    import subprocess

    script = tmp_path / "held.py"
    script.write_text(HELD)
    r = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                       timeout=60, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.strip() == str(["after one", "raised at the end", "raised at the second", True])
