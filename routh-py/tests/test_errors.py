"""Errors are Python exceptions; nothing panics across the boundary."""

import subprocess
import sys

import numpy as np
import pytest

import routh
from conftest import TOP_TEXT


def test_model_error_has_line_and_column():
    text = "kinetic = 0.5 * omega.dot(inertia * omega),\n    potential = mas * g * gamma.z"
    with pytest.raises(routh.ModelError) as info:
        routh.Model(text, {"inertia": np.eye(3), "mass": 1.0, "g": 9.81})
    e = info.value
    assert (e.line, e.column) == (2, 17)
    assert "mas" in str(e)
    assert isinstance(e, routh.RouthError)


def test_bad_parameter_shapes(top):
    with pytest.raises(routh.ModelError):
        routh.Model(TOP_TEXT, {"inertia": [1.0, 2.0], "mgl": 1.0})
    with pytest.raises(routh.ModelError):
        top.set("mgl", [1.0, 2.0, 3.0])  # a scalar parameter given a vector
    with pytest.raises(routh.ModelError):
        top.set("nope", 1.0)
    with pytest.raises(routh.ModelError):
        routh.Model.load("/nonexistent/model.toml")
    with pytest.raises(routh.ModelError):
        routh.Model.from_toml("[model]\nlagrangian = 3\n")


def test_routh_errors_carry_the_message(top):
    with pytest.raises(routh.RouthError, match="non-finite"):
        top.steady_motions(float("nan"))
    with pytest.raises(routh.RouthError):
        top.simulate([0, 0, 1], [0, 0, 2.0], 1.0)  # |γ₀| ≠ 1
    with pytest.raises(routh.RouthError):
        top.simulate([0, 0, 1], [0, 0, 1.0], 1.0, rtol=-1.0)
    with pytest.raises(routh.RouthError):
        top.simulate([0, 0], [0, 0, 1.0], 1.0)
    with pytest.raises(routh.RouthError):
        top.bifurcation_diagram((1.0, float("inf")))


def test_family_exception_propagates(top):
    class Boom(Exception):
        pass

    def family(s):
        if s > 1.0:
            raise Boom("from the family")
        return top, s

    with pytest.raises(Boom, match="from the family"):
        routh.bifurcation_diagram(family, (0.0, 5.0))
    with pytest.raises(TypeError):
        routh.bifurcation_diagram(lambda s: 3.0, (0.0, 5.0))

    def family2(x, y):
        raise KeyError("atlas")

    with pytest.raises(KeyError):
        routh.stability_atlas(family2, [0, 0, 1], (0, 1), (0, 1), nx=3, ny=3)


NASTY = r'''
import numpy as np, routh
m = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
                {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
inf, nan = float("inf"), float("nan")
calls = [
    lambda: m.steady_motions(inf), lambda: m.steady_motions(1e308),
    lambda: m.simulate([1e300, 0, 0], [0, 0, 1], 1.0), lambda: m.simulate([0, 0, 1], [0, 0, 0], 1.0),
    lambda: m.simulate([0, 0, 1], [0, 0, 1], -1.0), lambda: m.simulate([0, 0, 1], [0, 0, 1], nan),
    lambda: m.simulate_reduced([0, 0, 0], [0, 0, 1], nan, 1.0),
    lambda: m.bifurcation_diagram((5.0, 0.0)), lambda: m.bifurcation_diagram((0.0, 0.0)),
    lambda: m.bifurcation_diagram((0.0, 1.0), max_steps=0, initial_step=-1.0),
    lambda: routh.stability_atlas(lambda x, y: (m, y), [0, 0, 1], (0, 1), (0, 1), nx=0, ny=0),
    lambda: routh.Model("", {}), lambda: routh.Model("kinetic = ", {}),
    lambda: routh.Model("kinetic = 0.5 * omega.dot(omega) / 0", {}),
    lambda: m.with_params(mgl=nan).steady_motions(1.0),
    lambda: m.certify(nan),
]
for c in calls:
    try:
        c()
    except (routh.RouthError, ValueError, TypeError, OverflowError):
        pass
print("survived")
'''


def test_no_panic_aborts_the_interpreter():
    r = subprocess.run([sys.executable, "-c", NASTY], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert "survived" in r.stdout
    assert "panicked" not in r.stderr
