"""The phase a scene starts in (docs/types/scene.md: one-sided joints at t = 0).

A one-sided joint that is not in its held state at t = 0 starts in the phase it is in, and the
motion's first event is where that phase ends:

* a cord given a ``length`` longer than its path at t = 0 starts **slack** by the difference
  (its ends move freely until it is taut: the event ``taut``, an impulsive jerk); one shorter
  than its path is refused (the positions violate it);
* a cord that would have to push at t = 0 (T < 0) starts slack;
* a rolling body given velocities that slip (``v`` and ``omega`` both given, the contact
  point's speed t̂·ẋ + R ω ≠ 0) starts **slipping** with kinetic friction μ_k N against the
  slip (the event ``sticks`` where the slip stops and the static test holds: a bowling ball
  that skids, then rolls); one whose rolling would need more than μ_s N at t = 0 slips
  opposite to the friction it needed, as a sticking contact that fails the static test does.

The held states are tested as the events are after a change (phases.py): each failure is
changed in turn, the first in the joints' order, until none is left.
"""

from __future__ import annotations

import math

import numpy as np

from dyncli.errors import InputError, NumericalError

from .contacts import Contact, Rolls
from .elements import Cord

EPS = float(np.finfo(float).eps)


def slack_by_length(cord: Cord, length: float | None, taut_length: float, path: str) -> None:
    """Give ``cord`` (one run) the slack of a ``length`` longer than its path at t = 0."""
    if length is None:
        return
    excess = length - taut_length
    tol = 1e-9 * max(length, taut_length)
    if excess < -tol:
        raise InputError(f"the cord's length {length:.6g} m is shorter than its path between the positions given "
                         f"({taut_length:.6g} m): fix the positions, or the length", path + ".length")
    if excess <= tol:
        return
    if len(cord.runs) > 1:
        raise InputError("a cord over a disk body that starts slack is not followed (the slack's share on each side "
                         "of the disk is not given): give positions that make it taut at t = 0, or a cord without "
                         "the disk", path + ".length")
    cord.consts = [cord.consts[0] + excess]
    cord.slack = frozenset({0})


def _can_slip(e) -> bool:
    return isinstance(e, Rolls) and e.mu_k is not None


def slipping_given(system, q, v, vgiven) -> None:
    """Rolling bodies whose given velocities slip start slipping (before the velocities are
    projected on the joints, so that the slip is kept)."""
    changed = False
    for e in system.elements:
        if not (_can_slip(e) and e.mode == "roll"):
            continue
        J = e.tangent_jac(q)
        idx = np.nonzero(J)[0]
        if not all(vgiven[idx]):
            continue                    # a rate left out is placed by the rolling row
        vt = e.slip_speed(q, v)
        scale = float(np.max(np.abs(J[idx] * v[idx]), initial=0.0))
        if abs(vt) > 64 * EPS * scale:
            e.mode, e.sign = "slip", math.copysign(1.0, vt)
            changed = True
    if changed:
        system.refresh()


def settle(system, q, v) -> list[str]:
    """At t = 0: a cord that would push goes slack, friction past μ_s N slips (a rough contact
    held at rest slides, a rolling body slips), a contact that would pull lets go of a body that
    another joint still holds (a crate pushed over tips about one edge: :func:`_lets_go`), one
    change at a time until none is left; returns a note for each contact let go."""
    kept: set[int] = set()
    notes: list[str] = []              # contacts that would pull but may not let go (refused after)
    for _ in range(4 * len(system.elements) + 4):
        _, lam, _ = system.solve(q, v, 0.0)
        scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
        bad = None
        for i, e in enumerate(system.elements):
            if e.rows == 0 or not isinstance(e, (Contact, Rolls, Cord)):
                continue
            lm = system.lam_of(lam, i)
            for what, g in e.watch(lm, q, v, 0.0):
                if g < -64 * EPS * scale and (what == "slack" or (what == "slips" and (_can_slip(e) or
                                                                                        isinstance(e, Contact)))
                                              or (what == "separates" and id(e) not in kept)):
                    bad = (e, what, lm)
                    break
            if bad:
                break
        if bad is None:
            return notes
        e, what, lm = bad
        if what == "separates":
            if lets_go(system, q, v, e):
                notes.append(let_go_note(e, float(lm[0])))
            else:
                kept.add(id(e))
            continue
        if isinstance(e, Cord):                         # "slack"
            T = e.tensions(lm)
            e.slack = e.slack | {min(e.taut, key=lambda r: T[r])}
        elif isinstance(e, (Contact, Rolls)):           # "slips"
            F = e.friction(lm)
            e.mode = "slip" if isinstance(e, Rolls) else "slide"
            e.sign = -math.copysign(1.0, F)
        system.refresh()
    return notes


def let_go_note(e, N: float) -> str:
    label = e.P.label if isinstance(e, Contact) else e.body_point.label
    return (f"at t = 0 the contact {e.name!r} lets go of {label}: held, it would have to pull (N = {N:.6g} N), so "
            f"{label} lifts off the surface {e.surface.name!r} from the start")


def lets_go(system, q, v, e) -> bool:
    """Release the contact ``e`` (N < 0 at t = 0) when its body stays held by another joint and,
    released, its point moves off the surface (n·a ≥ 0): a crate pushed past tipping lifts one
    edge.  A body the contact alone holds is not released (a body placed on the wrong side of
    its surface: refused with the surface's normal, prepare._refuse_at_start)."""
    from .impulse import normal_acceleration

    body = e.P.body if isinstance(e, Contact) else e.body_point.body
    if body is None:
        return False
    state = e.phase()
    e.mode, e.sign = "off", 0.0
    system.refresh()
    J = system.jac(q)
    held = J.size > 0 and bool(np.any(J[:, list(body.index)] != 0))
    if held:
        try:
            a, _, _ = system.solve(q, v, 0.0)
            scale = max(float(np.max(np.abs(a), initial=0.0)), abs(system.g), 1e-300)
            if normal_acceleration(system, q, v, 0.0, e) >= -64 * EPS * scale:
                return True
        except (NumericalError, np.linalg.LinAlgError):     # the rows left still redundant: not decided here
            pass
    e.set_phase(state)
    system.refresh()
    return False
