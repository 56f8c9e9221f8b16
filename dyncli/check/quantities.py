"""Given answers with units (docs/check.md).

A given scalar is a YAML number, a constant expression (``"2*pi"``) or a
number with a unit (``"12 m/s"``, ``"1200 mm"``, ``"30 deg"``).  Numbers and
expressions are *bare*: they are read in the question's ``unit`` when the
key gives one, else as SI.  A number with a unit is converted to SI with
the units layer of problem files (pint, imported only when such a string is
met); when the expected dimension is known (the question's ``unit``, else
the unit the solver reports for that result) a unit of another dimension is
the slip ``wrong_dimension``: a diagnosed wrong answer, never invalid input.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from dyncli.check.tolerance import GivenError
from dyncli.check.safe import shown

__all__ = ["GivenError", "WrongDimension", "UnitSpec", "NO_UNIT", "unit_spec", "result_unit", "to_si", "convert"]


class WrongDimension(ValueError):
    """A number with a unit of another dimension than the expected one."""


@dataclass(frozen=True)
class UnitSpec:
    """How bare numbers and unit strings of one question are read.

    ``scale``: SI value of one ``unit`` (bare numbers are multiplied by it);
    ``dim``: the expected pint dimensionality (None when unknown)."""

    unit: str | None = None
    scale: float = 1.0
    dim: Any = None
    noun: str = ""


NO_UNIT = UnitSpec()


def _ureg():
    from dyncli.units import registry

    return registry()


def _parse_unit(text: str, angular: bool = False):
    from dyncli import units

    return _ureg().parse_units(units.clean_unit(text, angular))


@lru_cache(maxsize=512)
def unit_spec(unit: str | None, bare: bool = True) -> UnitSpec:
    """The :class:`UnitSpec` of a unit text (``"m/s"``, ``"kg·m²"``);
    ``bare=False``: the unit only fixes the dimension (a solver's SI unit),
    bare numbers stay SI.  Raises ValueError for an unknown unit."""
    if not unit:
        return NO_UNIT
    try:
        q = _ureg().Quantity(1.0, _parse_unit(unit))
        si = q.to_base_units()
    except Exception:  # noqa: BLE001 - pint raises assorted errors on garbage
        raise ValueError(f"unknown unit '{shown(unit)}'") from None
    return UnitSpec(unit, float(si.magnitude) if bare else 1.0, q.dimensionality, unit)


def result_unit(units: dict[str, str], path: str) -> str | None:
    """The SI unit a solver reports for a dotted result path (:func:`dyncli.frames.column_unit`,
    the frames' own rule), None when it has none."""
    from dyncli.frames import column_unit

    return column_unit(units, str(path)) or None


def to_si(given: Any, spec: UnitSpec = NO_UNIT) -> float | None:
    """A given scalar in SI, or None when it is not numeric (bool, list,
    mapping, null).  Raises :class:`GivenError` (unreadable) or
    :class:`WrongDimension`."""
    if isinstance(given, bool) or given is None or isinstance(given, (list, dict)):
        return None
    if isinstance(given, (int, float)):
        try:
            return float(given) * spec.scale
        except OverflowError:
            return math.inf if given > 0 else -math.inf
    if not isinstance(given, str):  # pragma: no cover - YAML gives no other scalars
        return None
    from dyncli.errors import InputError
    from dyncli.expr import parse

    try:
        return float(parse(given, (), {}).value()) * spec.scale
    except InputError as exc:
        first = exc.message
    except (ValueError, ArithmeticError) as exc:  # pragma: no cover - defensive
        first = str(exc)
    from dyncli import units

    if not units.looks_like_quantity(given):
        import re

        name = re.match(r"unknown name '([^']*)'", first)
        if name:                        # (the expression language's hint, params, is not a submission's)
            first = (f"'{name.group(1)}' is not a number or a unit here: write a number, an expression of "
                     "numbers (2*pi/3), or a number and its unit after a space ('19.6 m/s', '3.2 1/s')")
        raise GivenError(f"cannot read '{shown(given)}' as a number: {shown(first, 160)}")
    return _quantity(given, spec)


def _quantity(text: str, spec: UnitSpec) -> float:
    from dyncli import units

    m = units.QUANTITY.match(text)
    unit_text = m.group("unit").strip() if m else ""
    if not m or len(unit_text) > units.MAX_UNIT_TEXT:
        raise GivenError(f"cannot read '{shown(text)}' as a number with a unit")
    try:
        num = float(m.group("num"))
        q = _ureg().Quantity(num, _parse_unit(unit_text, angular=units.is_angular(spec.unit)))  # Hz: cycles/s
    except Exception:  # noqa: BLE001 - pint raises assorted errors on garbage
        raise GivenError(f"unknown unit '{shown(unit_text)}' in '{shown(text)}'") from None
    if spec.dim is not None and q.dimensionality != spec.dim:
        want = f" ({spec.noun})" if spec.noun else ""
        raise WrongDimension(f"wrong dimension: '{shown(text)}' is not in the unit of this answer{want}")
    try:
        return float(q.to_base_units().magnitude)
    except Exception:  # noqa: BLE001
        raise GivenError(f"cannot convert '{shown(text)}' to SI") from None


def convert(given: Any, spec: UnitSpec = NO_UNIT) -> Any:
    """A given answer (scalar, list, mapping) with every readable number in
    SI; strings that are not numbers stay (string results compare exactly).
    Raises :class:`WrongDimension` for a unit of another dimension."""
    if isinstance(given, list):
        return [convert(x, spec) for x in given]
    if isinstance(given, dict):
        return {k: convert(v, spec) for k, v in given.items()}
    if isinstance(given, str):
        try:
            return to_si(given, spec)
        except GivenError:
            return given
    if isinstance(given, (int, float)) and not isinstance(given, bool):
        return to_si(given, spec)
    return given
