"""Input model of ``impact`` problems (docs/types/impact.md, notes §28, §23)."""

from __future__ import annotations

import math
from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from dyncli.direction import norm, unit
from dyncli.errors import InputError
from dyncli.fields import Num, ProblemBase, Vec3, Vector

UNIT_TOL = 1e-4   # how far a given tangent t may be from unit length / perpendicular to n


class Impact(ProblemBase):
    """Impact of two particles A and B (notes §28).

    Smooth impact: give ``e`` (coefficient of restitution, 28.7).  General
    impact (with friction): give ``eta`` (28.26, 28.28) and the friction angle
    ``phi`` of the impulse direction f = -(cos(phi) n + sin(phi) t) (28.41)."""

    type: Literal["impact"]
    mA: Annotated[float, Num(gt=0, dim="mass", description="mass of particle A [kg]")]
    mB: Annotated[float, Num(gt=0, allow_inf=True, dim="mass", description="mass of particle B [kg]; .inf for a fixed massive body")]
    vA1: Annotated[Vector, Vec3(dim="velocity", description="velocity of A just before impact [m/s]")] = (0.0, 0.0, 0.0)
    vB1: Annotated[Vector, Vec3(dim="velocity", description="velocity of B just before impact [m/s]")] = (0.0, 0.0, 0.0)
    n: Annotated[Vector, Vec3(nonzero=True, description="outward normal of A at the contact, pointing from A toward B (normalised)")] = Field(...)
    e: Optional[Annotated[float, Num(ge=0, le=1, description="coefficient of restitution (smooth impact, 28.7)")]] = None
    eta: Optional[Annotated[float, Num(ge=0, le=1, description="restitution along the impulse direction f (28.26, 28.28)")]] = None
    phi: Optional[Annotated[float, Num(dim="angle", description="friction angle of the impulse [rad], -pi/2 <= phi <= pi/2 (28.41)")]] = None
    t: Optional[Annotated[Vector, Vec3(nonzero=True, description="unit tangent in the contact plane (needed only when vA1 - vB1 is parallel to n)")]] = None

    @model_validator(mode="after")
    def _check(self):
        if self.e is not None and self.eta is not None:
            raise InputError("give either e (smooth impact) or eta (general impact with phi), not both", "eta")
        if self.phi is not None and self.eta is None:
            raise InputError("phi (friction angle of the impulse) requires eta (general model, 28.26); "
                             "a smooth impact with e has f = -n", "phi")
        if self.t is not None and self.eta is None:
            raise InputError("t is used only by the general model (eta, phi); a smooth impact needs no tangent", "t")
        if self.e is None and self.eta is None:
            raise InputError("give e (smooth impact, 0 <= e <= 1) or eta with phi (impact with friction)", "e")
        if self.phi is not None and not (-math.pi / 2 <= self.phi <= math.pi / 2):
            raise InputError(f"the friction angle must lie in [-pi/2, pi/2] so that f·(-n) >= 0 (28.42c,d), got {self.phi:.6g}", "phi")
        if self.t is not None:
            nn = unit(self.n, "n", "n")          # scaled by max|nᵢ| first (dyncli.direction)
            tt = self.t
            length = norm(tt)
            if abs(length - 1.0) > UNIT_TOL:
                raise InputError(f"t must be a unit vector (its length is {length:.6g}): give it normalised, "
                                 "or omit t and dyncli computes it", "t")
            dot = sum(a * b for a, b in zip(tt, nn)) / length
            if abs(dot) > UNIT_TOL:
                raise InputError(f"t must be perpendicular to n (t·n = {dot:.3g}): omit t and dyncli computes it", "t")
        return self
