"""Impacts in a scene: the impulse–momentum balance of every body with the joints' own rows.

At the instant of an impact the positions are fixed and the velocities jump.  Integrating the
balance laws over the impact (28.4, 33.2) with impulsive joint reactions only (the finite loads
give no impulse) gives, in the scene's maximal coordinates,

    [ M   −Jᵀ − Φ ] [ Δq̇ ]   [ 0 ]
    [ J      0    ] [ Λ  ] = [ b ]

with the same Jacobian J as the equations of motion: for every joint that stays made,
b = −(J q̇⁻ + φ_t) (the velocities after still satisfy it); for a smooth impacting row,
b = −(1 + e) (n·v⁻) (Newton's restitution, 28.7: the normal speed after is −e times the
one before).  A rough striking point (two rows: normal and tangential) is followed through the
impact by Routh's method (routh.py): without its rows, the same system with unit impulses
at the point gives the 2 × 2 map W from its impulses to its velocity, Routh's method gives its
impulse (Coulomb's law on every increment, Poisson's impulse ratio, = Newton's while the impulse
keeps one direction), and the system is solved with that impulse applied.  A rough point
striking together with others keeps the single-step rule: held (tangential row 0 after), or
sliding at −μ_k Λ_n sign(v_t⁻) along d̂ (Φ) when holding needs more than μ_s Λ_n.  Φ also holds
the kinetic friction of the made contacts that slide.
A made contact or a taut cord whose impulse would pull is released and the system solved
again.  The energy lost is T⁻ − T⁺ (28.16 for one smooth impact of two particles:
(1 − e²) ½ m* (n·Δv)²).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import NumericalError

from . import routh
from .elements import Cord
from .contacts import Contact, Rolls

EPS = float(np.finfo(float).eps)


def _system(s, q, v, t, target: dict, applied=None):
    """The impulse system's matrix and right side; ``target`` maps (element index, row) -> the
    velocity the row must have after the impact (its other rows keep J q̇⁺ + φ_t = 0);
    ``applied``: a known generalized impulse (the rough striking points')."""
    J = s.jac(q)
    A = s.kkt_matrix(q, J)
    b = -(J @ v + s.phi_t(t)) if s.m else np.zeros(0)
    for (i, r), want in target.items():
        k = s.offsets[i] + r
        b[k] = want - float(J[k] @ v)
    top = np.zeros(s.n) if applied is None else np.asarray(applied, dtype=float)
    return A, np.concatenate([top, b])


def _solve(A, rhs, t):
    """(x, shared): the impulse system's solution; where its rows are dependent but consistent
    (two rough points of one body striking together along one line: their friction impulses are
    statically indeterminate, only their sum is fixed), the least-norm one, ``shared`` True."""
    try:
        return np.linalg.solve(A, rhs), False
    except np.linalg.LinAlgError:
        x = np.linalg.lstsq(A, rhs, rcond=None)[0]
        scale = max(float(np.max(np.abs(rhs), initial=0.0)), float(np.max(np.abs(A), initial=0.0) *
                                                                    np.max(np.abs(x), initial=0.0)), 1e-300)
        if np.all(np.isfinite(x)) and float(np.max(np.abs(A @ x - rhs), initial=0.0)) <= 1e-10 * scale:
            return x, True
        raise NumericalError(f"the impact at t = {t:.6g} s is not determined: the joints made at that instant "
                             "lock each other (redundant rows)") from None


def _kkt(s, q, v, t, target: dict, applied=None):
    """Solve the impulse system for (v⁺, Λ, shared) (shared: :func:`_solve`)."""
    A, rhs = _system(s, q, v, t, target, applied)
    x, shared = _solve(A, rhs, t)
    return v + x[:s.n], x[s.n:], shared


def _pulling(s, lam, skip=frozenset()) -> tuple | None:
    """A made one-sided joint whose impulse would pull: (element, run) or None."""
    scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
    for i, e in enumerate(s.elements):
        if i in skip or e.rows == 0:
            continue
        lm = s.lam_of(lam, i)
        if isinstance(e, (Contact, Rolls)) and float(lm[0]) < -1e-12 * scale and not getattr(e, "two_sided", False):
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


def make(e, q) -> None:
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
    instant.  Every smooth striking row has Newton's law v_n⁺ = −e v_n⁻ (28.7) in one solve; a
    rough point striking alone has no row during the impact: its impulse (P, F) from Routh's
    method (``rough``) is applied as a known impulse; a rough point striking with others keeps
    the single-step rule (held, or sliding against its slip before: ``_slides``).  A striking point whose impulse would pull drops
    out (it separates), as a made joint does.  Leaves the striking joints made (a rough one that
    slides on, in mode slide/slip); returns (v⁺, normal impulse, friction impulse, released
    joints, [(element, normal impulse, friction impulse)] of ``others``, {element name: the
    course of its slip (routh.Course.name), or "smooth"}).  ``hold`` keeps every striking point
    made whatever its impulse (the plastic remainder of the accumulation rule, where the
    rebound left is below the threshold)."""
    i = s.elements.index(e)
    released = []
    if isinstance(e, Cord):
        e.slack = e.slack - {run}
        rows = {(i, e.taut.index(run)): 0.0}  # type: ignore[arg-type]  # run is given with every cord (strike's contract)
        struck = []
    else:
        struck = [(e, rest)] + list(others)
    speeds = {id(el): el.normal_speed(q, v) for el, _ in struck}
    slips = {id(el): el.slip_speed(q, v) for el, _ in struck}
    for el, _ in struck:
        make(el, q)
    s.refresh()
    J = s.jac(q)
    pts = [(el, r, J[s.offsets[s.elements.index(el)]:][:2].copy()) for el, r in struck if el.rows == 2]
    together = bool(pts) and len(struck) > 1    # a rough point striking with others: the single-step rule
    if together:
        pts = []
    for el, _r, _J in pts:
        el.mode = "off"                         # its impulse is applied, not a row, through the impact
    courses: dict = {}
    applied = None
    for _ in range(4 * len(s.elements) + 4):
        s.refresh()
        if struck:
            rows = {(s.elements.index(el), 0): -r * speeds[id(el)] for el, r in struck if el.rows}
            rows.update({(s.elements.index(el), 1): 0.0 for el, r in struck if el.rows == 2})
        if together:
            vp, lam, shared = _kkt(s, q, v, t, rows)
            if _slides(s, lam, struck, slips):
                continue
        if pts:
            courses = rough(s, q, v, t, rows, pts)
            applied = sum(Jk.T @ np.array([courses[id(el)].P, courses[id(el)].F]) for el, _r, Jk in pts)
        vp, lam, shared = _kkt(s, q, v, t, rows, applied)
        if _held_slips(s, lam, struck):
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
        return vp, -float(lm[0]), 0.0, released, [], {}
    got = []
    for el, _ in struck:
        c = courses.get(id(el))
        if c is not None:
            got.append((el, float(c.P), float(c.F)))
            continue
        lk = s.lam_of(lam, s.elements.index(el))
        got.append((el, float(lk[0]) if el.rows else 0.0, el.friction(lk) if el.rows else 0.0))
    names = {el.name: "smooth" if not el.rough else ("single step: " + el.mode) for el, _ in struck}
    if shared:      # the friction impulses of points along one line of one body: only their sum is fixed
        names = {k: c if c == "smooth" else c + ", friction shared by least norm (indeterminate)" for k, c in names.items()}
    if together and s.kinetic(vp) - s.kinetic(v) > 64 * EPS * s.kinetic(v):
        raise NumericalError(f"the points striking together at t = {t:.6g} s ("
                             + ", ".join(el.name for el, _ in struck) + ") would gain energy by the "
                             "single-step rule of Coulomb's law for impulses (Routh's method follows one "
                             "striking point only); not solved")
    for el, _r, Jk in pts:
        c = courses[id(el)]
        names[el.name] = c.name
        make(el, q)                            # made again: sticking (rolling), or sliding on
        # a slip after at the rounding of its terms (a body that had already stopped slipping,
        # struck again with no approach: the course "none") is no slip: it sticks, not slides on
        # with the sign of its rounding (which can set friction to push along the slip)
        terms = float(np.max(np.abs(np.asarray(Jk, float)) * np.abs(np.asarray(vp, float))[None, :], initial=0.0))
        if abs(c.u_t) > 64 * EPS * terms:
            el.mode = "slip" if isinstance(el, Rolls) else "slide"
            el.sign = math.copysign(1.0, c.u_t)
    s.refresh()
    released = [(el, r) for el, r in released if not any(el is x for x, _ in struck)]
    return vp, got[0][1], got[0][2], released, got[1:], names


def _mu(el) -> tuple[float, float]:
    """(μ_s, μ_k) of a rough element for the impact (a rolling joint without μ_s cannot slip: ∞)."""
    mu_s = math.inf if el.mu_s is None else float(el.mu_s)
    mu_k = math.inf if el.mu_s is None else float(el.mu_k or 0.0)
    return mu_s, mu_k


def rough(s, q, v, t, rows: dict, pts) -> dict:
    """Routh's method (routh.py) at the rough striking point of ``pts`` = [(element, e, J_k)] (J_k
    its normal and tangential rows), the joints made keeping their rows: the point's velocity is
    u = u⁰ + W (P, F), u⁰ = J_k q̇ with no impulse of its own and W = J_k Δq̇ per unit impulse
    (three right sides of one system).  Returns {id(element): routh.Course}."""
    n = s.n
    out: dict = {}
    for el, r, Jk in pts:
        A, rhs = _system(s, q, v, t, rows)
        cols = np.zeros((len(rhs), 3))
        cols[:, 0] = rhs
        cols[:n, 1], cols[:n, 2] = Jk[0], Jk[1]
        x, _ = _solve(A, cols, t)
        u0 = Jk @ (v + x[:n, 0])
        W = Jk @ x[:n, 1:]
        mu_s, mu_k = _mu(el)
        try:
            out[id(el)] = routh.routh(W, float(u0[0]), float(u0[1]), r, mu_s, mu_k)
        except ArithmeticError as exc:
            held = [e.name for e in s.elements if e is not el and e.rows]
            wedge = (f" with {', '.join(held)} made: the body is wedged between them (friction jams it: the impulse "
                     "that would stop its approach has no bound); make one of them smooth or give it a smaller mu"
                     if held else "")
            raise NumericalError(f"the impact of '{el.name}' at t = {t:.6g} s: {exc}{wedge}") from None
    return out


def _slides(s, lam, struck, slips) -> bool:
    """Points striking together, one of them rough (the single-step rule): a point held whose impulse
    needs more than μ_s Λ_n slides at μ_k Λ_n against the slip before; True when one changed."""
    for el, _ in struck:
        if el.rows != 2:
            continue
        lm = s.lam_of(lam, s.elements.index(el))
        if not el.holds(float(lm[0]), float(lm[1])):
            vt = slips[id(el)]
            el.mode = "slip" if isinstance(el, Rolls) else "slide"
            el.sign = math.copysign(1.0, vt) if vt != 0 else -math.copysign(1.0, float(lm[1]))
            return True
    return False


def _held_slips(s, lam, struck) -> bool:
    """A rough contact or rolling body made and held at rest before the impact (not striking)
    keeps its tangential row only while its friction impulse is within μ_s times its normal
    impulse (Coulomb's law for impulses, as at a striking point): a block on a rough floor struck
    sideways has no normal impulse from the floor, so no friction impulse, and moves off.  The one
    furthest past its limit slides at μ_k Λ_n against the impulse it needed to hold (the single-step
    rule); True when one changed (the system is solved again).  The test's rounding is the
    impact's (64 ε of its largest impulse): a joint the impact does not load stays held."""
    scale = 64 * EPS * max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
    striking = {id(el) for el, _ in struck}
    worst, over = None, 0.0
    for i, el in enumerate(s.elements):
        if (not isinstance(el, (Contact, Rolls)) or id(el) in striking or el.rows != 2
                or el.mode not in ("stick", "roll") or not el.rough):
            continue
        if isinstance(el, Rolls) and el.mu_s is None:
            continue                                # (rolling without μ_s: it cannot slip)
        lm = s.lam_of(lam, i)
        limit, F = el.grip(lm)
        past = abs(F) - limit
        if past > scale and past > over:
            worst, over, sign = el, past, -math.copysign(1.0, F)
    if worst is None:
        return False
    worst.mode = "slip" if isinstance(worst, Rolls) else "slide"
    worst.sign = sign
    return True


def normal_acceleration(s, q, v, t, e) -> float:
    """n·a of the contact point with the contact released (free flight towards the surface: < 0)."""
    a, _, _ = s.solve(q, v, t)
    if isinstance(e, Rolls) and not hasattr(e, "gap_acceleration"):
        i = e.body_point.body.index
        n = e.normal(q) if hasattr(e, "normal") else np.array(e.surface.n)     # a curve's n at the foot
        return float(n @ np.array([a[i[0]], a[i[1]]]))
    return e.gap_acceleration(q, v, a)
