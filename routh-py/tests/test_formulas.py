"""The SymPy-syntax formulas (`Model.sympy()`, `Model.to_sympy()`) parse back with SymPy and
agree with the model's generated code (`Model.formula_values`) at random points, to 1e-10
relative, for the paper's models; skipped without SymPy."""

import pathlib

import numpy as np
import pytest

import routh

sympy = pytest.importorskip("sympy")

ROOT = pathlib.Path(__file__).resolve().parents[2]
MODELS = sorted((ROOT / "examples" / "models").glob("*.toml"))

TOP_TEXT = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"


def symbol_values(model, omega, gamma, p_psi):
    """name → value of every symbol the formulas use: the state, and the parameters (a vector
    `v` as `v_1 v_2 v_3`, a matrix `m` as `m_11 … m_33`, indices from 1)."""
    values = {"p_psi": p_psi}
    for i in range(3):
        values[f"omega{i + 1}"] = omega[i]
        values[f"Omega{i + 1}"] = omega[i]
        values[f"gamma{i + 1}"] = gamma[i]
    for name, value in model.parameters.items():
        a = np.asarray(value, dtype=float)
        if a.ndim == 0:
            values[name] = float(a)
        elif a.ndim == 1:
            for i in range(3):
                values[f"{name}_{i + 1}"] = a[i]
        else:
            for i in range(3):
                for j in range(3):
                    values[f"{name}_{i + 1}{j + 1}"] = a[i, j]
    return values


def evaluate(expr, values):
    subs = {s: values[s.name] for s in expr.free_symbols}
    if isinstance(expr, sympy.MatrixBase):
        return np.array(expr.subs(subs).evalf(30).tolist(), dtype=float)
    return float(expr.subs(subs).evalf(30))


def close(got, want, what):
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    scale = max(1.0, float(np.max(np.abs(want))))
    assert np.all(np.abs(got - want) <= 1e-10 * scale), (what, got, want)


def models():
    out = [("lagrange_top", routh.Model(TOP_TEXT, {"inertia": [1.0, 1.0, 1.25], "mgl": 1.0}))]
    out += [(p.stem, routh.Model.load(p)) for p in MODELS]
    return out


@pytest.mark.parametrize("name,model", models(), ids=lambda x: x if isinstance(x, str) else "")
def test_every_formula_parses_back_and_agrees_with_the_generated_code(name, model):
    f = model.sympy()
    exprs = model.to_sympy()
    assert sorted(exprs) == sorted(f.as_dict())
    for field in ("a", "g", "c"):
        assert exprs[field].shape == (3, 3), (name, field)
    rng = np.random.default_rng(7)
    for _ in range(5):
        gamma = rng.normal(size=3)
        gamma /= np.linalg.norm(gamma)  # the formulas are simplified with |γ|² = 1
        omega = rng.uniform(-2, 2, size=3)
        p_psi = rng.uniform(-3, 3)
        want = model.formula_values(omega, gamma, p_psi)
        values = symbol_values(model, omega, gamma, p_psi)
        for field, expr in exprs.items():
            close(evaluate(expr, values), want[field], f"{name} {field}")


def test_the_text_is_sympy_syntax_in_canonical_order(top):
    f = top.sympy()
    # Terms by degree then index, parameters before variables, components from 1.
    assert f.lagrangian == (
        "1/2*(inertia_1*omega1**2 + inertia_2*omega2**2 + inertia_3*omega3**2) - mgl*gamma3"
    )
    assert f.definitions == []
    assert f.a.startswith("Matrix([[") and "\\" not in f.c
    u = top.to_sympy()["amended_potential"]
    p, g3 = sympy.Symbol("p_psi", real=True), sympy.Symbol("gamma3", real=True)
    # At the sleeping top (γ = e₃): U_r = p²/(2C) + mgl.
    assert sympy.simplify(u.subs({g3: 1, sympy.Symbol("gamma1", real=True): 0,
                                  sympy.Symbol("gamma2", real=True): 0}).subs(
        {sympy.Symbol("inertia_3", real=True): sympy.Rational(5, 4),
         sympy.Symbol("mgl", real=True): 1}) - (p**2 * sympy.Rational(2, 5) + 1)) == 0


def test_to_sympy_without_sympy_says_so(top, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "sympy", None)  # `import sympy` raises ImportError
    with pytest.raises(ImportError, match="pip install sympy"):
        top.to_sympy()
    assert top.sympy().lagrangian  # the text needs no SymPy


@pytest.mark.parametrize("name,model", models(), ids=lambda x: x if isinstance(x, str) else "")
def test_to_sympy_reads_what_sympify_reads(name, model):
    """`to_sympy()`'s own parser (which reads sums of any length) gives the expressions
    `sympy.sympify` gives for the same text, the symbols bound by `symbols`: the same tree, or,
    where SymPy's automatic combination of like terms differs with the order of construction
    (the parser builds each sum n-ary, `sympify` pairwise: the gyrostat's G once the printer
    collects like terms), a difference that SymPy simplifies to 0."""
    f = model.sympy()
    local = {ident: sympy.Symbol(n, real=True) for ident, n in f.symbols}
    for d, text in f.definitions:
        local[d] = sympy.sympify(text, locals=local)
    exprs = model.to_sympy()
    for field in exprs:
        ours, theirs = exprs[field], sympy.sympify(f[field], locals=local)
        if ours == theirs:
            continue
        diff = sympy.Matrix(ours) - sympy.Matrix(theirs) if field in ("a", "g", "c") else None
        if diff is None:
            assert sympy.simplify(ours - theirs) == 0, (name, field)
        else:
            assert all(sympy.simplify(x) == 0 for x in diff), (name, field)
