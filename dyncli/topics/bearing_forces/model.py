"""Input model of ``bearing-forces`` problems (notes §36, Fig. 36.4, Table 36.1)."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional

from pydantic import Field, field_validator, model_validator

from dyncli.errors import InputError
from dyncli.fields import Expr, ExprField, Find, Num, ProblemBase, StrictModel, Times


class ArmMass(StrictModel):
    """A point mass on a massless arm pivoted at O, in the plane e'1-e'2 that turns with the shaft:
    x = L (sin α e'1 + cos α e'2), α measured from the axis e'2 towards e'1."""

    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")] = Field(...)
    L: Annotated[float, Num(ge=0, dim="length", description="arm length from O [m]")] = Field(...)
    alpha: Annotated[Expr, ExprField(("t",), dim="angle", description="α(t): angle of the arm from the axis e'2 towards e'1 [rad], a number or an expression in t (the notes' mass A has −α, B has +α)")] = Field(...)
    y: Annotated[float, Num(dim="length", description="axial position of the arm's pivot on the shaft, along e'2 from O [m]")] = 0.0
    beta: Annotated[float, Num(dim="angle", description="azimuth of the arm's plane about e'2: the arm swings in the plane of e'2 and cos β e'1 + sin β e'3 [rad]")] = 0.0


class Bearings(StrictModel):
    """Two bearings on the shaft, at axial positions along e'2 (from O): they share the load F = Ġ
    and carry the moment M_O between them as a pair of forces; A also takes the axial (thrust) load."""

    A: Annotated[float, Num(dim="length", description="axial position of bearing A (and the thrust bearing) along e'2 [m]")] = Field(...)
    B: Annotated[float, Num(dim="length", description="axial position of bearing B along e'2 [m]")] = Field(...)

    @model_validator(mode="after")
    def _apart(self):
        if self.A == self.B:
            raise InputError(f"bearings A and B are both at {self.A:g} m: two bearings at one point carry no "
                             "moment; give two different axial positions (or one bearing with h)", "bearings.B")
        return self


class BearingForces(ProblemBase):
    """Point masses on arms whose angles α(t) a motor prescribes, on a shaft turning about the
    fixed axis e'2 either at a prescribed rate ω(t) or freely (M_O·e'2 = 0): the bearing force
    F = Ġ and moment M_O = Ḣ_O over time (36.10-36.22)."""

    type: Literal["bearing-forces"]
    masses: list[ArmMass] = Field(..., description="the masses on their arms (at least one)", json_schema_extra={"minItems": 1})
    omega: Optional[Annotated[Expr, ExprField(("t",), dim="angular velocity", description="ω(t): prescribed spin of the shaft about e'2 [rad/s] (a motor drives it); give omega or omega0")]] = None
    omega0: Optional[Annotated[float, Num(dim="angular velocity", description="ω at t = 0 for a shaft turning freely (M_O·e'2 = 0, H_O·e'2 conserved, 36.19-36.22); give omega or omega0")]] = None
    h: Annotated[float, Num(dim="length", description="the bearing is at x1 = −h e'2 (36.17) [m]")] = 0.0
    bearings: Optional[Bearings] = Field(None, description="two bearings A and B at axial positions along e'2 "
                                         "instead of the one bearing at −h e'2")
    at: Annotated[list[float], Times(description="times t [s] at which to report the loads")] = Field(..., json_schema_extra={"minItems": 1})
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {max: F1.0}, {min: motor_torque}")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries)")]] = None

    @field_validator("masses")
    @classmethod
    def _some(cls, v):
        if not v:
            raise ValueError("at least one mass {m, L, alpha} is needed")
        return v

    @field_validator("at")
    @classmethod
    def _times(cls, v):
        if not v:
            raise ValueError("give at least one time, e.g. at: [0, 1]")
        return v

    @model_validator(mode="after")
    def _one_rate(self):
        if (self.omega is None) == (self.omega0 is None):
            raise InputError("give exactly one of omega (a prescribed spin ω(t)) or omega0 (a free shaft, ω at t = 0)"
                             + (" — both were given" if self.omega is not None else ""), "omega")
        if self.bearings is not None and "h" in self.model_fields_set:
            raise InputError("give either h (one bearing at −h e'2) or bearings (two, at A and B), not both", "h")
        return self
