"""The type stubs cover every public name, and every public name has a docstring."""

import ast
import inspect
import pathlib

import routh


def stub_tree():
    pyi = pathlib.Path(routh.__file__).parent / "__init__.pyi"
    tree = ast.parse(pyi.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            names = set()
            for b in node.body:
                if isinstance(b, ast.FunctionDef):
                    names.add(b.name)
                elif isinstance(b, ast.AnnAssign):
                    names.add(b.target.id)
            members[node.name] = names
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            top.add(node.target.id)
        elif isinstance(node, ast.Assign):
            top.update(t.id for t in node.targets)
    return top, members


def public(cls):
    return sorted(n for n in dir(cls) if not n.startswith("_"))


def test_stubs_cover_every_public_name():
    top, members = stub_tree()
    missing = [n for n in routh.__all__ if n not in top]
    assert not missing, missing
    for name in routh.__all__:
        obj = getattr(routh, name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            stub = members[obj.__name__ if obj.__name__ in members else name]
            absent = [m for m in public(obj) if m not in stub]
            assert not absent, (name, absent)
            for m in ("_repr_html_", "_repr_svg_", "_repr_latex_"):
                if hasattr(obj, m):
                    assert m in stub, (name, m)


def test_every_public_name_has_a_docstring():
    undocumented = []
    for name in routh.__all__:
        obj = getattr(routh, name)
        if callable(obj) and not (obj.__doc__ or "").strip():
            undocumented.append(name)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for m in public(obj):
                doc = getattr(getattr(obj, m), "__doc__", None)
                if not (doc or "").strip() or doc == getattr(type(getattr(obj, m)), "__doc__", None):
                    undocumented.append(f"{name}.{m}")
    assert not undocumented, undocumented
