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
    lambda: routh.stability_atlas(lambda x, y: (m, y), [0, 0, 1], (0, 1), (0, 1), nx=2**32, ny=2**32),
    lambda: routh.stability_atlas(lambda x, y: (m, y), [0, 0, 1], (0, 1), (0, 1), nx=2**62, ny=2**62),
    lambda: m.simulate([0, 0, 1], [0, 0, 1], 1.0, times=[]),
    lambda: m.simulate([0, 0, 1], [0, 0, 1], 1.0, attitude=True, times=[1.0, 0.5]),
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


INF, NAN = float("inf"), float("nan")

# Inputs that must raise routh.RouthError in-process: a panic would surface as
# pyo3_runtime.PanicException (a BaseException, not caught here), an abort would kill pytest.
HOSTILE = {
    "p_psi NaN": lambda m: m.steady_motions(NAN),
    "p_psi -inf": lambda m: m.steady_motions(-INF),
    "classify NaN model": lambda m: m.with_params(mgl=NAN).steady_motions(1.0),
    "diagram inverted": lambda m: m.bifurcation_diagram((5.0, 0.0)),
    "diagram empty range": lambda m: m.bifurcation_diagram((1.0, 1.0)),
    "diagram NaN range": lambda m: m.bifurcation_diagram((NAN, 1.0)),
    "diagram zero step": lambda m: m.bifurcation_diagram((0.0, 1.0), initial_step=0.0),
    "diagram NaN options": lambda m: m.bifurcation_diagram((0.0, 1.0), max_step=NAN,
                                                           newton_tol=NAN),
    "family inverted": lambda m: routh.bifurcation_diagram(lambda s: (m, s), (2.0, 1.0)),
    # nx·ny overflowed usize (a panic) or asked for 32 GiB (an abort) before the cap.
    "atlas overflowing grid": lambda m: routh.stability_atlas(
        lambda x, y: (m, y), [0, 0, 1], (0, 1), (0, 1), nx=2**62, ny=2**62),
    "atlas huge grid": lambda m: routh.stability_atlas(
        lambda x, y: (m, y), [0, 0, 1], (0, 1), (0, 1), nx=2**32, ny=2**32),
    "atlas empty grid": lambda m: routh.stability_atlas(
        lambda x, y: (m, y), [0, 0, 1], (0, 1), (0, 1), nx=0, ny=0),
    "atlas inverted": lambda m: routh.stability_atlas(
        lambda x, y: (m, y), [0, 0, 1], (1, 0), (1, 0), nx=3, ny=3),
    "atlas NaN guess": lambda m: routh.stability_atlas(
        lambda x, y: (m, y), [NAN, 0, 1], (0, 1), (0, 1), nx=3, ny=3),
    "simulate zero budget": lambda m: m.simulate([0, 0, 1], [0, 0, 1], 1.0, max_steps=0),
    "simulate small budget": lambda m: m.simulate([0, 1, 1], [0.6, 0, 0.8], 1e300,
                                                  max_steps=1000),
    "simulate NaN": lambda m: m.simulate([NAN, 0, 1], [0, 0, 1], 1.0),
    "simulate inf time": lambda m: m.simulate([0, 0, 1], [0, 0, 1], INF, attitude=True),
    "simulate times past end": lambda m: m.simulate([0, 0, 1], [0, 0, 1], 1.0, times=[0, 2.0]),
    "simulate NaN times": lambda m: m.simulate([0, 0, 1], [0, 0, 1], 1.0, times=[NAN]),
    "reduced zero gamma": lambda m: m.simulate_reduced([0, 0, 0], [0, 0, 0], 1.0, 1.0),
    "certify inf": lambda m: m.certify(INF),
    "certify zero split": lambda m: m.certify(2.2, initial_split=0),
    "certify huge split": lambda m: m.certify(2.2, initial_split=2**40),
    "certify NaN width": lambda m: m.certify(2.2, min_width=NAN),
    # Below what the chart's floating-point resolution can split.
    "certify tiny width": lambda m: m.certify(2.2, min_width=1e-300),
    "empty model": lambda m: routh.Model("", {}),
    "empty toml": lambda m: routh.Model.from_toml(""),
    "binary toml": lambda m: routh.Model.from_toml("[[[ \x00"),
    "zero inertia": lambda m: m.with_params(inertia=[0.0, 0.0, 0.0]).steady_motions(1.0),
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_inputs_raise_routh_errors(top, name):
    with pytest.raises(routh.RouthError):
        HOSTILE[name](top)


def test_huge_budgets_are_fine(top):
    # Budgets far beyond need are accepted and do not allocate up front.
    d = top.bifurcation_diagram((0.0, 5.0), max_steps=2**64 - 1, max_branches=2**64 - 1)
    assert len(d.events) == 2
    tr = top.simulate([0, 0, 1], [0, 0, 1], 1.0, max_steps=2**64 - 1)
    assert tr.t[-1] == 1.0
    with pytest.raises(OverflowError):
        top.simulate([0, 0, 1], [0, 0, 1], 1.0, max_steps=2**64)
    with pytest.raises(OverflowError):
        top.simulate([0, 0, 1], [0, 0, 1], 1.0, max_steps=-1)


def test_amended_potential_refuses_what_has_no_value(top):
    # U_r = mgl γ₃ + p²/(2 γᵀJγ): at γ = 0 the denominator vanishes.
    with pytest.raises(routh.RouthError) as info:
        top.amended_potential([0.0, 0.0, 0.0], 2.0)
    assert info.value.kind == "NonUnitGamma"
    # As simulate: a γ off the unit sphere is refused, with the same tolerance.
    for g in ([0.0, 0.0, 2.0], [0.0, 0.6, 0.7]):
        with pytest.raises(routh.RouthError) as info:
            top.amended_potential(g, 2.0)
        assert info.value.kind == "NonUnitGamma"
        with pytest.raises(routh.RouthError) as info:
            top.simulate([0, 0, 1], g, 1.0)
        assert info.value.kind == "NonUnitGamma"
    assert top.amended_potential([0.0, 0.0, 1.0 + 1e-9], 2.0) == pytest.approx(2.6)
    for gamma, p in [([float("nan"), 0.0, 1.0], 2.0), ([0.0, 0.0, 1.0], float("inf"))]:
        with pytest.raises(routh.RouthError) as info:
            top.amended_potential(gamma, p)
        assert info.value.kind == "NonFinite"


def test_nan_and_infinite_parameters_are_refused_naming_them(top):
    # Model(...): a ModelError at the parameter's use in the text, naming it.
    with pytest.raises(routh.ModelError) as info:
        routh.Model(TOP_TEXT, {"inertia": [1.0, 1.0, 1.25], "mgl": NAN})
    e = info.value
    assert "parameter `mgl` is NaN" in e.message
    assert e.line is not None and e.column is not None
    # set / with_params: no place in a text, so line and column are None.
    for call in (lambda: top.set("mgl", INF), lambda: top.with_params(inertia=[1.0, NAN, 1.0])):
        with pytest.raises(routh.ModelError) as info:
            call()
        e = info.value
        assert e.line is None and e.column is None
        assert "parameter `" in e.message and ("mgl" in e.message or "inertia" in e.message)
    assert top.get_param("mgl") == 1.0
    # TOML: at the value in the file.
    with pytest.raises(routh.ModelError) as info:
        routh.Model.from_toml('[model]\nlagrangian = "kinetic = 0.5 * omega.dot(omega), '
                              'potential = m * gamma.z"\n[parameters]\nm = inf\n')
    assert (info.value.line, info.value.column) == (4, 5)
    assert "`m` is infinite" in info.value.message


def test_set_errors_speak_python_and_have_no_position(top):
    with pytest.raises(routh.ModelError) as info:
        top.set("inertia", 2.0)
    e = info.value
    assert "Vector3" not in str(e) and "f64" not in str(e), str(e)
    assert "3-vector" in e.message and "number" in e.message
    assert e.line is None and e.column is None
    with pytest.raises(TypeError):
        top.set("mgl", True)
    with pytest.raises(TypeError):
        top.set("mgl", 1 + 2j)


HUGE = r'''
import threading, routh
kinetic = "kinetic = 0.5 * omega.dot(omega),\npotential = "
results = []
def build(text):
    try:
        routh.Model(text, {})
        results.append("ok")
    except routh.ModelError as e:
        results.append(f"err {e.line}:{e.column}")
build(kinetic + "-" * 7000 + "gamma.z")
build(kinetic + " + ".join(f"{k % 7}.5 * gamma.z" for k in range(50000)))
t = threading.Thread(target=build, args=(kinetic + " + ".join("gamma.x" for _ in range(50000)),))
t.start(); t.join()
print(results)
'''


def test_deep_and_long_texts_never_kill_the_interpreter():
    """7000 signs are refused with a position; a flat sum of 50 000 terms builds, also from a
    Python thread (these once killed the interpreter with SIGSEGV)."""
    r = subprocess.run([sys.executable, "-c", HUGE], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "['err 2:77', 'ok', 'ok']", r.stdout


def test_bool_and_complex_are_not_numbers(top):
    for bad in (True, 1 + 0j):
        with pytest.raises(TypeError):
            top.set("mgl", bad)
        with pytest.raises(TypeError):
            top.simulate([0, 0, bad], [0, 0, 1], 1.0)
        with pytest.raises(TypeError):
            top.with_params(inertia=[1.0, bad, 1.0])
    with pytest.raises(TypeError):
        top.steady_motions(1 + 2j)


def test_bool_is_not_a_real_argument(top):
    for call in (lambda: top.steady_motions(True), lambda: top.certify(False),
                 lambda: top.amended_potential([0, 0, 1], True),
                 lambda: top.simulate([0, 0, 1], [0, 0, 1], True),
                 lambda: top.bifurcation_diagram((False, 5.0)),
                 lambda: routh.stability_atlas(lambda x, y: (top, y), [0, 0, 1], (0, True),
                                               (0, 1), nx=3, ny=3)):
        with pytest.raises(TypeError):
            call()
    assert len(top.steady_motions(2)) >= 2  # an int is a number
