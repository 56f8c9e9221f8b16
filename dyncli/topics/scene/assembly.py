"""Assembly, degrees of freedom and consistent initial velocities (docs/types/scene.md: assembly and degrees of freedom).

* Positions the file left out are placed by Gauss–Newton on φ(q) = 0 over those coordinates
  only, minimum-norm steps from the sketch (so every given coordinate is kept).
* A joint whose rows still have a gap after assembly is refused, naming it and the gap.
* Degrees of freedom by the rank of J (never by counting); redundant joints are named.
* Velocities that violate the joints are projected, mass-weighted, with a warning.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from dyncli.errors import InputError

from .elements import Drive, Element

EPS = float(np.finfo(float).eps)


def length_scale(q, system) -> float:
    s = float(np.max(np.abs(q))) if q.size else 0.0
    for b in system.bodies:
        s = max(s, b.length, b.radius, *b.size)
    return s if s > 0 else 1.0


#: the turns tried on the free angles when Newton's method stalls from the sketch (a rod drawn
#: level whose end must reach a wall: the wall's row does not move the angle there)
RESTART_TURNS = (math.pi / 4, -math.pi / 4, math.pi / 2, -math.pi / 2, 3 * math.pi / 4, -3 * math.pi / 4, math.pi)


def assemble(system, q, free, t: float = 0.0, iters: int = 60, restarts: bool = True) -> np.ndarray:
    """The positions left out (``free``) placed by the joints: Newton's method (least squares,
    damped) from the sketch; where it stalls with the joints not closed — a sketch at a position
    where the rows do not move a free angle — again from the free angles turned by each of
    :data:`RESTART_TURNS` in turn, the first that closes them kept (else the sketch's, for the
    refusal to name the gap)."""
    q = q.astype(float).copy()
    if not np.any(free) or system.m == 0:
        return q
    got = _newton(system, q, free, t, iters)
    if not restarts or not gaps(system, got, t):
        return got
    angles = [k for k in np.nonzero(free)[0] if system.names[k].startswith("angle.")]
    for turn in RESTART_TURNS if angles else ():
        q2 = q.copy()
        q2[angles] += turn
        q2 = _newton(system, q2, free, t, iters)
        if not gaps(system, q2, t):
            return q2
    return got


def _newton(system, q, free, t: float, iters: int) -> np.ndarray:
    q = q.copy()
    cols = np.nonzero(free)[0]
    tol = 1e-14 * length_scale(q, system)
    for _ in range(iters):
        ph = system.phi(q, t)
        if float(np.max(np.abs(ph), initial=0.0)) <= tol:
            break
        J = system.jac(q)[:, cols]
        if not (np.all(np.isfinite(ph)) and np.all(np.isfinite(J))):   # (LAPACK would print to stdout)
            raise np.linalg.LinAlgError("the joints' equations are not finite while placing the bodies")
        step = np.linalg.lstsq(J, -ph, rcond=None)[0]
        nrm = float(np.max(np.abs(step), initial=0.0))
        if nrm > 0.5 * length_scale(q, system):         # damp far jumps from a rough sketch
            step *= 0.5 * length_scale(q, system) / nrm
        q[cols] += step
        if nrm <= 1e-16 * length_scale(q, system):
            break
    return q


def other_branch(system, q, free, t: float = 0.0):
    """A second assembly of the positions left out, when a loop closes two ways (an elbow up
    or down): assembled again from the sketch with each free angle mirrored about its value
    (θ → 2θ_line − θ) or turned by π; returns (coordinate, placed value, other value) of the
    first coordinate that differs, or None."""
    # an angle that only gears hold is placed by them up to whole turns of their line of centres
    # (a planet's sun turned by 2π D/R_s): a winding, not a branch the drawing could choose
    if system.m == 0:                   # (no joint row: nothing closes)
        return None
    geared = _geared_only(system, q)
    # an angle that no row moves (a disk whose stop is not made yet) is free, not placed: no branch
    held = np.any(system.jac(q) != 0, axis=0)
    angles = [k for k in np.nonzero(free)[0] if system.names[k].startswith("angle.") and k not in geared and held[k]]
    free = np.array(free, dtype=bool) & ~np.isin(np.arange(system.n), sorted(geared))
    scale = length_scale(q, system)
    for k in angles:
        for trial in (-q[k], q[k] + math.pi, q[k] - math.pi / 2, q[k] + math.pi / 2):
            q2 = q.copy()
            q2[k] = trial
            q2 = assemble(system, q2, free, t, restarts=False)
            if gaps(system, q2, t):
                continue
            d = (q2 - q + math.pi) % (2 * math.pi) - math.pi
            d = np.where([nm.startswith("angle.") for nm in system.names], d, q2 - q)
            if float(np.max(np.abs(d[free]), initial=0.0)) > 1e-6 * scale:
                j = int(np.argmax(np.abs(d) * free))
                return j, float(q[j]), float(q[j] + d[j])
    return None


def _geared_only(system, q) -> set[int]:
    """The angles whose only rows are gears' (elements.Gear)."""
    if not any(e.kind == "gear" for e in system.elements):
        return set()
    out = set()
    for k, nm in enumerate(system.names):
        if not nm.startswith("angle."):
            continue
        kinds = {e.kind for e in system.elements if e.rows and any(row[k] for row in e.jac_list(q))}
        if kinds == {"gear"}:
            out.add(k)
    return out


def gaps(system, q, t: float = 0.0) -> list[tuple[Element, float]]:
    """(element, largest |φ| of its rows) for every element not satisfied to rounding."""
    out = []
    tol = 1e-9 * length_scale(q, system)
    for e in system.elements:
        g = float(np.max(np.abs(e.phi(q, t)), initial=0.0))
        if g > tol:
            out.append((e, g))
    return out


#: positions given off the joints by no more than this fraction of the scene's size (a hand
#: solution's positions typed to 8 digits: 4.7e-9 m on a 0.5 m four-bar) are moved onto them
CLOSE_GAPS = 1e-6


def close_small_gaps(system, q, t: float = 0.0) -> tuple[np.ndarray, float, float]:
    """(q, the largest gap, the largest move): where every joint's gap is within
    :data:`CLOSE_GAPS` of the scene's size, q moved onto the joints by minimum-norm Newton steps
    over all the coordinates (given ones too); else q as it is (0, 0), for the refusal."""
    bad = gaps(system, q, t)
    size = length_scale(q, system)
    if not bad or max(g for _e, g in bad) > CLOSE_GAPS * size:
        return q, 0.0, 0.0
    q2 = system.project_position(q, t, iters=8)
    if gaps(system, q2, t):
        return q, 0.0, 0.0
    return q2, max(g for _e, g in bad), float(np.max(np.abs(q2 - q)))


def refuse_gaps(system, q, free, t: float = 0.0) -> None:
    bad = gaps(system, q, t)
    if not bad:
        return
    e, g = bad[0]
    placed = "" if not np.any(free) else " (the joints could not place the positions left out either)"
    if getattr(e, "gap", None) is not None and getattr(e, "mode", "") != "off":
        _refuse_off_surface(e, q, placed)
    unit = "rad" if isinstance(e, Drive) and system.names[e.index].startswith("angle") else "m"
    raise InputError(f"the positions given violate the {e.kind} joint {e.name!r}: a gap of {g:.6g} {unit}{placed}; "
                     "fix the positions, or leave one out (x or angle) so that the joints place it", e.path)


def _refuse_off_surface(e: Any, q, placed: str) -> None:
    """A contact or rolling joint given off its surface: the gap, and what to write instead (a
    stop, for a body that lands there), or the depth through it with the surface's normal."""
    if hasattr(e, "refuse_gap"):        # a corner, or another body's rim: their own words
        raise InputError(e.refuse_gap(q, placed), e.path)
    gap = float(e.gap(q))
    label = (getattr(e, "P", None) or e.body_point).label
    centre = _centre_hint(e)
    if gap > 0:                         # off its surface, on its side
        land = (f", or, for a body that lands on it, make the joint a stop (stop: [{label}, {e.surface.name}], e: E), "
                "which starts open and is made where it strikes" if e.kind == "contact" else "")
        fix = centre or (f"place it on the surface or leave its position out so that the joint places it{land}")
        raise InputError(f"the positions given violate the {e.kind} joint {e.name!r}: a gap of {gap:.6g} m ({label} is "
                         f"off the surface {e.surface.name!r}; a {'contact' if e.kind == 'contact' else 'rolling body'} "
                         f"starts touching){placed}: {fix}", e.path)
    if gap < 0:                         # through its surface
        nf = getattr(e, "normal", None)
        n = [0.0 if abs(c) < 1e-12 else float(c) for c in (nf(q) if nf is not None else e.surface.n)]
        side = "increasing q" if getattr(e.surface, "curved", False) else "its direction d̂"
        fix = centre or ("place it on the surface or on the side n points to, or reverse the surface's direction if "
                         "the body is on the other side")
        raise InputError(f"{label} is given {-gap:.6g} m through the surface {e.surface.name!r} of the {e.kind} joint "
                         f"{e.name!r}, which pushes along n = [{n[0]:.4g}, {n[1]:.4g}] (to the left of {side}){placed}: "
                         f"{fix}", e.path)


def _centre_hint(e: Any) -> str:
    """For a contact at a sized body's centre (the body named alone): that the point is the centre
    — a box rests on a face, a disk rolls — and what to write."""
    P = getattr(e, "P", None)
    if P is None or e.kind != "contact" or P.body is None or P.p != (0.0, 0.0):
        return ""
    b = P.body
    if b.shape not in ("box", "rod") and not b.radius:
        return ""
    head = "a body named alone touches with its centre: "
    if b.shape == "box":
        return head + (f"for {b.name!r} resting on a face, name a point of that face (points: {{bottom: [0, "
                       f"{-b.size[1] / 2:g}]}}, contact: [{b.name}.bottom, {e.surface.name}]) with its angle along the "
                       "surface, or, for a block that only slides, make it a point body on the surface")
    if b.radius:
        return head + (f"a {b.shape} on a surface is rolls: [{b.name}, {e.surface.name}] (its rim on the surface), or a "
                       "contact at a point of its rim")
    return head + f"name an end, {b.name}.end1 or {b.name}.end2"


def rank(J: np.ndarray) -> int:
    if J.size == 0:
        return 0
    s = np.linalg.svd(J, compute_uv=False)
    return int(np.sum(s > s[0] * 1e-10)) if s[0] > 0 else 0


def redundant(system, q) -> list[str]:
    """Names of the joints any one of which could go without changing the rank (empty when
    the rows are independent)."""
    J = system.jac(q)
    r = rank(J)
    if r == J.shape[0]:
        return []
    names = []
    for i, e in enumerate(system.elements):
        if e.kind == "guide":
            continue
        keep = np.ones(J.shape[0], bool)
        o = system.offsets[i]
        keep[o:o + e.rows] = False
        if rank(J[keep]) == r:
            names.append(e.name)
    return names or [e.name for e in system.elements]


def independent(J: np.ndarray, n: int) -> list[int]:
    """Coordinates that can be chosen freely: greedy from the last coordinate back (a body's
    angle before its position, the later bodies first), each kept when it raises the rank of
    [J; e_i]."""
    r0 = rank(J)
    chosen: list[int] = []
    rows = J.copy() if J.size else np.zeros((0, n))
    need = n - r0
    for i in sorted(range(n), key=lambda i: -i):
        if len(chosen) == need:
            break
        e = np.zeros((1, n))
        e[0, i] = 1.0
        trial = np.vstack([rows, e])
        if rank(trial) > rank(rows):
            rows, chosen = trial, chosen + [i]
    return sorted(chosen)


def motions(J: np.ndarray, n: int) -> np.ndarray:
    """The velocities the rows J allow, as the rows of an orthonormal basis of J's null space
    (singular values below 1e-10 of the largest, or of 1, count as zero)."""
    if not J.size:
        return np.eye(n)
    _, sv, vt = np.linalg.svd(J)
    return vt[int(np.sum(sv > max(float(sv.max(initial=0.0)), 1.0) * 1e-10)):]


def implied_rates(system, q, v, given, t: float = 0.0) -> np.ndarray:
    """v with the rates left out (``given`` False) set to what the joints impose with the rates
    given held: the least mass-weighted change of the left-out rates that brings J v + φ_t
    closest to 0 (a rolling disk given its centre's velocity turns at −v/R; a hanging mass tied
    to a block given a speed moves with it).  Left-out rates no joint fixes stay as they are
    (at rest); what the given rates themselves violate is left to :func:`project_velocity`."""
    free = ~np.asarray(given, dtype=bool)
    if system.m == 0 or not free.any():
        return v
    J = system.jac(q)
    r = J @ v + system.phi_t(t)
    if not float(np.max(np.abs(r), initial=0.0)) > 0.0:
        return v
    root_w = np.sqrt(system.weights()[free])
    z = np.linalg.lstsq(J[:, free] / root_w, -r, rcond=None)[0]
    out = np.array(v, dtype=float)
    out[free] += z / root_w
    return out


def project_velocity(system, q, v, t: float = 0.0):
    """(v projected onto J v + φ_t = 0, changed?)."""
    if system.m == 0:
        return v, False
    J = system.jac(q)
    r = J @ v + system.phi_t(t)
    scale = max(float(np.max(np.abs(v), initial=0.0)), 1e-300)
    if float(np.max(np.abs(r), initial=0.0)) <= 1e-12 * scale * max(1.0, float(np.max(np.abs(J)))):
        return v, False
    return system.project_velocity(q, v, t), True
