"""Work-precision of the torque-free rigid body (euler, notes §39).

Error at t = 100 against the exact Jacobi-elliptic solution, and wall time,
for rtol = 1e-4 ... 1e-12:

* bare scipy: ``solve_ivp(..., method="DOP853")`` on Euler's equations;
* dyncli ``euler`` with accuracy.method DOP853 (the default ODE route),
  RK45 and ``projected`` (DOP853 + projection onto |H| = H0, T = T0);

plus the drift of |H| and T at t = 1e4.  Prints a table and saves
docs/gyro_work_precision.png.  Run:  python benchmarks/gyro_work_precision.py
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from dyncli.topics.euler import free  # noqa: E402
from dyncli.topics.euler.model import Euler  # noqa: E402
from dyncli.topics.euler.solver import solve  # noqa: E402

I = np.array([1.0, 2.0, 3.0])
W0 = np.array([1.0, 0.3, 2.0])
T_END = 100.0
RTOLS = [1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12]
EXACT = free.exact(I, W0).omega(np.array([T_END]))[0]
SCALE = float(np.linalg.norm(W0))


def best_time(fn, repeat=3):
    best = float("inf")
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def bare_scipy(rtol):
    from scipy.integrate import solve_ivp

    def f(t, w):
        return -np.cross(w, I * w) / I

    s = solve_ivp(f, (0, T_END), W0, method="DOP853", rtol=rtol, atol=rtol * 1e-2, t_eval=[T_END])
    return s.y[:, -1]


def dyncli_run(method, rtol, t_end=T_END):
    pb = Euler.model_validate({"type": "euler", "I": I.tolist(), "omega0": W0.tolist(), "at": [t_end],
                               "accuracy": {"method": method, "rtol": rtol, "atol": rtol * 1e-2}})
    return solve(pb)


def main():
    rows = []
    print(f"torque-free body I = {I.tolist()}, ω0 = {W0.tolist()}, error at t = {T_END:g} (relative to |ω0|)")
    print(f"{'rtol':>8} | {'scipy DOP853':>22} | {'dyncli DOP853':>22} | {'dyncli RK45':>22} | {'dyncli projected':>22} | ratio")
    for rtol in RTOLS:
        line = {"rtol": rtol}
        t, y = best_time(lambda: bare_scipy(rtol))
        line["scipy"] = (t, float(np.max(np.abs(y - EXACT)) / SCALE))
        for m in ("DOP853", "RK45", "projected"):
            if m == "RK45" and rtol < 1e-10:
                line[m] = (float("nan"), float("nan"))
                continue
            t, res = best_time(lambda: dyncli_run(m, rtol))
            line[m] = (t, float(np.max(np.abs(np.array(res.results["omega"][0]) - EXACT)) / SCALE))
        rows.append(line)
        cell = lambda k: f"{line[k][0] * 1e3:8.1f} ms {line[k][1]:9.2e}"
        print(f"{rtol:8.0e} | {cell('scipy')} | {cell('DOP853')} | {cell('RK45')} | {cell('projected')} | "
              f"{line['DOP853'][0] / line['scipy'][0]:.2f}")
    print("ratio = dyncli DOP853 time / bare scipy DOP853 time at the same rtol (the errors match)")

    print("\ndrift of |H| and T at t = 1e4 (rtol 1e-8):")
    for m in ("DOP853", "projected"):
        t0 = time.perf_counter()
        res = dyncli_run(m, 1e-8, 1e4)
        dt = time.perf_counter() - t0
        d = res.results["drift_detail"]
        print(f"  {m:>9}: |H| {d['H']:.2e}   T {d['T']:.2e}   ({dt:.1f} s)")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for key, label, mk in (("scipy", "bare scipy DOP853", "o"), ("DOP853", "dyncli DOP853", "s"),
                           ("RK45", "dyncli RK45", "^"), ("projected", "dyncli projected", "d")):
        pts = [(r[key][1], r[key][0]) for r in rows if np.isfinite(r[key][0])]
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=mk, label=label)
    ax.set_xlabel("relative error of ω at t = 100")
    ax.set_ylabel("wall time [s]")
    ax.set_title("torque-free body: work-precision (rtol 1e-4 … 1e-12)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    out = ROOT / "docs" / "gyro_work_precision.png"
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"\nplot saved to {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
