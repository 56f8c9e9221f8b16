"""The results of ``rotating-frame`` also on the fixed basis e_i (``fixed``, ``basis0``).

The basis e'_i turns by (10.4), ė'_i = ω × e'_i, from its orientation at t = 0 (``basis0``,
default e'_i = e_i).  With Q the matrix whose columns are the e'_i in fixed components and ω'
the components of ω on e'_i, (10.4) reads Q̇ = Q [ω']× (the skew matrix of ω'), and a vector
with components c' on e'_i has the fixed components Q c'.

* ω' constant (no component uses t): Q(t) = Q0 R(ω', |ω'| t), the rotation about the fixed body
  axis ω' by |ω'| t (Rodrigues) — exact, ``method: closed-form``;
* otherwise (or ``accuracy.method: ode``): (10.4) integrated by the runner (DOP853, the rtol and
  atol of ``accuracy``, its error estimate: a check solve with ``accuracy.estimate``, else the
  nominal bound) — ``method: ode:DOP853``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from dyncli.errors import NumericalError
from dyncli.expr.jet import jet_at
from dyncli.topics.inertia import mat3, rotations

#: the vector results of the type, each reported again as NAME_fixed
VECTORS = ("omega", "p", "dp_dt", "omega_x_p", "p_dot", "omega_dot", "d2p_dt2", "omega_dot_x_p", "coriolis",
           "centripetal", "p_ddot", "vA", "aA")


@dataclass(frozen=True, slots=True)
class Turning:
    """How e'_i turns (10.4): ω' (components on e'_i, expressions in t), Q0 (rows of the matrix whose
    columns are e'_i at t = 0 in fixed components), and the route's controls (``method`` "ode"
    integrates even a constant ω'; the runner's rtol, atol, max_steps, estimate)."""

    omega: tuple
    Q0: tuple[tuple[float, float, float], ...]
    method: str = "auto"
    rtol: float = 1e-10
    atol: float = 1e-12
    max_steps: int | None = None
    estimate: bool = False



def skew_rate(Q, w):
    """Q̇ = Q [ω']× (10.4 for the three columns of Q), row-major 3×3 lists.

    >>> skew_rate([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]], (0.0, 0.0, 2.0))
    [[0.0, -2.0, 0.0], [2.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    """
    W = ((0.0, -w[2], w[1]), (w[2], 0.0, -w[0]), (-w[1], w[0], 0.0))
    return [[sum(Q[i][k] * W[k][j] for k in range(3)) + 0.0 for j in range(3)] for i in range(3)]


def _integrated(p: Turning, Q0, times, res):
    """Q at the times by (10.4), Q̇ = Q [ω'(t)]× on the nine entries of Q row by row, through the
    runner (imported here: numpy and scipy only when a problem integrates)."""
    from dyncli import runner
    from dyncli.expr.floateval import float_fn

    w1, w2, w3 = (float_fn(e, "t") for e in p.omega)       # ω'(t) in plain floats (no jets, no numpy)

    class Poisson(runner.Route):
        def initial_state(self):
            return [x for row in Q0 for x in row]

        def rhs(self, t, y):
            t = float(t)
            w = (w1(t), w2(t), w3(t))
            v = y.tolist() if hasattr(y, "tolist") else list(y)
            Q = [v[0:3], v[3:6], v[6:9]]
            return [x for row in skew_rate(Q, w) for x in row]

    route = Poisson(method="DOP853", rtol=p.rtol, atol=p.atol, max_steps=p.max_steps, estimate=p.estimate)
    route.times = list(times)
    out = route.run(res)
    res.method = "ode:DOP853"
    return [[[float(out[k, 3 * i + j]) for j in range(3)] for i in range(3)] for k in range(len(times))]


def orientations(p: Turning, times, res) -> list:
    """Q(t) at each time (the route by ω' and ``method``; sets ``res.method``)."""
    Q0 = p.Q0
    if p.method != "ode" and all(e.is_constant for e in p.omega):
        w = [jet_at(e, 0.0)[0] for e in p.omega]
        rate = math.hypot(*w)
        if rate == 0.0:
            return [Q0 for _ in times]
        for t in times:
            if not math.isfinite(rate * t):
                raise NumericalError(f"the frame turns through {rate:.3g} rad/s × {t:.3g} s, beyond the doubles: "
                                     "its orientation at that time is not determined (ask for an earlier time)")
        return [mat3.matmul(Q0, rotations.rot_axis(w, rate * t)) for t in times]
    return _integrated(p, Q0, times, res) if times else []


def report(p: Turning, res, times) -> None:
    """NAME_fixed for every vector result, and ``basis_fixed`` (e'_1, e'_2, e'_3 in fixed
    components) at each time."""
    Qs = orientations(p, times, res)
    R = res.results
    for name in VECTORS:
        if name in R:
            R[name + "_fixed"] = [None if v is None else [c + 0.0 for c in mat3.matvec(Q, v)]
                                  for v, Q in zip(R[name], Qs)]
    R["basis_fixed"] = [[[c + 0.0 for c in row] for row in mat3.transpose(Q)] for Q in Qs]
    res.equations.append("10.4")
