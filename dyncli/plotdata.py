"""Helpers the topics' ``plots.py`` share to build plot data (no matplotlib here).

* :func:`n_points` — how many samples a time span needs: ``per_cycle`` per
  period of the fastest rate, clipped to [lo, hi];
* :func:`range_anchor` — an invisible curve that keeps an axis from zooming
  into rounding noise when a value is (nearly) constant.
"""

from __future__ import annotations

import math

from dyncli.result import Line


def n_points(rate: float, span: float, *, per_cycle: int, lo: int, hi: int) -> int:
    """Samples for ``span`` seconds of a motion whose fastest angular rate is
    ``rate`` rad/s: ``per_cycle`` per period, at least ``lo``, at most ``hi``."""
    want = per_cycle * rate * span / (2 * math.pi)
    return int(min(hi, max(lo, want if math.isfinite(want) else hi)))


def range_anchor(values, t0: float, min_range: float) -> list[Line]:
    """An invisible curve (no line, no marker, no legend entry) at ``t0`` that
    widens the value axis to at least ``min_range``: a steady value that
    drifts by 1e-11 would otherwise fill the panel with rounding noise."""
    lo, hi = min(values), max(values)
    if hi - lo >= min_range:
        return []
    mid = 0.5 * (lo + hi)
    return [Line([t0, t0], [mid - min_range / 2, mid + min_range / 2], None, style="")]
