"""Plots of ``particle`` problems (``dyncli solve --plot``).

* the trajectory x(t) in 3-D from x(0) to x(t_end), the requested ``at``
  states marked, and the attracting centre of every inverse-square force (the
  focus of an orbit);
* the energies over time: T, V, E = T + V and the work W̄ of the
  non-conservative forces, with the initial energy E₁ as a reference line
  (by (20.4) E − E₁ = W̄, so E falls below E₁ exactly as W̄ goes negative).

The dense curves come from the solver's dense output
(``result.extra["sample"]``, the integration already done, evaluated on a
fine grid); nothing here re-derives or re-solves the motion.  A path in a
plane of the basis is drawn in 2-D by the renderer.
"""

from __future__ import annotations

from dyncli.result import Line, Plot

POINTS = 600


def _dense(problem, result):
    T = float(problem.t_end)
    grid = sorted(set([T * i / (POINTS - 1) for i in range(POINTS)] + [float(t) for t in problem.at]))
    S = result.extra["sample"](grid)
    R = {k: S[k].tolist() for k in ("T", "V", "E", "W_nc")}
    R["x"] = S["x"].T.tolist()
    return grid, R


def _centres(problem) -> list[tuple[float, float, float]]:
    """The distinct centres of the problem's inverse-square forces."""
    out: list[tuple[float, float, float]] = []
    for f in problem.forces:
        c = (float(f.center[0]), float(f.center[1]), float(f.center[2])) if f.kind == "inverse-square" else None
        if c is not None and c not in out:
            out.append(c)
    return out


def plots(problem, result) -> list[Plot]:
    if "sample" not in result.extra:
        return []
    t, R = _dense(problem, result)
    xs = R["x"]
    at = [float(a) for a in problem.at]
    xa = result.results["x"]
    traj = [
        Line([p[0] for p in xs], [p[1] for p in xs], "path x(t), 0 ≤ t ≤ t_end", style="-", z=[p[2] for p in xs]),
        Line([p[0] for p in xa], [p[1] for p in xa], "states at the requested times (at)", style="",
             marker="o", z=[p[2] for p in xa]),
        Line([xs[0][0]], [xs[0][1]], "start x(0)", style="", marker="s", z=[xs[0][2]]),
    ]
    for c in _centres(problem):
        traj.append(Line([c[0]], [c[1]], "attracting centre (inverse-square force)", style="", marker="*",
                         z=[c[2]]))
    E1 = R["E"][0]
    energy = [
        Line(t, R["T"], "T, kinetic energy", style="-"),
        Line(t, R["V"], "V, potential energy (20.5)", style="--"),
        Line(t, R["E"], "E = T + V", style="-."),
        Line(t, R["W_nc"], "W̄, work of the non-conservative forces (20.3)", style=":"),
    ]
    if at:
        energy.append(Line(at, result.results["E"], "E at the requested times (at)", style="", marker="o"))
    return [
        Plot("trajectory x(t) of the particle (16.7)", "x₁ [m]", "x₂ [m]", traj, zlabel="x₃ [m]"),
        Plot("energy: T, V, E and W̄ over time (E − E₁ = W̄, 20.4)", "t [s]", "energy [J]", energy,
             hlines=[(E1, "E₁, initial energy")]),
    ]
