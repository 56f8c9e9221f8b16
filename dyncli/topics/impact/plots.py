"""Plots of ``impact`` problems (``dyncli solve --plot``), like the notes'
Fig. 28.4: the admissible friction-angle bounds φ₁(θ), φ₂(θ) of (28.50) over
the approach angle θ for the problem's η, with the given (θ, φ) marked.

Only the general model (``eta``, ``phi``) draws a plot; a smooth impact
(``e``) has f = −n and no friction angle.  The bounds are evaluated with the
solver's own :func:`admissible_bounds`.
"""

from __future__ import annotations

import math

from dyncli.result import Line, Plot
from dyncli.topics.impact.solver import admissible_bounds

POINTS = 181


def plots(problem, result) -> list[Plot]:
    if problem.eta is None:
        return []
    eta = problem.eta
    R = result.results
    thetas = [0.5 * math.pi * i / (POINTS - 1) for i in range(POINTS)]
    bounds = [admissible_bounds(th, eta) for th in thetas]
    lines = [
        Line(thetas, [b[1] for b in bounds], f"φ₂ (upper bound, 28.50b), η = {eta:g}", style="-"),
        Line(thetas, thetas, "φ = θ (inside the bounds, 28.52)", style=":"),
        Line(thetas, [b[0] for b in bounds], f"φ₁ (lower bound, 28.50a), η = {eta:g}", style="--"),
    ]
    theta, phi = R.get("theta"), R.get("phi")
    title = "admissible friction angle φ₁ ≤ φ ≤ φ₂ over the approach angle θ (28.50, 28.53)"
    if theta is not None and phi is not None:
        ok = "admissible" if R.get("admissible") else "NOT admissible"
        lines.append(Line([theta], [phi], f"this impact: θ = {theta:.4g}, φ = {phi:.4g} rad ({ok})",
                          style="", marker="o"))
    else:
        title += " — no impact (the particles do not approach)"
    return [Plot(title, "θ, angle of the approach velocity (28.40) [rad]", "φ, friction angle [rad]", lines)]
