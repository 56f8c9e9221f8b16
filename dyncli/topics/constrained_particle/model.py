"""Input model of ``constrained-particle`` problems (notes §16 problem II, §18).

A bead on a wire or a particle in a slot: the curve y(q) is given by three
expressions in its parameter ``q`` on the frame of the curve; the curve is
fixed, or turns about a fixed axis through the origin at the rate ω(t)
(``rotation``).  Forces come from the ``particle`` library; ``friction``
takes only μ here — the normal force is computed.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal, Optional, Union

from pydantic import BeforeValidator, Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import Expr, ExprField, Find, Num, ProblemBase, StrictModel, Times, Vec3, Vector, check_times
from dyncli.topics.particle.model import Custom, Damper, Drag, Gravity, InverseSquare, Spring, Uniform
from dyncli.topics.particle.model import check_force_kind

CURVE_VARS = ("q",)


class CurveFriction(StrictModel):
    """Coulomb friction of the wire: −μ|N| v_rel/|v_rel| with the computed
    normal force N; the bead sticks (relative to the wire) when it stops
    and the other tangential force is at most μ|N|."""

    kind: Literal["friction"]
    mu: Annotated[float, Num(ge=0, description="friction coefficient (kinetic = static)")]


def _check_kind(value: Any) -> Any:
    """particle's checks of a force entry, and no N for friction here."""
    if isinstance(value, dict) and value.get("kind") == "friction" and "N" in value:
        raise ValueError("friction on a curve takes only mu: the normal force N is computed")
    return check_force_kind(value)


Force = Annotated[
    Annotated[Union[Uniform, Gravity, InverseSquare, Spring, Damper, Drag, CurveFriction, Custom],
              Field(discriminator="kind")],
    BeforeValidator(_check_kind),
]


class Curve(StrictModel):
    """The curve y(q) = x1(q) e1 + x2(q) e2 + x3(q) e3 on the frame of the curve."""

    x1: Annotated[Expr, ExprField(CURVE_VARS, dim="length", description="x1(q) [m]: number or expression in q")]
    x2: Annotated[Expr, ExprField(CURVE_VARS, dim="length", description="x2(q) [m]: number or expression in q")]
    x3: Annotated[Expr, ExprField(CURVE_VARS, dim="length", description="x3(q) [m]: number or expression in q")]


class Rotation(StrictModel):
    """The curve turns about the fixed axis through the origin along ``axis``
    at the rate ω(t) (right-handed about ``axis``)."""

    axis: Annotated[Vector, Vec3(unit=True, description="direction of the fixed axis (unit vector)")] = (0.0, 0.0, 1.0)
    omega: Optional[Annotated[Expr, ExprField(("t",), dim="angular_velocity", description="rate ω [rad/s]: number or expression in t; "
                                                                          "required unless the problem asks only steady queries")]] = None


class SteadyQuery(StrictModel):
    """A steady motion: the particle at rest relative to the curve at q, carried round the axis at the
    constant rate ω that holds it there (with friction: the range of rates)."""

    q: Annotated[float, Num(description="the parameter q where the particle stays")]


class ConstrainedParticle(ProblemBase):
    """A particle of mass m that must stay on a curve (one degree of freedom q)."""

    type: Literal["constrained-particle"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")]
    curve: Curve = Field(description="the curve {x1, x2, x3}: expressions in the parameter q [m]")
    q_range: Optional[list[Annotated[float, Num()]]] = Field(
        None, description="[q_min, q_max]: the ends of the wire (a closed curve when y(q_min) = y(q_max)); "
                          "needed for the relative equilibria (left out on a curve periodic in q: one period)")
    rotation: Optional[Rotation] = Field(None, description="{axis, omega}: the curve turns about a fixed axis; none = fixed")
    q0: Annotated[float, Num(description="initial parameter q(0)")] = 0.0
    q_dot0: Annotated[float, Num(description="initial rate dq/dt at t = 0 [1/s] (relative to the curve)")] = 0.0
    forces: list[Force] = Field(default_factory=list, description="force terms (as for particle; friction: only mu)")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion [s]; default max(at)")]] = None
    at: Annotated[list[float], Times(description="times at which to report the state [s]; default [0, t_end]")] = Field(default_factory=list)
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {q: VALUE}}, {max: x.1}, {min: N.1}")
    steady: list[SteadyQuery] = Field(
        default_factory=list, max_length=1000,
        description="steady motions solved for the rate that holds them: [{q: Q}, ...] on a curve turning about "
                    "rotation.axis (the bead on a turning hoop, the conical pendulum, the banked curve)")

    accuracy_methods = ("auto", "quadrature", "ode", "DOP853", "RK45", "Radau", "LSODA")

    @model_validator(mode="after")
    def _check(self):
        if self.steady_only:
            if self.rotation is None:
                raise InputError("steady motions need the axis the curve turns about: add rotation: {axis: [0, 0, 1]} "
                                 "(the rate ω is what steady finds)", "steady")
        else:
            if self.rotation is not None and self.rotation.omega is None:
                raise InputError("give the rate ω of the turning curve (a number or an expression in t); only a "
                                 "problem that asks steady queries alone (no at, t_end or find) may leave it out",
                                 "rotation.omega")
            check_times(self)
        if self.q_range is not None:
            if len(self.q_range) != 2 or not self.q_range[0] < self.q_range[1]:
                got = ", ".join(f"{v:g}" for v in self.q_range)
                raise InputError(f"q_range must be [q_min, q_max] with q_min < q_max, got [{got}]", "q_range")
            if not all(math.isfinite(v) for v in self.q_range):
                raise InputError("q_range must be finite: give the two ends of the wire as numbers", "q_range")
            if not self.steady_only and not self.q_range[0] <= self.q0 <= self.q_range[1]:
                raise InputError(f"q0 = {self.q0:g} is outside q_range [{self.q_range[0]:g}, {self.q_range[1]:g}]: "
                                 "start on the wire, or widen q_range", "q0")
        return self

    @property
    def steady_only(self) -> bool:
        """Only steady queries: no motion to solve (no at, t_end or find)."""
        return bool(self.steady) and not self.at and self.t_end is None and not self.find
