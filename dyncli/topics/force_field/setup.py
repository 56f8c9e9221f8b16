"""The plain inputs of a force-field problem (notes §19), built from the validated model by
:func:`dyncli.topics.force_field.solver.plain`: the field's three component expressions, the
points where the curl is wanted and the path of the work, in SI floats."""

from __future__ import annotations

from dataclasses import dataclass

from dyncli.expr import Expr


@dataclass(frozen=True, slots=True)
class Path:
    """x(t) = x1(t) e1 + x2(t) e2 + x3(t) e3 for t from t1 to t2 (19.4); in curvilinear
    coordinates x1, x2, x3 hold the system's coordinates q(t)."""

    x1: Expr
    x2: Expr
    x3: Expr
    t1: float
    t2: float


@dataclass(frozen=True, slots=True)
class Setup:
    """F (components on the basis of ``coordinates``, expressions in its variables), the points [m]
    of the curl, the path of the work (or None) and the quadrature's tolerances."""

    F: tuple[Expr, Expr, Expr]
    points: tuple[tuple[float, float, float], ...]
    path: Path | None
    coordinates: str = "cartesian"
    rtol: float = 1e-10
    atol: float = 1e-12
    max_steps: int | None = None
