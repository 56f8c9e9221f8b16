"""Input model of ``gyroscope`` problems (docs/types/gyroscope.md)."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional

from pydantic import Field, model_validator

from dyncli.fields import Find, Num, ProblemBase, Times


class Gyroscope(ProblemBase):
    """The gimballed gyroscope of notes §37: spin p about e''₁, turntable rate q about
    the vertical, free rotation θ about the horizontal e''₃ axis."""

    type: Literal["gyroscope"]
    I1: Annotated[float, Num(gt=0, dim="moment of inertia", description="axial moment of inertia Ī₁ (spin axis e''₁) [kg m²]")] = Field(...)
    I2: Annotated[float, Num(gt=0, dim="moment of inertia", description="transverse moment of inertia Ī₂ [kg m²]")] = Field(...)
    p: Annotated[float, Num(dim="angular velocity", description="spin rate relative to e'' about e''₁ [rad/s]")] = Field(...)
    q: Annotated[float, Num(dim="angular velocity", description="rate of the e''₁-e''₂ plane about the vertical e₂ [rad/s]")] = Field(...)
    theta0: Annotated[float, Num(dim="angle", description="initial tilt θ(0) of e''₁ above the horizontal [rad]")] = 0.0
    theta_dot0: Annotated[float, Num(dim="angular velocity", description="initial θ̇(0) [rad/s]")] = 0.0
    at: Annotated[list[float], Times()] = Field(default_factory=lambda: [0.0])
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {theta: VALUE}}, {max: theta}, {min: M.0}")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries)")]] = None

    accuracy_methods = ("auto", "exact", "closed-form", "DOP853", "RK45", "Radau", "LSODA")

    @model_validator(mode="after")
    def _check(self):
        if self.I1 > 2.0 * self.I2 * (1.0 + 1e-12):
            raise ValueError(f"I1 = {self.I1:g} exceeds 2·I2 = {2 * self.I2:g}: no body of revolution has such "
                             "moments of inertia (triangle inequality I1 <= I2 + I3)")
        return self
