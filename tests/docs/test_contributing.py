"""CONTRIBUTING.md's "What the tests enforce" lists exactly the tests that enforce the house rules.

* every test it names exists: a file ``tests/....py``, a test ``tests/....py::test_x`` in that
  file, and a bare ``test_x`` in some test file it names;
* every test module directly under ``tests/`` and under ``tests/docs/`` (the cross-cutting rules;
  the other folders test behaviour) is named there.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
TEXT = (ROOT / "CONTRIBUTING.md").read_text(encoding="utf-8")
SECTION = TEXT.split("### What the tests enforce", 1)[1].split("\n## ", 1)[0]


def _tests_in(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return {n.name for n in ast.walk(tree) if isinstance(n, ast.FunctionDef) and n.name.startswith("test")}


def _cited_files() -> set[str]:
    return set(re.findall(r"`(tests/[\w/]+\.py)(?:::\w+)?`", SECTION)) | set(re.findall(r"`(tests/[\w/]+/)`", SECTION))


def test_every_named_test_exists():
    missing = [f for f in _cited_files() if not (ROOT / f).exists()]
    assert not missing, f"CONTRIBUTING.md names test files that do not exist: {sorted(missing)}"
    wrong = [f"{f}::{t}" for f, t in re.findall(r"`(tests/[\w/]+\.py)::(\w+)`", SECTION)
             if t not in _tests_in(ROOT / f)]
    assert not wrong, f"CONTRIBUTING.md names tests that do not exist: {wrong}"
    known = set().union(*(_tests_in(ROOT / f) for f in _cited_files() if f.endswith(".py")))
    bare = sorted({t for t in re.findall(r"`(test_\w+)`", SECTION)} - known)
    assert not bare, f"CONTRIBUTING.md names tests found in none of the files it names: {bare}"


def test_every_rule_module_is_named():
    modules = sorted(p.relative_to(ROOT).as_posix() for d in ("tests", "tests/docs")
                     for p in (ROOT / d).glob("test_*.py"))
    unnamed = [m for m in modules if f"`{m}" not in SECTION]
    assert not unnamed, ("test modules that enforce house rules but are not listed in CONTRIBUTING.md's "
                         f"\"What the tests enforce\": {unnamed}")
