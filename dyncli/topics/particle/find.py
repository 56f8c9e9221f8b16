"""The ``find`` queries and ``distance`` of a particle's motion (§11), on the ODE's dense output.

The motion is the integrated trajectory at any time (every step's dense output, the same steps
as the reported times) or the exact conic of an orbit; its breaks are the accepted steps and the
phase ends (a stop by friction, a rest), between which the state is one interpolating
polynomial, or the orbit's equal steps of the eccentric anomaly; v is the rate of x, a of v
and m v·a of T, so a turning point of a coordinate or of T is a root of its rate (Brent).  ``distance`` is
∫|v| dt by Gauss–Legendre on every step (:class:`dyncli.motion_find.Odometer`).
"""

from __future__ import annotations

from dyncli import motion_find as mf
from dyncli.expr import constant, resolve_params

#: the results over time a find entry holds (as at an ``at`` time)
STATE = ("x", "v", "a", "T", "V", "E", "W_nc", "H_O")


def breaks(traj) -> list[float]:
    ts = {float(t) for t in traj.steps()[0]}
    for ph in traj.phases:
        ts |= {float(ph.t0), float(ph.t1)}
    return sorted(ts)


def report(p, res, at_times, traj_of, pieces=None) -> None:
    """``distance`` at the times of ``at`` and the ``find`` answers.  ``at_times(ts)``: the
    reported quantities at many times as arrays (report.at_times on the dense trajectory);
    ``traj_of()``: the dense trajectory; ``pieces``: the breaks when they are not its steps (the
    exact orbit: equal steps of the eccentric anomaly)."""
    B = pieces if pieces is not None else breaks(traj_of())

    def batch(ts) -> list[dict]:
        S = at_times(ts)
        out = []
        for j in range(len(ts)):
            out.append({k: (S[k][:, j].tolist() if S[k].ndim == 2 else float(S[k][j])) for k in STATE})
        return out

    def speeds(ts):                                  # |v| from the states alone (not every reported quantity)
        import numpy as np

        V = traj_of().state_array(ts, slice(3, 6))[1]
        return np.sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2])

    odo = mf.Odometer(speeds, B, arrays=True)
    res.results["distance"] = odo.at(p.at)
    if not p.find:
        return
    params = resolve_params(p.params)
    const = lambda text: constant(text, params)      # noqa: E731

    def full(t: float) -> dict:
        st = batch([t])[0]
        st["distance"] = odo.at([t])[0]
        return st

    def power(t: float) -> float:                   # Ṫ = m v·a: a turning point of T is a root of it
        f = motion.flat(t)
        return float(p.m) * sum(f[f"v.{i}"] * f[f"a.{i}"] for i in range(3))

    own = None if pieces is not None else _coordinate_breaks(p.find, traj_of(), B)
    motion = mf.StateMotion(full, 0.0, float(p.t_end), B, rtol=float(p.accuracy.rtol), subdivide=1,
                            rates={"x": "v", "v": "a", "T": lambda t, _: power(t)},
                            batch=lambda ts: [dict(s, distance=d) for s, d in zip(batch(ts), odo.at(ts))],
                            breaks_for=own, monotone=own is not None)
    mf.attach(res, p.find, mf.answer_find(p.find, motion, const, res.warn, full=full))


#: the state component of each coordinate path a query may ask about
_COMPONENT = {f"{q}.{i}": 3 * k + i for k, q in enumerate(("x", "v")) for i in range(3)}


def _coordinate_breaks(find, traj, B: list[float]):
    """``breaks_for(path)`` when every query asks about a coordinate of x or v (else None): the
    breaks with every critical point of that coordinate inside each step added — a step's dense
    output is a polynomial, whose extremes are decided exactly
    (:func:`dyncli.rootfind.polynomial_extremes`), so the coordinate is monotone between two of
    them and no excursion inside a step, however narrow, is stepped over."""
    asked: set[str] = set()
    for q in find if isinstance(find, (list, tuple)) else ():
        if not isinstance(q, dict):
            return None
        if set(q) <= {"t"}:                             # a time query: no search
            continue
        when = q.get("when")
        paths = list(when) if isinstance(when, dict) else [q[k] for k in ("max", "min") if k in q]
        if not paths or not all(isinstance(x, str) and x in _COMPONENT for x in paths):
            return None
        asked.update(str(x) for x in paths)
    pieces = []
    for ph in traj.phases:
        sol = getattr(ph, "sol", None)
        if sol is None:
            if ph.t1 > ph.t0 and not hasattr(ph, "x"):      # an ODE phase without its steps' polynomials
                return None
            continue
        pieces += [(f, float(a), float(b)) for f, a, b in zip(sol.interpolants, sol.ts[:-1], sol.ts[1:]) if b > a]
    if not asked or not pieces:
        return None
    from dyncli.rootfind import polynomial_extremes

    ext = polynomial_extremes(pieces)
    t_end = B[-1]
    own = {path: sorted(set(B).union(t for e in ext for t in e[_COMPONENT[path]] if B[0] < t < t_end))
           for path in asked}
    return lambda path: own[path] if path in own else B
