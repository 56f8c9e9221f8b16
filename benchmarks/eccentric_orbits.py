"""The ODE route of `particle` on eccentric Kepler orbits (issue #28): true error vs the default
error_estimate and vs the 100 x rtol promise.

mu = g R0² = 1 (R0 = 1, g = 1), r_p = 1, released at perigee; 5 revolutions; `at`: 400 equally
spaced times plus every perigee passage.  The ODE route is forced (accuracy.method DOP853); the
reference is the exact Kepler route of the same file (itself checked against mpmath at 30 digits
in tests/topics/particle/test_kepler.py).  Error: the largest |ODE − exact| of every reported
quantity (x, v, a, T, V, E, H_O), each relative to its scale (the largest magnitude over the
times), the measure error_estimate promises to bound.

    PYTHONPATH=. python benchmarks/eccentric_orbits.py [--estimate]
"""

from __future__ import annotations

import math
import sys
import time

import numpy as np

from dyncli.loader import split_problems, validate
from dyncli.run import solve_one

QUANTITIES = ("x", "v", "a", "T", "V", "E", "H_O")


def problem(e: float, rtol: float, method: str, estimate: bool = False) -> str:
    vp = math.sqrt(1 + e)
    a = 1 / (1 - e)
    T = 2 * math.pi * a ** 1.5
    at = sorted(set([5 * T * k / 400 for k in range(401)] + [k * T for k in range(6)]))
    return (f"type: particle\nm: 1\ng: 1\nx0: [1, 0, 0]\nv0: [0, {vp!r}, 0]\n"
            "forces: [{kind: inverse-square, R0: 1}]\n"
            f"t_end: {5 * T!r}\nat: {[float(t) for t in at]}\n"
            f"accuracy: {{rtol: {rtol!r}, atol: 1.0e-30, method: {method}, estimate: {str(estimate).lower()}}}\n")


def solve(text):
    (lp,), _ = split_problems("orbit.yaml", text.encode(), None)
    validate(lp)
    t0 = time.perf_counter()
    out = solve_one(lp)
    if out.result is None:
        raise SystemExit(out.message)
    return out.result, time.perf_counter() - t0


def error(ode, ref) -> float:
    worst = 0.0
    for k in QUANTITIES:
        a, b = np.asarray(ode.results[k], float), np.asarray(ref.results[k], float)
        s = float(np.max(np.abs(b)))
        if s > 0:
            worst = max(worst, float(np.max(np.abs(a - b))) / s)
    return worst


def main(estimate: bool = False) -> None:
    print("| e | rtol | error / rtol | estimate / error | internal rtol | steps | time [s] | warning |")
    print("|---|---|---|---|---|---|---|---|")
    for e in (0.5, 0.9, 0.97):
        for rtol in (1e-6, 1e-8, 1e-10, 1e-12):
            ref, _ = solve(problem(e, rtol, "exact"))
            ode, dt = solve(problem(e, rtol, "DOP853", estimate))
            err = error(ode, ref)
            est = ode.error_estimate
            note = ode.extra.get("error_estimate_note", "")
            inner = note.split("tightened to ")[1].split(" ")[0] if "tightened to" in note else f"{rtol:.0e}"
            missed = any("not met" in w for w in ode.warnings)
            print(f"| {e} | {rtol:.0e} | {err / rtol:.3g} | {est / err:.3g} | {inner} | {ode.extra.get('nsteps')} "
                  f"| {dt:.2f} | {'not met' if missed else ''} |")


if __name__ == "__main__":
    main("--estimate" in sys.argv)
