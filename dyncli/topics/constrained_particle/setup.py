"""A particle on a curve in plain numbers (notes §16 problem II, §18): what the curve, the routes
and the queries below ``solver.py`` read, as small frozen dataclasses of SI floats and compiled
expressions — built from the validated input by :func:`dyncli.topics.constrained_particle.solver.plain`,
or by hand (``curve``: three expressions of q from :func:`dyncli.expr.parse`).  Force terms and the
accuracy block are ``particle``'s (:mod:`dyncli.topics.particle.setup`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

from dyncli.topics.particle.setup import Accuracy, ForceTerm


@dataclass(frozen=True, slots=True)
class Rotation:
    """The curve turns about the fixed unit ``axis`` through the origin at the rate ω(t) [rad/s]
    (an expression in t; None: only steady queries, which find the rate)."""

    axis: tuple[float, float, float] = (0.0, 0.0, 1.0)
    omega: Any = None


@dataclass(frozen=True, slots=True)
class Setup:
    """A particle of mass m [kg] on the curve y(q) = (x1, x2, x3)(q) [m] of its frame, from q0 with
    q̇0 [1/s]; ``q_range``: the ends of the wire, or None; ``steady``: the q of each steady query."""

    m: float
    curve: tuple
    rotation: Rotation | None = None
    q0: float = 0.0
    q_dot0: float = 0.0
    forces: tuple[ForceTerm, ...] = ()
    q_range: tuple[float, float] | None = None
    t_end: float | None = None
    at: tuple[float, ...] = ()
    g: float = 9.81
    find: tuple = ()
    params: Mapping[str, Any] = field(default_factory=dict)
    steady: tuple[float, ...] = ()
    accuracy: Accuracy = Accuracy()
    steady_only: bool = False
