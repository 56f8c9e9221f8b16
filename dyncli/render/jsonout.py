"""JSON-safe conversion (no NaN/Infinity ever) and the contract's JSON shape.

Scales to long series: numpy arrays convert with one ``tolist()`` call (and
one vectorised finiteness test), flat lists of floats are checked in one pass
instead of a recursive call per element, and :func:`dumps` indents the
records' structure but writes each list of numbers (a series of 1e5 values,
or of 1e5 vectors) on one line, so the file is not a number per line.  A long
list of numbers, and a long series of flat records, is written by pydantic_core's
serializer (:func:`numbers_json`: the digits of ``repr``, its notation mended
where it differs), the same text as ``json.dumps`` at ~8 × its speed.
"""

from __future__ import annotations

import json
import math
import re
from operator import itemgetter
from typing import Any


def _floats(x: list) -> list | None:
    """``x`` unchanged when it is a flat list of finite floats/ints (the common
    case, checked without recursion), else None."""
    if len(x) > 16 and _finite_numbers(x):
        return x
    for v in x:
        t = type(v)
        if t is float:
            if v - v != 0.0:     # nan or inf
                return None
        elif t is not int:
            return None
    return x


_NUMBER_TYPES = frozenset((float, int))


def _finite_numbers(x) -> bool:
    """Whether the items of the iterable ``x`` are all floats or ints and all finite, decided
    at C speed: the set of their types, then their sum (a NaN or an infinity makes it
    non-finite).  False also when the sum merely overflows: the callers then check one by one."""
    if not set(map(type, x)) <= _NUMBER_TYPES:
        return False
    try:
        s = sum(x)
    except OverflowError:                        # (an int beyond a double)
        return False
    return s - s == 0


def _number_rows(x: list) -> bool:
    """Whether ``x`` is a non-empty list of lists of finite floats/ints (a series of vectors),
    decided at C speed (:func:`_finite_numbers` over the chained rows)."""
    from itertools import chain

    return bool(x) and set(map(type, x)) == {list} and _finite_numbers(list(chain.from_iterable(x)))


def _flat_dict(x: dict) -> bool:
    """Whether ``x`` is already plain JSON one level deep (str keys; values None, bool, str,
    int, finite floats or flat lists of them): a series of 1e5 small records (force terms,
    powers) then converts without a call per value."""
    for k, v in x.items():
        t = type(v)
        if type(k) is not str:
            return False
        if t is float:
            if v - v != 0.0:
                return False
        elif t is list:
            if _floats(v) is None:
                return False
        elif not (v is None or t is int or t is str or t is bool):
            return False
    return True


def _records(x: list) -> bool:
    """Whether ``x`` is a non-empty list of non-empty :func:`_flat_dict` records (a series of
    force terms, powers, works at 1e5 times), decided at C speed when every value is a list of
    numbers or every value a number (else record by record)."""
    from itertools import chain

    if not x or set(map(type, x)) != {dict} or not all(x):
        return False
    if len(x) > 16 and set(map(type, chain.from_iterable(x))) == {str}:
        values = list(chain.from_iterable(map(dict.values, x)))
        kinds = set(map(type, values))
        if kinds == {list} and _finite_numbers(list(chain.from_iterable(values))):
            return True
        if kinds <= _NUMBER_TYPES and _finite_numbers(values):
            return True
    return all(map(_flat_dict, x))


def _array(x) -> Any:
    import numpy as np

    if x.dtype.kind == "f":
        fin = np.isfinite(x)
        if fin.all():
            return x.tolist()
        return np.where(fin, x, None).tolist()  # type: ignore[attr-defined]  # numpy's stubs take where(c, x, None) for where(c)
    if x.dtype.kind in "iub":
        return x.tolist()
    return jsonable(x.tolist())


def jsonable(x: Any, seen: dict | None = None) -> Any:
    """numpy scalars/arrays, tuples, Expr... -> plain JSON values.
    Non-finite floats become None.  ``seen``: the lists kept as they are after a check (numbers,
    rows of numbers: "n"; flat records: "r") are noted there by id (with the list), so that
    :func:`encode_parts` given the same ``seen`` does not check them again."""
    if x is None or isinstance(x, (bool, str)):
        return x
    if isinstance(x, int):
        return x
    if isinstance(x, float):  # float(): numpy.float64 is a float subclass
        return float(x) if math.isfinite(x) else None
    if isinstance(x, dict):
        if type(x) is dict and _flat_dict(x):
            return x
        return {str(k): jsonable(v, seen) for k, v in x.items()}
    if isinstance(x, list):
        kind = "n" if _floats(x) is not None or _number_rows(x) else ("r" if _records(x) else None)
        if kind is not None:
            if seen is not None and type(x) is list and x:
                seen[id(x)] = (kind, x)
            return x
    if isinstance(x, (list, tuple)):
        return [jsonable(v, seen) for v in x]
    mod = type(x).__module__
    if mod.startswith("numpy"):
        import numpy as np

        if isinstance(x, np.ndarray):
            return _array(x)
        if isinstance(x, np.bool_):
            return bool(x)
        if isinstance(x, np.integer):
            return int(x)
        if isinstance(x, np.floating):
            return jsonable(float(x))
    if isinstance(x, complex):
        return jsonable(x.real) if x.imag == 0 else str(x)
    return str(x)


def input_sha256(raw: Any) -> str:
    """SHA-256 of the problem as solved: the canonical JSON (sorted keys, no
    spaces, UTF-8) of the problem's mapping after overrides (docs/cli.md)."""
    import hashlib

    text = json.dumps(jsonable(raw), sort_keys=True, separators=(",", ":"), ensure_ascii=False, allow_nan=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def problem_record(lp, result=None, error=None, exit_code: int = 0, seen: dict | None = None) -> dict:
    """One JSON object of the output array (docs/cli.md); ``seen``: see :func:`jsonable`."""
    from dyncli import __version__

    rec: dict[str, Any] = {
        "file": lp.file,
        "index": lp.index,
        "type": lp.type,
        "title": lp.title,
    }
    if getattr(lp, "swept", None):
        rec["swept"] = jsonable(lp.swept)
    if result is not None:
        rec["results"] = jsonable(result.results, seen)
        rec["method"] = result.method
        if result.error_estimate is not None or result.method not in ("closed-form",):
            rec["error_estimate"] = jsonable(result.error_estimate)
        rec["equations"] = list(result.equations)
        rec["warnings"] = list(result.warnings)
    else:
        rec["results"] = None
        rec["method"] = None
        rec["equations"] = []
        rec["warnings"] = []
        rec["error"] = str(error) if error is not None else None
        rec["exit_code"] = exit_code
    rec["dyncli_version"] = __version__
    rec["input_sha256"] = input_sha256(lp.raw)
    return rec


def _numeric(x: list) -> bool:
    """A list of finite numbers, or of lists of them (vectors, tensors): no
    strings or mappings, so it is safe and readable on one line."""
    if len(x) > 16 and (_finite_numbers(x) or _number_rows(x)):
        return True
    for v in x:
        t = type(v)
        if t is float:
            if v - v != 0.0:     # nan or inf: left to json.dumps, which refuses it
                return False
        elif t is list:
            if not _numeric(v):
                return False
        elif t is not int and v is not None:
            return False
    return True


_NUMBERS = 1        # the mark of a list written by repr (a series of flat records: its keys)


def _leaves(x: Any, out: list, marks: dict, seen: dict | None = None) -> None:
    """Every key and scalar of ``x`` in writing order, but those of the lists marked in
    ``marks`` (by id): numeric lists (written by ``repr``: the same text as ``json.dumps``) and
    series of flat records (:func:`_records_text`: their distinct keys once, then their values
    that are not numbers or lists of numbers, in order)."""
    if type(x) is dict:
        for k, v in x.items():
            out.append(str(k))
            t = type(v)
            if t is dict or t is list:
                _leaves(v, out, marks, seen)
            else:
                out.append(v)
    elif type(x) is list and x:
        got = seen.get(id(x)) if seen else None
        kind = got[0] if got is not None and got[1] is x else None     # checked by jsonable already
        if kind == "n" or (kind is None and _numeric(x)):
            marks[id(x)] = _NUMBERS
        elif kind == "r" or _records(x):
            from itertools import chain

            keys = list(dict.fromkeys(chain.from_iterable(x)))     # each key once, in order of first use
            marks[id(x)] = keys
            out.extend(keys)
            if not set(map(type, chain.from_iterable(map(dict.values, x)))) <= _REPR:
                out.extend(v for rec in x for v in rec.values() if type(v) not in _REPR)
        else:
            for v in x:
                _leaves(v, out, marks, seen)
    elif type(x) is not list:
        out.append(x)


def _layout(x: Any, indent: str, text, parts: list, marks: dict) -> None:
    """``x`` indented by 2, its keys and scalars taken from ``text`` (their
    JSON, in writing order); the lists ``marks`` holds written at once."""
    inner = indent + "  "
    if type(x) is dict and x:
        parts.append("{\n")
        last = len(x) - 1
        for i, v in enumerate(x.values()):
            t = type(v)
            if t is not dict and t is not list:      # a scalar: inline (a series of small records)
                parts.append(f"{inner}{next(text)}: {next(text)}")
            elif t is list and marks.get(id(v)) == _NUMBERS:
                parts.append(f"{inner}{next(text)}: " + numbers_json(v))
            else:
                parts.append(f"{inner}{next(text)}: ")
                _layout(v, inner, text, parts, marks)
            parts.append(",\n" if i < last else "\n")
        parts.append(indent + "}")
    elif type(x) is list and x:
        mark = marks.get(id(x))
        if mark == _NUMBERS:
            parts.append(numbers_json(x))
            return
        if mark is not None:
            parts.append(_records_text(x, indent, mark, text))
            return
        parts.append("[\n")
        last = len(x) - 1
        nxt = text.__next__
        for i, v in enumerate(x):
            parts.append(inner)
            if type(v) is dict and v and _flat_dict(v):      # a series of small records: no call per value
                parts.append(_flat_text(v, inner, nxt))
            else:
                _layout(v, inner, text, parts, marks)
            parts.append(",\n" if i < last else "\n")
        parts.append(indent + "]")
    elif type(x) is dict:
        parts.append("{}")
    elif type(x) is list:
        parts.append("[]")
    else:
        parts.append(next(text))


def _flat_text(x: dict, indent: str, nxt) -> str:
    """:func:`_layout` of a non-empty :func:`_flat_dict` (its keys and scalars from ``nxt``)."""
    inner = indent + "  "
    items = []
    for v in x.values():
        if type(v) is list:
            items.append(f"{inner}{nxt()}: " + (repr(v).replace("None", "null") if v else "[]"))
        else:
            items.append(f"{inner}{nxt()}: {nxt()}")
    return "{\n" + ",\n".join(items) + "\n" + indent + "}"


_REPR = frozenset((float, int, list))      # written by repr in a flat record: their JSON


def _records_text(x: list, indent: str, keys: list, text) -> str:
    """:func:`_layout` of a non-empty list of non-empty :func:`_flat_dict` records (a series of
    1e5 force terms, powers, works), written here at once: the JSON of each of its ``keys``
    and of its values that are not numbers or lists of numbers from ``text`` (in the order
    :func:`_leaves` put them), numbers and lists of numbers by ``repr`` (their JSON: every one
    is finite)."""
    inner, deeper = indent + "  ", indent + "    "
    heads = {k: f"{deeper}{next(text)}: " for k in keys}
    open_, close, rows = inner + "{\n", "\n" + inner + "}", []
    whole = _records_json(x, keys, [heads[k] for k in keys], indent)
    if whole is not None:
        return whole
    columns = _column_texts(x, keys)
    if columns is not None:         # every record the same keys, each a column of one kind: no call per value
        texts, lists = columns
        row = (open_ + ",\n".join(heads[k].replace("%", "%%") + ("[%s]" if listed else "%s")
                                   for k, listed in zip(keys, lists)) + close).__mod__
        return "[\n" + ",\n".join(map(row, zip(*texts))) + "\n" + indent + "]"
    for rec in x:
        rows.append(open_ + ",\n".join([heads[k] + (repr(v) if type(v) in _REPR else next(text))
                                        for k, v in rec.items()]) + close)
    return "[\n" + ",\n".join(rows) + "\n" + indent + "]"


#: a key written as is in :func:`_records_json`: letters, digits, spaces and a few signs (its JSON is
#: itself in quotes; no separator the text is cut at, nor a number's delimiter, is in it)
_PLAIN_KEY = re.compile(r"[A-Za-z0-9 _#.+*/()'-]+").fullmatch


def _records_json(x: list, keys: list, heads: list[str], indent: str) -> str | None:
    """:func:`_records_text` of records that all have exactly ``keys`` (plain ones: :data:`_PLAIN_KEY`,
    ``heads`` their indented JSON) and only numbers and lists of numbers as values (all finite:
    :func:`_records`), at once: :func:`numbers_json` of the whole list (``[{"k1": v, "k2": [a,
    b]}, {...}]``: the separators are the only commas), laid out by replacing its separators
    (``}, {"k1": `` between records, ``, "k2": `` between values: no number holds a quote or a
    brace); else None."""
    if len(x) < 64 or any(list(rec) != keys for rec in (x[0], x[-1])) or not all(map(_PLAIN_KEY, keys)):
        return None
    from itertools import chain

    if set(map(tuple, x)) != {tuple(keys)} or not set(map(type, chain.from_iterable(map(dict.values, x)))) <= _REPR:
        return None
    if heads != [f'{indent}    "{k}": ' for k in keys]:
        return None
    text = _serialized(x)
    if text is None:
        return None
    text = text.replace(",", ", ").replace('":', '": ')
    inner = indent + "  "
    first = '{"%s": ' % keys[0]
    if not (text.startswith("[" + first) and text.endswith("}]")):
        return None
    text = text[len(first) + 1:-2].replace("}, " + first, f"\n{inner}}},\n{inner}{{\n{heads[0]}")
    for k, head in zip(keys[1:], heads[1:]):
        text = text.replace(', "%s": ' % k, ",\n" + head)
    return f"[\n{inner}{{\n{heads[0]}{text}\n{inner}}}\n{indent}]"


def numbers_json(x: list) -> str:
    """``repr(x)`` with None as null — the JSON of a list of finite numbers or None, or of lists
    of them, as ``json.dumps`` writes it — at ~10 × its speed for a long list (:func:`_serialized`,
    its separators ``,`` made ``, ``: no number holds a comma); a short list by ``repr``."""
    text = _serialized(x) if len(x) >= 64 else None
    return repr(x).replace("None", "null") if text is None else text.replace(",", ", ")


def _serialized(x: Any) -> str | None:
    """The compact JSON of ``x`` (numbers, None, lists, plain-keyed mappings of them) by
    pydantic_core's serializer, every number as ``repr`` writes it, or None (the serializer
    refuses it, or does not pass :func:`_serializer_ok`).  The serializer writes each float in the
    shortest digits that read back as it (Ryu), ``repr``'s digits; only its notation differs, for
    1e-5 ≤ |x| < 1e-4 (``0.00001``, not ``1e-05``) and for a one-digit negative exponent
    (``1e-6``, not ``1e-06``): those numbers, found in the text, are mended."""
    if not _serializer_ok():
        return None
    from pydantic_core import to_json

    try:
        return _mend(to_json(x).decode("ascii"))
    except Exception:                           # (not expected: numbers and lists of them)
        return None


def _mend(text: str) -> str:
    """The serializer's ``text`` with every number in ``repr``'s notation (:func:`_serialized`)."""
    if "0.0000" in text:
        text = _SMALL(_small, text)
    if "e-" in text:
        text = _EXPONENT(r"e-0\1", text)
    return text


_PROBE: list = []       # [whether the serializer, mended, wrote the probe as json.dumps does]


def _serializer_ok() -> bool:
    """Whether :func:`_serialized`'s text of a probe of numbers in every notation (each decade
    from 1e-12 to 1e20, both signs, 0, -0.0, ints, a subnormal, the extremes, 17-digit values) is
    ``json.dumps``'s, decided once: a serializer that writes otherwise is not used (``repr``)."""
    if not _PROBE:
        from pydantic_core import to_json

        probe: list[Any] = [s * (1 + k / 7) * 10.0 ** e for e in range(-12, 21) for k in (0, 3) for s in (1, -1)]
        probe += [0.0, -0.0, 0, -3, 2**63, 10**20, 5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                  0.1, 0.30000000000000004, 9007199254740993.0, 1e-05, 1e-06, 1.5e-05, 1e16, 123456.789, None]
        try:
            text = _mend(to_json([probe, [probe]]).decode("ascii"))
            _PROBE.append(text.replace(",", ", ") == json.dumps([probe, [probe]]))
        except Exception:
            _PROBE.append(False)
    return _PROBE[0]


# a number written in the serializer's notation where repr's differs: 0.0000ddd (|x| < 1e-4, read
# again by repr: its sign, if any, stays before it) and a one-digit negative exponent (padded), each
# only as a whole number (after "[", ",", ":" or its sign; before ",", "]" or "}")
_SMALL = re.compile(r"0\.0000[0-9]*").sub
_EXPONENT = re.compile(r"e-([0-9])(?=[,\]}]|$)").sub


def _small(m) -> str:
    s, a, b = m.string, m.start(), m.end()
    whole = a > 0 and s[a - 1] in "[,:-" and (b == len(s) or s[b] in ",]}")
    return repr(float(m.group())) if whole else m.group()


def _column_texts(x: list, keys: list) -> tuple[list[list[str]], list[bool]] | None:
    """The JSON of each record's value of each of ``keys`` (one list per key, in record order;
    a list's without its brackets) and whether the key's values are lists, when every record of
    ``x`` has exactly ``keys`` in that order and each key's values are all numbers or all lists
    of numbers (every one finite: :func:`_records`), else None.  One
    ``repr`` per column, cut at its separators (", " between numbers, "], [" between lists:
    neither occurs inside a number's text), so each piece is the ``repr`` of its value."""
    if len(x) < 64 or any(list(rec) != keys for rec in (x[0], x[-1])):
        return None
    if set(map(tuple, x)) != {tuple(keys)}:
        return None
    out, lists = [], []
    for k in keys:
        col = list(map(itemgetter(k), x))
        kinds = set(map(type, col))
        if kinds <= {float, int}:
            out.append(numbers_json(col)[1:-1].split(", "))
        elif kinds == {list}:
            out.append(numbers_json(col)[2:-2].split("], ["))
        else:
            return None
        lists.append(kinds == {list})
        if len(out[-1]) != len(x):              # (a guard: a piece per record, or the slow way)
            return None
    return out, lists


def encode(record: Any, indent: str = "", ascii_only: bool = False) -> str:
    """One record (any JSON value) as :func:`dumps` writes it, its first line
    not indented, the others by ``indent`` + 2: one ``json.dumps`` call for
    all its keys and scalars (separated by newlines, which no JSON scalar
    holds), numeric lists by ``repr``, series of flat records at once."""
    return "".join(encode_parts(record, indent, ascii_only))


def encode_parts(record: Any, indent: str = "", ascii_only: bool = False, seen: dict | None = None) -> list[str]:
    """:func:`encode` as the list of its pieces, in order (a stream writes them one after the
    other: a record of 1e5 times is ~70 MB, not joined and copied again); ``seen``: the lists
    :func:`jsonable` checked in making ``record`` (their checks not repeated)."""
    leaves: list = []
    marks: dict = {}
    _leaves(record, leaves, marks, seen)
    text = json.dumps(leaves, ensure_ascii=ascii_only, allow_nan=False, separators=("\n", ": "))
    parts: list[str] = []
    _layout(record, indent, iter(text[1:-1].split("\n") if leaves else ()), parts, marks)
    return parts


def dumps(records: list[dict], ascii_only: bool = False) -> str:
    """The records indented by 2 (as ``json.dumps(indent=2)``), except that
    every list of numbers (a vector, a tensor, a series of 1e5 values or
    vectors) is written on one line, not one line per number; ``ascii_only``
    escapes non-ASCII characters (for a stdout that cannot encode them: the
    JSON is the same data)."""
    if not records:
        return "[]"
    return "[\n" + ",\n".join("  " + encode(r, "  ", ascii_only) for r in records) + "\n]"
