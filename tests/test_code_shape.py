"""The shape of the code (issue 26, item 5): modules along concepts, never cut to a line count.

Read from the source of ``dyncli/`` with ``ast`` (nothing is imported, no text search of names):

* **No private name crosses a module.**  A name with a leading underscore (``_x``, not a dunder)
  is its module's own: no other module of ``dyncli/`` imports it (``from dyncli.a import _x``,
  also relative, also inside a function) or reaches it through a module it imported
  (``import dyncli.a as m`` or ``from dyncli import a``, then ``m._x``/``a._x``).  Two modules that
  need one private name are one concept cut in two (merge them), or the name is a shared
  concept (make it public, with a docstring).
* **No class split over files.**  A class ``B`` of module ``N`` is *half of another class* when
  ``C``, defined in another module ``M`` of the same package (the same folder), lists ``B`` among
  its bases, ``B`` is the base of no other class in ``dyncli/``, and ``B`` is never called
  (instantiated) anywhere in ``dyncli/``: a mixin kept in another file, whose ``self.``
  uses of ``C``'s attributes no type checker can follow.  Put it back into ``C``'s module (or make
  it a real base: one that stands alone, or that several classes share).
* **Every module says what concept it holds**: it has a docstring whose first paragraph is at
  least three words and not a placeholder ("Helpers.", "Utilities", "Misc", "the rest of ...",
  "part 2 of ...", "continued"), and the docstring gives no line count (a size is never why a
  module exists).
* **Type names and package names agree**: a topic package holding one type is named after it
  (``constrained-particle`` in ``dyncli/topics/constrained_particle``); a package named
  otherwise is listed, with the reason, in ``dyncli.registry.PACKAGE_NAMES`` — exactly those,
  each reason naming every type the package holds.
* A smell, never a reason to split: a function over 150 lines says why in a comment or its
  docstring within its first lines (the words "on purpose").

The offences inside ``dyncli/topics/`` found when these rules came (topics being edited
elsewhere at the time) are listed below; the lists may only shrink: an entry no longer found
must be removed, and nothing may be added.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "dyncli"
SOURCES = sorted(p for p in PKG.rglob("*.py") if "__pycache__" not in p.parts)
SMELL_FUNCTION_LINES = 150

#: (importing file, module the private name lives in, name) found when the rule came; to be fixed
#: (merged or made public) by the topics' owners; may only shrink.
PRIVATE_IMPORTS_ALLOWED: set[tuple[str, str, str]] = set()

#: (file of the class, class, file of its split-off base, base) found when the rule came; may only shrink.
SPLIT_CLASSES_ALLOWED: set[tuple[str, str, str, str]] = set()


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def rel(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


MODULES = {module_name(p): p for p in SOURCES}
TREES = {p: ast.parse(p.read_text(encoding="utf-8"), str(p)) for p in SOURCES}


def _private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def _from_module(path: Path, node: ast.ImportFrom) -> str:
    """The absolute module name of ``from ... import``, relative forms resolved."""
    if not node.level:
        return node.module or ""
    base = module_name(path).split(".")
    if path.name != "__init__.py":
        base.pop()
    base = base[: len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _module_aliases(path: Path) -> dict[str, str]:
    """Local names bound to a module of dyncli (``import dyncli.a as m``, ``from dyncli import a``)."""
    out: dict[str, str] = {}
    for node in ast.walk(TREES[path]):
        if isinstance(node, ast.Import):
            for a in node.names:
                if a.name in MODULES:
                    out[a.asname or a.name] = a.name
        elif isinstance(node, ast.ImportFrom):
            src = _from_module(path, node)
            for a in node.names:
                if f"{src}.{a.name}" in MODULES:
                    out[a.asname or a.name] = f"{src}.{a.name}"
    return out


def private_imports() -> dict[tuple[str, str, str], list[int]]:
    """(importing file, module, private name) -> the lines where it crosses."""
    found: dict[tuple[str, str, str], list[int]] = {}
    for path in SOURCES:
        own = module_name(path)
        aliases = _module_aliases(path)
        for node in ast.walk(TREES[path]):
            hits: list[tuple[str, str]] = []
            if isinstance(node, ast.ImportFrom):
                src = _from_module(path, node)
                if src.split(".")[0] == "dyncli" and src != own:
                    hits = [(src, a.name) for a in node.names if _private(a.name)]
            elif isinstance(node, ast.Attribute) and _private(node.attr):
                dotted = ast.unparse(node.value)
                if dotted in aliases and aliases[dotted] != own:
                    hits = [(aliases[dotted], node.attr)]
            for src, name in hits:
                found.setdefault((rel(path), src, name), []).append(node.lineno)
    return found


def _shrink_only(found: set, allowed: set, what: str, fix: str) -> None:
    new, gone = sorted(found - allowed), sorted(allowed - found)
    assert not new, f"{what}:\n  " + "\n  ".join(map(str, new)) + f"\n{fix}"
    assert not gone, ("fixed (well done): remove from the allow-list of tests/test_code_shape.py:\n  "
                      + "\n  ".join(map(str, gone)))


def test_no_private_name_crosses_a_module():
    found = private_imports()
    located = {k: v for k, v in found.items() if k not in PRIVATE_IMPORTS_ALLOWED}
    new = [f"{f}:{','.join(map(str, lines))}: {name} of {src}" for (f, src, name), lines in sorted(located.items())]
    assert not new, ("private names used across modules (merge the modules that share them, or make the "
                     "name a public, documented one):\n  " + "\n  ".join(new))
    _shrink_only(set(found), PRIVATE_IMPORTS_ALLOWED, "private names used across modules", "")


def _classes() -> list[tuple[Path, ast.ClassDef, list[tuple[str, str]]]]:
    """Every class with its bases resolved to (module, class name) where they are dyncli's."""
    out = []
    for path in SOURCES:
        own = module_name(path)
        aliases = _module_aliases(path)
        names: dict[str, tuple[str, str]] = {}
        for node in ast.walk(TREES[path]):
            if isinstance(node, ast.ImportFrom):
                src = _from_module(path, node)
                if src in MODULES:
                    for a in node.names:
                        names[a.asname or a.name] = (src, a.name)
        for node in ast.walk(TREES[path]):
            if not isinstance(node, ast.ClassDef):
                continue
            bases = []
            for b in node.bases:
                if isinstance(b, ast.Name):
                    bases.append(names.get(b.id, (own, b.id)))
                elif isinstance(b, ast.Attribute) and ast.unparse(b.value) in aliases:
                    bases.append((aliases[ast.unparse(b.value)], b.attr))
            out.append((path, node, bases))
    return out


def _called_names() -> set[str]:
    """Every name called anywhere in dyncli (``B(...)`` or ``m.B(...)``)."""
    called = set()
    for tree in TREES.values():
        for node in ast.walk(tree):
            if isinstance(node, ast.Call):
                f = node.func
                called.add(f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else "")
    return called


def split_classes() -> set[tuple[str, str, str, str]]:
    classes = _classes()
    uses: dict[tuple[str, str], list[tuple[Path, ast.ClassDef]]] = {}
    for path, node, bases in classes:
        for b in bases:
            uses.setdefault(b, []).append((path, node))
    called = _called_names()
    out = set()
    for (mod, name), users in uses.items():
        if len(users) != 1 or mod not in MODULES or name in called:
            continue
        path, node = users[0]
        base_path = MODULES[mod]
        if base_path != path and base_path.parent == path.parent:
            out.add((rel(path), node.name, rel(base_path), name))
    return out


def test_no_class_is_split_over_files():
    _shrink_only(split_classes(), SPLIT_CLASSES_ALLOWED, "classes whose other half lives in another file "
                 "(file, class, file of the base, base)", "put the base back into its one subclass's module")


_PLACEHOLDER = re.compile(r"^\W*((helpers?|utils?|utilit(y|ies)|misc(ellaneous)?|common|shared)(\W+\w+){0,2}\W*"
                          r"|(the )?rest of\b.*|part \d+\b.*|continued\b.*|more of\b.*)$", re.I | re.S)
_SIZE = re.compile(r"\b\d+ lines\b|\bline count\b|\b(under|below) (~|about )?\d{2,4}\b", re.I)


def test_every_module_says_what_concept_it_holds():
    bad = []
    for path in SOURCES:
        doc = ast.get_docstring(TREES[path]) or ""
        first = doc.strip().split("\n\n")[0]
        if len(first.split()) < 3:
            bad.append(f"{rel(path)}: no docstring saying what it holds (first paragraph {first!r})")
        elif _PLACEHOLDER.search(first):
            bad.append(f"{rel(path)}: a placeholder, not a concept: {first!r}")
        elif m := _SIZE.search(doc):
            bad.append(f"{rel(path)}: its docstring gives a size ({m.group(0)!r}): say what it holds instead")
    assert not bad, "module docstrings:\n  " + "\n  ".join(bad)


def _long_functions(path: Path):
    lines = path.read_text(encoding="utf-8").splitlines()
    for node in ast.walk(TREES[path]):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            n = (node.end_lineno or node.lineno) - node.lineno + 1
            if n <= SMELL_FUNCTION_LINES:
                continue
            body = node.body[1] if len(node.body) > 1 and isinstance(node.body[0], ast.Expr) else node.body[0]
            head = "\n".join(lines[node.lineno - 1: body.lineno + 2])     # signature, docstring, first comments
            if "on purpose" not in head:
                yield f"{rel(path)}:{node.lineno} {node.name}() is {n} lines"


def test_a_very_long_function_says_why():
    long = [msg for p in SOURCES for msg in _long_functions(p)]
    assert not long, (f"functions over {SMELL_FUNCTION_LINES} lines: say why in their first lines (\"... on purpose: "
                      "...\") or find the concepts inside them (never split just to meet a count):\n  "
                      + "\n  ".join(long))


def test_type_names_and_package_names_agree_or_the_registry_says_why():
    from dyncli import registry

    held: dict[str, list[str]] = {}
    for name, spec in registry.TYPES.items():
        if spec.package.startswith("dyncli.topics."):
            held.setdefault(spec.package.rsplit(".", 1)[1], []).append(name)
    differ = {pkg for pkg, names in held.items() if names != [pkg.replace("_", "-")]}
    listed = set(registry.PACKAGE_NAMES)
    assert not differ - listed, ("packages not named after their one type (rename it, or say why in "
                                 "dyncli.registry.PACKAGE_NAMES): " + ", ".join(f"{p} holds {held[p]}" for p in sorted(differ - listed)))
    assert not listed - differ, f"named after their one type now: remove from PACKAGE_NAMES: {sorted(listed - differ)}"
    unnamed = [f"{p}: {n}" for p in sorted(differ) for n in held[p] if n not in registry.PACKAGE_NAMES[p]]
    assert not unnamed, "the reason in PACKAGE_NAMES names every type the package holds:\n  " + "\n  ".join(unnamed)
