"""Loading problem files: safe YAML -> validated problem models.

Knows nothing of any one topic: it reads ``type``, asks the registry for the
model class, evaluates ``params`` and validates with pydantic (context
``{"params": ...}``).  Every failure becomes a :class:`Diagnostic` printed as
``file:line:col: field.path: what is wrong``.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Mapping

from dyncli.angles import degrees_hint
from dyncli.errors import InputError
from dyncli.expr import did_you_mean, resolve_params
from dyncli.printable import line as one_line
from dyncli.yamlsafe import Document, YamlError, load as yaml_load


MAX_ERRORS = 50   # errors listed per problem (a document with 100,000 unknown keys stays fast)


@dataclass
class Diagnostic:
    file: str
    line: int | None
    col: int | None
    path: str | None
    message: str
    others: list = field(default_factory=list)   # further errors of the same problem (Diagnostics)

    def line_text(self) -> str:
        loc = self.file
        if self.line is not None:
            loc += f":{self.line}:{self.col or 1}"
        return one_line(f"{loc}: " + (f"{self.path}: " if self.path else "") + self.message)  # one line, shortened

    def lines(self) -> list[str]:
        """Every error of the problem, one line each."""
        return [self.line_text()] + [d.line_text() for d in self.others]

    def __str__(self) -> str:
        return "\n".join(self.lines())


@dataclass
class LoadedProblem:
    file: str
    index: int
    type: str | None
    title: str
    raw: Any
    doc: Document | None
    prefix: tuple        # path of this problem inside the document
    model: Any = None
    error: Diagnostic | None = None
    base_dir: Path | None = None
    swept: dict = field(default_factory=dict)     # path -> value of a --sweep point (dyncli.overrides)
    chain: dict = field(default_factory=dict)     # params name -> dyncli.chain.Link: validated when solved
    sources: dict = field(default_factory=dict)   # source index -> its LoadedProblem (dyncli.chain.link)
    outcome: Any = field(default=None, repr=False, compare=False)   # (raw, Outcome) once solved (run.solve_one)

    def diagnostic(self, path: str | tuple | None, message: str) -> Diagnostic:
        """A diagnostic for a field path (dotted string or tuple) inside this problem."""
        if isinstance(path, str):
            parts: tuple = tuple(int(p) if p.isdigit() else p for p in path.split(".")) if path else ()
        else:
            parts = tuple(path or ())
        line = col = None
        if self.doc is not None:
            pos = self.doc.locate(self.prefix + parts)
            if pos:
                line, col = pos
        dotted = ".".join(str(p) for p in parts) or None
        return Diagnostic(self.file, line, col, dotted, message)


def read_source(name: str) -> tuple[str, bytes]:
    """Read a file (``-`` = stdin).  Returns (display name, bytes)."""
    from dyncli.yamlsafe import MAX_BYTES

    if name == "-":
        stream = getattr(sys.stdin, "buffer", None)
        if stream is None:            # stdin closed (<&-) or detached
            raise InputError("-: standard input is closed; give a file name, or pipe the YAML in (... | dyncli solve -)")
        try:
            data = stream.read(MAX_BYTES + 1)
        except (OSError, ValueError) as exc:
            raise InputError(f"-: cannot read standard input ({getattr(exc, 'strerror', None) or exc})") from None
        return "<stdin>", data
    p = Path(name)
    if not p.exists():
        raise InputError(f"{name}: no such file (check the name, and the directory you run dyncli from)")
    if p.is_dir():
        raise InputError(f"{name}: is a directory (give the YAML files, e.g. {name}/*.yaml)")
    try:
        with p.open("rb") as fh:
            data = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise InputError(f"{name}: cannot read ({exc.strerror})") from None
    return name, data


def split_problems(display: str, data: bytes | str | Document, base_dir: Path | None = None) -> tuple[list[LoadedProblem], list[Diagnostic]]:
    """Parse a file's text into problems (not yet validated)."""
    try:
        doc = data if isinstance(data, Document) else yaml_load(data)   # a Document: a mapping from Python
    except YamlError as exc:
        return [], [Diagnostic(display, exc.line, exc.col, None, exc.message)]
    data = doc.data
    default_title = _file_name(display) if display != "<stdin>" else "stdin"
    if isinstance(data, dict) and "problems" in data and "type" not in data:
        extra = [k for k in data if k != "problems"]
        if extra:
            line, col = doc.locate((extra[0],)) or (None, None)
            return [], [Diagnostic(display, line, col, str(extra[0]), "unknown top-level key: a file with 'problems:' holds only that list")]
        items = data["problems"]
        if not isinstance(items, list) or not items:
            line, col = doc.locate(("problems",)) or (None, None)
            return [], [Diagnostic(display, line, col, "problems", "expected a non-empty list of problems")]
        prefixes: list[tuple[Any, ...]] = [("problems", i) for i in range(len(items))]
    elif isinstance(data, dict) and "type" not in data and (near := _near_key(data, "problems")) is not None:
        line, col = doc.locate((near,)) or (None, None)
        return [], [Diagnostic(display, line, col, str(near),
                               f"unknown top-level key '{near}' (did you mean 'problems'?): a file of several "
                               "problems lists them under 'problems:'")]
    elif isinstance(data, dict):
        items = [data]
        prefixes = [()]
    else:
        line, col = doc.locate(()) or (1, 1)
        return [], [Diagnostic(display, line, col, None, "expected a problem (a mapping with 'type') or 'problems: [...]'")]
    out = []
    for i, (item, prefix) in enumerate(zip(items, prefixes)):
        t = item.get("type") if isinstance(item, dict) else None
        title = item.get("title") if isinstance(item, dict) else None
        if not isinstance(title, str) or not title:
            title = default_title if len(items) == 1 else f"{default_title} #{i + 1}"
        out.append(LoadedProblem(display, i, t if isinstance(t, str) else None, title, item, doc, prefix, base_dir=base_dir))
    return out, []


@lru_cache(maxsize=256)
def _file_name(display: str) -> str:
    """``Path(display).name`` (the default title), worked out once per name."""
    return Path(display).name


def validate(lp: LoadedProblem) -> None:
    """Validate ``lp.raw`` into ``lp.model`` or set ``lp.error``."""
    from dyncli import registry

    raw = lp.raw
    if not isinstance(raw, dict):
        lp.error = lp.diagnostic((), "expected a problem: a mapping with 'type'")
        return
    if "type" not in raw:
        near = _near_key(raw, "type")
        if near is not None:
            lp.error = lp.diagnostic((near,), f"unknown field '{near}' (did you mean 'type'?): every problem names its type")
        else:
            lp.error = lp.diagnostic((), f"missing 'type': add 'type: NAME', one of: {', '.join(registry.TYPES)}")
        return
    t = raw["type"]
    if not isinstance(t, str) or t not in registry.TYPES:
        hint = did_you_mean(str(t), registry.TYPES)
        lp.error = lp.diagnostic(("type",), f"unknown problem type {t!r}{hint}; run 'dyncli types' for the list")
        lp.error.line, lp.error.col = (lp.doc.value_pos(lp.prefix + ("type",)) if lp.doc else None) or (lp.error.line, lp.error.col)
        return
    if not registry.available(t):
        lp.error = lp.diagnostic(("type",), f"problem type '{t}' is not implemented in this version")
        return
    cls = registry.model_class(t)
    try:
        if _pending(lp):
            return
        params = params_of(raw)
    except InputError as exc:
        lp.error = lp.diagnostic(exc.path, exc.message)
        return
    lp.model, lp.error = validate_model(lp, cls, raw, params)


def _pending(lp: LoadedProblem) -> bool:
    """A problem with params taken from other problems' results (dyncli.chain): the chain is
    checked now, the problem validated when solved.  Raises InputError."""
    from dyncli import chain

    found = chain.links(lp.raw)
    chain.check(lp, found)
    lp.chain, lp.model, lp.error = found, None, None
    return bool(found)


def _near_key(data: dict, word: str) -> Any:
    """The key of ``data`` that is a slip for ``word`` (``problem`` for
    ``problems``, ``Type`` for ``type``), or None."""
    for k in data:
        if isinstance(k, str) and k != word and did_you_mean(k, [word]):
            return k
    return None


def params_of(raw: dict) -> dict[str, float]:
    """The values of a problem's ``params`` (and ``g``) for its expressions
    (the validation context); raises InputError."""
    params = resolve_params(raw.get("params") or {})
    if "g" not in params:
        # the problem's gravity is usable in expressions as `g`
        params = {**params, "g": _gravity(raw.get("g", 9.81), params)}
    return params


def _gravity(value, params: dict[str, float]) -> float:
    """The value of the problem's ``g`` field for use in expressions (9.81
    when it cannot be read here; the model's validation reports the error)."""
    if type(value) is float and -math.inf < value < math.inf:
        return value                    # (to_float's answer for a finite float: the default 9.81)
    from dyncli.fields import to_float

    try:
        return to_float(value, None, dim="acceleration")
    except Exception:  # noqa: BLE001 - reported by model validation
        return 9.81


def validate_model(lp: LoadedProblem, cls, raw: dict, params: dict[str, float]):
    from pydantic import ValidationError

    try:
        return cls.model_validate(raw, context={"params": params, "base_dir": lp.base_dir}), None
    except ValidationError as exc:
        diags, seen = [], set()
        errors = _renamed(cls, raw, _union_branch(cls, raw, exc.errors(include_url=False)))
        for err in errors[:MAX_ERRORS]:
            loc = _strip_tags(raw, err["loc"])
            if loc not in seen:   # one message per field (a union reports each member)
                seen.add(loc)
                diags.append(lp.diagnostic(loc, _message(cls, err) + degrees_hint(cls, raw, loc)))
        first, *others = sorted(diags, key=lambda d: (d.line or 0, d.col or 0))
        if len(errors) > MAX_ERRORS:
            others.append(lp.diagnostic((), f"{len(errors) - MAX_ERRORS} more errors in this problem not listed"))
        first.others = others
        return None, first
    except InputError as exc:
        return None, lp.diagnostic(exc.path, exc.message + degrees_hint(cls, raw, exc.path))


#: the error types that say a union member does not take this kind of value at all
_WRONG_KIND = {"string_type", "list_type", "dict_type", "model_type", "model_attributes_type", "float_type",
               "float_parsing", "int_type", "bool_type", "literal_error", "is_instance_of"}


def _member_tag(raw: Any, loc) -> int | None:
    """The index in ``loc`` of the first tag pydantic inserts for a member of a plain union (a
    string where the value reached so far is not a mapping with that key: ``Wound``, ``str``,
    ``list[...]``), or None."""
    node = raw
    for k, part in enumerate(loc):
        if isinstance(node, dict):
            if isinstance(part, str) and part not in node and part not in [v for v in node.values() if isinstance(v, str)]:
                return k
            node = node.get(part) if isinstance(part, str) else None
        elif isinstance(node, list) and isinstance(part, int) and 0 <= part < len(node):
            node = node[part]
        elif isinstance(part, str):
            return k
        else:
            node = None
    return None


def _union_branch(cls, raw: Any, errors: list) -> list:
    """One member's errors for each value of a plain union (a cord entry, a force's point): the
    members that do not take that kind of value at all (text, a list, where a mapping was
    written) are dropped, and of the rest the member with the fewest errors is kept, its tag
    taken out of the locations (``cord.1.Wound.side`` -> ``cord.1.side``): one clear message
    per mistake, not one per member.  Where no member takes the value, one message says what
    the field takes (its description)."""
    groups: dict[tuple, dict[str, list]] = {}
    for err in errors:
        loc = tuple(err["loc"])
        k = _member_tag(raw, loc)
        if k is not None and (k < len(loc) - 1 or err["type"] in _WRONG_KIND):
            groups.setdefault(loc[:k], {}).setdefault(str(loc[k]), []).append(err)
    groups = {at: ms for at, ms in groups.items() if len(ms) >= 2}     # a plain union reports each member
    if not groups:
        return errors
    keep: dict[tuple, str] = {}         # the member kept at each union's place ("": none, one message)
    said = []
    for at, members in groups.items():
        fitting = {m: es for m, es in members.items()
                   if not all(e["type"] in _WRONG_KIND and len(e["loc"]) == len(at) + 1 for e in es)}
        keep[at] = min(fitting, key=lambda m: len(fitting[m])) if fitting else ""
        if not fitting:
            what = _description(cls, at[:-1] if at and isinstance(at[-1], int) else at, 240)
            given = next(iter(members.values()))[0].get("input")
            said.append({"type": "dyncli", "loc": at, "input": given,
                         "msg": f"got {_shown(given)}; expected {what or 'another kind of value'}"})
    out = []
    for err in errors:
        loc = tuple(err["loc"])
        k = _member_tag(raw, loc)
        if k is None or loc[:k] not in keep:
            out.append(err)
        elif keep[loc[:k]] == str(loc[k]):
            out.append(dict(err, loc=loc[:k] + loc[k + 1:]))
    return out + said


def _strip_tags(raw: Any, loc) -> tuple:
    """Drop the tags pydantic inserts into the location of an error inside a
    discriminated union (``forces.0.spring.k`` -> ``forces.0.k``): a string
    part that is not a key of the mapping reached so far but equals one of
    its values (the discriminator) is a tag."""
    out: list = []
    node = raw
    for part in loc:
        if isinstance(node, dict) and isinstance(part, str) and part not in node and part in [
            v for v in node.values() if isinstance(v, str)
        ]:
            continue
        out.append(part)
        if isinstance(node, dict):
            node = node.get(part)
        elif isinstance(node, list) and isinstance(part, int) and 0 <= part < len(node):
            node = node[part]
        else:
            node = None
    return tuple(out)


#: names students write for a field (a position, a velocity, a mass), tried after the spelling
_ALIASES = {"at": "x", "pos": "x", "position": "x", "x0": "x", "r0": "x", "vel": "v", "velocity": "v",
            "v0": "v", "m": "mass", "theta": "angle", "phi": "angle", "w": "omega", "inertia": "I"}


def _meant(key: str, fields: list[str], models: list | None = None) -> str | None:
    """The field an unknown ``key`` most likely means: the name its model declares for it
    (``unknown_keys``), a close spelling, a field it abbreviates (the only one it begins), or a
    common name for it (``at`` for ``x``); None."""
    declared = _declared_key(key, models or [])
    if declared in fields:
        return declared
    if declared:
        return None
    hint = did_you_mean(key, fields)
    if hint:
        return hint.split("'")[1]
    starts = [f for f in fields if f.lower().startswith(key.lower()) and f != key]
    if len(starts) == 1:
        return starts[0]
    alias = _ALIASES.get(key)
    return alias if alias in fields else None


def _declared_key(key: str, models: list) -> str | None:
    """What the model at hand says of ``key`` (its ``unknown_keys``): a field's name or a sentence."""
    for m in models:
        said = getattr(m, "unknown_keys", {}).get(key)
        if said:
            return said
    return None


def _renamed(cls, raw: Any, errors: list) -> list:
    """One message for a required field written under another name (``m: 2`` for ``mass``):
    the unknown key's message names the field; the field's own "missing" is dropped."""
    extras = {}
    for err in errors:
        loc = _strip_tags(raw, err["loc"])
        if err["type"] == "extra_forbidden" and loc:
            meant = _meant(str(loc[-1]), _fields_at(cls, loc[:-1]), _models_at(cls, loc[:-1]))
            if meant:
                extras[loc[:-1] + (meant,)] = err
    out = []
    for err in errors:
        loc = _strip_tags(raw, err["loc"])
        if err["type"] == "missing" and loc in extras:
            extras[loc]["required"] = _description(cls, loc) or "required"
            continue
        out.append(err)
    return out


def _message(cls, err: Mapping[str, Any]) -> str:
    t = err["type"]
    loc = tuple(err["loc"])
    if t == "extra_forbidden":
        key = str(loc[-1]) if loc else "?"
        fields = _fields_at(cls, loc[:-1])
        said = _declared_key(key, _models_at(cls, loc[:-1]))
        if said and said not in fields:
            return f"unknown field '{key}': {said}"
        meant = _meant(key, fields, _models_at(cls, loc[:-1])) if fields else None
        if meant and err.get("required"):
            return f"unknown field '{key}': rename it '{meant}' (required: {err['required']})"
        hint = f" (did you mean '{meant}'?)" if meant else ""
        known = f"; known fields: {', '.join(sorted(fields))}" if fields and not hint else ""
        return f"unknown field '{key}'{hint}{known}"
    if t == "missing":
        what = _description(cls, loc)
        return "required field is missing" + (f": add {loc[-1]} ({what})" if what else "")
    if t == "dyncli":
        return err["msg"]
    if t in _PLAIN:
        return _PLAIN[t](err.get("input"), err.get("ctx") or {})
    if t in ("literal_error",):
        return err["msg"].replace("Input should be", "must be")
    if t in ("union_tag_invalid", "union_tag_not_found"):
        return err["msg"]
    msg = err["msg"]
    for pre in ("Value error, ", "Assertion failed, "):
        if msg.startswith(pre):
            msg = msg[len(pre):]
    return msg.replace("Input should be", "must be")


def _shown(x: Any) -> str:
    from dyncli.expr import kind_of

    return repr(x) if isinstance(x, (str, int, float)) and not isinstance(x, bool) and len(repr(x)) <= 40 else kind_of(x)


def _entries(n: Any) -> str:
    return f"{n} entry" if n == 1 else f"{n} entries"


#: pydantic's wording of the common slips, said the way a problem file is written
_PLAIN = {
    "int_from_float": lambda x, c: f"must be a whole number, got {_shown(x)}",
    "int_parsing": lambda x, c: f"must be a whole number, got {_shown(x)}",
    "int_type": lambda x, c: f"must be a whole number, got {_shown(x)}",
    "bool_parsing": lambda x, c: f"must be true or false, got {_shown(x)}",
    "bool_type": lambda x, c: f"must be true or false, got {_shown(x)}",
    "string_type": lambda x, c: f"must be text, got {_shown(x)}",
    "list_type": lambda x, c: f"must be a list, got {_shown(x)}: write [a, b] or one '- ' line per entry",
    "dict_type": lambda x, c: f"must be a mapping (name: value lines, or {{name: value}}), got {_shown(x)}",
    "model_type": lambda x, c: f"must be a mapping (name: value lines, or {{name: value}}), got {_shown(x)}",
    "model_attributes_type": lambda x, c: f"must be a mapping (name: value lines, or {{name: value}}), got {_shown(x)}",
    "too_short": lambda x, c: f"must have at least {_entries(c.get('min_length', 1))}, got {c.get('actual_length', 0)}",
    "too_long": lambda x, c: f"must have at most {_entries(c.get('max_length', '?'))}, got {c.get('actual_length', '?')}",
}


def _description(cls, loc: tuple, limit: int = 90) -> str:
    """The declared description of the field at ``loc`` (at most ``limit`` characters), or ""."""
    for m in _models_at(cls, loc[:-1]):
        info = getattr(m, "model_fields", {}).get(loc[-1]) if loc else None
        schemas = [getattr(meta, "json_schema", None) for meta in (info.metadata if info is not None else ())]
        d = (info.description if info is not None else None) or next(
            (s["description"] for s in schemas if isinstance(s, dict) and s.get("description")), None)
        if d:
            return d if len(d) <= limit else d[:limit - 3] + "..."
    return ""


def _fields_at(cls, loc: tuple) -> list[str]:
    """Best effort: the field names of the model found at ``loc``."""
    names: list[str] = []
    for m in _models_at(cls, loc):
        names += list(getattr(m, "model_fields", {}))
    return names


def _models_at(cls, loc: tuple) -> list:
    """Best effort: the models found at ``loc``."""
    import typing

    from pydantic import BaseModel

    def models_in(tp) -> list:
        out = []
        if isinstance(tp, type) and issubclass(tp, BaseModel):
            return [tp]
        for a in typing.get_args(tp) or ():
            out += models_in(a)
        return out

    def tags(m) -> set:
        out: set[Any] = set()
        for f in getattr(m, "model_fields", {}).values():
            if typing.get_origin(f.annotation) is typing.Literal:
                out.update(str(a) for a in typing.get_args(f.annotation))
        return out

    current = [cls]
    for part in loc:
        nxt = []
        for m in current:
            if isinstance(part, str) and part in getattr(m, "model_fields", {}):
                nxt += models_in(m.model_fields[part].annotation)
            elif isinstance(part, int) or (isinstance(part, str) and part not in getattr(m, "model_fields", {})):
                nxt.append(m)  # list index or union tag: stay
        if isinstance(part, str) and len(nxt) > 1:
            tagged = [m for m in nxt if part in tags(m)]
            nxt = tagged or nxt  # union tag: keep the member it names
        current = nxt or current
    return current


def load_paths(names: list[str]) -> tuple[list[LoadedProblem], list[Diagnostic]]:
    """Read and split every file, then validate every problem."""
    problems: list[LoadedProblem] = []
    diags: list[Diagnostic] = []
    for name in names:
        try:
            display, data = read_source(name)
        except InputError as exc:
            diags.append(Diagnostic(name, None, None, None, exc.message.removeprefix(f"{name}: ")))
            continue
        base = Path(name).parent if name != "-" else Path.cwd()
        ps, ds = split_problems(display, data, base)
        diags += ds
        for p in ps:
            validate(p)
        problems += ps
    return problems, diags
