"""constrained-particle's ODE route at equal error against a plain scipy script of the same
equation (issue #26: goal <= 1.2x), in the manner of benchmarks/runner_cost.py.

The problem: a bead on a hoop of radius R turning at ω about its vertical diameter, q̈ = sin q
(ω² cos q − g/R), on the ODE route (``method: ode``: left to itself the hoop, a closed curve, has
the Jacobi integral and takes the quadrature route).  The reference
is mpmath's Taylor-series ODE solver at 30 digits; the error of q and q̇, each relative to its
scale over the requested times.

1. dyncli solves at ``rtol`` (atol = 1e-3 rtol) with ``estimate: false`` (the model reused: no
   YAML, no validation); its true error E against the reference;
2. ``solve_ivp(method="DOP853", t_eval=times)`` of the same equation in plain floats on a grid
   of rtols 10^(-k/4): the loosest rtol whose error (and every tighter one's) is <= E;
3. both timed warm (CPU time, interleaved, median of ``--repeats``).

Usage: python benchmarks/constrained_cost.py [--rtols 1e-6 1e-8 1e-10] [--repeats 9]

Measured (issue 31, load 5-6 on 2 CPUs, the code before and after run back to back in rounds,
median of 5 x 40): dyncli 3.19 / 4.30 / 5.94 ms against the script's 1.15 / 1.88 / 2.77 ms at rtol
1e-6 / 1e-8 / 1e-10: ratios 2.77 / 2.28 / 2.14 (3.57 / 2.72 / 2.28 before every sliding step's
interpolant was made once after the run and the times read in one pass over the stacked steps;
2.79 / 2.22 / 2.03 at load 1 in issue 26, 4.26 / 3.51 / 3.41 before that issue's right-hand side).
Then 2.65 / 3.45 / 4.70 -> 2.36 / 3.10 / 4.34 ms, ratios 2.37 / 2.00 / 1.81 -> 2.09 / 1.83 / 1.70
(load 5-7, back to back: the turning roots in plain floats, y' and y'' read once, docs/accuracy.md).
The steps are the script's (15 / 24 / 40); the integration alone costs about the script's whole
time; the rest is the results the script does not compute (docs/accuracy.md).
The hoop, a closed curve, also has its relative equilibria in the result ("equil ms", the solve
with them left out: "w/o eq"): 4.72 / 5.50 / 6.90 ms, ratios 4.09 / 3.10 / 2.59, of which the
equilibria 2.06 / 2.10 / 2.22 ms (36 ms before all_roots read its cells in batches; without them
2.30 / 1.92 / 1.76; load 1.4-2.1, median of 21).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import warnings
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from runner_cost import interleaved  # noqa: E402  the benchmarks' one timing loop

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

R, W, G, Q0 = 0.5, 6.0, 9.81, 0.3
TIMES = [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0]
GRID = [10.0 ** (-k / 4) for k in range(8, 57)]
TEXT = """type: constrained-particle
m: 0.1
curve: {{x1: "{R}*sin(q)", x2: 0, x3: "-{R}*cos(q)"}}
rotation: {{axis: [0, 0, 1], omega: {W}}}
q0: {Q0}
forces: [{{kind: gravity}}]
at: {TIMES}
accuracy: {{rtol: {rtol}, atol: {atol}, estimate: {estimate}, method: ode}}
"""


def reference():
    import mpmath

    mpmath.mp.dps = 30
    f = mpmath.odefun(lambda t, y: [y[1], mpmath.sin(y[0]) * (W * W * mpmath.cos(y[0]) - mpmath.mpf(G) / R)],
                      0, [mpmath.mpf(Q0), 0])
    return [[float(v) for v in f(t)] for t in TIMES]


def error(qs, qds, ref) -> float:
    sq = max(abs(r[0]) for r in ref)
    sqd = max(abs(r[1]) for r in ref)
    return max(max(abs(a - r[0]) / sq, abs(b - r[1]) / sqd) for a, b, r in zip(qs, qds, ref))


def script(rtol, atol):
    from scipy.integrate import solve_ivp

    k = G / R

    def rhs(t, y):
        q, qd = y
        return [qd, math.sin(q) * (W * W * math.cos(q) - k)]

    sol = solve_ivp(rhs, (0.0, TIMES[-1]), [Q0, 0.0], method="DOP853", t_eval=TIMES, rtol=rtol, atol=atol)
    return sol.y[0].tolist(), sol.y[1].tolist()


def dyncli_solver(rtol, estimate):
    from dyncli import registry
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions

    text = TEXT.format(R=R, W=W, G=G, Q0=Q0, TIMES=TIMES, rtol=rtol, atol=rtol * 1e-3,
                       estimate="true" if estimate else "false")
    (lp,), _ = split_problems("cost.yaml", text.encode(), ROOT)
    validate(lp)
    fn = registry.solver(lp.type)
    return fn(lp.model, SolveOptions()), lambda: fn(lp.model, SolveOptions())


def without_equilibria(fn):
    """``fn`` with the relative equilibria left out (their search timed apart: the script has none)."""
    from dyncli.topics.constrained_particle import equilibria

    def run():
        add, equilibria.add = equilibria.add, lambda res, p, model: None
        try:
            return fn()
        finally:
            equilibria.add = add
    return run


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--rtols", type=float, nargs="+", default=[1e-6, 1e-8, 1e-10])
    ap.add_argument("--repeats", type=int, default=9)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    ref = reference()
    print(f"load average {os.getloadavg()[0]:.2f}; CPU ms, median of {args.repeats}")
    print(f"{'rtol':>6} {'dyncli ms':>9} {'error':>8} {'est':>8} {'check ms':>8} {'equil ms':>8} | "
          f"{'scipy rtol':>10} {'ms':>6} {'error':>8} | {'ratio':>5} {'w/o eq':>6}")
    for rtol in args.rtols:
        res, plain = dyncli_solver(rtol, False)
        _, with_check = dyncli_solver(rtol, True)
        err = error(res.results["q"], res.results["q_dot"], ref)
        got = None
        for r in reversed(GRID):
            e = error(*script(r, r * 1e-3), ref)
            if e > err:
                break
            got = (r, e)
        if got is None:
            print(f"{rtol:6.0e}  scipy never reaches {err:.1e}")
            continue
        t_d, t_c, t_e, t_s = interleaved([plain, with_check, without_equilibria(plain),
                                          lambda: script(got[0], got[0] * 1e-3)], args.repeats)
        print(f"{rtol:6.0e} {t_d * 1e3:9.2f} {err:8.1e} {res.error_estimate:8.1e} {(t_c - t_d) * 1e3:8.2f} "
              f"{(t_d - t_e) * 1e3:8.2f} | {got[0]:10.1e} {t_s * 1e3:6.2f} {got[1]:8.1e} | {t_d / t_s:5.2f} "
              f"{t_e / t_s:6.2f}")


if __name__ == "__main__":
    main()
