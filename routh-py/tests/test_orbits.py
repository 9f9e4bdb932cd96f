"""Periodic orbits from Python: checked against the pendulum's closed form (the complete
elliptic integral by the arithmetic–geometric mean), against the family's own linear limit,
and by what the figures draw."""

import json
import math

import numpy as np
import pytest

import routh
from conftest import ROOT

PENDULUM = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"


def elliptic_k(m):
    a, g = 1.0, math.sqrt(1.0 - m)
    for _ in range(60):
        a, g = 0.5 * (a + g), math.sqrt(a * g)
    return math.pi / (2.0 * a)


@pytest.fixture
def body():
    """A heavy body J = diag(1, 2, 3), centre of mass on the third axis: swings about e₁ are a
    pendulum with ω₀² = mgl/A = 1.5."""
    return routh.Model(PENDULUM, {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5})


@pytest.fixture
def asymmetric():
    return routh.Model.load(ROOT / "examples" / "models" / "asymmetric_top.toml")


def hanging(m):
    return min(m.steady_motions(0.0), key=lambda s: s.energy)


def test_pendulum_period_is_the_elliptic_integral(body):
    w0 = math.sqrt(1.5)
    for theta0 in (0.3, 1.5, 2.5):
        o = body.periodic_orbit([0, 0, 0], [0, math.sin(theta0), -math.cos(theta0)], 2 * math.pi / w0)
        exact = 4 * elliptic_k(math.sin(theta0 / 2) ** 2) / w0
        assert abs(o.period - exact) < 1e-8 * exact
        assert o.stability in routh.ORBIT_STABILITIES
        assert o.multipliers.dtype == np.complex128 and o.multipliers.shape == (2,)
        assert o.omega0.shape == (3,) and abs(np.linalg.norm(o.gamma0) - 1) < 1e-12
        back = json.loads(o.to_json())
        assert back["period"] == o.period and back["stability"] == o.stability.title().replace("_", "")


def test_lyapunov_family_linear_limit_and_events(asymmetric):
    s = hanging(asymmetric)
    f = asymmetric.lyapunov_family(s, 0, max_orbits=40)
    assert len(f) == len(f.orbits) == f.energy.shape[0] == len(f.stability)
    assert f.energy[0] > s.energy
    kinds = {e.kind for e in f.events}
    assert kinds <= set(routh.ORBIT_EVENT_KINDS)
    assert "period_doubling" in kinds, f.events
    for e in f.events:
        if e.kind == "period_doubling":
            assert abs(e.orbit.stability_index + 1) < 1e-6
            d = asymmetric.period_doubled_family(e, max_orbits=3)
            assert abs(d.orbits[-1].period - 2 * e.orbit.period) < 0.05 * e.orbit.period
            break


def test_family_plot_draws_the_index_and_the_unit_lines(asymmetric):
    import matplotlib

    from routh._plot import index_axis

    matplotlib.use("Agg")
    # The axis is k on [-1, 1] and a decade per unit beyond, as the Rust SVG.
    assert np.allclose(index_axis([-100.0, -10.0, -1.0, 0.3, 1.0, 10.0, 1e4]),
                       [-3.0, -2.0, -1.0, 0.3, 1.0, 2.0, 5.0])
    f = asymmetric.lyapunov_family(hanging(asymmetric), 0, max_orbits=30)
    ax = f.plot()
    ys = np.concatenate([line.get_ydata() for line in ax.get_lines() if len(line.get_xdata()) > 2])
    # The runs draw every orbit's index through the axis map (and nothing else).
    assert np.isclose(ys.max(), index_axis([f.stability_index.max()])[0])
    assert np.isclose(ys.min(), index_axis([f.stability_index.min()])[0])
    assert np.isin(np.round(index_axis(f.stability_index), 12), np.round(ys, 12)).all()
    # The lines k = ±1 (axhline: 2 points), not the event marks on them (period doublings at
    # k = -1, one point each).
    flat = [line for line in ax.get_lines() if len(line.get_xdata()) == 2
            and np.allclose(line.get_ydata(), line.get_ydata()[0])
            and abs(abs(line.get_ydata()[0]) - 1) < 1e-12]
    assert len(flat) == 2  # k = ±1
    assert ax.get_xlabel() == "E" and ax.get_ylabel() == "k"
    ax = f.plot(quantity="period")
    xs = np.concatenate([line.get_xdata() for line in ax.get_lines() if len(line.get_xdata()) > 1])
    assert np.isclose(xs.min(), f.energy.min()) and ax.get_ylabel() == "T"
    with pytest.raises(ValueError):
        f.plot(quantity="nonsense")


def test_poincare_section_and_fixed_points(body):
    import matplotlib

    matplotlib.use("Agg")
    o = body.periodic_orbit([0, 0, 0], [0, math.sin(0.8), -math.cos(0.8)], 5.0)
    fixed = body.orbit_crossings(o, normal=[0, 1, 0])
    assert fixed.shape == (1, 2)
    sec = body.poincare_section(o.p_psi, o.energy, normal=[0, 1, 0], orbits=6, crossings=25)
    assert len(sec.points) == 6 and sec.starts.shape == (6, 6)
    assert all(p.shape[1] == 2 for p in sec.points)
    ax = sec.plot(fixed_points=fixed)
    marks = [line for line in ax.get_lines() if line.get_marker() == "x"]
    assert len(marks) == 1 and np.allclose(marks[0].get_xydata(), fixed)


def test_bad_guesses_raise_routh_errors(body):
    s = hanging(body)
    with pytest.raises(routh.RouthError) as e:
        body.periodic_orbit(s.gamma * s.psi_dot, s.gamma, 3.0)
    assert e.value.kind == "InvalidOption" and "steady motion" in str(e.value)
    with pytest.raises(routh.RouthError):
        body.periodic_orbit([0, 0, 0], [0, 0.1, -1.0], -1.0)
    with pytest.raises(routh.RouthError):
        body.lyapunov_family(s, 2)


@pytest.fixture
def branching():
    """A heavy body J = diag(1, 1.6, 2.3), mgl = 1 (routh-cli/tests/models/branching_body.toml):
    hanging at p_ψ = 0, its mode-0 orbits are planar swings about e₁, which meet a branch point
    at E ≈ 0.2725, where a family of non-planar orbits crosses them."""
    return routh.Model(PENDULUM, {"inertia": [1.0, 1.6, 2.3], "mgl": 1.0})


def off_plane(m, o):
    """The largest |γ₁| and |ω₂|, |ω₃| along one period: 0 on a planar swing about e₁."""
    p = m.orbit_path(o, 200)
    return max(np.abs(p.gamma[:, 0]).max(), np.abs(p.omega[:, 1:]).max())


def test_switch_branch_leaves_the_plane_of_the_swings(branching):
    f = branching.lyapunov_family(hanging(branching), 0, max_orbits=30)
    bps = [e for e in f.events if e.kind == "branch_point"]
    assert len(bps) == 1, f.events
    bp = bps[0]
    assert 0.2 < bp.energy < 0.35
    # The parent's orbits are planar swings.
    assert all(off_plane(branching, o) < 1e-9 for o in f.orbits)
    assert np.abs(f.precession).max() < 1e-9
    g = branching.switch_branch(bp, max_orbits=20)
    assert isinstance(g, routh.OrbitFamily) and len(g) == 20
    # Through the branch point, its energy least there (a pitchfork), at the event's period.
    near = g.orbits[int(np.argmin(g.energy))]
    assert abs(near.energy - bp.energy) < 2e-2
    assert abs(near.period / bp.orbit.period - 1) < 1e-2
    # Away from the branch point the crossing family's orbits leave the plane and precess, both
    # ways (its two halves are mirror images).
    away = [o for o in g.orbits if o.energy > bp.energy + 0.05]
    assert len(away) >= 4
    assert all(off_plane(branching, o) > 1e-2 for o in away)
    assert min(g.precession) < -0.1 and max(g.precession) > 0.1
    for o in g.orbits:
        assert o.body_turn == 0.0 and not o.degenerate and abs(o.p_psi) < 1e-9
    # A closed orbit: the path ends where it starts.
    o = away[0]
    p = branching.orbit_path(o, 50)
    assert np.allclose(p.omega[-1], o.omega0, atol=1e-7) and np.allclose(p.gamma[-1], o.gamma0, atol=1e-7)


def test_switch_branch_refuses_other_events(branching, asymmetric):
    f = asymmetric.lyapunov_family(hanging(asymmetric), 0, max_orbits=40)
    pd = next(e for e in f.events if e.kind == "period_doubling")
    with pytest.raises(routh.RouthError) as e:
        asymmetric.switch_branch(pd)
    assert e.value.kind == "InvalidOption"
    assert "a branch point is needed, got a period_doubling" in str(e.value)
    bp = next(e for e in branching.lyapunov_family(hanging(branching), 0, max_orbits=30).events
              if e.kind == "branch_point")
    with pytest.raises(routh.RouthError) as e:
        branching.period_doubled_family(bp)
    assert e.value.kind == "InvalidOption" and "period doubling is needed" in str(e.value)
    with pytest.raises(TypeError):
        branching.switch_branch(bp.orbit)
    with pytest.raises(routh.RouthError) as e:
        branching.switch_branch(bp, max_orbits=0)
    assert e.value.kind == "InvalidOption"


def test_continue_orbit_in_a_parameter_is_the_pendulum_at_fixed_energy():
    # J = diag(a, 2, 3), mgl = 1.5: at E = −1.5 cos 1 the planar swings are pendulums of
    # amplitude 1 whatever a, ω₀ = √(mgl/a): T(a) = 4K(sin²½)/√(mgl/a) (docs/method.md §11).
    m = routh.Model("kinetic = 0.5 * (a * omega.x * omega.x + 2.0 * omega.y * omega.y"
                    " + 3.0 * omega.z * omega.z), potential = mgl * gamma.z",
                    {"a": 1.0, "mgl": 1.5})
    o = m.periodic_orbit([0, 0, 0], [0, math.sin(1.0), -math.cos(1.0)], 5.6)
    f = m.continue_orbit_in(o, "a", (0.8, 1.5))
    assert isinstance(f, routh.OrbitParameterFamily) and isinstance(f.family, routh.OrbitFamily)
    assert f.name == "a" and f.family.stop is None
    assert f.parameter.dtype == np.float64 and f.parameter.shape == (len(f.family.orbits),)
    assert f.event_parameter.shape == (len(f.family.events),)
    assert len(f) == len(f.family) >= 5
    assert f.parameter.min() == 0.8 and f.parameter.max() == 1.5
    k = 4 * elliptic_k(math.sin(0.5) ** 2)
    for orbit, a in zip(f.family.orbits, f.parameter):
        assert abs(orbit.energy - o.energy) < 1e-9
        assert abs(orbit.period - k / math.sqrt(1.5 / a)) < 1e-8, (a, orbit.period)
    assert "OrbitParameterFamily(a=" in repr(f)
    # Pickles with its name and numbers.
    import pickle

    g = pickle.loads(pickle.dumps(f))
    assert g.name == "a" and g.family.to_json() == f.family.to_json()
    np.testing.assert_array_equal(g.parameter, f.parameter)
    # Through p_ψ ("momentum" is the command line's name): each orbit's p_ψ is its parameter.
    p = m.continue_orbit_in(o, "momentum", (-0.1, 0.1), max_orbits=5)
    assert p.name == "p_psi" and len(p) == 5
    np.testing.assert_allclose([x.p_psi for x in p.family.orbits], p.parameter, atol=1e-9)
    assert all(abs(x.energy - o.energy) < 1e-9 for x in p.family.orbits)


def test_continue_orbit_in_refuses_with_the_rust_message():
    m = routh.Model(PENDULUM, {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5})
    o = m.periodic_orbit([0, 0, 0], [0, math.sin(1.0), -math.cos(1.0)], 5.6)
    with pytest.raises(routh.ModelError, match="unknown parameter `b`"):
        m.continue_orbit_in(o, "b", (1.0, 2.0))
    with pytest.raises(routh.RouthError, match="inertia"):
        m.continue_orbit_in(o, "inertia", (1.0, 2.0))
    # The start (mgl = 1.5, p_ψ = 0) outside the range: the Rust InvalidOption, its message.
    with pytest.raises(routh.RouthError) as e:
        m.continue_orbit_in(o, "mgl", (1.6, 2.0))
    assert e.value.kind == "InvalidOption" and "outside the range" in str(e.value)
    with pytest.raises(routh.RouthError) as e:
        m.continue_orbit_in(o, "p_psi", (0.5, 1.0))
    assert e.value.kind == "InvalidOption"
    with pytest.raises(routh.RouthError) as e:
        m.continue_orbit_in(o, "mgl", (2.0, 1.0))
    assert e.value.kind == "InvalidOption"
    # An orbit of another model (mgl = 2 there) is not one of this one.
    with pytest.raises(routh.RouthError) as e:
        m.with_params(mgl=2.0).continue_orbit_in(o, "mgl", (1.0, 3.0))
    assert e.value.kind == "InvalidOption" and "not an orbit" in str(e.value)
