"""``routh.study``: a parameter study mapped over a Dask cluster, gathered as a tidy table.

Dask, distributed and pandas are optional: ``pip install ./routh-py[dask]``.
"""

from __future__ import annotations

import collections
import concurrent.futures
import contextlib
import itertools
import math
import numbers
import pickle
import queue
import signal
import sys
import threading
import time
import uuid
import warnings
from collections.abc import Iterable, Mapping

import numpy as np

_EXTRA = (
    "routh.study needs dask[distributed] and pandas, the optional extra 'dask' of routh: "
    "pip install 'routh[dask]' (from a checkout: pip install './routh-py[dask]')"
)

# The error of a point whose worker process died on its first run (in its chunk) and again on
# its retry (alone).
_LOST = (
    "KilledWorker: the worker process running this point died, and again when the point was "
    "retried alone on another worker (a crash, os._exit or the OOM killer in the job?)"
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


def _describe(e):
    """``"Type: message"`` of an exception (the type alone if the message is empty)."""
    try:
        msg = str(e)
    except Exception:
        msg = "(its message could not be formed)"
    return f"{type(e).__name__}: {msg}" if msg else type(e).__name__


# --- the grid, streamed -------------------------------------------------------------------


class _Product:
    """The product of named axes, never built: point ``i`` is the ``i``-th of
    ``itertools.product(*axes)`` (the last axis varies fastest), found from ``i`` alone."""

    def __init__(self, names, axes):
        self.names = names
        self.axes = axes
        self.sizes = [len(a) for a in axes]
        self.n = math.prod(self.sizes)

    def point(self, i):
        coords = [None] * len(self.axes)
        for j in range(len(self.axes) - 1, -1, -1):
            i, r = divmod(i, self.sizes[j])
            coords[j] = self.axes[j][r]
        return dict(zip(self.names, coords))

    def chunks(self, chunk):
        for start in range(0, self.n, chunk):
            yield range(start, min(start + chunk, self.n)), None

    def column(self, pandas, j):
        """The ``j``-th coordinate of all the points, typed as `_typed` types the axis."""
        stride = math.prod(self.sizes[j + 1 :])
        axis = _typed(pandas, self.axes[j])
        values = axis.to_numpy() if isinstance(axis.dtype, np.dtype) else axis.array
        if isinstance(values, np.ndarray):
            return pandas.Series(
                np.tile(np.repeat(values, stride), self.n // (stride * len(values))), copy=False
            )
        idx = (np.arange(self.n, dtype=np.int64) // stride) % self.sizes[j]
        return axis.take(idx).reset_index(drop=True)


class _Points:
    """Points given one by one (dicts): a sized collection (``n`` its length) or an iterator
    (``n`` None), drawn as the study goes."""

    def __init__(self, source, n):
        self.source = iter(source)
        self.n = n
        self.drawn = 0

    def draw(self, k):
        out = []
        for p in itertools.islice(self.source, k):
            out.append(_point(p, self.drawn + len(out)))
        self.drawn += len(out)
        return out

    def chunks(self, chunk):
        while True:
            start = self.drawn
            pts = self.draw(chunk)
            if not pts:
                return
            yield range(start, start + len(pts)), pts


def _point(p, i):
    if not isinstance(p, Mapping):
        raise TypeError(f"grid: point {i} is a {type(p).__name__}, not a dict of coordinates")
    if "error" in p:
        raise ValueError(f"grid: point {i} has a coordinate named 'error', the error column's name")
    return dict(p)


def _grid(grid):
    """`grid` as a `_Product` (a dict of axes) or `_Points` (a sequence or iterator of dicts)."""
    if isinstance(grid, Mapping):
        names = list(grid)
        axes = []
        for name in names:
            if not isinstance(name, str):
                raise TypeError(f"grid: an axis name is a {type(name).__name__} ({name!r}), not a str")
            if name == "error":
                raise ValueError("grid: an axis is named 'error', the error column's name")
            try:
                axes.append(np.atleast_1d(np.asarray(grid[name])).tolist())
            except Exception as e:
                raise ValueError(f"grid: axis {name!r} is not a sequence of values ({_describe(e)})") from e
        return _Product(names, axes)
    if isinstance(grid, (str, bytes)) or not isinstance(grid, Iterable):
        raise TypeError(
            "grid: expected a dict of axes {name: values} or a sequence of points (dicts), "
            f"got {type(grid).__name__}"
        )
    if hasattr(grid, "__len__"):
        for i, p in enumerate(grid):  # a collection in hand: checked before any work
            _point(p, i)
        return _Points(grid, len(grid))
    return _Points(grid, None)


# --- on the worker ------------------------------------------------------------------------


class _Blob:
    """A field's value that is not a plain scalar, pickled on the worker (so that a value that
    cannot be pickled is that point's error, not its chunk's) and loaded on the client."""

    __slots__ = ("data",)

    def __init__(self, data):
        self.data = data

    def __reduce__(self):
        return (_Blob, (self.data,))


_SCALARS = (bool, int, float, complex, str, bytes)


def _sendable(value):
    """A field's value as a plain value: None, a Python scalar (numpy scalars, an IntEnum, …
    converted), or a `_Blob`. Raises if the value cannot be pickled."""
    if value is None:
        return None
    if isinstance(value, np.generic):
        value = value.item()
    if type(value) in _SCALARS:
        return value
    for t in _SCALARS:
        if isinstance(value, t):
            return t(value)
    import cloudpickle

    return _Blob(cloudpickle.dumps(value))


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


def _run_point(job, model, parameters, point):
    """Runs `job` at one point: ``(fields, None)``, or ``(None, error)`` where the job raised
    (any exception but KeyboardInterrupt: a ``SystemExit`` too) or a field cannot be sent
    back. A field named as a coordinate (a SteadyMotion's p_psi) is kept as result_<name>."""
    try:
        params = {k: v for k, v in point.items() if k in parameters}
        m = model.with_params(**params) if params else model
        if callable(job):
            r = job(m, **point)
        else:
            r = getattr(m, job)(**{k: v for k, v in point.items() if k not in parameters})
        fields = _fields(r)
    except KeyboardInterrupt:
        raise
    except BaseException as e:  # a failing point is recorded, never loses the study
        return None, _describe(e)
    out = {}
    for k, v in fields.items():
        try:
            out[f"result_{k}" if k in point or k == "error" else k] = _sendable(v)
        except Exception as e:
            return None, (
                f"TypeError: the result's field {k!r} ({type(v).__name__}) cannot be sent back "
                f"from the worker ({_describe(e)})"
            )
    return out, None


_LOADED = collections.OrderedDict()  # token -> (job, model, parameters, product, point_timeout)
_LOADED_LOCK = threading.Lock()


def _payload(blob):
    """The study's job, model and grid, pickled once: a task of its own, so that a worker that
    dies with it does not lose it (the scheduler computes it again; scattered data would be
    gone, and every task needing it cancelled)."""
    return blob


def _load(token, blob):
    with _LOADED_LOCK:
        got = _LOADED.get(token)
    if got is None:
        got = pickle.loads(blob)
        with _LOADED_LOCK:
            _LOADED[token] = got
            while len(_LOADED) > 4:
                _LOADED.popitem(last=False)
    return got


def _worker_address():
    try:
        import distributed

        return distributed.get_worker().address
    except Exception:
        return None


def _run_chunk(token, blob, indices, points):
    """Runs the job at each point of a chunk (on a worker): ``(results, stopped_at, worker,
    blobs)``, `results` a list of ``(fields, error)`` and `blobs` whether a field is a `_Blob`;
    with a per-point time limit, `stopped_at` is the position of a point that overran it (the
    results end before it; the job is left running in a thread of this process, which the
    client restarts) and `worker` this worker's address, else both None."""
    job, model, parameters, product, point_timeout = _load(token, blob)
    if points is None:
        points = [product.point(i) for i in indices]
    if point_timeout is None:
        return _marked([_run_point(job, model, parameters, p) for p in points], None, None)
    out = []
    current = [(0, time.monotonic())]
    finished = threading.Event()

    def work():
        try:
            for i, p in enumerate(points):
                current[0] = (i, time.monotonic())
                try:
                    out.append(_run_point(job, model, parameters, p))
                except BaseException as e:
                    out.append((None, _describe(e)))
        finally:
            finished.set()

    threading.Thread(target=work, name="routh-study-point", daemon=True).start()
    while not finished.is_set():
        i, began = current[0]
        left = began + point_timeout - time.monotonic()
        if left <= 0 and len(out) <= i:  # point i still runs past its limit
            return _marked(out[:i], i, _worker_address())
        finished.wait(max(left, 0.001))
    return _marked(out, None, None)


def _marked(results, stopped_at, worker):
    blobs = any(
        isinstance(v, _Blob) for f, _ in results if f is not None for v in f.values()
    )
    return results, stopped_at, worker, blobs


# --- on the client ------------------------------------------------------------------------


def _typed(pandas, values, extra=0):
    """A column as a pandas Series of `values` followed by `extra` missing values, typed: ints
    stay ints ("Int64" where some are missing), bools stay bools ("boolean" where some are
    missing), numbers with missing values are float64 with NaN, the rest as pandas infers."""
    kinds = set()
    missing = extra > 0
    for v in values:
        if v is None:
            missing = True
        elif isinstance(v, (bool, np.bool_)):
            kinds.add("b")
        elif isinstance(v, (numbers.Integral)):
            kinds.add("i")
        elif isinstance(v, float):
            kinds.add("f")
        else:
            kinds = {"o"}
            break
    n = len(values) + extra
    if kinds == {"b"}:
        if not missing:
            return pandas.Series(np.array(values, dtype=bool), copy=False)
        return pandas.Series(pandas.array(list(values) + [None] * extra, dtype="boolean"))
    if kinds == {"i"}:
        try:
            data = np.zeros(n, dtype=np.int64)
            data[: len(values)] = [0 if v is None else v for v in values]
        except OverflowError:  # beyond int64: kept as Python ints
            kinds = {"o"}
        else:
            if not missing:
                return pandas.Series(data, copy=False)
            mask = np.ones(n, dtype=bool)
            mask[: len(values)] = [v is None for v in values]
            return pandas.Series(pandas.arrays.IntegerArray(data, mask), copy=False)
    if kinds and kinds <= {"i", "f"}:
        data = np.full(n, np.nan)
        data[: len(values)] = [np.nan if v is None else v for v in values]
        return pandas.Series(data, copy=False)
    return pandas.Series(list(values) + [None] * extra, dtype=None if values else object)


def _table(pandas, g, fields, errors, points, unfinished):
    """The DataFrame: the coordinates, the fields, then ``error``. `fields` and `errors` hold
    the points drawn; the product's points not drawn (a study stopped by its timeout) follow,
    with the error `unfinished`."""
    drawn = len(fields)
    n = g.n if isinstance(g, _Product) else drawn
    columns = {}
    if isinstance(g, _Product):
        for j, name in enumerate(g.names):
            columns[name] = g.column(pandas, j)
    else:
        names = {}
        for p in points:
            for k in p:
                names.setdefault(k)
        for name in names:
            columns[name] = _typed(pandas, [p.get(name) for p in points])
    found = {}
    for f in fields:
        if f:
            for k in f:
                found.setdefault(k)
    for name in found:
        columns[name] = _typed(
            pandas, [None if f is None else f.get(name) for f in fields], n - drawn
        )
    error = np.empty(n, dtype=object)  # object: None where the point succeeded
    error[:drawn] = [unfinished if e is _PENDING else e for e in errors]
    error[drawn:] = unfinished
    columns["error"] = pandas.Series(error, dtype=object, copy=False)
    return pandas.DataFrame(columns, copy=False)


_PENDING = object()  # the error of a point not finished yet


def _loaded(fields):
    """A point's fields as sent by the worker, with their `_Blob`s loaded: ``(fields, None)``,
    or ``(None, error)`` if one cannot be loaded here."""
    if fields is None or not any(isinstance(v, _Blob) for v in fields.values()):
        return fields, None
    out = {}
    for k, v in fields.items():
        if isinstance(v, _Blob):
            try:
                v = pickle.loads(v.data)
            except Exception as e:
                return None, f"the result's field {k!r} could not be loaded here ({_describe(e)})"
        out[k] = v
    return out, None


def _count(name, value, what):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 1:
        raise ValueError(f"{name}: expected a positive int ({what}), got {value!r}")
    return int(value)


def _seconds(name, value):
    if value is None:
        return None
    if (
        isinstance(value, bool)
        or not isinstance(value, numbers.Real)
        or not math.isfinite(value)
        or value <= 0
    ):
        raise ValueError(f"{name}: expected a positive number of seconds or None, got {value!r}")
    return float(value)


class _Progress:
    """``routh.study: k of N points`` rewritten on stderr, at most every 0.25 s."""

    def __init__(self, on, total):
        self.on = on
        self.total = total
        self.last = 0.0

    def show(self, done, final=False):
        if not self.on:
            return
        now = time.monotonic()
        if not final and now - self.last < 0.25:
            return
        self.last = now
        of = f" of {self.total}" if self.total is not None else ""
        sys.stderr.write(f"\rrouth.study: {done}{of} points" + ("\n" if final else ""))
        sys.stderr.flush()


def study(
    job,
    model,
    grid,
    client=None,
    chunk=None,
    progress=True,
    n_workers=2,
    timeout=None,
    point_timeout=None,
):
    """Runs `job` at every point of `grid` on a Dask cluster and returns a tidy
    ``pandas.DataFrame``: one row per point, the point's coordinates, the result's fields and
    an ``error`` column (the exception's type and message where the point failed, else
    missing). A failing point never loses the study: an exception (``SystemExit`` too), a
    result that cannot be pickled, a crashed worker process or a time limit is that point's
    error, and the other points' results are kept.

    - `job`: a callable ``job(model, **point) -> result``, called with `model` with the
      point's parameters set (``model.with_params(...)``) and all the point's coordinates as
      keywords; or the name of a `Model` method, called as ``getattr(model, job)(**rest)``
      with the coordinates that are not parameters (e.g. ``"steady_motions"`` over
      ``p_psi``). The result becomes columns: a dict its keys, a number ``value``, a routh
      result (``StabilityReport``, ``SteadyMotion``, …) its scalar fields and short vectors.
      Ints stay ints (``Int64`` where some points failed), bools bools (``boolean``).
    - `grid`: named axes ``{name: values}``, whose product is the set of points; names that
      are parameters of `model` are set on it, the others (``p_psi``, …) are passed to `job`.
      The product is never built: chunks of it are made as workers take them (so a grid of
      10⁷ points starts at once). A sequence of dicts is taken as the points themselves
      (Monte Carlo samples); an iterator of dicts is drawn as the study goes.
    - `client`: a ``dask.distributed.Client``, or a scheduler's address (``"tcp://host:8786"``,
      connected to and disconnected afterwards); None: a ``LocalCluster`` of `n_workers`
      worker processes (one thread each) on this machine, closed afterwards.
    - `chunk`: points per task (default: about 8 tasks per worker thread, at most 2000
      points per task). At most two tasks per worker thread are in flight at a time.
    - `progress`: ``routh.study: k of N points`` rewritten on stderr.
    - `timeout`: seconds from the call, for the whole study (the start of its own cluster
      included): then the tasks still running are cancelled, and the table is returned with
      the points not finished marked ``"TimeoutError: not finished within T s"``.
    - `point_timeout`: seconds per point, measured on the worker by a watchdog thread: a point
      running longer is marked ``"TimeoutError: point not finished within T s"``, the finished
      points of its chunk are kept, the rest of the chunk is run again, and its worker process
      is restarted (through its nanny; a worker without one keeps the job running in a
      thread). The watchdog needs the GIL: a job stuck in native code that holds it is noticed
      when it lets go.

    A worker process that dies (a crash, ``os._exit``, the OOM killer) costs only its points:
    those are retried once, each point alone, on a worker process that is alive, and a point
    whose worker dies again is marked ``KilledWorker``. On its own ``LocalCluster`` the study
    lets dask make no retries of its own (``allowed_failures=0``); on a given cluster the
    scheduler's ``distributed.scheduler.allowed-failures`` (3 by default) are made first.

    If the study is interrupted (Ctrl-C, an exception) its tasks are cancelled, and a cluster
    it made is closed, its worker processes ended. A Ctrl-C while that cluster starts is held
    until it has started (then raised and the cluster closed); a second Ctrl-C is not held.

    Arguments are checked before any work: a `model` that is not a routh ``Model``, a `job`
    that is neither callable nor a method's name, a closed `client`, a `grid` that is not
    axes or points, or a `chunk`, `n_workers`, `timeout` or `point_timeout` that is not
    positive raise ``TypeError`` or ``ValueError`` naming the argument.

    The ``LocalCluster`` starts worker processes that import the calling script: in a script,
    call ``routh.study`` under ``if __name__ == "__main__":``, and define the job at the top
    level (a notebook needs neither).

    >>> import numpy as np, routh
    >>> def sleeping(model, p_psi, **_):          # the verdict of the sleeping top γ = e₃
    ...     m = [s for s in model.steady_motions(p_psi) if abs(s.gamma[2] - 1) < 1e-9][0]
    ...     return model.classify(m)
    >>> if __name__ == "__main__":
    ...     top = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), "
    ...                       "potential = mgl * gamma.z", {"inertia": [1, 1, 1.25], "mgl": 1.0})
    ...     df = routh.study(sleeping, top, {"mgl": np.linspace(0.5, 2, 20),
    ...                                      "p_psi": np.linspace(0.1, 5, 50)})
    ...     print(df.groupby("verdict").size())
    """
    started = time.monotonic()
    distributed, pandas = _imports()
    import cloudpickle
    from distributed.scheduler import KilledWorker

    # The arguments, before any work.
    if not (callable(job) or isinstance(job, str)):
        raise TypeError(
            "job: expected a callable job(model, **point) or the name of a Model method, "
            f"got {type(job).__name__}"
        )
    if not (callable(getattr(model, "with_params", None)) and hasattr(model, "parameters")):
        raise TypeError(f"model: expected a routh.Model, got {type(model).__name__}")
    if isinstance(job, str) and not callable(getattr(model, job, None)):
        raise ValueError(f"job: {job!r} is not a method of the model")
    if chunk is not None:
        chunk = _count("chunk", chunk, "points per task")
    n_workers = _count("n_workers", n_workers, "worker processes of the LocalCluster")
    timeout = _seconds("timeout", timeout)
    point_timeout = _seconds("point_timeout", point_timeout)
    if client is not None and not isinstance(client, str):
        if not isinstance(client, distributed.Client):
            raise TypeError(
                "client: expected a dask.distributed.Client, a scheduler's address "
                f"('tcp://host:8786') or None, got {type(client).__name__}"
            )
        if client.status in ("closing", "closed", "failed"):
            raise ValueError(
                f"client: the Client is {client.status}; give a running Client, a scheduler's "
                "address or None (a LocalCluster)"
            )
    g = _grid(grid)
    parameters = set(model.parameters)
    try:
        cloudpickle.dumps(job)
    except Exception as e:
        raise TypeError(f"job: cannot be pickled to send it to the workers ({_describe(e)})") from e
    blob = cloudpickle.dumps(
        (job, model, parameters, g if isinstance(g, _Product) else None, point_timeout)
    )
    deadline = None if timeout is None else started + timeout
    unfinished = f"TimeoutError: not finished within {timeout:g} s" if timeout else None

    fields, errors, points = [], [], []
    if g.n == 0:
        return _table(pandas, g, fields, errors, points, unfinished)

    own_cluster = None
    own_client = None
    inflight = {}  # future -> (indices, points or None, attempt)
    payload = None
    shown = _Progress(progress, g.n)
    try:
        if client is None:
            with _ctrl_c_held():
                own_cluster = distributed.LocalCluster(
                    n_workers=n_workers,
                    threads_per_worker=1,
                    processes=True,
                    dashboard_address=":0",
                    scheduler_kwargs={"allowed_failures": 0},
                )
                client = own_client = distributed.Client(own_cluster)
        elif isinstance(client, str):
            address = client
            try:
                if deadline is None:
                    client = own_client = distributed.Client(address)
                else:
                    left = max(deadline - time.monotonic(), 0.1)
                    client = own_client = distributed.Client(address, timeout=left)
            except OSError as e:
                raise OSError(f"client: cannot connect to the scheduler at {address!r} ({e})") from e

        threads = max(1, sum(client.nthreads().values()))
        if chunk is None:
            n = g.n if g.n is not None else 100 * 8 * threads
            chunk = min(2000, max(1, math.ceil(n / (8 * threads))))
        source = g.chunks(chunk)
        token = uuid.uuid4().hex
        payload = client.submit(_payload, blob, pure=False)
        done = queue.Queue()
        retry = collections.deque()  # (indices, points or None, attempt)
        exhausted = False
        finished = 0
        refreshed = time.monotonic()

        def store(indices, results, blobs):
            nonlocal finished
            for i, (f, err) in zip(indices, results):
                if blobs:
                    f, bad = _loaded(f)
                    err = err if bad is None else bad
                fields[i], errors[i] = f, err
            finished += len(results)

        def fail(indices, error):
            nonlocal finished
            for i in indices:
                errors[i] = error
            finished += len(indices)

        while True:
            now = time.monotonic()
            if deadline is not None and now >= deadline:
                break
            # Retries go one task per live worker thread, so that a point that kills its
            # worker again takes no other point's retry with it.
            careful = any(a > 0 for _, _, a in retry) or any(a > 0 for _, _, a in inflight.values())
            if now - refreshed > (0.2 if careful else 1.0):
                threads = sum(client.nthreads().values())
                refreshed = now
            limit = max(1, threads if careful else 2 * threads)
            while len(inflight) < limit:
                if retry:
                    item = retry.popleft()
                elif not exhausted:
                    item = next(source, None)
                    if item is None:
                        exhausted = True
                        break
                    fields.extend([None] * len(item[0]))
                    errors.extend([_PENDING] * len(item[0]))
                    if item[1] is not None:
                        points.extend(item[1])
                    item = (item[0], item[1], 0)
                else:
                    break
                fut = client.submit(_run_chunk, token, payload, item[0], item[1], pure=False)
                inflight[fut] = item
                fut.add_done_callback(done.put)
            if not inflight:
                if exhausted and not retry:
                    break
                continue
            wait = 0.25 if deadline is None else min(0.25, max(deadline - now, 0.0))
            try:
                batch = [done.get(timeout=wait)]
            except queue.Empty:
                shown.show(finished)
                continue
            while True:  # the chunks done meanwhile, gathered in one call
                try:
                    batch.append(done.get_nowait())
                except queue.Empty:
                    break
            batch = [(f, inflight.pop(f)) for f in batch if f in inflight]
            gathered = {}
            ok = [f for f, _ in batch if f.status == "finished"]
            if len(ok) > 1:
                try:
                    gathered = dict(zip(ok, client.gather(ok)))
                except Exception:
                    pass  # each on its own below
            for fut, (indices, pts, attempt) in batch:
                try:
                    if fut in gathered:
                        got = gathered.pop(fut)
                    elif deadline is None:
                        got = fut.result()
                    else:
                        got = fut.result(timeout=max(deadline - time.monotonic(), 0.001))
                    results, stopped_at, worker, blobs = got
                except TimeoutError:
                    if deadline is not None and time.monotonic() >= deadline:
                        inflight[fut] = (indices, pts, attempt)  # unfinished, cancelled below
                        continue
                    fail(indices, "TimeoutError: the chunk's results could not be fetched")
                    continue
                except (KilledWorker, concurrent.futures.CancelledError) as e:
                    # The worker died under the chunk (or the task was cancelled with it).
                    if attempt == 0:
                        for k, i in enumerate(indices):
                            retry.append((range(i, i + 1), None if pts is None else [pts[k]], 1))
                    else:
                        fail(indices, _LOST if isinstance(e, KilledWorker) else _describe(e))
                    continue
                except Exception as e:
                    fail(indices, _describe(e))
                    continue
                store(indices, results, blobs)
                if stopped_at is not None:
                    fail(indices[stopped_at : stopped_at + 1],
                         f"TimeoutError: point not finished within {point_timeout:g} s "
                         "(point_timeout)")
                    rest = indices[stopped_at + 1 :]
                    if len(rest):
                        retry.appendleft(
                            (rest, None if pts is None else pts[stopped_at + 1 :], attempt)
                        )
                    _restart(client, worker, deadline)
            del batch, gathered, ok
            shown.show(finished)
        shown.show(finished, final=True)
    finally:
        pending = list(inflight) + ([payload] if payload is not None else [])
        if pending and client is not None:
            try:
                client.cancel(pending)
            except Exception:
                pass
        inflight.clear()
        payload = None
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()
    if isinstance(g, _Points) and g.n is not None and deadline is not None:
        points.extend(g.draw(g.n))  # the points of the sequence not drawn: unfinished
        fields.extend([None] * (len(points) - len(fields)))
        errors.extend([_PENDING] * (len(points) - len(errors)))
    return _table(pandas, g, fields, errors, points, unfinished)


def _restart(client, worker, deadline):
    """Restarts the worker process whose job overran `point_timeout` (its thread cannot be
    stopped otherwise), if a nanny watches it."""
    if worker is None:
        return
    try:
        info = client.scheduler_info()["workers"].get(worker) or {}
        if not info.get("nanny"):
            warnings.warn(
                f"routh.study: the worker {worker} has no nanny and is not restarted; the job "
                "that overran point_timeout still runs in one of its threads",
                RuntimeWarning,
                stacklevel=3,
            )
            return
        left = 60.0 if deadline is None else max(deadline - time.monotonic(), 1.0)
        client.restart_workers([worker], timeout=left, raise_for_error=False)
    except Exception as e:
        warnings.warn(f"routh.study: restarting the worker {worker}: {_describe(e)}",
                      RuntimeWarning, stacklevel=3)
