"""Oracle cases: a bead on a circular hoop (constrained-particle) at its separatrix and its
bifurcation.  Fixed hoop released from rest 1e-4 and 1e-8 rad below the top (the pendulum:
period 4 sqrt(R/g) K(sin²(q0/2)), q(t) = 2 asin(k cd(ω0 t | k²))), and 1e-13 rad below it (not
determined in doubles: refused); hoop turning at ω²R/g = 1 + δ (δ = 1e-6, 1e-10, 1e-12): the
relative equilibria 0, ±acos(g/(ω²R)) ≈ ±sqrt(2δ), ±π."""

from __future__ import annotations

import math

import mpmath as mp

from tests.oracle.common import EPS, case, closed, estimated, same, x

R, G = 0.5, 9.81
HOOP = {"m": 0.1, "curve": {"x1": "0.5*sin(q)", "x2": 0, "x3": "-0.5*cos(q)"}, "q_range": [-math.pi, math.pi],
        "forces": [{"kind": "gravity"}]}


def _released(dq, times):
    q0 = math.pi - dq
    Q0, r, g = x(q0), x(R), x(G)
    k = mp.sin(Q0 / 2)
    m = k ** 2
    w0 = mp.sqrt(g / r)
    P = 4 * mp.ellipk(m) / w0
    q = lambda t: 2 * mp.asin(k * mp.ellipfun("cd", w0 * t, m=m))     # noqa: E731
    # the route's error_estimate is relative to max|x| + v_max t_max (docs/types/constrained-particle.md)
    vmax = 2 * w0 * r * k
    scale = r + vmax * max(times)
    checks = [estimated(f"q.{i}", q(x(t)), scale / r, reason="the estimate x (|x| + v t)/R: radians")
              for i, t in enumerate(times)]
    checks.append(estimated("period", P, scale / vmax, reason="the estimate x (|x| + v t)/v_max: seconds"))
    # the far turning point: a root of V(q) = V(q0) where V' = sin q ~ dq (condition 1/(q dq))
    checks.append(closed("q_turn.0", -Q0, cond=2 / (Q0 * mp.sin(x(dq))), reason="the root of V(q) = V(q0) at V' ~ dq"))
    return case(f"hoop released {dq:g} rad below the top", "constrained-particle",
                {**HOOP, "q0": q0, "at": times}, checks,
                f"fixed hoop R = 0.5 m from rest at q0 = π − {dq:g}: period {mp.nstr(P, 6)} s",
                same_=[same("q_turn.1", q0)])


def _turning(delta):
    w = math.sqrt(G * (1 + delta) / R)
    c = x(G) / (x(w) ** 2 * x(R))
    qs = mp.acos(c)
    cond = 1 / (qs * mp.sin(qs))                   # of acos at c → 1 (relative)
    checks = [closed("equilibria.0.q", -mp.pi, cond=2),
              closed("equilibria.1.q", -qs, cond=cond, reason="acos next to 1: condition 1/(q sin q)"),
              closed("equilibria.2.q", 0, scale=qs, cond=cond),
              closed("equilibria.3.q", qs, cond=cond, reason="acos next to 1: condition 1/(q sin q)")]
    st = [same(f"equilibria.{i}.stable", s) for i, s in enumerate((False, True, False, True))]
    return case(f"hoop turning just past the bifurcation, delta = {delta:g}", "constrained-particle",
                {**HOOP, "rotation": {"axis": [0, 0, 1], "omega": w}, "q0": 0.3, "at": [0]}, checks,
                f"ω²R/g = 1 + {delta:g}: two stable relative equilibria at ±{mp.nstr(qs, 6)} rad beside the unstable bottom",
                same_=st)


def cases():
    out = [_released(1e-4, [1, 10, 30]), _released(1e-8, [1, 30])]
    out.append(case("hoop released 1e-13 rad below the top", "constrained-particle",
                    {**HOOP, "q0": math.pi - 1e-13, "at": [0, 10]}, [],
                    "the timing depends on the last digits of q0 (ulp(π)/1e-13 = 4e-3): refused, not guessed",
                    expect="refused"))
    out += [_turning(d) for d in (1e-6, 1e-10, 1e-12)]
    return out


assert EPS > 0
