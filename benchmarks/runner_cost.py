"""The runner's cost at equal error: dyncli's solver-only time over a plain scipy script's.

For each integrating route (particle, rectilinear general, euler ODE, top ODE, gyroscope ODE),
on the problems of tests/accuracy/cases.py (exact or 50-digit references):

1. dyncli solves at ``rtol`` (atol = 1e-3 rtol) without an error estimate; its true error E
   is measured against the reference (the case's own error function);
2. the plain scipy script a student would write for the same problem (``solve_ivp``, DOP853,
   the equations in plain floats, ``t_eval``/events) is run on a grid of rtols
   10^(-k/4); the loosest rtol whose error, and the error at every tighter grid point, is <= E
   is "scipy at equal error";
3. both are timed warm (CPU time of this process) and interleaved (median of ``--repeats`` rounds; dyncli's validated
   model is reused, so no YAML or validation is in the time), and the ratio dyncli/scipy printed.  The check solve
   (``accuracy.estimate: true``) is costed separately: its extra time over the plain solve, as
   a ratio to the same scipy time.

Usage: python benchmarks/runner_cost.py [--rtols 1e-6 1e-10] [--repeats 7] [--only rectilinear ...]
Goal (issue 19): dyncli/scipy <= 1.2 at equal error.

Measured (issue 31, rectilinear general, load 5-6 on 2 CPUs, before and after run back to back in
rounds): 1.81 at rtol 1e-6, 1.34 at 1e-10 (2.39 and 2.19 before the find engine replayed the
route's own march instead of integrating the motion again); the other routes: docs/accuracy.md.
"""

from __future__ import annotations

import argparse
import math
import os
import statistics
import sys
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

GRID = [10.0 ** (-k / 4) for k in range(8, 57)]          # 1e-2 ... 1e-14


# --- the plain scipy scripts: (rtol, atol) -> the values the reference is compared with -----------
def _ivp(rhs, t_end, y0, rtol, atol, **kw):
    from scipy.integrate import solve_ivp

    return solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=atol, **kw)


def particle_script(rtol, atol):
    def rhs(t, y):
        return [y[3], y[4], y[5], -0.2 * y[3], -0.2 * y[4], -9.81 - 0.2 * y[5]]

    return _ivp(rhs, 3.0, [0.0, 0, 0, 20, 0, 20], rtol, atol, t_eval=[1, 2, 3]).y.T.ravel().tolist()


def rectilinear_script(rtol, atol):
    def rhs(t, y):
        return [y[1], -4.0 * y[0] - 0.4 * y[1]]

    def ev_v(t, y):
        return y[1]

    def ev_s(t, y):
        return y[0] + 0.3

    sol = _ivp(rhs, 10.0, [0.5, 1.0], rtol, atol, dense_output=True, events=[ev_v, ev_s])
    out = [float(c) for t in (1, 3, 10) for c in sol.sol(t)]
    for k, comp in ((0, 0), (1, 1)):        # (t, s) at v = 0; (t, v) at s = -0.3
        if not len(sol.t_events[k]):
            return None                     # the crossing was missed (it happens at loose rtol)
        out += [float(sol.t_events[k][0]), float(sol.y_events[k][0][comp])]
    return out


def euler_script(rtol, atol):
    I1, I2, I3 = 1.0, 2.0, 3.0
    a, b, c = (I2 - I3) / I1, (I3 - I1) / I2, (I1 - I2) / I3

    def rhs(t, w):
        return [a * w[1] * w[2], b * w[2] * w[0], c * w[0] * w[1]]

    return _ivp(rhs, 20.0, [0.1, 0.0, 2.0], rtol, atol, t_eval=[1, 5, 20]).y.T.ravel().tolist()


def lagrange_top(m, L, A, C, g, th, thd, ps, ph, psd, phd, times, rtol, atol):
    """The heavy symmetric top in 3-1-3 Euler angles (Lagrange), state [θ, θ̇, ψ, φ], ψ̇ from
    the conserved p_ψ and ω3: rows [ψ, θ, φ, ψ̇, θ̇, φ̇] at ``times``."""
    w3 = phd + psd * math.cos(th)
    p_psi = A * psd * math.sin(th) ** 2 + C * w3 * math.cos(th)

    def rates(th):
        s, c = math.sin(th), math.cos(th)
        return s, c, (p_psi - C * w3 * c) / (A * s * s)

    def rhs(t, y):
        s, c, psid = rates(y[0])
        return [y[1], (A * psid * psid * s * c - C * w3 * psid * s + m * g * L * s) / A, psid, w3 - psid * c]

    rows = []
    for th_, thd_, ps_, ph_ in _ivp(rhs, max(times), [th, thd, ps, ph], rtol, atol, t_eval=times).y.T:
        _, c, psid = rates(th_)
        rows.append([ps_, th_, ph_, psid, thd_, w3 - psid * c])
    return rows


def top_script(rtol, atol):
    """Steady precession (slow root of 38.22): ψ, θ, φ at t = 1, 2, 5."""
    m, L, A, C, p, g, th0 = 0.5, 0.05, 2e-3, 1e-3, 150.0, 9.81, math.pi / 6
    om = 2 * m * g * L / (C * p + math.sqrt((C * p) ** 2 - 4 * m * g * L * (A - C) * math.cos(th0)))
    rows = lagrange_top(m, L, A, C, g, th0, 0.0, 0.0, 0.0, om, p, [1, 2, 5], rtol, atol)
    return [v for row in rows for v in row[:3]]


def nutating_script(rtol, atol):
    """The nutating top of tests/topics/top: ψ, θ, φ and their rates."""
    from tests.topics.top.exact_reference_data import CASES as REF

    m, L, A, C, ps, th, ph, psd, thd, phd = REF["nutating"]["input"]
    rows = lagrange_top(m, L, A, C, 9.81, th, thd, ps, ph, psd, phd, REF["nutating"]["times"], rtol, atol)
    return [v for row in rows for v in row]


def gyroscope_script(rtol, atol):
    """(37.12): Ī₂ θ̈ + (Ī₂ − Ī₁) q² sin θ cos θ − Ī₁ p q cos θ = 0 from θ = θ̇ = 0."""
    I1, I2, p, q = 0.01, 0.006, 100.0, 1.0
    a, b = (I2 - I1) * q * q / I2, I1 * p * q / I2

    def rhs(t, y):
        c = math.cos(y[0])
        return [y[1], b * c - a * math.sin(y[0]) * c]

    return _ivp(rhs, 0.33, [0.0, 0.0], rtol, atol, t_eval=[0.05, 0.1, 0.2, 0.33]).y.T.ravel().tolist()


# --- the references, as floats, in the scripts' order -------------------------------------------
def references() -> dict:
    from tests.accuracy import cases as C
    from tests.topics.gyroscope.gyroscope_reference_data import CASES as GREF
    from tests.topics.top.exact_reference_data import CASES as TREF

    ts = C._rectg_times()
    # rectilinear's error is relative (tests/accuracy/cases.py): t to the largest time, s and v
    # to their largest magnitudes over the answers
    sc_t, sc_s, sc_v = (float(max(abs(f(t)) for t in ts)) for f in (lambda t: t, C._osc_s, C._osc_v))
    om = 2 * C.TM * C.TG * C.TL / (C.TC * C.TP + C.mp.sqrt((C.TC * C.TP) ** 2 - 4 * C.TM * C.TG * C.TL
                                                            * (C.TA - C.TC) * C.mp.cos(C.TTH)))
    om = float(om)
    s_thd = math.sqrt(2 * 0.004 / 0.006 + 2 * 2 * 0.01 * 100 / 0.006)
    # particle: x and v each relative to its scale over the run, as the case's error
    px, pv = (max(abs(float(c)) for t in C.PT for c in C._part_exact(t)[k]) for k in (0, 1))
    return {
        "particle": ([float(v) for t in C.PT for xv in C._part_exact(t) for v in xv], (px,) * 3 + (pv,) * 3),
        "rectilinear": ([float(f(t)) for t in (1, 3, 10) for f in (C._osc_s, C._osc_v)]
                        + [float(C._T_V0), float(C._osc_s(C._T_V0)), float(C._T_SM), float(C._osc_v(C._T_SM))],
                        (sc_s, sc_v) * 3 + (sc_t, sc_s, sc_t, sc_v)),
        "euler": ([float(v) for t in C.ET for v in C._euler_exact(t)], 1.0),
        "top": ([v for t in C.TT for v in (om * t, float(C.TTH), float(C.TP) * t)], 1.0),
        "nutating": ([v for row in TREF["nutating"]["rows"] for v in row[:6]],
                     tuple(max(abs(row[k]) for row in TREF["nutating"]["rows"]) for k in range(6))),
        "gyroscope": ([v for row in GREF["zero_to_pi"]["rows"] for v in row], (math.pi, s_thd)),
    }


def script_error(values, ref) -> float:
    """Largest error, each relative to its scale as the case measures it (1: absolute; particle,
    rectilinear, the nutating top, the gyroscope: relative to each quantity's scale)."""
    if values is None:
        return math.inf
    ref, scale = ref
    scales = scale if isinstance(scale, tuple) else (scale,)
    return max(abs(v - r) / scales[i % len(scales)] for i, (v, r) in enumerate(zip(values, ref)))


ROUTES = [   # (label, case name in tests/accuracy/cases.py, script, reference key)
    ("particle ODE", "particle", particle_script, "particle"),
    ("rectilinear general (ODE + events)", "rectilinear ODE + events", rectilinear_script, "rectilinear"),
    ("euler ODE (torque-free, DOP853)", "euler", euler_script, "euler"),
    ("top ODE (steady precession)", "top ODE (steady", top_script, "top"),
    ("top ODE (nutating)", "top ODE (nutating", nutating_script, "nutating"),
    ("gyroscope ODE (0 to pi)", "gyroscope ODE", gyroscope_script, "gyroscope"),
]


def dyncli_solver(case, rtol, estimate):
    """(record, the solver call alone): the validated model is reused (no YAML, no validation)."""
    from dyncli import registry
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions
    from tests.conftest import solve_text

    text = case.text(rtol, estimate)
    rec = solve_text(text)[0]
    (lp,), _ = split_problems("cost.yaml", text.encode(), ROOT)
    validate(lp)
    fn = registry.solver(lp.type)
    return rec, lambda: fn(lp.model, SolveOptions())


def scipy_rtol_at_error(script, ref, target: float):
    """(rtol, error) of the script at the loosest grid rtol whose error, and the error at every
    tighter grid rtol, is <= target (None when even the tightest misses)."""
    best = None
    for rtol in reversed(GRID):
        err = script_error(script(rtol, rtol * 1e-3), ref)
        if err > target:
            break
        best = (rtol, err)
    return best


def interleaved(fns, repeats: int) -> list[float]:
    """Median CPU seconds of each call (process time: the robust number on a shared machine),
    timed in rounds that call each once (a change in the machine's load hits them alike)."""
    for f in fns:
        f()
    ts: list[list[float]] = [[] for _ in fns]
    for _ in range(repeats):
        for i, f in enumerate(fns):
            t0 = time.process_time()
            f()
            ts[i].append(time.process_time() - t0)
    return [statistics.median(t) for t in ts]


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--rtols", type=float, nargs="+", default=[1e-6, 1e-10])
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--only", nargs="+", default=None, help="only the routes whose label contains one of these")
    args = ap.parse_args()
    warnings.simplefilter("ignore")
    from tests.accuracy.cases import CASES

    refs = references()
    load = os.getloadavg()
    print(f"runner cost at equal error (warm, solver only, CPU time, median of {args.repeats}); "
          f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} CPUs")
    print(f"{'route':<36} {'rtol':>6} {'dyncli ms':>9} {'error':>8} {'check ms':>8} | "
          f"{'scipy rtol':>10} {'ms':>7} {'error':>8} | {'ratio':>5} {'check/scipy':>11}")
    for label, name, script, key in ROUTES:
        if args.only and not any(w in label for w in args.only):
            continue
        case = next(c for c in CASES if c.name.startswith(name) or c.type == name)
        for rtol in args.rtols:
            rec, plain = dyncli_solver(case, rtol, False)
            if rec.get("error"):
                print(f"{label:<36} {rtol:6.0e}  failed: {rec['error']}")
                continue
            _, with_check = dyncli_solver(case, rtol, True)
            err = case.error(rec)
            got = scipy_rtol_at_error(script, refs[key], max(err, 1e-300))
            if got is None:
                t_d, t_est = interleaved([plain, with_check], args.repeats)
                print(f"{label:<36} {rtol:6.0e} {t_d * 1e3:9.2f} {err:8.1e} {(t_est - t_d) * 1e3:8.2f} | "
                      "scipy never reaches this error on the grid")
                continue
            r_s, e_s = got
            t_d, t_est, t_s = interleaved([plain, with_check, lambda: script(r_s, r_s * 1e-3)], args.repeats)
            print(f"{label:<36} {rtol:6.0e} {t_d * 1e3:9.2f} {err:8.1e} {(t_est - t_d) * 1e3:8.2f} | "
                  f"{r_s:10.1e} {t_s * 1e3:7.2f} {e_s:8.1e} | {t_d / t_s:5.2f} {(t_est - t_d) / t_s:11.2f}")


if __name__ == "__main__":
    main()
