"""Impacts in a scene: the impulse–momentum balance of every body with the joints' own rows.

At the instant of an impact the positions are fixed and the velocities jump.  Integrating the
balance laws over the impact (28.4, 33.2) with impulsive joint reactions only (the finite loads
give no impulse) gives, in the scene's maximal coordinates,

    [ M   −Jᵀ − Φ ] [ Δq̇ ]   [ 0 ]
    [ J      0    ] [ Λ  ] = [ b ]

with the same Jacobian J as the equations of motion: for every joint that stays made,
b = −(J q̇⁻ + φ_t) (the velocities after still satisfy it); for the impacting row,
b = −(1 + e) (n·v⁻) (Newton's restitution, 28.7: the normal speed after is −e times the
one before); for its tangential row (rough, sticking) b = −v_t⁻.  Φ holds the friction of the
impact where it slides: −μ Λ_n sign(v_t⁻) along d̂ (Coulomb, as in 28.26 with the impulse at
the friction angle).  A made contact or a taut cord whose impulse would pull is released and
the system solved again.  The energy lost is T⁻ − T⁺ (28.16 for one smooth impact of two
particles: (1 − e²) ½ m* (n·Δv)²).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError

from .elements import Cord
from .contacts import Contact, Rolls

EPS = float(np.finfo(float).eps)


def _kkt(s, q, v, t, target: dict):
    """Solve the impulse system; ``target`` maps (element index, row) -> the velocity the row
    must have after the impact (its other rows keep J q̇⁺ + φ_t = 0)."""
    n, m = s.n, s.m
    J = s.jac(q)
    A = s.kkt_matrix(q, J)
    b = -(J @ v + s.phi_t(t)) if m else np.zeros(0)
    for (i, r), want in target.items():
        k = s.offsets[i] + r
        b[k] = want - float(J[k] @ v)
    try:
        x = np.linalg.solve(A, np.concatenate([np.zeros(n), b]))
    except np.linalg.LinAlgError:
        raise NumericalError(f"the impact at t = {t:.6g} s is not determined: the joints made at that instant "
                             "lock each other (redundant rows)") from None
    return v + x[:n], x[n:]


def _pulling(s, lam, skip=frozenset()) -> tuple | None:
    """A made one-sided joint whose impulse would pull: (element, run) or None."""
    scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
    for i, e in enumerate(s.elements):
        if i in skip or e.rows == 0:
            continue
        lm = s.lam_of(lam, i)
        if isinstance(e, (Contact, Rolls)) and float(lm[0]) < -1e-12 * scale:
            return e, None
        if isinstance(e, Cord):
            for r, T in zip(e.taut, (-float(x) for x in lm)):
                if T < -1e-12 * scale:
                    return e, r
    return None


def release(e, run=None) -> None:
    if isinstance(e, Cord):
        e.slack = e.slack | {run}
    else:
        e.mode, e.sign = "off", 0.0


def _make(e, q) -> None:
    """Make a striking contact (or rolling body) at q."""
    e.mode, e.sign = e.made(), 0.0
    if isinstance(e, Rolls):
        e.c0 = e.roll_const(q)
    elif e.mode == "stick":
        e.stick_here(q)


def strike(s, q, v, t, e, rest: float, run: int | None = None, others=(), hold: bool = False):
    """The impact of element ``e`` (a contact, stop or rolling body reaching its surface with
    restitution ``rest``, or a cord run jerked taut: ``run``, restitution 0) at (t, q, v⁻),
    together with ``others``: [(element, restitution)] of the points striking at the same
    instant.  Every striking row has Newton's law v_n⁺ = −e v_n⁻ (28.7) in one solve; a striking
    point whose impulse would pull drops out (it separates), as a made joint does.  Leaves the
    striking joints made (those with an impulse); returns (v⁺, normal impulse, friction impulse,
    released joints, [(element, normal impulse, friction impulse)] of ``others``).  ``hold``
    keeps every striking point made whatever its impulse (the plastic remainder of the
    accumulation rule, where the rebound left is below the threshold)."""
    i = s.elements.index(e)
    released = []
    if isinstance(e, Cord):
        e.slack = e.slack - {run}
        rows = {(i, e.taut.index(run)): 0.0}  # type: ignore[arg-type]  # run is given with every cord (strike's contract)
        struck = []
    else:
        struck = [(e, rest)] + list(others)
    speeds = {id(el): (el.normal_speed(q, v), el.slip_speed(q, v)) for el, _ in struck}
    for el, _ in struck:
        _make(el, q)
    for _ in range(4 * len(s.elements) + 4):
        s.refresh()
        if struck:
            rows = {}
            for el, r in struck:
                k = s.elements.index(el)
                if el.rows:
                    rows[(k, 0)] = -r * speeds[id(el)][0]
                if el.rows == 2:
                    rows[(k, 1)] = 0.0
        vp, lam = _kkt(s, q, v, t, rows)
        slid = _slides(s, lam, struck, speeds)
        if slid:
            continue
        skip = {i} if isinstance(e, Cord) else {s.elements.index(el) for el, _ in struck} if hold else set()
        pull = _pulling(s, lam, skip)
        if pull is None:
            break
        release(*pull)
        released.append(pull)
    else:
        raise NumericalError(f"the impact at t = {t:.6g} s could not be resolved (joints releasing each other)")
    lm = s.lam_of(lam, i)
    if isinstance(e, Cord):
        return vp, -float(lm[0]), 0.0, released, []
    got = []
    for el, _ in struck:
        lk = s.lam_of(lam, s.elements.index(el))
        got.append((el, float(lk[0]) if el.rows else 0.0, el.friction(lk) if el.rows else 0.0))
    released = [(el, r) for el, r in released if not any(el is x for x, _ in struck)]
    return vp, got[0][1], got[0][2], released, got[1:]


def _slides(s, lam, struck, speeds) -> bool:
    """A rough striking point held whose impulse needs more than μ Λ_n slides (Coulomb for
    impulses, against the slip before); True when one changed."""
    for el, _ in struck:
        if el.rows != 2:
            continue
        lm = s.lam_of(lam, s.elements.index(el))
        if not el.holds(float(lm[0]), float(lm[1])):
            vt = speeds[id(el)][1]
            el.mode = "slip" if isinstance(el, Rolls) else "slide"
            el.sign = math.copysign(1.0, vt) if vt != 0 else -math.copysign(1.0, float(lm[1]))
            return True
    return False


def normal_acceleration(s, q, v, t, e) -> float:
    """n·a of the contact point with the contact released (free flight towards the surface: < 0)."""
    a, _, _ = s.solve(q, v, t)
    if isinstance(e, Rolls):
        i = e.body_point.body.index
        n = e.normal(q) if hasattr(e, "normal") else np.array(e.surface.n)     # a curve's n at the foot
        return float(n @ np.array([a[i[0]], a[i[1]]]))
    acc = e.P.jac(q, s.n) @ a + e.P.bias(q, v)
    return float(e.normal(q) @ acc)
