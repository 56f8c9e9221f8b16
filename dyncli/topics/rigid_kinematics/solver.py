"""Rigid-body kinematics (notes §13, §14, §15) — closed forms in plain
Python (no numpy, scipy or sympy; no input-model imports)."""

from __future__ import annotations

import math
from typing import Any

from dyncli.errors import InputError
from dyncli.result import Result, SolveOptions
from dyncli.topics.rigid_kinematics import equations as eq
from dyncli.topics.rigid_kinematics.equations import Vec, add, cross, dot, mul, norm, sub  # noqa: F401

#: angular-velocity: the data are rigid (13.7) when, for every pair of points,
#: |v_P/Q · e_P/Q| <= RIGID_TOL · max(max |v_P/Q|, NOISE_FLOOR · max |v_P|):
#: the rate of change of each distance relative to the largest relative
#: speed; relative speeds below NOISE_FLOOR of the absolute speeds are
#: rounding noise of the subtraction v_P − v_Q and do not count as motion.
RIGID_TOL = 1e-6
NOISE_FLOOR = 1e-9
#: three points are collinear when |x_A/B × x_C/B| <= COLLINEAR_TOL·|x_A/B||x_C/B|
COLLINEAR_TOL = 1e-12
#: screw: planar motion (instant center exists) when |v_B·e_ω| <= PLANAR_TOL·|v_B|
PLANAR_TOL = 1e-12
#: contact: a velocity component counts as zero when below CONTACT_TOL times
#: the velocity scale max(|v1|, |ω1||r1|, |v2|, |ω2||r2|)
CONTACT_TOL = 1e-10


def _finite(x: Any) -> bool:
    if isinstance(x, float):
        return math.isfinite(x)
    if isinstance(x, (list, tuple)):
        return all(_finite(c) for c in x)
    if isinstance(x, dict):
        return all(_finite(c) for c in x.values())
    return True


def _out(res: Result, name: str, value: Any) -> None:
    """Store a result; a non-finite value (overflow) becomes null + warning."""
    if isinstance(value, tuple):
        value = [c + 0.0 for c in value]  # + 0.0: no -0.0
    elif isinstance(value, float):
        value += 0.0
    if not _finite(value):
        res.warn(f"{name} overflows (the input magnitudes are too large): reported as null")
        value = None
    res.results[name] = value


# ---------------------------------------------------------------------------
# rigid-velocity (13.8, 13.9)


def solve_rigid_velocity(p, options: SolveOptions | None = None) -> Result:
    res = Result({}, method="closed-form", equations=["13.8", "13.9"])
    w, al = p.omega, p.alpha
    if p.rolling is not None:            # v_C = 0 at the contact (15.9): ω, ω̇ from the centre's motion
        w, al = eq.rolling_rates(p.vB, p.aB, p.rolling.contact)
        _out(res, "omega", w)
        _out(res, "alpha", al)
        res.equations.append("15.9")
    elif p.rotations is not None:        # ω = Ω + ω_rel, ω̇ = Ω̇ + δω_rel/δt + Ω × ω_rel, down the chain
        w, al, coupling = eq.nested_rates([(r.omega, r.omega_dot) for r in p.rotations])
        _out(res, "omega", w)
        _out(res, "alpha", al)
        _out(res, "alpha_coupling", coupling)
        res.equations.append("11.7")
    v_out, a_out = {}, {}
    for name, x in p.points.items():
        v_out[name] = [c + 0.0 for c in eq.rigid_velocity(p.vB, w, x)]                # (13.8)
        a_out[name] = [c + 0.0 for c in eq.rigid_acceleration(p.aB, al, w, x)]        # (13.9)
    _out(res, "v", v_out)
    _out(res, "a", a_out)
    return res


# ---------------------------------------------------------------------------
# angular-velocity (13.13, 13.17, 13.20, check 13.7)


def rigid_residual(points: dict) -> tuple[float, str | None]:
    """max over pairs of |v_P/Q · e_P/Q| / max(max |v_P/Q|, NOISE_FLOOR·max |v_P|)
    (0 when nothing moves relative to anything) and the worst pair."""
    names = list(points)
    rel = []
    vmax = 0.0
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            P, Q = points[names[i]], points[names[j]]
            x = sub(P.x, Q.x)
            v = sub(P.v, Q.v)
            rel.append((names[i], names[j], x, v))
            vmax = max(vmax, norm(v))
    worst, pair = 0.0, None
    vmax = max(vmax, NOISE_FLOOR * max(norm(P.v) for P in points.values()))
    if vmax == 0.0:
        return 0.0, None
    for a, b, x, v in rel:
        L = norm(x)
        if not L * vmax > 0:            # (coincident points, or a product below the doubles: no direction)
            continue
        r = abs(dot(v, x)) / (L * vmax)
        if r > worst:
            worst, pair = r, f"{a}-{b}"
    return worst, pair


def solve_angular_velocity(p, options: SolveOptions | None = None) -> Result:
    pts = p.points
    names = list(pts)
    res = Result({}, method="closed-form")
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            if sub(pts[names[i]].x, pts[names[j]].x) == (0.0, 0.0, 0.0):
                raise InputError(f"points {names[i]} and {names[j]} are at the same position: "
                                 "their velocities give no information on ω; give points at distinct positions",
                                 f"points.{names[j]}.x")
    B = pts[names[0]]
    if len(names) == 2:
        A = pts[names[1]]
        x = sub(A.x, B.x)
        v = sub(A.v, B.v)
        omega_n = eq.normal_angular_velocity(x, v)                                      # (13.20)
        if not all(math.isfinite(c) for c in omega_n):
            raise InputError(f"ω overflows a double: points {names[0]} and {names[1]} are too close for these "
                             "velocities (13.20 divides by |x_A/B|²)", f"points.{names[1]}.x")
        _out(res, "omega_n", omega_n)
        res.equations = ["13.20", "13.7"]
    else:
        A, C = pts[names[1]], pts[names[2]]
        xA, xC = sub(A.x, B.x), sub(C.x, B.x)
        vA, vC = sub(A.v, B.v), sub(C.v, B.v)
        N = cross(xA, xC)
        nN = norm(N)
        if nN <= COLLINEAR_TOL * norm(xA) * norm(xC):
            raise InputError(
                f"points {', '.join(names)} are collinear: the velocities of points on one line cannot "
                "determine the component of ω along that line (13.14: x_A/B × x_C/B = 0); give a third "
                "point off the line, or only two points for omega_n (13.20)", f"points.{names[2]}.x")
        # ω on the basis (x_A/B, x_C/B, N): ω·N = v_A/B·x_C/B (13.14) and the
        # in-plane part from the N-components of v_A/B, v_C/B (13.15-13.16)
        D = dot(vA, xC)
        omega = eq.three_point_angular_velocity(xA, xC, vA, vC, N, nN)     # (13.13-13.17)
        if not all(math.isfinite(c) for c in omega):
            raise InputError(f"ω overflows a double: points {', '.join(names)} are too close to each other or "
                             "to collinear for these velocities (13.13-13.17 divide by |x_A/B × x_C/B|)",
                             f"points.{names[2]}.x")
        in_plane = abs(D) <= 1e-9 * norm(vA) * norm(xC) or norm(vA) == 0.0
        res.equations = (["13.17", "13.15", "13.16"] if in_plane else ["13.13", "13.14"]) + ["13.7"]
        _out(res, "omega", omega)
        res.results["omega_in_plane"] = in_plane
    resid, pair = rigid_residual(pts)
    rigid = resid <= RIGID_TOL
    res.results["rigid"] = rigid
    res.results["rigid_residual"] = resid
    if not rigid:
        res.warn(f"the data are not those of a rigid body: v_P/Q·x_P/Q ≠ 0 (13.7) for points {pair} "
                 f"(relative residual {resid:.3g} > {RIGID_TOL:g}); the angular velocity is only a best guess")
    return res


# ---------------------------------------------------------------------------
# screw (14.1-14.9)


def solve_screw(p, options: SolveOptions | None = None) -> Result:
    w, vB, xB = p.omega, p.vB, p.xB
    res = Result({}, method="closed-form", equations=["14.1", "14.3", "14.4", "14.7"])
    wn = norm(w)
    if wn == 0.0:
        speed = norm(vB)
        res.results.update({"e_omega": None, "advance_speed": speed, "xD": None, "pitch": None,
                            "instant_center": None, "pure_translation": True})
        res.warn("ω = 0: pure translation (every point moves with v_B); the screw axis is undefined "
                 "(e_omega, xD, instant_center are null) and the pitch is infinite (null); "
                 "advance_speed is |v_B|")
        return res
    e = eq.unit(w)
    adv = dot(vB, e)                                                   # (14.3)
    xDB = eq.screw_axis_offset(e, vB, wn)                              # (14.7c): ω×v_B/ω²
    xD = add(xB, xDB)
    _out(res, "e_omega", e)
    _out(res, "advance_speed", adv)
    _out(res, "xD", xD)
    _out(res, "pitch", adv / wn)
    res.results["pure_translation"] = False
    if abs(adv) <= PLANAR_TOL * norm(vB):
        res.equations.append("14.9")
        _out(res, "instant_center", xD)                                # (14.9)
    else:
        res.results["instant_center"] = None
        res.warn("instant_center is null: v_B has a component along ω (v_B·e_ω ≠ 0), so the motion is not "
                 "planar and no point is at rest; the points of the screw axis move with advance_speed·e_ω (14.4)")
    return res


# ---------------------------------------------------------------------------
# contact (15.8, 15.9)


def solve_contact(p, options: SolveOptions | None = None) -> Result:
    b1, b2 = p.body1, p.body2
    n = eq.unit(p.n, "n", "n")
    vM1 = eq.rigid_velocity(b1.v, b1.omega, b1.r)                      # (13.8) at the contact point
    vM2 = eq.rigid_velocity(b2.v, b2.omega, b2.r)
    vrel, approach, slip = eq.contact_split(vM1, vM2, n)               # (15.8), (15.9)
    slip_speed = norm(slip)
    scale = max(norm(b1.v), norm(b1.omega) * norm(b1.r), norm(b2.v), norm(b2.omega) * norm(b2.r))
    tol = CONTACT_TOL * scale
    if approach < -tol:
        state = "separating"
    elif approach > tol:
        state = "approaching"
    elif slip_speed <= tol:
        state = "rolling"
    else:
        state = "slipping"
    res = Result({}, method="closed-form", equations=["15.8", "15.9"])
    _out(res, "vM1", vM1)
    _out(res, "vM2", vM2)
    _out(res, "v_rel", vrel)
    _out(res, "approach", approach)
    _out(res, "slip", slip)
    _out(res, "slip_speed", slip_speed)
    res.results["rolling"] = state == "rolling"
    res.results["state"] = state
    if state == "approaching":
        res.warn("the material points approach each other (v_rel·n > 0): bodies already in contact would "
                 "interpenetrate, i.e. this is an impact; separated bodies are closing in")
    return res
