"""Input model of ``precession`` problems (docs/types/precession.md)."""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from dyncli.fields import Num, ProblemBase


class Precession(ProblemBase):
    """Steady precession of a symmetric top about a fixed point O (notes §38)."""

    type: Literal["precession"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass of the top [kg]")] = Field(...)
    L: Annotated[float, Num(dim="length", description="distance from the fixed point O to the center of mass [m] (negative: center of mass below O)")] = Field(...)
    I11: Annotated[float, Num(gt=0, dim="moment of inertia", description="transverse moment of inertia about O [kg m²]")] = Field(...)
    I33: Annotated[float, Num(gt=0, dim="moment of inertia", description="axial moment of inertia about O [kg m²]")] = Field(...)
    theta: Annotated[float, Num(dim="angle", description="nutation angle θ of the axis from the upward vertical [rad]")] = Field(...)
    p: Optional[Annotated[float, Num(dim="angular velocity", description="spin rate φ̇ relative to e'' [rad/s]; give p or Omega")]] = None
    Omega: Optional[Annotated[float, Num(dim="angular velocity", description="precession rate ψ̇ [rad/s]; give p or Omega")]] = None

    @model_validator(mode="after")
    def _check(self):
        if (self.p is None) == (self.Omega is None):
            raise ValueError("give exactly one of p (spin rate, find Omega) or Omega (precession rate, find p)"
                             + (" — both were given" if self.p is not None else ""))
        if self.I33 > 2.0 * self.I11 * (1.0 + 1e-12):
            raise ValueError(f"I33 = {self.I33:g} exceeds 2·I11 = {2 * self.I11:g}: no rigid body has such "
                             "moments of inertia (triangle inequality I33 <= I11 + I22)")
        return self
