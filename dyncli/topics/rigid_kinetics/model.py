"""Input models of ``planar-moments`` and ``rigid-energy`` (docs/types/planar-moments.md, docs/types/rigid-energy.md)."""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, field_validator, model_validator

from dyncli.errors import InputError
from dyncli.fields import ExprTriple, ExprVec3, Matrix, Num, ProblemBase, StrictModel, Tensor3, Times, Vec3, Vector
from dyncli.topics.inertia.model import check_psd


class AppliedForce(StrictModel):
    """A force F applied at the material point x of the body."""

    F: Annotated[Vector, Vec3(dim="force", description="the force [N]")] = Field(...)
    x: Optional[Annotated[Vector, Vec3(dim="length", description="point of application [m] (rigid-energy: absolute position; planar-moments: relative to the center of mass, body axes); default the center of mass")]] = None


class Motion(StrictModel):
    """A prescribed motion: v̄(t) and ω(t) on the body axes (where Ī is constant)."""

    v: Annotated[ExprTriple, ExprVec3(("t",), dim="velocity", description="v̄(t): 3 expressions in t [m/s]")]
    omega: Annotated[ExprTriple, ExprVec3(("t",), dim="angular velocity", description="ω(t): 3 expressions in t [rad/s]")]
    at: Annotated[list[float], Times(description="times [s] at which to report T, its rate and the work since the first time")] = Field(..., json_schema_extra={"minItems": 1})

    @field_validator("at")
    @classmethod
    def _some(cls, v):
        if not v:
            raise ValueError("give at least one time, e.g. at: [0, 1]")
        return v


class PlanarMoments(ProblemBase):
    """Moments about the center of mass that keep a rigid body in planar
    motion ω = ω e'3 (notes §32, 32.13)."""

    type: Literal["planar-moments"]
    I13: Annotated[float, Num(dim="moment of inertia", description="Ī'13 about the center of mass [kg m²] (minus the product of inertia)")]
    I23: Annotated[float, Num(dim="moment of inertia", description="Ī'23 about the center of mass [kg m²] (minus the product of inertia)")]
    I33: Annotated[float, Num(ge=0, dim="moment of inertia", description="Ī'33 about the center of mass [kg m²]")]
    omega: Annotated[float, Num(dim="angular velocity", description="ω [rad/s] about e'3 = e3")]
    omega_dot: Annotated[float, Num(dim="angular acceleration", description="ω̇ [rad/s²]")] = 0.0
    m: Optional[Annotated[float, Num(gt=0, dim="mass", description="mass [kg] (with forces: ā = F/m, 32.8)")]] = None
    forces: list[AppliedForce] = Field(default_factory=list, description="forces {F, x} on the body (components on e'_i, x relative to the center of mass): resultant, ā (32.6, 32.8), their moment about the center of mass")

    @model_validator(mode="after")
    def _mass_with_forces(self):
        if self.forces and self.m is None:
            raise InputError("forces need the mass m (for ā = F/m, 32.6)", "m")
        return self


class RigidEnergy(ProblemBase):
    """Kinetic energy and angular momentum of a rigid body (notes §34, 34.6-34.7)."""

    type: Literal["rigid-energy"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")]
    v: Optional[Annotated[Vector, Vec3(dim="velocity", description="velocity of the center of mass [m/s] (required unless motion is given: then v̄ at its first time)")]] = None
    omega: Optional[Annotated[Vector, Vec3(dim="angular velocity", description="angular velocity [rad/s], same basis as I (required unless motion is given: then ω at its first time)")]] = None
    I: Annotated[Matrix, Tensor3(symmetric=True, dim="moment of inertia", description="inertia tensor about the center of mass [kg m²], same basis as omega")]
    x: Optional[Annotated[Vector, Vec3(dim="length", description="position x̄ of the center of mass [m] (for H_O, 29.25, and the points of application)")]] = None
    about: Optional[Annotated[Vector, Vec3(dim="length", description="the point O for H_O [m] (default the origin; needs x)")]] = None
    forces: list[AppliedForce] = Field(default_factory=list, description="external forces {F, x}: x is the absolute position of the point of application (default the center of mass)")
    moments: list[Annotated[Vector, Vec3(dim="moment", description="a couple [N m]")]] = Field(default_factory=list, description="external couples M_i [N m]")
    b: Optional[Annotated[Vector, Vec3(dim="acceleration", description="uniform body force per unit mass [m/s²] (e.g. gravity [0, 0, -9.81])")]] = None
    motion: Optional[Motion] = Field(None, description="a prescribed motion {v, omega, at}: T, its rate (the power 34.16) and the work since the first time (34.20)")

    @model_validator(mode="after")
    def _about_needs_x(self):
        for name in ("v", "omega"):
            if getattr(self, name) is None and self.motion is None:
                raise InputError("required field is missing (or give a prescribed motion {v, omega, at})", name)
        if self.about is not None and self.x is None:
            raise InputError("about (the point O for H_O) needs the position x of the center of mass", "about")
        for i, f in enumerate(self.forces):
            if f.x is not None and self.x is None:
                raise InputError("a force's point of application x needs the position x of the center of mass "
                                 "(or leave out the force's x: it then acts at the center of mass)", f"forces.{i}.x")
        return self

    @field_validator("I")
    @classmethod
    def _psd(cls, v):
        check_psd(v)
        return v
