"""Models and every result class pickle (and copy/deepcopy): equal numbers after the trip."""

import copy
import math
import pickle

import numpy as np
import pytest

import routh
from conftest import ROOT


def same(a, b, path="x"):
    """`a` and `b` are equal field by field (arrays bit for bit, NaN equal to NaN)."""
    assert type(a) is type(b), (path, type(a), type(b))
    if isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape, path
        np.testing.assert_array_equal(a, b, err_msg=path)
    elif isinstance(a, (list, tuple)):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(a, dict):
        assert a.keys() == b.keys(), path
        for k in a:
            same(a[k], b[k], f"{path}[{k!r}]")
    elif isinstance(a, float) and math.isnan(a):
        assert math.isnan(b), path
    elif type(a).__module__ == "routh":
        names = [n for n in dir(a) if not n.startswith("_")]
        assert names, path
        for n in names:
            x, y = getattr(a, n), getattr(b, n)
            if callable(x):
                continue
            same(x, y, f"{path}.{n}")
        if hasattr(a, "to_json"):
            assert a.to_json() == b.to_json(), path
    else:
        assert a == b, (path, a, b)


def trips(obj):
    """`obj` after pickle (every protocol), copy and deepcopy, each equal to it."""
    outs = [pickle.loads(pickle.dumps(obj, protocol=p)) for p in range(2, pickle.HIGHEST_PROTOCOL + 1)]
    outs += [copy.copy(obj), copy.deepcopy(obj)]
    for o in outs:
        assert o is not obj
        same(obj, o)
    return outs


def motions_equal(m1, m2, p):
    a, b = m1.steady_motions(p), m2.steady_motions(p)
    same(a, b)
    for x, y in zip(a, b):
        same(m1.classify(x), m2.classify(y))


def test_model_pickles_with_text_parameters_and_symbols(top, gyrostat):
    for model in (top, gyrostat, top.with_params(mgl=2.5)):
        for back in [pickle.loads(pickle.dumps(model)), copy.copy(model), copy.deepcopy(model)]:
            assert back.lagrangian == model.lagrangian
            same(back.parameters, model.parameters)
            assert back.latex_symbols == model.latex_symbols
            assert back.latex().as_dict() == model.latex().as_dict()
            motions_equal(model, back, 2.2)
    assert gyrostat.latex_symbols  # the TOML's [latex] table came through


def test_a_model_from_toml_pickles():
    m = routh.Model.load(ROOT / "examples" / "models" / "asymmetric_top.toml")
    back = pickle.loads(pickle.dumps(m))
    same(back.parameters, m.parameters)
    motions_equal(m, back, 0.5)


def test_unpickled_models_are_independent(top):
    a = pickle.loads(pickle.dumps(top))
    b = pickle.loads(pickle.dumps(top))  # the same compiled model, cached in this process
    a.set("mgl", 3.0)
    assert b.get_param("mgl") == 1.0 and top.get_param("mgl") == 1.0
    assert a.amended_potential([0, 0, 1], 2.0) == pytest.approx(2.0**2 / 2.5 + 3.0)
    assert b.amended_potential([0, 0, 1], 2.0) == pytest.approx(2.0**2 / 2.5 + 1.0)


def test_steady_motions_and_reports_pickle(top):
    motions = top.steady_motions(3.0)
    for m in motions:
        trips(m)
        trips(top.classify(m))
    circle = [m for m in motions if not m.isolated][0]
    trips(top.classify_circle(circle, (0.0, 0.0, 1.0)))
    sleeping = top.steady_motions(2.2)[0]
    trips(top.nonlinear_stability(sleeping))
    unstable = [m for m in top.steady_motions(1.0) if abs(m.gamma[2] - 1) < 1e-9][0]
    r = top.nonlinear_stability(unstable)  # NaN frequencies survive the trip
    trips(r)
    trips(top.certify(2.2))
    trips(top.latex())


def test_diagrams_and_atlases_pickle(top):
    d = top.bifurcation_diagram((0.0, 5.0))
    assert d.events and d.branches
    trips(d)
    trips(d.branches[0])
    trips(d.events[0])
    a = routh.stability_atlas(
        lambda mgl, p: (top.with_params(mgl=mgl), p), [0, 0, 1], (0.5, 2.0), (0.5, 5.0), nx=9, ny=9
    )
    assert a.boundaries
    trips(a)
    trips(a.boundaries[0])


def test_trajectories_pickle(top):
    tr = top.simulate([0, 0.3, 5.0], [0.6, 0, 0.8], 1.0, attitude=True)
    for back in trips(tr):
        same(back.euler_angles(), tr.euler_angles())
    trips(top.simulate([0, 0.3, 5.0], [0.6, 0, 0.8], 1.0))
    red = top.simulate_reduced([0, 0.3, 0], [0.6, 0, 0.8], 3.0, 1.0, attitude=True)
    for back in trips(red):
        same(back.euler_angles(), red.euler_angles())
    trips(top.simulate_reduced([0, 0.3, 0], [0.6, 0, 0.8], 3.0, 1.0))


def test_periodic_orbits_pickle():
    body = routh.Model(
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
        {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5},
    )
    o = body.periodic_orbit([0, 0, 0], [0, math.sin(0.5), -math.cos(0.5)], 2 * math.pi / math.sqrt(1.5))
    trips(o)
    s = body.poincare_section(o.p_psi, o.energy, normal=[0, 1, 0], orbits=3, crossings=5)
    trips(s)
    asym = routh.Model.load(ROOT / "examples" / "models" / "asymmetric_top.toml")
    hanging = min(asym.steady_motions(0.0), key=lambda s: s.energy)
    f = asym.lyapunov_family(hanging, 0, max_orbits=40)
    assert f.events
    trips(f)
    trips(f.events[0])
    # A nutation of the Lagrange top: degenerate, with its turn Δφ about the axis.
    top = routh.Model(
        "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
        {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0},
    )
    n = top.periodic_orbit([0.3, 0, 3.0], [0, math.sin(0.5), math.cos(0.5)], 2.0)
    assert n.degenerate and abs(n.body_turn) > 0.1
    for back in (pickle.loads(pickle.dumps(n)), copy.deepcopy(n)):
        assert back.body_turn == n.body_turn and back.degenerate is True
    trips(n)


def test_a_state_not_made_by_reduce_is_refused():
    with pytest.raises(routh.RouthError):
        routh._restore("NoSuchClass", ())
