"""Closed form vs DOP853 for the vibration type (notes §17).

For the same base-excited problem, prints the cost per evaluated time point
of the vectorised closed form (dyncli.topics.vibration.closed_form) and of a
scipy DOP853 integration of (17.15a) at rtol 1e-10 (atol 1e-12), both errors
against a 50-digit mpmath reference (max |error| / max |x| over the run), and
the ratios.  Run from the repository root:

    python benchmarks/vibration_closed_form_vs_ode.py [N]
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from dyncli.topics.vibration import closed_form as cf  # noqa: E402
from tests.topics.vibration.reference import max_rel_err, reference  # noqa: E402


def best_of(fn, repeat=5):
    best = math.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def dop853(t, omega_n, zeta, L, x0, v0, s0, Omega, rtol=1e-10, atol=1e-12):
    Om = Omega
    from scipy.integrate import solve_ivp

    wn2, two_zw = omega_n ** 2, 2 * zeta * omega_n

    def rhs(tt, y):
        s = s0 * math.sin(Om * tt)
        sd = s0 * Om * math.cos(Om * tt)
        return [y[1], -wn2 * (y[0] - s - L) - two_zw * (y[1] - sd)]

    sol = solve_ivp(rhs, (0.0, t[-1]), [x0, v0], method="DOP853", t_eval=t, rtol=rtol, atol=atol)
    return sol.y[0], sol.y[1], sol.nfev


def main(n=2000):
    import scipy  # noqa: F401  (import cost outside the timings)

    T = 50.0
    t = np.linspace(0.0, T, n)
    print(f"vibration: closed form vs DOP853 (rtol 1e-10, atol 1e-12), {n} time points on [0, {T:g}] s")
    print("m = 1 kg, k = 4 N/m (ωₙ = 2 rad/s), x0 = 0.1 m, v0 = 0, base s0 = 0.01 m, ω = 1.7 rad/s")
    print("errors: max |x − x_ref| / max |x_ref| against a 50-digit mpmath reference\n")
    head = f"{'ζ':>8} {'closed µs/pt':>13} {'DOP853 µs/pt':>13} {'cost ratio':>11} {'closed err':>11} {'DOP853 err':>11} {'RHS evals':>10}"
    print(head)
    print("-" * len(head))
    for zeta in (0.0, 0.05, 1.0, 10.0):
        p = dict(omega_n=2.0, zeta=zeta, L=0.0, x0=0.1, v0=0.0, s0=0.01, Omega=1.7)
        tc, (xc, vc, _) = best_of(lambda: cf.response(t, **p))
        to, (xo, vo, nfev) = best_of(lambda: dop853(t, **p), repeat=3)
        rx, rv, _ = reference(t.tolist(), **p)
        ec = max_rel_err(xc.tolist(), rx)
        eo = max_rel_err(xo.tolist(), rx)
        print(f"{zeta:>8g} {1e6 * tc / n:>13.3f} {1e6 * to / n:>13.3f} {to / tc:>10.0f}× {ec:>11.1e} {eo:>11.1e} {nfev:>10d}")
    # the stiff end: DOP853 cost grows with the fast root ~2ζωₙ; the closed form does not
    zeta = 1e8
    p = dict(omega_n=2.0, zeta=zeta, L=0.0, x0=0.1, v0=0.0, s0=0.01, Omega=1.7)
    tc, (xc, _, _) = best_of(lambda: cf.response(t, **p))
    rx, _, _ = reference(t.tolist(), **p)
    print(f"{zeta:>8g} {1e6 * tc / n:>13.3f} {'(not run)':>13} {'':>11} {max_rel_err(xc.tolist(), rx):>11.1e} "
          f"{'':>11} {'~' + format(2 * zeta * 2.0 * T / 3.5, '.0e'):>10}")
    print("\nζ = 1e8: an explicit integrator needs ~(fast root × T / stability bound) steps; "
          "the closed form costs the same at every ζ.")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 2000)
