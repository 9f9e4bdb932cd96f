"""`SympyFormulas.to_sympy()` and `Model.to_sympy()`: the SymPy-syntax formulas parsed back.

SymPy is imported here, lazily: routh itself does not need it.
"""

import re

FIELDS = ("lagrangian", "psi_dot", "routhian", "amended_potential", "a", "g", "c")

#: The functions the formulas' text may call, by their SymPy names.
FUNCTIONS = ("Matrix", "sqrt", "Abs", "sign", "sin", "cos", "tan", "exp", "log", "nan")

_NAME = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")


def to_sympy(formulas):
    """The seven formulas of a `routh.SympyFormulas` as SymPy objects: a dict name →
    expression (`sympy.Matrix` for `a`, `g`, `c`). Every other name in the text (`omega1`,
    `gamma3`, `p_psi`, the parameters, even `I`, `E`, `S` or `gamma`) is a real `sympy.Symbol`;
    the named subexpressions of `formulas.definitions` are substituted."""
    try:
        import sympy
    except ImportError as e:
        raise ImportError(
            "routh: to_sympy() needs SymPy (`pip install sympy`); "
            "Model.sympy() gives the same formulas as text without it"
        ) from e
    texts = [getattr(formulas, f) for f in FIELDS] + [d for _, d in formulas.definitions]
    defined = {name for name, _ in formulas.definitions}
    names = {n for t in texts for n in _NAME.findall(t)} - set(FUNCTIONS) - defined
    local = {n: sympy.Symbol(n, real=True) for n in sorted(names)}
    local.update({f: getattr(sympy, f) for f in FUNCTIONS})
    for name, text in formulas.definitions:
        local[name] = sympy.sympify(text, locals=local)
    return {f: sympy.sympify(getattr(formulas, f), locals=local) for f in FIELDS}
