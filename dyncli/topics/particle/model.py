"""Input model of ``particle`` problems (docs/types/particle.md, notes §16, §18-§22).

``forces`` is a list of force terms, a pydantic discriminated union on
``kind``.  The solver (``solver.py``) builds the equation of motion
m a = sum of the listed forces (16.7) and integrates it.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal, Optional, Union

from pydantic import BeforeValidator, Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import ExprTriple, ExprVec3, Find, Num, ProblemBase, StrictModel, Times, Vec3, Vector, check_times
from dyncli.springs import one_sided_length

CUSTOM_VARS = ("t", "x1", "x2", "x3", "v1", "v2", "v3")


class Uniform(StrictModel):
    """A constant force F (a constant force field, 19.14)."""

    kind: Literal["uniform"]
    F: Annotated[Vector, Vec3(dim="force", description="the constant force [N]")]


class Gravity(StrictModel):
    """Gravity near the earth, -m g e3 (potential m g x3, 19.23)."""

    kind: Literal["gravity"]


class InverseSquare(StrictModel):
    """Inverse-square gravity towards ``center``: F_R = -m g (R0/R)² (19.18),
    potential -m g R0²/R (19.20b)."""

    kind: Literal["inverse-square"]
    center: Annotated[Vector, Vec3(dim="length", description="the attracting centre [m]")] = (0.0, 0.0, 0.0)
    R0: Annotated[float, Num(gt=0, dim="length", description="radius where the attraction is m g [m]")]
    g: Optional[Annotated[float, Num(gt=0, dim="acceleration", description="attraction per unit mass at R = R0 [m/s²]; default: the problem's g")]] = None


class Spring(StrictModel):
    """Linear spring from a fixed ``anchor``: F_R = -k (R - L) (19.26a)."""

    kind: Literal["spring"]
    anchor: Annotated[Vector, Vec3(dim="length", description="fixed end of the spring [m]")] = (0.0, 0.0, 0.0)
    k: Annotated[float, Num(gt=0, dim="stiffness", description="stiffness [N/m]")]
    L: Annotated[float, Num(ge=0, dim="length", description="free length [m]")] = 0.0
    one_sided: Optional[Literal["compression", "tension"]] = Field(
        None, description="compression: only pushes (acts while R < L: a block dropped onto it); tension: only "
                          "pulls (R > L: an elastic cord); default two-sided")

    @model_validator(mode="after")
    def _one_sided_needs_length(self):
        one_sided_length(self.one_sided, self.L)
        return self


class Damper(StrictModel):
    """Linear viscous damper to the fixed frame: F = -c v."""

    kind: Literal["damper"]
    c: Annotated[float, Num(ge=0, dim="damping", description="damping coefficient [N·s/m]")]


def _power(value: Any) -> Any:
    if isinstance(value, bool) or value not in (1, 2, 1.0, 2.0):
        raise ValueError(f"power must be 1 (linear drag) or 2 (quadratic drag), got {value!r}")
    return int(value)


class Drag(StrictModel):
    """Fluid drag opposing the velocity: F = -c |v|^(power-1) v."""

    kind: Literal["drag"]
    c: Annotated[float, Num(ge=0, description="drag coefficient [N·s/m] (power 1) or [N·s²/m²] (power 2)")]
    power: Annotated[int, BeforeValidator(_power), Field(description="1 (linear) or 2 (quadratic)")] = 2


class Friction(StrictModel):
    """Coulomb (sliding) friction with a given normal force: F = -mu N v/|v| (19.27);
    the particle sticks when it stops and |other forces| <= mu N."""

    kind: Literal["friction"]
    mu: Annotated[float, Num(ge=0, description="friction coefficient (kinetic = static)")]
    N: Annotated[float, Num(ge=0, dim="force", description="magnitude of the normal force [N]")]


class Custom(StrictModel):
    """Any force given as 3 expressions in t, x1, x2, x3, v1, v2, v3."""

    kind: Literal["custom"]
    F: Annotated[ExprTriple, ExprVec3(CUSTOM_VARS, dim="force", description="3 expressions in t, x1, x2, x3, v1, v2, v3 [N]")]
    name: Optional[str] = Field(None, description="label used in messages")


FORCE_KINDS = ("uniform", "gravity", "inverse-square", "spring", "damper", "drag", "friction", "custom")


def check_force_kind(value: Any) -> Any:
    """The check of a force entry before its ``kind`` picks the model: a mapping with a known
    ``kind`` (one of FORCE_KINDS, with a did-you-mean for a misspelling) or an already-built
    force; the one clear message otherwise.  Shared by every type whose forces come from this
    library (``constrained-particle`` adds its own rule before calling it)."""
    if isinstance(value, dict):
        kind = value.get("kind")
        if kind is None:
            raise ValueError(f"a force needs 'kind', one of: {', '.join(FORCE_KINDS)}")
        if kind not in FORCE_KINDS:
            from dyncli.expr import did_you_mean

            raise ValueError(f"unknown force kind {kind!r}{did_you_mean(str(kind), FORCE_KINDS)}; "
                             f"one of: {', '.join(FORCE_KINDS)}")
    elif not hasattr(value, "kind"):
        raise ValueError(f"a force is a mapping with 'kind' (one of: {', '.join(FORCE_KINDS)})")
    return value


Force = Annotated[
    Annotated[Union[Uniform, Gravity, InverseSquare, Spring, Damper, Drag, Friction, Custom], Field(discriminator="kind")],
    BeforeValidator(check_force_kind),
]


class SteadyAxis(StrictModel):
    """A steady circular motion about the fixed axis through the origin along ``axis``, at x0."""

    axis: Annotated[Vector, Vec3(unit=True, description="direction of the axis through the origin (unit vector)")] = (0.0, 0.0, 1.0)


class Particle(ProblemBase):
    """A particle of mass m under the listed forces (problem II of §16)."""

    type: Literal["particle"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")]
    x0: Annotated[Vector, Vec3(dim="length", description="initial position x(0) [m]")] = (0.0, 0.0, 0.0)
    v0: Annotated[Vector, Vec3(dim="velocity", description="initial velocity v(0) [m/s]")] = (0.0, 0.0, 0.0)
    forces: list[Force] = Field(default_factory=list, description="force terms; none = a free particle")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the integration [s]; default max(at)")]] = None
    at: Annotated[list[float], Times(description="times at which to report the state [s]; default [0, t_end]")] = Field(default_factory=list)
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {x.1: 0}}, {max: x.1}, {min: v.0}")
    basis: Literal["cartesian", "cylindrical"] = Field(
        "cartesian", description="cylindrical: also report x, v, a, F, H_O on {e_r, e_θ, e3} and the drift of r²θ̇, ẋ3, H_O (§22)")

    accuracy_methods = ("auto", "exact", "ode", "DOP853", "RK45", "Radau", "LSODA")

    steady: list[SteadyAxis] = Field(
        default_factory=list, max_length=100,
        description="steady circular motions at x0 solved for their rate: [{axis: [0, 0, 1]}] (the forces must be "
                    "centripetal there: a circular orbit, a puck on a spring)")

    @property
    def steady_only(self) -> bool:
        """Only steady queries: no motion to solve (no at, t_end or find)."""
        return bool(self.steady) and not self.at and self.t_end is None and not self.find

    @model_validator(mode="after")
    def _check(self):
        if not self.steady_only:
            check_times(self)
        for i, f in enumerate(self.forces):
            if isinstance(f, InverseSquare) and math.dist(f.center, self.x0) == 0:
                raise InputError("x0 is at the centre of the inverse-square field (R = 0, infinite force): "
                                 "start the particle elsewhere", f"forces.{i}.center")
            if isinstance(f, Spring) and f.L > 0 and math.dist(f.anchor, self.x0) == 0:
                raise InputError("x0 is at the spring's anchor while L > 0: the spring force has no direction; "
                                 "start the particle off the anchor", f"forces.{i}.anchor")
        return self
