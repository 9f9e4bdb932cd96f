"""Nonlinear stability from Python, against the normal form of the sleeping Lagrange top derived
by hand (docs/method.md §10.8), and the nonlinear events of a diagram."""

import math

import numpy as np
import pytest

import routh

TEXT = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z"


def by_hand(a, c, g, p):
    """(c20, c11, c02), (w1, w2), s1*s2, D of the sleeping top (method.md §10.8)."""
    d = math.sqrt(p * p - 4 * a * g)
    a1 = (p * p + 2 * a * g) / (12 * a * d * d)
    a2 = p / (4 * a * d)
    a3 = (3 * a - 2 * c) / (6 * a * c)
    cs = (a1 + a2 + a3, 4 * a1 - 2 * a3, a1 - a2 + a3)
    lam = (2 * a - c) / c
    w1, sigma2 = (lam * p + d) / (2 * a), (d - lam * p) / (2 * a)
    w2, s12 = abs(sigma2), math.copysign(1.0, sigma2)
    D = cs[0] * w2 * w2 - s12 * cs[1] * w1 * w2 + cs[2] * w1 * w1
    return cs, (w1, w2), s12, D


def sleeping(model, p):
    ms = [m for m in model.steady_motions(p) if abs(m.gamma[2] - 1) < 1e-9]
    assert len(ms) == 1
    return ms[0]


@pytest.mark.parametrize("a, c, g, p", [(1.0, 0.8, 1.0, 3.0), (2.0, 1.2, 0.7, 2.6)])
def test_sleeping_top_matches_the_hand_normal_form(a, c, g, p):
    top = routh.Model(TEXT, {"inertia": [a, a, c], "l": g})
    r = top.nonlinear_stability(sleeping(top, p))
    cs, w, s12, D = by_hand(a, c, g, p)
    assert r.linear.verdict == "gyroscopically_stabilized"
    assert r.normal_form.shape == (3,) and r.frequencies.shape == (3 - 1,)
    np.testing.assert_allclose(r.normal_form, cs, rtol=0, atol=1e-8 * max(map(abs, cs)))
    np.testing.assert_allclose(r.frequencies, w, rtol=1e-8)
    assert r.krein_signs[0] * r.krein_signs[1] == s12
    scale = abs(cs[0]) * w[1] ** 2 + abs(cs[1]) * w[0] * w[1] + abs(cs[2]) * w[0] ** 2
    assert abs(r.arnold_determinant - D) <= 1e-8 * scale
    assert r.verdict == "lyapunov_stable" and r.resonance is None
    assert r.verdict in routh.NONLINEAR_VERDICTS
    assert "NonlinearReport(verdict='lyapunov_stable'" in repr(r)


def test_resonance_is_named():
    # A = 1, C = 0.8, mgl = 1: ω₁ = 2ω₂ at p² = 16/3 (the 1:2 resonance of method.md §10.8).
    top = routh.Model(TEXT, {"inertia": [1.0, 1.0, 0.8], "l": 1.0})
    r = top.nonlinear_stability(sleeping(top, math.sqrt(16 / 3)))
    assert r.resonance == "1:2"
    np.testing.assert_allclose(r.normal_form, (1.25, 1.25, 0.25), rtol=1e-8)


def test_diagram_reports_the_resonance_event_only_when_asked():
    top = routh.Model(TEXT, {"inertia": [1.0, 1.0, 0.8], "l": 1.0})
    plain = top.bifurcation_diagram((2.1, 3.0))
    assert all(e.nonlinear is None and e.resonance is None for e in plain.events)
    d = top.bifurcation_diagram((2.1, 3.0), nonlinear=True)
    res = [e for e in d.events if e.kind == "resonance" and e.resonance == "1:2"]
    assert res, d.events
    assert any(abs(e.s - math.sqrt(16 / 3)) < 1e-8 for e in res)
    for e in res:
        assert len(e.nonlinear) == 3
        assert all(v in routh.NONLINEAR_VERDICTS for v in e.nonlinear)


def test_bad_tolerance_raises_routh_error(top):
    m = top.steady_motions(3.0)[0]
    with pytest.raises(routh.RouthError):
        top.nonlinear_stability(m, resonance_tol=-1.0)
