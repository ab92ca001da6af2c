"""The type hints (tmc429/_native.pyi) name exactly what the extension has, and every public
class, method and function has a docstring."""

import ast
from pathlib import Path

import tmc429
from tmc429 import _native

STUB = Path(tmc429.__file__).with_name("_native.pyi")


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            members[node.name] = {
                n.name if isinstance(n, ast.FunctionDef) else n.target.id
                for n in node.body
                if isinstance(n, (ast.FunctionDef, ast.AnnAssign))
            }
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign) and not node.target.id.startswith("_"):
            top.add(node.target.id)
    return top, members


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_stub_matches_the_extension():
    top, members = stub_names()
    assert public(dir(_native)) - {"tmc429"} == top
    for cls, names in members.items():
        assert public(dir(getattr(_native, cls))) == public(names), cls


def test_everything_public_has_a_docstring():
    for name in public(dir(_native)):
        obj = getattr(_native, name)
        if callable(obj):
            assert obj.__doc__, name
        if isinstance(obj, type):
            for m in public(dir(obj)):
                attr = getattr(obj, m)
                if callable(attr) and not isinstance(attr, type):
                    assert attr.__doc__, f"{name}.{m}"
