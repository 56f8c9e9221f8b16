"""From a scene's plain description to its system: bodies, points, joints as rows, loads.

The input arrives here as :class:`Plan` — plain numbers, names and callables made by the
solver from the validated model — never the model itself.  Every name is resolved with a
did-you-mean; every refusal names the field.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from dyncli.errors import InputError
from dyncli.expr import did_you_mean

from . import contacts
from . import elements as el
from .dynamics import Load, SceneSystem
from .system import BodyData, BodyPoint, Point, SurfaceData, perp

if TYPE_CHECKING:
    from .corner import CornerData
    from .curved import CurveData

SHAPE_I = {"rod": lambda b: b["mass"] * b["length"] ** 2 / 12, "disk": lambda b: b["mass"] * b["radius"] ** 2 / 2,
           "ring": lambda b: b["mass"] * b["radius"] ** 2, "cylinder": lambda b: b["mass"] * b["radius"] ** 2 / 2,
           "sphere": lambda b: 2 * b["mass"] * b["radius"] ** 2 / 5, "shell": lambda b: 2 * b["mass"] * b["radius"] ** 2 / 3,
           "box": lambda b: b["mass"] * (b["size"][0] ** 2 + b["size"][1] ** 2) / 12}


@dataclass
class Plan:
    """A scene as plain data (dicts of floats, strings and callables of t)."""

    bodies: dict[str, dict]
    surfaces: dict[str, dict]
    joints: dict[str, dict]
    loads: list[dict]
    g: float


@dataclass
class Built:
    system: SceneSystem
    q: np.ndarray                  # the sketch (given coordinates, defaults for the rest)
    free: np.ndarray               # True where the file left the coordinate out
    v: np.ndarray
    bodies: dict[str, BodyData]
    cords: list[tuple[str, dict]] = field(default_factory=list)   # placed after a first assembly
    surfaces: dict[str, SurfaceData | CurveData | CornerData] = field(default_factory=dict)


def bodies_of(plan: Plan) -> tuple:
    out: dict[str, BodyData] = {}
    q: list[float] = []
    free: list[bool] = []
    v: list[float] = []
    names: list[str] = []
    vgiven: list[bool] = []
    for name, b in plan.bodies.items():
        rigid = b["shape"] != "point"
        I = b["I"] if b["I"] is not None else (SHAPE_I[b["shape"]](b) if rigid else None)
        k = len(q)
        idx = (k, k + 1, k + 2) if rigid else (k, k + 1)
        pts = {"center": (0.0, 0.0)}
        if b["shape"] == "rod":
            pts["end1"], pts["end2"] = (-b["length"] / 2, 0.0), (b["length"] / 2, 0.0)
        pts.update(b["points"])
        out[name] = BodyData(name, b["mass"], I, idx, pts, b["shape"], b["length"] or 0.0, b["radius"] or 0.0,
                             tuple(b["size"] or (0.0, 0.0)))
        x = b["x"]
        q += list(x) if x is not None else [0.0, 0.0]
        free += [x is None] * 2
        v += list(b["v"]) if b["v"] is not None else [0.0, 0.0]
        vgiven += [b["v"] is not None] * 2
        names += [f"x.{name}.0", f"x.{name}.1"]
        if rigid:
            q.append(b["angle"] if b["angle"] is not None else 0.0)
            free.append(b["angle"] is None)
            v.append(b["omega"] or 0.0)
            vgiven.append(b["omega"] is not None)
            names.append(f"angle.{name}")
    return out, np.array(q, float), np.array(free, bool), np.array(v, float), names, np.array(vgiven, bool)


def surface_of(name: str, s: dict, bodies: dict[str, BodyData], q: np.ndarray) -> SurfaceData | CurveData | CornerData:
    """A fixed line or curve, or a line carried by a body (``body``: placed by the body's sketch)."""
    if s.get("body") is not None:
        path = f"surfaces.{name}.body"
        if s["body"] not in bodies:
            raise InputError(f"unknown body {s['body']!r}{did_you_mean(s['body'], bodies)}; bodies: {', '.join(bodies)}",
                             path)
        if s.get("curve") is not None:
            from .carried_curve import CarriedCurve

            x1, x2 = s["curve"]
            return CarriedCurve(name, x1, x2, s.get("q_range"), bodies[s["body"]], q)
        from .carried import carried_line

        return carried_line(name, s, bodies[s["body"]], q)
    if s.get("corner") is not None:
        from .corner import CornerData

        return CornerData(name, s["corner"], s.get("normals"))
    if s.get("curve") is not None:
        from .curved import CurveData

        x1, x2 = s["curve"]
        return CurveData(name, x1, x2, s.get("q_range"))
    d = np.array(s["direction"], float)
    d = d / math.hypot(d[0], d[1])
    return SurfaceData(name, tuple(s["through"]), (float(d[0]), float(d[1])), (float(-d[1]), float(d[0])),
                       s.get("length"))


class Resolver:
    def __init__(self, bodies: dict[str, BodyData], surfaces: dict[str, SurfaceData | CurveData | CornerData]):
        self.bodies, self.surfaces = bodies, surfaces

    def body(self, name, path) -> BodyData:
        if not isinstance(name, str) or name not in self.bodies:
            hint = did_you_mean(name, self.bodies) if isinstance(name, str) else ""
            raise InputError(f"unknown body {name!r}{hint}; bodies: {', '.join(self.bodies)}", path)
        return self.bodies[name]

    def surface(self, name, path) -> SurfaceData | CurveData | CornerData:
        if not isinstance(name, str) or name not in self.surfaces:
            hint = did_you_mean(name, self.surfaces) if isinstance(name, str) else ""
            known = ", ".join(self.surfaces) or "none: add a `surfaces:` entry"
            raise InputError(f"unknown surface {name!r}{hint}; surfaces: {known}", path)
        return self.surfaces[name]

    def line(self, name, path, what: str) -> SurfaceData:
        """A straight surface, fixed or carried by a body (``what`` runs along lines only: a curve
        is refused)."""
        s = self.surface(name, path)
        if getattr(s, "corner", False):
            raise InputError(f"{what} runs along a straight surface; {name!r} is a corner (a point: the rim of a round "
                             "body rolls on it or strikes it, rolls or stop)", path)
        if not isinstance(s, SurfaceData):
            raise InputError(f"{what} runs along a straight surface; {name!r} is a curve", path)
        return s

    def pair(self, refs, path, q) -> tuple[Point, Point]:
        """Two points; `ground` alone is the ground point where the other one is at t = 0."""
        if refs[0] == "ground" and refs[1] == "ground":
            raise InputError("join a body to the ground, not the ground to itself", path)
        if refs[1] == "ground":
            P = self.point(refs[0], path + ".0")
            return P, Point("ground", None, P.xy(q))
        if refs[0] == "ground":
            Q = self.point(refs[1], path + ".1")
            return Point("ground", None, Q.xy(q)), Q
        return self.point(refs[0], path + ".0"), self.point(refs[1], path + ".1")

    def point(self, ref, path) -> Point:
        if isinstance(ref, (list, tuple)):
            if len(ref) != 2:
                raise InputError(f"a ground point is [x1, x2], got {len(ref)} numbers", path)
            return Point(f"[{ref[0]:g}, {ref[1]:g}]", None, (float(ref[0]), float(ref[1])))
        if not isinstance(ref, str):
            raise InputError("a point is BODY, BODY.POINT or [x1, x2] on the ground", path)
        bname, _, pname = ref.partition(".")
        if bname == "ground":
            raise InputError("a ground point is written [x1, x2] (`ground` alone only as the second point of a pin, "
                             "link, spring or damper: the ground where the first point is)", path)
        b = self.body(bname, path)
        if not pname:
            return Point(ref, b, (0.0, 0.0))
        if pname not in b.points:
            raise InputError(f"body {bname!r} has no point {pname!r}{did_you_mean(pname, b.points)}; its points: "
                             f"{', '.join(b.points)}", path)
        if not b.rigid and pname != "center":
            raise InputError(f"{bname!r} is a point body: it has no point {pname!r}", path)
        return Point(ref, b, b.points[pname])


def _rigid(b: BodyData, what: str, path: str) -> None:
    if not b.rigid:
        raise InputError(f"{what} needs a rigid body; {b.name!r} is a point", path)


def joint_elements(plan: Plan, R: Resolver, q: np.ndarray, n: int) -> tuple[list, list]:
    """Every joint but the cords (placed after a first assembly) as elements; the cords as
    (name, spec) to build later."""
    out: list[el.Element] = []
    cords: list[tuple[str, dict]] = []
    for name, j in plan.joints.items():
        kind, path = j["kind"], f"joints.{name}.{j['kind']}"
        a = j[kind]
        if kind in ("contact", "stop") and _rims(name, j, R, q, n, out):
            continue
        if kind in ("contact", "rolls") and _on_curve(name, j, R, q, n, out):
            continue
        if kind == "pin":
            P, Q = R.pair(a, path, q)
            out.append(el.Pin(name, kind, n, path, P=P, Q=Q))
        elif kind == "link":
            P, Q = R.pair(a, path, q)
            L = j["length"]
            if L is None:
                d = P.pos(q) - Q.pos(q)
                L = math.hypot(d[0], d[1])
                if L == 0:
                    raise InputError("the link's ends coincide in the sketch: give its length", f"joints.{name}.length")
            out.append(el.Link(name, kind, n, path, P=P, Q=Q, L=L))
        elif kind == "slider":
            b = R.body(a[0], path + ".0")
            sf = R.surface(a[1], path + ".1")
            if getattr(sf, "curved", False) and not getattr(sf, "corner", False):
                out.append(_curve_slider(name, j, R, b, path, n, q))
                continue
            s = R.line(a[1], path + ".1", "a slider")
            if any(j.get(k) for k in ("mu", "mu_s", "mu_k")):
                out.append(_rough_slider(name, j, R, b, s, path, n))
                continue
            if getattr(s, "carried", False):
                out.append(_carried_slider(name, kind, n, path, b, s, q))
                continue
            P = BodyPoint(b.name, b, (0.0, 0.0))
            c0 = float(np.array(s.n) @ P.pos(q))
            th0 = float(q[b.index[2]]) if b.rigid else None
            out.append(el.Slider(name, kind, n, path, body_point=P, surface=s, c0=c0, theta0=th0))
        elif kind == "stop" and (_rim_stop(name, j, R, path, n, q, out) or _curve_stop(name, j, R, path, n, q, out)):
            continue
        elif kind in ("contact", "stop"):
            out.append(_contact(name, kind, j, R, path, n))
        elif kind == "rolls":
            b = R.body(a[0], path + ".0")
            _rigid(b, "rolling", path + ".0")
            if b.radius <= 0:
                raise InputError(f"{b.name!r} rolls, so it needs a radius (a disk or a ring)", path + ".0")
            s = R.line(a[1], path + ".1", "rolling")
            centre = BodyPoint(b.name, b, (0.0, 0.0))
            if getattr(s, "carried", False):
                out.append(_carried_rolls(name, kind, n, path, centre, s, j, q))
                continue
            out.append(contacts.Rolls(name, kind, n, path, body_point=centre, surface=s, R=b.radius,
                                      c0=_roll_const(s, b, q), mu_s=j["mu_s"],
                                      mu_k=j["mu_k"] if j.get("mu_k") is not None else j["mu_s"],
                                      e=float(j.get("e") or 0.0)))
        elif kind == "drive":
            bname, _, coord = a.partition(".")
            b = R.body(bname, path)
            choices = {"x1": 0, "x2": 1, "angle": 2}
            if coord not in choices:
                raise InputError(f"drive a body's coordinate: {bname}.angle, {bname}.x1 or {bname}.x2 (got {a!r})"
                                 f"{did_you_mean(coord, choices)}", path)
            if coord == "angle":
                _rigid(b, "an angle drive", path)
            out.append(el.Drive(name, kind, n, path, index=b.index[choices[coord]], f=j["value"],
                               f_many=j.get("values")))
        elif kind == "cord":
            cords.append((name, j))
        elif kind == "gear":
            out.append(_gear(name, j, R, path, n, q, plan))
    return out, cords


def _rack(name: str, j: dict, R: Resolver, path: str, n: int, q: np.ndarray, plan: Plan) -> el.Element:
    """A gear on a rack: ``gear: [GEAR, SURFACE]``, the surface the rack's pitch line (fixed, or
    carried by the rack's body): elements.Rack or carried.CarriedRack."""
    A = R.body(j["gear"][0], path + ".0")
    _rigid(A, "a gear", path + ".0")
    if plan.bodies[A.name].get("x") is None:
        raise InputError(f"give the centre of the gear {A.name!r} (x: [x1, x2]): gears mesh where they are drawn",
                         f"bodies.{A.name}.x")
    radii = j.get("radii")
    if radii is not None and len(radii) != 1:
        raise InputError(f"a gear on a rack has one pitch radius: radii: [R], got {len(radii)} numbers",
                         f"joints.{name}.radii")
    if j.get("internal"):
        raise InputError("a rack is straight: internal applies to a ring gear", f"joints.{name}.internal")
    s = R.line(j["gear"][1], path + ".1", "a rack")
    if getattr(s, "body", None) is A:
        raise InputError(f"{A.name!r} carries {s.name!r}: a gear cannot mesh with its own rack", path + ".0")
    Rp = float(radii[0]) if radii else A.radius
    if not Rp > 0:
        raise InputError(f"give the pitch radius, radii: [R] ({A.name!r} has no radius)", f"joints.{name}.radii")
    centre = BodyPoint(A.name, A, (0.0, 0.0))
    e: el.Element
    if getattr(s, "carried", False):
        from .carried import CarriedLine, CarriedRack

        assert isinstance(s, CarriedLine), "a carried surface is a CarriedLine"
        carried = CarriedRack(name, "gear", n, path, P=centre, surface=s, R=Rp)
        gap = carried.gap(q) - Rp
        carried.c0 = carried.roll_const(q)
        e = carried
    else:
        fixed = el.Rack(name, "gear", n, path, body=A, d=(float(s.d[0]), float(s.d[1])), R=Rp)
        gap = float(np.array(s.n) @ (centre.pos(q) - np.array(s.origin))) - Rp
        fixed.c0 = fixed.roll_const(q)
        e = fixed
    if abs(gap) > 1e-9 * max(Rp, abs(gap + Rp)):
        raise InputError(f"the gear {A.name!r} does not mesh with the rack: its centre is {gap + Rp:.6g} m from the pitch "
                         f"line {s.name!r} (on the side of its normal), its pitch radius {Rp:.6g} m", path)
    return e


def _gear(name: str, j: dict, R: Resolver, path: str, n: int, q: np.ndarray, plan: Plan) -> el.Element:
    """Two gears in mesh (elements.Gear): their pitch radii (given, or the bodies' radius), the
    centres' distance at t = 0 checked against R_A ± R_B."""
    if j["gear"][1] in R.surfaces and j["gear"][1] not in R.bodies:
        return _rack(name, j, R, path, n, q, plan)
    A, B = (R.body(j["gear"][k], f"{path}.{k}") for k in (0, 1))
    for k, body in enumerate((A, B)):
        _rigid(body, "a gear", f"{path}.{k}")
        if plan.bodies[body.name].get("x") is None:
            raise InputError(f"give the centre of the gear {body.name!r} (x: [x1, x2]): gears mesh where they are drawn",
                             f"bodies.{body.name}.x")
    radii = j.get("radii")
    if radii is not None and len(radii) != 2:
        raise InputError(f"expected the two pitch radii [R_A, R_B], got {len(radii)} numbers", f"joints.{name}.radii")
    if radii is None:
        missing = [body.name for body in (A, B) if not body.radius > 0]
        if missing:
            raise InputError(f"give the pitch radii, radii: [R_A, R_B] ({', '.join(repr(m) for m in missing)} has no "
                             "radius)", f"joints.{name}.radii")
        radii = [A.radius, B.radius]
    RA, RB = float(radii[0]), float(radii[1])
    s = -1.0 if j.get("internal") else 1.0
    D = RA + s * RB
    if not D > 0:
        raise InputError(f"an internal gear is the larger: R_A = {RA:g} m must exceed R_B = {RB:g} m (A is the ring "
                         "gear, B meshes inside it)", f"joints.{name}.radii" if j.get("radii") else path)
    a, b = A.index, B.index
    d1, d2 = float(q[b[0]] - q[a[0]]), float(q[b[1]] - q[a[1]])
    gap = math.hypot(d1, d2) - D
    if abs(gap) > 1e-9 * max(D, math.hypot(d1, d2)):
        raise InputError(f"the gears do not mesh: their centres are {math.hypot(d1, d2):.6g} m apart, and "
                         f"R_A {'−' if s < 0 else '+'} R_B = {D:.6g} m: place the centres so that the pitch circles "
                         "touch", path)
    e = el.Gear(name, "gear", n, path, A=A, B=B, RA=RA, RB=RB, s=s, D=D)
    e.c0 = e.angle_sum(q) - D * math.atan2(d2, d1)
    return e


def _carried_slider(name: str, kind: str, n: int, path: str, b: BodyData, s, q: np.ndarray):
    """A slider on a line carried by another body (carried.py): its offset from the line and
    (a rigid body) its angle to the carrier kept from t = 0."""
    from .carried import CarriedSlider

    if b is s.body:
        raise InputError(f"{b.name!r} carries {s.name!r}: a body cannot slide on its own surface", path + ".0")
    P = BodyPoint(b.name, b, (0.0, 0.0))
    e = CarriedSlider(name, kind, n, path, P=P, surface=s)
    e.c0 = e.gap(q)
    if b.rigid:
        e.dtheta = float(q[b.index[2]]) - (float(q[s.body.index[2]]) if s.body.rigid else 0.0)
    return e


def _carried_rolls(name: str, kind: str, n: int, path: str, centre: BodyPoint, s, j: dict, q: np.ndarray):
    """A disk rolling on a line carried by another body (carried.py)."""
    from .carried import CarriedRolls

    b = centre.body
    if b is s.body:
        raise InputError(f"{b.name!r} carries {s.name!r}: a body cannot roll on its own surface", path + ".0")
    e = CarriedRolls(name, kind, n, path, body_point=centre, surface=s, R=b.radius, mu_s=j["mu_s"],
                     mu_k=j["mu_k"] if j.get("mu_k") is not None else j["mu_s"], e=float(j.get("e") or 0.0))
    e.c0 = e.roll_const(q)
    return e


def _rim_stop(name: str, j: dict, R: Resolver, path: str, n: int, q: np.ndarray, out: list) -> bool:
    """A stop of a disk or ring body named alone: its rim strikes the surface (a ball, a wheel, a
    spinning disk dropped onto a floor) — a rolling joint that starts off the surface, made at the
    impact (with e: 0 it stays on: it rolls, or slips with kinetic friction mu; smooth without mu).
    Appended to ``out`` (True), or False for any other stop (a point's)."""
    a = j["stop"]
    if not (isinstance(a[0], str) and "." not in a[0] and a[0] in R.bodies):
        return False
    b = R.bodies[a[0]]
    if not (b.rigid and b.radius > 0):
        return False
    corner = R.surface(a[1], path + ".1")
    if getattr(corner, "corner", False):
        from .corner import CornerData, corner_rolls

        assert isinstance(corner, CornerData)
        out.append(corner_rolls(name, "rolls", n, path, BodyPoint(b.name, b, (0.0, 0.0)), corner, b.radius, j, q,
                                mode="off", mu=float(j["mu"] or 0.0)))
        return True
    s = R.line(a[1], path + ".1", "a disk's stop")
    if getattr(s, "carried", False) or not isinstance(s, SurfaceData):
        raise InputError(f"a disk's stop is on a fixed straight surface; {s.name!r} is carried by a body or curved: "
                         "give the disk's rim point as the stop (stop: [DISK.POINT, SURFACE])", path + ".1")
    mu = float(j["mu"] or 0.0)
    out.append(contacts.Rolls(name, "rolls", n, path, body_point=BodyPoint(b.name, b, (0.0, 0.0)), surface=s,
                              R=b.radius, c0=_roll_const(s, b, q), mu_s=mu, mu_k=mu, e=float(j.get("e") or 0.0),
                              mode="off"))
    return True


def _roll_const(s: SurfaceData, b: BodyData, q: np.ndarray) -> float:
    """d̂·x̄ + R θ of a disk on the straight surface s (kept while it rolls, 15.8)."""
    i = b.index
    return float(np.array(s.d) @ q[[i[0], i[1]]]) + b.radius * float(q[i[2]])


def _contact(name: str, kind: str, j: dict, R: Resolver, path: str, n: int):
    """A contact (or a stop: made only at an impact) of a point on a straight surface, with its
    friction coefficients (mu for both, or mu_s / mu_k; one given stands for the other)."""
    a = j[kind]
    P = R.point(a[0], path + ".0")
    s = R.line(a[1], path + ".1", "a contact")
    mu_s, mu_k = _friction_of(j)
    mode = "off" if kind == "stop" else "slide" if (mu_s or mu_k) else "smooth"
    if getattr(s, "carried", False):        # (carried.py loaded only for a scene that has one)
        from .carried import CarriedContact, CarriedLine

        assert isinstance(s, CarriedLine)
        if P.body is s.body:
            raise InputError(f"{P.label!r} is on {s.body.name!r}, which carries {s.name!r}: a body cannot touch its "
                             "own surface", path + ".0")
        return CarriedContact(name, kind, n, path, P=P, surface=s, mu_s=mu_s, mu_k=mu_k, mode=mode, sign=0.0,
                              e=float(j.get("e") or 0.0), stop=kind == "stop")
    return contacts.Contact(name, kind, n, path, P=P, surface=s, mu_s=mu_s, mu_k=mu_k, mode=mode, sign=0.0,
                            e=float(j.get("e") or 0.0), stop=kind == "stop")


def _curve_stop(name: str, j: dict, R: Resolver, path: str, n: int, q: np.ndarray, out: list) -> bool:
    """A stop of a point on a curve, fixed or carried (a ball dropped into a bowl): the curve's
    contact, open at t = 0 and made where the point strikes (with e: 0 it stays on: a contact
    from then on), appended to ``out`` (True); False for a stop on anything else."""
    a = j["stop"]
    s = R.surface(a[1], path + ".1")
    if not getattr(s, "curved", False) or getattr(s, "corner", False):
        return False
    e = _curve_module(s).contact_on(name, "stop", n, path, R.point(a[0], path + ".0"), s, j, q)
    e.mode, e.stop = "off", True
    out.append(e)
    return True


def _friction_of(j: dict) -> tuple[float, float]:
    """(μ_s, μ_k) of a joint: mu for both, or mu_s / mu_k (one given stands for the other)."""
    mu_s = j["mu"] if j["mu"] is not None else (j.get("mu_s") or 0.0)
    mu_k = j["mu"] if j["mu"] is not None else (j["mu_k"] if j.get("mu_k") is not None else mu_s)
    if j.get("mu_k") is not None and j.get("mu_s") is None:
        mu_s = mu_k
    return mu_s, mu_k


def _rough_slider(name: str, j: dict, R: Resolver, b: BodyData, s, path: str, n: int):
    """A rough guide of a point body (a collar threaded on a rough rod, fixed or carried by a body
    that moves it): two-sided, the friction μ_k |N| against the slip while it slides, held while
    |F| ≤ μ_s |N| — a contact that cannot leave its line (contacts.py, ``two_sided``).  A rigid
    body's rough guide is refused: where its friction acts depends on how the guide holds its
    angle (two points, each a contact)."""
    if b.rigid:
        raise InputError(f"a rough slider is for a point body (a collar threaded on a rod); {b.name!r} is rigid, and "
                         "where a guide's friction acts on it depends on how the guide holds its angle: write a "
                         "contact with mu at each point where the guide touches it, or make the slider smooth",
                         path + ".0")
    mu_s, mu_k = _friction_of(j)
    P = BodyPoint(b.name, b, (0.0, 0.0))
    if getattr(s, "carried", False):        # a collar on a rough rod that another body turns
        from .carried import CarriedContact

        if b is s.body:
            raise InputError(f"{b.name!r} carries {s.name!r}: a body cannot slide on its own surface", path + ".0")
        return CarriedContact(name, "contact", n, path, P=P, surface=s, mu_s=mu_s, mu_k=mu_k, mode="slide", sign=0.0,
                              two_sided=True)
    return contacts.Contact(name, "contact", n, path, P=P, surface=s, mu_s=mu_s, mu_k=mu_k, mode="slide", sign=0.0,
                            two_sided=True)


def _curve_slider(name: str, j: dict, R: Resolver, b: BodyData, path: str, n: int, q: np.ndarray):
    """A point body threaded on a curve, fixed or carried (a collar on a curved rod): the curve's
    contact held both ways (N signed, ``two_sided``: it never lets go; it runs off at an end of
    q_range), smooth, or rough with μ_k |N| against the slip while it slides."""
    if b.rigid:
        raise InputError(f"a slider on a curve is for a point body (a collar threaded on a curved rod); {b.name!r} "
                         "is rigid: write a contact (or rolls) at each point where the curve touches it", path + ".0")
    s = R.surface(j["slider"][1], path + ".1")
    spec = {"mu": j.get("mu"), "mu_s": j.get("mu_s"), "mu_k": j.get("mu_k"), "e": 0.0, "at": j.get("at")}
    e = _curve_module(s).contact_on(name, "contact", n, path, BodyPoint(b.name, b, (0.0, 0.0)), s, spec, q)
    e.two_sided = True
    return e


def _on_curve(name: str, j: dict, R: Resolver, q: np.ndarray, n: int, out: list) -> bool:
    """A contact or rolling joint on a curved surface (dyncli/topics/scene/curved.py) appended
    to ``out`` (True), or False on a straight one (where `at` of a contact is refused)."""
    kind = j["kind"]
    path = f"joints.{name}.{kind}"
    s = R.surface(j[kind][1], path + ".1")
    if getattr(s, "corner", False):
        return _on_corner(name, j, R, s, q, n, out)
    if isinstance(s, SurfaceData):
        if kind == "contact" and j["at"] is not None:
            raise InputError("`at` places a contact on a curved surface (the curve's q); on a straight one give "
                             "the point's position", f"joints.{name}.at")
        return False
    from . import curved

    assert isinstance(s, curved.CurveData), "a surface is a line, a corner or a curve"
    if kind == "contact":
        out.append(_curve_module(s).contact_on(name, kind, n, path, R.point(j[kind][0], path + ".0"), s, j, q))
        return True
    b = R.body(j[kind][0], path + ".0")
    _rigid(b, "rolling", path + ".0")
    if b.radius <= 0:
        raise InputError(f"{b.name!r} rolls, so it needs a radius (a disk or a ring)", path + ".0")
    out.append(_curve_module(s).rolls_on(name, kind, n, path, BodyPoint(b.name, b, (0.0, 0.0)), s, b.radius, j, q))
    return True


def _curve_module(s):
    """The module whose ``contact_on`` and ``rolls_on`` make the joints on the curve ``s``:
    curved.py for a fixed curve, carried_curve.py for one carried by a body (loaded only then)."""
    if getattr(s, "carried", False):
        from . import carried_curve

        return carried_curve
    from . import curved

    return curved


def _rims(name: str, j: dict, R: Resolver, q: np.ndarray, n: int, out: list) -> bool:
    """``stop: [A, B]`` or ``contact: [A, B]`` with two bodies (not a surface) second: their rims
    touch (rims.py; a point body has radius 0), appended to ``out`` (True); else False."""
    kind = j["kind"]
    a = j[kind]
    other = a[1] if isinstance(a, (list, tuple)) and len(a) == 2 else None
    if not (isinstance(other, str) and other in R.bodies and other not in R.surfaces):
        return False
    path = f"joints.{name}.{kind}"
    if not (isinstance(a[0], str) and "." not in a[0]):
        raise InputError(f"a {kind} between two bodies names both bodies ([A, B], their rims touch); a point on a "
                         f"body's side is a {kind} with a surface the body carries ({{body: {other}, through, "
                         "direction}})", path + ".0")
    A, B = R.body(a[0], path + ".0"), R.body(other, path + ".1")
    if A is B:
        raise InputError(f"a body cannot touch itself: name two bodies, {kind}: [A, B]", path)
    for k, b in enumerate((A, B)):
        if b.rigid and not b.radius > 0:
            raise InputError(f"{b.name!r} has no radius: two bodies touch rim to rim (balls, disks, rings, or a point "
                             f"mass); a {b.shape}'s side is a surface it carries ({{body: {b.name}, through, "
                             f"direction}}) for a {kind} of the other's point", f"{path}.{k}")
    if not A.rigid and not B.rigid:
        raise InputError("two point masses have no rims to touch: give one a round shape (sphere, disk) and its "
                         "radius", path)
    from .rims import PairSurface, RimContact

    mu_s, mu_k = _friction_of(j)

    RA, RB = (A.radius if A.rigid else 0.0), (B.radius if B.rigid else 0.0)
    d0 = math.hypot(float(q[B.index[0]] - q[A.index[0]]), float(q[B.index[1]] - q[A.index[1]]))
    # inside a ring: as given (internal), else the other's centre within its radius at t = 0 (a marble
    # in a hoop; a point on the ring itself is outside unless internal: true)
    ring = B.shape == "ring" or A.shape == "ring"
    if j.get("internal") and not ring:
        raise InputError(f"internal: true is for a body inside a ring; neither {A.name!r} nor {B.name!r} is a ring "
                         "(shape: ring)", f"joints.{name}.internal")
    inside = bool(j["internal"]) if j.get("internal") is not None else \
        (B.shape == "ring" and d0 < RB) or (A.shape == "ring" and d0 < RA)
    if inside and not abs(RA - RB) > 0:
        raise InputError(f"{A.name!r} and {B.name!r} have the same radius: one cannot move inside the other", path)
    out.append(RimContact(name, kind, n, path, P=BodyPoint(A.name, A, (0.0, 0.0)), surface=PairSurface(B.name),
                          A=A, B=B, RA=RA, RB=RB, inside=inside, mu_s=mu_s, mu_k=mu_k,
                          mode="off" if kind == "stop" else "slide" if (mu_s or mu_k) else "smooth",
                          e=float(j.get("e") or 0.0), stop=kind == "stop"))
    return True


def _on_corner(name: str, j: dict, R: Resolver, s, q: np.ndarray, n: int, out: list) -> bool:
    """A round body's rim rolling on a corner (corner.py); a point's contact with a corner is
    refused (a point on a point: write the corner as the contact point and the body's side as
    a surface it carries)."""
    kind = j["kind"]
    path = f"joints.{name}.{kind}"
    if j.get("at") is not None:
        raise InputError("`at` places a joint along a line or a curve; on a corner the body touches the corner "
                         "itself: give its centre x", f"joints.{name}.at")
    if kind == "contact":
        raise InputError(f"a point cannot rest on the corner {s.name!r} (a point on a point): a round body's rim "
                         f"rolls on it (rolls: [BODY, {s.name}]); for a flat side leaning on the corner, make the "
                         "corner the contact point and the side a surface carried by the body (contact: "
                         "[[x1, x2], SIDE] with SIDE: {body: BODY, through, direction})", path + ".1")
    b = R.body(j[kind][0], path + ".0")
    _rigid(b, "rolling", path + ".0")
    if b.radius <= 0:
        raise InputError(f"{b.name!r} rolls, so it needs a radius (a disk or a ring)", path + ".0")
    from .corner import corner_rolls

    out.append(corner_rolls(name, kind, n, path, BodyPoint(b.name, b, (0.0, 0.0)), s, b.radius, j, q))
    return True


def loads_of(plan: Plan, R: Resolver, q: np.ndarray) -> list[Load]:
    out = []
    named: dict[str, int] = {}
    for i, f in enumerate(plan.loads):
        kind, path = f["kind"], f"forces.{i}.{f['kind']}"
        if f.get("name") is not None:   # each load's result force.NAME: two of one name would be one
            if f["name"] in named:
                raise InputError(f"two loads are named {f['name']!r} (forces.{named[f['name']]} and this one): each "
                                 "load's force is reported under its name, so give them different names",
                                 f"forces.{i}.name")
            named[f["name"]] = i
        if kind in ("spring", "damper"):
            P, Q = R.pair(f[kind], path, q)
            d = P.pos(q) - Q.pos(q)
            if d[0] == 0 and d[1] == 0:
                raise InputError(f"the {kind}'s ends coincide at t = 0, so its direction is undefined: attach it "
                                 "between two distinct points", path)
            out.append(Load(kind, f["name"], P=P, Q=Q, k=f["k"] or 0.0, L=f["L"] or 0.0, one_sided=f["one_sided"],
                            c=f["c"] or 0.0))
        elif kind == "force" and isinstance(f["force"], dict):      # through a string wound on a body
            w = f["force"]
            b = R.body(w["wound"], path + ".wound")
            _rigid(b, "a force through a wound string", path + ".wound")
            r = w.get("radius") or b.radius
            if not r:
                raise InputError(f"give the radius the string unwinds from ({w['wound']!r} has none)", path + ".radius")
            out.append(Load(kind, f["name"], P=Point(w["wound"], b, (0.0, 0.0)), F=f["F"], constant=f["constant"],
                            wound=(float(r) if w["side"] == "left" else -float(r))))
        elif kind == "force":
            out.append(Load(kind, f["name"], P=R.point(f["force"], path), F=f["F"], constant=f["constant"]))
        else:
            b = R.body(f["torque"], path)
            _rigid(b, "a couple", path)
            out.append(Load(kind, f["name"], body=b, M=f["M"], constant=f["constant"]))
    return out


# ---------------------------------------------------------------------------- cords

def _cord_nodes(path: str, items: list, R: Resolver) -> list[tuple]:
    """The cord's entries resolved: (kind, data, field path), kind point, disk, pulley, wound."""
    nodes: list[tuple[str, Any, str]] = []
    for i, it in enumerate(items):
        p = f"{path}.{i}"
        end = i in (0, len(items) - 1)
        if isinstance(it, dict):
            if "pulley" in it:
                if end:
                    raise InputError("a cord ends at a point or a wound body, not at a pulley", p)
                c = it["pulley"]
                nodes.append(("pulley", (np.array(c, float), float(it.get("radius") or 0.0)), p))
            elif "peg" in it:
                if end:
                    raise InputError("a cord ends at a point or a wound body, not at a peg", p)
                nodes.append(("peg", (np.array(it["peg"], float), float(it.get("radius") or 0.0)), p))
            elif "wound" in it:
                if not end:
                    raise InputError("a wound body is an end of the cord (first or last)", p)
                b = R.body(it["wound"], p + ".wound")
                _rigid(b, "a wound cord", p + ".wound")
                r = it.get("radius") or b.radius
                if not r:
                    raise InputError(f"give the radius the cord unwinds from ({it['wound']!r} has none)", p + ".radius")
                nodes.append(("wound", (b, float(r), it.get("side")), p))
            else:
                raise InputError("a cord entry is a point, a body, {pulley: [x1, x2], radius: r}, {peg: [x1, x2]} or "
                                 "{wound: BODY, radius: r}", p)
        elif not end and isinstance(it, str) and "." not in it and it in R.bodies and R.bodies[it].rigid:
            b = R.bodies[it]
            if b.radius <= 0:
                raise InputError(f"the cord passes over {it!r}, which has no radius (a disk or ring)", p)
            nodes.append(("disk", b, p))
        else:
            if not end:
                raise InputError("the cord's inner entries are pulleys: a disk body or {pulley: [x1, x2], radius: r}", p)
            nodes.append(("point", R.point(it, p), p))
    return nodes


def cord_element(name: str, spec: dict, R: Resolver, q: np.ndarray, n: int) -> tuple[el.Cord, list[el.Guide]]:
    """A cord with the directions of its segments at the assembled positions of t = 0 (one
    between two points over no pulley: a :class:`~.elements.String`, its length exact)."""
    path = f"joints.{name}.cord"
    nodes = _cord_nodes(path, spec["cord"], R)
    if any(nd[0] == "peg" for nd in nodes):
        return _pegged_string(name, path, nodes, q, n), []
    centres = [_centre(nd, q) for nd in nodes]
    rho = _sides(nodes, centres)
    runs, run, guides = [], [], []
    for i in range(len(nodes) - 1):
        tg = el.segment_tangents(centres[i], rho[i], centres[i + 1], rho[i + 1])
        if tg is None:
            raise InputError(f"the cord's segment {i + 1} has no straight part (its ends overlap)", path)
        u, Ta, Tb = tg
        seg = el.Segment(_end(nodes[i], Ta, centres[i], u), _end(nodes[i + 1], Tb, centres[i + 1], u), u,
                         centres=(centres[i], rho[i], centres[i + 1], rho[i + 1]))
        ends = (nodes[i][0], nodes[i + 1][0])
        if ends in (("point", "pulley"), ("point", "disk")) and nodes[i][1].body is not None:
            seg.pulley = ("a", centres[i + 1], rho[i + 1], nodes[i + 1][1] if ends[1] == "disk" else None)
        elif ends in (("pulley", "point"), ("disk", "point")) and nodes[i + 1][1].body is not None:
            seg.pulley = ("b", centres[i], rho[i], nodes[i][1] if ends[0] == "disk" else None)
        run.append(seg)
        for nd in (nodes[i], nodes[i + 1]):
            guided = None
            if nd[0] == "point" and nd[1].body is not None and not nd[1].body.rigid:
                guided = nd[1]                  # a hanging mass moves along its segment
            elif nd[0] == "wound":
                guided = Point(nd[1][0].name, nd[1][0], (0.0, 0.0))   # a yo-yo's centre likewise
            if guided is not None:
                w = perp(u)
                guides.append(el.Guide(f"{name}:guide", "guide", len(q), path, P=guided, w=w,
                                       c0=float(w @ guided.pos(q)), segment=seg))
        if nodes[i + 1][0] == "disk":
            runs.append(run)
            run = []
    runs.append(run)
    if len(nodes) == 2 and all(nd[0] == "point" for nd in nodes):
        # a string between two points: its own length, not its direction of t = 0 (no guide)
        string = el.String(name, "cord", len(q), path, runs=runs)
        string.consts = list(string.lengths(q))
        return string, []
    cord = el.Cord(name, "cord", len(q), path, runs=runs)
    for seg in (sg for r in runs for sg in r):
        # a rigid body's point over a fixed pulley: no guide holds it, its segment turns with it
        if seg.pulley is None or seg.pulley[3] is not None:
            continue                    # (over a disk body: once its axle is known fixed, prepare.py)
        P = (seg.a if seg.pulley[0] == "a" else seg.b).point
        if P is not None and P.body is not None and P.body.rigid:
            cord.let_turn(seg, q)
    cord.consts = list(cord.lengths(q))
    return cord, guides


def _pegged_string(name: str, path: str, nodes: list, q: np.ndarray, n: int) -> el.PeggedString:
    """A string between a fixed point and a body point that catches the pegs listed between them
    (elements.PeggedString): it starts straight between its ends."""
    inner = nodes[1:-1]
    if not all(nd[0] == "peg" for nd in inner) or not all(nd[0] == "point" for nd in (nodes[0], nodes[-1])):
        raise InputError("pegs are caught by a string between two points: [POINT, {peg: [x1, x2]}..., POINT], "
                         "without pulleys or wound ends", path)
    ends = [nodes[0], nodes[-1]]
    if ends[0][1].body is not None:
        ends.reverse()                          # the string hangs from its fixed end
    if ends[0][1].body is not None or ends[1][1].body is None:
        raise InputError("a string over pegs runs from a fixed point (a ground point [x1, x2]) to a point of a body: "
                         + ("here both ends move (a cord over a smooth peg between two moving bodies is a cord over a "
                            "point pulley: {pulley: [x1, x2]})" if ends[0][1].body is not None else "here neither end moves"),
                         path)
    A, B = ends[0][1].pos(q), ends[1][1].pos(q)
    d = B - A
    if not math.hypot(*d) > 0:
        raise InputError("the string's ends coincide at t = 0", path)
    pegs, radii = [], []
    for nd in inner:
        p, rho = nd[1]
        w = p - A
        cross, proj = float(d[0] * w[1] - d[1] * w[0]), float(d @ w) / float(d @ d)
        if abs(cross) <= 1e-12 * float(d @ d) + rho * math.hypot(*d) and 0 <= proj <= 1:
            raise InputError(f"the peg {'touches' if rho else 'lies on'} the string at t = 0: place it off the string's "
                             "line (a string already bent over it is a cord over {pulley: [x1, x2], radius: r})", nd[2])
        for end, which in ((A, "fixed end"), (B, "body's end")):
            if rho and math.hypot(*(end - p)) <= rho:
                raise InputError(f"the string's {which} is inside the round peg at t = 0: tie it outside the peg "
                                 "(its distance from the centre more than the radius)", nd[2])
        pegs.append(Point(f"peg {p[0]:g}, {p[1]:g}", None, (float(p[0]), float(p[1]))))
        radii.append(rho)
    u = d / math.hypot(*d)
    seg = el.Segment(el.CordEnd(point=ends[0][1]), el.CordEnd(point=ends[1][1]), u)
    string = el.PeggedString(name, "cord", len(q), path, runs=[[seg]], pegs=pegs, radii=radii)
    string.consts = list(string.lengths(q))
    string.start_sides(q)
    return string


def _sides(nodes, centres) -> list[float]:
    """Signed radii: a pulley is passed on the side away from the line of its neighbours; a
    wound end on the side its `side` names (or the drawing's)."""
    rho = [0.0] * len(nodes)
    for i in range(1, len(nodes) - 1):
        r = nodes[i][1][1] if nodes[i][0] == "pulley" else nodes[i][1].radius
        a, b, c = centres[i - 1], centres[i + 1], centres[i]
        side = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        rho[i] = r if side >= 0 else -r
    for i in (0, len(nodes) - 1):
        if nodes[i][0] == "wound":
            rho[i] = _wound_side(nodes, centres, rho, i)
    return rho


def _centre(nd, q):
    kind, data, _ = nd
    if kind == "point":
        return data.pos(q)
    if kind == "pulley":
        return data[0]
    b = data if kind == "disk" else data[0]
    i = b.index
    return np.array([q[i[0]], q[i[1]]])


def _wound_side(nodes, centres, rho, i):
    b, r, side = nodes[i][1]
    j = 1 if i == 0 else len(nodes) - 2
    if side in ("left", "right"):
        sgn = 1.0 if side == "left" else -1.0
        return sgn * r if i == 0 else -sgn * r
    best = None
    for s in (r, -r):       # the textbook drawing: the free segment the more nearly vertical or horizontal
        args = (centres[i], s, centres[j], rho[j]) if i == 0 else (centres[j], rho[j], centres[i], s)
        tg = el.segment_tangents(*args)
        if tg is None:
            continue
        u = tg[0]
        score = min(abs(u[0]), abs(u[1]))
        if best is None or score < best[0] - 1e-12:
            best = (score, s)
    return best[1] if best else r


def _end(nd, T, C, u) -> el.CordEnd:
    kind, data, _ = nd
    if kind == "point":
        return el.CordEnd(point=data)
    if kind == "pulley":
        return el.CordEnd(fixed=T)
    b = data if kind == "disk" else data[0]
    k = float(u @ perp(T - C))
    return el.CordEnd(centre=BodyPoint(b.name, b, (0.0, 0.0)), k=k)
