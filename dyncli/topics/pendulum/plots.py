"""Plots of ``pendulum`` problems (``dyncli solve --plot``).

* θ(t) over 0 … max(at) (or three periods, or 6/ωₙ on the separatrix), the amplitude ±θ_max of a
  swing as horizontal lines and the requested ``at`` times marked;
* the phase portrait (θ, θ̇) of that span with the separatrix θ̇ = ±2ωₙ cos(θ/2), which parts the
  swings inside it from the rotations outside.

The curves come from the solver's sampler (``result.extra["sample"]``: the elliptic solution at
the grid's times); nothing here re-derives the motion.
"""

from __future__ import annotations

import math

from dyncli.plotdata import n_points, range_anchor
from dyncli.result import Line, Plot

MIN_POINTS, MAX_POINTS, PER_CYCLE = 400, 4000, 60
MIN_RANGE = 0.02        # rad: the smallest θ range shown
SEPARATRIX = 201


def plots(problem, result) -> list[Plot]:
    if "sample" not in result.extra:
        return []
    R = result.results
    at = [float(t) for t in problem.at]
    wn, T = R["omega_n"], R["period"]
    hi = max([0.0] + at)
    if hi <= 0.0:
        hi = 3.0 * T if T else 6.0 / wn
    rate = 2 * math.pi / T if T else wn
    n = n_points(rate, hi, per_cycle=PER_CYCLE, lo=MIN_POINTS, hi=MAX_POINTS)
    grid = sorted(set([hi * i / (n - 1) for i in range(n)] + at))
    states = result.extra["sample"](grid)
    th, thd = [s[0] for s in states], [s[1] for s in states]

    lines = [Line(grid, th, "θ(t) by Jacobi's elliptic functions", style="-")]
    if at:
        lines.append(Line(at, R["theta"], "requested times (at)", style="", marker="o"))
    hl = []
    if R.get("theta_max") is not None:
        tm = R["theta_max"]
        hl = [(tm, f"θ_max = {tm:.6g} rad"), (-tm, "−θ_max")]
    lines += range_anchor(th + [y for y, _ in hl], grid[0], MIN_RANGE)
    motion = Plot(f"θ(t) of the pendulum ({R['regime']})", "t [s]", "θ [rad]", lines, hlines=hl)

    ang = [-math.pi + 2 * math.pi * i / (SEPARATRIX - 1) for i in range(SEPARATRIX)]
    sep = [2 * wn * math.cos(a / 2) for a in ang]
    portrait = Plot("phase portrait (θ, θ̇) and the separatrix θ̇ = ±2ωₙ cos(θ/2)", "θ [rad]", "θ̇ [rad/s]",
                    [Line(th, thd, "the motion", style="-"),
                     Line(ang + ang[::-1], sep + [-v for v in sep[::-1]], "separatrix", style="--"),
                     Line([th[0]], [thd[0]], "start", style="", marker="s")])
    return [motion, portrait]
