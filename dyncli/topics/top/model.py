"""Input model of ``top`` problems (contract §4.11)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from dyncli.fields import Num, ProblemBase, Times


class Top(ProblemBase):
    """The heavy symmetric top about a fixed point O (notes §38), 3-1-3 Euler angles."""

    type: Literal["top"]
    m: Num(gt=0, dim="mass", description="mass [kg]") = Field(...)  # type: ignore[valid-type]
    L: Num(dim="length", description="distance from O to the center of mass along the axis [m]") = Field(...)  # type: ignore[valid-type]
    I11: Num(gt=0, dim="moment of inertia", description="transverse moment of inertia about O [kg m²]") = Field(...)  # type: ignore[valid-type]
    I33: Num(gt=0, dim="moment of inertia", description="axial moment of inertia about O [kg m²]") = Field(...)  # type: ignore[valid-type]
    psi: Num(dim="angle", description="initial precession angle ψ [rad]") = 0.0  # type: ignore[valid-type]
    theta: Num(dim="angle", description="initial nutation angle θ from the upward vertical [rad]") = Field(...)  # type: ignore[valid-type]
    phi: Num(dim="angle", description="initial spin angle φ [rad]") = 0.0  # type: ignore[valid-type]
    psi_dot: Num(dim="angular velocity", description="initial ψ̇ [rad/s]") = 0.0  # type: ignore[valid-type]
    theta_dot: Num(dim="angular velocity", description="initial θ̇ [rad/s]") = 0.0  # type: ignore[valid-type]
    phi_dot: Num(dim="angular velocity", description="initial spin φ̇ relative to e'' [rad/s]") = 0.0  # type: ignore[valid-type]
    at: Times() = Field(default_factory=lambda: [0.0])  # type: ignore[valid-type]

    accuracy_methods = ("auto", "DOP853", "RK45", "Radau", "LSODA", "projected")

    @model_validator(mode="after")
    def _check(self):
        if self.I33 > 2.0 * self.I11 * (1.0 + 1e-12):
            raise ValueError(f"I33 = {self.I33:g} exceeds 2·I11 = {2 * self.I11:g}: no rigid body has such "
                             "moments of inertia (triangle inequality I33 <= I11 + I22)")
        return self
