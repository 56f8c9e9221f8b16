"""The doctests of the numeric core run with the suite: every ``dyncli/topics/*/equations.py``
(the notes' results as named pure functions, issue #19) and the neutral helpers."""

from __future__ import annotations

import doctest
import importlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
EQUATIONS = sorted(ROOT.glob("dyncli/topics/*/equations.py"))
MODULES = [f"dyncli.topics.{p.parent.name}.equations" for p in EQUATIONS] + ["dyncli.numfmt", "dyncli.vec3", "dyncli.phase",
                                                                          "dyncli.topics.particle.kepler"]


def test_equations_modules_exist():
    assert EQUATIONS, "no dyncli/topics/*/equations.py found"


@pytest.mark.parametrize("name", MODULES)
def test_doctests(name):
    mod = importlib.import_module(name)
    res = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert res.failed == 0, f"{res.failed} doctest(s) of {name} failed (run `python -m doctest -v {mod.__file__}`)"
    if name.endswith(".equations"):
        public = [f for k, f in vars(mod).items()
                  if callable(f) and not k.startswith("_") and getattr(f, "__module__", None) == name]
        missing = [f.__name__ for f in public if ">>>" not in (f.__doc__ or "")]
        assert not missing, f"{name}: functions without a doctest: {missing}"
