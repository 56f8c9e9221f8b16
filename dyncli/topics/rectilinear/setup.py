"""A rectilinear problem in plain numbers (notes §6): what the routes below ``solver.py`` read (the
closed form, the quadratures of cases 2-4, the ODE, the §11 searches), as small frozen dataclasses
of SI floats — built from the validated input by :func:`dyncli.topics.rectilinear.solver.plain`,
or by hand in a notebook::

    from dyncli.expr import parse
    from dyncli.topics.rectilinear import solver
    from dyncli.topics.rectilinear.setup import Query, Setup
    s = Setup(a=parse("-9.81", ("t", "s", "v"), {}), v1=20.0, find=(Query(t=1.0), Query(v=0.0)))
    solver.solve_setup(s).results      # {'case': 1, 'find': [{'t': 1.0, 's': 15.095, ...}, ...]}

The attribute names are the input's (``p.s1``, ``q.kind``, ``p.accuracy.rtol``), so the physics
reads either.  ``a`` is a compiled expression of t, s, v (:class:`dyncli.expr.Expr`, not a model).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

from dyncli.integrators import Accuracy      # the one form of the accuracy controls

#: the kinds of query; the last three are answered by the queries of every motion (§11)
KINDS = ("t", "v", "s", "when", "max", "min")
#: the keys that go with a kind (when: direction, occurrence; max, min: within)
QUALIFIERS = ("direction", "occurrence", "within")


@dataclass(frozen=True, slots=True)
class Spring:
    """A linear spring along the line (§19 (19.26a)): stiffness k [N/m], fixed end at ``anchor``
    [m], free length L [m]; ``one_sided``: None, "compression" or "tension"."""

    k: float
    anchor: float = 0.0
    L: float = 0.0
    one_sided: str | None = None


@dataclass(frozen=True, slots=True)
class Query:
    """One ``find`` entry: exactly one of t [s], v [m/s], s [m] (the type's own queries) or
    when/max/min with their qualifiers (§11, as written: answered by dyncli.queries)."""

    t: float | None = None
    v: float | None = None
    s: float | None = None
    when: Any = None
    direction: Any = None
    occurrence: Any = None
    max: Any = None
    min: Any = None
    within: Any = None

    @property
    def kind(self) -> str:
        return next(k for k in KINDS if getattr(self, k) is not None)

    @property
    def target(self):
        return getattr(self, self.kind)

    def raw(self) -> dict:
        """The query as written, for dyncli.queries."""
        return {k: getattr(self, k) for k in KINDS + QUALIFIERS if getattr(self, k) is not None}


#: the fields of a query, by name (the conversion copies each)
QUERY_FIELDS = KINDS + QUALIFIERS


@dataclass(frozen=True, slots=True)
class Setup:
    """A body on a line with acceleration ``a`` = a(t, s, v) [m/s²] (plus the springs' k/m terms),
    from s1 [m] with v1 [m/s] at t1 [s]; ``find``: the queries, searched up to t1 + t_max [s];
    m [kg] (needed with springs); ``params``: the input's parameters (for the §11 queries' texts);
    ``labels``: how each query is named in warnings (None: ``find[i]``)."""

    a: Any
    t1: float = 0.0
    s1: float = 0.0
    v1: float = 0.0
    find: tuple[Query, ...] = ()
    t_max: float = 1000.0
    m: float | None = None
    springs: tuple[Spring, ...] = ()
    params: Mapping[str, Any] = field(default_factory=dict)
    accuracy: Accuracy = Accuracy()
    labels: tuple[str, ...] | None = None
