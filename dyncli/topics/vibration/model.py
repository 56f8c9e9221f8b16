"""Input model of ``vibration`` problems (docs/types/vibration.md, notes §17)."""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal, Optional

from pydantic import Field, field_validator, model_validator

from dyncli.errors import InputError
from dyncli.fields import Find, Num, ProblemBase, StrictModel, Times

MAX_SWEEP_POINTS = 100_000
MAX_RATIO = 1e100   # frequency ratios and ζ beyond this are not physical (and would overflow)


class Base(StrictModel):
    """Base motion s(t) = amplitude·sin(omega·t) (17.26)."""

    amplitude: Annotated[float, Num(dim="length", description="s0: base amplitude [m]")] = Field(...)
    omega: Annotated[float, Num(ge=0, dim="angular velocity", description="ω: base frequency [rad/s], >= 0")] = Field(...)


class Force(StrictModel):
    """Force on the mass F(t) = amplitude·sin(omega·t)."""

    amplitude: Annotated[float, Num(dim="force", description="F0: force amplitude [N]")] = Field(...)
    omega: Annotated[float, Num(ge=0, dim="angular velocity", description="ω: forcing frequency [rad/s], >= 0")] = Field(...)


class Unbalance(StrictModel):
    """A rotating unbalance: a mass m0 at eccentricity e turning at ω puts F = m0 e ω² sin(ωt) on the mass."""

    m0: Annotated[float, Num(gt=0, dim="mass", description="the unbalanced mass [kg] (part of m)")] = Field(...)
    e: Annotated[float, Num(gt=0, dim="length", description="its eccentricity (distance from the axis of rotation) [m]")] = Field(...)
    omega: Annotated[float, Num(ge=0, dim="angular velocity", description="ω: the rotation rate [rad/s], >= 0")] = Field(...)


class Sweep(StrictModel):
    """Frequency sweep of the amplification functions over r = ω/ωₙ."""

    ratio: tuple[Annotated[float, Num(ge=0, le=MAX_RATIO)], Annotated[float, Num(ge=0, le=MAX_RATIO)]] = Field(..., description="[r_min, r_max], 0 <= r_min < r_max")
    points: int = Field(50, ge=2, le=MAX_SWEEP_POINTS, description="number of ratios, endpoints included")
    spacing: Literal["linear", "log"] = "linear"

    @field_validator("ratio", mode="before")
    @classmethod
    def _pair(cls, v):
        if not isinstance(v, (list, tuple)) or len(v) != 2:
            raise ValueError("expected [r_min, r_max]: a list of 2 frequency ratios ω/ωₙ")
        return v

    @model_validator(mode="after")
    def _check(self):
        lo, hi = self.ratio
        if not lo < hi:
            raise InputError(f"must be [r_min, r_max] with r_min < r_max (got [{lo:g}, {hi:g}])", "sweep.ratio")
        if self.spacing == "log" and lo <= 0:
            raise InputError(f"log spacing needs r_min > 0 (got {lo:g}): start the ratios above 0, or use spacing: linear",
                             "sweep.ratio")
        return self


class Vibration(ProblemBase):
    """Spring–mass–damper with optional base excitation (notes §17)."""

    type: Literal["vibration"]
    m: Annotated[float, Num(gt=0, dim="mass", description="mass [kg]")] = Field(...)
    k: Annotated[float, Num(gt=0, dim="stiffness", description="spring constant [N/m]")] = Field(...)
    c: Optional[Annotated[float, Num(ge=0, dim="damping", description="damping coefficient [N·s/m] (default 0; not with zeta)")]] = None
    zeta: Optional[Annotated[float, Num(ge=0, le=MAX_RATIO, description="damping ratio ζ = c/(2mωₙ) (not with c)")]] = None
    L: Annotated[float, Num(dim="length", description="free length of the spring [m]")] = 0.0
    x0: Optional[Annotated[float, Num(dim="length", description="initial position of the mass [m] (default L)")]] = None
    v0: Annotated[float, Num(dim="velocity", description="initial velocity of the mass [m/s]")] = 0.0
    base: Optional[Base] = None
    force: Optional[Force] = Field(None, description="force on the mass F(t) = amplitude·sin(omega·t) (not with base)")
    unbalance: Optional[Unbalance] = Field(None, description="a rotating unbalance: F = m0·e·omega²·sin(omega·t) on "
                                           "the mass, m the total mass (m0 included); not with base or force")
    at: Annotated[list[float], Times(from_zero=True, description="times t >= 0 [s] at which to report x, v, w")] = Field(default_factory=list)
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {x: VALUE}}, {max: x}, {min: v}")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries)")]] = None
    sweep: Optional[Sweep] = None

    accuracy_methods = ("auto", "closed-form", "ode", "DOP853")

    @model_validator(mode="after")
    def _check(self):
        if self.c is not None and self.zeta is not None:
            raise InputError("give the damping as either c or zeta, not both", "zeta")
        omega_n = math.sqrt(self.k / self.m) if self.k / self.m < math.inf else math.inf
        if not (0.0 < omega_n < math.inf):
            raise InputError(f"k/m = {self.k:g}/{self.m:g} gives a natural frequency that is not a finite positive number", "k")
        if self.c is not None and not math.isfinite(self.c / (2.0 * math.sqrt(self.k) * math.sqrt(self.m))):
            raise InputError("c/(2√(km)) overflows", "c")
        if self.zeta is not None and not math.isfinite(2.0 * self.m * self.zeta * omega_n):
            raise InputError("c = 2mζωₙ overflows", "zeta")
        if self.c is not None and self.c / (2.0 * math.sqrt(self.k) * math.sqrt(self.m)) > MAX_RATIO:
            raise InputError(f"ζ = c/(2√(km)) must be <= {MAX_RATIO:g}", "c")
        if self.force is not None:
            if self.base is not None:
                raise InputError("give either base (base motion) or force (force on the mass), not both", "force")
            if self.force.omega / omega_n > MAX_RATIO:
                raise InputError(f"ω/ωₙ must be <= {MAX_RATIO:g}", "force.omega")
            if not math.isfinite(self.force.amplitude / self.m):
                raise InputError("F0/m overflows", "force.amplitude")
        if self.unbalance is not None:
            self._check_unbalance(omega_n)
        if self.base is not None:
            if self.base.omega / omega_n > MAX_RATIO:
                raise InputError(f"ω/ωₙ must be <= {MAX_RATIO:g}", "base.omega")
            if not math.isfinite(self.base.amplitude * self.base.omega * self.base.omega):
                raise InputError("amplitude·ω² overflows", "base")
        return self

    def _check_unbalance(self, omega_n: float) -> None:
        u = self.unbalance
        assert u is not None                 # called when unbalance is given
        for other in ("base", "force"):
            if getattr(self, other) is not None:
                raise InputError(f"give one excitation: unbalance (a rotating unbalance) or {other}, not both; "
                                 f"for an unbalanced machine on a moving base, solve the two and add them (linear)",
                                 "unbalance")
        if u.m0 > self.m:
            raise InputError(f"m0 = {u.m0:g} kg exceeds m = {self.m:g} kg: m is the total mass of the machine, "
                             "the unbalanced mass m0 included (give m as that total)", "unbalance.m0")
        if u.omega / omega_n > MAX_RATIO:
            raise InputError(f"ω/ωₙ must be <= {MAX_RATIO:g}", "unbalance.omega")
        if not math.isfinite(u.m0 * u.e * u.omega * u.omega / self.m):
            raise InputError("m0·e·ω²/m overflows", "unbalance")
