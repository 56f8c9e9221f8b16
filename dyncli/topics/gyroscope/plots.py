"""Plots of ``gyroscope`` problems (``dyncli solve --plot``): θ(t) of (37.12)
with the nutation bounds θ_min, θ_max of (37.13) as horizontal lines and the
requested ``at`` times marked.

θ(t) is the topic's own solver run again on a dense grid of times (``at``);
θ_min, θ_max are the solver's results.  The span is 0 … max(at), or a few
oscillations (from the rates of the problem) when ``at`` ends at 0.
"""

from __future__ import annotations

import math

from dyncli.result import Line, Plot

MIN_POINTS, MAX_POINTS, PER_CYCLE = 600, 4000, 40
MIN_RANGE = 0.02      # rad: the smallest θ range shown


def _rate(p) -> float:
    """A rough angular rate of θ (for the span and the sampling only)."""
    I1, I2, q = p.I1, p.I2, p.q
    return math.sqrt((abs(I1 - I2) * q * q + abs(I1 * p.p * q)) / I2) + abs(p.theta_dot0) + abs(q)


def _range_anchor(values, t0) -> list[Line]:
    """An invisible curve (no line, no marker, no legend entry) that widens
    the θ axis to at least MIN_RANGE rad: a steady θ that drifts by 1e-11
    would otherwise fill the panel with rounding noise."""
    lo, hi = min(values), max(values)
    if hi - lo >= MIN_RANGE:
        return []
    mid = 0.5 * (lo + hi)
    return [Line([t0, t0], [mid - MIN_RANGE / 2, mid + MIN_RANGE / 2], None, style="")]


def plots(problem, result) -> list[Plot]:
    from dyncli.topics.gyroscope.solver import solve

    at = [float(t) for t in problem.at]
    rate = _rate(problem)
    lo, hi = min([0.0] + at), max([0.0] + at)
    if hi <= lo:
        hi = lo + (3 * 2 * math.pi / rate if rate > 0 else 1.0)
    n = int(min(MAX_POINTS, max(MIN_POINTS, PER_CYCLE * rate * (hi - lo) / (2 * math.pi))))
    grid = sorted(set([lo + (hi - lo) * i / (n - 1) for i in range(n)] + at))
    R = solve(problem.model_copy(update={"at": grid})).results
    lines = [Line(grid, R["theta"], "θ(t), tilt of the spin axis (37.12)", style="-")]
    if at:
        lines.append(Line(at, result.results["theta"], "requested times (at)", style="", marker="o"))
    r = result.results
    hl = []
    if r.get("theta_min") is not None:
        hl = [(r["theta_max"], f"θ_max = {r['theta_max']:.6g} rad (37.13)"),
              (r["theta_min"], f"θ_min = {r['theta_min']:.6g} rad (37.13)")]
        title = "θ(t) of the gyroscope between its turning points θ_min, θ_max"
    else:
        title = "θ(t) of the gyroscope: θ circulates (no turning points)"
    lines += _range_anchor(R["theta"] + [y for y, _ in hl], grid[0])
    return [Plot(title, "t [s]", "θ [rad]", lines, hlines=hl)]
