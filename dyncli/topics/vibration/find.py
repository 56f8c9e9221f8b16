"""The ``find`` queries and ``distance`` of a vibration (§11), on the exact closed form.

The motion is the closed-form total response at any time (:func:`closed_form.response_at`, or the
force- or unbalance-excited :func:`forced.response_at`); its rates are exact (v is the rate of x, and the rates
of v and w follow from the equation of motion (17.15a)), so a turning point is a root of the rate
(Brent), never a sampled peak.  The breaks are an eighth of the shortest period present (the
damped free vibration's, the excitation's), so every piece holds at most one turning point of
each harmonic; ``distance`` is Σ|Δx| between the turning points (the roots of v).
"""

from __future__ import annotations

import math

from dyncli import motion_find as mf
from dyncli.expr import constant, resolve_params

from . import closed_form as cf
from . import forced

#: pieces per shortest period, and the most pieces a search takes (beyond: a coarser grid, warned)
PER_PERIOD, MAX_PIECES = 8, 20_000


class Response:
    """x(t), v(t), w(t) and the acceleration of one vibration problem, exact."""

    def __init__(self, p, omega_n, zeta):
        self.p, self.omega_n, self.zeta = p, omega_n, zeta
        self.L = p.L
        self.x0 = self.L if p.x0 is None else p.x0
        self.s0, self.Om = (p.base.amplitude, p.base.omega) if p.base is not None else (0.0, 0.0)
        self.fo = forced.forcing(p)      # (F0, ω) of a force on the mass or a rotating unbalance, or None

    def at(self, t: float) -> tuple[float, float, float]:
        p = self.p
        if self.fo is None:
            return cf.response_at(t, omega_n=self.omega_n, zeta=self.zeta, L=self.L, x0=self.x0, v0=p.v0,
                                  s0=self.s0, Omega=self.Om)
        return forced.response_at(t, m=p.m, omega_n=self.omega_n, zeta=self.zeta, L=self.L, x0=self.x0,
                                  v0=p.v0, F0=self.fo[0], Om=self.fo[1])

    def acceleration(self, t: float) -> float:
        """ẍ from (17.15a): −ωₙ²(x − s − L) − 2ζωₙ(ẋ − ṡ) + F/m."""
        x, v, _ = self.at(t)
        s, sd = self.s0 * math.sin(self.Om * t), self.s0 * self.Om * math.cos(self.Om * t)
        f = 0.0 if self.fo is None else self.fo[0] * math.sin(self.fo[1] * t) / self.p.m
        wn = self.omega_n
        return -wn * wn * (x - s - self.L) - 2.0 * self.zeta * wn * (v - sd) + f

    def w_rate(self, t: float) -> float:
        return self.at(t)[1] - self.s0 * self.Om * math.cos(self.Om * t)

    def breaks(self, t_end: float) -> tuple[list[float], bool]:
        """Every 1/PER_PERIOD of the shortest period over [0, t_end] (and whether capped)."""
        _, _, lam2 = cf.roots(self.omega_n, self.zeta)
        rate = max(self.omega_n, lam2 if self.zeta >= 1 else 0.0, self.Om, self.fo[1] if self.fo else 0.0)
        h = 2.0 * math.pi / rate / PER_PERIOD
        n = math.ceil(t_end / h) if h > 0 and t_end > 0 else 1
        capped = n > MAX_PIECES
        n = min(max(n, 1), MAX_PIECES)
        return [t_end * k / n for k in range(n + 1)], capped


def report(p, res, omega_n, zeta) -> None:
    """``distance`` at the times of ``at`` and the ``find`` answers."""
    if not p.at and not p.find:
        return
    params = resolve_params(p.params)
    const = lambda text: constant(text, params)      # noqa: E731
    t_end = mf.search_end(max([p.t_end or 0.0] + list(p.at)), p.find, const)
    resp = Response(p, omega_n, zeta)
    breaks, capped = resp.breaks(t_end)
    turns = mf.turns(lambda t: resp.at(t)[1], breaks) if t_end > 0 else []
    x = lambda t: resp.at(t)[0]                      # noqa: E731

    def distance(t: float) -> float:
        return mf.turning_length(x, turns, [t])[0]

    if p.at:
        res.results["distance"] = mf.turning_length(x, turns, p.at)
    if not p.find:
        return
    if capped:
        res.warn(f"find: the motion to t = {t_end:g} s spans more than {MAX_PIECES} eighths of a period; "
                 "turning points closer than the coarser grid may be missed (shorten the window with within)")

    def state(t: float) -> dict:
        xx, v, w = resp.at(t)
        return {"x": xx, "v": v, "w": w, "distance": distance(t)}

    motion = mf.StateMotion(state, 0.0, t_end, breaks,
                            rates={"x": "v", "v": lambda t, _: resp.acceleration(t), "w": lambda t, _: resp.w_rate(t),
                                   "distance": lambda t, _: abs(resp.at(t)[1])})
    mf.attach(res, p.find, mf.answer_find(p.find, motion, const, res.warn))
