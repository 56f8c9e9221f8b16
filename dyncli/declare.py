"""One declaration per problem type.

Each topic package declares its types once, in ``dyncli/topics/<topic>/
results.py``: a module-level ``TYPES = [TypeSpec(...), ...]``.  Everything
that used to be written by hand in several places is derived from it:

* the registry (``dyncli.registry``: names, sections, model, solver, plots);
* the symbols and units the renderers print (``Result.symbols``/``.units``
  are filled from the declaration after the solver returns);
* the results tables of ``docs/types/TYPE.md`` (``<!-- results: TYPE -->``
  regions, ``python docs/hooks.py``) and ``docs/reference/results.md``;
* the JSON Schema of results (``dyncli schema TYPE --results``);
* the contract test (``tests/test_contract.py``).

A solver that produces a key its type does not declare is a bug:
:meth:`TypeSpec.check` raises :class:`UndeclaredResult` (exit 3, caught by
the tests).

This module imports nothing heavy: the registry imports every declaration at
start-up.
"""

from __future__ import annotations

import re
from typing import Any

# result kinds, for the JSON Schema of results and the docs; "list|number" is either (e.g. a list
# over times, or the single value of one instant)
KINDS = ("number", "vector", "tensor", "string", "bool", "list", "mapping", "any")


#: the capabilities a :class:`TypeSpec` declares as flags (``plots``: a plots module, not None)
CAPABILITIES = ("numpy_free", "symbolic", "exact", "plots")


class UndeclaredResult(RuntimeError):
    """A solver produced a result key its type does not declare (a bug)."""


class ResultSpec:
    """One result of a problem type.

    ``name`` is the JSON key; a name with a ``{placeholder}`` (e.g.
    ``"v_{point}"``) is a pattern matching every key with a word in place of
    the placeholder (results named after the input).  ``symbol`` is the
    notes' symbol the tables print, ``unit`` the SI unit ("" for
    dimensionless, strings and flags), ``equations`` the notes' equation
    numbers, ``meaning`` one line for the docs.  ``kind`` is the JSON shape.

    ``contract``: the name is binding (add, never rename): the contract test
    requires an example of ``problems/`` to produce it.  ``example``: False
    when no file of ``problems/`` reaches it (the unit tests do); every other
    declared result must appear in some example.  ``part_of``: the name is a
    field inside another result (e.g. the ``t``/``s``/``v``/``a`` of each
    rectilinear ``find`` entry): it gives a unit and symbol, never a key.

    A plain class with slots, not a dataclass: some 300 are built when the
    registry is imported at start-up.
    """

    __slots__ = ("name", "symbol", "unit", "equations", "meaning", "kind", "contract", "example", "part_of")

    def __init__(self, name: str, symbol: str = "", unit: str = "", equations: tuple[str, ...] = (),
                 meaning: str = "", kind: str = "any", contract: bool = False, example: bool = True,
                 part_of: str | None = None):
        self.name, self.symbol, self.unit, self.equations, self.meaning = name, symbol, unit, tuple(equations), meaning
        self.kind, self.contract, self.example, self.part_of = kind, contract, example, part_of

    def __repr__(self) -> str:
        return f"ResultSpec({self.name!r}, {self.symbol!r}, {self.unit!r}, {self.equations!r})"

    @property
    def is_pattern(self) -> bool:
        return "{" in self.name

    def matches(self, key: str) -> bool:
        if not self.is_pattern:
            return key == self.name
        return _pattern(self.name).fullmatch(key) is not None


_PATTERNS: dict[str, re.Pattern] = {}


def _pattern(name: str) -> re.Pattern:
    p = _PATTERNS.get(name)
    if p is None:
        parts = re.split(r"\{\w+\}", name)
        p = _PATTERNS[name] = re.compile(r"\w+?".join(re.escape(s) for s in parts))
    return p


def R(name: str, symbol: str = "", unit: str = "", equations: str = "", meaning: str = "", **kw) -> ResultSpec:
    """Shorthand for a :class:`ResultSpec`; ``equations`` is a space- or
    comma-separated string ("33.7, 33.8")."""
    return ResultSpec(name, symbol, unit, tuple(equations.replace(",", " ").split()), meaning, **kw)


class DeclarationError(ValueError):
    """A declaration is wrong (an unknown result kind or unit, a result declared twice): raised when the
    declaration is built, at import, naming the type and the result."""


def check_unit(unit: str) -> str | None:
    """None for a result unit dyncli knows (``""``, or one of :data:`dyncli.units.RESULT_UNITS`),
    else what is wrong with it."""
    from dyncli.units import RESULT_UNITS

    if not unit or unit in RESULT_UNITS:
        return None
    import difflib

    near = difflib.get_close_matches(unit, sorted(RESULT_UNITS), n=1)
    hint = f" (did you mean {near[0]!r}?)" if near else ""
    return (f"unknown unit {unit!r}{hint}; a result's unit is an SI unit of dyncli.units.DIMENSIONS or one of "
            "dyncli.units.EXTRA_RESULT_UNITS (add it there with what it measures)")


def check_kind(kind: str) -> str | None:
    """None for a known kind (one of :data:`KINDS`, or a union ``"list|number"`` of them), else
    what is wrong with it."""
    bad = [k for k in kind.split("|") if k not in KINDS]
    if not bad:
        return None
    import difflib

    near = difflib.get_close_matches(bad[0], KINDS, n=1)
    hint = f" (did you mean {near[0]!r}?)" if near else ""
    return f"unknown kind {bad[0]!r}{hint}; kinds: {', '.join(KINDS)}, or a union such as 'list|number'"


class TypeSpec:
    """A problem type: everything the project needs to know about it.

    ``name`` is the YAML ``type``; ``title`` one line on what it solves;
    ``sections`` the notes' sections ("§6", "§28, §23").  ``model``,
    ``solve`` and ``plots`` are ``"module:attr"`` references relative to the
    topic package (``"model:Rectilinear"``) or the objects themselves (a
    test-only type); they are imported only when used (``plots`` is None for
    a type that draws no plot of its own).  ``template`` and
    ``example`` are paths relative to the repository root.  ``package`` is
    filled by the registry ("dyncli.topics.rectilinear").  ``gallery`` is the row of
    docs/gallery.md for the example (what it shows, one line; the file and sections are added):
    the gallery's generated regions list it, so the page is never edited by hand for a new type.

    Capabilities, as flags (every list of types with a capability is derived from them, and the
    tests check each flag against what the type does):

    * ``numpy_free``: its example is solved in plain floats, without importing numpy (cold start);
    * ``symbolic``: it has a ``--symbolic`` view (formulas in the tables);
    * ``exact``: it has an exact route (``accuracy.method: exact``: elliptic functions, Kepler);
    * ``plots`` (not None): it draws plots of its own for ``--plot``.

    Each result's ``kind`` and ``unit`` are checked here: a misspelt kind or an unknown unit is a
    :class:`DeclarationError` at import, naming the type and the result (a kind would otherwise drop
    the result from the schema; a unit would print unchecked and escape ``--units``).
    """

    def __init__(self, name: str, title: str, sections: str, model: Any, solve: Any = "solver:solve",
                 results: list[ResultSpec] | None = None, plots: Any = None, template: str = "",
                 example: str = "", package: str = "", motion: dict | None = None, gallery: str = "",
                 numpy_free: bool = False, symbolic: bool = False, exact: bool = False):
        self.name, self.title, self.sections, self.model, self.solve = name, title, sections, model, solve
        #: a type whose solver reports its motion at the times of ``at`` and answers ``find`` by
        #: solving at other times (dyncli.motion_find.resolved): ``{"rates": {result: its rate},
        #: "fast": [angular rates that set the search grid]}``; None: the solver answers find itself
        self.motion = motion
        self.results = list(results or [])
        self.plots, self.example, self.package, self.gallery = plots, example, package, gallery
        self.numpy_free, self.symbolic, self.exact = numpy_free, symbolic, exact
        self.template = template or f"dyncli/templates/{name}.yaml"
        self._by_name: dict[str, ResultSpec] = {}
        self._patterns: list[ResultSpec] = []
        for r in self.results:
            wrong = check_kind(r.kind) or check_unit(r.unit)
            if wrong:
                raise DeclarationError(f"type {name!r}, result {r.name!r}: {wrong}")
            if r.part_of is not None:
                continue
            if r.name in self._by_name or any(p.name == r.name for p in self._patterns):
                raise DeclarationError(f"type {name!r}, result {r.name!r}: declared twice")
            if r.is_pattern:
                self._patterns.append(r)
            else:
                self._by_name[r.name] = r

    def __repr__(self) -> str:
        return f"TypeSpec({self.name!r}, {len(self.results)} results)"

    def ref(self, what: Any) -> Any:
        """``"module:attr"`` made absolute (``package.module:attr``)."""
        if isinstance(what, str) and self.package and not what.startswith(self.package):
            return f"{self.package}.{what}"
        return what

    # --- results -------------------------------------------------------------
    def spec_of(self, key: str) -> ResultSpec | None:
        r = self._by_name.get(key)
        if r is not None:
            return r
        return next((p for p in self._patterns if p.matches(key)), None)

    def check(self, results: dict) -> None:
        """Raise :class:`UndeclaredResult` for a key the type does not declare."""
        bad = [k for k in results if self.spec_of(k) is None]
        if bad:
            raise UndeclaredResult(
                f"type {self.name!r} produced undeclared result(s) {bad}: declare them in "
                f"{self.package or 'its topic package'}.results")

    def symbols_units(self, keys) -> tuple[dict[str, str], dict[str, str]]:
        """Symbols and units for ``keys`` (result names) plus every ``part_of``
        field, as the renderers read them."""
        sym, uni = self._fixed_symbols_units()
        for k in keys:
            r = self.spec_of(k)
            if r is not None and r.is_pattern:
                if r.symbol:
                    sym[k] = _fill(r.symbol, r.name, k)
                if r.unit:
                    uni[k] = r.unit
        return sym, uni

    def _fixed_symbols_units(self) -> tuple[dict[str, str], dict[str, str]]:
        """Fresh copies of the symbols and units of the non-pattern results
        (computed once per declaration: a sweep attaches thousands of results)."""
        key = tuple(self.results)
        cached = getattr(self, "_fixed_cache", None)
        if cached is None or cached[0] != key:
            sym: dict[str, str] = {}
            uni: dict[str, str] = {}
            for r in self.results:
                if r.part_of is not None or not r.is_pattern:
                    if r.symbol:
                        sym[r.name] = r.symbol
                    if r.unit:
                        uni[r.name] = r.unit
            cached = self._fixed_cache = (key, sym, uni)
        return dict(cached[1]), dict(cached[2])

    def attach(self, result) -> Any:
        """Check a solver's :class:`~dyncli.result.Result` and fill its
        ``symbols``/``units`` from the declaration (a solver's own entries,
        e.g. a test type's, are kept)."""
        sym, uni = self._checked(tuple(result.results))
        result.symbols = {**sym, **result.symbols}
        result.units = {**uni, **result.units}
        return result

    def _checked(self, keys: tuple) -> tuple[dict[str, str], dict[str, str]]:
        """:meth:`check` then :meth:`symbols_units` of ``keys``, remembered per
        tuple of keys (a type's solves return the same keys: a sweep asks
        thousands of times); fresh dicts each call."""
        cache: tuple[int, dict] | None = getattr(self, "_keys_cache", None)
        if cache is None or cache[0] != len(self.results):
            cache = (len(self.results), {})
            self._keys_cache = cache
        hit = cache[1].get(keys)
        if hit is None:
            self.check(dict.fromkeys(keys))
            hit = self.symbols_units(keys)
            if len(cache[1]) < 256:
                cache[1][keys] = hit
        return dict(hit[0]), dict(hit[1])

    def top_level(self) -> list[ResultSpec]:
        return [r for r in self.results if r.part_of is None]


def _fill(symbol: str, pattern: str, key: str) -> str:
    """``"v_{point}"``, key ``"v_A"``: the symbol with ``{point}`` -> ``A``."""
    names = re.findall(r"\{(\w+)\}", pattern)
    regex = re.compile("".join(
        f"(?P<{p[1:-1]}>\\w+?)" if p.startswith("{") else re.escape(p)
        for p in re.split(r"(\{\w+\})", pattern) if p))
    m = regex.fullmatch(key)
    if not m:
        return symbol
    for n in names:
        symbol = symbol.replace("{" + n + "}", m.group(n))
    return symbol


_JSON_KIND: dict[str, dict[str, Any]] = {
    "number": {"type": ["number", "null"]},
    "vector": {"type": ["array", "null"], "items": {"type": ["number", "string", "null"]}, "minItems": 3, "maxItems": 3},
    "tensor": {"type": ["array", "null"], "items": {"type": "array"}},
    "string": {"type": ["string", "null"]},
    "bool": {"type": ["boolean", "null"]},
    "list": {"type": ["array", "null"]},
    "mapping": {"type": ["object", "null"]},
}


def _json_kind(kind: str) -> dict[str, Any]:
    """The JSON Schema of a result kind; of a union "a|b", its types (every value of either)."""
    if "|" not in kind:
        return dict(_JSON_KIND.get(kind, {}))
    types: list[str] = []
    for k in kind.split("|"):
        types += [t for t in _JSON_KIND[k]["type"] if t not in types]
    return {"type": types}


def results_schema(spec: TypeSpec) -> dict:
    """The JSON Schema of a type's ``results`` object (draft 2020-12)."""
    props: dict[str, Any] = {}
    patterns: dict[str, Any] = {}
    for r in spec.top_level():
        s: dict[str, Any] = _json_kind(r.kind)
        desc = r.meaning + (f" [{r.unit}]" if r.unit else "")
        if r.equations:
            desc += " (" + ", ".join(r.equations) + ")"
        s["description"] = desc.strip()
        if r.symbol:
            s["title"] = r.symbol
        if r.unit:
            s["x-unit"] = r.unit
        if r.is_pattern:
            patterns["^" + _pattern(r.name).pattern + "$"] = s
        else:
            props[r.name] = s
    out: dict[str, Any] = {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": f"dyncli results of {spec.name}",
        "type": "object",
        "properties": props,
        "additionalProperties": False,
    }
    if patterns:
        out["patternProperties"] = patterns
    return out
