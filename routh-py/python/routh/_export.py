"""Export of the result classes: ``to_pandas()``, ``to_csv(path)``, ``to_json()``, ``from_json``.

Every result class has the methods ``to_pandas()``, ``to_csv(path)``, ``to_json()`` and the class
method ``from_json(text)`` (which call the functions here); ``routh.to_pandas``,
``routh.to_csv``, ``routh.to_json`` and ``routh.from_json`` also take a list of results (e.g.
what ``Model.steady_motions`` returns).

JSON. ``to_json()`` is a JSON object ``{"routh": "<class>", "format": 1, <fields>}``:

- ``SteadyMotion``, ``PeriodicOrbit``, ``OrbitEvent``, ``OrbitFamily`` hold a Rust value; their
  fields are its serde form (what ``serde_json`` writes for ``routh::SteadyMotion`` etc., so
  Rust reads the text back with ``serde_json::from_str``: the two extra keys are ignored).
- Every other class: its attributes by name (numpy arrays as nested lists, a complex number as
  ``[re, im]``, a nested result as its own JSON object), and for the trajectories
  ``euler_angles`` (None without attitude).

Floats are written with Python's ``repr`` (the shortest text that reads back as the same double),
so finite numbers come back bit for bit, ``-0.0`` included. JSON has no NaN or infinity: they are
the strings ``"NaN"``, ``"Infinity"`` and ``"-Infinity"`` (the convention of the Rust crate's
serde form), and read back as NaN, +inf, -inf (a NaN comes back as the standard quiet NaN: its
sign and payload bits are not kept). The text is strict JSON (RFC 8259).

DataFrames (pandas is optional: ``to_pandas`` and ``to_csv`` raise ImportError without it); the
columns are listed in docs/python.md ("Export"). ``to_csv`` writes the DataFrame without its
index to a temporary file beside ``path`` and renames it, so the file is whole or absent; floats
are written at full precision (``pandas.read_csv(path, float_precision="round_trip")`` reads the
same numbers; NaN is an empty cell).

>>> import routh
>>> top = routh.Model(
...     "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
...     {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
>>> d = top.bifurcation_diagram((0.0, 5.0))
>>> routh.Diagram.from_json(d.to_json()).to_json() == d.to_json()
True
>>> list(d.to_pandas().columns)[:4]
['kind', 'branch', 's', 'gamma1']
"""

import json
import math
import os
import tempfile

import numpy as np

from . import _routh

FORMAT = 1

# The classes whose JSON is the serde form of the Rust value they wrap (their pickle state).
_SERDE = ("SteadyMotion", "PeriodicOrbit", "OrbitEvent", "OrbitFamily")

# The JSON fields of every other class, in the order of its pickle state, each with its kind:
# "f" float, "i" int, "b" bool, "s" str (or None), "a<k>" float64 array of k columns ("a" for
# (n,)), "c" complex128 (n,) array, "r:<Class>" a nested result, "l:<kind>" a list of them,
# "o:<kind>" None or one.
_FIELDS = {
    "StabilityReport": [
        ("verdict", "s"),
        ("degree_of_instability", "i"),
        ("restricted_hessian_eigenvalues", "a"),
        ("f2_roots", "c"),
    ],
    "CircleReport": [
        ("verdict", "s"),
        ("curvature", "f"),
        ("across", "f"),
        ("momentum_term", "f"),
        ("axis_momentum", "f"),
        ("axis", "a"),
        ("report", "r:StabilityReport"),
    ],
    "Branch": [
        ("s", "a"),
        ("gamma", "a3"),
        ("p_psi", "a"),
        ("energy", "a"),
        ("verdicts", "l:s"),
        ("isolated", "b"),
    ],
    "Event": [
        ("kind", "s"),
        ("s", "f"),
        ("gamma", "a"),
        ("branch", "i"),
        ("before", "s"),
        ("after", "s"),
        ("resonance", "s"),
        ("nonlinear", "o:t"),
    ],
    "Diagram": [
        ("branches", "l:r:Branch"),
        ("events", "l:r:Event"),
        ("stop", "s"),
        ("checks", "l:t"),
    ],
    "Boundary": [("kind", "s"), ("points", "a2")],
    "Atlas": [
        ("x", "a"),
        ("y", "a"),
        ("verdicts", "l:t"),
        ("lost", "l:t"),
        ("stop", "s"),
        ("boundaries", "l:r:Boundary"),
    ],
    "Trajectory": [
        ("t", "a"),
        ("omega", "a3"),
        ("gamma", "a3"),
        ("energy", "a"),
        ("p_psi", "a"),
        ("attitude", "o:a4"),
        ("euler_angles", "o:a3"),
    ],
    "ReducedTrajectory": [
        ("t", "a"),
        ("big_omega", "a3"),
        ("gamma", "a3"),
        ("psi", "a"),
        ("psi_dot", "a"),
        ("omega", "a3"),
        ("energy", "a"),
        ("p_psi", "a"),
        ("attitude", "o:a4"),
        ("euler_angles", "o:a3"),
    ],
    "Certificate": [
        ("complete", "b"),
        ("motions", "l:r:SteadyMotion"),
        ("p_psi", "f"),
        ("boxes", "i"),
        ("undecided", "i"),
    ],
    "NonlinearReport": [
        ("verdict", "s"),
        ("reason", "s"),
        ("linear", "r:StabilityReport"),
        ("frequencies", "a"),
        ("krein_signs", "t"),
        ("normal_form", "a"),
        ("arnold_determinant", "f"),
        ("resonance", "s"),
        ("resonance_distance", "f"),
    ],
    "PoincareSection": [
        ("p_psi", "f"),
        ("energy", "f"),
        ("normal", "a"),
        ("points", "l:a2"),
        ("starts", "a6"),
    ],
}

CLASSES = _SERDE + tuple(_FIELDS)


# ---------------------------------------------------------------------------------------------
# JSON


def _float(x):
    """A float as JSON: itself, or "NaN", "Infinity", "-Infinity"."""
    x = float(x)
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "Infinity" if x > 0 else "-Infinity"
    return x


def _unfloat(v, where):
    if isinstance(v, bool) or v is None:
        raise _routh.RouthError(f"from_json: {where}: expected a number, got {v!r}")
    if isinstance(v, (int, float)):
        return float(v)
    if v == "NaN":
        return math.nan
    if v == "Infinity":
        return math.inf
    if v == "-Infinity":
        return -math.inf
    raise _routh.RouthError(f"from_json: {where}: expected a number, got {v!r}")


def _plain(v):
    """Numbers (also numpy scalars), strings, None, lists and tuples as JSON values."""
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, (int, np.integer)):
        return int(v)
    if isinstance(v, (float, np.floating)):
        return _float(v)
    if isinstance(v, (complex, np.complexfloating)):
        return [_float(v.real), _float(v.imag)]
    if isinstance(v, np.ndarray):
        return [_plain(x) for x in v]
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    raise TypeError(f"to_json: cannot write {type(v).__name__}")


def _class_name(obj):
    name = type(obj).__name__
    if type(obj).__module__ != "routh" or name not in CLASSES:
        raise TypeError(f"to_json: not a routh result: {type(obj).__name__}")
    return name


def _document(obj):
    """The JSON object (a dict) of a result."""
    name = _class_name(obj)
    doc = {"routh": name, "format": FORMAT}
    if name in _SERDE:
        # The pickle state of these classes is the serde JSON of the Rust value.
        _, (_, state) = obj.__reduce__()
        doc.update(json.loads(state))
        return doc
    for field, kind in _FIELDS[name]:
        if field == "euler_angles":
            value = obj.euler_angles() if obj.attitude is not None else None
        else:
            value = getattr(obj, field)
        doc[field] = _encode(value, kind)
    return doc


def _encode(value, kind):
    if kind.startswith("r:"):
        return _document(value)
    if kind.startswith("l:"):
        return [_encode(v, kind[2:]) for v in value]
    if kind.startswith("o:"):
        return None if value is None else _encode(value, kind[2:])
    return _plain(value)


def to_json(obj):
    """The JSON text of a result (or of a list of results: a JSON array of them)."""
    if isinstance(obj, (list, tuple)):
        doc = [_document(o) for o in obj]
    else:
        doc = _document(obj)
    return json.dumps(doc, allow_nan=False, ensure_ascii=False)


def _array(v, kind, where):
    if not isinstance(v, list):
        raise _routh.RouthError(f"from_json: {where}: expected an array, got {v!r}")
    if kind == "c":
        try:
            out = [complex(_unfloat(re, where), _unfloat(im, where)) for re, im in v]
        except (TypeError, ValueError):
            raise _routh.RouthError(f"from_json: {where}: expected [re, im] pairs") from None
        return np.array(out, dtype=np.complex128).reshape(-1)
    cols = int(kind[1:]) if len(kind) > 1 else None
    try:
        if cols is None:
            flat = [_unfloat(x, where) for x in v]
            return np.array(flat, dtype=np.float64).reshape(-1)
        flat = []
        for row in v:
            if not isinstance(row, list) or len(row) != cols:
                raise _routh.RouthError(f"from_json: {where}: expected rows of {cols} numbers")
            flat.extend(_unfloat(x, where) for x in row)
        return np.array(flat, dtype=np.float64).reshape(-1, cols)
    except TypeError:
        raise _routh.RouthError(f"from_json: {where}: expected numbers") from None


def _tuples(v):
    """JSON arrays as tuples (what the pickle states hold), numbers as they are."""
    if isinstance(v, list):
        return tuple(_tuples(x) for x in v)
    return v


def _decode(v, kind, where):
    if kind.startswith("r:"):
        return _object(v, kind[2:], where)
    if kind.startswith("l:"):
        if not isinstance(v, list):
            raise _routh.RouthError(f"from_json: {where}: expected an array, got {v!r}")
        return [_decode(x, kind[2:], f"{where}[{i}]") for i, x in enumerate(v)]
    if kind.startswith("o:"):
        return None if v is None else _decode(v, kind[2:], where)
    if kind == "f":
        return _unfloat(v, where)
    if kind.startswith("a") or kind == "c":
        return _array(v, kind, where)
    if kind == "t":
        if not isinstance(v, list):
            raise _routh.RouthError(f"from_json: {where}: expected an array, got {v!r}")
        return _tuples(v)
    return v


def _object(doc, expected, where="text"):
    """The result of a JSON object (a dict); `expected` a class name or None (any)."""
    if not isinstance(doc, dict) or "routh" not in doc:
        raise _routh.RouthError(f"from_json: {where}: not a routh result (no \"routh\" key)")
    name = doc["routh"]
    if name not in CLASSES:
        raise _routh.RouthError(f"from_json: {where}: unknown class {name!r}")
    if expected is not None and name != expected:
        raise _routh.RouthError(f"from_json: {where}: a {name}, not a {expected}")
    if doc.get("format") != FORMAT:
        raise _routh.RouthError(f"from_json: {where}: format {doc.get('format')!r}, expected {FORMAT}")
    if name in _SERDE:
        body = {k: v for k, v in doc.items() if k not in ("routh", "format")}
        return _routh._restore(name, json.dumps(body))
    values = []
    for field, kind in _FIELDS[name]:
        if field not in doc:
            raise _routh.RouthError(f"from_json: {where}: {name} without {field!r}")
        values.append(_decode(doc[field], kind, f"{where}.{field}"))
    state = _state(name, values)
    try:
        return _routh._restore(name, state)
    except (TypeError, ValueError) as e:
        raise _routh.RouthError(f"from_json: {where}: {e}") from None


def _state(name, values):
    """The pickle state of class `name` from its JSON fields in order."""
    if name in ("Trajectory", "ReducedTrajectory"):
        *arrays, attitude, euler = values
        n = len(arrays[0])
        if name == "Trajectory":
            return (*arrays, attitude, euler, n)
        return (tuple(arrays), attitude, euler, n)
    if name == "Atlas":
        x, y, verdicts, lost, stop, boundaries = values
        return (x, y, [list(r) for r in verdicts], [list(r) for r in lost], stop, boundaries)
    if name == "Diagram":
        branches, events, stop, checks = values
        checks = [(_unfloat(s, "checks"), a, b) for s, a, b in checks]
        return (branches, events, stop, checks)
    if name == "Branch":
        s, gamma, p_psi, energy, verdicts, isolated = values
        return (s, gamma, p_psi, energy, list(verdicts), isolated)
    return tuple(values)


def from_json(text, cls=None):
    """The result (or list of results) whose JSON text is `text`; with `cls`, it must be one."""
    try:
        doc = json.loads(text)
    except (TypeError, ValueError) as e:
        raise _routh.RouthError(f"from_json: not JSON: {e}") from None
    expected = None if cls is None else cls.__name__
    if isinstance(doc, list) and cls is None:
        return [_object(d, None, f"[{i}]") for i, d in enumerate(doc)]
    return _object(doc, expected)


# ---------------------------------------------------------------------------------------------
# DataFrames


def _pandas():
    try:
        import pandas
    except ImportError as e:
        raise ImportError(
            "routh: to_pandas() and to_csv() need pandas, which is not installed "
            "(pip install pandas, or pip install 'routh[pandas]')"
        ) from e
    return pandas


def _vec(prefix, v):
    return {f"{prefix}{i + 1}": float(v[i]) for i in range(len(v))}


def _motion_row(m):
    row = {"p_psi": m.p_psi}
    row.update(_vec("gamma", m.gamma))
    row.update(psi_dot=m.psi_dot, mu=m.mu, amended_potential=m.amended_potential, energy=m.energy)
    row["isolated"] = m.isolated
    return row


def _report_row(r):
    row = {"verdict": r.verdict, "degree_of_instability": r.degree_of_instability}
    row.update(_vec("kappa", r.restricted_hessian_eigenvalues))
    for i, z in enumerate(r.f2_roots):
        row[f"f2_root{i + 1}_re"] = float(z.real)
        row[f"f2_root{i + 1}_im"] = float(z.imag)
    return row


def _circle_row(c):
    row = {
        "verdict": c.verdict,
        "curvature": c.curvature,
        "across": c.across,
        "momentum_term": c.momentum_term,
        "axis_momentum": c.axis_momentum,
    }
    row.update(_vec("axis", c.axis))
    inner = _report_row(c.report)
    inner["report_verdict"] = inner.pop("verdict")
    row.update(inner)
    return row


def _nonlinear_row(r):
    row = {
        "verdict": r.verdict,
        "reason": r.reason,
        "linear": r.linear.verdict,
        "degree_of_instability": r.linear.degree_of_instability,
    }
    row.update(_vec("omega", r.frequencies))
    row.update(krein1=int(r.krein_signs[0]), krein2=int(r.krein_signs[1]))
    c20, c11, c02 = (float(x) for x in r.normal_form)
    row.update(c20=c20, c11=c11, c02=c02)
    row.update(
        arnold_determinant=r.arnold_determinant,
        resonance=r.resonance,
        resonance_distance=r.resonance_distance,
    )
    return row


def _orbit_row(o):
    row = {
        "period": o.period,
        "energy": o.energy,
        "p_psi": o.p_psi,
        "precession": o.precession,
        "stability_index": o.stability_index,
        "stability": o.stability,
        "amplitude": o.amplitude,
    }
    row.update(_vec("omega", o.omega0))
    row.update(_vec("gamma", o.gamma0))
    for i, z in enumerate(o.multipliers):
        row[f"multiplier{i + 1}_re"] = float(z.real)
        row[f"multiplier{i + 1}_im"] = float(z.imag)
    return row


_EVENT_COLUMNS = ["before", "after", "resonance", "nonlinear_before", "nonlinear_at", "nonlinear_after"]


def _branch_rows(b, index):
    n = len(b)
    s, g, p, e = b.s, b.gamma, b.p_psi, b.energy
    for k in range(n):
        row = {"kind": "point", "branch": index, "s": float(s[k])}
        row.update(_vec("gamma", g[k]))
        row.update(p_psi=float(p[k]), energy=float(e[k]), verdict=b.verdicts[k], isolated=b.isolated)
        yield row


def _event_row(e):
    row = {"kind": e.kind, "branch": e.branch, "s": e.s}
    row.update(_vec("gamma", e.gamma))
    row.update(before=e.before, after=e.after, resonance=e.resonance)
    nl = e.nonlinear or (None, None, None)
    row.update(nonlinear_before=nl[0], nonlinear_at=nl[1], nonlinear_after=nl[2])
    return row


_DIAGRAM_COLUMNS = [
    "kind", "branch", "s", "gamma1", "gamma2", "gamma3", "p_psi", "energy", "verdict", "isolated",
] + _EVENT_COLUMNS


def _traj_rows(tr, columns):
    data = {}
    for name, arr in columns:
        arr = np.asarray(arr)
        if arr.ndim == 1:
            data[name] = arr
        else:
            for i in range(arr.shape[1]):
                data[f"{name}{i + 1}"] = arr[:, i]
    if tr.attitude is not None:
        q = np.asarray(tr.attitude)
        for i, c in enumerate("xyzw"):
            data[f"q{c}"] = q[:, i]
        eu = tr.euler_angles()
        for i, c in enumerate(("euler_psi", "euler_theta", "euler_phi")):
            data[c] = eu[:, i]
    return data


def _frame(obj):
    pd = _pandas()
    name = _class_name(obj)
    if name == "SteadyMotion":
        return pd.DataFrame([_motion_row(obj)])
    if name == "StabilityReport":
        return pd.DataFrame([_report_row(obj)])
    if name == "CircleReport":
        return pd.DataFrame([_circle_row(obj)])
    if name == "NonlinearReport":
        return pd.DataFrame([_nonlinear_row(obj)])
    if name == "PeriodicOrbit":
        return pd.DataFrame([_orbit_row(obj)])
    if name in ("Branch", "Event", "Diagram"):
        if name == "Branch":
            rows = list(_branch_rows(obj, 0))
        elif name == "Event":
            rows = [_event_row(obj)]
        else:
            rows = [r for i, b in enumerate(obj.branches) for r in _branch_rows(b, i)]
            rows += [_event_row(e) for e in obj.events]
        df = pd.DataFrame(rows, columns=_DIAGRAM_COLUMNS)
        df["branch"] = df["branch"].astype("int64")
        df.attrs.update(stop=getattr(obj, "stop", None))
        if name == "Diagram":
            df.attrs.update(checks=list(obj.checks))
        return df
    if name in ("Atlas", "Boundary"):
        rows = []
        if name == "Atlas":
            x, y = obj.x, obj.y
            for j, line in enumerate(obj.verdicts):
                for i, v in enumerate(line):
                    rows.append({"kind": "cell", "i": i, "j": j, "boundary": None, "x": float(x[i]),
                                 "y": float(y[j]), "verdict": v, "lost": obj.lost[j][i]})
            boundaries = obj.boundaries
        else:
            boundaries = [obj]
        for k, b in enumerate(boundaries):
            for px, py in np.asarray(b.points):
                rows.append({"kind": b.kind, "i": None, "j": None, "boundary": k, "x": float(px),
                             "y": float(py), "verdict": None, "lost": None})
        df = pd.DataFrame(rows, columns=["kind", "i", "j", "boundary", "x", "y", "verdict", "lost"])
        for c in ("i", "j", "boundary"):
            df[c] = df[c].astype("Int64")
        if name == "Atlas":
            df.attrs.update(stop=obj.stop)
        return df
    if name == "Trajectory":
        cols = [("t", obj.t), ("omega", obj.omega), ("gamma", obj.gamma), ("energy", obj.energy),
                ("p_psi", obj.p_psi)]
        return pd.DataFrame(_traj_rows(obj, cols))
    if name == "ReducedTrajectory":
        cols = [("t", obj.t), ("big_omega", obj.big_omega), ("gamma", obj.gamma), ("psi", obj.psi),
                ("psi_dot", obj.psi_dot), ("omega", obj.omega), ("energy", obj.energy),
                ("p_psi", obj.p_psi)]
        return pd.DataFrame(_traj_rows(obj, cols))
    if name == "Certificate":
        cols = ["p_psi", "gamma1", "gamma2", "gamma3", "psi_dot", "mu", "amended_potential", "energy",
                "isolated"]
        df = pd.DataFrame([_motion_row(m) for m in obj.motions], columns=cols)
        df.attrs.update(complete=obj.complete, p_psi=obj.p_psi, boxes=obj.boxes, undecided=obj.undecided)
        return df
    if name in ("OrbitEvent", "OrbitFamily"):
        events = [obj] if name == "OrbitEvent" else list(obj.events)
        rows = [] if name == "OrbitEvent" else [dict(kind="orbit", **_orbit_row(o)) for o in obj.orbits]
        for e in events:
            row = dict(kind=e.kind, **_orbit_row(e.orbit))
            row.update(before=e.before, after=e.after)
            rows.append(row)
        cols = ["kind", "period", "energy", "p_psi", "precession", "stability_index", "stability",
                "amplitude", "omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3",
                "multiplier1_re", "multiplier1_im", "multiplier2_re", "multiplier2_im", "before", "after"]
        df = pd.DataFrame(rows, columns=cols)
        if name == "OrbitFamily":
            df.attrs.update(stop=obj.stop)
        return df
    if name == "PoincareSection":
        rows = []
        for k, pts in enumerate(obj.points):
            for c, (theta, m) in enumerate(np.asarray(pts)):
                rows.append({"orbit": k, "crossing": c, "theta": float(theta), "m_n": float(m)})
        df = pd.DataFrame(rows, columns=["orbit", "crossing", "theta", "m_n"])
        df["orbit"] = df["orbit"].astype("int64")
        df["crossing"] = df["crossing"].astype("int64")
        df.attrs.update(p_psi=obj.p_psi, energy=obj.energy, normal=np.asarray(obj.normal).tolist())
        return df
    raise TypeError(f"to_pandas: not a routh result: {name}")  # pragma: no cover


def to_pandas(obj):
    """The DataFrame of a result, or of a list of results (their frames one after another)."""
    if isinstance(obj, (list, tuple)):
        pd = _pandas()
        frames = [_frame(o) for o in obj]
        if not frames:
            return pd.DataFrame()
        return pd.concat(frames, ignore_index=True)
    return _frame(obj)


def to_csv(obj, path):
    """Writes `to_pandas(obj)` to the CSV file `path`, whole or not at all."""
    df = to_pandas(obj)
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=".routh-", suffix=".csv.tmp", dir=directory)
        with os.fdopen(fd, "w", newline="") as f:
            df.to_csv(f, index=False)
        os.replace(tmp, path)
        tmp = None
    except OSError as e:
        raise type(e)(e.errno, f"cannot write the CSV file: {e.strerror}", path) from e
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass
