"""Input model of ``particles`` problems (docs/types/particles.md, notes §24-§27)."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional

from pydantic import Field, field_validator, model_validator

from dyncli.errors import InputError
from dyncli.fields import Find, Num, ProblemBase, StrictModel, Times, Vec3, Vector

#: the fields each pair kind needs (the others are rejected)
PAIR_FIELDS = {"spring": ("k", "L"), "damper": ("c",), "inverse-square": ("K",)}


class Pair(StrictModel):
    """A central pair force f_ij = f(x_ij)(x_i − x_j) between two particles (24.15)."""

    between: tuple[int, int] = Field(..., description="the two particles [i, j] (0-based, as listed)")
    kind: Literal["spring", "damper", "inverse-square"] = Field(..., description="spring (k, L), damper (c) or inverse-square (K: attraction K/r²; K < 0 repels)")
    k: Optional[Annotated[float, Num(ge=0, dim="stiffness", description="spring: stiffness [N/m]")]] = None
    L: Optional[Annotated[float, Num(ge=0, dim="length", description="spring: free length [m]")]] = None
    c: Optional[Annotated[float, Num(ge=0, dim="damping", description="damper: coefficient [N·s/m] (force c·dr/dt along the line)")]] = None
    K: Optional[Annotated[float, Num(description="inverse-square: strength [N·m²], attraction K/r² (G mᵢ mⱼ for gravitation; negative repels)")]] = None

    @model_validator(mode="after")
    def _fields(self):
        need = PAIR_FIELDS[self.kind]
        missing = [f for f in need if getattr(self, f) is None]
        if missing:
            raise ValueError(f"a {self.kind} pair needs {' and '.join(repr(f) for f in missing)}")
        extra = [f for f in ("k", "L", "c", "K") if f not in need and getattr(self, f) is not None]
        if extra:
            raise ValueError(f"{', '.join(repr(f) for f in extra)} does not apply to a {self.kind} pair "
                             f"(it takes {', '.join(repr(f) for f in need)})")
        if self.between[0] == self.between[1]:
            raise ValueError(f"a pair needs two different particles (got [{self.between[0]}, {self.between[1]}])")
        return self


class Particle(StrictModel):
    """One particle of the system."""

    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")] = Field(...)
    x: Annotated[Vector, Vec3(dim="length", description="position relative to the fixed origin [m]")] = Field(...)
    v: Annotated[Vector, Vec3(dim="velocity", description="velocity [m/s]")] = (0.0, 0.0, 0.0)


class Particles(ProblemBase):
    """A system of particles: total mass, center of mass, momentum, angular
    momentum and kinetic energy (24.12, 25.7, 27.8)."""

    type: Literal["particles"]
    particles: list[Particle] = Field(..., description="the particles: list of {m, x, v} (at least one)",
                                      json_schema_extra={"minItems": 1})
    about: Annotated[Vector, Vec3(dim="length", description="the fixed point O for H_O [m]")] = (0.0, 0.0, 0.0)
    pairs: list[Pair] = Field(default_factory=list, description="internal pair forces (springs, dampers, inverse-square attraction) between particles")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="integrate the motion under the pair forces to this time [s] (default max(at))")]] = None
    at: Annotated[list[float], Times(description="times [s] at which to report the motion (default [0, t_end])")] = Field(default_factory=list)
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {x_motion.0.0: 1}}, {min: V_internal_motion}")

    accuracy_methods = ("auto", "ode", "DOP853", "RK45", "Radau", "LSODA")

    @model_validator(mode="after")
    def _pairs_and_times(self):
        n = len(self.particles)
        for k, pr in enumerate(self.pairs):
            for i in pr.between:
                if not 0 <= i < n:
                    raise InputError(f"particle {i} does not exist (the particles are numbered 0 to {n - 1})",
                                     f"pairs.{k}.between")
            if pr.kind == "inverse-square" and self.particles[pr.between[0]].x == self.particles[pr.between[1]].x:
                raise InputError("the two particles of an inverse-square pair start at the same point "
                                 "(the force is infinite): give them distinct positions x", f"pairs.{k}")
        if self.t_end is None and self.at:
            self.t_end = max(self.at)
        if self.t_end is not None:
            for i, t in enumerate(self.at):
                if t < 0 or t > self.t_end:
                    raise InputError(f"time {t:g} is outside [0, t_end = {self.t_end:g}]", f"at.{i}")
            if not self.at:
                self.at = [0.0, self.t_end]
        return self

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
