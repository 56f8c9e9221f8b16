"""Angles written as bare numbers that look like degrees.

Every field that takes an angle is declared with ``dim="angle"`` (``Num``,
``Vec3``, ``ExprField`` of :mod:`dyncli.fields`); its value is in radians.
``theta: 30`` meant as 30° is the most common slip of all and gives a
plausible wrong answer, so a bare number (a YAML number, or a string that
is only a number) larger in size than a full turn, 2π, gets a warning that
names the field and says how to write degrees (``30*deg``).  ``30*deg``,
``0.5`` and ``pi/2`` never warn.  Knows no topic: the fields are found
through the declarations of the validated model.
"""

from __future__ import annotations

import math
import re
import typing
from typing import Any, Iterator

FULL_TURN = 2 * math.pi
_NUMBER = re.compile(r"^\s*[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?\s*$")


def is_angle(info) -> bool:
    """Whether a pydantic field (its FieldInfo) is declared with ``dim="angle"``."""
    return any(_angle_meta(m) for m in info.metadata) or _angle_type(info.annotation)


def _angle_meta(meta: Any) -> bool:
    schema = getattr(meta, "json_schema", None)
    return isinstance(schema, dict) and schema.get("x-dimension") == "angle"


def _angle_type(tp: Any) -> bool:
    if typing.get_origin(tp) is typing.Annotated:
        if any(_angle_meta(m) for m in tp.__metadata__):
            return True
    return any(_angle_type(a) for a in typing.get_args(tp) or ())


def angle_fields(model: Any, raw: Any, path: tuple = ()) -> Iterator[tuple[tuple, Any]]:
    """(path, value as written) of every angle field given in ``raw``, the
    input of the validated ``model`` (nested models and lists of them too)."""
    from pydantic import BaseModel

    if not isinstance(raw, dict):
        return
    for name, key, angle in _fields(type(model)):
        if key not in raw:
            continue
        value, written, here = getattr(model, name, None), raw[key], path + (key,)
        if angle:
            yield here, written
        elif isinstance(value, BaseModel):
            yield from angle_fields(value, written, here)
        elif isinstance(value, (list, tuple)) and isinstance(written, list):
            for i, (v, w) in enumerate(zip(value, written)):
                if isinstance(v, BaseModel):
                    yield from angle_fields(v, w, here + (i,))
        elif isinstance(value, dict) and isinstance(written, dict):
            for k, v in value.items():
                if isinstance(v, BaseModel) and k in written:
                    yield from angle_fields(v, written[k], here + (k,))


_FIELDS: dict[Any, list[tuple[str, str, bool]]] = {}


def _fields(cls: Any) -> list[tuple[str, str, bool]]:
    """(name, key as written, is an angle) of the fields of a model class that are angles or may
    hold a model with one (a field declared as numbers, text, a choice, or a model with no such
    field anywhere can hold none and is left out), worked out once per class (every solve asks)."""
    out = _FIELDS.get(cls)
    if out is None:
        _BUSY.add(cls)
        try:
            out = [(name, info.alias or name, angle) for name, info in cls.model_fields.items()
                   if (angle := is_angle(info)) or _may_hold_angles(info.annotation)]
        finally:
            _BUSY.discard(cls)
        _FIELDS[cls] = out
    return out


_BUSY: set = set()       # the classes whose fields are being worked out (a model that may hold itself)


_PLAIN = (float, int, str, bool, type(None))


def _may_hold_angles(tp: Any) -> bool:
    """Whether a value of the declared type ``tp`` may be, or hold, a model with an angle field:
    False for numbers, text, choices and containers of them, and for a model whose fields hold
    none; True for anything not declared so plainly (``Any``, a bare ``tuple``, another class)."""
    from pydantic import BaseModel

    if tp in _PLAIN or tp is Ellipsis:
        return False
    if isinstance(tp, type) and issubclass(tp, BaseModel):
        return tp in _BUSY or bool(_fields(tp))
    origin = typing.get_origin(tp)
    if origin is typing.Literal:
        return False
    if origin is typing.Annotated:
        return _may_hold_angles(typing.get_args(tp)[0])
    args = typing.get_args(tp)
    if origin is None or not args:
        return True
    return any(_may_hold_angles(a) for a in args)


def _bare(written: Any) -> float | None:
    """The number a value is when written as a bare number, else None."""
    if isinstance(written, bool):
        return None
    try:
        if isinstance(written, (int, float)):
            return float(written)
        if isinstance(written, str) and len(written) < 400 and _NUMBER.match(written):
            return float(written)
    except OverflowError:     # a 400-digit integer: refused by the field itself, not judged here
        return None
    return None


def degrees_warnings(model: Any, raw: Any) -> list[str]:
    """One warning per bare angle larger than a full turn."""
    out = []
    got = raw.get("params") if isinstance(raw, dict) else None
    params: dict = got if isinstance(got, dict) else {}
    for path, written in angle_fields(model, raw):
        items = list(enumerate(written)) if isinstance(written, list) else [(None, written)]
        for i, w in items:
            v, via = _bare(w), ""
            if v is None and isinstance(w, str) and w.strip() in params:     # a param written bare: th0 = -30
                v, via = _bare(params[w.strip()]), f" (params.{w.strip()})"
            if v is None or not math.isfinite(v) or abs(v) <= FULL_TURN:
                continue
            where = ".".join(str(p) for p in path) + (f" (component {i + 1})" if i is not None else "") + via
            shown = f"{v:g}"
            out.append(f"{where}: {shown} is read in radians ({math.degrees(v):.4g}°, more than a full turn); "
                       f"if you meant degrees, write {shown}*deg")
    return out


def declared_angle_fields(cls: Any, path: tuple = (), seen: frozenset = frozenset()) -> list[str]:
    """The dotted paths of every angle field a model class declares (``*``
    for a list entry), for the docs and the tests."""
    out: list[str] = []
    for name, info in getattr(cls, "model_fields", {}).items():
        key = info.alias or name
        if is_angle(info):
            out.append(".".join(path + (key,)))
            continue
        for sub, listed in _models_in(info.annotation):
            if sub not in seen:
                out += declared_angle_fields(sub, path + ((key, "*") if listed else (key,)), seen | {cls})
    return out


def _models_in(tp: Any, listed: bool = False) -> list[tuple[Any, bool]]:
    from pydantic import BaseModel

    if isinstance(tp, type) and issubclass(tp, BaseModel):
        return [(tp, listed)]
    origin = typing.get_origin(tp)
    listed = listed or origin in (list, tuple, dict)       # (a mapping's entries by name: `*` too)
    out = []
    for a in (typing.get_args(tp)[1:] if origin is dict else typing.get_args(tp)) or ():
        out += _models_in(a, listed)
    return out


def degrees_hint(cls: Any, raw: Any, path: tuple | str | None) -> str:
    """``"; if you meant degrees, write 30*deg"`` when ``path`` is an angle
    field of the model class ``cls`` written as a bare number beyond a full
    turn (for an angle refused by a range check), else ``""``."""
    if not path:
        return ""
    parts = tuple(path.split(".")) if isinstance(path, str) else tuple(str(p) for p in path)
    if not any(_matches(d.split("."), parts) for d in declared_angle_fields(cls)):
        return ""
    written: Any = raw
    for p in parts:
        if isinstance(written, dict) and p in written:
            written = written[p]
        elif isinstance(written, list) and p.isdigit() and int(p) < len(written):
            written = written[int(p)]
        else:
            return ""
    for w in written if isinstance(written, list) else [written]:
        v = _bare(w)
        if v is not None and math.isfinite(v) and abs(v) > FULL_TURN:
            return f"; if you meant degrees, write {v:g}*deg"
    return ""


def _matches(pattern: list[str], parts: tuple) -> bool:
    return len(pattern) == len(parts) and all(a == "*" and b.isdigit() or a == b for a, b in zip(pattern, parts))
