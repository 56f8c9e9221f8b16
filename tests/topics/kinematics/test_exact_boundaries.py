"""Yes/no results of rigid kinematics and inertia with exact inputs given
as expressions (issue 16): contact `rolling`, angular-velocity `rigid`,
repeated principal moments.  Each is decided with a tolerance stated on its
page, far above the rounding of such inputs (docs/types/contact.md,
angular-velocity.md, inertia.md); the boundary cases below are exact in the
notes' mathematics."""

from __future__ import annotations

import pytest

from tests.conftest import solve_one_text


@pytest.mark.parametrize("w,r", [("0.3/0.7", "0.7"), ("4", "0.5"), ("1/3", "3"), ("sqrt(2)", "1/sqrt(2)")])
def test_rolling_disk_with_expressions(w, r):
    """(15.9) v = ω r on a floor tilted by π/9: rolling; ω·(1 + 1e-9) slips."""
    def doc(wexpr):
        return ("type: contact\n"
                f"body1: {{v: [\"({w})*(-({r})*cos(pi/9))\", \"-({w})*({r})*sin(pi/9)\", 0], "
                f"omega: [0, 0, \"{wexpr}\"], r: [\"({r})*sin(pi/9)\", \"-({r})*cos(pi/9)\", 0]}}\n"
                "body2: {}\nn: [\"sin(pi/9)\", \"-cos(pi/9)\", 0]\n")
    res = solve_one_text(doc(w))["results"]
    assert res["rolling"] is True and res["state"] == "rolling"
    res = solve_one_text(doc(f"({w})*(1 + 1e-9)"))["results"]
    assert res["rolling"] is False and res["state"] == "slipping"


def test_rigid_points_given_with_trigonometry():
    text = ("type: angular-velocity\npoints:\n  B: {x: [0, 0, 0], v: [0, 0, 0]}\n"
            "  A: {x: [\"cos(pi/7)\", \"sin(pi/7)\", 0], v: [\"-3*sin(pi/7)\", \"3*cos(pi/7)\", 0]}\n"
            "  C: {x: [\"cos(pi/7)\", 0, \"sin(pi/7)\"], v: [0, \"3*cos(pi/7)\", 0]}\n")
    r = solve_one_text(text)["results"]
    assert r["rigid"] is True and r["rigid_residual"] <= 1e-15
    assert r["omega"] == pytest.approx([0, 0, 3], abs=2e-15)
    # a stretch of 1e-5 of the relative speed is not rigid
    bad = text.replace('v: [0, "3*cos(pi/7)", 0]', 'v: ["3e-5", "3*cos(pi/7)", 0]')
    assert solve_one_text(bad)["results"]["rigid"] is False


@pytest.mark.parametrize("part", [
    '{shape: box, mass: 2, size: [a, a, a], at: [0.1, 0.2, 0.3], orientation: {axis: [1, 2, 3], angle: "pi/7"}}',
    '{shape: cylinder, mass: 2, radius: a, height: "sqrt(3)*a", orientation: {axis: [1, 1, 0], angle: "pi/5"}}',
    '{shape: sphere, mass: 2, radius: a, orientation: {axis: [0, 1, 1], angle: "pi/3"}}',
])
def test_isotropic_bodies_have_repeated_moments(part):
    """A cube, a sphere and a cylinder with h = √3 r (m r²/2 = m(3r² + h²)/12)."""
    r = solve_one_text(f"type: inertia\nparams: {{a: 0.3}}\nparts:\n  - {part}\n")["results"]
    pm = r["principal_moments"]
    assert r["principal_axes_unique"] is False
    assert max(pm) - min(pm) <= 4e-16 * max(pm)


def test_rest_points_at_times_given_as_expressions():
    """x = (cos t, sin² t): v = (−sin t, sin 2t) vanishes at t = kπ; at t = pi,
    2*pi (|v| ~ 1e-16 from rounding) e_t, a_t, rho are null like at t = 0."""
    text = 'type: kinematics\nposition: {x1: "cos(t)", x2: "sin(t)**2"}\nat: [0, pi, "pi/2", "2*pi", "pi + 1e-9"]\n'
    rec = solve_one_text(text)
    r = rec["results"]
    assert r["e_t"][0] is None and r["e_t"][1] is None and r["e_t"][3] is None and r["a_t"][1] is None
    assert r["e_t"][2] == pytest.approx([-1, 0, 0], abs=1e-15)
    # 1e-9 after the rest point the point moves: e_t = a/|a| = (1, 2)/√5
    assert r["e_t"][4] == pytest.approx([5 ** -0.5, 2 * 5 ** -0.5, 0], rel=1e-6)
