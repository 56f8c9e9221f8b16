"""Routh's incremental method: one rough impact point followed through the impact in its normal impulse.

During an impact the positions are fixed, so the velocity of the striking point, u = (u_n, u_t)
(normal, and slip along the surface's d̂), is linear in the impulses (P, F) applied there
(28.21, 33.2 with the other joints' rows held):

    u(P, F) = u⁻ + W (P, F),     W = J M⁻¹ Jᵀ (2 × 2, symmetric positive definite).

Routh's method follows u as P grows from 0 (Coulomb's law for the impulse *increments*, the
friction angle of 28.41 chosen at every instant of the impact, not once for its whole):

* while the point slips (u_t ≠ 0): dF = −μ_k sign(u_t) dP (sliding against the current slip);
* where u_t reaches 0 (or is 0 at the start): it sticks (dF = k dP with k = −W_tn / W_tt, which
  keeps u_t = 0) when |k| ≤ μ_s — the static test — and then sticks to the end; otherwise it
  slides on, with u_t growing in the direction sign(W_tn) (the slip reverses where it had the
  other sign);
* compression ends where u_n = 0, at P = P_c; the impact ends at P_f = (1 + e) P_c (Poisson's
  impulse ratio).

While the impulse keeps one direction (a smooth point, a point that sticks from the start, one
that slides the whole impact one way, and any ball or disk struck through its centre, where W
is diagonal) u_n is linear in P and Poisson's P_f gives exactly Newton's u_n⁺ = −e u_n⁻ (28.7).
Where the slip stops or reverses during the impact the two laws differ; Newton's can then give
energy (Kane's paradox), Poisson's cannot: friction does work −μ_k |u_t| dP ≤ 0 on every
increment, and the normal impulse's work is −(1 − e²) times that of the compression on every
piece where u_n is linear in P — so dyncli uses the impulse ratio there.

An infinite μ (a rolling joint without ``mu_s``) stops the slip at P = 0⁺: a tangential impulse
−u_t / W_tt first, then the impact sticks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

EPS = 2.220446049250313e-16
#: the slip before taken as 0 (sticking from the start) below this fraction of the normal speed
SLIP_ZERO = 1e-12


@dataclass
class Course:
    """The outcome of one rough impact: the impulses, the velocity after, and the phases of the slip."""

    P: float = 0.0                  # normal impulse
    F: float = 0.0                  # friction impulse along d̂
    u_n: float = 0.0                # normal speed after
    u_t: float = 0.0                # slip after
    P_c: float = 0.0                # normal impulse at the end of compression
    steps: list = field(default_factory=list)    # "slides", "sticks", "slides back", in order

    @property
    def straight(self) -> bool:
        """One direction of impulse through the whole impact (Poisson = Newton)."""
        return len(self.steps) <= 1

    @property
    def name(self) -> str:
        return ", then ".join(self.steps) if self.steps else "none"


def _sign(x: float) -> float:
    return math.copysign(1.0, x)


def routh(W, u_n: float, u_t: float, e: float, mu_s: float, mu_k: float) -> Course:
    """Routh's method for one rough point: W the 2 × 2 matrix of (normal, tangent) rows, u⁻ =
    (u_n < 0, u_t), restitution e (Poisson's, = Newton's for a straight impulse), μ_s for the
    static test and μ_k for sliding (``math.inf`` for a point that cannot slip)."""
    (Wnn, Wnt), (Wtn, Wtt) = W
    c = Course()
    P = F = 0.0
    un, ut = float(u_n), float(u_t)
    if abs(ut) <= SLIP_ZERO * abs(un):
        ut = 0.0
    if ut != 0.0 and math.isinf(mu_k):          # infinite friction: the slip stops at once
        dF = -ut / Wtt
        F, un, ut = dF, un + Wnt * dF, 0.0
        c.steps.append("stops slipping at once")
    if un >= 0:                                 # no approach left: no normal impulse
        c.u_n, c.u_t, c.F = un, ut, F
        return c
    tiny = 1e-13 * (abs(un) + abs(ut))         # speeds within the rounding of W's solves: 0
    k_st = -Wtn / Wtt if Wtt > 1e-13 * (abs(Wnn) + abs(Wtt)) else 0.0    # (W_tt = 0: friction moves nothing)
    sticks = abs(k_st) - mu_s <= 64 * EPS * max(abs(k_st), mu_s)     # the static test (|F| ≤ μ_s P)
    P_f, first = None, 0.0                      # first: the direction of the first slide
    for _ in range(8):
        if ut != 0.0 or not sticks:
            s = _sign(ut) if ut != 0.0 else _sign(Wtn)
            first = first or s
            k, what = -mu_k * s, "slides" if s == first else "slides back"
        else:
            s, k, what = 0.0, k_st, "sticks"
        if not c.steps or c.steps[-1] != what:
            c.steps.append(what)
        dn, dt = Wnn + Wnt * k, Wtn + Wtt * k
        ends = []                               # (ΔP, which)
        if s != 0.0 and ut != 0.0 and dt * ut < 0 and abs(dt) > abs(ut) * 1e-300:
            ends.append((-ut / dt, "stop"))
        if P_f is None and dn > 0:
            ends.append((-un / dn, "compression"))
        if P_f is not None:
            ends.append((P_f - P, "end"))
        if not ends:
            raise ArithmeticError("the impact does not end (the point keeps approaching)")
        dP, which = min(ends)
        dP = max(dP, 0.0)
        P, F, un, ut = P + dP, F + k * dP, un + dn * dP, ut + dt * dP
        if s == 0.0 or abs(ut) <= tiny:
            ut = 0.0                            # sticking keeps it at 0, not at rounding
        if which == "stop":
            ut = 0.0
        if P_f is None and which != "compression" and un >= -tiny:
            which = "compression"               # it ended with the slip (a point on a circle: both at once)
        if which == "compression":
            un, c.P_c = 0.0, P
            P_f = (1.0 + e) * P
            if e == 0.0:
                break
        elif which == "end":
            break
    else:
        raise ArithmeticError("the impact's slip changed more often than Routh's method allows")
    c.P, c.F, c.u_n, c.u_t = P, F, un, ut
    return c
