"""Exact time derivatives of user expressions: forward-mode AD jets
(dyncli.expr.jet) versus sympy (dyncli.symbolic.diff, which
differentiates and converts back to dyncli's evaluator).

Prints, from one run:
  * cold start: a fresh interpreter that derives x, x', x'' of a few
    expressions (AD needs numpy only; the sympy route imports sympy);
  * warm setup per expression (sympy diff + conversion vs building the jet);
  * evaluation time at N times, and the ratio sympy/AD;
  * accuracy of both against mpmath at 40 digits.

Run from the worktree root:  /work/venv/bin/python benchmarks/kinematics_derivatives.py
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

EXPRS = [
    "2 + 0.5*sin(t)",                                        # spherical R
    "0.3*t",                                                  # spherical phi
    "s0 + c*sin(3*t)",                                        # slot
    "exp(-0.1*t)*sin(3*t)**2 + sqrt(1 + t**2)*atan(t)",       # heavier
    "log(2 + t)*cosh(0.2*t)/(1 + t**2) + t**1.5",
]
PARAMS = {"s0": 0.1, "c": 0.05}

COLD_AD = """
import numpy as np
from dyncli import expr
from dyncli.expr.jet import jet
t = np.linspace(0.1, 2, 5)
for s in {exprs!r}:
    e = expr.parse(s, ("t",), {params!r})
    jet(e, t)
"""
COLD_SYMPY = """
import numpy as np
from dyncli import expr, symbolic
t = np.linspace(0.1, 2, 5)
for s in {exprs!r}:
    e = expr.parse(s, ("t",), {params!r})
    e.evaluate(t=t); symbolic.diff(e, "t", 1).evaluate(t=t); symbolic.diff(e, "t", 2).evaluate(t=t)
"""


def cold(code: str, reps: int = 5) -> float:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    best = float("inf")
    for _ in range(reps):
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-c", code.format(exprs=EXPRS, params=PARAMS)], check=True, env=env, cwd=ROOT)
        best = min(best, time.perf_counter() - t0)
    return best


def best_of(fn, reps: int = 5) -> float:
    best = float("inf")
    for _ in range(reps):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    import mpmath
    import numpy as np

    from dyncli import expr, symbolic
    from dyncli.expr import jet as J

    print("cold start (fresh interpreter, derive 5 expressions at 5 times; best of 5)")
    c_ad, c_sp = cold(COLD_AD), cold(COLD_SYMPY)
    print(f"  AD jets : {c_ad * 1e3:8.1f} ms")
    print(f"  sympy   : {c_sp * 1e3:8.1f} ms   ratio sympy/AD = {c_sp / c_ad:.2f}")

    parsed = [expr.parse(s, ("t",), PARAMS) for s in EXPRS]
    symbolic.diff(parsed[0], "t")  # import sympy outside the timings

    def setup_sympy():
        for e in parsed:
            symbolic.diff(e, "t", 1)
            symbolic.diff(e, "t", 2)

    def setup_ad():
        for e in parsed:
            J.compile_jet(e.ir)

    s_sp, s_ad = best_of(setup_sympy), best_of(setup_ad)
    print("warm setup for the 5 expressions (sympy: diff + convert back; AD: build the jet closures)")
    print(f"  AD jets : {s_ad * 1e3:8.3f} ms")
    print(f"  sympy   : {s_sp * 1e3:8.3f} ms   ratio sympy/AD = {s_sp / s_ad:.0f}")

    d1 = [symbolic.diff(e, "t", 1) for e in parsed]
    d2 = [symbolic.diff(e, "t", 2) for e in parsed]
    jets = [J.compile_jet(e.ir) for e in parsed]
    print("evaluation of (f, f', f'') for the 5 expressions (setup excluded)")
    for n in (10, 10_000, 1_000_000):
        t = np.linspace(0.1, 2.0, n)

        def ev_sympy():
            for e, a, b in zip(parsed, d1, d2):
                e(t=t), a(t=t), b(t=t)

        def ev_ad():
            with np.errstate(all="ignore"):
                for f in jets:
                    f({"t": t})

        reps = 3 if n >= 1_000_000 else 20
        e_sp, e_ad = best_of(ev_sympy, reps), best_of(ev_ad, reps)
        print(f"  N = {n:>9,}: AD {e_ad * 1e3:9.3f} ms   sympy-exprs {e_sp * 1e3:9.3f} ms   ratio sympy/AD = {e_sp / e_ad:.2f}")

    # accuracy against mpmath (40 digits)
    mpmath.mp.dps = 40
    ts = np.linspace(0.1, 2.0, 25)
    worst_ad = worst_sp = 0.0
    for e, a, b in zip(parsed, d1, d2):
        sp_e = symbolic.sym(e)
        import sympy

        tsym = symbolic.symbol("t")
        ref1 = [sympy.diff(sp_e, tsym).evalf(40, subs={tsym: sympy.Float(float(x), 40)}) for x in ts]
        ref2 = [sympy.diff(sp_e, tsym, 2).evalf(40, subs={tsym: sympy.Float(float(x), 40)}) for x in ts]
        f0, f1, f2 = J.jet(e, ts)
        for k, x in enumerate(ts):
            for ref, ad, sy in ((ref1[k], f1[k], a(t=x)), (ref2[k], f2[k], b(t=x))):
                r = float(ref)
                scale = max(1.0, abs(r))
                worst_ad = max(worst_ad, abs(ad - r) / scale)
                worst_sp = max(worst_sp, abs(float(sy) - r) / scale)
    print("accuracy of f', f'' against 40-digit references (max relative error over 25 times)")
    print(f"  AD jets : {worst_ad:.2e}")
    print(f"  sympy   : {worst_sp:.2e}")


if __name__ == "__main__":
    main()
