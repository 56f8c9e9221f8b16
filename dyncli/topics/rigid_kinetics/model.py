"""Input models of ``planar-moments`` and ``rigid-energy`` (contract §4.10)."""

from __future__ import annotations

from typing import Literal

from pydantic import field_validator

from dyncli.fields import Num, ProblemBase, Tensor3, Vec3
from dyncli.topics.inertia.model import check_psd


class PlanarMoments(ProblemBase):
    """Moments about the center of mass that keep a rigid body in planar
    motion ω = ω e'3 (notes §32, 32.13)."""

    type: Literal["planar-moments"]
    I13: Num(dim="moment of inertia", description="Ī'13 about the center of mass [kg m²] (minus the product of inertia)")  # type: ignore[valid-type]
    I23: Num(dim="moment of inertia", description="Ī'23 about the center of mass [kg m²] (minus the product of inertia)")  # type: ignore[valid-type]
    I33: Num(ge=0, dim="moment of inertia", description="Ī'33 about the center of mass [kg m²]")  # type: ignore[valid-type]
    omega: Num(dim="angular velocity", description="ω [rad/s] about e'3 = e3")  # type: ignore[valid-type]
    omega_dot: Num(dim="angular acceleration", description="ω̇ [rad/s²]") = 0.0  # type: ignore[valid-type]


class RigidEnergy(ProblemBase):
    """Kinetic energy and angular momentum of a rigid body (notes §34, 34.6-34.7)."""

    type: Literal["rigid-energy"]
    m: Num(gt=0, dim="mass", description="mass [kg]")  # type: ignore[valid-type]
    v: Vec3(dim="velocity", description="velocity of the center of mass [m/s]")  # type: ignore[valid-type]
    omega: Vec3(dim="angular velocity", description="angular velocity [rad/s], same basis as I")  # type: ignore[valid-type]
    I: Tensor3(symmetric=True, dim="moment of inertia", description="inertia tensor about the center of mass [kg m²], same basis as omega")  # type: ignore[valid-type]

    @field_validator("I")
    @classmethod
    def _psd(cls, v):
        check_psd(v)
        return v
