"""``routh.study``: a parameter study mapped over a Dask cluster, gathered as a tidy table.

Dask, distributed and pandas are optional: ``pip install ./routh-py[dask]``.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import numbers
import signal
import threading

import numpy as np

_EXTRA = (
    "routh.study needs dask[distributed] and pandas, the optional extra 'dask' of routh: "
    "pip install 'routh[dask]' (from a checkout: pip install './routh-py[dask]')"
)


def _imports():
    try:
        import distributed
        import pandas
    except ImportError as e:
        raise ImportError(f"{_EXTRA} ({e})") from e
    return distributed, pandas


@contextlib.contextmanager
def _ctrl_c_held():
    """Holds a Ctrl-C (SIGINT) that arrives inside the block until the block ends, then raises
    it as usual. Starting a ``LocalCluster`` takes seconds, and a KeyboardInterrupt raised
    inside its constructor (which catches only ``Exception``) leaves its worker processes
    running with no object in hand to close them; held, it is raised once the cluster is
    assigned, and the study's ``finally`` closes it. A second Ctrl-C is not held (a start that
    hangs can still be left). Signals reach Python code in the main thread only: elsewhere, or
    with a SIGINT handler that is not a Python callable, nothing is held."""
    previous = signal.getsignal(signal.SIGINT)
    if threading.current_thread() is not threading.main_thread() or not callable(previous):
        yield
        return
    held = []

    def hold(signum, frame):
        if held:
            previous(signum, frame)
        held.append((signum, frame))

    signal.signal(signal.SIGINT, hold)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        if held:
            previous(*held[0])


def _points(grid):
    """The points of `grid`: the product of its axes (a dict name -> values), or the given
    points (a sequence of dicts, e.g. Monte Carlo samples)."""
    if isinstance(grid, dict):
        names = list(grid)
        axes = [np.atleast_1d(np.asarray(grid[n])).tolist() for n in names]
        return [dict(zip(names, p)) for p in itertools.product(*axes)]
    return [dict(p) for p in grid]


def _fields(result):
    """A result as columns: a dict as its items; a number, string or None as ``value``; a
    routh result object as its scalar attributes (``verdict``, ``energy``, …) and its short
    real vectors (``gamma`` → ``gamma_0``, ``gamma_1``, ``gamma_2``); anything else as
    ``value``."""
    if isinstance(result, dict):
        return dict(result)
    if result is None or isinstance(result, (numbers.Number, str, np.generic)):
        return {"value": result}
    if type(result).__module__ == "routh":
        out = {}
        for name in dir(result):
            if name.startswith("_"):
                continue
            try:
                v = getattr(result, name)
            except Exception:
                continue
            if v is None or isinstance(v, (numbers.Number, str, np.generic)):
                out[name] = v
            elif (
                isinstance(v, np.ndarray)
                and v.ndim == 1
                and v.size <= 4
                and np.isrealobj(v)
            ):
                out.update({f"{name}_{i}": float(x) for i, x in enumerate(v)})
        return out
    return {"value": result}


def _run_chunk(job, model, points, parameters):
    """Runs `job` at each point of a chunk (on a worker): a list of (fields, error)."""
    out = []
    for point in points:
        try:
            params = {k: v for k, v in point.items() if k in parameters}
            m = model.with_params(**params) if params else model
            if callable(job):
                r = job(m, **point)
            else:
                rest = {k: v for k, v in point.items() if k not in parameters}
                r = getattr(m, job)(**rest)
            out.append((_fields(r), None))
        except Exception as e:  # a failing point is recorded, never loses the study
            out.append(({}, f"{type(e).__name__}: {e}"))
    return out


def study(
    job,
    model,
    grid,
    client=None,
    chunk=None,
    progress=True,
    n_workers=2,
    timeout=None,
):
    """Runs `job` at every point of `grid` on a Dask cluster and returns a tidy
    ``pandas.DataFrame``: one row per point, the point's coordinates, the result's fields and
    an ``error`` column (the exception's type and message where the point failed, else None).

    - `job`: a callable ``job(model, **point) -> result``, called with `model` with the
      point's parameters set (``model.with_params(...)``) and all the point's coordinates as
      keywords; or the name of a `Model` method, called as ``getattr(model, job)(**rest)``
      with the coordinates that are not parameters (e.g. ``"steady_motions"`` over
      ``p_psi``). The result becomes columns: a dict its keys, a number ``value``, a routh
      result (``StabilityReport``, ``SteadyMotion``, …) its scalar fields and short vectors.
    - `grid`: named axes ``{name: values}``, whose product is the set of points; names that
      are parameters of `model` are set on it, the others (``p_psi``, …) are passed to `job`.
      A sequence of dicts is taken as the points themselves (Monte Carlo samples).
    - `client`: a ``dask.distributed.Client``, or a scheduler's address (``"tcp://host:8786"``,
      connected to and disconnected afterwards); None: a ``LocalCluster`` of `n_workers`
      worker processes (one thread each) on this machine, closed afterwards.
    - `chunk`: points per task (default: about 8 tasks per worker thread, at most 2000
      points per task). The model is scattered once to every worker (``broadcast=True``);
      tasks refer to it, so it is not shipped per task or per point.
    - `progress`: dask's progress bar while the study runs (not with a `timeout`).
    - `timeout`: seconds; past it the tasks are cancelled and ``TimeoutError`` is raised.

    If the study is interrupted (Ctrl-C, a timeout) its tasks are cancelled, and a cluster it
    made is closed, its worker processes ended. A Ctrl-C while that cluster starts is held until
    it has started (then raised and the cluster closed); a second Ctrl-C is not held.

    >>> import numpy as np, routh
    >>> top = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), "
    ...                   "potential = mgl * gamma.z", {"inertia": [1, 1, 1.25], "mgl": 1.0})
    >>> def sleeping(model, p_psi, **_):          # the verdict of the sleeping top γ = e₃
    ...     m = [s for s in model.steady_motions(p_psi) if abs(s.gamma[2] - 1) < 1e-9][0]
    ...     return model.classify(m)
    >>> df = routh.study(sleeping, top, {"mgl": np.linspace(0.5, 2, 20),
    ...                                  "p_psi": np.linspace(0.1, 5, 50)})
    >>> df.groupby("verdict").size()
    """
    distributed, pandas = _imports()
    points = _points(grid)
    parameters = set(model.parameters)
    own_cluster = None
    own_client = None
    futures = []
    try:
        if client is None:
            with _ctrl_c_held():
                own_cluster = distributed.LocalCluster(
                    n_workers=n_workers,
                    threads_per_worker=1,
                    processes=True,
                    dashboard_address=":0",
                )
                client = own_client = distributed.Client(own_cluster)
        elif isinstance(client, str):
            client = own_client = distributed.Client(client)
        threads = max(1, sum(client.nthreads().values()))
        if chunk is None:
            chunk = min(2000, max(1, math.ceil(len(points) / (8 * threads))))
        chunks = [points[i : i + chunk] for i in range(0, len(points), chunk)]
        # A key of its own (hash=False): with the content's hash as key, the same model
        # scattered by the previous study on this client shares it, and that study's release
        # of the key can reach the scheduler after this scatter, dropping the model under
        # this study's tasks ("lost dependencies").
        shipped = client.scatter(model, broadcast=True, hash=False)
        futures = [
            client.submit(_run_chunk, job, shipped, c, parameters, pure=False)
            for c in chunks
        ]
        if progress and timeout is None:
            distributed.progress(futures)
        distributed.wait(futures, timeout=timeout)
        rows = []
        for c, f in zip(chunks, futures):
            try:
                results = f.result()
            except Exception as e:  # the whole chunk failed (a worker died, …)
                results = [({}, f"{type(e).__name__}: {e}")] * len(c)
            for point, (fields, error) in zip(c, results):
                # A field named as a coordinate (a SteadyMotion's p_psi) is kept as result_<name>.
                fields = {(f"result_{k}" if k in point or k == "error" else k): v
                          for k, v in fields.items()}
                rows.append({**point, **fields, "error": error})
        futures = []
    finally:
        if futures:
            try:
                client.cancel(futures)
            except Exception:
                pass
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()
    df = pandas.DataFrame(rows)
    if "error" not in df:
        df["error"] = None
    axes = list(points[0]) if points else []
    rest = [c for c in df.columns if c not in axes and c != "error"]
    return df[axes + rest + ["error"]]
