"""Set up a scene: bodies and joints, assembly, degrees of freedom, the contacts' initial modes
(the static test decides stick or slip at rest) and the refusals at t = 0 (a one-sided joint
that would pull, push or slip already)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from dyncli.errors import InputError, NumericalError

from . import assembly, build, motion, start
from . import elements as el
from .dynamics import SceneSystem
from .contacts import Contact, Rolls

EPS = float(np.finfo(float).eps)


@dataclass
class Scene:
    system: SceneSystem
    q0: np.ndarray
    v0: np.ndarray
    dof: int
    coords: list[str]
    warnings: list[str] = field(default_factory=list)
    surfaces: list = field(default_factory=list)


def setup(plan: build.Plan) -> Scene:
    bodies, q, free, v, names, vgiven = build.bodies_of(plan)
    _carriers_placed(plan, bodies, free)
    surfaces = {k: build.surface_of(k, s, bodies, q) for k, s in plan.surfaces.items()}
    R = build.Resolver(bodies, surfaces)
    _sketch_links_and_rolls(plan, R, q, free)
    n = len(q)
    elems, cords = build.joint_elements(plan, R, q, n)
    loads = build.loads_of(plan, R, q)
    system = SceneSystem(list(bodies.values()), elems, loads, plan.g, n, names)
    warnings: list[str] = [f"joints.{name}: mu_k = {j['mu_k']:g} is larger than mu_s = {j['mu_s']:g} (kinetic friction "
                           "is the smaller in the notes' tables: were they swapped?); solved as given"
                           for name, j in plan.joints.items()
                           if j.get("mu_s") is not None and j.get("mu_k") is not None and j["mu_k"] > j["mu_s"]]
    q = assembly.assemble(system, q, free)
    if cords:
        _place_hanging(plan, cords, R, q, free, system)
        for name, spec in cords:
            cord, guides = build.cord_element(name, spec, R, q, n)
            start.slack_by_length(cord, spec["length"], _cord_length(cord, spec, R, q), f"joints.{name}")
            system.elements.append(cord)
            system.refresh()
            for gd in guides:
                if _held_otherwise(system, q, gd, warnings.append, cord):
                    continue
                system.elements.append(gd)
                system.refresh()
                J = system.jac(q)
                if assembly.rank(J) < J.shape[0]:
                    system.elements.pop()
                    system.refresh()
        q = assembly.assemble(system, q, free)
    q, gap, shift = assembly.close_small_gaps(system, q)
    if gap:
        warnings.append(f"the positions given leave the joints up to {gap:.3g} m open (within "
                        f"{assembly.CLOSE_GAPS:g} of the scene's size: rounded inputs): moved onto them, no "
                        f"coordinate by more than {shift:.3g}")
    assembly.refuse_gaps(system, q, free)
    _span_moving(system, q)
    _refuse_moving_pulley_at_angle(system, q)
    _carried_fixed_angles(system, q)
    other = assembly.other_branch(system, q, free)
    if other is not None:
        k, mine, theirs = other
        warnings.append(f"the joints close two ways: assembled with {names[k]} = {mine:.6g} (the other branch has "
                        f"{names[k]} = {theirs:.6g}); give that coordinate in the file to choose")
    _refuse_redundant(system, q)
    _refuse_loose_gears(system, q)
    _gear_carriers(system, q)
    v_in = v.copy()
    start.slipping_given(system, q, v, vgiven)
    v, changed = assembly.project_velocity(system, q, assembly.implied_rates(system, q, v, vgiven))
    moved = [k for k in range(n) if vgiven[k] and abs(v[k] - v_in[k]) > 1e-12 * max(abs(v_in[k]), abs(v[k]), 1e-300)]
    if changed and moved:
        warnings.append("the initial velocities given violate the joints and were projected (mass-weighted) onto "
                        "them: " + ", ".join(f"{_rate_name(names[k])} = {v[k]:.6g}" for k in range(n)
                                             if vgiven[k] or abs(v[k]) > 0))
    _refuse_massless(system, q, plan)
    _start_modes(system, q, v)
    warnings += [motion.indeterminate_warning(names) for names in motion.held_groups(system)]
    J = _freedom_rows(system, q)
    dof = n - assembly.rank(J)
    coords = [names[i] for i in assembly.independent(J, n)]
    _refuse_at_start(system, q, v)
    _guided_aside(system, q, v, warnings.append)
    _kept_across(system, q)
    return Scene(system, q, v, dof, coords, warnings, list(surfaces.values()))


#: the joints that hold a disk's axle for good (a cord, a contact, rolling or a drive may let it move:
#: a rolling drum held at t = 0 by friction and its own cord slips once the static test fails)
AXLE_HOLDERS = ("pin", "link", "slider", "gear")


def _axle_motions(system, q) -> np.ndarray:
    """The velocities that the joints holding axles for good (:data:`AXLE_HOLDERS`) allow."""
    rows = [r for e in system.elements if e.rows and e.kind in AXLE_HOLDERS for r in e.jac_list(q.tolist())]
    return assembly.motions(np.array(rows, dtype=float).reshape(len(rows), system.n), system.n)


def _axle_fixed(system, q, disk, free=None) -> bool:
    """Whether the disk body's centre cannot move (a massive pulley on a fixed axle); True for no
    disk (a light fixed pulley).  ``free``: :func:`_axle_motions`, when already made."""
    if disk is None:
        return True
    if free is None:
        free = _axle_motions(system, q)
    return float(np.max(np.abs(free[:, list(disk.index[:2])]), initial=0.0)) <= 1e-12


def _kept_across(system, q) -> None:
    """A cord segment from a disk body on a fixed axle to a rigid body's point (a rod tied over a
    massive pulley) turns with the point (``Cord.let_turn``, the disk's turn in its length); one
    from a disk that moves already turns with both ends (``_span_moving``)."""
    kept = [(cord, s) for cord in system.elements if cord.kind == "cord"
            for run in cord.runs for s in run if s.turning is None and s.spanning is None
            for end, other in ((s.a, s.b), (s.b, s.a)) if other.centre is not None
            and end.point is not None and end.point.body is not None and end.point.body.rigid]
    if not kept:
        return
    free = _axle_motions(system, q)
    for cord, seg in kept:
        if seg.pulley is not None and _axle_fixed(system, q, seg.pulley[3], free):
            cord.let_turn(seg, q)


def _freedom_rows(system, q):
    """The joint rows of the mechanism's freedom at t = 0, once the start's modes are decided: a
    contact held by friction still may slide (its sticking row left out), a rolling body that
    rolls counts its no-slip row and one that slips from the start (given so, or by the static
    test) does not."""
    saved = [e.phase() for e in system.elements]
    for e in system.elements:
        if isinstance(e, Contact) and e.mode in ("stick", "shared"):
            e.mode, e.holder = "slide", None
    system.refresh()
    J = system.jac(q)
    for e, ph in zip(system.elements, saved):
        e.set_phase(ph)
    system.refresh()
    return J


def _carriers_placed(plan, bodies, free) -> None:
    """A body that carries a surface is where the file draws it: its `x` given (refused
    otherwise), its angle as given or 0 (not left to the joints), so that the line drawn in
    ground coordinates at t = 0 is where it was drawn."""
    for name, sf in plan.surfaces.items():
        b = bodies.get(sf.get("body")) if sf.get("body") is not None else None
        if b is None:
            continue
        if free[b.index[0]]:
            raise InputError(f"give the position x of {b.name!r}, which carries the surface {name!r}: the line is "
                             "drawn in ground coordinates with its body where the file puts it",
                             f"bodies.{b.name}.x")
        if b.rigid:
            free[b.index[2]] = False


def _held_otherwise(system, q, guide, warn, cord=None) -> bool:
    """Whether another joint than a cord already holds the guided mass in some direction (a block
    on a table tied over a pulley, a collar on a rod): the table guides it, not its segment;
    guided along the segment too, it could not move at all.  Its segment, from a fixed pulley,
    then turns with it (``cord.let_turn``: exact), one from a moving pulley with both its ends
    (``_span_moving``); any other keeps its direction of t = 0, told (``warn``) when at an angle
    to the one path left to the mass.  A segment across that path (a block on the floor that the
    cord will lift) still guides the mass."""
    cols = list(guide.P.body.index[:2])
    ql = q.tolist()
    rows = [r for e in system.elements if e.rows and e.kind not in ("cord", "guide") for r in e.jac_list(ql)]
    if not rows:
        return False
    held = np.array(rows, dtype=float)[:, cols]
    if assembly.rank(held) == 0:
        return False
    turnable = cord is not None and guide.segment is not None and guide.segment.pulley is not None \
        and _axle_fixed(system, q, guide.segment.pulley[3])
    # from a disk that moves, it turns with both ends once no guide holds it (_span_moving)
    spans = cord is not None and guide.segment is not None and guide.segment.pulley is not None and not turnable
    if assembly.rank(held) > 1 and turnable:
        cord.let_turn(guide.segment, q)
        system.refresh()
    if assembly.rank(held) == 1:
        k = int(np.argmax(np.abs(held).sum(axis=1)))
        path = np.array([-held[k, 1], held[k, 0]]) / math.hypot(held[k, 0], held[k, 1])
        off = abs(float(guide.w @ path))
        if off > 1.0 - 1e-9:
            return False                # a segment across the path (a block lifted off the floor): guided by it
        if turnable:
            cord.let_turn(guide.segment, q)
            system.refresh()
            return True
        if off > 1e-9 and not spans:
            cord = guide.name.partition(":")[0]
            warn(f"the cord {cord!r} meets {guide.P.body.name!r} at {math.degrees(math.asin(min(off, 1.0))):.3g}° to "
                 "the path its other joints allow: the cord keeps its segments' directions of t = 0, so that angle "
                 "stays as it is (exact while the segment runs along the path: put the pulley in line with it)")
    return True


def _span_moving(system, q) -> None:
    """A cord segment at a disk body whose centre can move (a moving pulley, a disk hanging in a
    loop of cord) turns with both its ends (``cord.let_span``: exact), unless a guide holds a
    hanging mass or a wound body at its other end along it (the textbook's hoist: that segment
    keeps its direction of t = 0)."""
    cords = [e for e in system.elements if e.kind == "cord" and not hasattr(e, "ends")]
    if not cords:
        return
    guided = {id(e.segment) for e in system.elements if e.kind == "guide" and e.segment is not None}
    free = None
    for cord in cords:
        for seg in (sg for run in cord.runs for sg in run):
            if seg.turning is not None or seg.spanning is not None or seg.centres is None or id(seg) in guided:
                continue
            disks = [end.centre.body for end in (seg.a, seg.b) if end.centre is not None]
            if not disks:
                continue
            if free is None:
                free = _axle_motions(system, q)
            if any(not _axle_fixed(system, q, d, free) for d in disks):
                cord.let_span(seg, q)
    system.refresh()


def _refuse_moving_pulley_at_angle(system, q) -> None:
    """A cord over a disk body whose centre can move (a moving pulley) is followed only with its
    two segments there parallel when one of them keeps its direction of t = 0 (a guide holds a
    hanging mass along it: ``_span_moving`` turns every other one), which holds while the pulley
    moves along them; at an angle their pull turns the pulley aside and the direction kept would
    not be the cord's."""
    cords = [e for e in system.elements if e.kind == "cord"]
    if not cords:
        return
    free_motion = None
    for cord in cords:
        segs = [sg for run in cord.runs for sg in run]
        for s_in, s_out in zip(segs[:-1], segs[1:]):
            c = s_in.b.centre
            if c is None or s_out.a.centre is None or s_out.a.centre.body is not c.body:
                continue
            if s_in.spanning is not None and s_out.spanning is not None:
                continue                # both turn with the pulley: exact at any angle
            cross = abs(float(s_in.u[0] * s_out.u[1] - s_in.u[1] * s_out.u[0]))
            if cross <= 1e-9:
                continue
            if free_motion is None:     # the velocities the joints allow
                free_motion = assembly.motions(system.jac(q), system.n)
            cols = list(c.body.index[:2])
            if float(np.max(np.abs(free_motion[:, cols]), initial=0.0)) > 1e-9:
                deg = math.degrees(math.asin(min(cross, 1.0)))
                raise InputError(f"the cord {cord.name!r} passes over the moving disk {c.body.name!r} with its two "
                                 f"segments at {deg:.3g}° to each other, one of them to a hanging mass or wound body "
                                 "guided along it (it keeps its direction of t = 0, exact only while the pulley moves "
                                 "along it); place the pulleys so that both segments run parallel", cord.path)


def _carried_fixed_angles(system, q) -> None:
    """A contact or slider on a line carried by a body whose angle the two-sided joints hold (a
    wedge on a slider, a cart on a point body) has rows affine in q: marked, for the closed forms."""
    from .carried import CarriedContact, CarriedRolls, CarriedSlider

    carried = [e for e in system.elements if isinstance(e, (CarriedContact, CarriedRolls, CarriedSlider))]
    if not carried:
        return
    rows = [r for e in system.elements if e.rows and e.kind in ("pin", "slider", "link", "drive")
            for r in e.jac_list(q.tolist())]
    free_motion = assembly.motions(np.array(rows, dtype=float).reshape(len(rows), system.n), system.n)
    for e in carried:
        W = e.surface.body
        e.fixed_angle = not W.rigid or float(np.max(np.abs(free_motion[:, int(W.index[2])]), initial=0.0)) <= 1e-9


def _rate_name(coord: str) -> str:
    """x.A.0 -> v.A.0, angle.rod -> omega.rod."""
    head, _, rest = coord.partition(".")
    return ("v." if head == "x" else "omega.") + rest


def _sketch_links_and_rolls(plan, R, q, free) -> None:
    """Sketch positions the joints place exactly: a link's free end from its `angle`, a rolling
    body's centre from `at` (held there: given), the centre of a body on a straight slider whose
    position is left out on the slider's line (the guide runs along the line through the centre
    at t = 0: left at the sketch's default, the origin, it would run along another line)."""
    for name, j in plan.joints.items():
        if j["kind"] == "slider" and not any(j.get(k) for k in ("mu", "mu_s", "mu_k")):
            b, s = R.body(j["slider"][0], ""), R.surface(j["slider"][1], "")
            if free[b.index[0]] and free[b.index[1]] and not getattr(s, "curved", False) \
                    and not getattr(s, "carried", False) and not getattr(s, "corner", False):
                (o1, o2), (n1, n2) = s.origin, s.n
                i1, i2 = b.index[0], b.index[1]
                off = n1 * (q[i1] - o1) + n2 * (q[i2] - o2)
                q[i1], q[i2] = q[i1] - off * n1, q[i2] - off * n2
        if j["kind"] == "link" and j["angle"] is not None and j["length"] is not None:
            P, Q = R.point(j["link"][0], ""), R.point(j["link"][1], "")
            if Q.body is not None and free[Q.body.index[0]]:
                r = P.pos(q) + j["length"] * np.array([math.sin(j["angle"]), -math.cos(j["angle"])])
                i = Q.body.index
                q[i[0]], q[i[1]] = r - Q.arm(q)
        if j["kind"] == "rolls" and j["at"] is not None:
            b, s = R.body(j["rolls"][0], ""), R.surface(j["rolls"][1], "")
            if b.rigid and free[b.index[0]]:
                # `at` is where it touches: its centre is held there (its angle, left free, is the
                # rolling row's: not a second branch of the assembly) — on a curve, where the body
                # fits in its bend there (radius × curvature < 1: the centre's foot is `at`)
                if getattr(s, "curved", False):
                    from . import curved

                    c = curved.place_on(s, j["at"], b.radius)
                    held = b.radius * float(s.frame(j["at"])[4]) < 1.0
                else:
                    c = np.array(s.origin) + j["at"] * np.array(s.d) + b.radius * np.array(s.n)
                    held = True
                if held:
                    free[b.index[0]] = free[b.index[1]] = False
                q[b.index[0]], q[b.index[1]] = c
        if j["kind"] == "contact" and j["at"] is not None:
            P, s = R.point(j["contact"][0], ""), R.surface(j["contact"][1], "")
            if getattr(s, "curved", False) and P.body is not None and free[P.body.index[0]]:
                from . import curved

                i = P.body.index
                q[i[0]], q[i[1]] = curved.place_on(s, j["at"], 0.0) - P.arm(q)


def _place_hanging(plan, cords, R, q, free, system) -> None:
    """A cord end mass left out hangs straight down from its neighbour, at the cord's length."""
    for name, spec in cords:
        items = spec["cord"]
        for k in (0, len(items) - 1):
            it = items[k]
            if isinstance(it, str) and it in R.bodies and free[R.bodies[it].index[0]]:
                if spec["length"] is None:
                    raise InputError(f"the position of {it!r} is left out: give its x, or the cord's length so that "
                                     "the cord places it", f"joints.{name}.length")
                b = R.bodies[it]
                i = b.index
                nb = items[1] if k == 0 else items[-2]
                top = _node_xy(nb, R, q)
                q[i[0]], q[i[1]] = top[0], top[1] - 1.0        # a first guess below; the length row places it
                cord, _ = build.cord_element(name, spec, R, q, len(q))
                shortfall = spec["length"] - _cord_length(cord, spec, R, q)
                q[i[1]] -= shortfall
                if not _cord_length(cord, spec, R, q) > 0:
                    raise InputError("the cord is too short to reach its ends", f"joints.{name}.length")


def _node_xy(nd, R, q):
    if isinstance(nd, dict) and "pulley" in nd:
        c = np.array(nd["pulley"], float)
        return c + np.array([float(nd.get("radius", 0.0)), 0.0])
    if isinstance(nd, str):
        return R.point(nd, "").pos(q)
    return np.array(nd, float)


def _cord_length(cord, spec, R, q) -> float:
    """Straight lengths plus the arcs over pulleys (the cord's whole length at q); a string over
    pegs starts straight: its length."""
    if isinstance(cord, el.PeggedString):
        return float(cord.lengths(q)[0])
    total = 0.0
    segs = [s for run in cord.runs for s in run]
    for s in segs:
        total += float(s.u @ (_tangent(s.b, s.u, q) - _tangent(s.a, s.u, q)))
    items = spec["cord"]
    for i in range(1, len(items) - 1):
        u1, u2 = segs[i - 1].u, segs[i].u
        turn = abs(math.atan2(u1[0] * u2[1] - u1[1] * u2[0], float(u1 @ u2)))
        it = items[i]
        r = float(it.get("radius", 0.0)) if isinstance(it, dict) else R.bodies[it].radius
        total += r * turn
    return total


def _tangent(end, u, q):
    if end.point is not None:
        return end.point.pos(q)
    if end.centre is not None:
        return end.centre.pos(q)
    return end.fixed


def _guided_aside(system, q, v, warn) -> None:
    """A hanging mass is guided along its segment's direction of t = 0 (as textbooks treat it):
    exact while its loads pull along that line.  A guide that has to push the mass sideways at
    t = 0 (a mass placed off the vertical below its pulley, a sideways force on it) is told: a
    mass hanging free would swing there."""
    guides = [(i, e) for i, e in enumerate(system.elements) if e.kind == "guide"]
    if not guides:
        return
    _, lam, _ = system.solve(q, v, 0.0)
    scale = float(np.max(np.abs(lam), initial=0.0))
    for i, e in guides:
        G = abs(float(system.lam_of(lam, i)[0]))
        if G <= 1e-9 * scale:
            continue
        cord = e.name.partition(":")[0]
        tilt = math.degrees(math.acos(min(abs(float(e.w[0])), 1.0)))     # the segment's angle from e2
        warn(f"the cord {cord!r} holds {e.P.body.name!r} on its segment's line of t = 0 ({tilt:.3g}° from the "
             f"vertical) with a sideways force of {G:.6g} N: a mass hanging from a cord over a pulley (or off a wound "
             "body) is guided along its segment, exact while its loads pull along that line; here they do not, and "
             "a mass hanging free would swing. Place it so that its segment runs along the pull (straight below the "
             "pulley's rim under gravity), or hang it from a point by a string (a cord of two points), whose "
             "direction turns")


def _refuse_massless(system, q, plan) -> None:
    """A motion the joints allow that moves no mass (a body without mass, or inertia, whose
    coordinate no joint ties to a massive one) has no equation of motion: refused naming the
    body.  A massless body the joints carry with massive ones (a collar pinned to a rod's end in
    a slot: the elliptic trammel) is not: the mass matrix on the joints' null space, Nᵀ M N, must
    be positive definite."""
    mass = np.asarray(system.mass, dtype=float)
    if not np.any(mass == 0):
        return
    J = system.jac(q)
    if J.size:
        _, sv, Vt = np.linalg.svd(J)
        r = int(np.sum(sv > sv[0] * 1e-10)) if sv.size and sv[0] > 0 else 0
        null = Vt[r:]
    else:
        null = np.eye(system.n)
    if not null.size:
        return
    w, U = np.linalg.eigh((null * mass[None, :]) @ null.T)
    top = float(np.max(mass))
    if float(w[0]) > 1e-12 * top:
        return
    z = np.abs(U[:, 0] @ null)                       # the motion that moves no mass
    k = max((k for k in range(system.n) if mass[k] == 0), key=lambda k: z[k])
    body = next(b for b in system.bodies if k in b.index)
    what = "I" if body.rigid and k == body.index[-1] and body.mass > 0 else "mass"
    pulley = any(e.kind == "cord" and any(end.centre is not None and end.centre.body is body
                                          for run in e.runs for sg in run for end in (sg.a, sg.b))
                 for e in system.elements)
    hint = (f" (a light pulley hanging in a cord: pin its load at its centre, {{pin: [{body.name}, LOAD]}}, "
            "or give the load's mass to the pulley)") if pulley and what == "mass" else ""
    raise InputError(f"{body.name!r} has no {'moment of inertia' if what == 'I' else 'mass'} but can move "
                     f"freely ({system.names[k]} is held by no joint): give it a {what}, or join it so that "
                     f"the joints carry it{hint}", f"bodies.{body.name}.{what}")


def _gear_carriers(system, q) -> None:
    """Each gear pair's carrier: the ground, or the rigid body, that its line of centres turns with
    along every motion the joints allow (φ̇ = 0, or φ̇ = θ̇_C, on their null space: pinned axles, a
    planet's arm); the row then reads φ on that branch, so that its windings are no branches of
    the positions (elements.Gear)."""
    gears = [e for e in system.elements if e.kind == "gear" and hasattr(e, "B")]
    if not gears:
        return
    # the mechanism's motions, its drives left free (a driven carrier turns the line of centres)
    rows = [r for e in system.elements if e.kind != "drive" for r in e.jac_list(q)]
    J = np.array(rows, dtype=float).reshape(len(rows), system.n)
    _, sv, Vt = np.linalg.svd(J)
    N = Vt[int(np.sum(sv > sv[0] * 1e-10)) if sv.size and sv[0] > 0 else 0:].T
    for g in gears:
        d1, d2 = g._d(q)
        dd = d1 * d1 + d2 * d2
        rate = g.phi_grad(q) @ N if N.size else np.zeros(0)
        tol = 1e-9 * max(1.0, float(np.max(np.abs(rate), initial=0.0)))
        if float(np.max(np.abs(rate), initial=0.0)) <= 1e-12 / math.sqrt(dd):
            g.carrier, g.phi0 = "ground", math.atan2(d2, d1)
            continue
        for body in system.bodies:
            k = body.index[2] if body.rigid else None
            if k is not None and float(np.max(np.abs(rate - N[k]), initial=0.0)) <= tol:
                g.carrier, g.phi0 = k, math.atan2(d2, d1) - float(q[k])
                break


def _refuse_loose_gears(system, q) -> None:
    """A gear row holds the pitch circles rolling on each other, not their centres' distance D:
    the other joints (pins, a carrier arm) must hold it, or the gears would part while the row
    still meshes them.  Held means to first and second order along every motion the joints allow:
    ∇D = Σ c_k ∇φ_k over the other rows, and then D̈ = q̇ᵀ (∇²D − Σ c_k ∇²φ_k) q̇ = 0 on their null
    space (a centre guided along the tangent only, as a wound drum's, keeps D to first order and
    not to second: refused)."""
    from .curvature import rows_hessian

    gears = [e for e in system.elements if e.kind == "gear"]
    if not gears:
        return
    J = system.jac(q)
    others = np.ones(J.shape[0], dtype=bool)
    for i, e in enumerate(system.elements):
        if e.kind == "gear":
            others[system.offsets[i]:system.offsets[i] + e.rows] = False
    Jo = J[others]
    _, sv, Vt = np.linalg.svd(J)
    N = Vt[int(np.sum(sv > sv[0] * 1e-10)) if sv.size and sv[0] > 0 else 0:].T      # the motions allowed
    for g in gears:
        grad, hess = g.distance_terms(q, system.n)
        c = np.linalg.lstsq(Jo.T, grad, rcond=None)[0] if Jo.size else np.zeros(0)
        held = float(np.linalg.norm(Jo.T @ c - grad)) <= 1e-9 if Jo.size else False
        if held and N.size:
            lam = np.zeros(J.shape[0])
            lam[others] = c
            H = hess - rows_hessian(system, q, lam)
            held = float(np.max(np.abs(N.T @ H @ N), initial=0.0)) <= 1e-9 / assembly.length_scale(q, system)
        if not held:
            if hasattr(g, "B"):
                what = f"the gears {g.A.name!r} and {g.B.name!r} are not held at their distance"
            else:
                gear = g.body if hasattr(g, "body") else g.P.body
                what = f"the gear {gear.name!r} is not held at its distance from the rack"
            raise InputError(f"{what}: a gear joint meshes the pitch circles, and the centres must be held by other "
                             "joints — pin a gear to the ground (or to a carrier arm), guide a rack with a slider",
                             g.path)


def _refuse_redundant(system, q) -> None:
    """Dependent joint rows: refused naming the joints any one of which could go."""
    red = assembly.redundant(system, q)
    if red:
        raise InputError(f"redundant joints: {', '.join(red)} — their rows are dependent (one of them removes a "
                         "freedom the others already remove), so the joint forces are not unique (statically "
                         "indeterminate); remove one of them", f"joints.{red[0]}")


def _start_modes(system, q, v) -> None:
    """The joints' phases at t = 0 (:func:`_initial_modes`, :func:`start.settle`).  A stop whose
    point (a disk's rim) is on its surface at t = 0 and not moving off or into it is first tried
    made — a ball resting on the floor, then kicked, is on the floor from the start, not struck an
    instant later with a zero impulse (a disk made so rolls, or slips where its rim slips); where
    its surface would have to pull it then (a crate's corner that lifts off), or the start cannot
    be decided with it made, it stays open as before."""
    saved = [e.phase() for e in system.elements]
    made = _rest_stops(system, q, v)
    if made:
        try:
            _initial_modes(system, q, v)
            start.settle(system, q, v)
            _, lam, _ = system.solve(q, v, 0.0)
            if all(e.mode != "off" and float(system.lam_of(lam, system.elements.index(e))[0]) >= 0 for e in made):
                return
        except InputError:
            pass
        for e, ph in zip(system.elements, saved):   # as drawn: the stops open
            e.set_phase(ph)
        system.refresh()
    _initial_modes(system, q, v)
    start.settle(system, q, v)


def _rest_stops(system, q, v) -> list:
    """The stops touching their surfaces at t = 0 without a normal speed, made (and returned)."""
    tol = 1e-12 * assembly.length_scale(q, system)
    vtol = 1e-12 * max(1.0, float(np.max(np.abs(v), initial=0.0)))
    made = []
    for e in system.elements:
        if not (isinstance(e, Rolls) or (isinstance(e, Contact) and e.stop)) or e.mode != "off":
            continue
        if abs(e.gap(q)) > tol or abs(e.normal_speed(q, v)) > vtol:
            continue
        if isinstance(e, Rolls):
            slip = e.slip_speed(q, v)
            e.mode, e.sign = ("slip", math.copysign(1.0, slip)) if slip != 0 else ("roll", 0.0)
        else:
            e.mode = "slide" if e.rough else "smooth"      # (rough: _initial_modes decides stick or slide)
        made.append(e)
    if made:
        system.refresh()
    return made


def _slip_rounding(e, q, v) -> float:
    """The rounding of a contact's slip speed at t = 0: 16 ε Σ|J_t,i v_i| (its terms, each with
    its row's own rounding: a ball set rolling inside a hoop, v = ω r, has a slip of 6e-17 from
    the hoop's radius less the ball's).  A slip within it is none: the point is at rest."""
    Jt = np.abs(np.asarray(e.tangent_jac(q), dtype=float))
    return 16 * EPS * float(Jt @ np.abs(np.asarray(v, dtype=float)))


def _initial_modes(system, q, v) -> None:
    """Rough contacts: sliding when their point slides; those at rest are held together (a
    second row each) and the static test decides: every one with |F| ≤ μ_s N sticks; else the
    one furthest past its limit slides opposite to the friction it needed, and the rest are
    tested again.  Where the held rows are redundant, a contact whose N they do determine and
    that would pull is refused as such (:func:`_pull_determined`: a crate pushed past tipping
    on two rough corners is not "at rest"); friction that equilibrium does not determine is
    refused naming the contacts."""
    at_rest = []
    for e in system.elements:
        if isinstance(e, Contact) and e.rough and e.mode != "off":       # a stop is open until it is struck
            vt = e.slip_speed(q, v)
            if abs(vt) > _slip_rounding(e, q, v):
                e.mode, e.sign = "slide", math.copysign(1.0, vt)
            else:
                e.mode, e.sign = "stick", 0.0
                e.stick_here(q)
                at_rest.append(e)
    system.refresh()
    if not at_rest:
        return
    J = system.jac(q)
    redundant = assembly.rank(J) < J.shape[0]
    if redundant:
        _pull_determined(system, q, v)
    verdict = _slide_together(system, q, v, at_rest) if redundant else None
    if verdict == "slides":
        at_rest = [e for e in at_rest if e.mode == "stick"]
        J = system.jac(q)
    if assembly.rank(J) < J.shape[0] and not at_rest:      # every rough contact slides: the normal rows are
        _refuse_redundant(system, q)                        # the dependent ones
    if at_rest and assembly.rank(J) < J.shape[0] and verdict != "slides":
        for e in at_rest:                   # points of one body held on one line: one row holds them
            if e.mode == "stick":
                motion.join_held(system, e, q)
        at_rest = [e for e in at_rest if e.mode == "stick"]
        J = system.jac(q)
    if at_rest and assembly.rank(J) < J.shape[0]:
        names = [e.name for e in at_rest]
        held = " they stay at rest (the friction within μ_s N can hold them), but" if verdict == "held" else ""
        raise InputError(f"the friction at {', '.join(names)}:{held} how it is shared is not determined by the equations "
                         "of motion (statically indeterminate: the rows that hold the contacts at rest are redundant); "
                         "make one contact smooth, or give the friction as a force", at_rest[0].path)
    while at_rest:
        v0 = system.project_velocity(q, v, 0.0)
        _, lam, _ = system.solve(q, v0, 0.0)
        worst, ratio = None, 0.0
        for e in at_rest:
            lm = system.lam_of(lam, system.elements.index(e))
            if not e.held(lm):
                limit, F = e.grip(lm)
                r = abs(F) / max(limit, 1e-300)
                if worst is None or r > ratio:
                    worst, ratio, sign = e, r, -math.copysign(1.0, F)
        if worst is None:
            return
        worst.mode, worst.sign = "slide", sign
        at_rest.remove(worst)
        system.refresh()


def _pull_determined(system, q, v) -> None:
    """With the held rows redundant (their multipliers not unique), a contact whose N is still
    determined (no dependent combination of the rows involves its normal row: the null space of
    Jᵀ is zero there) and would pull (N < 0 in the least-norm multipliers) is refused as any
    contact that would pull at t = 0 (:func:`_refuse_at_start`), not as indeterminate friction."""
    n = system.n
    J = system.jac(q)
    f, _ = system.applied(q, v, 0.0)
    b = np.concatenate([f, system.gamma(q, v, 0.0)])
    K = system.kkt_matrix(q, J)
    if not (np.all(np.isfinite(K)) and np.all(np.isfinite(b))):     # (LAPACK would print to stdout)
        raise np.linalg.LinAlgError("the joints' equations are not finite at t = 0")
    lam = np.linalg.lstsq(K, b, rcond=None)[0][n:]
    _, sv, Vt = np.linalg.svd(J.T)
    r = int(np.sum(sv > 1e-10 * max(float(sv[0]), 1e-300))) if sv.size else 0
    null = Vt[r:]
    scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
    for i, e in enumerate(system.elements):
        if not isinstance(e, Contact) or e.mode == "off":
            continue
        o = system.offsets[i]
        if float(lam[o]) < -1e-9 * scale and not np.any(np.abs(null[:, o]) > 1e-9):
            _refuse_pull(system, e, float(lam[o]), q)


def _slide_together(system, q, v, at_rest) -> str | None:
    """Rough contacts at rest whose held rows are dependent (blocks tied by a string on a rough
    floor): which friction each would take is not determined, but whether they can be held at
    all is.  Their group (the contacts whose held row takes part in the dependence) slides when
    even the static limit μ_s N at every one, against the way each point goes without friction,
    leaves each going that way: no friction within the limits then holds them (between none and
    all of it the points' accelerations only shrink).  Returns "slides" (the group left sliding,
    with kinetic friction), "held" (nothing pushes them, or the limit stops or turns every one:
    they stay at rest) or None (undecided: the contacts left as they were)."""
    def deficiency() -> int:
        J = system.jac(q)
        return J.shape[0] - assembly.rank(J)

    d0 = deficiency()
    group = []
    for e in at_rest:
        e.mode, e.sign = "slide", 0.0
        system.refresh()
        if deficiency() < d0:
            group.append(e)
        e.mode = "stick"
        system.refresh()
    if not group or any(getattr(e.surface, "curved", False) for e in group):
        return None                                 # (a curve's slip rate has its own terms)

    def tangential(sign_of) -> list[float]:
        for e in group:
            e.mode, e.sign = "slide", sign_of(e)
        system.refresh()
        a, _, _ = system.solve(q, v, 0.0)
        return [e.slip_rate(q, v, a) for e in group]

    kept = [(e.mu_k, e.mode, e.sign) for e in group]
    free = tangential(lambda e: 0.0)                # the way each point goes without friction
    scale = max(map(abs, free), default=0.0)
    signs = {id(e): math.copysign(1.0, f) for e, f in zip(group, free)}
    verdict: str | None = "held" if not scale > 0 else None
    if scale > 0 and all(abs(f) > 1e-9 * scale for f in free):
        for e in group:
            e.mu_k = e.mu_s                         # the static limit, against the way it goes
        held = tangential(lambda e: signs[id(e)])
        goes = [math.copysign(1.0, h) == signs[id(e)] and abs(h) > 1e-9 * scale for e, h in zip(group, held)]
        verdict = "slides" if all(goes) else "held" if not any(goes) else None
    for e, (mu_k, mode, sign) in zip(group, kept):
        e.mu_k = mu_k
        e.mode, e.sign = ("slide", signs[id(e)]) if verdict == "slides" else (mode, sign)
    system.refresh()
    return verdict


def _refuse_at_start(system, q, v) -> None:
    """A one-sided joint on its wrong side at t = 0: refused.  A force is told from 0 at 64 ε of
    the multipliers; a gap or an end's margin at 1e-12 of the scene's size (a point placed on a
    curve by its own formula is 4e-33 m off it: on it, not through it)."""
    _, lam, _ = system.solve(q, v, 0.0)
    forces = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
    lengths = 1e-12 * assembly.length_scale(q, system)
    for i, e in enumerate(system.elements):
        lm = system.lam_of(lam, i)
        for what, g in e.watch(lm, q, v, 0.0):
            if g >= -(lengths if what in ("impact", "leaves") else 64 * EPS * forces):
                continue
            if what == "separates":
                _refuse_pull(system, e, g, q)
            if what == "impact" and hasattr(e, "refuse_gap"):        # a corner's or another body's rim
                raise InputError(e.refuse_gap(q, ""), e.path)
            if what == "leaves" and hasattr(e, "refuse_outside"):     # a corner's faces
                raise InputError(e.refuse_outside(q), e.path)
            if what == "leaves" and getattr(e.surface, "curved", False):
                raise InputError(f"at t = 0 the contact point is beyond an end of the curve {e.surface.name!r} (q_range "
                                 f"{list(e.surface.q_range)}): place it on the curve or widen q_range", e.path)
            if what == "leaves":
                raise InputError(f"at t = 0 the contact point is {-g:.6g} m beyond an end of the surface "
                                 f"{e.surface.name!r} (length {e.surface.length:g} m from its `through` point): "
                                 "place it on the surface or lengthen it", e.path)
            if what == "impact":
                who = f"the point {e.P.label}" if hasattr(e, "P") else f"the rim of {e.body_point.body.name!r}"
                normal = ("its normal (to the left of increasing q)" if getattr(e.surface, "curved", False)
                          else "the surface's normal n = e3 × d̂")
                raise InputError(f"at t = 0 {who} is {-g:.6g} m on the wrong side of the surface "
                                 f"{e.surface.name!r} it may not cross: place it on the side of {normal} (or reverse "
                                 "the surface's direction)", e.path)


def _pushes_at_rest(system, e, q) -> bool:
    """Whether the contact ``e`` would push (N ≥ 0) were the scene at rest at q: its pull at t = 0
    is then the velocities' (a point launched over a dome's top faster than √(g R))."""
    try:
        _, lam, _ = system.solve(q, np.zeros(system.n), 0.0)
    except (NumericalError, np.linalg.LinAlgError):     # (a singular rest state: no hint)
        return False
    return float(system.lam_of(lam, system.elements.index(e))[0]) >= 0


def _refuse_pull(system, e, N: float, q) -> None:
    """A contact (or rolling body) that would have to pull at t = 0: refused, with the surface's
    normal (a body on the wrong side) and, when another joint holds the body too, the way to
    let it lift off there (a crate pushed past tipping: that corner a `stop`)."""
    if hasattr(e, "refuse_pull"):       # a corner, or another body's rim: their own words
        raise InputError(e.refuse_pull(q, N), e.path)
    on = e.P.label if isinstance(e, Contact) else e.body_point.label
    n = [0.0 if abs(c) < 1e-12 else float(c) for c in (e.normal(q) if hasattr(e, "normal") else e.surface.n)]
    side = "increasing q" if getattr(e.surface, "curved", False) else "its direction d̂"
    body = e.P.body if isinstance(e, Contact) else e.body_point.body
    others = [o.name for o in system.elements if o is not e and o.rows and body is not None
              and any(x != 0 for row in o.jac_list(q) for x in (row[i] for i in body.index))]
    lift = (f"; if {on} lifts off there (held by {', '.join(others)}: a crate tipping about its other edge), "
            f"make '{e.name}' a stop (stop: [{on}, {e.surface.name}], e: 0): it starts open and is made where "
            f"{on} strikes" if others and isinstance(e, Contact) else "")
    if not lift and isinstance(e, Contact) and _pushes_at_rest(system, e, q):
        lift = (f"; {on} is launched faster than the surface's bend lets it follow (at rest it would push): to let "
                f"it fly off there, make '{e.name}' a stop (stop: [{on}, {e.surface.name}], e: 0): it starts open "
                f"and is made where {on} strikes")
    raise InputError(f"at t = 0 the surface {e.surface.name!r} would have to pull {on}: N = {N:.6g} N; it pushes "
                     f"along its normal n = [{n[0]:.4g}, {n[1]:.4g}] (to the left of {side}): if {on} rests on the "
                     f"other side, reverse the surface's direction; else release it from a position where it pushes, "
                     f"or join them with a two-sided joint{lift}", e.path)
