"""Input model of ``pendulum`` problems (docs/types/pendulum.md)."""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal, Optional

from pydantic import Field, model_validator

from dyncli.errors import InputError
from dyncli.fields import Find, Num, ProblemBase, Times

#: |θ₀| beyond this many radians is no release angle (and its whole turns would lose the fraction)
MAX_ANGLE = 1e6


class Pendulum(ProblemBase):
    """A bob of mass m on a light rod (or string) of length l swinging in a vertical plane."""

    type: Literal["pendulum"]
    l: Annotated[float, Num(gt=0, dim="length", description="length of the pendulum (pivot to bob) [m]")] = Field(...)
    g: Annotated[float, Num(gt=0, dim="acceleration", description="gravitational acceleration [m/s²] (default 9.81)")] = 9.81
    m: Optional[Annotated[float, Num(gt=0, dim="mass", description="mass of the bob [kg]: gives the tension and the energy")]] = None
    theta0: Annotated[float, Num(dim="angle", description="θ(0), from the downward vertical [rad] (write 30*deg for degrees)")] = Field(...)
    theta_dot0: Annotated[float, Num(dim="angular velocity", description="θ̇(0) [rad/s] (default 0: released from rest)")] = 0.0
    at: Annotated[list[float], Times(from_zero=True, description="times t >= 0 [s] at which to report θ, θ̇, the tension and the distance")] = Field(default_factory=list)
    find: Annotated[list[Any], Find()] = Field(default_factory=list, description="queries about the motion (§11): {t: T}, {when: {theta: VALUE}}, {max: theta_dot}, {min: tension}")
    t_end: Optional[Annotated[float, Num(gt=0, dim="time", description="end of the motion `find` searches [s] (default the largest time of at and of the queries, else one period)")]] = None

    @model_validator(mode="after")
    def _check(self):
        if not abs(self.theta0) <= MAX_ANGLE:
            raise InputError(f"|theta0| must be <= {MAX_ANGLE:g} rad (got {self.theta0:g}); give the release "
                             "angle itself (whole turns change nothing)", "theta0")
        w2 = self.g / self.l
        if not (0.0 < w2 < math.inf):
            raise InputError(f"g/l = {self.g:g}/{self.l:g} gives a frequency √(g/l) that is not a finite positive "
                             "number", "l")
        q = self.theta_dot0 / math.sqrt(w2)
        if not math.isfinite(q * q) or not math.isfinite(self.theta_dot0 * self.theta_dot0 * self.l * (self.m or 1.0)):
            raise InputError("θ̇₀/√(g/l) overflows: give a rate whose square (and m l θ̇₀²) is a finite number", "theta_dot0")
        if self.m is not None:
            # the mass scales E = 2 m g l k² and the tension m g (4k² + 3 cos θ − 2), at most
            # m g (1 + 4k²) in size: both doubles (its rate may overflow: the extremes are found by its sign)
            k2 = math.sin(0.5 * self.theta0) ** 2 + 0.25 * q * q
            mg = self.m * self.g
            if not (math.isfinite(2.0 * mg * self.l * k2) and math.isfinite(mg * (1.0 + 4.0 * k2))):
                raise InputError(f"m = {self.m:g} kg puts the energy or the rod's tension beyond the range of a double "
                                 f"(1.8e308): m g l = {self.m:g}·{self.g:g}·{self.l:g}; give a smaller mass (or "
                                 "leave m out: the motion does not depend on it)", "m")
        return self
