"""The ``find`` queries and ``distance`` of a particle's motion (§11), on the ODE's dense output.

The motion is the integrated trajectory at any time (every step's dense output, the same steps
as the reported times) or the exact conic of an orbit; its breaks are the accepted steps and the
phase ends (a stop by friction, a rest), between which the state is one interpolating
polynomial, or the orbit's equal steps of the eccentric anomaly; v is the rate of x, a of v
and m v·a of T, so a turning point of a coordinate or of T is a root of its rate (Brent); on
the ODE route every step is cut at the exact extremes of each result searched
(:func:`exact_breaks`), between which the search takes it as monotone.  ``distance`` is
∫|v| dt by Gauss–Legendre on every step (:class:`dyncli.motion_find.Odometer`).
"""

from __future__ import annotations

import math

from dyncli import motion_find as mf
from dyncli.expr import constant, resolve_params

#: the results over time a find entry holds (as at an ``at`` time)
STATE = ("x", "v", "a", "T", "V", "E", "W_nc", "H_O")


def breaks(traj) -> list[float]:
    ts = {float(t) for t in traj.steps()[0]}
    for ph in traj.phases:
        ts |= {float(ph.t0), float(ph.t1)}
    return sorted(ts)


def report(p, res, at_times, traj_of, pieces=None, period=None) -> None:
    """``distance`` at the times of ``at`` and the ``find`` answers.  ``at_times(ts)``: the
    reported quantities at many times as arrays (report.at_times on the dense trajectory);
    ``traj_of()``: the dense trajectory; ``pieces``: the breaks when they are not its steps (the
    exact orbit: equal steps of the eccentric anomaly); ``period``: (T, the breaks of [0, T]) of a
    periodic motion (the exact ellipse), whose distance is then k times one period's plus the rest
    (the speed repeats every T): the same cost at any time, however many turns."""
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

    rtol = float(p.accuracy.rtol)
    odo = (mf.Odometer(speeds, B, arrays=True, times=p.at, rtol=rtol) if period is None else
           _Periodic(mf.Odometer(speeds, period[1], arrays=True, rtol=rtol), period[0]))
    mf.check_resolved(odo, res.warn)
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

    own = exact_breaks(p.find, traj_of() if pieces is None else None, B, at_times, odo, res.warn)
    motion = mf.StateMotion(full, 0.0, float(p.t_end), B, rtol=float(p.accuracy.rtol), subdivide=1,
                            rates={"x": "v", "v": "a", "T": lambda t, _: power(t)},
                            batch=lambda ts: [dict(s, distance=d) for s, d in zip(batch(ts), odo.at(ts))],
                            breaks_for=own, monotone=own is not None)
    mf.attach(res, p.find, mf.answer_find(p.find, motion, const, res.warn, full=full))


class _Periodic:
    """The odometer of a motion whose speed repeats every ``T`` from one period's odometer:
    d(kT + τ) = k d(T) + d(τ), 0 ≤ τ < T."""

    def __init__(self, one, T: float):
        self.one, self.T = one, float(T)
        self.full = float(one.at([self.T])[0])

    def at(self, times) -> list:
        rest, ks = [], []
        for t in times:
            k = math.floor(float(t) / self.T)
            ks.append(k)
            rest.append(min(max(float(t) - k * self.T, 0.0), self.T))
        return [k * self.full + d + 0.0 for k, d in zip(ks, self.one.at(rest))]


#: the state component of each coordinate path a query may ask about
_COMPONENT = {f"{q}.{i}": 3 * k + i for k, q in enumerate(("x", "v")) for i in range(3)}


def exact_breaks(find, traj, B: list[float], at_times, odo, warn=None):
    """``breaks_for(path)`` cutting every piece at the exact extremes of each result searched (else
    None: see :func:`dyncli.motion_find.exact_breaks`).  On the ODE route (``traj``: the dense
    trajectory) a coordinate of x or v is a coordinate of the step's dense output, a polynomial,
    whose critical points are decided exactly (:func:`dyncli.rootfind.polynomial_extremes`); any
    other result (|v| through T, a, V, E, H_O, W_nc, distance) is a smooth function of that
    polynomial inside the step, whose critical points are the roots of its derivative
    (:func:`dyncli.rootfind.smooth_extremes`); on the exact orbit (``traj`` None) every result
    is such a function on each piece of the conic.  Between two cuts each result is monotone, so
    no excursion inside a piece, however narrow, is stepped over."""
    import numpy as np

    pieces = []
    for ph in (traj.phases if traj is not None else ()):
        sol = getattr(ph, "sol", None)
        if sol is None:
            if ph.t1 > ph.t0 and not hasattr(ph, "x"):      # an ODE phase without its steps' polynomials
                if warn is not None:
                    warn("find: an ODE phase's step polynomials are not kept: its crossings are searched between the "
                         "steps' ends, where a level crossed and crossed back inside one step is not seen")
                return None
            continue
        pieces += [(f, float(a), float(b)) for f, a, b in zip(sol.interpolants, sol.ts[:-1], sol.ts[1:]) if b > a]
    if traj is not None and not pieces:
        return None
    coordinates: dict[str, list[float]] = {}

    def known(path: str):
        if path not in _COMPONENT or not pieces:
            return None
        if not coordinates:
            from dyncli.rootfind import polynomial_extremes

            ext = polynomial_extremes(pieces)
            coordinates.update({k: [t for e in ext for t in e[c]] for k, c in _COMPONENT.items()})
        return coordinates[path]

    def values(paths, ts):
        ts = np.asarray(ts, dtype=float)
        S = at_times(ts.tolist())
        rows = []
        for path in paths:
            head, _, rest = path.partition(".")
            if head == "distance" and not rest:
                rows.append(np.asarray(odo.at(ts), dtype=float))
            elif head in STATE and head in S and np.ndim(S[head]) == (2 if rest else 1):
                if rest and not (rest.isdigit() and int(rest) < len(S[head])):
                    raise KeyError(path)
                rows.append(np.asarray(S[head][int(rest)] if rest else S[head], dtype=float))
            else:
                raise KeyError(path)
        return np.stack(rows)

    return mf.exact_breaks(find, B, values, known, warn)
