"""Input model of ``rotating-frame`` problems (docs/types/rotating-frame.md)."""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field

from dyncli.fields import ExprTriple, ExprVec3, ProblemBase, Times
from dyncli.topics.inertia.model import Orientation


class RotatingFrame(ProblemBase):
    """A vector p = x_{A/B} given by its components on a basis e'_i that
    rotates with angular velocity ω (components on e'_i); all components are
    expressions in t (notes §10, §11)."""

    type: Literal["rotating-frame"]
    omega: Annotated[ExprTriple, ExprVec3(("t",), dim="angular velocity", description="ω'_1, ω'_2, ω'_3: components of ω on e'_i, expressions in t [rad/s]")] = Field(...)
    p: Annotated[ExprTriple, ExprVec3(("t",), dim="length", description="p'_1, p'_2, p'_3: components of p = x_A/B on e'_i, expressions in t [m]")] = Field(...)
    vB: Optional[Annotated[ExprTriple, ExprVec3(("t",), dim="velocity", description="velocity of B, components on e'_i, expressions in t [m/s]")]] = None
    aB: Optional[Annotated[ExprTriple, ExprVec3(("t",), dim="acceleration", description="acceleration of B, components on e'_i, expressions in t [m/s²]")]] = None
    at: Annotated[list[float], Times()] = Field(default_factory=list)
    fixed: bool = Field(False, description="also report every vector on the fixed basis e_i (names ending in "
                        "_fixed), e'_i = e_i at t = 0 unless basis0 says otherwise")
    basis0: Optional[Orientation] = Field(None, description="the orientation of e'_i at t = 0 relative to the fixed "
                                          "basis (implies fixed): {axis, angle}, {euler313} or {matrix} whose "
                                          "columns are e'_i in fixed components")

    accuracy_methods = ("auto", "ode")
