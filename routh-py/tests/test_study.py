"""`routh.study` on a LocalCluster of 2 worker processes: the numbers of a serial loop, a failing
point recorded in `error`, and no worker process left after a cancelled study."""

import sys
import time

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
    before = {p.pid for p in workers()}
    with pytest.raises(TimeoutError):
        routh.study(slow, top, {"p_psi": [1.0, 2.0, 3.0, 4.0]}, chunk=1, timeout=1.0)
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
