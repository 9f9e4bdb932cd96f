"""`SympyFormulas.to_sympy()` and `Model.to_sympy()`: the SymPy-syntax formulas parsed back.

SymPy is imported here, lazily: routh itself does not need it.

The text is read by a parser of its own (`parse`), not by `sympy.sympify`: Python's parser,
which `sympify` uses, recurses on the length of a sum and gives up ("maximum recursion depth
exceeded during compilation") beyond about a thousand terms, while a model's formulas may have
any number. This one keeps its operands and operators on two lists (no recursion at all), reads
a sum or a product into one `sympy.Add` or `sympy.Mul` (not a chain of binary ones), and
evaluates as Python would the same text with SymPy objects: `1/2` is `Rational(1, 2)`, `1.5`
`Float("1.5")`, `x**-1` `x**(-1)`, `-x**2` `-(x**2)`.
"""

import re

FIELDS = ("lagrangian", "psi_dot", "routhian", "amended_potential", "a", "g", "c")

#: The functions the formulas' text may call, by their SymPy names.
FUNCTIONS = ("Matrix", "sqrt", "Abs", "sign", "sin", "cos", "tan", "exp", "log")

#: The constants the text may use: `nan` (a formula too large to print, a NaN constant), `oo`.
CONSTANTS = ("nan", "oo")

_TOKEN = re.compile(
    r"""\s*(?:
        (?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)
      | (?P<name>[^\W\d]\w*)
      | (?P<op>\*\*|[-+*/(),\[\]])
      | (?P<end>$)
    )""",
    re.X,
)

_CALL = re.compile(r"\s*\(")

# Binary operators: precedence, right-associative.
_BINARY = {"+": (1, False), "-": (1, False), "*": (2, False), "/": (2, False), "**": (4, True)}
# Prefix signs bind tighter than * and looser than ** (Python's: -x**2 is -(x**2)).
_UNARY = 3


class _Sum:
    """The terms of a sum read so far (one `sympy.Add` when used)."""

    __slots__ = ("terms",)

    def __init__(self, terms):
        self.terms = terms


class _Product:
    """The factors of a product read so far (one `sympy.Mul` when used)."""

    __slots__ = ("factors",)

    def __init__(self, factors):
        self.factors = factors


def _value(x, sympy):
    if isinstance(x, _Sum):
        return sympy.Add(*x.terms)
    if isinstance(x, _Product):
        return sympy.Mul(*x.factors)
    return x


def parse(text, names, sympy):
    """The SymPy object of `text` (the syntax of `routh.SympyFormulas`: numbers, names, `+ - * /
    **`, signs, brackets, calls of `FUNCTIONS`, lists `[…]` as `Matrix`'s argument). `names`
    maps a name to its object; a name not in it is a real `sympy.Symbol` of that name. Raises
    ValueError for text not of that syntax."""
    functions = {f: getattr(sympy, f) for f in FUNCTIONS}
    operands = []
    # Entries: ("bin", op), ("sign", op), ("call", function, first operand), ("paren",),
    # ("list", first operand).
    ops = []
    expect_operand = True

    def fail(pos, what):
        raise ValueError(f"routh: SymPy text not understood at character {pos}: {what}")

    def reduce():
        op = ops.pop()
        if op[0] == "sign":
            x = _value(operands.pop(), sympy)
            operands.append(-x if op[1] == "-" else x)
            return
        o = op[1]
        r = _value(operands.pop(), sympy)
        left = operands.pop()
        if o == "+" or o == "-":
            term = r if o == "+" else -r
            if isinstance(left, _Sum):
                left.terms.append(term)
                operands.append(left)
            else:
                operands.append(_Sum([_value(left, sympy), term]))
        elif o == "*" or o == "/":
            factor = r if o == "*" else sympy.Pow(r, -1)
            if isinstance(left, _Product):
                left.factors.append(factor)
                operands.append(left)
            else:
                operands.append(_Product([_value(left, sympy), factor]))
        else:
            operands.append(_value(left, sympy) ** r)

    def close(pos, kinds):
        """Reduces to the innermost bracket; returns it (an error unless of `kinds`)."""
        while ops and ops[-1][0] in ("bin", "sign"):
            reduce()
        if not ops or ops[-1][0] not in kinds:
            fail(pos, "unbalanced bracket or comma")
        return ops[-1]

    pos = 0
    while True:
        m = _TOKEN.match(text, pos)
        if m is None:
            fail(pos, repr(text[pos:pos + 20]))
        start, pos = m.start(m.lastgroup), m.end()
        kind, tok = m.lastgroup, m.group(m.lastgroup)
        if kind == "end":
            break
        if kind in ("num", "name"):
            if not expect_operand:
                fail(start, f"{tok!r} after an operand")
            if kind == "num":
                is_float = any(c in tok for c in ".eE")
                operands.append(sympy.Float(tok) if is_float else sympy.Integer(tok))
                expect_operand = False
            elif (call := _CALL.match(text, pos)) is not None:
                if tok not in functions:
                    fail(start, f"unknown function {tok!r}")
                pos = call.end()
                ops.append(("call", functions[tok], len(operands)))
            else:
                if tok in names:
                    operands.append(names[tok])
                else:
                    operands.append(sympy.Symbol(tok, real=True))
                expect_operand = False
        elif tok in ("(", "["):
            if not expect_operand:
                fail(start, f"{tok!r} after an operand")
            ops.append(("paren",) if tok == "(" else ("list", len(operands)))
        elif tok == ",":
            if expect_operand:
                fail(start, "',' without an operand before it")
            close(start, ("call", "list"))
            expect_operand = True
        elif tok == ")":
            if expect_operand:
                fail(start, "')' without an operand before it")
            top = close(start, ("paren", "call"))
            ops.pop()
            if top[0] == "call":
                args = [_value(x, sympy) for x in operands[top[2]:]]
                del operands[top[2]:]
                operands.append(top[1](*args))
            else:
                operands.append(_value(operands.pop(), sympy))
        elif tok == "]":
            if expect_operand and not (ops and ops[-1][0] == "list" and ops[-1][1] == len(operands)):
                fail(start, "']' without an operand before it")
            top = close(start, ("list",))
            ops.pop()
            items = [_value(x, sympy) for x in operands[top[1]:]]
            del operands[top[1]:]
            operands.append(items)
            expect_operand = False
        elif expect_operand:
            if tok not in ("+", "-"):
                fail(start, f"{tok!r} where an operand was expected")
            ops.append(("sign", tok))
        else:
            prec, right = _BINARY[tok]
            while ops and ops[-1][0] in ("bin", "sign"):
                top = ops[-1]
                top_prec = _UNARY if top[0] == "sign" else _BINARY[top[1]][0]
                if top_prec > prec or (top_prec == prec and not right):
                    reduce()
                else:
                    break
            ops.append(("bin", tok))
            expect_operand = True
    if expect_operand:
        fail(len(text), "the text ends where an operand was expected")
    while ops:
        if ops[-1][0] not in ("bin", "sign"):
            fail(len(text), "unbalanced bracket")
        reduce()
    if len(operands) != 1:
        fail(len(text), "more than one expression")
    return _value(operands[0], sympy)


def to_sympy(formulas):
    """The seven formulas of a `routh.SympyFormulas` as SymPy objects: a dict name →
    expression (`sympy.Matrix` for `a`, `g`, `c`). Every symbol is a real `sympy.Symbol` of
    its name in `formulas.symbols` (`lambda` for the identifier `lambda_` of a parameter
    `lambda`), every other name in the text a real `sympy.Symbol` of that name; the named
    subexpressions of `formulas.definitions` are substituted. A sum may have any number of
    terms (see `parse`)."""
    try:
        import sympy
    except ImportError as e:
        raise ImportError(
            "routh: to_sympy() needs SymPy (`pip install sympy`); "
            "Model.sympy() gives the same formulas as text without it"
        ) from e
    local = {c: getattr(sympy, c) for c in CONSTANTS}
    for ident, name in getattr(formulas, "symbols", ()):
        local[ident] = sympy.Symbol(name, real=True)
    for name, text in formulas.definitions:
        local[name] = parse(text, local, sympy)
    return {f: parse(getattr(formulas, f), local, sympy) for f in FIELDS}
