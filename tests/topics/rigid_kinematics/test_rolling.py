"""rigid-velocity `rolling: {contact}` (issue 27): ω and ω̇ of a disk rolling without slip from its
centre's motion.  References: the hand derivation of the gallery file (a wheel inside a circular
track), and a second route: the motion of a disk rolling on a line, inside and outside a circle
written as positions in t (θ from the arc lengths rolled), differentiated by sympy, with the
material points' velocities and accelerations compared with (13.8)-(13.9) at ω, ω̇ from rolling."""

from __future__ import annotations

import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

TOL = 1e-12


def close(a, b, tol=TOL):
    assert len(a) == len(b) and all(abs(x - y) <= tol * max(1.0, abs(y)) for x, y in zip(a, b)), (a, b)


def test_gallery_wheel_in_a_track_by_hand():
    (rec,) = solve_path(PROBLEMS / "kinematics" / "rolling-in-a-track.yaml")
    r = rec["results"]
    rad, R, v, at = 0.1, 0.5, 2.0, 1.0
    w = v / rad
    assert r["omega"] == [0.0, 0.0, -w] and r["alpha"] == [0.0, 0.0, -at / rad]
    close(r["v"]["contact"], [0, 0, 0])
    close(r["a"]["contact"], [0, w * w * rad * R / (R - rad), 0])        # the contact point's a, toward B
    close(r["v"]["top"], [2 * v, 0, 0])
    close(r["a"]["top"], [2 * at, v * v / (R - rad) - w * w * rad, 0])
    assert "15.9" in rec["equations"]


def _sympy_route(kind, psi0, psi1, psi2, rad=0.3, R=1.2, spin0=0.4):
    """(vB, aB, contact, ω_z, ω̇_z, {name: (x_P/B, v_P, a_P)}) at t = 0 of a disk of radius rad
    rolling on a line (kind 'line': the centre at s(t) along e1), inside ('in') or outside ('out')
    a fixed circle of radius R (the centre at the angle ψ(t)); s or ψ = psi0 + psi1 t + psi2 t²/2."""
    import sympy as sp

    t = sp.symbols("t")
    q = psi0 + psi1 * t + psi2 * t ** 2 / 2
    if kind == "line":
        B = sp.Matrix([q, rad, 0])
        out = sp.Matrix([0, -1, 0])                  # from B toward the contact
        theta = -q / rad + spin0                     # rolling to +e1 turns clockwise
    else:
        rho = R - rad if kind == "in" else R + rad
        u = sp.Matrix([sp.sin(q), -sp.cos(q), 0])    # from the circle's centre toward B
        B = rho * u
        out = u if kind == "in" else -u
        theta = (-(rho / rad) if kind == "in" else rho / rad) * q + spin0
    rot = sp.Matrix([[sp.cos(theta), -sp.sin(theta), 0], [sp.sin(theta), sp.cos(theta), 0], [0, 0, 1]])
    body = {"rim": (rad, 0.7), "inner": (0.5 * rad, -2.0), "centre-ish": (0.05 * rad, 1.0)}
    pts = {}
    for name, (d, ang) in body.items():
        xP = B + rot * sp.Matrix([d * sp.cos(ang), d * sp.sin(ang), 0])
        xr = xP - B
        pts[name] = [[float(c.subs(t, 0)) for c in m] for m in (xr, xP.diff(t), xP.diff(t, 2))]
    # the material point at the contact has no velocity (the reference's own check of θ(t))
    c_now = [float(c.subs(t, 0)) for c in rad * out]
    ang_c = sp.atan2(c_now[1], c_now[0]) - theta.subs(t, 0)
    xC = B + rot * sp.Matrix([rad * sp.cos(ang_c), rad * sp.sin(ang_c), 0])
    assert all(abs(float(c.diff(t).subs(t, 0))) < 1e-12 for c in xC)
    f = lambda e: [float(c.subs(t, 0)) for c in e]        # noqa: E731
    return f(B.diff(t)), f(B.diff(t, 2)), c_now, float(theta.diff(t).subs(t, 0)), \
        float(theta.diff(t, 2).subs(t, 0)), pts


def _yaml(vB, aB, c, pts):
    body = "\n".join(f"  {n}: {list(x)!r}" for n, (x, _, _) in pts.items())
    return (f"type: rigid-velocity\nvB: {vB!r}\naB: {aB!r}\nrolling: {{contact: {c!r}}}\n"
            f"points:\n{body}\n")


@pytest.mark.parametrize("kind", ["line", "in", "out"])
@pytest.mark.parametrize("psi", [(0.3, 1.7, -0.6), (2.5, -0.8, 3.0), (-1.0, 0.0, 2.0)])
def test_against_the_motion_differentiated(kind, psi):
    vB, aB, c, wz, wdz, pts = _sympy_route(kind, *psi)
    r = solve_one_text(_yaml(vB, aB, c, pts))["results"]
    close(r["omega"], [0, 0, wz])
    close(r["alpha"], [0, 0, wdz])
    for name, (_, v, a) in pts.items():
        close(r["v"][name], v)
        close(r["a"][name], a)


def test_inclined_plane_and_a_plane_off_the_axes():
    """A disk rolling down a 30° incline: ω = v/r about the normal of the plane of motion, from
    vectors with cos/sin rounding (the tolerance of 'parallel to the surface' is relative)."""
    text = ("type: rigid-velocity\nvB: [3*cos(pi/6), -3*sin(pi/6), 0]\naB: [2*cos(pi/6), -2*sin(pi/6), 0]\n"
            "rolling: {contact: [-0.2*sin(pi/6), -0.2*cos(pi/6), 0]}\npoints: {C: [-0.2*sin(pi/6), -0.2*cos(pi/6), 0]}\n")
    r = solve_one_text(text)["results"]
    close(r["omega"], [0, 0, -3 / 0.2])
    close(r["alpha"], [0, 0, -2 / 0.2])
    close(r["v"]["C"], [0, 0, 0], 1e-14)


@pytest.mark.parametrize("text,field,fix", [
    ("vB: [1, 0, 0]\nomega: [0, 0, 1]\nrolling: {contact: [0, -1, 0]}\n", "omega", "not both"),
    ("vB: [1, 0, 0]\nalpha: [0, 0, 0]\nrolling: {contact: [0, -1, 0]}\n", "alpha", "not both"),
    ("vB: [1, 0.5, 0]\nrolling: {contact: [0, -1, 0]}\n", "vB", "vB·x_C/B = 0"),
    ("vB: [1, 0, 0]\naB: [0, 0, 2]\nrolling: {contact: [0, -1, 0]}\n", "aB", "in the plane of vB and x_C/B"),
    ("vB: [1, 0, 0]\nrolling: {contact: [0, 0, 0]}\n", "rolling.contact", ""),
    ("vB: [1, 0, 0]\n", "omega", "rolling: {contact"),
    ("vB: [1, 0, 0]\nrolling: {contact: [0, -1, 0], radius: 1}\n", "rolling.radius", "unknown field"),
])
def test_invalid_rolling(text, field, fix):
    msg = error_of("type: rigid-velocity\n" + text + "points: {P: [0, 1, 0]}\n")
    assert f" {field}:" in msg and fix in msg, msg
