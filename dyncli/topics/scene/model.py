"""Input model of ``scene`` problems: a planar mechanism as a student draws it (docs/types/scene.md).

Surfaces (fixed straight lines), bodies (points and the ``inertia`` type's planar shapes),
joints (each a block of constraint rows whose multipliers are its forces), forces, the times to
report and the ``find`` queries.  Only the shapes of the entries are checked here; names,
geometry and mechanics (assembly, degrees of freedom, one-sided joints) are checked by the
solver, which reports each refusal at the field it concerns.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, ClassVar, Literal, Optional, Union

from pydantic import Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import Expr, ExprField, Num, ProblemBase, StrictModel, Times, check_times

TIME = ("t",)
#: the largest starting angle of a body [rad] (~160,000 turns; a double holds it to ~1e-10 rad)
MAX_ANGLE = 1e6


def _at(base: str, field: str | None) -> str:
    """The full path of a field inside one entry (``joints.motor`` + ``value``)."""
    return f"{base}.{field}" if field else base

#: a point: "BODY", "BODY.POINT", or [x1, x2] on the ground
PointRef = Union[str, list[Annotated[float, Num(dim="length")]]]


class SurfaceCurve(StrictModel):
    """A curved surface r(q) = x1(q) e1 + x2(q) e2 (the constrained-particle curve language, in the plane)."""

    x1: Annotated[Expr, ExprField(("q",), dim="length", description="x1(q) [m]: number or expression in q")]
    x2: Annotated[Expr, ExprField(("q",), dim="length", description="x2(q) [m]: number or expression in q")]


class Surface(StrictModel):
    """A fixed straight line through ``through`` along ``direction``, or a fixed ``curve``;
    bodies are on its left (the side of n = e3 × d̂, d̂ the direction or the curve's tangent
    in the sense of increasing q).  A line or curve given a ``body`` moves with that body (carried.py,
    carried_curve.py)."""

    through: Optional[list[Annotated[float, Num(dim="length")]]] = Field(None, description="[x1, x2]: a point of the line [m]")
    direction: Optional[list[Annotated[float, Num()]]] = Field(None, description="[d1, d2]: its direction (bodies on the left)")
    length: Optional[Annotated[float, Num(gt=0, dim="length", description="where it ends: `length` m from `through` along the direction (default: no end); a contact, slider or rolling body reaching an end leaves the surface (the event `leaves`; one started at an end, moving off it, leaves at once)")]] = None
    curve: Optional[SurfaceCurve] = Field(None, description="a curved surface {x1, x2}: expressions in the parameter q [m] "
                                          "(instead of through and direction); bodies on the left of increasing q")
    q_range: Optional[list[Annotated[float, Num()]]] = Field(None, description="curve: [q_min, q_max], its ends (default: none); a body "
                                           "reaching an end leaves the surface (an event)")
    body: Optional[str] = Field(None, description="a body that carries the line or curve (a wedge, a cart, a plank, a block "
                              "with a groove): it moves and turns with that body, given as drawn at t = 0")
    corner: Optional[list[Annotated[float, Num(dim="length")]]] = Field(
        None, description="[x1, x2]: a corner (instead of a line or a curve): the edge of a curb or a step, the top of a "
                          "post, a peg [m]; the rim of a round body rolls on it or strikes it (rolls, stop)")
    normals: Optional[list[list[Annotated[float, Num()]]]] = Field(
        None, description="corner: the outward normals [[a1, a2], [b1, b2]] of its two faces; it touches a rim only while "
                          "the direction from the corner to the centre lies between them (the event `leaves` where it "
                          "reaches one); default: from any side")

    def check(self, base: str) -> None:
        if self.corner is not None:
            self._check_corner(base)
            return
        if self.normals is not None:
            raise InputError("normals go with a corner (corner: [x1, x2]): the outward normals of its two faces",
                             _at(base, "normals"))
        if self.curve is not None:
            for name in ("through", "direction", "length"):
                if getattr(self, name) is not None:
                    raise InputError(f"a curved surface takes no {name}" + (" (give q_range for its ends)" if name == "length"
                                                                             else ": its points are the curve's"),
                                     _at(base, name))
            if self.q_range is not None and (len(self.q_range) != 2 or not self.q_range[0] < self.q_range[1]):
                raise InputError("q_range must be [q_min, q_max] with q_min < q_max", _at(base, "q_range"))
            return
        if self.q_range is not None:
            raise InputError("q_range goes with a curve (a straight surface ends at `length`)", _at(base, "q_range"))
        for name, example in (("through", "[0, 0]"), ("direction", "[1, 0]")):
            if getattr(self, name) is None:
                raise InputError(f"a straight surface needs {name}, e.g. {name}: {example} (or give a curve: {{x1, x2}} "
                                 "in q)", _at(base, name))
        through, direction = self.through or [], self.direction or []      # both given (just checked)
        if len(through) != 2:
            raise InputError(f"expected [x1, x2], got {len(through)} numbers", _at(base, "through"))
        if len(direction) != 2:
            raise InputError(f"expected [d1, d2], got {len(direction)} numbers", _at(base, "direction"))
        if direction[0] == 0 and direction[1] == 0:
            raise InputError("the direction must be non-zero, e.g. [1, 0] for a floor", _at(base, "direction"))


    def _check_corner(self, base: str) -> None:
        for name in ("through", "direction", "length", "curve", "q_range", "body"):
            if getattr(self, name) is not None:
                raise InputError(f"a corner takes no {name}: it is one fixed point, corner: [x1, x2]"
                                 + (" (a corner on a moving body is not modelled in this release)" if name == "body"
                                    else ""), _at(base, name))
        if len(self.corner or []) != 2:
            raise InputError(f"expected [x1, x2], got {len(self.corner or [])} numbers", _at(base, "corner"))
        if self.normals is None:
            return
        if len(self.normals) != 2 or any(len(u) != 2 for u in self.normals):
            raise InputError("expected the two faces' outward normals [[a1, a2], [b1, b2]]", _at(base, "normals"))
        (a1, a2), (b1, b2) = self.normals
        if a1 == a2 == 0 or b1 == b2 == 0:
            raise InputError("a face's normal must be non-zero, e.g. [-1, 0] for the riser of a curb met from the left",
                             _at(base, "normals"))
        la, lb = math.hypot(a1, a2), math.hypot(b1, b2)
        if abs(a1 * b2 - a2 * b1) <= 1e-9 * la * lb:
            raise InputError("the two faces' normals are parallel: a corner's faces meet at an angle (a curb: "
                             "[[-1, 0], [0, 1]]); a flat surface is a line (through, direction)", _at(base, "normals"))


#: the round shapes: a disk's section in the plane, rolling on its rim of radius R
ROUND = ("disk", "ring", "sphere", "shell", "cylinder")
SHAPES = ("point", "rod", "disk", "ring", "box", "sphere", "shell", "cylinder")


class Body(StrictModel):
    """A body: a particle (``shape: point``) or a rigid body in planar motion."""

    shape: Optional[Literal["point", "rod", "disk", "ring", "box", "sphere", "shell", "cylinder"]] = Field(
        None, description="point, rod (along e'1), disk, ring, box, sphere (solid), shell (a thin spherical shell), "
                          "cylinder (solid: a disk's I); or give I instead")
    mass: Annotated[float, Num(ge=0, dim="mass", description="mass [kg]")]
    length: Optional[Annotated[float, Num(gt=0, dim="length", description="rod length [m]")]] = None
    radius: Optional[Annotated[float, Num(gt=0, dim="length", description="radius of a round body (disk, ring, sphere, shell, cylinder) [m]")]] = None
    size: Optional[list[Annotated[float, Num(gt=0, dim="length")]]] = Field(None, description="box [a, b] along e'1, e'2 [m]")
    I: Optional[Annotated[float, Num(ge=0, dim="moment_of_inertia", description="I33 about the centre [kg·m²]")]] = None
    x: Optional[list[Annotated[float, Num(dim="length")]]] = Field(None, description="[x1, x2]: centre at t = 0 (left out: placed by the joints)")
    angle: Optional[Annotated[float, Num(dim="angle", description="angle of e'1 from e1 at t = 0 [rad] (write 30*deg for degrees; left out: placed by the joints)")]] = None
    v: Optional[list[Annotated[float, Num(dim="velocity")]]] = Field(None, description="[v1, v2] of the centre at t = 0 (default rest, or what the drives and joints impose)")
    omega: Optional[Annotated[float, Num(dim="angular_velocity", description="angular velocity at t = 0 [rad/s] (default rest, or what the drives and joints impose)")]] = None
    points: dict[str, list[Annotated[float, Num(dim="length")]]] = Field(default_factory=dict, description="named points [p1, p2] on e'1, e'2 [m]")

    def check(self, base: str) -> None:
        if self.shape is None and self.I is None:
            raise InputError("give shape (point, rod, disk, ring, box, sphere, shell, cylinder) or I (the moment of "
                             "inertia about the "
                             "centre)", _at(base, "shape"))
        need = {"rod": "length", "box": "size"}.get(self.shape or "", "radius" if self.shape in ROUND else "")
        if need and getattr(self, need) is None:
            raise InputError(f"a {self.shape} needs {need}", _at(base, need))
        if self.size is not None and len(self.size) != 2:
            raise InputError("expected [a, b]", _at(base, "size"))
        for name in ("x", "v"):
            val = getattr(self, name)
            if val is not None and len(val) != 2:
                raise InputError(f"expected [{name}1, {name}2] (a planar vector), got {len(val)} numbers", _at(base, name))
        for k, p in self.points.items():
            if len(p) != 2:
                raise InputError(f"expected [p1, p2], got {len(p)} numbers", _at(base, f"points.{k}"))
        if self.angle is not None and not abs(self.angle) <= MAX_ANGLE:
            raise InputError(f"{self.angle:g} rad is held by a double only to ±{math.ulp(self.angle) / 2:g} rad: the "
                             "joints cannot be met to rounding; give the angle within a few turns (its value "
                             "modulo 2π)", _at(base, "angle"))
        if self.shape == "point":
            for name in ("length", "radius", "size", "I"):
                if getattr(self, name) is not None:
                    raise InputError(f"a point body has no {name}", _at(base, name))
            if self.points:
                raise InputError("a point body has no named points (it is one point)", _at(base, "points"))
            if self.omega is not None or self.angle is not None:
                raise InputError("a point body has no angle or angular velocity (give the body a shape to turn it)",
                                 _at(base, "omega" if self.omega is not None else "angle"))


class FixedPulley(StrictModel):
    """A light, smooth, fixed pulley the cord passes over."""

    pulley: list[Annotated[float, Num(dim="length")]] = Field(description="[x1, x2]: its centre [m]")
    radius: Annotated[float, Num(ge=0, dim="length", description="its radius [m] (default 0)")] = 0.0

    def check(self, base: str) -> None:
        if len(self.pulley) != 2:
            raise InputError(f"expected [x1, x2], got {len(self.pulley)} numbers", _at(base, "pulley"))


class Peg(StrictModel):
    """A fixed smooth peg (a point, or a round post of ``radius``) that a string between two
    points catches when its line sweeps onto it, and leaves when it swings back straight (a
    pendulum's string caught by a nail; a string that winds onto a post)."""

    peg: list[Annotated[float, Num(dim="length")]] = Field(description="[x1, x2]: the peg (its centre) [m]")
    radius: Annotated[float, Num(ge=0, dim="length", description="its radius [m] (default 0: a point; > 0: a round "
                                 "post the string winds onto)")] = 0.0

    def check(self, base: str) -> None:
        if len(self.peg) != 2:
            raise InputError(f"expected [x1, x2], got {len(self.peg)} numbers", _at(base, "peg"))


class Wound(StrictModel):
    """A cord end wound on a body: it unwinds at ``radius`` without slipping (a yo-yo, a spool)."""

    wound: str = Field(description="the body the cord is wound on")
    radius: Optional[Annotated[float, Num(gt=0, dim="length", description="the radius it unwinds from [m] (default the body's radius)")]] = None
    side: Optional[Literal["left", "right"]] = Field(None, description="the side of the body the cord leaves from, seen from the body looking along the cord (a force: along F) (default for a cord: the drawing's, the free segment nearest vertical or horizontal; a force needs it)")


CordEntry = Union[FixedPulley, Peg, Wound, str, list[Annotated[float, Num(dim="length")]]]


class _OneOf(StrictModel):
    """An entry that is exactly one of ``KINDS`` (a joint, a load)."""

    KINDS: ClassVar[tuple[str, ...]] = ()

    @property
    def kind(self) -> str:
        return next(k for k in self.KINDS if getattr(self, k) is not None)

    def _one(self, base: str, what: str, example: str) -> str:
        given = [k for k in self.KINDS if getattr(self, k) is not None]
        if len(given) != 1:
            raise InputError(f"{what} is exactly one of " + ", ".join(self.KINDS)
                             + (f" (got {', '.join(given)})" if given else f": add one, e.g. {example}"), base)
        return given[0]


class Joint(_OneOf):
    """One joint: exactly one of pin, slider, contact, rolls, cord, link, drive, stop, gear."""

    pin: Optional[list[PointRef]] = Field(None, description="[P, Q]: a smooth pin")
    slider: Optional[list[str]] = Field(None, description="[BODY, SURFACE]: translates along the surface")
    contact: Optional[list[PointRef]] = Field(None, description="[P, SURFACE]: one-sided contact, Coulomb friction; [A, B] with two bodies: their rims touch")
    rolls: Optional[list[str]] = Field(None, description="[BODY, SURFACE]: rolls without slipping")
    cord: Optional[list[CordEntry]] = Field(None, description="[END, PULLEY..., END]: a taut inextensible cord; [END, {peg: [x1, x2]}..., END]: a string that catches pegs (points, or round posts with a radius it winds onto)")
    link: Optional[list[PointRef]] = Field(None, description="[P, Q]: a massless rigid link")
    drive: Optional[str] = Field(None, description="BODY.angle, BODY.x1 or BODY.x2: a prescribed motion")
    stop: Optional[list[PointRef]] = Field(None, description="[P, SURFACE]: a one-sided contact made only at the instant of an impact (give e); a disk or ring named alone strikes with its rim (on a line or a corner) and then rolls or slips; [A, B] with two bodies: their rims strike")
    gear: Optional[list[str]] = Field(None, description="[A, B]: two gears in mesh, their pitch circles rolling on each other (the centres held by other joints: pins, a carrier); [A, SURFACE]: a gear on a rack, the surface its pitch line")
    radii: Optional[list[Annotated[float, Num(gt=0, dim="length")]]] = Field(None, description="gear: the pitch radii [R_A, R_B] [m] (a rack: [R]; default the bodies' radius)")
    internal: Optional[bool] = Field(None, description="gear: true when B meshes inside A's ring gear (default false: an external mesh); contact or stop between two bodies: true when one touches the other, a ring, from within (a marble in a hoop; default: from the positions at t = 0, inside when a centre is within the ring's radius)")
    e: Optional[Annotated[float, Num(ge=0, le=1, description="coefficient of restitution of an impact on the surface (stop: required; contact, rolls: default 0)")]] = None
    value: Optional[Annotated[Expr, ExprField(TIME, description="drive: the coordinate as an expression in t")]] = None
    mu: Optional[Annotated[float, Num(ge=0, description="friction coefficient (static = kinetic)")]] = None
    mu_s: Optional[Annotated[float, Num(ge=0, description="static friction coefficient")]] = None
    mu_k: Optional[Annotated[float, Num(ge=0, description="kinetic friction coefficient")]] = None
    at: Optional[Annotated[float, Num(dim="length", description="rolls: the contact point along d̂ from the surface's `through` at t = 0 [m]; on a curved surface (rolls or contact): the curve's parameter q there")]] = None
    length: Optional[Annotated[float, Num(gt=0, dim="length", description="cord or link length [m]")]] = None
    angle: Optional[Annotated[float, Num(description="link: its angle from −e2, placing Q when its position is left out [rad]")]] = None

    KINDS: ClassVar[tuple[str, ...]] = ("pin", "slider", "contact", "rolls", "cord", "link", "drive", "stop", "gear")

    def check(self, base: str) -> None:
        kind = self._one(base, "a joint", "pin: [BODY, ground]")
        allowed = {"pin": set(), "slider": {"mu", "mu_s", "mu_k"}, "contact": {"mu", "mu_s", "mu_k", "at", "e", "internal"},
                   "rolls": {"at", "mu_s", "mu_k", "e"}, "cord": {"length"}, "link": {"length", "angle"},
                   "drive": {"value"}, "stop": {"e", "mu", "internal"}, "gear": {"radii", "internal"}}[kind]
        for extra in ("value", "mu", "mu_s", "mu_k", "at", "length", "angle", "e", "radii", "internal"):
            if getattr(self, extra) is not None and extra not in allowed:
                raise InputError(f"a {kind} joint takes no {extra}", _at(base, extra))
        if kind == "drive" and self.value is None:
            raise InputError("a drive needs value: the coordinate as an expression in t, e.g. \"2*t\"", _at(base, "value"))
        if kind == "stop" and self.e is None:
            raise InputError("a stop needs e, the coefficient of restitution (0 <= e <= 1), e.g. e: 0.8", _at(base, "e"))
        if kind == "contact" and self.mu is not None and (self.mu_s is not None or self.mu_k is not None):
            raise InputError("give mu, or mu_s and mu_k, not both", _at(base, "mu"))
        two = {"pin": 2, "slider": 2, "contact": 2, "rolls": 2, "link": 2, "stop": 2, "gear": 2}.get(kind)
        if two and len(getattr(self, kind)) != 2:
            what = {"pin": "P, Q", "link": "P, Q", "gear": "A, B"}.get(kind, "BODY, SURFACE")
            raise InputError(f"a {kind} joins exactly two things: [{what}]", _at(base, kind))
        if kind == "gear" and self.radii is not None and len(self.radii) not in (1, 2):
            raise InputError(f"expected the pitch radii [R_A, R_B] (a gear on a rack: [R]), got {len(self.radii)} "
                             "numbers", _at(base, "radii"))
        if kind in ("pin", "link", "gear") and getattr(self, kind)[0] == getattr(self, kind)[1]:
            raise InputError(f"a {kind} joins two different points: both ends are {getattr(self, kind)[0]}", _at(base, kind))
        cord = self.cord or []                  # set when kind is "cord"
        if kind == "cord":
            for i, it in enumerate(cord):
                if isinstance(it, (FixedPulley, Peg)):
                    it.check(_at(base, f"cord.{i}"))
        if kind == "cord" and len(cord) < 2:
            raise InputError("a cord needs two ends: [END, PULLEY..., END]", _at(base, "cord"))


class Force(_OneOf):
    """One applied element: exactly one of spring, damper, force, torque."""

    spring: Optional[list[PointRef]] = Field(None, description="[P, Q]: a linear spring (tension positive)")
    damper: Optional[list[PointRef]] = Field(None, description="[P, Q]: a linear damper")
    force: Optional[Union[Wound, PointRef]] = Field(None, description="P: a force applied at P; or {wound: BODY, radius: r, side}: pulled by a string wound on the body, F applied where a string along F leaves the circle of radius r (its line stays tangent to it as the body turns)")
    torque: Optional[str] = Field(None, description="BODY: a couple on the body")
    k: Optional[Annotated[float, Num(ge=0, dim="stiffness", description="spring stiffness [N/m]")]] = None
    L: Optional[Annotated[float, Num(ge=0, dim="length", description="spring free length [m]")]] = None
    one_sided: Optional[Literal["compression", "tension"]] = Field(
        None, description="compression: the spring only pushes; tension: it only pulls")
    c: Optional[Annotated[float, Num(ge=0, dim="damping", description="damping coefficient [N·s/m]")]] = None
    F: Optional[list[Annotated[Expr, ExprField(TIME, dim="force")]]] = Field(None, description="[F1, F2]: expressions in t [N]")
    M: Optional[Annotated[Expr, ExprField(TIME, dim="moment", description="couple about e3 [N·m], expression in t")]] = None
    name: Optional[str] = Field(None, description="reported as force.NAME")

    KINDS: ClassVar[tuple[str, ...]] = ("spring", "damper", "force", "torque")

    def check(self, base: str) -> None:
        kind = self._one(base, "a force entry", "force: BODY")
        need = {"spring": ("k", "L"), "damper": ("c",), "force": ("F",), "torque": ("M",)}[kind]
        what = {"k": "its stiffness k [N/m], e.g. k: 200", "L": "its free length L [m], e.g. L: 0.5 (L: 0 for a spring "
                "stretched from zero length)", "c": "its damping coefficient c [N·s/m], e.g. c: 5",
                "F": "its force F: [F1, F2] [N] on e1, e2 (numbers or expressions in t)",
                "M": "its couple M [N·m] about e3 (counter-clockwise positive)"}
        for n in need:
            if getattr(self, n) is None:
                raise InputError(f"a {kind} needs {what[n]}", _at(base, n))
        for extra in ("k", "L", "one_sided", "c", "F", "M"):
            if getattr(self, extra) is not None and extra not in need and not (kind == "spring" and extra == "one_sided"):
                raise InputError(f"a {kind} takes no {extra}", _at(base, extra))
        if kind in ("spring", "damper") and len(getattr(self, kind)) != 2:
            raise InputError(f"a {kind} joins exactly two points: [P, Q]", _at(base, kind))
        if kind == "force" and len(self.F or []) != 2:
            raise InputError("expected [F1, F2] (a planar force)", _at(base, "F"))
        if kind == "force" and isinstance(self.force, Wound) and self.force.side is None:
            raise InputError(f"a force through a string wound on {self.force.wound!r} needs side: left or right (the side "
                             "the string leaves from, seen from the body looking along F)", _at(base, "force.side"))


class Scene(ProblemBase):
    """A planar mechanism: bodies, joints, forces (docs/types/scene.md)."""

    type: Literal["scene"]
    surfaces: dict[str, Surface] = Field(default_factory=dict, description="fixed straight lines (or curves) by name")
    bodies: dict[str, Body] = Field(description="bodies by name (`ground` is reserved)")
    joints: dict[str, Joint] = Field(default_factory=dict, description="joints by name")
    forces: list[Force] = Field(default_factory=list, description="springs, dampers, forces, couples")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion [s]; default max(at)")]] = None
    at: Annotated[list[float], Times(description="times at which to report the state [s]")] = Field(default_factory=list)
    find: list[Any] = Field(default_factory=list, description="queries (§11): {t: T}, {when: {RESULT: VALUE}}, {max: RESULT}, {min: RESULT}, {event: WHAT, joint: NAME, after: true}")
    motion: Optional[Any] = Field(None, description="out-of-plane motion is refused (use top, euler, gyroscope)")
    linearize: bool = Field(False, description="true: the equilibria (rest configurations) with their stability, "
                            "natural frequencies, mode shapes and the linear response (result `equilibria`)")

    accuracy_methods = ("auto", "closed-form", "quadrature", "ode", "DOP853", "RK45", "Radau", "LSODA")

    @model_validator(mode="after")
    def _check(self):
        if self.motion is not None:
            raise InputError("motion out of the plane is not a scene: use the top, euler or gyroscope types",
                             "motion")
        if "ground" in self.bodies:
            raise InputError("'ground' is reserved for the fixed frame: name the body otherwise", "bodies.ground")
        if not self.bodies:
            raise InputError("a scene needs at least one body", "bodies")
        for group, entries in (("surfaces", self.surfaces), ("bodies", self.bodies), ("joints", self.joints),
                               ("forces", dict(enumerate(self.forces)))):
            for name, entry in entries.items():
                entry.check(f"{group}.{name}")
        if self.t_end is None and not self.at:
            self.at = [0.0]
        check_times(self)
        return self
