"""Oracle cases: the kinematics of points and of rigid bodies at one instant, and force fields
(kinematics, rotating-frame, rigid-velocity, angular-velocity, screw, contact, force-field), at
huge and tiny scales (lengths 1e-8 … 1e8 m, rates 1e-9 … 1e8), where an absolute threshold
would decide wrongly."""

from __future__ import annotations

import mpmath as mp

from tests.oracle.common import EPS, case, closed, cross, dot, estimated, norm, same, vclosed, vec, x


def _kinematics():
    a, w, c, T = x(1e-8), x(1e8), x(3e-9), x(3e-8)
    th = x(1e8 * 3e-8)                      # dyncli's θ = w t at t = 3e-8 is this double ± ε
    speed = mp.sqrt((a * w) ** 2 + (c * w) ** 2)
    checks = [closed("speed.1", speed), closed("rho.1", a + c ** 2 / a, cond=2),
              closed("a_basis.1.0", -a * w ** 2), closed("v_basis.1.1", a * w), closed("v_basis.1.2", c * w)]
    checks += vclosed("x.1", [a * mp.cos(th), a * mp.sin(th), c * w * T], cond=8, reason="θ = fl(w t) to 2 ulp")
    checks.append(estimated("distance", speed * x(5e-8), speed * x(5e-8), reason="the quadrature of the speed"))
    helix = case("tiny fast helix", "kinematics", {
        "coordinates": "cylindrical", "position": {"r": "1e-8", "theta": "1e8*t", "x3": "3e-9*1e8*t"},
        "at": [0, 3e-8], "distance": [0, 5e-8]}, checks,
        "a helix of radius 1e-8 m at 1e8 rad/s, times 1e-8 s: v ~ 1 m/s, a ~ 1e8 m/s², rho ~ 1e-8 m")
    r, rd, rdd, td, tdd = x(1e8), x(3), x(-2e-8), x(1e-8), x(5e-17)
    ab = [rdd - r * td ** 2, r * tdd + 2 * rd * td, 0]
    polar = case("huge slow polar instant", "kinematics", {
        "coordinates": "polar", "instant": {"r": 1e8, "r_dot": 3, "r_ddot": -2e-8, "theta": 0.5,
                                            "theta_dot": 1e-8, "theta_ddot": 5e-17}},
        [closed("a_basis.0", ab[0], scale=norm(ab), cond=2), closed("a_basis.1", ab[1], scale=norm(ab), cond=2),
         closed("v_basis.1", r * td), closed("speed", mp.sqrt(rd ** 2 + (r * td) ** 2))],
        "r = 1e8 m turning at 1e-8 rad/s: accelerations ~ 1e-8 m/s² from terms of 1e-8 and 6e-8")
    return [helix, polar]


def _rotating_frame():
    # ω = [0, 0, 1e8 t], p = [1e-8 + 2e-8 t, 3e-9 t², 0] at t = 1e-8
    t = x(1e-8)
    W, Wd = vec([0, 0, x(1e8) * t]), vec([0, 0, x(1e8)])
    p = [x(1e-8) + x(2e-8) * t, x(3e-9) * t ** 2, 0]
    dp, d2p = [x(2e-8), 2 * x(3e-9) * t, 0], [0, 2 * x(3e-9), 0]
    cor, cen = [2 * q for q in cross(W, dp)], cross(W, cross(W, p))
    pdd = [d2p[i] + cross(Wd, p)[i] + cor[i] + cen[i] for i in range(3)]
    sc = max(norm(d2p), norm(cross(Wd, p)), norm(cor), norm(cen))
    checks = (vclosed("coriolis.0", cor, cond=4) + vclosed("centripetal.0", cen, cond=4)
              + vclosed("p_ddot.0", pdd, scale=sc, cond=8, reason="a sum of four terms"))
    return [case("tiny point in a fast frame", "rotating-frame", {
        "omega": ["0", "0", "1e8*t"], "p": ["1e-8 + 2e-8*t", "3e-9*t**2", "0"], "at": [1e-8]}, checks,
        "p ~ 1e-8 m in a frame at ω = 1 rad/s with ω̇ = 1e8 rad/s², t = 1e-8 s")]


def _rigid_velocity():
    vB, aB, xc = vec([x(2), 0, 0]), vec([x(3), 0, 0]), vec([0, x(-1e-8), 0])
    r2 = dot(xc, xc)
    W = [q / r2 for q in cross(vB, xc)]
    Al = [q / r2 for q in cross(aB, xc)]
    top = vec([0, x(1e-8), 0])

    def va(p):
        v = [vB[i] + cross(W, p)[i] for i in range(3)]
        a = [aB[i] + cross(Al, p)[i] + cross(W, cross(W, p))[i] for i in range(3)]
        return v, a
    vt, at_ = va(top)
    vc, ac = va(xc)
    checks = (vclosed("v.top", vt) + vclosed("a.top", at_, scale=norm(at_), cond=2)
              + vclosed("v.contact", vc, scale=norm(vB), cond=2, reason="v_C = 0 from terms of 2 m/s")
              + vclosed("a.contact", ac, cond=2) + vclosed("omega", W))
    return [case("tiny rolling wheel", "rigid-velocity", {
        "vB": [2, 0, 0], "aB": [3, 0, 0], "rolling": {"contact": [0, -1e-8, 0]},
        "points": {"contact": [0, -1e-8, 0], "top": [0, 1e-8, 0]}}, checks,
        "a wheel of radius 1e-8 m rolling at 2 m/s: ω = 2e8 rad/s, the contact's a = 4e8 m/s²")]


def _angular_velocity():
    W, vB = vec([x(3e7), x(-1e8), x(5e7)]), vec([x(0.1), x(0.2), x(0.3)])
    pts = {"B": [0, 0, 0], "A": [1e-8, 0, 0], "C": [0, 2e-8, 1e-8]}
    doc = {}
    for k, p in pts.items():
        v = [vB[i] + cross(W, vec([x(c) for c in p]))[i] for i in range(3)]
        doc[k] = {"x": p, "v": [float(c) for c in v]}
    # the reference from the rounded velocities: least squares of ω × x_P/B = v_P − v_B
    rows, rhs = [], []
    for k in ("A", "C"):
        xp, dv = vec([x(c) for c in doc[k]["x"]]), [x(doc[k]["v"][i]) - x(doc["B"]["v"][i]) for i in range(3)]
        rows += [[0, xp[2], -xp[1]], [-xp[2], 0, xp[0]], [xp[1], -xp[0], 0]]
        rhs += dv
    A, b = mp.matrix(rows), mp.matrix(rhs)
    om = mp.lu_solve(A.T * A, A.T * b)
    om = [om[i] for i in range(3)]
    checks = vclosed("omega", om, cond=64, reason="ω from velocity differences ~ 1 m/s rounded beside v_B ~ 0.3 m/s")
    return [case("tiny fast body", "angular-velocity", {"points": doc}, checks,
                 "points 1e-8 m apart, ω ~ 1e8 rad/s: a relative rigidity test must still say rigid",
                 same_=[same("rigid", True), same("omega_in_plane", False)])]


def _screw():
    W, vB, xB = vec([x(1e-9), x(2e-9), x(2e-9)]), vec([x(3e8), 0, x(1e8)]), vec([x(1e8), x(1), 0])
    w2 = dot(W, W)
    adv = dot(vB, W) / mp.sqrt(w2)
    xD = [xB[i] + cross(W, vB)[i] / w2 for i in range(3)]
    slow = case("slow screw, huge speeds", "screw", {"omega": [1e-9, 2e-9, 2e-9], "vB": [3e8, 0, 1e8],
                                                     "xB": [1e8, 1, 0]},
                [closed("advance_speed", adv), closed("pitch", adv / mp.sqrt(w2))] + vclosed("xD", xD, cond=4),
                "ω ~ 1e-9 rad/s, v ~ 1e8 m/s: the axis 1e17 m away",
                same_=[same("pure_translation", False)])
    W2, v2 = vec([0, 0, x(1e-8)]), vec([x(1e8), 0, 0])
    ic = [cross(W2, v2)[i] / dot(W2, W2) for i in range(3)]
    planar = case("planar, slow turn", "screw", {"omega": [0, 0, 1e-8], "vB": [1e8, 0, 0]},
                  vclosed("instant_center", ic) + [closed("advance_speed", 0, scale=norm(v2))],
                  "plane motion at ω = 1e-8 rad/s, v = 1e8 m/s: the instant centre 1e16 m away",
                  same_=[same("pure_translation", False)])
    return [slow, planar]


def _contact():
    v1, w1, r1 = vec([x(-1), 0, 0]), vec([0, 0, x(1e8)]), vec([0, x(-1e-8), 0])
    vM1 = [v1[i] + cross(w1, r1)[i] for i in range(3)]
    checks = vclosed("vM1", vM1, scale=1, cond=2, reason="v_M = 0 from terms of 1 m/s") + \
        [closed("slip_speed", norm(vM1), scale=1, cond=2)]
    return [case("tiny fast rolling disk", "contact", {
        "body1": {"v": [-1, 0, 0], "omega": [0, 0, 1e8], "r": [0, -1e-8, 0]},
        "body2": {"v": [0, 0, 0], "omega": [0, 0, 0], "r": [0, 0, 0]}, "n": [0, -1, 0]}, checks,
        "a disk of radius 1e-8 m rolling at 1 m/s: v_M1 = rounding of 1 m/s; the state must be rolling",
        same_=[same("rolling", True), same("state", "rolling")])]


def _force_field():
    R, T = x(1e8), x(6)
    W = R ** 2 * T                                       # ∮ -x2 dx1 + x1 dx2 = R² T
    big = case("huge circle, non-conservative", "force-field", {
        "F": ["-x2", "x1", "0"], "points": [[1e8, 0, 0]],
        "path": {"x1": "1e8*cos(t)", "x2": "1e8*sin(t)", "x3": "0", "t_span": [0, 6]}},
        [estimated("work", W, W)] + vclosed("curl.0", [0, 0, 2]),
        "F = (−x2, x1, 0) along a circle of radius 1e8 m: work 6e16 J",
        same_=[same("conservative", False)])
    e = x(1e-8)
    U = e ** 3 + e ** 4                                  # V(0) − V(e, e, e), V = −x1² x2 − x1 x3³
    tiny = case("tiny straight path, conservative", "force-field", {
        "F": ["2*x1*x2 + x3**3", "x1**2", "3*x1*x3**2"], "points": [[1e-8, 1e-8, 1e-8]],
        "path": {"x1": "1e-8*t", "x2": "1e-8*t", "x3": "1e-8*t", "t_span": [0, 1]}},
        [estimated("work", U, U, reason="the work's own scale, 1e-24 J")],
        "the field of the template along a path 1e-8 m long: work 1e-24 J, no absolute floor may swallow it",
        same_=[same("conservative", True)])
    return [big, tiny]


def cases():
    return (_kinematics() + _rotating_frame() + _rigid_velocity() + _angular_velocity() + _screw()
            + _contact() + _force_field())


assert EPS > 0
