"""Input model of ``particles`` problems (contract §4.9, notes §24-§27)."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, field_validator

from dyncli.fields import Num, ProblemBase, StrictModel, Vec3


class Particle(StrictModel):
    """One particle of the system."""

    m: Num(gt=0, dim="mass", description="mass [kg]") = Field(...)  # type: ignore[valid-type]
    x: Vec3(dim="length", description="position relative to the fixed origin [m]") = Field(...)  # type: ignore[valid-type]
    v: Vec3(dim="velocity", description="velocity [m/s]") = (0.0, 0.0, 0.0)  # type: ignore[valid-type]


class Particles(ProblemBase):
    """A system of particles: total mass, center of mass, momentum, angular
    momentum and kinetic energy (24.12, 25.7, 27.8)."""

    type: Literal["particles"]
    particles: list[Particle] = Field(..., description="the particles: list of {m, x, v} (at least one)",
                                      json_schema_extra={"minItems": 1})
    about: Vec3(dim="length", description="the fixed point O for H_O [m]") = (0.0, 0.0, 0.0)  # type: ignore[valid-type]

    @field_validator("particles")
    @classmethod
    def _not_empty(cls, v):
        if not v:
            raise ValueError("at least one particle {m, x, v} is needed")
        return v

    @field_validator("about", mode="before")
    @classmethod
    def _zero_is_origin(cls, v: Any):
        # the contract writes the default as [0]: accept 0 and [0] for the origin
        if (isinstance(v, (int, float)) and not isinstance(v, bool) and v == 0) or v == [0]:
            return [0.0, 0.0, 0.0]
        return v
