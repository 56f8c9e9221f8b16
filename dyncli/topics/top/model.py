"""Input model of ``top`` problems (docs/types/top.md, notes §38)."""

from __future__ import annotations

from typing import Literal, Optional

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
    m: Num(gt=0, dim="mass", description="mass of the top [kg]") = Field(...)  # type: ignore[valid-type]
    L: Num(gt=0, dim="length", description="distance from O to the center of mass along the axis [m]") = Field(...)  # type: ignore[valid-type]
    I11: Num(gt=0, dim="moment of inertia", description="transverse moment of inertia about O [kg·m²]") = Field(...)  # type: ignore[valid-type]
    I33: Num(gt=0, dim="moment of inertia", description="axial moment of inertia about O [kg·m²]") = Field(...)  # type: ignore[valid-type]
    psi: Num(dim="angle", description="initial precession angle ψ [rad]") = 0.0  # type: ignore[valid-type]
    theta: Num(dim="angle", description="initial nutation angle θ [rad] (angle of the axis from e3)") = 0.0  # type: ignore[valid-type]
    phi: Num(dim="angle", description="initial spin angle φ [rad]") = 0.0  # type: ignore[valid-type]
    psi_dot: Num(dim="angular velocity", description="initial ψ̇ [rad/s]") = 0.0  # type: ignore[valid-type]
    theta_dot: Num(dim="angular velocity", description="initial θ̇ [rad/s]") = 0.0  # type: ignore[valid-type]
    phi_dot: Num(dim="angular velocity", description="initial φ̇ = spin p relative to e'' [rad/s]") = 0.0  # type: ignore[valid-type]
    at: Times(description="times t >= 0 [s] at which to report the motion") = Field(default_factory=list)  # type: ignore[valid-type]
    find: Find() = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {theta: VALUE}}, {max: theta}, {min: R.2}")  # type: ignore[valid-type]
    t_end: Optional[Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries)")] = None  # type: ignore[valid-type]

    accuracy_methods = METHODS

    @model_validator(mode="after")
    def _check(self):
        for i, t in enumerate(self.at):
            if t < 0:
                raise InputError(f"times must be >= 0 (the motion starts at t = 0), got {t:g}", f"at.{i}")
        return self
