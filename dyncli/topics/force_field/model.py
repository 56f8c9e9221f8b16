"""Input model of ``force-field`` problems (docs/types/force-field.md, notes §19)."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional

from pydantic import Field, ValidationInfo, model_validator

from dyncli.fields import Expr, ExprField, ExprTriple, ExprVec3, ProblemBase, StrictModel, Times, Vec3, Vector

FIELD_VARS = ("x1", "x2", "x3")


class Path(StrictModel):
    """A parametrised path x(t) = x1(t) e1 + x2(t) e2 + x3(t) e3, t from t1 to t2."""

    x1: Annotated[Expr, ExprField(("t",), dim="length", description="x1(t) [m]: number or expression in t")]
    x2: Annotated[Expr, ExprField(("t",), dim="length", description="x2(t) [m]: number or expression in t")]
    x3: Annotated[Expr, ExprField(("t",), dim="length", description="x3(t) [m]: number or expression in t")]
    t_span: Annotated[list[float], Times(max_len=2, description="[t1, t2]: the parameter runs from t1 to t2")]

    @model_validator(mode="after")
    def _two(self):
        if len(self.t_span) != 2:
            raise ValueError(f"t_span must be [t1, t2] (2 numbers), got {len(self.t_span)}")
        return self


class ForceField(ProblemBase):
    """A force field F(x) (notes §19): curl, conservative verdict, potential,
    work along a path."""

    type: Literal["force-field"]
    F: Annotated[ExprTriple, ExprVec3(FIELD_VARS, dim="force", description="3 expressions in x1, x2, x3 [N]")]
    points: list[Annotated[Vector, Vec3(dim="length")]] = Field(default_factory=list, description="points where the curl is evaluated [m]")
    path: Optional[Path] = Field(None, description="path for the work: {x1, x2, x3 (expressions in t), t_span: [t1, t2]}")

    coordinates: Literal["cartesian", "polar", "cylindrical", "spherical"] = Field(
        "cartesian", description="the coordinates of F, points and path: cartesian (x1, x2, x3), polar (r, theta), "
                                 "cylindrical (r, theta, x3), spherical (R, theta, phi; phi the elevation); "
                                 "F's components are on that system's basis (Tables 19.1-19.2)")

    accuracy_methods = ("auto", "quadrature")

    @model_validator(mode="before")
    @classmethod
    def _curvilinear(cls, data: Any, info: ValidationInfo) -> Any:
        """F and the path in the chosen coordinates (parsed here: the fields
        themselves are declared in x1, x2, x3)."""
        from dyncli.topics.force_field.coordinates import prepare

        return prepare(data, info)

