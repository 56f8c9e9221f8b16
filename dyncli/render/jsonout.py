"""JSON-safe conversion (no NaN/Infinity ever) and the contract's JSON shape.

Scales to long series: numpy arrays convert with one ``tolist()`` call (and
one vectorised finiteness test), flat lists of floats are checked in one pass
instead of a recursive call per element, and :func:`dumps` indents the
records' structure but writes each list of numbers (a series of 1e5 values,
or of 1e5 vectors) on one line, so the file is not a number per line.
"""

from __future__ import annotations

import json
import math
from typing import Any


def _floats(x: list) -> list | None:
    """``x`` unchanged when it is a flat list of finite floats/ints (the common
    case, checked without recursion), else None."""
    for v in x:
        t = type(v)
        if t is float:
            if v - v != 0.0:     # nan or inf
                return None
        elif t is not int:
            return None
    return x


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


def jsonable(x: Any) -> Any:
    """numpy scalars/arrays, tuples, Expr... -> plain JSON values.
    Non-finite floats become None."""
    if x is None or isinstance(x, (bool, str)):
        return x
    if isinstance(x, int):
        return x
    if isinstance(x, float):  # float(): numpy.float64 is a float subclass
        return float(x) if math.isfinite(x) else None
    if isinstance(x, dict):
        return {str(k): jsonable(v) for k, v in x.items()}
    if isinstance(x, list) and _floats(x) is not None:
        return x
    if isinstance(x, (list, tuple)):
        return [jsonable(v) for v in x]
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


def problem_record(lp, result=None, error=None, exit_code: int = 0) -> dict:
    """One JSON object of the output array (docs/cli.md)."""
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
        rec["results"] = jsonable(result.results)
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
    """A list of numbers, or of lists of numbers (vectors, tensors): no strings
    or mappings, so it is safe and readable on one line."""
    for v in x:
        t = type(v)
        if t is list:
            if not _numeric(v):
                return False
        elif t is not float and t is not int and v is not None:
            return False
    return True


def _encode(x: Any, indent: str, ascii_only: bool) -> str:
    inner = indent + "  "
    if isinstance(x, dict) and x:
        items = (f"{inner}{json.dumps(str(k), ensure_ascii=ascii_only)}: {_encode(v, inner, ascii_only)}"
                 for k, v in x.items())
        return "{\n" + ",\n".join(items) + "\n" + indent + "}"
    if isinstance(x, list) and x:
        if _numeric(x):
            return json.dumps(x, allow_nan=False)
        return "[\n" + ",\n".join(inner + _encode(v, inner, ascii_only) for v in x) + "\n" + indent + "]"
    return json.dumps(x, allow_nan=False, ensure_ascii=ascii_only)


def dumps(records: list[dict], ascii_only: bool = False) -> str:
    """The records indented by 2 (as ``json.dumps(indent=2)``), except that
    every list of numbers (a vector, a tensor, a series of 1e5 values or
    vectors) is written on one line, not one line per number; ``ascii_only``
    escapes non-ASCII characters (for a stdout that cannot encode them: the
    JSON is the same data)."""
    return _encode(records, "", ascii_only)
