"""Export of the result classes: ``to_pandas()``, ``to_csv(path)``, ``to_json()``, ``from_json``.

Every result class has the methods ``to_pandas()``, ``to_csv(path)``, ``to_json()`` and the class
method ``from_json(text)`` (which call the functions here); ``routh.to_pandas``,
``routh.to_csv``, ``routh.to_json`` and ``routh.from_json`` also take a list of results (e.g.
what ``Model.steady_motions`` returns).

JSON. ``to_json()`` is a JSON object ``{"routh": "<class>", "format": 1, <fields>}``:

- ``SteadyMotion``, ``PeriodicOrbit``, ``OrbitEvent``, ``OrbitFamily``, ``OrbitNonlinearReport``,
  ``OrbitChartCurve`` and ``OrbitChart`` hold a Rust value; their fields are its serde form
  (what ``serde_json`` writes for ``routh::SteadyMotion`` etc., so Rust reads the text back with
  ``serde_json::from_str``: the two extra keys are ignored; ``OrbitChart`` has a third,
  ``parameter``, the name of its parameter, also ignored by Rust). The
  same schema is what ``routh orbit --json`` prints (one ``PeriodicOrbit`` document) and
  ``routh orbits --json`` (an array of ``OrbitFamily`` documents with the keys ``origin``,
  ``motion``, ``mode``, ``parent``, ``event`` besides, ignored here); and with the class named
  (``routh.PeriodicOrbit.from_json(text)``), the bare serde text of the Rust value, without the
  two keys, is read too. A JSON array gives a list (of ``cls``, when it is named).
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
are written in Python's shortest round-trip form, so ``pandas.read_csv(path)`` reads the same
numbers (pandas < 3: pass ``float_precision="round_trip"``); NaN is an empty cell.

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

import numpy as np

from . import _routh

__all__ = ["from_json", "to_csv", "to_json", "to_pandas"]

FORMAT = 1

# The classes whose JSON is the serde form of the Rust value they wrap (their pickle state).
_SERDE = ("SteadyMotion", "PeriodicOrbit", "OrbitEvent", "OrbitFamily", "OrbitNonlinearReport",
          "OrbitChartCurve", "OrbitChart")

# The classes of _SERDE whose pickle state is (name, serde JSON): the name is the JSON key given
# here, beside the Rust value's own keys (which do not include it).
_NAMED = {"OrbitChart": "parameter"}

# The JSON fields of every other class, in the order of its pickle state, each with its kind:
# "f" float, "i" int, "b" bool, "s" str (or None), "a<k>" float64 array of k columns ("a" for
# (n,)), "v3" a float64 (3,) vector, "c" complex128 (n,) array, "r:<Class>" a nested result,
# "l:<kind>" a list of them, "o:<kind>" None or one. What the fields' shapes must be together (a
# row of the atlas per y, …) is checked by `_check`.
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
        ("axis", "v3"),
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
        ("gamma", "v3"),
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
        ("normal", "v3"),
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
        # The pickle state of these classes is the serde JSON of the Rust value (with a name
        # before it for those of _NAMED).
        _, (_, state) = obj.__reduce__()
        if name in _NAMED:
            label, state = state
            doc[_NAMED[name]] = label
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
    if kind == "v3":
        if len(v) != 3:
            raise _routh.RouthError(f"from_json: {where}: expected 3 numbers, got {len(v)}")
        return np.array([_unfloat(x, where) for x in v], dtype=np.float64)
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
    if kind.startswith("a") or kind in ("c", "v3"):
        return _array(v, kind, where)
    if kind == "t":
        if not isinstance(v, list):
            raise _routh.RouthError(f"from_json: {where}: expected an array, got {v!r}")
        return _tuples(v)
    return v


def _restore(name, state, where):
    """`_routh._restore(name, state)`, its errors (worded for pickles) as from_json's."""
    try:
        return _routh._restore(name, state)
    except (_routh.RouthError, TypeError, ValueError) as e:
        msg = str(e).removeprefix("unpickling: ")
        raise _routh.RouthError(f"from_json: {where}: not a {name}: {msg}") from None


def _serde(name, body, where):
    """The result of class `name` (one of _SERDE) from the serde form of its Rust value (a
    non-finite float as "NaN", "Infinity", "-Infinity" or null); for a class of _NAMED, its
    name taken from the body's key (default "x": the bare serde form has none)."""
    if name in _NAMED:
        body = dict(body)
        label = body.pop(_NAMED[name], "x")
        if not isinstance(label, str):
            raise _routh.RouthError(
                f"from_json: {where}: {_NAMED[name]!r} must be a string, got {label!r}")
        return _restore(name, (label, json.dumps(body)), where)
    return _restore(name, json.dumps(body), where)


def _length(v, n, what, where):
    if len(v) != n:
        raise _routh.RouthError(f"from_json: {where}: {len(v)} {what}, expected {n}")


def _check(name, fields, where):
    """Checks what the shapes of a result's fields must be together (that `_decode` cannot see
    field by field): the result is refused here, not by an IndexError when it is used."""
    if name == "Branch":
        n = len(fields["s"])
        for f in ("gamma", "p_psi", "energy", "verdicts"):
            _length(fields[f], n, "points", f"{where}.{f}")
    elif name == "Atlas":
        nx, ny = len(fields["x"]), len(fields["y"])
        for f, ok, what in (("verdicts", (str, type(None)), "a verdict name or null"),
                            ("lost", (bool,), "true or false")):
            rows = fields[f]
            _length(rows, ny, "rows", f"{where}.{f} (one per y)")
            for j, row in enumerate(rows):
                if not isinstance(row, tuple):
                    raise _routh.RouthError(f"from_json: {where}.{f}[{j}]: expected an array")
                _length(row, nx, "entries", f"{where}.{f}[{j}] (one per x)")
                for x in row:
                    if not isinstance(x, ok):
                        raise _routh.RouthError(
                            f"from_json: {where}.{f}[{j}]: expected {what}, got {x!r}")
    elif name in ("Trajectory", "ReducedTrajectory"):
        n = len(fields["t"])
        for f, v in fields.items():
            if v is not None and f not in ("t",):
                _length(v, n, "samples", f"{where}.{f} (one per t)")
    elif name == "PoincareSection":
        _length(fields["points"], len(fields["starts"]), "orbits",
                f"{where}.points (one per row of starts)")
    elif name == "Diagram":
        for i, c in enumerate(fields["checks"]):
            if not isinstance(c, tuple) or len(c) != 3:
                raise _routh.RouthError(
                    f"from_json: {where}.checks[{i}]: expected [s, branch, index], got {c!r}")
    elif name == "NonlinearReport":
        k = fields["krein_signs"]
        if len(k) != 2 or not all(isinstance(x, int) and not isinstance(x, bool) for x in k):
            raise _routh.RouthError(
                f"from_json: {where}.krein_signs: expected two integers, got {list(k)!r}")


def _object(doc, expected, where="text"):
    """The result of a JSON object (a dict); `expected` a class name or None (any)."""
    if isinstance(doc, dict) and "routh" not in doc and expected in _SERDE:
        # The bare serde form of the Rust value (serde_json::to_string(&orbit) in Rust), read
        # when the class is named: PeriodicOrbit.from_json(text).
        return _serde(expected, doc, where)
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
        # Keys the Rust type does not have (the CLI's "origin", "motion", "mode", "parent",
        # "event" of a family) are ignored, as serde ignores them.
        body = {k: v for k, v in doc.items() if k not in ("routh", "format")}
        return _serde(name, body, where)
    values = {}
    for field, kind in _FIELDS[name]:
        if field not in doc:
            raise _routh.RouthError(f"from_json: {where}: {name} without {field!r}")
        values[field] = _decode(doc[field], kind, f"{where}.{field}")
    _check(name, values, where)
    try:
        state = _state(name, list(values.values()))
    except (TypeError, ValueError) as e:
        raise _routh.RouthError(f"from_json: {where}: not a {name}: {e}") from None
    return _restore(name, state, where)


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
    """The result (or list of results) whose JSON text is `text`; with `cls`, it must be one.
    Every text that is not one raises RouthError, whatever its size or nesting."""
    try:
        doc = json.loads(text)
    except (TypeError, ValueError) as e:
        raise _routh.RouthError(f"from_json: not JSON: {e}") from None
    except RecursionError:
        # Python's parser recurses on the nesting (a 100 000-deep array); no result is deeper
        # than a few levels.
        raise _routh.RouthError("from_json: not a routh result: nested too deep") from None
    expected = None if cls is None else cls.__name__
    try:
        if isinstance(doc, list):
            # A list of results (routh.to_json of a list; `routh orbits --json`): each must be
            # one of `cls` when it is given.
            return [_object(d, expected, f"[{i}]") for i, d in enumerate(doc)]
        return _object(doc, expected)
    except RecursionError:
        # A document just under the parser's limit, in a field read by recursion.
        raise _routh.RouthError("from_json: not a routh result: nested too deep") from None


# The DataFrames and CSV files (the methods to_pandas and to_csv call these names here).
from ._frames import to_csv, to_pandas  # noqa: E402
