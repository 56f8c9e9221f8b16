"""Input model of ``kinematics`` problems (docs/types/kinematics.md)."""

from __future__ import annotations

from typing import Annotated, Any, Literal, Optional

from pydantic import Field, model_validator

from dyncli.errors import InputError
from dyncli.expr import did_you_mean
from dyncli.fields import Expr, ExprField, FieldSpec, Num, ProblemBase, StrictModel, Times

#: the coordinate names of each system, in basis order
COORDINATES: dict[str, tuple[str, ...]] = {
    "cartesian": ("x1", "x2", "x3"),
    "polar": ("r", "theta"),
    "cylindrical": ("r", "theta", "x3"),
    "spherical": ("R", "theta", "phi"),
}

#: coordinates that may be omitted (taken as 0)
OPTIONAL: dict[str, tuple[str, ...]] = {
    "cartesian": ("x1", "x2", "x3"),
    "polar": (),
    "cylindrical": ("x3",),
    "spherical": (),
}

#: the entries of ``instant`` each system takes (a coordinate, its rate, its second rate)
INSTANT: dict[str, tuple[str, ...]] = {
    c: tuple(f"{n}{d}" for n in COORDINATES[c] for d in ("", "_dot", "_ddot"))
    for c in ("polar", "cylindrical", "spherical")
}
INSTANT["path"] = ("v", "v_dot", "rho")

#: the entries of ``instant`` that must be given (the rates default to 0; x3 to 0; rho to a straight path)
INSTANT_REQUIRED: dict[str, tuple[str, ...]] = {
    "polar": ("r", "theta"), "cylindrical": ("r", "theta"), "spherical": ("R", "theta", "phi"), "path": ("v",),
}


def _n(dim: str, what: str, **kw: Any) -> FieldSpec:
    return Num(dim=dim, description=what, **kw)


class Instant(StrictModel):
    """The state at one instant, as the textbooks give it (polar/cylindrical: r, θ, x3 and their
    first and second rates; spherical: R, θ, φ and their rates; path: v, v̇, ρ)."""

    r: Optional[Annotated[float, _n("length", "polar/cylindrical: r [m]")]] = None
    r_dot: Optional[Annotated[float, _n("velocity", "ṙ [m/s] (default 0)")]] = None
    r_ddot: Optional[Annotated[float, _n("acceleration", "r̈ [m/s²] (default 0)")]] = None
    theta: Optional[Annotated[float, _n("angle", "θ [rad] (polar, cylindrical; spherical: azimuth about e3)")]] = None
    theta_dot: Optional[Annotated[float, _n("angular_velocity", "θ̇ [rad/s] (default 0)")]] = None
    theta_ddot: Optional[Annotated[float, _n("angular_acceleration", "θ̈ [rad/s²] (default 0)")]] = None
    x3: Optional[Annotated[float, _n("length", "cylindrical: x3 [m] (default 0)")]] = None
    x3_dot: Optional[Annotated[float, _n("velocity", "cylindrical: ẋ3 [m/s] (default 0)")]] = None
    x3_ddot: Optional[Annotated[float, _n("acceleration", "cylindrical: ẍ3 [m/s²] (default 0)")]] = None
    R: Optional[Annotated[float, _n("length", "spherical: R [m]")]] = None
    R_dot: Optional[Annotated[float, _n("velocity", "spherical: Ṙ [m/s] (default 0)")]] = None
    R_ddot: Optional[Annotated[float, _n("acceleration", "spherical: R̈ [m/s²] (default 0)")]] = None
    phi: Optional[Annotated[float, _n("angle", "spherical: φ [rad], elevation from the e1-e2 plane")]] = None
    phi_dot: Optional[Annotated[float, _n("angular_velocity", "spherical: φ̇ [rad/s] (default 0)")]] = None
    phi_ddot: Optional[Annotated[float, _n("angular_acceleration", "spherical: φ̈ [rad/s²] (default 0)")]] = None
    v: Optional[Annotated[float, _n("velocity", "path: the speed v = ṡ [m/s], >= 0", ge=0)]] = None
    v_dot: Optional[Annotated[float, _n("acceleration", "path: the rate of change of speed v̇ = s̈ [m/s²] (default 0)")]] = None
    rho: Optional[Annotated[float, _n("length", "path: radius of curvature ρ [m], > 0 (default: a straight path)", gt=0, allow_inf=True)]] = None

    def given(self) -> list[str]:
        return [k for k in type(self).model_fields if getattr(self, k) is not None]

    def jets(self, coords: str) -> dict[str, tuple[float, float, float]]:
        """name -> (q, q̇, q̈) for the coordinates of ``coords`` (absent entries 0)."""
        val = lambda k: getattr(self, k) or 0.0      # noqa: E731
        return {n: (val(n), val(n + "_dot"), val(n + "_ddot")) for n in COORDINATES[coords]}


class Kinematics(ProblemBase):
    """Motion of a point given by its coordinates as functions of time
    (notes §4, §5, §7, §8, §12)."""

    type: Literal["kinematics"]
    coordinates: Literal["cartesian", "polar", "cylindrical", "spherical", "path"] = Field(
        "cartesian",
        description="cartesian (x1, x2, x3), polar (r, theta), cylindrical (r, theta, x3), "
        "spherical (R, theta, phi; theta azimuth about e3, phi elevation from the e1-e2 plane), "
        "path (with instant: v, v_dot, rho)",
    )
    position: Optional[dict[str, Annotated[Expr, ExprField(("t",), description="coordinate as an expression in t")]]] = Field(
        None, description="coordinate name -> expression in t (lengths in m, angles in rad); not with instant"
    )
    instant: Optional[Instant] = Field(
        None, description="the state at one instant instead of position: the coordinates and their "
        "rates (polar, cylindrical, spherical) or v, v_dot, rho (path)"
    )
    at: Annotated[list[float], Times()] = Field(default_factory=list)
    distance: Optional[Annotated[list[float], Times(description="[t1, t2]: distance traveled between these times (4.5)")]] = None
    m: Optional[Annotated[float, Num(gt=0, dim="mass", description="mass: adds the force F = m a")]] = None

    accuracy_methods = ("auto", "quadrature")

    @model_validator(mode="after")
    def _check(self):
        if self.instant is not None:
            return self._check_instant()
        if self.position is None:
            raise InputError("give the motion: position (the coordinates as expressions in t) or instant "
                             "(the state at one instant: e.g. r, r_dot, r_ddot, theta, theta_dot, theta_ddot)",
                             "position")
        if self.coordinates == "path":
            raise InputError("coordinates: path describes the state at one instant: give instant: "
                             "{v, v_dot, rho} instead of position", "position")
        names = COORDINATES[self.coordinates]
        for key in self.position:
            if key not in names:
                hint = did_you_mean(key, names)
                if not hint:
                    low = [n for n in names if n.lower() == str(key).lower()]
                    hint = f" (did you mean '{low[0]}'?)" if low else ""
                other = [c for c, ns in COORDINATES.items() if key in ns and c != self.coordinates]
                extra = f"; '{key}' belongs to {' / '.join(other)} coordinates (set coordinates: {other[0]})" if other and not hint else ""
                raise InputError(
                    f"unknown coordinate '{key}' for {self.coordinates} coordinates{hint}{extra}; "
                    f"give {', '.join(names)}",
                    f"position.{key}",
                )
        missing = [n for n in names if n not in self.position and n not in OPTIONAL[self.coordinates]]
        if missing:
            raise InputError(
                f"{self.coordinates} coordinates need {', '.join(names)}; missing: {', '.join(missing)}",
                "position",
            )
        if not self.position:
            raise InputError(f"give at least one coordinate: {', '.join(names)}", "position")
        if self.distance is not None:
            if len(self.distance) != 2:
                raise InputError(f"distance must be a list [t1, t2] of two times, got {len(self.distance)} value(s)", "distance")
            t1, t2 = self.distance
            if t2 < t1:
                raise InputError(f"distance: t2 = {t2:g} is before t1 = {t1:g}; give [t1, t2] with t1 <= t2", "distance")
        return self

    def _check_instant(self):
        c = self.coordinates
        if self.position is not None:
            raise InputError("give either position (functions of t) or instant (the state at one instant), "
                             "not both", "instant")
        if c not in INSTANT:
            raise InputError(f"instant needs coordinates: polar, cylindrical, spherical or path (here {c}): set "
                             "coordinates, or give position (x1, x2, x3 as expressions in t)", "coordinates")
        names = INSTANT[c]
        for key in self.instant.given():
            if key not in names:
                other = [o for o, ns in INSTANT.items() if key in ns and o != c]
                extra = f"; '{key}' belongs to {' / '.join(other)} (set coordinates: {other[0]})" if other else ""
                raise InputError(f"{c} coordinates take no '{key}' at an instant{extra}; give {', '.join(names)}",
                                 f"instant.{key}")
        missing = [n for n in INSTANT_REQUIRED[c] if getattr(self.instant, n) is None]
        if missing:
            raise InputError(f"{c} coordinates need {', '.join(INSTANT_REQUIRED[c])} at the instant; missing: "
                             f"{', '.join(missing)} (the rates default to 0)", "instant")
        if self.at:
            raise InputError("with instant the results are at that one instant: remove at "
                             "(at lists times of a motion given by position)", "at")
        if self.distance is not None:
            raise InputError("the distance travelled needs the motion over time: give position (functions of t) "
                             "instead of instant", "distance")
        return self
