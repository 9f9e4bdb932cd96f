"""Every field of an analysis's options struct is a keyword, its default written once (in Rust):
the keywords act on what the analysis computes (a family of `max_orbits` orbits, a section of
`orbits` orbits, steps no longer than `h_max`), an unknown keyword names itself, a near one and
the valid ones, a wrong value names its keyword, the library's own checks pass through; and the
stub `__init__.pyi` declares exactly those keywords with those defaults (`routh._options_schema()`)
for exactly the functions that take them."""

import ast
import json
import math
import pathlib
import re

import numpy as np
import pytest

import routh

BODY = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = l * gamma.z"
BODY_B = ("kinetic = 0.5 * (omega.x * omega.x + b * omega.y * omega.y + 3.0 * omega.z * omega.z),"
          " potential = l * gamma.z")
STUB = pathlib.Path(routh.__file__).parent / "__init__.pyi"


@pytest.fixture(scope="module")
def body():
    return routh.Model(BODY, {"inertia": [1.0, 2.0, 3.0], "l": 1.5})


@pytest.fixture(scope="module")
def family(body):
    return body.lyapunov_family(hanging(body), 0, max_orbits=3)


def hanging(m):
    return min(m.steady_motions(0.0), key=lambda s: s.energy)


def test_max_orbits_is_the_number_of_orbits(body, family):
    assert len(family) == 3
    f = body.lyapunov_family(hanging(body), 0, max_orbits=5, rtol=1e-12, atol=1e-13)
    assert len(f) == 5
    # None is the default, as before.
    assert len(body.lyapunov_family(hanging(body), 0, max_orbits=3, max_step=None)) == 3


def test_a_field_that_was_no_keyword_before_acts(body):
    s = hanging(body)
    # max_period_ratio: the family ends once T exceeds that many times its first period.
    f = body.lyapunov_family(s, 0, max_orbits=60, max_period_ratio=1.01)
    assert f.stop is not None and "period" in f.stop, f.stop
    assert f.period.max() <= 1.01 * f.period[0] * (1 + 1e-9) or len(f) < 60
    # h_max bounds the integrator's steps (every recorded step by default).
    tr = body.simulate_full([0.3, 0, 0], [0, 0, -1], 2.0, h_max=0.01)
    assert np.diff(tr.t).max() <= 0.01 + 1e-12
    # method: the Lie–Euler RK4 of fixed step, given as serde writes the enum.
    tr = body.simulate_full([0.3, 0, 0], [0, 0, -1], 1.0, method={"LieRk4": {"step": 0.125}})
    assert np.allclose(np.diff(tr.t), 0.125)


def test_section_sizes_and_the_default(body):
    o = body.periodic_orbit([0, 0, 0], [0, math.sin(0.8), -math.cos(0.8)], 5.0)
    sec = body.poincare_section(o.p_psi, o.energy, orbits=3, crossings=4, normal=(0, 1, 0))
    assert len(sec.points) == 3 and all(p.shape == (4, 2) for p in sec.points)
    assert np.allclose(sec.normal, [0, 1, 0])
    # The default number of orbits is the documented 50.
    assert len(body.poincare_section(o.p_psi, o.energy, crossings=1).points) == 50


def test_an_unknown_keyword_names_itself_a_near_one_and_the_valid_ones(body, family):
    with pytest.raises(TypeError) as e:
        body.lyapunov_family(hanging(body), 0, max_orbit=3)
    msg = str(e.value)
    assert "lyapunov_family()" in msg and "unexpected keyword" in msg
    assert "`max_orbit`" in msg and "did you mean `max_orbits`" in msg
    assert "newton_tol" in msg and "max_period_ratio" in msg
    with pytest.raises(TypeError, match="`colour`"):
        body.orbit_nonlinear_stability(family.orbits[-1], colour="red")
    # The chart sets its families' energy bounds and `nonlinear` itself: no keywords there.
    with pytest.raises(TypeError, match="unexpected keyword argument: unknown option `nonlinear`"):
        body.orbit_chart("l", [0, 0, -1], (1.4, 1.6), (0.0, 1.0), nonlinear=True)


def test_a_wrong_value_names_its_keyword(body):
    s = hanging(body)
    with pytest.raises(TypeError, match="`max_orbits`.*string"):
        body.lyapunov_family(s, 0, max_orbits="many")
    with pytest.raises(TypeError, match="`max_orbits`"):
        body.lyapunov_family(s, 0, max_orbits=2.5)
    with pytest.raises(OverflowError, match="`max_orbits`"):
        body.lyapunov_family(s, 0, max_orbits=-1)
    with pytest.raises(ValueError, match="`energy_bounds`: invalid length 3"):
        body.lyapunov_family(s, 0, energy_bounds=(0, 1, 2))
    with pytest.raises(TypeError, match="complex"):
        body.lyapunov_family(s, 0, rtol=1j)


def test_the_librarys_own_checks_pass_through(body):
    s = hanging(body)
    with pytest.raises(routh.RouthError) as e:
        body.lyapunov_family(s, 0, min_step=1.0)
    assert e.value.kind == "InvalidOption"
    assert "OrbitOptions::min_step: 1 exceeds max_step = 0.1" in str(e.value)
    with pytest.raises(routh.RouthError, match="OrbitOptions::rtol") as e:
        body.lyapunov_family(s, 0, rtol=float("nan"))
    assert e.value.kind == "InvalidOption"


def test_nonlinear_of_a_diagram_and_nested_fields(body):
    top = routh.Model("kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z",
                      {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0})
    d = top.bifurcation_diagram((0.0, 5.0), nonlinear=False, seeds=3)
    assert sorted(e.kind for e in d.events) == ["branch_point", "hamiltonian_hopf"]
    with pytest.raises(TypeError, match="`nonlinear`"):
        top.bifurcation_diagram((0.0, 5.0), nonlinear="yes")
    # A field of a nested struct by its own name, or by its path when two nested structs have it.
    with pytest.raises(TypeError) as e:
        top.bifurcation_diagram((0.0, 5.0), zero_eigenvalue_tol=1e-8)
    assert "classify.zero_eigenvalue_tol" in str(e.value)
    same = top.bifurcation_diagram((0.0, 5.0), steady_tol=1e-7,
                                   **{"classify.zero_eigenvalue_tol": 1e-8})
    assert [e.kind for e in same.events] == [e.kind for e in top.bifurcation_diagram((0.0, 5.0)).events]


# --- the stub against the structs --------------------------------------------------------------


def stub_typed_dicts():
    """{struct: {keyword: default}} of the stub's `class _Struct(TypedDict, total=False)` (or of
    another of them, whose fields it has too), each default written as `# default VALUE` after
    its field."""
    text = STUB.read_text()
    lines = text.splitlines()
    out = {}
    for node in ast.parse(text).body:
        bases = [getattr(b, "id", None) for b in node.bases] if isinstance(node, ast.ClassDef) else []
        if not bases or not all(b == "TypedDict" or b.lstrip("_") in out for b in bases):
            continue
        fields = {}
        for b in bases:
            fields.update(out.get(b.lstrip("_"), {}))
        for b in node.body:
            if isinstance(b, ast.AnnAssign):
                m = re.search(r"#\s*default\s+(.+?)\s*$", lines[b.lineno - 1])
                assert m, f"{node.name}.{b.target.id}: no `# default VALUE` comment"
                fields[b.target.id] = ast.literal_eval(m.group(1))
        out[node.name.lstrip("_")] = fields
    return out


def stub_functions():
    """{"Model.method" or "function": struct} of every stub function with `**options:
    Unpack[_Struct]`."""
    out = {}

    def visit(fn, prefix):
        k = fn.args.kwarg
        if k is not None and isinstance(k.annotation, ast.Subscript):
            if getattr(k.annotation.value, "id", None) == "Unpack":
                out[prefix + fn.name] = k.annotation.slice.id.lstrip("_")

    for node in ast.parse(STUB.read_text()).body:
        if isinstance(node, ast.FunctionDef):
            visit(node, "")
        elif isinstance(node, ast.ClassDef):
            for b in node.body:
                if isinstance(b, ast.FunctionDef):
                    visit(b, node.name + ".")
    return out


def same(a, b):
    if isinstance(a, float) or isinstance(b, float):
        return isinstance(a, (int, float)) and isinstance(b, (int, float)) and a == b
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and a == b


def test_the_stub_declares_every_field_with_its_default():
    schema = routh._options_schema()
    stub = stub_typed_dicts()
    assert set(stub_functions().values()) == set(schema), "a TypedDict per options struct"
    for name, fields in schema.items():
        # A key by its path only ("classify.zero_eigenvalue_tol") is not a Python identifier.
        fields = {k: v for k, v in fields.items() if "." not in k}
        assert sorted(stub[name]) == sorted(fields), (name, sorted(stub[name]), sorted(fields))
        for k, v in fields.items():
            assert same(stub[name][k], v), (name, k, stub[name][k], v)


def test_each_function_takes_the_keywords_its_stub_names(body, family):
    schema = routh._options_schema()
    o = family.orbits[-1]
    event = routh.OrbitEvent.from_json(json.dumps({
        "kind": "PeriodDoubling", "energy": o.energy, "orbit": json.loads(o.to_json()),
        "before": "Elliptic", "after": "InverseHyperbolic"}))
    b = routh.Model(BODY_B, {"b": 2.0, "l": 1.5})
    s = hanging(body)
    calls = {
        "Model.periodic_orbit": lambda **k: body.periodic_orbit([0, 0, 0], [0, 0, -1], 1.0, **k),
        "Model.lyapunov_family": lambda **k: body.lyapunov_family(s, 0, **k),
        "Model.continue_orbit": lambda **k: body.continue_orbit(o, (-1.5, -1.0), **k),
        "Model.continue_orbit_in": lambda **k: body.continue_orbit_in(o, "l", (1.0, 2.0), **k),
        "Model.period_doubled_family": lambda **k: body.period_doubled_family(event, **k),
        "Model.switch_branch": lambda **k: body.switch_branch(event, **k),
        "Model.poincare_section": lambda **k: body.poincare_section(0.0, -1.0, **k),
        "Model.orbit_crossings": lambda **k: body.orbit_crossings(o, **k),
        "Model.orbit_nonlinear_stability": lambda **k: body.orbit_nonlinear_stability(o, **k),
        "Model.orbit_chart": lambda **k: b.orbit_chart("b", [0, 0, -1], (1.9, 2.1), (0, 1), **k),
        "orbit_chart": lambda **k: routh.orbit_chart(b, [0, 0, -1], (1.9, 2.1), (0, 1),
                                                     parameter="b", **k),
        "Model.nonlinear_stability": lambda **k: body.nonlinear_stability(s, **k),
        "Model.bifurcation_diagram": lambda **k: body.bifurcation_diagram((0, 1), **k),
        "bifurcation_diagram": lambda **k: routh.bifurcation_diagram(lambda p: (body, p), (0, 1),
                                                                     **k),
        "stability_atlas": lambda **k: routh.stability_atlas(lambda x, y: (body, y), [0, 0, -1],
                                                             (0, 1), (0, 1), **k),
        "Model.simulate_full": lambda **k: body.simulate_full([0, 0, 0], [0, 0, -1], 1.0, **k),
        "Model.simulate": lambda **k: body.simulate([0, 0, 0], [0, 0, -1], 1.0, **k),
        "Model.simulate_reduced": lambda **k: body.simulate_reduced([0, 0, 0], [0, 0, -1], 0.0,
                                                                    1.0, **k),
    }
    functions = stub_functions()
    assert sorted(functions) == sorted(calls), "a stub function with **options untested, or gone"
    for fn, struct in functions.items():
        with pytest.raises(TypeError) as e:
            calls[fn](zzz_not_an_option=1)
        listed = str(e.value).split("the options are ", 1)[1].split(", ")
        assert listed == list(schema[struct]), (fn, struct)
