"""Markdown generated from the declarations (:mod:`dyncli.declare`): the
results table of a type page and the reference page of every result.

Used by ``docs/hooks.py`` (``<!-- results: TYPE -->`` and
``<!-- results-reference -->`` regions) and by the tests.
"""

from __future__ import annotations

from collections.abc import Set as AbstractSet

from dyncli.declare import ResultSpec, TypeSpec


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _eqs(r: ResultSpec) -> str:
    return ", ".join(r.equations)


def _name(r: ResultSpec) -> str:
    if r.part_of:
        return f"`{r.part_of}[].{r.name}`"
    return f"`{r.name}`"


def results_table(spec: TypeSpec, names: list[str] | None = None, exclude: AbstractSet[str] = frozenset()) -> str:
    """The results table of a type: the declared results named in ``names``
    (in declaration order), or every result not in ``exclude``."""
    rows = ["| result | symbol | unit | meaning | equations |", "|---|---|---|---|---|"]
    for r in spec.results:
        key = r.name if r.part_of is None else f"{r.part_of}.{r.name}"
        if (names is not None and key not in names) or (names is None and key in exclude):
            continue
        rows.append(f"| {_name(r)} | {_cell(r.symbol)} | {_cell(r.unit)} | {_cell(r.meaning)} | {_eqs(r)} |")
    return "\n".join(rows) + "\n"


def region(arg: str, listed: dict[str, set]) -> str:
    """A ``<!-- results: ARG -->`` region: ``TYPE`` (every result not in
    ``listed[TYPE]``, the names other regions of the page show) or
    ``TYPE/a,b,c`` (those results)."""
    from dyncli import registry

    t, _, names = arg.partition("/")
    spec = registry.TYPES[t]
    if names:
        return results_table(spec, names.split(","))
    return results_table(spec, exclude=listed.get(t, set()))


def reference(types: dict[str, TypeSpec]) -> str:
    """Every type's results: the binding names of the contract (marked
    **contract**: added to, never renamed) and the others."""
    out: list[str] = []
    for name, spec in types.items():
        out += [f"## `{name}` ({spec.sections})", "",
                f"{spec.title[:1].upper() + spec.title[1:]}. Page: [{name}](../types/{name}.md).", "",
                "| result | binding | symbol | unit | equations | meaning |", "|---|---|---|---|---|---|"]
        for r in spec.results:
            flag = "contract" if r.contract else ("part" if r.part_of else "")
            out.append(f"| {_name(r)} | {flag} | {_cell(r.symbol)} | {_cell(r.unit)} | {_eqs(r)} | {_cell(r.meaning)} |")
        out.append("")
    return "\n".join(out)
