"""Input model of ``rectilinear`` problems (docs/types/rectilinear.md)."""

from __future__ import annotations

from typing import Annotated, Any, ClassVar, Literal, Optional

from pydantic import Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import Expr, ExprField, Num, ProblemBase, StrictModel
from dyncli.topics.rectilinear.setup import KINDS
from dyncli.topics.rectilinear.springs import LineSpring


class Query(StrictModel):
    """Exactly one of t (state at time t), v (the first time v is reached), s (the first time s
    is reached) or the queries of every motion (§11): when (with direction, occurrence), max, min
    (with within).  A v or s held at the start counts only when the motion reaches it again; the
    entries of when/max/min are checked where they are answered (dyncli.queries)."""

    unknown_keys: ClassVar[dict[str, str]] = {
        "event": "event queries are for scenes (the events of their one-sided joints); ask when: {v: 0} "
                 "(or {s: S}) for the moment the motion reaches a value",
        "x": "s", "position": "s", "velocity": "v", "time": "t"}

    t: Optional[Annotated[float, Num(dim="time")]] = None
    v: Optional[Annotated[float, Num(dim="velocity")]] = None
    s: Optional[Annotated[float, Num(dim="length")]] = None
    when: Optional[Any] = None
    direction: Optional[Any] = None
    occurrence: Optional[Any] = None
    max: Optional[Any] = None
    min: Optional[Any] = None
    within: Optional[Any] = None

    @model_validator(mode="after")
    def _exactly_one(self):
        given = [k for k in KINDS if getattr(self, k) is not None]
        if len(given) != 1:
            raise ValueError("a query is exactly one of {t: T}, {v: V}, {s: S}, {when: {s: S}}, {max: s} or {min: v}"
                             + (f" (got {', '.join(given)})" if given else ""))
        extra = [k for k in ("direction", "occurrence", "within") if getattr(self, k) is not None]
        allowed = {"when": ("direction", "occurrence"), "max": ("within",), "min": ("within",)}.get(given[0], ())
        bad = [k for k in extra if k not in allowed]
        if bad:
            raise ValueError(f"'{bad[0]}' goes with " + ("when" if bad[0] != "within" else "max or min")
                             + f", not with {given[0]}")
        return self


class Rectilinear(ProblemBase):
    """Straight-line motion with a = a(t, s, v) (notes §6)."""

    unknown_keys: ClassVar[dict[str, str]] = {
        "s0": "s1", "v0": "v1", "t0": "t1", "x0": "s1", "t_end": "t_max", "tmax": "t_max", "mass": "m",
        "at": "the state at a time is a query: find: [{t: T}]", "times": "the state at a time is a query: "
        "find: [{t: T}]", "case": "the notes' case is read from a (a function of t, of v or of s): drop it"}

    type: Literal["rectilinear"]
    a: Annotated[Expr, ExprField(("t", "s", "v"), dim="acceleration", description="acceleration: constant or expression in t, s, v")] = Field(...)
    t1: Annotated[float, Num(dim="time")] = 0.0
    s1: Annotated[float, Num(dim="length")] = 0.0
    v1: Annotated[float, Num(dim="velocity")] = 0.0
    find: list[Query] = Field(default_factory=list, description="queries: {t: T}, {v: V}, {s: S}, {when: {s: S}}, {max: s}, {min: v}")
    t_max: Annotated[float, Num(gt=0, dim="time")] = 1000.0
    m: Optional[Annotated[float, Num(gt=0, dim="mass", description="mass [kg]: needed with springs")]] = None
    springs: list[LineSpring] = Field(
        default_factory=list, max_length=100,
        description="springs along the line, [{k, anchor, L, one_sided}]: their acceleration is added to a")

    @model_validator(mode="after")
    def _springs_need_m(self):
        if self.springs and self.m is None:
            raise InputError("springs need the body's mass m (their acceleration is the force over m): give m", "m")
        return self

    accuracy_methods = ("auto", "closed-form", "quadrature", "ode", "DOP853", "RK45", "Radau", "LSODA")
