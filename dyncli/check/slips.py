"""The common slips of ``dyncli check`` (docs/check.md, "Diagnosis"): their
names, the factor each one multiplies an answer by, and the words
feedback says of them.  Tried in this order (the first that fits wins):
``sign``, ``power_of_ten`` (10^k, 1 <= |k| <= 9), ``degrees_radians``,
``two_pi``, ``factor_two``; ``wrong_dimension`` is found while reading a
unit (:mod:`dyncli.check.quantities`).

Only data and the ratio test: :mod:`dyncli.check.compare` names the slip
shared by every wrong element (its hint), :mod:`dyncli.check.diagnose` the
slip that explains a whole answer.
"""

from __future__ import annotations

import math

SLIPS = ("sign", "power_of_ten", "degrees_radians", "two_pi", "factor_two", "wrong_dimension")

TEXT = {
    "sign": "the sign looks wrong",
    "power_of_ten": "off by a power of ten (units? e.g. mm vs m, g vs kg)",
    "degrees_radians": "off by a factor 180/π (degrees vs radians?)",
    "two_pi": "off by a factor 2π (rad/s vs Hz or rev/s?)",
    "factor_two": "off by a factor of 2",
    "wrong_dimension": "the unit has the wrong dimension",
}


def _factors() -> list[tuple[str, float]]:
    out = [("sign", -1.0)]
    for k in range(1, 10):
        out += [("power_of_ten", 10.0 ** k), ("power_of_ten", 10.0 ** -k)]
    out += [("degrees_radians", 180 / math.pi), ("degrees_radians", math.pi / 180),
            ("two_pi", 2 * math.pi), ("two_pi", 1 / (2 * math.pi)),
            ("factor_two", 2.0), ("factor_two", 0.5)]
    return out


FACTORS = _factors()


def diagnose_ratios(ratios: list[float], rtol: float) -> tuple[str, float] | None:
    """The slip (name, factor) shared by every ratio given/true of the wrong
    elements (the hint of §5 feedback), or None."""
    if not ratios:
        return None
    for name, f in FACTORS:
        if all(abs(r - f) <= rtol * abs(f) for r in ratios):
            return name, f
    return None
