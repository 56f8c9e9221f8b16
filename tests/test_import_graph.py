"""No import circle anywhere in ``dyncli/`` (issue #26), read with ``ast``.

The graph has an edge A -> B for every ``import`` statement of module A
that names the ``dyncli`` module B — module-level AND function-level
imports both (a lazy import inside a function closes a circle just as
well: it only hides it until that function runs).  Imports under
``if TYPE_CHECKING:`` are left out (they never run).  ``from P import x``
is an edge to ``P.x`` when that is a module of the package, else to ``P``.
Package ``__init__`` modules count as their package's name.

A circle is a strongly connected component of more than one module (or a
module importing itself); the test names each with one of its cycles.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "dyncli"


def module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _is_type_checking(node: ast.If) -> bool:
    t = node.test
    return (isinstance(t, ast.Name) and t.id == "TYPE_CHECKING") or \
        (isinstance(t, ast.Attribute) and t.attr == "TYPE_CHECKING")


def _imports(tree: ast.AST):
    """Every Import/ImportFrom node, at any depth, outside ``if TYPE_CHECKING``."""
    stack = [tree]
    while stack:
        node = stack.pop()
        if isinstance(node, ast.If) and _is_type_checking(node):
            stack.extend(node.orelse)
            continue
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            yield node
        stack.extend(ast.iter_child_nodes(node))


def import_graph() -> dict[str, set[str]]:
    files = {module_name(p): p for p in PKG.rglob("*.py")}
    graph: dict[str, set[str]] = {m: set() for m in files}
    for mod, path in files.items():
        is_pkg = path.name == "__init__.py"
        for node in _imports(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                base = node.module or ""
                if node.level:
                    anchor = mod.split(".") if is_pkg else mod.split(".")[:-1]
                    anchor = anchor[:len(anchor) - (node.level - 1)]
                    base = ".".join(anchor + ([base] if base else []))
                targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in files else base for a in node.names]
            for t in targets:
                while t and t not in files and "." in t:     # import dyncli.a.b.c (an attribute): dyncli.a.b
                    t = t.rsplit(".", 1)[0]
                if t in files and t != "dyncli" or t == mod:
                    graph[mod].add(t)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """One cycle per strongly connected component (Tarjan), each as a path A -> ... -> A."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    comps: list[set[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = set()
            while True:
                w = stack.pop()
                on.discard(w)
                comp.add(w)
                if w == v:
                    break
            if len(comp) > 1 or v in graph[v]:
                comps.append(comp)

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return [_one_cycle(graph, c) for c in comps]


def _one_cycle(graph: dict[str, set[str]], comp: set[str]) -> list[str]:
    start = min(comp)
    prev = {start: None}
    todo = [start]
    while todo:                      # breadth-first back to start inside the component
        v = todo.pop(0)
        for w in sorted(graph[v] & comp):
            if w == start:
                path = [v]
                while prev[path[-1]] is not None:
                    path.append(prev[path[-1]])
                return list(reversed(path)) + [start]
            if w not in prev:
                prev[w] = v
                todo.append(w)
    return sorted(comp)  # pragma: no cover - a component always holds a cycle


def test_the_graph_is_read():
    g = import_graph()
    assert "dyncli.check.compare" in g and "dyncli.run" in g
    assert "dyncli.loader" in g["dyncli.run"]                     # module level
    assert "dyncli.run" in g["dyncli.check.problemfiles"]         # function level


def test_a_circle_is_found():
    g = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert cycles(g) == [["a", "b", "c", "a"]]


def test_no_import_circle_in_dyncli():
    """None at all: what two modules share lives in a module below both (a route's report, the
    method map of dyncli.integrators), never in a solver its routes call back into."""
    found = cycles(import_graph())
    assert not found, "import circles in dyncli/:\n" + "\n".join(" -> ".join(c) for c in found)


def test_no_import_circle_in_check_render_or_run():
    """The circles issue #26 names are gone for good: none in dyncli/check, none through render and run.py."""
    for c in cycles(import_graph()):
        assert not any(m.startswith(("dyncli.check", "dyncli.render")) or m == "dyncli.run" for m in c), c
