"""Input model of ``rigid-impulse`` problems (docs/types/rigid-impulse.md, notes §33)."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from dyncli.fields import Num, ProblemBase


class RigidImpulse(ProblemBase):
    """A rigid body at rest in planar motion struck by an impulse R̂ e'_1 at
    the point −s e'_1 − h e'_2 relative to its center of mass (33.3, 33.4)."""

    type: Literal["rigid-impulse"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass of the body [kg]")] = Field(...)
    k: Annotated[float, Num(gt=0, dim="length", description="radius of gyration about the center of mass [m] (Ī = m k²)")] = Field(...)
    R: Annotated[float, Num(dim="impulse", description="impulse R̂ along e'_1 [N·s]")] = Field(...)
    h: Annotated[float, Num(dim="length", description="point of application: −s e'_1 − h e'_2 [m]")] = Field(...)
    s: Annotated[float, Num(dim="length", description="point of application: −s e'_1 − h e'_2 [m]")] = 0.0
