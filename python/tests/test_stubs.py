"""The shipped type stubs are the ones the registry renders (so a new problem or parameter
cannot leave the editor's completion stale), and they parse."""

from __future__ import annotations

import ast
from pathlib import Path

import microslip
from microslip import _stubs


def test_the_installed_stubs_are_current():
    shipped = Path(microslip.__file__).with_name("__init__.pyi")
    assert shipped.exists(), "the wheel must ship microslip/__init__.pyi"
    assert shipped.read_text() == _stubs.render(), "run `python -m microslip._stubs`"
    assert Path(microslip.__file__).with_name("py.typed").exists()


def test_the_stubs_declare_every_class_and_keyword():
    tree = ast.parse(_stubs.render())
    classes = {node.name: node for node in tree.body if isinstance(node, ast.ClassDef)}
    for entry in microslip.PROBLEMS:
        cls = classes[microslip.problem_class(entry["key"]).__name__]
        init = next(n for n in cls.body if isinstance(n, ast.FunctionDef) and n.name == "__init__")
        keywords = [a.arg for a in init.args.kwonlyargs]
        assert keywords == ["name", *(p["name"] for p in entry["params"])]


def test_runtime_api_is_declared():
    stub = _stubs.render()
    for name in microslip.__all__:
        assert f"{name}" in stub, name
    for method in ("solve", "sweep", "replace", "cycle", "fe_defaults", "kt_tolerance", "fit", "continuum", "deck"):
        assert callable(getattr(microslip.TwinBeams, method))
        assert f"def {method}(" in stub
