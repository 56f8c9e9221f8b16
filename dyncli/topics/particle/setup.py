"""A particle problem in plain numbers (notes §16, §19): what the equations and the routes below
``solver.py`` read, as small frozen dataclasses of SI floats — built from the validated input by
:func:`dyncli.topics.particle.solver.plain`, or by hand in a notebook::

    from dyncli.topics.particle.setup import Accuracy, ForceTerm, Setup
    s = Setup(m=0.5, x0=(0, 0, 0), v0=(20, 0, 20), forces=(ForceTerm("gravity"),), t_end=3.0, at=(1.0, 2.0, 3.0))

The attribute names are the input's (``p.m``, ``f.kind``, ``p.accuracy.rtol``), so the physics reads
either; ``constrained-particle`` uses :class:`ForceTerm` and :class:`Accuracy` too.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

from dyncli.integrators import Accuracy      # the one form of the accuracy controls


@dataclass(frozen=True, slots=True)
class ForceTerm:
    """One force term (§19) of kind ``kind``: the fields of its kind, the others at their defaults.
    ``F``: uniform, 3 floats [N]; custom, 3 compiled expressions of t, x1..x3, v1..v3."""

    kind: str
    F: tuple | None = None
    name: str | None = None
    center: tuple[float, float, float] = (0.0, 0.0, 0.0)
    R0: float | None = None
    g: float | None = None
    anchor: tuple[float, float, float] = (0.0, 0.0, 0.0)
    k: float | None = None
    L: float = 0.0
    one_sided: str | None = None
    c: float | None = None
    power: int = 2
    mu: float | None = None
    N: float | None = None


#: the fields a force entry may carry, by name (the conversion copies those it has)
FORCE_FIELDS = tuple(n for n in ForceTerm.__dataclass_fields__ if n != "kind")


@dataclass(frozen=True, slots=True)
class Setup:
    """A particle of mass m [kg] from x0 [m] with v0 [m/s] under ``forces``, reported at ``at``
    [s] up to ``t_end``; ``g`` [m/s²] for gravity terms; ``steady``: the axes (unit vectors) of the
    steady circular motions asked; ``find``: the §11 queries as given, ``params`` resolved."""

    m: float
    x0: tuple[float, float, float] = (0.0, 0.0, 0.0)
    v0: tuple[float, float, float] = (0.0, 0.0, 0.0)
    forces: tuple[ForceTerm, ...] = ()
    t_end: float | None = None
    at: tuple[float, ...] = ()
    g: float = 9.81
    find: tuple = ()
    params: Mapping[str, Any] = field(default_factory=dict)
    basis: str = "cartesian"
    steady: tuple[tuple[float, float, float], ...] = ()
    accuracy: Accuracy = Accuracy()


def extended(s):
    """``s`` (any setup with ``t_end``, ``find`` and ``params``) with t_end extended to the end of
    every ``within`` window and ``t`` query of its ``find`` (§11: the motion runs as far as the
    queries search), else itself — :func:`dyncli.motion_find.extended` on plain numbers."""
    if not s.find or s.t_end is None:
        return s
    from dataclasses import replace

    from dyncli.expr import constant, resolve_params
    from dyncli.motion_find import search_end

    params = resolve_params(s.params or {})
    end = search_end(float(s.t_end), s.find, lambda x: constant(x, params))
    return replace(s, t_end=end) if end > s.t_end else s
