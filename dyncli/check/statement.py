"""Statement text of a key (docs/check.md, "Statement text"): per question
and per problem ``text:`` with ``{name}`` replaced by the student's value of
that parameter, and the numbers a problem uses, for the sheets.

The formatter is deliberately small: a field is ``{name}`` or
``{name:SPEC}`` where ``name`` is one of the problem's ``params`` and SPEC
is ``[+][,][.N][e|f|g|%]`` (N at most 2 digits); ``{{`` and ``}}`` are
literal braces.  Nothing is evaluated, no attribute or index is looked up:
``{v0.__class__}`` or ``{v0[0]}`` is refused when the key is read.
"""

from __future__ import annotations

import re
from functools import lru_cache
from typing import Any

from dyncli.check.safe import shown

MAX_TEXT = 4000
_SPEC = re.compile(r"^\+?,?(?:\.\d{1,2})?[eEfFgG%]?$")
_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")


class TextError(ValueError):
    """A statement text the formatter refuses (the message names the fix)."""


def parse_text(text: str) -> list:
    """Pieces: literal strings and ``(name, spec)`` fields (TextError if malformed)."""
    out: list = []
    lit: list[str] = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in "{}" and text[i:i + 2] in ("{{", "}}"):
            lit.append(c)
            i += 2
            continue
        if c == "}":
            raise TextError("a single '}' in text: write '}}' for a literal brace")
        if c != "{":
            lit.append(c)
            i += 1
            continue
        j = text.find("}", i)
        body = text[i + 1:j] if j > 0 else ""
        if j < 0 or "{" in body:
            raise TextError("a '{' without its '}' in text: write '{{' for a literal brace")
        name, _, spec = body.partition(":")
        if not _NAME.match(name):
            raise TextError(f"'{{{shown(body)}}}' in text: a field is {{name}} or {{name:.3g}} with a params name "
                            "(no attribute, index or expression)")
        if not _SPEC.match(spec):
            raise TextError(f"'{{{shown(body)}}}' in text: the format '{shown(spec)}' is not one of "
                            "[+][,][.N][e|f|g|%] (e.g. .3g, .2f, ,.0f)")
        if lit:
            out.append("".join(lit))
            lit = []
        out.append((name, spec))
        i = j + 1
    if lit:
        out.append("".join(lit))
    return out


def check_text(raw: Any, names: set[str]) -> list:
    """The parsed text, or TextError naming an unknown name (with "did you mean")."""
    from dyncli.expr import did_you_mean

    if not isinstance(raw, str) or not raw.strip() or len(raw) > MAX_TEXT:
        raise TextError(f"text must be the statement (1 to {MAX_TEXT} characters), with {{name}} for a "
                        "params value")
    pieces = parse_text(raw.strip())
    for p in pieces:
        if isinstance(p, tuple) and p[0] not in names:
            known = ", ".join(sorted(names)) or "none"
            raise TextError(f"unknown name '{{{shown(p[0])}}}' in text{did_you_mean(p[0], names)}: the names are "
                            f"this problem's params ({known})")
    return pieces


def render_text(pieces: list, values: dict[str, Any]) -> str:
    """The text with the student's values; a carried value is its wording."""
    out = []
    for p in pieces:
        if isinstance(p, str):
            out.append(p)
            continue
        v = values[p[0]]
        if isinstance(v, str):
            out.append(v)
        else:
            out.append(format(float(v), p[1]) if p[1] else f"{v:g}")
    return "".join(out)


# ---------------------------------------------------------------------------
# the numbers a problem uses


_QTY = re.compile(r"^\s*([-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)\s*([^\d\s].*)$")


def param_values(raw_params: dict, drawn: dict[str, float], units: dict[str, str | None],
                 carried: dict[str, str]) -> tuple[dict[str, Any], dict[str, str]]:
    """({name: value as the instructor writes it}, {name: unit}) of a
    problem's params: drawn values in their variant unit, fixed numbers as
    written ("2 mm" is 2 in mm), expressions evaluated (SI), carried inputs
    as "your answer to Q"."""
    from dyncli.expr.params import resolve_params

    vals: dict[str, Any] = {}
    shown_units: dict[str, str] = {}
    pending = {}
    for n, v in raw_params.items():
        if n in carried:
            vals[n] = f"your answer to {carried[n]}"
        elif n in drawn:
            vals[n] = drawn[n]
            if u := units.get(n):
                shown_units[n] = u
        elif isinstance(v, (int, float)) and not isinstance(v, bool):
            vals[n] = v
        elif isinstance(v, str) and (m := _QTY.match(v)) and m.group(2).strip():
            vals[n], shown_units[n] = float(m.group(1)), m.group(2).strip()
        else:
            pending[n] = v
    if pending:
        try:
            si = resolve_params(_si_params(raw_params, drawn, units))
        except Exception:  # noqa: BLE001 - the solve reports an invalid params entry
            si = {}
        for n, v in pending.items():
            vals[n] = si[n] if n in si else shown(v)
    return vals, shown_units


def _si_params(raw: dict, drawn: dict, units: dict) -> dict:
    """The params with the drawn values (a carried input keeps the key's default)."""
    return {n: ((f"{drawn[n]!r} {units[n]}" if units.get(n) else drawn[n]) if n in drawn else v)
            for n, v in raw.items()}


SKIP = ("type", "title", "params", "accuracy")


def param_units(ptype: str | None, raw: Any, names) -> dict[str, str]:
    """The unit of a params name used as a whole field's value (``s1: s0``
    gives s0 the unit of s1)."""
    out: dict[str, str] = {}
    if not isinstance(raw, dict):
        return out
    leaves: list[tuple[tuple, Any]] = []
    for k, v in raw.items():
        if k not in SKIP:
            _leaves(v, (k,), leaves)
    for path, x in leaves:
        if isinstance(x, str) and x.strip() in names and x.strip() not in out:
            u = field_unit(ptype, path)
            if u:
                out[x.strip()] = u
    return out


def given_data(ptype: str | None, raw: dict, values: dict[str, Any], units: dict[str, str]) -> list[tuple[str, str]]:
    """(field, shown value with unit) for every number the problem's fields
    use, beyond its params: ``v1 = v0 = 18.5 m/s``, ``find: t = 2 s``."""
    out = []
    for k, v in raw.items():
        if k in SKIP:
            continue
        leaves: list[tuple[tuple, Any]] = []
        _leaves(v, (k,), leaves)
        for path, x in leaves:
            unit = field_unit(ptype, path)
            label = "find: " + ".".join(str(p) for p in path[1:] if not isinstance(p, int)) if k == "find" \
                else ".".join(str(p) for p in path)
            out.append((label, _show(x, unit, values, units)))
    return out


def _leaves(x: Any, path: tuple, out: list) -> None:
    if isinstance(x, dict):
        for k, v in x.items():
            _leaves(v, path + (k,), out)
    elif isinstance(x, list) and not (x and all(isinstance(c, (int, float, str)) and not isinstance(c, bool)
                                                 for c in x)):
        for i, v in enumerate(x):
            _leaves(v, path + (i,), out)
    elif x is not None and not isinstance(x, bool):
        out.append((path, x))


def _show(x: Any, unit: str, values: dict, units: dict) -> str:
    if isinstance(x, list):
        inner = ", ".join(_show(c, "", values, units) for c in x)
        return (f"({inner})" if len(x) == 3 else inner) + (f" {unit}" if unit else "")
    if isinstance(x, str) and x.strip() in values:
        name = x.strip()
        v = values[name]
        return f"{name} = " + (v if isinstance(v, str) else f"{v:g}" + (f" {units.get(name) or unit}".rstrip()))
    if isinstance(x, (int, float)):
        return f"{x:g}" + (f" {unit}" if unit else "")
    return shown(x)


@lru_cache(maxsize=64)
def _schema(ptype: str) -> dict:
    from dyncli.schema import json_schema

    try:
        return json_schema(ptype)
    except KeyError:
        return {}


@lru_cache(maxsize=64)
def _results_schema(ptype: str) -> dict:
    from dyncli.schema import results_json_schema

    try:
        return results_json_schema(ptype)
    except KeyError:
        return {}


def declared_dimensionless(ptype: str | None, answer: str) -> bool:
    """True when the type declares the answer's result as a plain number
    without a unit (an amplification, a ratio, a count of turns)."""
    if not ptype:
        return False
    prop = (_results_schema(ptype).get("properties") or {}).get(str(answer).split(".")[0])
    if not isinstance(prop, dict) or "." in str(answer) or prop.get("x-unit"):
        return False
    types = prop.get("type")
    return types == "number" or (isinstance(types, list) and "number" in types)


def field_unit(ptype: str | None, path: tuple) -> str:
    """The SI unit of a problem field (from its declared dimension), or ''."""
    from dyncli.units import si_unit

    if not ptype:
        return ""
    sch = _schema(ptype)
    node: Any = sch
    for p in path:
        node = _resolve(node, sch)
        if isinstance(p, int):
            node = node.get("items") if isinstance(node, dict) else None
        else:
            node = (node.get("properties") or {}).get(p) if isinstance(node, dict) else None
        if node is None:
            return ""
    dim = _dim(node, sch) or _dim(_resolve(node.get("items"), sch), sch) if isinstance(node, dict) else None
    return si_unit(dim) if dim else ""


def _resolve(node: Any, sch: dict) -> Any:
    for _ in range(8):
        if not isinstance(node, dict):
            return node
        if "$ref" in node:
            node = sch.get("$defs", {}).get(node["$ref"].rsplit("/", 1)[-1], {})
        elif "anyOf" in node and "properties" not in node and "items" not in node:
            node = next((b for b in node["anyOf"] if isinstance(b, dict) and ("$ref" in b or "properties" in b
                                                                              or "items" in b)), node["anyOf"][0])
        else:
            return node
    return node


def _dim(node: Any, sch: dict, depth: int = 0) -> str | None:
    if not isinstance(node, dict) or depth > 6:
        return None
    if node.get("x-dimension"):
        return node["x-dimension"]
    for b in node.get("anyOf", []):
        d = _dim(b, sch, depth + 1)
        if d:
            return d
    return None


# ---------------------------------------------------------------------------
# reading a key's texts (called by dyncli.check.keyfile's reader, as ``self``)


def read_problem_texts(self, raw: Any, Question) -> None:
    """``problems: [{problem: FILE, index: N, text: ...}]``: a statement per problem."""
    from dyncli.check.tolerance import FieldError

    if not isinstance(raw, list) or len(raw) > 1000:
        self.diag(("problems",), "problems must be a list of {problem: FILE, index: N, text: STATEMENT}")
        return
    for i, item in enumerate(raw):
        path = ("problems", i)
        if not isinstance(item, dict) or not {"problem", "text"} <= set(item) \
                or not set(item) <= {"problem", "index", "text"}:
            self.diag(path, "expected {problem: FILE, index: N, text: STATEMENT} (index when the file holds "
                            "several problems)")
            continue
        q = Question(f"problems.{i}", prefix=path)
        try:
            self.problem(q, item, path)
        except FieldError as exc:
            self.diag(exc.path, exc.message, exc.key)
            continue
        self.key.texts[(q.problem.file, q.problem.index)] = (path + ("text",), item["text"], q.problem)



def check_texts(self, names, Question) -> None:
    """Every text parsed, its names among its problem's params (a diagnostic at its field otherwise)."""
    todo = [(q.prefix + ("text",), q.text, q.problem, q) for q in self.key.questions if q.text is not None]
    todo += [(path, text, lp, None) for path, text, lp in self.key.texts.values()]
    for path, text, lp, q in todo:
        try:
            pieces = check_text(text, names(Question("", problem=lp)))
        except TextError as exc:
            self.diag(path, str(exc), key=False)
            continue
        if q is not None:
            q.text = pieces
        else:
            self.key.texts[(lp.file, lp.index)] = pieces
