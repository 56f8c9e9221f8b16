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

from dyncli.errors import InputError

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
    projected on the joints, so that the slip is kept).  A rate left out counts as given where
    the other joints fix it (a plank on a slider: its angle's rate 0, whatever the rolling row
    says; before, a disk spun on a carried deck whose ω the file left out was made to roll)."""
    from . import assembly

    changed = False
    for e in system.elements:
        if not (_can_slip(e) and e.mode == "roll"):
            continue
        J = e.tangent_jac(q)
        idx = np.nonzero(J)[0]
        left = [k for k in idx if not vgiven[k]]
        if left:
            rows = [r for x in system.elements if x is not e and x.rows for r in x.jac_list(q.tolist())]
            free = assembly.motions(np.array(rows, dtype=float).reshape(len(rows), system.n), system.n)
            if any(float(np.max(np.abs(free[:, k]), initial=0.0)) > 1e-12 for k in left):
                continue                # a rate left out is placed by the rolling row
        vt = e.slip_speed(q, v)
        scale = float(np.max(np.abs(J[idx] * v[idx]), initial=0.0))
        if abs(vt) > 64 * EPS * scale:
            e.mode, e.sign = "slip", math.copysign(1.0, vt)
            changed = True
    if changed:
        system.refresh()


def settle(system, q, v) -> None:
    """At t = 0: a cord that would push goes slack, friction past μ_s N slips (a rough contact
    held at rest slides, a rolling body slips), a two-sided rough guide's sliding friction takes
    the sign of its N, one change at a time until none is left."""
    loads = float(np.max(np.abs(system.applied(q, v, 0.0)[0]), initial=0.0))
    for _ in range(4 * len(system.elements) + 4):
        _, lam, _ = system.solve(q, v, 0.0)
        scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
        bad = None
        for i, e in enumerate(system.elements):
            if e.rows == 0 or not isinstance(e, (Contact, Rolls, Cord)):
                continue
            lm = system.lam_of(lam, i)
            for what, g in e.watch(lm, q, v, 0.0):
                slips = what == "slips" and (_can_slip(e) or isinstance(e, Contact))
                if what == "reverses" and not g < -64 * EPS * max(scale, loads):
                    continue                            # (N at 0 to the rounding of the loads: either way)
                if g < -64 * EPS * scale and (what in ("slack", "reverses") or slips):
                    bad = (e, what, lm)
                    break
            if bad:
                break
        if bad is None:
            return
        e, what, lm = bad
        if isinstance(e, Cord):                         # "slack"
            T = e.tensions(lm)
            e.slack = e.slack | {min(e.taut, key=lambda r: T[r])}
        elif what == "reverses" and isinstance(e, Contact):     # a two-sided guide's N is the other way
            e.nsign = -e.nsign
        elif isinstance(e, (Contact, Rolls)):           # "slips"
            F = e.friction(lm)
            e.mode = "slip" if isinstance(e, Rolls) else "slide"
            e.sign = -math.copysign(1.0, F)
        system.refresh()
