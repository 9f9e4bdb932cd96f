"""Export of every result: to_json/from_json (bit for bit), to_pandas (the columns of
docs/python.md, the values of the objects' own attributes), to_csv (whole or not at all, read back
by pandas with the same numbers); the Rust names of load/simulate/certify beside the old ones."""

import json
import math
import os
import re
import sys

import numpy as np
import pytest

import routh
from conftest import ROOT

pd = pytest.importorskip("pandas")

READ_KW = {} if int(pd.__version__.split(".")[0]) >= 3 else {"float_precision": "round_trip"}


def bits(a):
    """The bit patterns of a float or complex array (NaN as one pattern: its bits are not kept)."""
    a = np.asarray(a)
    if a.dtype == np.complex128:
        a = a.view(np.float64)
    a = np.where(np.isnan(a), np.nan, a).astype(np.float64)
    return a.view(np.uint64)


def same(a, b, path="x"):
    """`a` and `b` are equal field by field, floats bit for bit (-0.0 is not 0.0; NaN is NaN)."""
    assert type(a) is type(b), (path, type(a), type(b))
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape, path
        np.testing.assert_array_equal(bits(a), bits(b), err_msg=path)
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(a, float):
        assert bits(a) == bits(b), (path, a, b)
    elif type(a).__module__ == "routh":
        names = [n for n in dir(a) if not n.startswith("_")]
        for n in names:
            x, y = getattr(a, n), getattr(b, n)
            if callable(x):
                continue
            same(x, y, f"{path}.{n}")
    else:
        assert a == b, (path, a, b)


def strict(text):
    """`text` parsed as strict JSON (no NaN/Infinity tokens)."""

    def refuse(token):
        raise AssertionError(f"non-standard JSON token {token}")

    return json.loads(text, parse_constant=refuse)


def round_trip(obj):
    """to_json → from_json (the class method and routh.from_json) gives the same object."""
    text = obj.to_json()
    doc = strict(text)
    assert doc["routh"] == type(obj).__name__ and doc["format"] == 1
    for back in (type(obj).from_json(text), routh.from_json(text)):
        assert back is not obj
        same(obj, back)
        assert back.to_json() == text
    return doc


def csv_trip(obj, tmp_path):
    """to_csv then pandas.read_csv: the numbers of to_pandas(), bit for bit; no file left over."""
    df = obj.to_pandas()
    path = tmp_path / f"{type(obj).__name__}.csv"
    obj.to_csv(path)
    assert sorted(os.listdir(tmp_path)) == [path.name]
    back = pd.read_csv(path, **READ_KW)
    assert list(back.columns) == list(df.columns)
    assert len(back) == len(df)
    for c in df.columns:
        if df[c].dtype == np.float64:
            np.testing.assert_array_equal(bits(back[c].to_numpy(np.float64)), bits(df[c].to_numpy()), err_msg=c)
        elif df[c].dtype == np.int64:
            assert back[c].tolist() == df[c].tolist(), c
    path.unlink()
    return back


# --- the columns of docs/python.md ---------------------------------------------------------------

DOC = (ROOT / "docs" / "python.md").read_text()


def doc_columns(cls):
    """The column names docs/python.md's export table lists for `cls` (shorthands expanded)."""
    rows = [line for line in DOC.splitlines() if line.startswith("| `") and f"`{cls}`" in line.split("|")[1]]
    assert len(rows) == 1, (cls, rows)
    cell = rows[0].split("|")[3]
    names = set()
    for tok in re.findall(r"`([A-Za-z_0-9.]+)`", cell):
        m = re.fullmatch(r"([a-z_]+?)(\d)\.\.(\d)(\w*)", tok)
        if tok[0].isupper():  # "as `SteadyMotion`": that class's columns
            names |= doc_columns(tok)
        elif m:
            names |= {f"{m[1]}{k}{m[4]}" for k in range(int(m[2]), int(m[3]) + 1)}
        else:
            names.add(tok)
    for m in re.finditer(r"`([a-z0-9_]+?)1_re`[^|]*?…[^|]*?`\1(\d)_im`", cell):
        names |= {f"{m[1]}{k}_{p}" for k in range(1, int(m[2]) + 1) for p in ("re", "im")}
    return names


def documented(df, cls):
    missing = set(df.columns) - doc_columns(cls)
    assert not missing, (cls, missing)


MOTION = ["p_psi", "gamma1", "gamma2", "gamma3", "psi_dot", "mu", "amended_potential", "energy", "isolated"]
REPORT = ["verdict", "degree_of_instability", "kappa1", "kappa2"] + [
    f"f2_root{k}_{p}" for k in range(1, 5) for p in ("re", "im")
]
ORBIT = [
    "period", "energy", "p_psi", "precession", "body_turn", "degenerate", "stability_index",
    "stability", "amplitude",
    "omega1", "omega2", "omega3", "gamma1", "gamma2", "gamma3",
    "multiplier1_re", "multiplier1_im", "multiplier2_re", "multiplier2_im",
]
DIAGRAM = [
    "kind", "branch", "s", "gamma1", "gamma2", "gamma3", "p_psi", "energy", "verdict", "isolated",
    "before", "after", "resonance", "nonlinear_before", "nonlinear_at", "nonlinear_after",
]


# --- steady motions and reports ----------------------------------------------------------------


def test_steady_motions_and_reports_export(top, tmp_path):
    motions = top.steady_motions(3.0)
    for m in motions:
        doc = round_trip(m)
        assert doc["gamma"] == [float(x) for x in m.gamma] and doc["energy"] == m.energy
        df = m.to_pandas()
        assert list(df.columns) == MOTION and len(df) == 1
        documented(df, "SteadyMotion")
        row = df.iloc[0]
        assert [row.gamma1, row.gamma2, row.gamma3] == list(m.gamma)
        assert (row.p_psi, row.psi_dot, row.mu, row.energy) == (m.p_psi, m.psi_dot, m.mu, m.energy)
        r = top.classify(m)
        round_trip(r)
        df = r.to_pandas()
        assert list(df.columns) == REPORT
        documented(df, "StabilityReport")
        assert df.kappa1[0] == r.restricted_hessian_eigenvalues[0]
        roots = [complex(df[f"f2_root{k}_re"][0], df[f"f2_root{k}_im"][0]) for k in range(1, 5)]
        assert roots == list(r.f2_roots)
        csv_trip(r, tmp_path)
    # A list: one row per motion, in order; the JSON array comes back a list.
    df = routh.to_pandas(motions)
    assert len(df) == len(motions) and list(df.columns) == MOTION
    assert df.energy.tolist() == [m.energy for m in motions]
    back = routh.from_json(routh.to_json(motions))
    same(back, motions)
    path = tmp_path / "motions.csv"
    routh.to_csv(motions, path)
    np.testing.assert_array_equal(pd.read_csv(path, **READ_KW).energy, [m.energy for m in motions])
    # The sleeping top's energy is the closed form U_r = p²/(2C) + mgl·γ₃ (C = 1.25, mgl = 1).
    for m in motions:
        if m.isolated:
            assert abs(m.energy - (3.0**2 / 2.5 + m.gamma[2])) < 1e-12

    circle = [m for m in motions if not m.isolated][0]
    c = top.classify_circle(circle, (0.0, 0.0, 1.0))
    round_trip(c)
    df = c.to_pandas()
    documented(df, "CircleReport")
    assert df.curvature[0] == c.curvature and df.report_verdict[0] == c.report.verdict
    assert [df.axis1[0], df.axis2[0], df.axis3[0]] == list(c.axis)


def test_nonlinear_reports_and_nan(top, tmp_path):
    sleeping = max(top.steady_motions(2.2), key=lambda s: s.gamma[2])
    r = top.nonlinear_stability(sleeping)
    round_trip(r)
    df = r.to_pandas()
    documented(df, "NonlinearReport")
    assert (df.omega1[0], df.omega2[0]) == tuple(r.frequencies)
    assert (df.c20[0], df.c11[0], df.c02[0]) == tuple(r.normal_form)
    assert (df.krein1[0], df.krein2[0]) == r.krein_signs and df.linear[0] == r.linear.verdict
    # Linearly unstable: the frequencies are NaN; JSON writes them as the string "NaN".
    unstable = [m for m in top.steady_motions(1.0) if abs(m.gamma[2] - 1) < 1e-9][0]
    r = top.nonlinear_stability(unstable)
    assert np.isnan(r.frequencies).all()
    doc = round_trip(r)
    assert doc["frequencies"] == ["NaN", "NaN"]
    back = csv_trip(r, tmp_path)
    assert np.isnan(back.omega1[0]) and np.isnan(back.omega2[0])


def test_nan_infinity_and_negative_zero_are_kept():
    """JSON written by hand with ±∞ and −0.0 comes back with those bits, and is written again
    the same."""
    text = json.dumps({
        "routh": "StabilityReport", "format": 1, "verdict": "degenerate", "degree_of_instability": 0,
        "restricted_hessian_eigenvalues": [-0.0, "Infinity"],
        "f2_roots": [["-Infinity", 0.1], ["NaN", -0.0], [5e-324, 1.7976931348623157e308], [0.0, 0.0]],
    }, ensure_ascii=False)
    r = routh.StabilityReport.from_json(text)
    eig = r.restricted_hessian_eigenvalues
    assert eig.dtype == np.float64 and math.copysign(1.0, eig[0]) == -1.0 and eig[1] == math.inf
    z = r.f2_roots
    assert z.dtype == np.complex128 and z[0].real == -math.inf and z[0].imag == 0.1
    assert math.isnan(z[1].real) and math.copysign(1.0, z[1].imag) == -1.0
    assert z[2].real == 5e-324 and z[2].imag == 1.7976931348623157e308
    assert r.to_json() == text
    # Random doubles of every magnitude round-trip bit for bit (a Trajectory made from JSON).
    rng = np.random.default_rng(7)
    x = rng.standard_normal(600) * 10.0 ** rng.integers(-300, 300, 600)
    doc = {"routh": "Trajectory", "format": 1, "t": list(x[:100]), "omega": x[:300].reshape(100, 3).tolist(),
           "gamma": x[300:600].reshape(100, 3).tolist(), "energy": list(x[:100]), "p_psi": list(x[100:200]),
           "attitude": None, "euler_angles": None}
    tr = routh.Trajectory.from_json(json.dumps(doc))
    np.testing.assert_array_equal(bits(tr.omega), bits(x[:300].reshape(100, 3)))
    assert len(tr) == 100 and tr.attitude is None


def test_bad_json_is_a_routh_error(top):
    m = top.steady_motions(3.0)[0]
    with pytest.raises(routh.RouthError, match="not JSON"):
        routh.from_json("{")
    with pytest.raises(routh.RouthError, match="not a StabilityReport"):
        routh.StabilityReport.from_json(m.to_json())
    with pytest.raises(routh.RouthError, match="no \"routh\" key"):
        routh.from_json("{}")
    doc = strict(top.classify(m).to_json())
    doc["restricted_hessian_eigenvalues"] = ["x", 1.0]
    with pytest.raises(routh.RouthError, match="expected a number"):
        routh.from_json(json.dumps(doc))
    doc = strict(top.classify(m).to_json())
    doc["format"] = 2
    with pytest.raises(routh.RouthError, match="format"):
        routh.from_json(json.dumps(doc))


def test_certificates_export(top, tmp_path):
    c = top.steady_motions_certified(2.2)
    round_trip(c)
    df = c.to_pandas()
    assert list(df.columns) == MOTION and len(df) == len(c.motions) == 2
    documented(df, "Certificate")
    assert df.attrs == {"complete": True, "p_psi": 2.2, "boxes": c.boxes, "undecided": 0}
    assert sorted(df.gamma3) == sorted(m.gamma[2] for m in c.motions)
    csv_trip(c, tmp_path)


# --- diagrams and atlases ----------------------------------------------------------------------


def test_diagrams_export_with_checks_and_stop(top, tmp_path):
    # The checks and stop of the Rust diagram: one check between consecutive events and at the
    # ends, each count of the branches equal to the global search's (and to steady_motions').
    d = top.bifurcation_diagram((0.0, 5.0))
    assert d.stop is None and d.consistent()
    assert len(d.checks) == len(d.events) + 1
    for s, on, searched in d.checks:
        assert 0.0 < s < 5.0 and on == searched == len(top.steady_motions(s))
    assert routh.from_json(d.to_json()).checks == d.checks
    d = top.bifurcation_diagram((0.0, 5.0), nonlinear=True)
    assert {e.kind for e in d.events} > {"hamiltonian_hopf", "branch_point"}
    doc = round_trip(d)
    assert doc["checks"] == [list(c) for c in d.checks]
    df = d.to_pandas()
    assert list(df.columns) == DIAGRAM
    documented(df, "Diagram")
    points = df[df.kind == "point"]
    assert len(points) == sum(len(b) for b in d.branches)
    for i, b in enumerate(d.branches):
        rows = points[points.branch == i]
        np.testing.assert_array_equal(rows.s, b.s)
        np.testing.assert_array_equal(rows[["gamma1", "gamma2", "gamma3"]].to_numpy(), b.gamma)
        np.testing.assert_array_equal(rows.energy, b.energy)
        assert rows.verdict.tolist() == b.verdicts
        # Over p_ψ the energy–momentum columns: p_ψ = s, and at γ = ±e₃ the closed form
        # E = p²/(2C) ± mgl.
        np.testing.assert_array_equal(rows.p_psi, b.s)
        axial = np.abs(np.abs(b.gamma[:, 2]) - 1) < 1e-12
        np.testing.assert_allclose(b.energy[axial], b.s[axial] ** 2 / 2.5 + b.gamma[axial, 2], rtol=0, atol=1e-12)
    events = df[df.kind != "point"]
    assert events.kind.tolist() == [e.kind for e in d.events]
    assert events.s.tolist() == [e.s for e in d.events]
    assert events.before.tolist() == [e.before for e in d.events]
    for e in d.events:
        round_trip(e)
    round_trip(d.branches[0])
    documented(d.branches[0].to_pandas(), "Branch")
    csv_trip(d, tmp_path)
    # A diagram stopped by its budget says why, and the JSON keeps it.
    short = top.bifurcation_diagram((0.0, 5.0), max_steps=3)
    assert isinstance(short.stop, str) and "max_steps" in short.stop
    assert routh.from_json(short.to_json()).stop == short.stop


def test_atlases_export(top, tmp_path):
    a = routh.stability_atlas(
        lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1], (0.5, 2.0), (0.5, 5.0), nx=7, ny=6
    )
    assert a.boundaries
    round_trip(a)
    round_trip(a.boundaries[0])
    df = a.to_pandas()
    documented(df, "Atlas")
    cells = df[df.kind == "cell"]
    assert len(cells) == 7 * 6
    for _, row in cells.iterrows():
        i, j = int(row.i), int(row.j)
        assert (row.x, row.y) == (a.x[i], a.y[j])
        assert row.verdict == a.verdicts[j][i] and row.lost == a.lost[j][i]
    curves = df[df.kind != "cell"]
    for k, b in enumerate(a.boundaries):
        np.testing.assert_array_equal(curves[curves.boundary == k][["x", "y"]].to_numpy(), b.points)
    csv_trip(a, tmp_path)


# --- trajectories ------------------------------------------------------------------------------


def test_trajectories_export(top, tmp_path):
    for attitude in (True, False):
        tr = top.simulate_full([0, 0.3, 5.0], [0.6, 0, 0.8], 1.0, attitude=attitude)
        round_trip(tr)
        df = tr.to_pandas()
        documented(df, "Trajectory")
        assert len(df) == len(tr)
        np.testing.assert_array_equal(df.t, tr.t)
        np.testing.assert_array_equal(df[["omega1", "omega2", "omega3"]].to_numpy(), tr.omega)
        np.testing.assert_array_equal(df.energy, tr.energy)
        if attitude:
            np.testing.assert_array_equal(df[["qx", "qy", "qz", "qw"]].to_numpy(), tr.attitude)
            np.testing.assert_array_equal(df[["euler_psi", "euler_theta", "euler_phi"]].to_numpy(), tr.euler_angles())
            same(routh.from_json(tr.to_json()).euler_angles(), tr.euler_angles())
        else:
            assert "qx" not in df.columns
        csv_trip(tr, tmp_path)
        red = top.simulate_reduced([0, 0.3, 0], [0.6, 0, 0.8], 3.0, 1.0, attitude=attitude)
        round_trip(red)
        df = red.to_pandas()
        documented(df, "ReducedTrajectory")
        np.testing.assert_array_equal(df[["big_omega1", "big_omega2", "big_omega3"]].to_numpy(), red.big_omega)
        np.testing.assert_array_equal(df.psi, red.psi)
        csv_trip(red, tmp_path)


# --- periodic orbits ---------------------------------------------------------------------------


def test_periodic_orbits_export(tmp_path):
    body = routh.Model(
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
        {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5},
    )
    o = body.periodic_orbit([0, 0, 0], [0, math.sin(0.5), -math.cos(0.5)], 2 * math.pi / math.sqrt(1.5))
    doc = round_trip(o)
    assert doc["period"] == o.period
    df = o.to_pandas()
    assert list(df.columns) == ORBIT
    documented(df, "PeriodicOrbit")
    assert complex(df.multiplier1_re[0], df.multiplier1_im[0]) == o.multipliers[0]
    assert [df.gamma1[0], df.gamma2[0], df.gamma3[0]] == list(o.gamma0)
    assert df.body_turn[0] == 0.0 and not df.degenerate[0]
    csv_trip(o, tmp_path)
    # A nutation of the Lagrange top: Δφ and the degenerate flag in the JSON and the frame.
    top = routh.Model(
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
        {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0},
    )
    n = top.periodic_orbit([0.3, 0, 3.0], [0, math.sin(0.5), math.cos(0.5)], 2.0)
    doc = round_trip(n)
    assert doc["body_turn"] == n.body_turn and doc["degenerate"] is True
    back = routh.PeriodicOrbit.from_json(n.to_json())
    assert back.body_turn == n.body_turn and back.degenerate is True
    df = n.to_pandas()
    assert df.body_turn[0] == n.body_turn and bool(df.degenerate[0]) is True
    csv_trip(n, tmp_path)

    s = body.poincare_section(o.p_psi, o.energy, normal=[0, 1, 0], orbits=3, crossings=5)
    round_trip(s)
    df = s.to_pandas()
    documented(df, "PoincareSection")
    for k, pts in enumerate(s.points):
        np.testing.assert_array_equal(df[df.orbit == k][["theta", "m_n"]].to_numpy(), pts)
    assert df.attrs["energy"] == s.energy
    csv_trip(s, tmp_path)

    asym = routh.Model.from_file(ROOT / "examples" / "models" / "asymmetric_top.toml")
    hanging = min(asym.steady_motions(0.0), key=lambda m: m.energy)
    f = asym.lyapunov_family(hanging, 0, max_orbits=40)
    assert f.events
    round_trip(f)
    round_trip(f.events[0])
    df = f.to_pandas()
    documented(df, "OrbitFamily")
    orbits = df[df.kind == "orbit"]
    np.testing.assert_array_equal(orbits.energy, f.energy)
    np.testing.assert_array_equal(orbits.stability_index, f.stability_index)
    assert orbits.stability.tolist() == f.stability
    events = df[df.kind != "orbit"]
    assert events.kind.tolist() == [e.kind for e in f.events]
    assert events.energy.tolist() == [e.orbit.energy for e in f.events]
    documented(f.events[0].to_pandas(), "OrbitEvent")
    csv_trip(f, tmp_path)


# --- CSV files: whole or not at all; pandas optional -------------------------------------------


def test_csv_errors_name_the_path_and_leave_nothing(top, tmp_path):
    r = top.classify(top.steady_motions(3.0)[0])
    missing = tmp_path / "no" / "such" / "dir" / "r.csv"
    with pytest.raises(FileNotFoundError) as e:
        r.to_csv(missing)
    assert str(missing) in str(e.value)
    # The target is a directory: the rename fails, the directory and its file are untouched,
    # and no temporary file is left.
    target = tmp_path / "target"
    target.mkdir()
    (target / "keep").write_text("x")
    with pytest.raises(OSError) as e:
        r.to_csv(target)
    assert str(target) in str(e.value)
    assert sorted(os.listdir(tmp_path)) == ["target"] and os.listdir(target) == ["keep"]
    # An existing file is replaced whole.
    path = tmp_path / "r.csv"
    path.write_text("old contents\n" * 1000)
    r.to_csv(path)
    assert pd.read_csv(path).verdict[0] == r.verdict and "old" not in path.read_text()


def _umasked_mode(directory):
    """The mode a new file gets here (0666 less the umask), read off a file open() makes."""
    probe = directory / "probe"
    probe.write_text("")
    m = probe.stat().st_mode & 0o7777
    probe.unlink()
    return m


@pytest.mark.skipif(os.name != "posix", reason="links, modes, pipes and devices of Unix")
def test_csv_hostile_paths(top, tmp_path):
    """Issue 43: to_csv goes through routh's one writer. A new file gets 0666 less the umask (not
    mkstemp's 0600), an existing one keeps its mode, a link is written through and stays a link,
    a pipe or device is written in place (never replaced), a file the user may not write is
    refused (PermissionError, not replaced by a rename), every error is an OSError naming the
    path, and nothing is left behind."""
    r = top.classify(top.steady_motions(3.0)[0])
    d = tmp_path / "d"
    d.mkdir()
    new = d / "new.csv"
    r.to_csv(new)
    assert new.stat().st_mode & 0o7777 == _umasked_mode(d)
    assert pd.read_csv(new).verdict[0] == r.verdict

    new.chmod(0o640)
    r.to_csv(new)
    assert new.stat().st_mode & 0o7777 == 0o640

    other = tmp_path / "other"
    other.mkdir()
    target = other / "real.csv"
    target.write_text("old\n")
    target.chmod(0o600)
    link = d / "link.csv"
    link.symlink_to(target)
    r.to_csv(link)
    assert link.is_symlink() and pd.read_csv(target).verdict[0] == r.verdict
    assert target.stat().st_mode & 0o7777 == 0o600
    assert sorted(os.listdir(other)) == ["real.csv"]
    dangling = d / "dangling.csv"
    dangling.symlink_to(other / "made.csv")
    r.to_csv(dangling)
    assert dangling.is_symlink() and pd.read_csv(other / "made.csv").verdict[0] == r.verdict

    # A device in place: /dev/null stays a device; /dev/full's error names it.
    r.to_csv("/dev/null")
    import stat

    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)
    if os.path.exists("/dev/full"):
        with pytest.raises(OSError) as e:
            r.to_csv("/dev/full")
        assert e.value.errno == __import__("errno").ENOSPC and e.value.filename == "/dev/full"
    # A named pipe: written directly, still a pipe, nothing beside it.
    fifo = d / "fifo"
    os.mkfifo(fifo)
    import threading

    got = {}
    reader = threading.Thread(target=lambda: got.update(text=fifo.read_text()), daemon=True)
    reader.start()
    r.to_csv(fifo)
    reader.join(10)
    import io

    assert pd.read_csv(io.StringIO(got["text"])).verdict[0] == r.verdict
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    fifo.unlink()

    # A read-only file: refused for a user (root may write any file).
    ro = d / "ro.csv"
    ro.write_text("keep\n")
    ro.chmod(0o444)
    if os.geteuid() != 0:
        with pytest.raises(PermissionError) as e:
            r.to_csv(ro)
        assert e.value.filename == str(ro) and ro.read_text() == "keep\n"
    assert ro.stat().st_mode & 0o7777 == 0o444

    # Errors: the OSError subclass of the system's error, with the path.
    for path, kind in [(d / "no" / "dir" / "x.csv", FileNotFoundError), (other, IsADirectoryError),
                       (new / "below.csv", NotADirectoryError)]:
        with pytest.raises(kind) as e:
            r.to_csv(path)
        assert e.value.filename == str(path) and str(path) in str(e.value)
    assert sorted(os.listdir(d)) == ["dangling.csv", "link.csv", "new.csv", "ro.csv"]
    assert sorted(os.listdir(other)) == ["made.csv", "real.csv"]


def test_csv_of_an_empty_list_is_refused(tmp_path):
    """An empty list has no columns: a ValueError naming the path and no file (before, a file that
    pandas.read_csv could not read)."""
    path = tmp_path / "empty.csv"
    with pytest.raises(ValueError, match="empty list") as e:
        routh.to_csv([], path)
    assert str(path) in str(e.value)
    assert not path.exists()
    assert routh.to_pandas([]).empty


def test_without_pandas_a_clear_import_error(top, monkeypatch):
    m = top.steady_motions(3.0)[0]
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="need pandas"):
        m.to_pandas()
    with pytest.raises(ImportError, match="need pandas"):
        m.to_csv("never-written.csv")
    assert not os.path.exists("never-written.csv")
    assert routh.SteadyMotion.from_json(m.to_json()).energy == m.energy  # JSON needs no pandas


# --- the Rust names of load / simulate / certify -----------------------------------------------


def test_rust_names_and_their_aliases_agree(top):
    path = ROOT / "examples" / "models" / "gyrostat.toml"
    a, b = routh.Model.from_file(path), routh.Model.load(path)
    assert a.lagrangian == b.lagrangian and a.parameters.keys() == b.parameters.keys()
    kw = dict(attitude=True, times=np.linspace(0, 1, 11))
    t1 = top.simulate_full([0, 0.3, 5.0], [0.6, 0, 0.8], 1.0, **kw)
    t2 = top.simulate([0, 0.3, 5.0], [0.6, 0, 0.8], 1.0, **kw)
    same(t1, t2)
    c1, c2 = top.steady_motions_certified(2.2, max_boxes=50000), top.certify(2.2, max_boxes=50000)
    same(c1, c2)
    for old, new in (("load", "from_file"), ("simulate", "simulate_full"), ("certify", "steady_motions_certified")):
        assert f"Alias of `Model.{new}`" in " ".join(getattr(routh.Model, old).__doc__.split())
        assert f"`{old}` is an alias" in " ".join(getattr(routh.Model, new).__doc__.split())


def test_the_examples_of_the_export_modules_run():
    import doctest

    import routh._export
    import routh._frames

    for module in (routh._export, routh._frames):
        result = doctest.testmod(module)
        assert result.attempted > 0 and result.failed == 0, module.__name__
