"""Hostile inputs of the formulas, `formula_values`, the family plot and `from_json` (issue 43):
one table, `CASES`, of an input and what must come of it, driven by one parametrised test.

The formulas are checked against something independent of their text: SymPy's expressions,
with each parameter's value put in by the name the user gave it, are evaluated at random states
and compared with the model's generated code (`Model.formula_values`)."""

import ast
import json
import math
import pathlib
import subprocess
import tempfile

import numpy as np
import pytest

import routh
from test_cli_json import routh_bin

sympy = pytest.importorskip("sympy")

# A body with functions in its potential, so that a parameter named like one of them (`sin`,
# `sqrt`, `Abs`) meets the function in the same formula.
KINETIC = "kinetic = 0.5 * omega.dot(diag(inertia) * omega)"
FUNCTIONS = "0.25 * gamma.x.sin() + (2.0 + gamma.y).sqrt() + 0.1 * gamma.y.abs() + gamma.x.exp()"
INERTIA = [1.0, 2.0, 3.0]


def body(names, extra=""):
    """The body B (inertia (1, 2, 3)) with the potential Σ (name · γ₃) + FUNCTIONS + extra, each
    scalar parameter `name` = 1.5 + its place / 10."""
    potential = " + ".join(f"{n} * gamma.z" for n in names) + " + " + FUNCTIONS + extra
    params = {"inertia": INERTIA}
    params.update({n: 1.5 + i / 10 for i, n in enumerate(names)})
    return routh.Model(f"{KINETIC}, potential = {potential}", params)


def values_by_name(model, renamed=()):
    """SymPy name → value of every parameter: a scalar by the user's name, a vector `v` as
    `v_1 … v_3`; `renamed` the (usual name, name expected instead) of the names that clash."""
    out = {}
    for name, value in model.parameters.items():
        a = np.asarray(value, dtype=float)
        if a.ndim == 0:
            out[name] = float(a)
        else:
            for i in range(3):
                out[f"{name}_{i + 1}"] = float(a[i])
    for usual, instead in renamed:
        out[instead] = out.pop(usual)
    return out


def evaluate(expr, values):
    subs = {s: sympy.Float(values[s.name], 30) for s in expr.free_symbols}
    if isinstance(expr, sympy.MatrixBase):
        return np.array(expr.xreplace(subs).evalf(30).tolist(), dtype=float)
    return float(expr.xreplace(subs).evalf(30))


def agree(model, exprs, renamed=(), points=3):
    """The SymPy expressions `exprs` (dict field → expression) equal the generated code's values
    at random states, each symbol read by its name (the parameters' as `values_by_name`)."""
    rng = np.random.default_rng(43)
    params = values_by_name(model, renamed)
    for _ in range(points):
        gamma = rng.normal(size=3)
        gamma /= np.linalg.norm(gamma)
        omega = rng.uniform(-2, 2, size=3)
        p_psi = float(rng.uniform(-3, 3))
        want = model.formula_values(omega, gamma, p_psi)
        values = dict(params, p_psi=p_psi)
        for i in range(3):
            values[f"omega{i + 1}"] = values[f"Omega{i + 1}"] = omega[i]
            values[f"gamma{i + 1}"] = gamma[i]
        for field, expr in exprs.items():
            got = np.asarray(evaluate(expr, values))
            w = np.asarray(want[field], dtype=float)
            scale = max(1.0, float(np.max(np.abs(w))))
            assert np.all(np.abs(got - w) <= 1e-9 * scale), (field, got, w)
    return True


def round_trip(names, renamed=()):
    """`to_sympy()` of the body with parameters `names` agrees with its generated code, and each
    parameter's symbol carries the user's name (or the one in `renamed`)."""
    model = body(names)
    exprs = model.to_sympy()
    got = {s.name for e in exprs.values() for s in e.free_symbols}
    want = set(values_by_name(model, renamed)) - {"inertia_1", "inertia_2", "inertia_3"}
    assert want <= got, (want, got)
    return agree(model, exprs, renamed)


def cli_script(names):
    """`routh formulas FILE --sympy` of the body is a Python script (ast.parse) that, run, binds
    the seven formulas, which agree with the generated code."""
    exe = routh_bin()
    if exe is None:
        pytest.skip("no routh binary (set ROUTH_BIN)")
    model = body(names)
    toml = pathlib.Path(tempfile.mkdtemp()) / "hostile.toml"
    params = "\n".join(f"{n} = {v!r}" for n, v in model.parameters.items()
                       if n != "inertia")
    potential = " + ".join(f"{n} * gamma.z" for n in names) + " + " + FUNCTIONS
    toml.write_text(f'[model]\nlagrangian = """{KINETIC}, potential = {potential}"""\n'
                    f"[parameters]\ninertia = {INERTIA}\n{params}\n")
    out = subprocess.run([exe, "formulas", str(toml), "--sympy"], capture_output=True,
                         text=True, check=True).stdout
    ast.parse(out)
    ns = {}
    exec(compile(out, "formulas.py", "exec"), ns)
    # The formulas under their names, `_` appended where a parameter has the name.
    fields = {}
    for field in ("lagrangian", "psi_dot", "routhian", "amended_potential", "a", "g", "c"):
        key = field + "_" * (field in model.parameters)
        fields[field] = ns[key]
    return agree(model, fields)


def long_sum(n):
    """A potential of `n` terms c_k γ₃ + c_k² γ₁: to_sympy reads it (Python's parser, and so
    `sympify`, gives up at about a thousand) and it agrees with the generated code."""
    terms = " + ".join(f"c{k} * gamma.z + c{k} * c{k} * gamma.x" for k in range(n))
    params = {"inertia": INERTIA}
    params.update({f"c{k}": 1.0 + k / n for k in range(n)})
    model = routh.Model(f"{KINETIC}, potential = {terms}", params)
    exprs = model.to_sympy()
    # The long sums themselves (L, U_r); the matrices hold the same sums, checked in short.
    return agree(model, {f: exprs[f] for f in ("lagrangian", "amended_potential")}, points=1)


B = routh.Model(f"{KINETIC}, potential = mgl * gamma.z", {"inertia": INERTIA, "mgl": 1.5})
UP = [0.0, 0.0, 1.0]
NAN = float("nan")


def formula_values(omega, gamma, p_psi):
    return B.formula_values(omega, gamma, p_psi)


def family_doc():
    """The JSON document of a short family of B's periodic orbits."""
    o = B.periodic_orbit([0, 0, 0], [0, math.sin(0.5), -math.cos(0.5)], 6.0)
    return json.loads(B.continue_orbit(o, (o.energy - 0.05, o.energy + 0.05),
                                       max_orbits=6).to_json())


def plot_family(k):
    """OrbitFamily.plot() of a family whose orbits have stability index `k` (all but the first,
    read back from JSON): the axis of k has at most a dozen finite ticks, labelled without
    overflow, the top one naming the decade of the largest finite |k|."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    doc = family_doc()
    for orbit in doc["orbits"][1:]:
        orbit["stability_index"] = k
    family = routh.OrbitFamily.from_json(json.dumps(doc))
    fig, ax = plt.subplots()
    try:
        family.plot(ax=ax)
        fig.canvas.draw()
        ticks = ax.get_yticks()
        labels = [t.get_text() for t in ax.get_yticklabels()]
    finally:
        plt.close(fig)
    assert 3 <= len(ticks) <= 14 and np.all(np.isfinite(ticks)), ticks
    assert all(lab and len(lab) <= 7 for lab in labels), labels
    return labels


def section_doc():
    e = B.amended_potential([0, math.sin(0.5), -math.cos(0.5)], 1.0) + 0.1
    return json.loads(B.poincare_section(1.0, e, orbits=2).to_json())


def atlas_doc():
    a = routh.stability_atlas(lambda mgl, p: (B.with_params(mgl=mgl), p), UP, (0.5, 2.0),
                              (0.5, 5.0), nx=3, ny=4)
    return json.loads(a.to_json())


def edited(doc, edit):
    edit(doc)
    return json.dumps(doc)


def orbit_doc():
    return json.loads(B.periodic_orbit([0, 0, 0], [0, math.sin(0.5), -math.cos(0.5)],
                                       6.0).to_json())


def orbit_with(**fields):
    return routh.PeriodicOrbit.from_json(edited(orbit_doc(), lambda d: d.update(fields)))


def bare_orbit_with(**fields):
    def edit(d):
        d.update(fields)
        del d["routh"], d["format"]

    return routh.PeriodicOrbit.from_json(edited(orbit_doc(), edit))


def family_with_nan():
    def edit(d):
        d["orbits"][2]["amplitude"] = "NaN"
        d["orbits"][3]["multipliers"][0] = ["Infinity", "-Infinity"]

    f = routh.OrbitFamily.from_json(edited(family_doc(), edit))
    return f.orbits[2].amplitude, f.orbits[3].multipliers[0]


def ragged(edit):
    return routh.Atlas.from_json(edited(atlas_doc(), edit))


def round_trip_com():
    """A scalar `com_1` keeps its name; the vector `com`'s first component is `com_1_`."""
    model = routh.Model(f"{KINETIC}, potential = com_1 * com.dot(gamma)",
                        {"inertia": INERTIA, "com": [0.3, -0.2, 1.1], "com_1": 2.0})
    values = values_by_name(model)
    values["com_1_"] = 0.3  # the component
    values["com_1"] = 2.0  # the scalar
    exprs = model.to_sympy()
    names = {s.name for s in exprs["amended_potential"].free_symbols}
    assert {"com_1", "com_1_", "com_2", "com_3"} <= names, names
    return agree_values(model, exprs, values)


def agree_values(model, exprs, params):
    rng = np.random.default_rng(5)
    gamma = rng.normal(size=3)
    gamma /= np.linalg.norm(gamma)
    omega, p_psi = rng.uniform(-2, 2, size=3), 0.7
    want = model.formula_values(omega, gamma, p_psi)
    values = dict(params, p_psi=p_psi)
    for i in range(3):
        values[f"omega{i + 1}"] = values[f"Omega{i + 1}"] = omega[i]
        values[f"gamma{i + 1}"] = gamma[i]
    for field, expr in exprs.items():
        np.testing.assert_allclose(evaluate(expr, values), want[field], rtol=1e-9, atol=1e-9)
    return True


# (id, what to do, what must come of it): ("ok", check) with check(result) true, or
# ("raises", exception, regex of its message).
def ok(check=lambda r: r is True):
    return ("ok", check)


def raises(exc, match):
    return ("raises", exc, match)


def nonfinite(what):
    return raises(routh.RouthError, rf"^non-finite input: {what} = (NaN|inf)")


NOT_UNIT = raises(routh.RouthError, r"^gamma must be a unit vector: \|gamma\| = ")
KEYWORDS_AND_FUNCTIONS = ["lambda", "sin", "sqrt", "Matrix", "Abs", "nan", "oo", "Symbol",
                          "None", "sigma1", "log"]

CASES = [
    # to_sympy: any valid parameter name round-trips (the user's name on the Symbol).
    *[(f"to_sympy: a parameter named {n}", lambda n=n: round_trip([n]), ok())
      for n in KEYWORDS_AND_FUNCTIONS],
    ("to_sympy: all of them in one model", lambda: round_trip(KEYWORDS_AND_FUNCTIONS), ok()),
    ("to_sympy: a parameter named α", lambda: round_trip(["α"]), ok()),
    ("to_sympy: parameters omega1 and p_psi (the state's names) get a _",
     lambda: round_trip(["omega1", "p_psi"], renamed=[("omega1", "omega1_"),
                                                      ("p_psi", "p_psi_")]), ok()),
    ("to_sympy: a scalar com_1 beside a vector com (the component gets a _)", round_trip_com,
     ok()),
    ("to_sympy: the text names the symbols by safe identifiers",
     lambda: dict(body(["lambda", "nan"]).sympy().symbols)["lambda_"], ok(lambda r: r == "lambda")),
    # `routh formulas --sympy` is Python that runs, for the same names, and `g`, `c`, `a`.
    ("formulas --sympy: keywords and functions", lambda: cli_script(KEYWORDS_AND_FUNCTIONS),
     ok()),
    ("formulas --sympy: parameters g, c, a, routhian (formula names)",
     lambda: cli_script(["g", "c", "a", "routhian"]), ok()),
    # A sum of any length.
    ("to_sympy: a potential of 3000 terms", lambda: long_sum(1500), ok()),
    # formula_values: non-finite inputs and a γ off the sphere are errors naming the input.
    ("formula_values: NaN in omega", lambda: formula_values([NAN, 0, 0], UP, 1.0),
     nonfinite("omega")),
    ("formula_values: inf in omega", lambda: formula_values([math.inf, 0, 0], UP, 1.0),
     nonfinite("omega")),
    ("formula_values: NaN in gamma", lambda: formula_values([0, 0, 0], [0, 0, NAN], 1.0),
     nonfinite("gamma")),
    ("formula_values: NaN p_psi", lambda: formula_values([0, 0, 0], UP, NAN),
     nonfinite("p_psi")),
    ("formula_values: gamma = (0, 0, 5)", lambda: formula_values([0, 0, 0], [0, 0, 5], 1.0),
     NOT_UNIT),
    ("formula_values: gamma = 0", lambda: formula_values([0, 0, 0], [0, 0, 0], 1.0), NOT_UNIT),
    ("formula_values: a unit gamma still works",
     lambda: formula_values([0.1, 0.2, 0.3], UP, 2.0)["amended_potential"],
     ok(lambda u: abs(u - (4 / 6 + 1.5)) < 1e-12)),
    # The family plot at huge and infinite stability indices.
    ("OrbitFamily.plot: k = 1e300", lambda: plot_family(1e300),
     ok(lambda labels: labels[-1] in ("10³⁰⁰", "10³⁰¹"))),
    ("OrbitFamily.plot: k = -1e300", lambda: plot_family(-1e300),
     ok(lambda labels: labels[0] in ("−10³⁰⁰", "−10³⁰¹"))),
    ("OrbitFamily.plot: k = 1e308", lambda: plot_family(1e308), ok(lambda labels: True)),
    ("OrbitFamily.plot: k = inf", lambda: plot_family("Infinity"), ok(lambda labels: True)),
    # from_json: every bad text is a RouthError at load, worded for JSON.
    ("from_json: a 100 000-deep array", lambda: routh.from_json("[" * 100_000 + "]" * 100_000),
     raises(routh.RouthError, r"^from_json: .*nested too deep")),
    ("from_json: a 100 000-deep object",
     lambda: routh.from_json('{"a": ' * 100_000 + "1" + "}" * 100_000),
     raises(routh.RouthError, r"^from_json: .*nested too deep")),
    ("from_json: a 100 000-deep array as a PeriodicOrbit",
     lambda: routh.PeriodicOrbit.from_json("[" * 100_000 + "]" * 100_000),
     raises(routh.RouthError, r"^from_json: .*nested too deep")),
    ("from_json: an atlas with a short row",
     lambda: ragged(lambda d: d["verdicts"][1].pop()),
     raises(routh.RouthError, r"^from_json: text\.verdicts\[1\] \(one per x\): 2 entries, "
                              r"expected 3")),
    ("from_json: an atlas with a row too many",
     lambda: ragged(lambda d: d["lost"].append(d["lost"][0])),
     raises(routh.RouthError, r"^from_json: text\.lost \(one per y\): 5 rows, expected 4")),
    ("from_json: an atlas with a number for a verdict",
     lambda: ragged(lambda d: d["verdicts"][0].__setitem__(0, 7)),
     raises(routh.RouthError, r"^from_json: text\.verdicts\[0\]: expected a verdict name")),
    ("from_json: an atlas as it was written", lambda: ragged(lambda d: None),
     ok(lambda a: len(a.verdicts) == 4 and len(a.verdicts[0]) == 3)),
    ("from_json: a section with a 2-vector normal",
     lambda: routh.PoincareSection.from_json(
         edited(section_doc(), lambda d: d.update(normal=[1.0, 0.0]))),
     raises(routh.RouthError, r"^from_json: text\.normal: expected 3 numbers, got 2")),
    ("from_json: a section with more orbits than starts",
     lambda: routh.PoincareSection.from_json(
         edited(section_doc(), lambda d: d["points"].append([]))),
     raises(routh.RouthError, r"^from_json: text\.points .*: 3 orbits, expected 2")),
    ("from_json: a branch with fewer verdicts than points",
     lambda: routh.Branch.from_json(edited(
         json.loads(B.bifurcation_diagram((0.0, 2.0)).branches[0].to_json()),
         lambda d: d["verdicts"].pop())),
     raises(routh.RouthError, r"^from_json: text\.verdicts: \d+ points, expected \d+")),
    ("from_json: the documented \"NaN\" in a PeriodicOrbit", lambda: orbit_with(amplitude="NaN"),
     ok(lambda o: math.isnan(o.amplitude))),
    ("from_json: \"Infinity\" and null in a PeriodicOrbit",
     lambda: orbit_with(stability_index="Infinity", energy=None),
     ok(lambda o: o.stability_index == math.inf and math.isnan(o.energy))),
    ("from_json: \"-Infinity\" in the bare serde form",
     lambda: bare_orbit_with(period="-Infinity"), ok(lambda o: o.period == -math.inf)),
    ("from_json: NaN and infinities inside a family", family_with_nan,
     ok(lambda r: math.isnan(r[0]) and r[1] == complex(math.inf, -math.inf))),
    ("from_json: a string that is not a number in a PeriodicOrbit",
     lambda: orbit_with(period="abc"),
     raises(routh.RouthError, r"^from_json: text: not a PeriodicOrbit: invalid type: "
                              r"string \"abc\"")),
    ("from_json: an unknown verdict name (no word of unpickling)",
     lambda: routh.StabilityReport.from_json(edited(
         json.loads(B.classify(B.steady_motions(1.0)[0]).to_json()),
         lambda d: d.update(verdict="bogus"))),
     raises(routh.RouthError, r"^from_json: text: not a StabilityReport: unknown name "
                              r"\"bogus\"$")),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_hostile_input(case):
    what, run, expect = case
    if expect[0] == "raises":
        _, exc, match = expect
        with pytest.raises(exc, match=match):
            run()
    else:
        assert expect[1](run()), what
