"""Input model of ``euler`` problems (docs/types/euler.md)."""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal, Optional

from pydantic import Field, model_validator

from dyncli.fields import ExprTriple, ExprVec3, Find, Num, ProblemBase, StrictModel, Times, Vec3, Vector


class Coin(StrictModel):
    """A homogeneous coin (disk) of radius R and thickness h: moments (39.10)."""

    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")] = Field(...)
    R: Annotated[float, Num(gt=0, dim="length", description="radius [m]")] = Field(...)
    h: Annotated[float, Num(ge=0, dim="length", description="thickness [m]")] = Field(...)


class Euler(ProblemBase):
    """Euler's equations (39.5) on the principal body basis e'; torque-free
    bodies are solved exactly (39.14-39.22 axisymmetric, Jacobi elliptic
    functions otherwise)."""

    type: Literal["euler"]
    I: Optional[Annotated[Vector, Vec3(dim="moment of inertia", description="principal moments of inertia [I1, I2, I3] about the center of mass [kg m²]")]] = None
    coin: Optional[Coin] = Field(None, description="a coin {m, R, h}: I1 = I2 = mR²/4 + mh²/12, I3 = mR²/2 (39.10)")
    omega0: Annotated[Vector, Vec3(dim="angular velocity", description="initial angular velocity, body components ω'₀ᵢ [rad/s]")] = Field(...)
    M: Optional[Annotated[ExprTriple, ExprVec3(("t",), dim="moment", description="applied moment about the center of mass, body components, expressions in t [N m]")]] = None
    at: Annotated[list[float], Times()] = Field(default_factory=lambda: [0.0])
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {omega.2: VALUE}}, {max: omega.0}")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries)")]] = None

    accuracy_methods = ("auto", "closed-form", "DOP853", "RK45", "Radau", "LSODA", "projected")

    @model_validator(mode="after")
    def _check(self):
        if (self.I is None) == (self.coin is None):
            raise ValueError("give exactly one of I (principal moments) or coin: {m, R, h}"
                             + (" — both were given" if self.I is not None else ""))
        if self.I is not None:
            I = self.I
            for i, v in enumerate(I):
                if not v > 0:
                    raise ValueError(f"I: principal moment I{i + 1} must be > 0, got {v:g}")
            for i in range(3):
                others = I[(i + 1) % 3] + I[(i + 2) % 3]
                if I[i] > others * (1 + 1e-12):
                    raise ValueError(f"I: I{i + 1} = {I[i]:g} exceeds the sum of the other two ({others:g}): "
                                     "no rigid body has these principal moments (triangle inequality)")
        if self.coin is not None:
            I = self.moments()
            if not all(0 < v < math.inf for v in I):
                c = self.coin
                raise ValueError(f"coin: its moments of inertia (m R²/4 + m h²/12, m R²/2 = {I[0]:g}, {I[2]:g} kg·m² "
                                 f"for m = {c.m:g}, R = {c.R:g}, h = {c.h:g}) are beyond the range of a double; "
                                 "give m, R and h in units that keep m R² between about 1e-300 and 1e300")
        if self.M is not None and self.accuracy.method == "projected":
            raise ValueError("accuracy.method projected conserves |H| and T and needs a torque-free body (no M)")
        return self

    def moments(self) -> tuple[float, float, float]:
        if self.I is not None:
            return self.I
        c = self.coin
        assert c is not None                 # exactly one of I and coin (checked above)
        # (39.10): I1 = I2 = m R²/4 + m h²/12, I3 = m R²/2 (no division: R² may underflow)
        i1 = c.m * (c.R * c.R / 4.0 + c.h * c.h / 12.0)
        return (i1, i1, 0.5 * c.m * c.R * c.R)
