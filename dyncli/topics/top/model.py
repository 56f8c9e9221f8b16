"""Input model of ``top`` problems (docs/types/top.md, notes §38)."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional

from pydantic import Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import Find, Num, ProblemBase, Times

#: accepted ``accuracy.method`` values (auto = exact: the elliptic solution)
METHODS = ("auto", "exact", "DOP853", "RK45", "Radau", "LSODA", "projected")


class Top(ProblemBase):
    """Heavy symmetric top with a fixed point O on its axis (notes §38).

    Orientation by the 3-1-3 Euler angles of (38.3)-(38.5): ψ about e3,
    θ about e'''_1, φ about e''_3; rates ψ̇, θ̇, φ̇ (φ̇ is the spin p of (38.19e))."""

    type: Literal["top"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass of the top [kg]")] = Field(...)
    L: Annotated[float, Num(gt=0, dim="length", description="distance from O to the center of mass along the axis [m]")] = Field(...)
    I11: Annotated[float, Num(gt=0, dim="moment of inertia", description="transverse moment of inertia about O [kg·m²]")] = Field(...)
    I33: Annotated[float, Num(gt=0, dim="moment of inertia", description="axial moment of inertia about O [kg·m²]")] = Field(...)
    psi: Annotated[float, Num(dim="angle", description="initial precession angle ψ [rad]")] = 0.0
    theta: Annotated[float, Num(dim="angle", description="initial nutation angle θ [rad] (angle of the axis from e3)")] = 0.0
    phi: Annotated[float, Num(dim="angle", description="initial spin angle φ [rad]")] = 0.0
    psi_dot: Annotated[float, Num(dim="angular velocity", description="initial ψ̇ [rad/s]")] = 0.0
    theta_dot: Annotated[float, Num(dim="angular velocity", description="initial θ̇ [rad/s]")] = 0.0
    phi_dot: Annotated[float, Num(dim="angular velocity", description="initial φ̇ = spin p relative to e'' [rad/s]")] = 0.0
    at: Annotated[list[float], Times(description="times t >= 0 [s] at which to report the motion")] = Field(default_factory=list)
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {theta: VALUE}}, {max: theta}, {min: R.2}")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries)")]] = None

    accuracy_methods = METHODS

    @model_validator(mode="after")
    def _check(self):
        for i, t in enumerate(self.at):
            if t < 0:
                raise InputError(f"times must be >= 0 (the motion starts at t = 0), got {t:g}", f"at.{i}")
        return self
