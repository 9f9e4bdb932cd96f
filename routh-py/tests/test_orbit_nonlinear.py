"""Orbital stability beyond linear and orbit charts from Python (docs/method.md §12), checked
against what the code under test does not compute: the twist at small amplitude against the
steady motion's Birkhoff normal form (`Model.nonlinear_stability`, a different algorithm in
another chart: τ → D/(π ω_k³)), cos 2πρ against k, the chart's curve points against
finite-difference monodromies of `simulate_full` (an integration the variational equations play
no part in), the twist's sign on both sides of a twist zero; hostile inputs; the figure's lines
against the curve points; pickles, JSON and frames."""

import json
import math
import os
import pickle
import signal
import threading
import time

import numpy as np
import pytest

import routh

BODY = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z"
# The same body with its middle moment a scalar parameter (the chart's x).
BODY_B = ("kinetic = 0.5 * (omega.x * omega.x + b * omega.y * omega.y + 3.0 * omega.z * omega.z),"
          " potential = l * gamma.z")


@pytest.fixture(scope="module")
def body():
    """Moments (1, 2, 3), centre of mass on e₃ at l = 1.5 (m g = 1): the Rust tests' body."""
    return routh.Model(BODY, {"inertia": [1.0, 2.0, 3.0], "l": 1.5})


@pytest.fixture(scope="module")
def body_b():
    return routh.Model(BODY_B, {"b": 2.0, "l": 1.5})


def hanging(m):
    return min(m.steady_motions(0.0), key=lambda s: s.energy)


@pytest.fixture(scope="module")
def family(body):
    return body.lyapunov_family(hanging(body), 0, max_orbits=40, nonlinear=True)


@pytest.fixture(scope="module")
def chart(body_b):
    return body_b.orbit_chart("b", [0, 0, -1], (1.9, 2.1), (0.0, 2.8), nx=3, max_orbits=120)


def fd_index(m, o, h=1e-6):
    """k = (tr Φ(T) − 4)/2 by central differences of `simulate_full` over one period (as
    tests/orbit_nonlinear.rs's `fd_index`): the three ω axes, two tangents of the sphere at γ₀,
    and γ₀ itself, whose diagonal entry is 1."""
    w0, g0 = np.asarray(o.omega0), np.asarray(o.gamma0)

    def end(w, g):
        t = m.simulate_full(w, g, o.period, rtol=1e-12, atol=1e-13)
        return np.concatenate([t.omega[-1], t.gamma[-1]])

    u = np.cross(g0, [0.3, 0.5, 0.7])
    u /= np.linalg.norm(u)
    v = np.cross(g0, u)
    trace = 1.0
    for i in range(5):
        wp, wm, gp, gm = w0.copy(), w0.copy(), g0.copy(), g0.copy()
        if i < 3:
            wp[i] += h
            wm[i] -= h
        else:
            d = (u, v)[i - 3]
            gp = (g0 + h * d) / np.linalg.norm(g0 + h * d)
            gm = (g0 - h * d) / np.linalg.norm(g0 - h * d)
        diff = (end(wp, gp) - end(wm, gm)) / (2 * h)
        trace += diff[i] if i < 3 else float(diff[3:] @ (u, v)[i - 3])
    return (trace - 4.0) / 2.0


# --- the report against the steady motion's normal form ------------------------------------------


def test_twist_at_small_amplitude_is_the_normal_forms_d_over_pi_omega_cubed(body):
    """τ(0) = D/(π ω_k³) on the family of mode k: D and ω from `nonlinear_stability` of the
    hanging body (the normal form H₄ of the steady motion). A twist off by 2π or of the wrong
    sign fails by orders of magnitude."""
    s = hanging(body)
    nf = body.nonlinear_stability(s)
    assert tuple(nf.krein_signs) == (1, 1)
    w1, w2 = (float(x) for x in nf.frequencies)
    d = nf.arnold_determinant
    for mode in (0, 1):
        wk, wj = (w1, w2) if mode == 0 else (w2, w1)
        f = body.lyapunov_family(s, mode, max_orbits=3, initial_amplitude=2e-3, max_step=0.004)
        a, b = f.orbits[0], f.orbits[2]
        ra, rb = body.orbit_nonlinear_stability(a), body.orbit_nonlinear_stability(b)
        assert isinstance(ra, routh.OrbitNonlinearReport)
        assert ra.verdict == "orbitally_stable" and ra.resonance is None, ra
        assert ra.verdict in routh.ORBIT_NONLINEAR_VERDICTS
        assert ra.area_defect < 1e-6
        # ρ → ω_j/ω_k mod 1, and cos 2πρ = k of the orbit's own monodromy.
        assert abs(ra.rotation_number - (wj / wk) % 1.0) < 1e-3
        assert abs(math.cos(2 * math.pi * ra.rotation_number) - a.stability_index) < 1e-7
        ea, eb = a.energy - s.energy, b.energy - s.energy
        tau0 = ra.twist - (rb.twist - ra.twist) / (eb - ea) * ea
        expected = d / (math.pi * wk**3)
        assert abs(tau0 - expected) < 1e-6 * abs(expected), (mode, tau0, expected)
        # The report's orbit is the orbit analysed.
        assert ra.orbit.to_json() == a.to_json()


def test_nonlinear_events_along_a_family(body, family):
    """With nonlinear=True the linear events are those without it; the resonances sit where
    k = −1/2 and 0 (checked by an independent monodromy), and the twist changes sign across a
    twist zero (on the family's own orbits either side)."""
    plain = body.lyapunov_family(hanging(body), 0, max_orbits=40)
    linear = [(e.kind, e.energy) for e in family.events
              if e.kind in ("fold", "branch_point", "period_doubling")]
    assert [k for k, _ in linear] == [e.kind for e in plain.events]
    for (_, e1), e2 in zip(linear, plain.events):
        assert abs(e1 - e2.energy) < 1e-8
    kinds = {e.kind for e in family.events}
    assert kinds <= set(routh.ORBIT_EVENT_KINDS)
    nonlinear = kinds - {"fold", "branch_point", "period_doubling"}
    assert nonlinear, [e.kind for e in family.events]
    for e in family.events:
        if e.kind == "fourth_order_resonance":
            assert abs(e.orbit.stability_index) < 1e-6
            assert abs(fd_index(body, e.orbit)) < 1e-5
        elif e.kind == "third_order_resonance":
            assert abs(e.orbit.stability_index + 0.5) < 1e-6
            assert abs(fd_index(body, e.orbit) + 0.5) < 1e-5
        elif e.kind == "twist_degenerate":
            r = body.orbit_nonlinear_stability(e.orbit)
            before = max((o for o in family.orbits if o.energy < e.energy),
                         key=lambda o: o.energy)
            after = min((o for o in family.orbits if o.energy > e.energy),
                        key=lambda o: o.energy)
            tb = body.orbit_nonlinear_stability(before).twist
            ta = body.orbit_nonlinear_stability(after).twist
            assert tb * ta < 0, (tb, ta)
            assert abs(r.twist) < 1e-3 * max(abs(tb), abs(ta)), (r.twist, tb, ta)


def test_verdicts_of_non_elliptic_and_degenerate_orbits(body):
    """Hyperbolic: "unstable" with NaN ρ, τ; a degenerate nutation of the Lagrange top:
    "undecided", saying why. Orbits rewritten by hand through JSON are analysed as they say."""
    s = hanging(body)
    f = body.lyapunov_family(s, 0, max_orbits=3)
    doc = json.loads(f.orbits[0].to_json())
    doc["stability"] = "Hyperbolic"
    hyper = routh.PeriodicOrbit.from_json(json.dumps(doc))
    r = body.orbit_nonlinear_stability(hyper)
    assert r.verdict == "unstable" and math.isnan(r.twist) and math.isnan(r.rotation_number)
    assert math.isnan(r.area_defect) and r.resonance is None
    top = routh.Model(BODY.replace("l * ", "mgl * "), {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    n = top.periodic_orbit([0.3, 0, 3.0], [0, math.sin(0.5), math.cos(0.5)], 2.0)
    assert n.degenerate
    r = top.orbit_nonlinear_stability(n)
    assert r.verdict == "undecided" and "degenerate" in r.reason


def test_hostile_options_and_orbits_are_python_errors(body):
    o = body.lyapunov_family(hanging(body), 0, max_orbits=3).orbits[-1]
    with pytest.raises(TypeError, match="twist_toll"):
        body.orbit_nonlinear_stability(o, twist_toll=1e-3)
    with pytest.raises(TypeError):
        body.orbit_nonlinear_stability(o, 1e-3)  # options are keywords only
    for kw, name in ((dict(twist_tol=0.0), "twist_tol"), (dict(rtol=2.0), "rtol"),
                     (dict(resonance_tol=float("nan")), "resonance_tol"),
                     (dict(criterion_tol=1.5), "criterion_tol"), (dict(max_steps=0), "max_steps"),
                     (dict(atol=-1.0), "atol")):
        with pytest.raises(routh.RouthError, match=name) as e:
            body.orbit_nonlinear_stability(o, **kw)
        assert e.value.kind == "InvalidOption"
    with pytest.raises(TypeError):
        body.orbit_nonlinear_stability(o, rtol=True)
    with pytest.raises(OverflowError):
        body.orbit_nonlinear_stability(o, max_steps=-1)
    with pytest.raises(TypeError):
        body.orbit_nonlinear_stability("not an orbit")
    # Hand-written orbits that are not orbits: refused by the orbit's checks, not a panic.
    doc = json.loads(o.to_json())
    for key, value in (("period", -1.0), ("period", "NaN"), ("gamma0", [0.0, 0.0, 2.0]),
                       ("omega0", ["Infinity", 0.0, 0.0])):
        bad = dict(doc, **{key: value})
        with pytest.raises(routh.RouthError) as e:
            body.orbit_nonlinear_stability(routh.PeriodicOrbit.from_json(json.dumps(bad)))
        assert e.value.kind != "Panic", e.value
    # A starting point that is not periodic, claimed elliptic: an answer or a RouthError.
    off = dict(doc, omega0=[x + 0.05 for x in doc["omega0"]])
    try:
        r = body.orbit_nonlinear_stability(routh.PeriodicOrbit.from_json(json.dumps(off)))
        assert r.verdict in routh.ORBIT_NONLINEAR_VERDICTS
    except routh.RouthError as e:
        assert e.kind != "Panic", e
    # nonlinear= is a bool on every family.
    with pytest.raises(TypeError):
        body.lyapunov_family(hanging(body), 0, max_orbits=3, nonlinear="yes")


def test_report_repr_pickle_json_frame(body):
    o = body.lyapunov_family(hanging(body), 0, max_orbits=6).orbits[-1]
    r = body.orbit_nonlinear_stability(o)
    assert repr(r).startswith("OrbitNonlinearReport(verdict='orbitally_stable'")
    back = pickle.loads(pickle.dumps(r))
    assert isinstance(back, routh.OrbitNonlinearReport)
    assert (back.twist, back.rotation_number, back.verdict, back.reason, back.area_defect) == (
        r.twist, r.rotation_number, r.verdict, r.reason, r.area_defect)
    assert back.orbit.period == o.period
    text = r.to_json()
    doc = json.loads(text)
    assert doc["routh"] == "OrbitNonlinearReport" and doc["verdict"] == "OrbitallyStable"
    assert doc["twist"] == r.twist
    same = routh.OrbitNonlinearReport.from_json(text)
    assert same.to_json() == text and routh.from_json(text).twist == r.twist
    df = r.to_pandas()
    assert list(df.columns[:6]) == ["verdict", "reason", "rotation_number", "twist", "resonance",
                                    "area_defect"]
    assert df.twist[0] == r.twist and df.period[0] == o.period
    # NaN fields of a non-elliptic report survive JSON and pickles.
    doc = json.loads(o.to_json())
    doc["stability"] = "Hyperbolic"
    u = body.orbit_nonlinear_stability(routh.PeriodicOrbit.from_json(json.dumps(doc)))
    assert math.isnan(routh.OrbitNonlinearReport.from_json(u.to_json()).twist)
    assert math.isnan(pickle.loads(pickle.dumps(u)).rotation_number)


def test_family_plot_marks_the_nonlinear_events(family):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from routh._plot import ORBIT_EVENT_NAME

    ax = family.plot()
    labels = set(ax.get_legend_handles_labels()[1])
    for e in family.events:
        assert ORBIT_EVENT_NAME[e.kind] in labels
    plt.close(ax.figure)


# --- the chart ------------------------------------------------------------------------------------


def test_chart_curves_are_where_an_independent_monodromy_says(body_b, chart):
    """Every event at the chart's ends: k = 1 and k = 0 by finite differences of
    `simulate_full` on the model at that x; a twist zero where the twist, recomputed, is small
    against its neighbours'. The curves run across the chart (continued in (x, h): a curve may
    turn back in x); their points at the grid's x are the families' events there."""
    assert isinstance(chart, routh.OrbitChart) and chart.parameter == "b"
    np.testing.assert_allclose(chart.x, [1.9, 2.0, 2.1], rtol=0, atol=1e-15)
    assert chart.stop is None and chart.failures == [None, None, None]
    kinds = {c.kind: len(c) for c in chart.curves}
    for kind in ("branch_point", "fourth_order_resonance", "twist_degenerate"):
        assert any(c.kind == kind and len(c) == 3 for c in chart.curves), kinds
    for c in chart.curves:
        pts = np.asarray(c.points)
        assert pts.shape == (len(c), 2)
        assert np.all((1.9 <= pts[:, 0]) & (pts[:, 0] <= 2.1) & (0 <= pts[:, 1]) & (pts[:, 1] <= 2.8))
        for x, h in pts:
            i = int(np.argmin(np.abs(chart.x - x)))
            if abs(chart.x[i] - x) > 1e-12:
                continue  # between the grid's x (checked in Rust against the family there)
            es = chart.steady_energy[i]
            assert any(e.kind == c.kind and abs(e.energy - es - h) < 1e-6
                       for e in chart.families[i].events), (c.kind, x, h)
    for i in (0, 2):
        m = body_b.with_params(b=float(chart.x[i]))
        s = hanging(m)
        assert abs(s.energy - chart.steady_energy[i]) < 1e-12
        fam = chart.families[i]
        for e in fam.events:
            if e.kind == "branch_point":
                assert abs(fd_index(m, e.orbit) - 1.0) < 1e-5
            elif e.kind == "fourth_order_resonance":
                assert abs(fd_index(m, e.orbit)) < 1e-5
            elif e.kind == "twist_degenerate":
                near = [o for o in fam.orbits if o.stability == "elliptic"]
                scale = max(abs(m.orbit_nonlinear_stability(o).twist) for o in near[:3])
                assert abs(m.orbit_nonlinear_stability(e.orbit).twist) < 1e-4 * scale


def test_chart_of_a_callable_family_is_the_models(body_b, chart):
    same = routh.orbit_chart(lambda b: (body_b.with_params(b=b), 0.0), [0, 0, -1], (1.9, 2.1),
                             (0.0, 2.8), nx=3, max_orbits=120, parameter="b")
    assert same.to_json() == chart.to_json()
    again = routh.orbit_chart(body_b, [0, 0, -1], (1.9, 2.1), (0.0, 2.8), nx=3, max_orbits=120,
                              parameter="b")
    assert again.to_json() == chart.to_json()
    # Each family is the Lyapunov family of the model at that x, nonlinear, over the chart's h
    # (from the steady motion `steady_motions` finds, equal to the chart's to roundoff).
    m = body_b.with_params(b=2.0)
    s = hanging(m)
    f = m.lyapunov_family(s, 0, max_orbits=120, nonlinear=True,
                          energy_bounds=(s.energy, s.energy + 2.8))
    g = chart.families[1]
    assert len(f) == len(g) and [e.kind for e in f.events] == [e.kind for e in g.events]
    np.testing.assert_allclose(f.energy, g.energy, rtol=0, atol=1e-9)
    np.testing.assert_allclose(f.stability_index, g.stability_index, rtol=0, atol=1e-7)
    np.testing.assert_allclose([e.energy for e in f.events], [e.energy for e in g.events],
                               rtol=0, atol=1e-8)


def test_chart_samples_frames_pickle_json(chart):
    n = sum(len(f) for f in chart.families)
    assert chart.samples.shape == (n, 3) and len(chart) == 3
    df = chart.to_pandas()
    assert list(df.columns[:3]) == ["i", "x", "h"] and len(df) == n
    assert {"stability_index", "stability", "energy", "period"} <= set(df.columns)
    np.testing.assert_array_equal(df[["x", "h", "stability_index"]].to_numpy(), chart.samples)
    assert df.attrs["parameter"] == "b" and df.attrs["stop"] is None
    cf = chart.curves_frame()
    assert list(cf.columns) == ["kind", "curve", "x", "h"]
    for k, c in enumerate(chart.curves):
        rows = cf[cf.curve == k]
        assert set(rows.kind) == {c.kind}
        np.testing.assert_array_equal(rows[["x", "h"]].to_numpy(), c.points)
    assert list(chart.curves[0].to_pandas().columns) == ["kind", "curve", "x", "h"]
    back = pickle.loads(pickle.dumps(chart))
    assert isinstance(back, routh.OrbitChart) and back.parameter == "b"
    assert back.to_json() == chart.to_json()
    text = chart.to_json()
    doc = json.loads(text)
    assert doc["routh"] == "OrbitChart" and doc["parameter"] == "b"
    assert routh.OrbitChart.from_json(text).to_json() == text
    c0 = chart.curves[0]
    assert pickle.loads(pickle.dumps(c0)).to_json() == c0.to_json()
    assert routh.from_json(c0.to_json()).kind == c0.kind
    assert "OrbitChart(b=1.9..2.1, 3 values" in repr(chart)
    assert repr(c0).startswith(f"OrbitChartCurve(kind='{c0.kind}'")


def test_chart_plot_draws_the_curves_and_the_regions(chart):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from routh._plot import THE_STYLE, _linestyle

    ax = chart.plot()
    lines = [l for l in ax.get_lines() if l.get_color() != "white"]
    for c in chart.curves:
        look = THE_STYLE["orbit_curve"][c.kind]
        hits = [l for l in lines if l.get_xydata().shape == np.shape(c.points)
                and np.array_equal(l.get_xydata(), c.points)]
        assert hits, c.kind
        assert hits[0].get_color() == look["color"]
        solid = _linestyle(look) == "-"
        assert (hits[0].get_linestyle() == "-") == solid, (c.kind, hits[0].get_linestyle())
        assert hits[0].get_linewidth() == look["width"]
    handles, labels = ax.get_legend_handles_labels()
    drawn = {c.kind for c in chart.curves if len(c)}
    assert {THE_STYLE["orbit_curve"][k]["label"] for k in drawn} <= set(labels)
    assert THE_STYLE["orbit_verdict"]["elliptic"]["label"] in labels
    absent = set(THE_STYLE["orbit_curve"]) - drawn
    assert not {THE_STYLE["orbit_curve"][k]["label"] for k in absent} & set(labels)
    # The regions: every orbit drawn, in its stability's colour.
    pts = np.vstack([col.get_offsets() for col in ax.collections])
    assert len(pts) == len(chart.samples)
    assert ax.get_xlabel() == "b" and ax.get_ylabel() == r"$h = E - E_\mathrm{s}$"
    # The dash patterns differ between the kinds drawn.
    looks = {k: _linestyle(THE_STYLE["orbit_curve"][k]) for k in THE_STYLE["orbit_curve"]}
    assert len({str(v) for v in looks.values()}) == len(looks)
    plt.close(ax.figure)


def test_chart_hostile_inputs(body_b):
    args = ([0, 0, -1], (1.9, 2.1), (0.0, 1.0))
    with pytest.raises(routh.ModelError):
        body_b.orbit_chart("nope", *args, nx=2)
    vec = routh.Model(BODY, {"inertia": [1.0, 2.0, 3.0], "l": 1.5})
    with pytest.raises(routh.ModelError, match="not a number"):
        vec.orbit_chart("inertia", *args, nx=2)
    with pytest.raises(routh.RouthError, match="parameter") as e:
        routh.orbit_chart(body_b, *args, nx=2)
    assert e.value.kind == "InvalidOption"
    for kw, what in ((dict(x_range=(2.1, 1.9)), "x_range"),
                     (dict(excess_energy=(-1.0, 1.0)), "excess_energy"),
                     (dict(excess_energy=(0.0, float("inf"))), "excess_energy"),
                     (dict(mode=2), "mode"), (dict(nx=1), "nx"), (dict(nx=10**6), "nx"),
                     (dict(join_tol=0.0), "join_tol"), (dict(momentum=1.0, parameter="p_psi"),
                                                        "momentum")):
        a = dict(gamma_guess=[0, 0, -1], x_range=(1.9, 2.1), excess_energy=(0.0, 1.0),
                 parameter="b", nx=2)
        a.update(kw)
        with pytest.raises(routh.RouthError, match=what) as e:
            routh.orbit_chart(body_b, **a)
        assert e.value.kind == "InvalidOption", e.value
    with pytest.raises(TypeError, match="unexpected keyword"):
        body_b.orbit_chart("b", *args, energy_bounds=(0, 1))
    with pytest.raises(TypeError, match="unexpected keyword"):
        body_b.orbit_chart("b", *args, nonlinear=True)  # always on in a chart
    with pytest.raises(TypeError):
        routh.orbit_chart(42, *args, parameter="b")
    with pytest.raises(routh.RouthError, match="gamma_guess"):
        body_b.orbit_chart("b", [0, 1], (1.9, 2.1), (0.0, 1.0))
    with pytest.raises(routh.RouthError, match="momentum"):
        routh.orbit_chart(lambda b: (body_b, 0.0), *args, momentum=0.0)
    with pytest.raises(TypeError, match="tuple"):
        routh.orbit_chart(lambda b: 3.0, *args)

    def boom(b):
        if b > 2.0:
            raise ValueError("no model here")
        return body_b.with_params(b=b), 0.0

    with pytest.raises(ValueError, match="no model here"):
        routh.orbit_chart(boom, *args, nx=3, max_orbits=5)


def test_chart_records_failures_instead_of_raising(body_b):
    """Upright (γ = e₃, centre of mass above the point): no stable steady motion to start
    from at any x. The chart says so per x and still draws (an empty chart)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    c = body_b.orbit_chart("b", [0, 0, 1], (1.9, 2.1), (0.0, 1.0), nx=2, max_orbits=5)
    assert c.families == [None, None] and all(f for f in c.failures), c.failures
    assert c.curves == [] and c.samples.shape == (0, 3)
    assert np.isnan(c.steady_energy).all()
    assert routh.OrbitChart.from_json(c.to_json()).failures == c.failures
    assert len(c.to_pandas()) == 0 and len(c.curves_frame()) == 0
    ax = c.plot()
    assert ax.get_xlabel() == "b"
    plt.close(ax.figure)


def test_chart_through_the_momentum(body_b):
    c = routh.orbit_chart(body_b, [0, 0, -1], (0.0, 0.2), (0.0, 0.5), parameter="p_psi", nx=2,
                          max_orbits=10)
    assert c.parameter == "p_psi" and c.failures == [None, None]
    for x, f in zip(c.x, c.families):
        assert all(abs(o.p_psi - x) < 1e-9 for o in f.orbits)


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="signals reach the main thread only")
@pytest.mark.parametrize("form", ["model", "callable", "report"])
def test_ctrl_c_stops_a_chart_at_once(body, body_b, form):
    o = body.lyapunov_family(hanging(body), 0, max_orbits=3).orbits[-1]
    calls = {
        # Each runs for minutes uninterrupted.
        "model": lambda: body_b.orbit_chart("b", [0, 0, -1], (1.0, 3.0), (0.0, 50.0), nx=10000,
                                            max_orbits=100_000, max_step=1e-4),
        "callable": lambda: routh.orbit_chart(lambda b: (body_b.with_params(b=b), 0.0),
                                              [0, 0, -1], (1.0, 3.0), (0.0, 50.0), nx=10000,
                                              max_orbits=100_000, max_step=1e-4),
        "report": lambda: [body.orbit_nonlinear_stability(o, rtol=1e-13, atol=1e-13)
                           for _ in range(100_000)],
    }
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    t0 = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            calls[form]()
    finally:
        timer.cancel()
    assert time.monotonic() - t0 < 5
