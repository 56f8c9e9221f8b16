"""Numbers against a tolerance (docs/check.md, "Comparison rules"): the
tolerance of an answer, the scalar rules (``rtol``/``atol`` and
PrairieLearn's significant figures), reading a given scalar, and the
relative error as feedback may say it (2 significant figures).

Also the readers of a tolerance mapping and of ``points`` (keys and answer
files alike).  The bottom of the grader: of ``dyncli.check`` it imports only
:mod:`dyncli.check.safe`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from dyncli.check.safe import shown

TOL_KEYS = ("rtol", "atol", "sigfigs")

DEFAULT_RTOL = 1e-2
DEFAULT_ATOL = 1e-8


@dataclass(frozen=True)
class Tolerance:
    rtol: float = DEFAULT_RTOL
    atol: float = DEFAULT_ATOL
    sigfigs: int | None = None

    def describe(self) -> str:
        if self.sigfigs is not None:
            return f"{self.sigfigs} significant figure{'s' if self.sigfigs != 1 else ''}"
        return f"rtol {g3(self.rtol)}, atol {g3(self.atol)}"

    def as_dict(self) -> dict:
        if self.sigfigs is not None:
            return {"sigfigs": self.sigfigs}
        return {"rtol": self.rtol, "atol": self.atol}


def g3(x: float) -> str:
    return f"{x:.3g}"


class GivenError(ValueError):
    """The given value cannot be read as an answer (invalid answer file)."""


def sigfig_bound(true: float, n: int) -> float:
    """Half-width of the acceptance interval of the significant-figure rule."""
    a = abs(true)
    if a == 0:
        return 0.51 * 10.0 ** (1 - n)
    e = math.floor(math.log10(a))
    # guard log10 rounding just below/above a power of ten
    if 10.0 ** e > a:
        e -= 1
    elif 10.0 ** (e + 1) <= a:
        e += 1
    return 0.51 * 10.0 ** (e - n + 1)


def number_ok(given: float, true: float, tol: Tolerance) -> bool:
    if not (math.isfinite(given) and math.isfinite(true)):
        return False
    d = abs(given - true)
    if tol.sigfigs is not None:
        return d < sigfig_bound(true, tol.sigfigs)
    return d <= tol.atol + tol.rtol * abs(true)


def to_number(given: Any) -> float | None:
    """A given scalar as a float, or None when it is not numeric at all
    (bool, list, mapping).  Strings are read as constant expressions;
    unreadable strings raise :class:`GivenError`."""
    if isinstance(given, bool) or given is None:
        return None
    if isinstance(given, (int, float)):
        try:
            return float(given)
        except OverflowError:
            return math.inf if given > 0 else -math.inf
    if isinstance(given, str):
        from dyncli.errors import InputError
        from dyncli.expr import parse

        try:
            e = parse(given, (), {})
            return float(e.value())
        except InputError as exc:
            raise GivenError(f"cannot read {given!r} as a number: {exc.message}") from None
        except (ValueError, ArithmeticError) as exc:  # pragma: no cover - defensive
            raise GivenError(f"cannot read {given!r} as a number: {exc}") from None
    return None


def round2(x: float) -> float:
    """``x`` rounded to 2 significant figures (what feedback may say of an
    error without revealing the expected value)."""
    if x == 0 or not math.isfinite(x):
        return x
    return float(f"{x:.2g}")


def rel_text(rel: float) -> str:
    """2 significant figures, a percentage up to 1,000 %, beyond it how many
    times the correct value's size: ``0.0123 -> "1.2%"``, ``99 -> "×99"``,
    ``3.7e7 -> "×3.7e+07"``."""
    if rel < 10:
        return f"{round2(rel) * 100:g}%"
    return f"×{round2(rel):g}"


# ---------------------------------------------------------------------------
# reading a tolerance and points


class FieldError(Exception):
    """A field of a key or an answer file that cannot be read: its path and why
    (``key``: the position is the key's, else the value's)."""

    def __init__(self, path: tuple, message: str, key: bool = True):
        super().__init__(message)
        self.path = path
        self.message = message
        self.key = key


MAX_POINTS = 1e6      # points of one answer; sums of thousands stay exact and finite
MAX_RTOL = 1e6
MAX_ATOL = 1e300


def read_number(x: Any) -> float:
    """A tolerance/points number: YAML number or constant expression string."""
    from dyncli.errors import InputError
    from dyncli.expr import constant

    if isinstance(x, bool) or x is None or isinstance(x, (list, dict)):
        raise ValueError("expected a number")
    if isinstance(x, (int, float)):
        try:
            return float(x)
        except OverflowError:
            raise ValueError("number is too large") from None
    try:
        return constant(x)
    except InputError as exc:
        raise ValueError(exc.message) from None


def read_points(x: Any) -> float:
    """``points``: a number from 0 to MAX_POINTS; raises ValueError."""
    try:
        pts = read_number(x)
    except ValueError as exc:
        raise ValueError(f"points: {exc}") from None
    if not math.isfinite(pts) or not 0 <= pts <= MAX_POINTS:
        raise ValueError(f"points must be a number from 0 to {MAX_POINTS:g}")
    return pts


def parse_tolerance(raw: Any, base: Tolerance, path: tuple) -> Tolerance:
    """``{rtol, atol}`` or ``{sigfigs}`` on top of ``base``; raises FieldError."""
    if not isinstance(raw, dict):
        raise FieldError(path, "tolerance must be a mapping: {rtol: 0.01, atol: 1.0e-8} or {sigfigs: 3}")
    return tolerance_from(raw, base, path, TOL_KEYS)


def tolerance_from(raw: dict, base: Tolerance, path: tuple, allowed: tuple) -> Tolerance:
    for k in raw:
        if k not in allowed:
            from dyncli.expr import did_you_mean

            raise FieldError(path + (k,), f"unknown key '{shown(k)}'{did_you_mean(str(k), allowed)}; known: {', '.join(allowed)}")
    has_sf = "sigfigs" in raw
    has_ra = "rtol" in raw or "atol" in raw
    if has_sf and has_ra:
        raise FieldError(path + ("sigfigs",), "give either sigfigs or rtol/atol, not both")
    if has_sf:
        v = raw["sigfigs"]
        if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 17:
            raise FieldError(path + ("sigfigs",), "sigfigs must be a whole number from 1 to 17", key=False)
        return Tolerance(sigfigs=v)
    if has_ra:
        vals = {}
        for k in ("rtol", "atol"):
            if k in raw:
                try:
                    v = read_number(raw[k])
                except ValueError as exc:
                    raise FieldError(path + (k,), f"{k}: {exc}", key=False) from None
                top = MAX_RTOL if k == "rtol" else MAX_ATOL
                if not math.isfinite(v) or not 0 <= v <= top:
                    raise FieldError(path + (k,), f"{k} must be a number from 0 to {top:g}", key=False)
                vals[k] = v
        # relative/absolute on top of a sigfigs default starts from the defaults
        start = base if base.sigfigs is None else Tolerance()
        return Tolerance(vals.get("rtol", start.rtol), vals.get("atol", start.atol))
    return base
