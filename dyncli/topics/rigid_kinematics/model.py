"""Input models of ``rigid-velocity``, ``angular-velocity``, ``screw`` and
``contact`` problems (docs/types/rigid-velocity.md, docs/types/angular-velocity.md, docs/types/screw.md, docs/types/contact.md)."""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import ProblemBase, StrictModel, Vec3, Vector

ZERO = (0.0, 0.0, 0.0)


def _check_names(points: dict) -> None:
    if not points:
        raise ValueError("give at least one point: a mapping name -> ...")


#: rolling: v_B counts as parallel to the surface when |v_B·ĉ| <= ROLLING_TOL·|v_B| (and a_B as in
#: the plane of motion when |a_B·n| <= ROLLING_TOL·|a_B|): far above the rounding of components
#: given as cos/sin expressions, far below any real component toward the surface
ROLLING_TOL = 1e-9


class Rolling(StrictModel):
    """The body rolls without slip on a fixed surface, in plane motion: ω and ω̇ follow from vB, aB."""

    contact: Annotated[Vector, Vec3(nonzero=True, dim="length", description="x_C/B: the contact point C relative to B, B the centre of the rolling disk (of curvature of its rim) [m]")] = Field(...)


class Rotation(StrictModel):
    """One rotation of a chain: a frame (or the body) turning relative to the one before."""

    omega: Annotated[Vector, Vec3(dim="angular velocity", description="its angular velocity relative to the frame before (the first: relative to the fixed frame) [rad/s]")] = Field(...)
    omega_dot: Annotated[Vector, Vec3(dim="angular acceleration", description="the rate of that omega as seen in the frame before (δ/δt; the first: its absolute rate) [rad/s²]")] = ZERO


class RigidVelocity(ProblemBase):
    """Velocity and acceleration of points of a rigid body (13.8, 13.9)."""

    type: Literal["rigid-velocity"]
    vB: Annotated[Vector, Vec3(dim="velocity", description="velocity of the reference point B [m/s]")] = ZERO
    aB: Annotated[Vector, Vec3(dim="acceleration", description="acceleration of B [m/s²]")] = ZERO
    omega: Optional[Annotated[Vector, Vec3(dim="angular velocity", description="angular velocity ω of the body [rad/s] (required unless rolling)")]] = None
    alpha: Annotated[Vector, Vec3(dim="angular acceleration", description="angular acceleration ω̇ [rad/s²]")] = ZERO
    rolling: Optional[Rolling] = Field(None, description="rolling without slip on a fixed surface: omega and "
                                       "alpha from vB and aB (not with omega or alpha)")
    rotations: Optional[list[Rotation]] = Field(None, description="nested rotations, outermost first (an axle "
                                                "turning at Omega, then the disk spinning on it): omega and alpha "
                                                "of the last (not with omega, alpha or rolling)")
    points: dict[str, Annotated[Vector, Vec3(dim="length", description="x_P/B: position of the point relative to B [m]")]] = Field(
        ..., description="point name -> x_P/B (position relative to B)")

    @model_validator(mode="after")
    def _pts(self):
        _check_names(self.points)
        if self.rotations is not None:
            return self._check_rotations()
        if self.rolling is None:
            if self.omega is None:
                raise InputError("give the angular velocity omega, or rolling: {contact: x_C/B} for a body "
                                 "rolling without slip (omega then follows from vB), or rotations (nested: "
                                 "[{omega: axle}, {omega: spin relative to the axle}])", "omega")
            return self
        for name in ("omega", "alpha"):
            if name in self.model_fields_set:
                raise InputError(f"give either {name} or rolling, not both: rolling computes omega from vB "
                                 "and alpha from aB", name)
        self._check_rolling()
        return self

    def _check_rotations(self):
        for name in ("omega", "alpha", "rolling"):
            if name in self.model_fields_set:
                raise InputError(f"give either {name} or rotations, not both: rotations compose omega and alpha "
                                 "of the body from the chain", name)
        if not self.rotations:
            raise InputError("give at least one rotation: [{omega: Ω, omega_dot: Ω̇}, {omega: ω_rel, ...}], "
                             "the outermost first", "rotations")
        return self

    def _check_rolling(self) -> None:
        from dyncli.topics.rigid_kinematics import equations as eq

        assert self.rolling is not None      # called when rolling is given
        c = eq.unit(self.rolling.contact, "rolling.contact")
        vn = eq.dot(self.vB, c)
        if abs(vn) > ROLLING_TOL * eq.norm(self.vB):
            raise InputError(f"rolling on a fixed surface moves the centre B parallel to it, but vB has the "
                             f"component {vn:.6g} m/s along x_C/B: give vB tangent to the surface (vB·x_C/B = 0), "
                             "or check rolling.contact", "vB")
        w, _ = eq.rolling_rates(self.vB, self.aB, self.rolling.contact)
        if eq.norm(w) > 0:
            an = eq.dot(self.aB, eq.unit(w))
            if abs(an) > ROLLING_TOL * eq.norm(self.aB):
                raise InputError(f"aB has the component {an:.6g} m/s² out of the plane of the motion (along ω): "
                                 "rolling here is plane motion; give aB in the plane of vB and x_C/B", "aB")


class PointState(StrictModel):
    """Position and velocity of a point of the body."""

    x: Annotated[Vector, Vec3(dim="length", description="position [m]")] = Field(...)
    v: Annotated[Vector, Vec3(dim="velocity", description="velocity [m/s]")] = Field(...)


class AngularVelocity(ProblemBase):
    """Angular velocity of a rigid body from the velocities of two or three
    of its points (13.13, 13.17, 13.20)."""

    type: Literal["angular-velocity"]
    points: dict[str, PointState] = Field(..., description="point name -> {x, v}; two or three points")

    @model_validator(mode="after")
    def _pts(self):
        n = len(self.points)
        if n not in (2, 3):
            raise ValueError(f"give two points (for omega_n, 13.20) or three non-collinear points "
                             f"(for omega, 13.13/13.17); got {n}")
        return self


class Screw(ProblemBase):
    """Instantaneous screw axis of a rigid body (14.1-14.9)."""

    type: Literal["screw"]
    omega: Annotated[Vector, Vec3(dim="angular velocity", description="angular velocity ω [rad/s]")] = Field(...)
    vB: Annotated[Vector, Vec3(dim="velocity", description="velocity of the point B [m/s]")] = Field(...)
    xB: Annotated[Vector, Vec3(dim="length", description="absolute position of B [m]")] = ZERO


class Body(StrictModel):
    """One body at the contact: motion of a reference point and the material
    point M in contact."""

    v: Annotated[Vector, Vec3(dim="velocity", description="velocity of the body's reference point [m/s]")] = ZERO
    omega: Annotated[Vector, Vec3(dim="angular velocity", description="angular velocity of the body [rad/s]")] = ZERO
    r: Annotated[Vector, Vec3(dim="length", description="vector from the reference point to the contact material point M [m]")] = ZERO


class Contact(ProblemBase):
    """Contact of two bodies: approach, slip, rolling (15.8, 15.9)."""

    type: Literal["contact"]
    body1: Body = Field(..., description="body B' (material point M')")
    body2: Body = Field(..., description="body B'' (material point M'')")
    n: Annotated[Vector, Vec3(nonzero=True, description="normal at the contact, from P' toward P'' (normalised by the tool)")] = Field(...)
