"""Comparison rules of ``dyncli check`` (docs/check.md).

* numbers: correct when ``|given - true| <= atol + rtol*|true|`` (defaults
  ``rtol = 1e-2``, ``atol = 1e-8``, PrairieLearn's numeric-input defaults), or
  with ``sigfigs: n`` when ``|given - true| < 0.51*10**(floor(log10|true|) - n + 1)``
  (PrairieLearn's significant-figure rule; a true value of 0 uses ``10**(1 - n)``);
* vectors, tensors, lists and mappings: element by element, all-or-nothing;
* booleans and strings: exactly (a boolean is never a number);
* ``null`` (not defined) matches only ``null``;
* a non-finite given value (``.inf``, ``.nan``) is never correct;
* a given number may be a YAML number or a string holding a constant
  expression (``"2*pi"``, ``"1.5e3"``, ``"30*deg"``; no params, no variables).

Nothing here formats the expected value: callers decide whether to reveal it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from dyncli.check.slips import TEXT, diagnose_ratios
from dyncli.check.tolerance import (DEFAULT_ATOL, DEFAULT_RTOL, GivenError, Tolerance, number_ok, rel_text, round2,
                                    sigfig_bound, to_number)

__all__ = ["DEFAULT_ATOL", "DEFAULT_RTOL", "GivenError", "Tolerance", "Verdict", "compare", "has_unit_text",
           "number_ok", "rel_text", "round2", "sigfig_bound", "to_number"]


@dataclass
class Verdict:
    """Outcome of comparing one answer.

    ``status``: ``correct``, ``wrong``, ``missing`` (null given for a defined
    quantity) or ``invalid`` (the given value cannot be read).
    ``message`` never contains the expected value."""

    status: str
    message: str = ""
    rel_error: float | None = None    # worst element: |g - t| / |t| (None if t = 0)
    abs_error: float | None = None    # worst element: |g - t|
    wrong_elements: list[str] = field(default_factory=list)   # e.g. ["1", "2.0"]
    hints: list[str] = field(default_factory=list)
    diagnosis: str | None = None      # a slip name of dyncli.check.diagnose

    @property
    def correct(self) -> bool:
        return self.status == "correct"


def _is_num(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


# ---------------------------------------------------------------------------
# structural comparison


class _Walk:
    def __init__(self, tol: Tolerance):
        self.tol = tol
        self.wrong: list[str] = []
        self.reasons: list[str] = []
        self.worst_rel: float | None = None
        self.worst_abs: float | None = None
        self.ratios: list[float] = []      # given/true of wrong non-zero elements
        self.n_numbers = 0
        self.exceeded = False

    def fail(self, where: str, reason: str) -> None:
        self.wrong.append(where)
        self.reasons.append(f"{where}: {reason}" if where else reason)

    def walk(self, given: Any, true: Any, where: str) -> None:
        if true is None:
            if given is not None:
                self.fail(where, "incorrect")
            return
        if given is None:
            self.fail(where, "no value given (null)")
            return
        if isinstance(true, bool):
            if not isinstance(given, bool):
                self.fail(where, "expected true or false")
            elif given is not true:
                self.fail(where, "incorrect")
            return
        if isinstance(true, str):
            if given != true:
                self.fail(where, "incorrect")
            return
        if _is_num(true):
            self.number(given, float(true), where)
            return
        if isinstance(true, list):
            if not isinstance(given, list):
                self.fail(where, f"expected a list of {len(true)} values")
                return
            if len(given) != len(true):
                self.fail(where, f"expected {len(true)} values, got {len(given)}")
                return
            for i, (g, t) in enumerate(zip(given, true)):
                self.walk(g, t, f"{where}.{i}" if where else str(i))
            return
        if isinstance(true, dict):
            if not isinstance(given, dict):
                self.fail(where, f"expected a mapping with entries {', '.join(map(str, true))}")
                return
            gk = {str(k): v for k, v in given.items()}
            tk = {str(k): v for k, v in true.items()}
            missing = [k for k in tk if k not in gk]
            extra = [k for k in gk if k not in tk]
            if missing or extra:
                parts = []
                if missing:
                    parts.append("missing " + ", ".join(missing))
                if extra:
                    parts.append("unknown " + ", ".join(extra))
                self.fail(where, "; ".join(parts))
                return
            for k, t in tk.items():
                self.walk(gk[k], t, f"{where}.{k}" if where else k)
            return
        self.fail(where, "cannot compare")  # pragma: no cover - results are plain data

    def number(self, given: Any, true: float, where: str) -> None:
        self.n_numbers += 1
        if isinstance(given, bool):
            self.fail(where, "expected a number, not true/false")
            return
        if isinstance(given, (list, dict)):
            self.fail(where, "expected a single number")
            return
        g = to_number(given)
        if g is None:  # pragma: no cover - covered by the checks above
            self.fail(where, "expected a number")
            return
        if not math.isfinite(g):
            self.fail(where, "not a finite number (write null for a quantity that is not defined)")
            return
        d = abs(g - true)
        rel = d / abs(true) if true != 0 else None
        if self.worst_abs is None or d > self.worst_abs:
            self.worst_abs = d
        if rel is not None and (self.worst_rel is None or rel > self.worst_rel):
            self.worst_rel = rel
        if not number_ok(g, true, self.tol):
            if true != 0 and g != 0:
                self.ratios.append(g / true)
            # never an absolute error: for a true 0 it would be the given value itself
            err = f"relative error {rel_text(rel)}" if rel is not None else "error"
            self.exceeded = True
            self.fail(where, err)


def _hints(ratios: list[float], tol: Tolerance) -> tuple[str | None, list[str]]:
    """The common slip shared by every wrong element (sign, powers of ten,
    2π, degrees, 2), as (slip name, [hint text])."""
    rt = max(tol.rtol if tol.sigfigs is None else 0.51 * 10.0 ** (1 - tol.sigfigs), 1e-9)
    hit = diagnose_ratios(ratios, rt)
    if hit is None:
        return None, []
    name, factor = hit
    if name == "power_of_ten":
        k = round(math.log10(factor))
        shown = f"{10 ** k}" if k > 0 else f"1/{10 ** -k}"
        return name, [f"off by a factor of {shown} (units? e.g. mm vs m, g vs kg)"]
    return name, [TEXT[name]]


def compare(given: Any, true: Any, tol: Tolerance, unit=None) -> Verdict:
    """Compare one answer with the solved value.  ``unit``: a
    :class:`~dyncli.check.quantities.UnitSpec` for numbers with units."""
    if given is None and true is not None:
        return Verdict("missing", "no value given (null)")
    if has_unit_text(given) or (unit is not None and unit.scale != 1.0):
        from dyncli.check.quantities import NO_UNIT, WrongDimension, convert

        try:
            given = convert(given, unit or NO_UNIT)
        except WrongDimension as exc:
            return Verdict("wrong", str(exc), diagnosis="wrong_dimension")
    w = _Walk(tol)
    try:
        w.walk(given, true, "")
    except GivenError as exc:
        return Verdict("invalid", str(exc))
    if not w.wrong:
        return Verdict("correct", "", w.worst_rel, w.worst_abs)
    slip, hints = _hints(w.ratios, tol) if len(w.ratios) == len(w.wrong) else (None, [])
    elems = [x for x in w.wrong if x]
    if not elems:
        msg = w.reasons[0]
        if w.exceeded:
            msg += f" exceeds the tolerance ({tol.describe()})"
    else:
        total = _count_leaves(true)
        shown = "; ".join(w.reasons[:3]) + ("; ..." if len(w.reasons) > 3 else "")
        msg = f"{len(elems)} of {total} elements wrong ({shown})"
        if w.exceeded:
            msg += f"; tolerance: {tol.describe()}"
    if hints:
        msg += "; hint: " + hints[0]
    return Verdict("wrong", msg, w.worst_rel, w.worst_abs, elems, hints, slip)


def has_unit_text(x: Any) -> bool:
    """Whether a given answer holds a string that may be a number with a unit."""
    if isinstance(x, list):
        return any(has_unit_text(v) for v in x)
    if isinstance(x, dict):
        return any(has_unit_text(v) for v in x.values())
    return isinstance(x, str) and any(c.isalpha() for c in x) and any(c.isdigit() for c in x)


def _count_leaves(x: Any) -> int:
    if isinstance(x, list):
        return sum(_count_leaves(v) for v in x) or 1
    if isinstance(x, dict):
        return sum(_count_leaves(v) for v in x.values()) or 1
    return 1
