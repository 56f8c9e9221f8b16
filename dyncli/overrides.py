"""Overrides and sweeps of problem fields (docs/cli.md): ``--set PATH=VALUE``
and ``--sweep PATH=LO:HI:N | PATH=V1,V2,...``, and ``dyncli.solve(...,
**overrides)``.

The machinery is reusable: :func:`parse_set` / :func:`parse_sweep` read the
option texts, :func:`expand` turns loaded problems into one validated
problem per (problem, sweep point), each carrying ``swept`` (the values of
that point).  A path is a field (``k``), a dotted field (``base.omega``,
``find.0.t``, ``vA1.0``) or a ``params`` name (``--set k=500`` sets
``params.k`` when the problem defines a parameter ``k``; a parameter feeds
every expression that uses it).  Overrides apply to every problem whose type
has the field; a path that no problem has is an :class:`OverrideError`
(exit 2) with a "did you mean".

Sweeps of top-level numeric fields are validated once: each further point
copies the validated model and validates only the swept fields
(``validate_assignment``, which also runs the model's checks).  The second
and the last point are checked against a full validation first; any difference (a field
derived from a swept one, an expression field) switches that problem back
to validating every point in full.
"""

from __future__ import annotations

import copy
import itertools
import math
import re
import typing
from dataclasses import dataclass, replace
from typing import Any

from dyncli.chain import link
from dyncli.errors import InputError

MAX_POINTS = 200_000
_FLOAT = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)[eE][-+]?\d+")


class OverrideError(InputError):
    """A bad ``--set``/``--sweep`` (exit 2); the message names the option."""


@dataclass(frozen=True)
class Assign:
    """One ``--set`` (one value) or ``--sweep`` (several values)."""

    option: str          # "--set" / "--sweep" (or "override" from Python)
    path: str            # as written: "k", "base.omega"
    values: tuple        # parsed values
    sweep: bool = False

    @property
    def parts(self) -> tuple:
        return tuple(int(p) if p.isdigit() else p for p in self.path.split("."))

    def label(self) -> str:
        return f"{self.option} {self.path}"


def _split_spec(spec: str, option: str) -> tuple[str, str]:
    path, eq, text = spec.partition("=")
    path = path.strip()
    if not eq or not path:
        raise OverrideError(f"{option} {spec!r}: expected PATH=VALUE, e.g. {option} k=500")
    if any(not p for p in path.split(".")):
        raise OverrideError(f"{option} {spec!r}: the path {path!r} has an empty part")
    if not text.strip():
        raise OverrideError(f"{option} {spec!r}: a value is required after '='")
    return path, text


def _yaml_value(text: str, option: str, spec: str) -> Any:
    from dyncli.yamlsafe import YamlError, load

    try:
        value = load(text).data
        if isinstance(value, str) and _FLOAT.fullmatch(value.strip()):
            return float(value)   # YAML 1.1 reads 1e6 as a string; the contract says it is a number
        return value
    except YamlError as exc:
        raise OverrideError(f"{option} {spec!r}: the value is not a YAML scalar or list ({exc.message})") from None


def parse_set(spec: str, option: str = "--set") -> Assign:
    """``"k=500"`` -> Assign(path "k", values (500,)).  VALUE is a YAML scalar
    or list; an expression string is kept for the field to read."""
    path, text = _split_spec(spec, option)
    return Assign(option, path, (_yaml_value(text, option, spec),))


def parse_sweep(spec: str, option: str = "--sweep") -> Assign:
    """``"k=100:1000:10"`` (10 points, ends included) or ``"zeta=0.1,0.2"``."""
    path, text = _split_spec(spec, option)
    if ":" in text and not text.lstrip().startswith(("[", "{", '"', "'")):
        return Assign(option, path, _range(text, option, spec), sweep=True)
    items = _top_level_split(text)
    if any(not i.strip() for i in items):
        raise OverrideError(f"{option} {spec!r}: an empty value in the list")
    return Assign(option, path, tuple(_yaml_value(i, option, spec) for i in items), sweep=True)


def _range(text: str, option: str, spec: str) -> tuple:
    from dyncli.expr import constant

    parts = text.split(":")
    if len(parts) != 3:
        raise OverrideError(f"{option} {spec!r}: a range is LO:HI:N (N points, both ends included)")
    try:
        lo, hi = constant(parts[0].strip()), constant(parts[1].strip())
    except InputError as exc:
        raise OverrideError(f"{option} {spec!r}: {exc.message}") from None
    n_text = parts[2].strip()
    if not n_text.isdigit() or len(n_text) > 7:
        raise OverrideError(f"{option} {spec!r}: N must be a whole number of points from 1 to {MAX_POINTS:,}")
    n = int(n_text)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise OverrideError(f"{option} {spec!r}: LO and HI must be finite")
    if n < 1 or n > MAX_POINTS or (n == 1 and lo != hi):
        raise OverrideError(f"{option} {spec!r}: N must be from 2 to {MAX_POINTS:,} (1 only when LO = HI)")
    if n == 1:
        return (lo,)
    step = (hi - lo) / (n - 1)
    if not math.isfinite(step):
        step = hi / (n - 1) - lo / (n - 1)
    return tuple(lo + i * step for i in range(n - 1)) + (hi,)


def _top_level_split(text: str) -> list[str]:
    """Split at commas outside brackets and quotes: ``[1,0,0],[0,1,0]``."""
    out, cur, depth, quote = [], list[str](), 0, None
    for ch in text:
        if quote:
            quote = None if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch in "[{(":
            depth += 1
        elif ch in "]})":
            depth -= 1
        elif ch == "," and depth == 0:
            out.append("".join(cur))
            cur = []
            continue
        cur.append(ch)
    out.append("".join(cur))
    return out


# ---------------------------------------------------------------- paths

def _models(tp) -> list:
    from pydantic import BaseModel

    if isinstance(tp, type) and issubclass(tp, BaseModel):
        return [tp]
    return [m for a in typing.get_args(tp) for m in _models(a)]


def _origins(tp) -> set:
    o = typing.get_origin(tp)
    out = {o} if o is not None else ({tp} if isinstance(tp, type) else set())
    for a in typing.get_args(tp):
        out |= _origins(a)
    return out


def _step(tp, part) -> tuple[list, list[str]]:
    """Annotations reached from ``tp`` by ``part``; and the field names that
    were possible there (for "did you mean")."""
    nxt, names = [], []
    for m in _models(tp):
        names += list(m.model_fields)
        if isinstance(part, str) and part in m.model_fields:
            nxt.append(m.model_fields[part].annotation)
    origins = _origins(tp)
    if isinstance(part, int) and origins & {list, tuple}:
        nxt.append(typing.Any)
    if isinstance(part, str) and (dict in origins or tp is typing.Any) and not nxt:
        nxt.append(typing.Any)
    if tp is typing.Any:
        nxt.append(typing.Any)
    return nxt, names


def field_path(cls, parts: tuple) -> tuple[bool, str]:
    """(True, "") when ``parts`` names a field of model ``cls``; else
    (False, hint) with a "did you mean" for the first unknown part."""
    tps: list = [cls]
    for i, part in enumerate(parts):
        nxt, names = [], []
        for tp in tps:
            n, nm = _step(tp, part)
            nxt += n
            names += nm
        if not nxt:
            from dyncli.expr import did_you_mean

            prefix = ".".join(str(p) for p in parts[:i])
            hint = did_you_mean(str(part), names)
            if hint and prefix:
                hint = hint.replace("'", f"'{prefix}.", 1)
            return False, hint
        tps = nxt
    return True, ""


def target(lp, a: Assign) -> tuple[Any, ...] | None:
    """Where ``a`` lands in problem ``lp`` (a path tuple inside ``lp.raw``),
    or None when this problem has no such field or parameter."""
    from dyncli import registry

    raw = lp.raw if isinstance(lp.raw, dict) else {}
    parts = a.parts
    params = raw.get("params")
    if len(parts) == 1 and isinstance(params, dict) and parts[0] in params:
        return ("params", parts[0])
    if lp.type not in registry.TYPES or not registry.available(lp.type):
        return None
    ok, _ = field_path(registry.model_class(lp.type), parts)
    return parts if ok and parts[0] != "type" else None


def _unknown(problems, a: Assign) -> OverrideError:
    from dyncli import registry
    from dyncli.expr import did_you_mean

    hint = ""
    names: list[str] = []
    for lp in problems:
        if lp.type in registry.TYPES and registry.available(lp.type):
            ok, h = field_path(registry.model_class(lp.type), a.parts)
            hint = hint or h
        params = lp.raw.get("params") if isinstance(lp.raw, dict) else None
        names += list(params) if isinstance(params, dict) else []
    if not hint and len(a.parts) == 1:
        hint = did_you_mean(a.path, names)
    return OverrideError(f"{a.label()}: no problem has a field or parameter {a.path!r}{hint}")


def put(raw: dict, path: tuple, value: Any) -> dict:
    """A copy of ``raw`` with ``path`` set to ``value`` (mappings on the way
    are created; a list index must exist)."""
    out = copy.deepcopy(raw)
    node = out
    for i, part in enumerate(path[:-1]):
        nxt = path[i + 1]
        if isinstance(node, dict):
            if not isinstance(node.get(part), (dict, list)):
                node[part] = {}
            node = node[part]
        elif isinstance(node, list) and isinstance(part, int) and part < len(node):
            if not isinstance(node[part], (dict, list)):
                node[part] = {} if isinstance(nxt, str) else []
            node = node[part]
        else:
            raise InputError(f"there is no entry {part} to set", ".".join(str(p) for p in path[: i + 1]))
    last = path[-1]
    if isinstance(node, dict):
        node[last] = value
    elif isinstance(node, list) and isinstance(last, int) and last < len(node):
        node[last] = value
    else:
        raise InputError(f"there is no entry {last} to set (the list has {len(node) if isinstance(node, list) else 0})",
                         ".".join(str(p) for p in path))
    return out


# ---------------------------------------------------------------- expansion

FAST_EXCLUDED = ("type", "title", "params", "g", "accuracy")


def expand(problems: list, assigns: list[Assign], lazy: bool = False):
    """One validated problem per (problem, point of the sweeps' product), in input order; ``--set``
    values apply to every point.  A problem that has none of the swept fields appears once (a chained
    one once per point of its source: dyncli.chain.link).  Raises :class:`OverrideError` for a path
    that no problem has, or a product beyond ``MAX_POINTS``.  ``lazy``: an iterator making them one at
    a time (a streamed output holds one point; not when a problem is chained: it needs its source's)."""
    if not assigns and not any(getattr(lp, "chain", None) for lp in problems):
        return iter(problems) if lazy else list(problems)     # (each problem once, as it is)
    points = _points(problems, assigns)
    if lazy and not any(getattr(lp, "chain", None) for lp in problems):
        return points
    return link(list(points))


def _points(problems: list, assigns: list[Assign]):
    for a in assigns:
        if not any(target(lp, a) for lp in problems):
            raise _unknown(problems, a)
    _no_path_twice(problems, assigns)
    n = math.prod(len(a.values) for a in assigns if a.sweep)
    if n > MAX_POINTS:
        raise OverrideError(f"--sweep: {n:,} combinations; at most {MAX_POINTS:,} per run")
    return (p for lp in problems for p in _expand_one(lp, assigns))


def _no_path_twice(problems, assigns: list[Assign]) -> None:
    """A field given values twice (two --sweep of k, --set and --sweep of k, base and base.omega) is refused."""
    for lp in problems:
        hits = [(a, t) for a in assigns if (t := target(lp, a)) is not None]
        for i, (a, t) in enumerate(hits):
            for b, u in hits[:i]:
                if t[:len(u)] == u or u[:len(t)] == t:
                    raise OverrideError(f"{b.label()} and {a.label()}: both give {'.'.join(map(str, (t if len(t) <= len(u) else u)))!r} "
                                        "its values; give each field once (a sweep of several values: one --sweep PATH=V1,V2,...)")


def _expand_one(lp, assigns: list[Assign]):
    from dyncli import registry

    hits = [(a, t) for a in assigns if (t := target(lp, a)) is not None]
    if not hits:
        return (lp,)
    sets = [(a, t) for a, t in hits if not a.sweep]
    sweeps = [(a, t) for a, t in hits if a.sweep]
    base = lp.raw
    try:
        for a, t in sets:
            base = put(base, t, a.values[0])
    except InputError as exc:
        return (_failed(lp, exc, hits),)
    if not sweeps:
        return (_validated(lp, base, {}, hits),)
    points = list(itertools.product(*[a.values for a, _ in sweeps]))
    fast = all(len(t) == 1 and t[0] not in FAST_EXCLUDED for _, t in sweeps) and registry.available(lp.type or "")
    return (_fast if fast else _full)(lp, base, sweeps, hits, points)


def _swept(sweeps, point) -> dict:
    return {a.path: v for (a, _), v in zip(sweeps, point)}


def _full(lp, base, sweeps, hits, points):
    for point in points:
        try:
            raw = base
            for (_, t), v in zip(sweeps, point):
                raw = put(raw, t, v)
        except InputError as exc:
            yield _failed(lp, exc, hits, _swept(sweeps, point))
            continue
        yield _validated(lp, raw, _swept(sweeps, point), hits)


def _fast(lp, base, sweeps, hits, points):
    """One point at a time, the fast route of the module's docstring (the
    second and the last point checked first)."""
    from dyncli.loader import params_of

    first = _validated(lp, _with(base, sweeps, points[0]), _swept(sweeps, points[0]), hits)
    yield first
    if first.error is not None or first.model is None or len(points) == 1:   # None: a chained problem
        yield from _full(lp, base, sweeps, hits, points[1:])
        return
    validator, names = type(first.model).__pydantic_validator__, [t[0] for _, t in sweeps]
    ctx = {"params": params_of(base), "base_dir": lp.base_dir}

    def quick(point):          # None when it fails: the full validation reports it
        try:
            m = first.model.model_copy()
            for name, v in zip(names, point):
                validator.validate_assignment(m, name, v, context=ctx)
            return m
        except Exception:  # noqa: BLE001
            return None

    for k in sorted({1, len(points) - 1}):
        m, ref = quick(points[k]), _validated(lp, _with(base, sweeps, points[k]), _swept(sweeps, points[k]), hits)
        if m is not None and (ref.error is not None or ref.model.model_dump(warnings=False) != m.model_dump(warnings=False)):
            yield from _full(lp, base, sweeps, hits, points[1:])
            return
    for point in points[1:]:
        raw, swept, m = _with(base, sweeps, point), _swept(sweeps, point), quick(point)
        yield _validated(lp, raw, swept, hits) if m is None else replace(lp, raw=raw, model=m, error=None, swept=swept)


def _with(base: dict, sweeps, point) -> dict:
    """``base`` with top-level swept fields set (a shallow copy suffices)."""
    raw = dict(base)
    for (_, t), v in zip(sweeps, point):
        raw[t[0]] = v
    return raw


def _validated(lp, raw: dict, swept: dict, hits):
    from dyncli.loader import validate

    title = raw.get("title") if isinstance(raw, dict) else None
    new = replace(lp, raw=raw, model=None, error=None, swept=swept,
                  title=title if isinstance(title, str) and title and title != lp.raw.get("title") else lp.title)
    validate(new)
    if new.error is not None:
        for d in [new.error, *new.error.others]:
            _blame(d, hits)
    return new


def _failed(lp, exc: InputError, hits, swept: dict | None = None):
    new = replace(lp, model=None, swept=swept or {}, error=lp.diagnostic(exc.path, exc.message))
    _blame(new.error, hits)
    return new


def _blame(d, hits) -> None:
    """Say which option set the field a message is about."""
    for a, t in hits:
        dotted = ".".join(str(p) for p in t)
        if d.path and (d.path == dotted or d.path.startswith(dotted + ".") or dotted.startswith(d.path + ".")):
            d.message += f" (from {a.label()})"
            return
