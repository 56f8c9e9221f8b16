"""Diagnosis of a wrong answer (docs/check.md): which common slip, undone,
makes the given value correct within the question's tolerance.

Slips, tried in this order (the first that explains the answer wins):

* ``sign``            given = -true
* ``power_of_ten``    given = true·10^k, k = ±1 … ±9 (mm vs m, g vs kg)
* ``degrees_radians`` given = true·180/π or true·π/180
* ``two_pi``          given = true·2π or true/2π (rad/s vs Hz or rev/s)
* ``factor_two``      given = true·2 or true/2
* ``wrong_dimension`` a unit of another dimension (found while reading the
  answer, see :mod:`dyncli.check.quantities`)

A vector or tensor answer is diagnosed when the same slip explains every
element.  A slip with the sign also wrong is not a diagnosis (two slips).
"""

from __future__ import annotations

import math
from typing import Any, Callable

from dyncli.check.compare import compare
from dyncli.check.slips import FACTORS, SLIPS, TEXT
from dyncli.check.tolerance import Tolerance, number_ok

__all__ = ["SLIPS", "TEXT", "diagnose"]


def _scaled(x: Any, f: float) -> Any:
    """``x`` with every number divided by ``f`` (bools and strings kept)."""
    if isinstance(x, list):
        return [_scaled(v, f) for v in x]
    if isinstance(x, dict):
        return {k: _scaled(v, f) for k, v in x.items()}
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return x / f
    return x


def _is_num(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _has_number(x: Any) -> bool:
    if isinstance(x, list):
        return any(_has_number(v) for v in x)
    if isinstance(x, dict):
        return any(_has_number(v) for v in x.values())
    return isinstance(x, (int, float)) and not isinstance(x, bool) and x != 0 and math.isfinite(x)


def diagnose(given: Any, true: Any, tol: Tolerance,
             ok: Callable[[Any, Any, Tolerance], bool] | None = None) -> str | None:
    """The slip that explains a wrong ``given`` (numbers in SI), or None."""
    if not _has_number(given) or not _has_number(true):
        return None
    if ok is None and _is_num(given) and _is_num(true):     # one number: the scalar rule itself
        ok = lambda g, t, tl: number_ok(float(g), float(t), tl)   # noqa: E731
    ok = ok or (lambda g, t, tl: compare(g, t, tl).correct)
    for name, f in FACTORS:
        if ok(_scaled(given, f), true, tol):
            return name
    return None
