"""``euler`` with an applied moment at equal error: dyncli's solver-only time over a plain scipy
``solve_ivp(DOP853)`` script of the same equations (issue 31 item 3).

The body I = (1, 2, 3) kg·m², ω0 = (0.1, 0, 2) rad/s, M(t) = (0.1 sin t, 0.2 cos 2t, 0.05) N·m,
ω reported at t = 1, 5, 20 s.  The reference is the same equations by DOP853 at rtol 1e-14,
atol 1e-16 (its error is far below the errors compared here).

1. dyncli solves at ``rtol`` (atol = 1e-3 rtol, no error estimate); its error E against the
   reference is measured (max over the reported components of |Δω|, absolute: |ω| ~ 2 rad/s);
2. the plain scipy script (3 equations in plain floats, ``t_eval``) runs on a grid of rtols
   10^(-k/4); the loosest rtol whose error, and the error at every tighter grid rtol, is <= E
   is "scipy at equal error";
3. both are timed warm (CPU time, interleaved rounds, median), and the ratio dyncli/scipy printed
   (the validated model is reused: no YAML, no validation in dyncli's time).

Usage: python benchmarks/euler_cost.py [--rtols 1e-6 1e-8 1e-10] [--repeats 9]
Goal (issue 31 item 3): dyncli/scipy <= 1.2 at equal error.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.runner_cost import GRID, interleaved  # noqa: E402

I = (1.0, 2.0, 3.0)
W0 = [0.1, 0.0, 2.0]
AT = [1.0, 5.0, 20.0]
M_TEXT = ["0.1*sin(t)", "0.2*cos(2*t)", "0.05"]


def script(rtol, atol):
    """What a student writes: Euler's equations (39.5) with M(t), DOP853, t_eval."""
    from scipy.integrate import solve_ivp

    I1, I2, I3 = I

    def rhs(t, w):
        M1, M2, M3 = 0.1 * math.sin(t), 0.2 * math.cos(2 * t), 0.05
        return [(M1 - (I3 - I2) * w[1] * w[2]) / I1, (M2 - (I1 - I3) * w[2] * w[0]) / I2,
                (M3 - (I2 - I1) * w[0] * w[1]) / I3]

    sol = solve_ivp(rhs, (0.0, AT[-1]), W0, method="DOP853", rtol=rtol, atol=atol, t_eval=AT)
    return sol.y.T.ravel().tolist()


def error(values, ref) -> float:
    return max(abs(v - r) for v, r in zip(values, ref))


def dyncli_solver(rtol):
    """(ω at AT, the solver call alone on the validated model)."""
    from dyncli.registry import solver
    from dyncli.result import SolveOptions
    from dyncli.topics.euler.model import Euler

    pb = Euler.model_validate({"type": "euler", "I": list(I), "omega0": W0, "M": M_TEXT, "at": AT,
                               "accuracy": {"method": "DOP853", "rtol": rtol, "atol": rtol * 1e-3}})
    fn = solver("euler")
    res = fn(pb, SolveOptions())
    return [c for w in res.results["omega"] for c in w], lambda: fn(pb, SolveOptions())


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--rtols", type=float, nargs="+", default=[1e-6, 1e-8, 1e-10])
    ap.add_argument("--repeats", type=int, default=9)
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    ref = script(1e-14, 1e-16)
    load = os.getloadavg()
    print(f"euler with M(t) at equal error (warm, solver only, CPU time, median of {args.repeats} interleaved "
          f"rounds); load average {load[0]:.2f} on {os.cpu_count()} CPUs")
    print(f"{'rtol':>6} {'dyncli ms':>9} {'error':>8} | {'scipy rtol':>10} {'ms':>7} {'error':>8} | {'ratio':>5}")
    for rtol in args.rtols:
        vals, plain = dyncli_solver(rtol)
        err = error(vals, ref)
        best = None
        for r in reversed(GRID):
            e = error(script(r, r * 1e-3), ref)
            if e > err:
                break
            best = (r, e)
        if best is None:
            print(f"{rtol:6.0e}  scipy never reaches dyncli's error {err:.1e} on the grid")
            continue
        r_s, e_s = best
        t_d, t_s = interleaved([plain, lambda: script(r_s, r_s * 1e-3)], args.repeats)
        print(f"{rtol:6.0e} {t_d * 1e3:9.2f} {err:8.1e} | {r_s:10.1e} {t_s * 1e3:7.2f} {e_s:8.1e} | {t_d / t_s:5.2f}")


if __name__ == "__main__":
    main()
