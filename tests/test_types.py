"""The package's types are checked (issue 26): `mypy` runs in .ci/run at the newest allowed versions
(pyproject.toml's [tool.mypy]); these tests keep what mypy cannot see from drifting: every
``type: ignore`` names its code and says why, field declarations use the form mypy reads
(``Annotated[float, Num(...)]``, never a call as a type), and the packages left unchecked may
only be taken off their list."""

from __future__ import annotations

import ast
import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PKG = ROOT / "dyncli"
SOURCES = sorted(p for p in PKG.rglob("*.py") if "__pycache__" not in p.parts)

#: packages whose mypy errors are not reported yet; a package made clean is removed here and in
#: pyproject.toml, never added
UNCHECKED: set[str] = set()

_IGNORE = re.compile(r"#\s*type:\s*ignore(?P<rest>.*)$")
_WITH_REASON = re.compile(r"^\[[a-z-]+(?:,\s*[a-z-]+)*\]\s+#\s*\S")


def test_every_type_ignore_names_its_code_and_a_reason():
    bad = []
    for path in SOURCES:
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = _IGNORE.search(line)
            if m and not _WITH_REASON.match(m.group("rest")):
                bad.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert not bad, "write `# type: ignore[code]  # why`:\n" + "\n".join(bad)


def _calls_outside_annotated(node: ast.AST) -> list[ast.Call]:
    """Calls in a type expression, but for the metadata of ``Annotated[T, ...]``."""
    if isinstance(node, ast.Call):
        return [node]
    if isinstance(node, ast.Subscript):
        base = node.value.attr if isinstance(node.value, ast.Attribute) else getattr(node.value, "id", "")
        if base == "Annotated" and isinstance(node.slice, ast.Tuple):
            return _calls_outside_annotated(node.slice.elts[0])
        return _calls_outside_annotated(node.slice)
    if isinstance(node, ast.Tuple):
        return [c for e in node.elts for c in _calls_outside_annotated(e)]
    if isinstance(node, ast.BinOp):
        return _calls_outside_annotated(node.left) + _calls_outside_annotated(node.right)
    return []


def test_fields_are_declared_in_a_form_mypy_reads():
    bad = []
    for path in SOURCES:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.AnnAssign) and _calls_outside_annotated(node.annotation):
                bad.append(f"{path.relative_to(ROOT)}:{node.lineno}: {ast.unparse(node.annotation)[:80]}")
    assert not bad, "declare fields as Annotated[float, Num(...)] (dyncli/fields.py), not Num(...):\n" + "\n".join(bad)


def test_the_unchecked_packages_may_only_shrink():
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["mypy"]
    unchecked = {m for o in cfg.get("overrides", []) if o.get("ignore_errors")
                 for m in ([o["module"]] if isinstance(o["module"], str) else o["module"])}
    assert unchecked <= UNCHECKED, f"new packages left unchecked by mypy: {sorted(unchecked - UNCHECKED)}"
    assert cfg["packages"] == ["dyncli"]
