"""Input models of ``spin-change`` and ``motor-bodies`` (docs/types/spin-change.md, docs/types/motor-bodies.md)."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from dyncli.fields import Num, ProblemBase, StrictModel, Vec3, Vector


class MovingMass(StrictModel):
    """A point mass that the system's mechanism moves from ``before`` to ``after``."""

    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")]
    before: Annotated[Vector, Vec3(dim="length", description="position before the change [m] (body components, origin on the axis)")]
    after: Annotated[Vector, Vec3(dim="length", description="position after the change [m]")]


class SpinChange(ProblemBase):
    """A body spinning freely about a fixed axis through the origin while
    internal mechanisms move point masses: H·e conserved (notes §36, 36.21-36.22)."""

    type: Literal["spin-change"]
    masses: list[MovingMass] = Field(..., description="the moving point masses")
    axis: Annotated[Vector, Vec3(nonzero=True, description="direction of the fixed axis through the origin (normalised)")]
    omega0: Annotated[float, Num(dim="angular velocity", description="angular velocity about the axis before the change [rad/s]")]
    I0: Annotated[float, Num(ge=0, dim="moment of inertia", description="moment of inertia of the rigid rest about the axis [kg m²]")] = 0.0


class MotorBodies(ProblemBase):
    """Two bodies joined by a motor (notes §36, Fig. 36.6, 36.23-36.40): body B
    turns freely about the fixed axis e''2; the motor shaft, at the constant
    angle alpha to the plane normal to that axis (e'''1 = cos α e''1 +
    sin α e''2), spins the axisymmetric body A relative to B at rate p.  The
    system starts at rest, so H_O·e''2 = 0 and B turns at Ω (36.40)."""

    type: Literal["motor-bodies"]
    IA1: Annotated[float, Num(ge=0, dim="moment of inertia", description="body A: moment about its own symmetry axis (the shaft e'''1), about its center of mass [kg m²]")]
    IA2: Annotated[float, Num(ge=0, dim="moment of inertia", description="body A: transverse moment about its center of mass [kg m²]")]
    mA: Annotated[float, Num(ge=0, dim="mass", description="mass of body A [kg]")]
    L: Annotated[float, Num(ge=0, dim="length", description="distance from O (on the fixed axis) to A's center of mass along the shaft [m]")]
    IB2: Annotated[float, Num(ge=0, dim="moment of inertia", description="body B: moment about the fixed axis e''2 (its symmetry axis, through its center of mass) [kg m²]")]
    alpha: Annotated[float, Num(dim="angle", description="angle between the shaft and the plane normal to the fixed axis [rad]")]
    p: Annotated[float, Num(dim="angular velocity", description="spin rate of A relative to B about the shaft [rad/s]")]
