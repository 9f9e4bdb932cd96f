"""The DataFrames and CSV files of the result classes (``to_pandas()``, ``to_csv(path)``).

pandas is optional: these raise ImportError without it. The columns are listed in
docs/python.md ("Export"); ``routh._export`` has the JSON half and the overview.

>>> import routh
>>> top = routh.Model(
...     "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
...     {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
>>> list(routh.to_pandas(top.steady_motions(3.0)).columns)[:4]
['p_psi', 'gamma1', 'gamma2', 'gamma3']
"""

import os

import numpy as np


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
        "body_turn": o.body_turn,
        "degenerate": o.degenerate,
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
    name = type(obj).__name__
    if type(obj).__module__ != "routh":
        raise TypeError(f"to_pandas: not a routh result: {name}")
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
        cols = ["kind", "period", "energy", "p_psi", "precession", "body_turn", "degenerate",
                "stability_index", "stability", "amplitude", "omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3",
                "multiplier1_re", "multiplier1_im", "multiplier2_re", "multiplier2_im", "before", "after"]
        df = pd.DataFrame(rows, columns=cols)
        if name == "OrbitFamily":
            df.attrs.update(stop=obj.stop)
        return df
    if name == "OrbitNonlinearReport":
        row = {
            "verdict": obj.verdict,
            "reason": obj.reason,
            "rotation_number": obj.rotation_number,
            "twist": obj.twist,
            "resonance": obj.resonance,
            "area_defect": obj.area_defect,
        }
        row.update(_orbit_row(obj.orbit))
        return pd.DataFrame([row])
    if name == "OrbitChart":
        rows = []
        for i, (x, es, fam) in enumerate(zip(obj.x, obj.steady_energy, obj.families)):
            for o in (fam.orbits if fam is not None else []):
                row = {"i": i, "x": float(x), "h": o.energy - float(es)}
                row.update(_orbit_row(o))
                rows.append(row)
        df = pd.DataFrame(rows, columns=_CHART_COLUMNS)
        df["i"] = df["i"].astype("int64")
        df.attrs.update(parameter=obj.parameter, stop=obj.stop, failures=list(obj.failures),
                        x=np.asarray(obj.x).tolist(),
                        steady_energy=np.asarray(obj.steady_energy).tolist())
        return df
    if name == "OrbitChartCurve":
        return _curve_frame(pd, [obj])
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


_CHART_COLUMNS = ["i", "x", "h", "period", "energy", "p_psi", "precession", "body_turn",
                  "degenerate", "stability_index", "stability", "amplitude", "omega1", "omega2",
                  "omega3", "gamma1", "gamma2", "gamma3", "multiplier1_re", "multiplier1_im",
                  "multiplier2_re", "multiplier2_im"]


def _curve_frame(pd, curves):
    rows = []
    for k, c in enumerate(curves):
        for x, h in np.asarray(c.points):
            rows.append({"kind": c.kind, "curve": k, "x": float(x), "h": float(h)})
    df = pd.DataFrame(rows, columns=["kind", "curve", "x", "h"])
    df["curve"] = df["curve"].astype("int64")
    return df


def curves_frame(chart):
    """The points of an orbit chart's curves, one row each: ``kind``, ``curve`` (the index in
    ``chart.curves``), ``x``, ``h`` (``OrbitChart.curves_frame()``)."""
    df = _curve_frame(_pandas(), chart.curves)
    df.attrs.update(parameter=chart.parameter)
    return df


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
    """Writes `to_pandas(obj)` to the CSV file `path`, whole or not at all.

    pandas renders the text; routh's one writer (``routh::files``, as the command line's and the
    figures') writes it: a temporary file beside `path`, flushed and renamed over it; a symbolic
    link written through, a pipe or device written in place, an existing file's mode kept (a new
    one gets 0666 less the umask). An error is the OSError subclass of the system's error with
    `path` as its filename, and leaves `path` as it was. An empty list has no columns to write:
    ValueError, nothing written.
    """
    if isinstance(obj, (list, tuple)) and not obj:
        raise ValueError(
            "to_csv: an empty list has no columns (they come from its results); nothing was "
            f"written to {os.fspath(path)!r}"
        )
    text = to_pandas(obj).to_csv(index=False)
    from ._routh import _write_file

    _write_file(os.fspath(path), text)
