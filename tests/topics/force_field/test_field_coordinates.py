"""force-field with coordinates: polar | cylindrical | spherical (notes §19,
Tables 19.1-19.2): the gallery file fields-in-coordinates.yaml against values
derived by hand, an independent route (the field turned into Cartesian
components, its Cartesian curl by sympy, projected back on the basis), the
extremes and invalid input."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from tests.conftest import PROBLEMS, error_of, solve_one_text, solve_path

EXACT = 1e-13          # closed forms evaluated in floating point


@functools.lru_cache(maxsize=None)
def gallery():
    recs = solve_path(PROBLEMS / "particle" / "fields-in-coordinates.yaml")
    for r in recs:
        assert r.get("error") is None, r.get("error")
    return recs


def close(a, b, tol=EXACT):
    np.testing.assert_allclose(np.asarray(a, float), np.asarray(b, float), rtol=tol, atol=tol)


def test_gallery_inverse_square_spherical():
    r = gallery()[0]["results"]
    assert r["conservative"] is True and r["potential"] == "-4/R"
    close(r["curl"][0], [0, 0, 0])
    close(r["work"], -2.0)
    close(r["x_end"], [2 * math.cos(0.5) * math.cos(3), 2 * math.cos(0.5) * math.sin(3), 2 * math.sin(0.5)])


def test_gallery_cylindrical_potential_and_work():
    r = gallery()[1]["results"]
    assert r["conservative"] is True and r["potential"] == "r**2*x3"
    close(r["work"], -4.0)
    close(r["work_check"], 0.0)


def test_gallery_vortex_is_not_conservative():
    rec = gallery()[2]
    r = rec["results"]
    assert r["curl_formula"] == ["0", "0", "0"] and r["conservative"] is False and r["potential"] is None
    close(r["work"], 2 * math.pi)
    assert any("single-valued" in w for w in rec["warnings"])


def test_gallery_rotational_field_curl_is_2e3():
    r = gallery()[3]["results"]
    assert r["curl_formula"] == ["2*sin(phi)", "0", "2*cos(phi)"]
    close(r["curl"][0], [1, 0, math.sqrt(3)])
    close(r["work"], 2 * math.pi)


# --- an independent route: Cartesian components and Cartesian curl (sympy) -----------

def _cartesian_curl_projected(system, comps, point):
    """Turn F into Cartesian components with the basis vectors, take the
    Cartesian curl in x1, x2, x3, and project it back on the basis."""
    import sympy as sp

    x1, x2, x3 = sp.symbols("x1 x2 x3", real=True)
    if system == "cylindrical":
        r, th = sp.sqrt(x1 ** 2 + x2 ** 2), sp.atan2(x2, x1)
        coords = {"r": r, "theta": th, "x3": x3}
        e = [sp.Matrix([sp.cos(th), sp.sin(th), 0]), sp.Matrix([-sp.sin(th), sp.cos(th), 0]), sp.Matrix([0, 0, 1])]
        a, b, c = point
        xp = {x1: a * math.cos(b), x2: a * math.sin(b), x3: c}
    else:
        R = sp.sqrt(x1 ** 2 + x2 ** 2 + x3 ** 2)
        th, ph = sp.atan2(x2, x1), sp.asin(x3 / R)
        coords = {"R": R, "theta": th, "phi": ph}
        er = sp.Matrix([sp.cos(th), sp.sin(th), 0])
        e = [sp.cos(ph) * er + sp.sin(ph) * sp.Matrix([0, 0, 1]), sp.Matrix([-sp.sin(th), sp.cos(th), 0]),
             -sp.sin(ph) * er + sp.cos(ph) * sp.Matrix([0, 0, 1])]
        a, b, c = point
        xp = {x1: a * math.cos(c) * math.cos(b), x2: a * math.cos(c) * math.sin(b), x3: a * math.sin(c)}
    loc = {k: v for k, v in coords.items()}
    F = sum((sp.sympify(s, locals=loc) * ei for s, ei in zip(comps, e)), sp.zeros(3, 1))
    curl = sp.Matrix([sp.diff(F[2], x2) - sp.diff(F[1], x3), sp.diff(F[0], x3) - sp.diff(F[2], x1),
                      sp.diff(F[1], x1) - sp.diff(F[0], x2)])
    return [float((curl.T * ei)[0].subs(xp).evalf(30)) for ei in e]


@pytest.mark.parametrize("system, comps, point", [
    ("cylindrical", ["r*x3", "r", "sin(theta)"], (2.0, 0.5, 1.0)),
    ("cylindrical", ["x3**2/r", "r**2*cos(theta)", "r*theta"], (1.3, -2.0, 0.7)),
    ("spherical", ["R*sin(phi)", "cos(theta)/R", "R**2"], (1.5, 0.8, 0.3)),
    ("spherical", ["exp(-R)", "R*cos(phi)**2", "sin(theta)*R"], (0.7, 2.5, -1.1)),
])
def test_curl_against_the_cartesian_route(system, comps, point):
    ref = _cartesian_curl_projected(system, comps, point)
    F = ", ".join(f'"{c}"' for c in comps)
    rec = solve_one_text(f"type: force-field\ncoordinates: {system}\nF: [{F}]\npoints: [[{point[0]}, {point[1]}, {point[2]}]]\n")
    close(rec["results"]["curl"][0], ref, tol=1e-12)


def test_work_against_the_cartesian_field():
    """The same field and path given in Cartesian terms: the same work."""
    cyl = solve_one_text("type: force-field\ncoordinates: cylindrical\nF: [\"r*x3\", r, \"sin(theta)\"]\n"
                         "path: {r: \"1 + t\", theta: \"2*t\", x3: \"t**2\", t_span: [0, 1]}\n")["results"]
    # F_r e_r + F_θ e_θ + F_3 e3 with r = sqrt(x1²+x2²), cosθ = x1/r, sinθ = x2/r
    car = solve_one_text(
        "type: force-field\n"
        "F: [\"x1*x3 - x2\", \"x2*x3 + x1\", \"x2/sqrt(x1**2 + x2**2)\"]\n"
        "path: {x1: \"(1 + t)*cos(2*t)\", x2: \"(1 + t)*sin(2*t)\", x3: \"t**2\", t_span: [0, 1]}\n")["results"]
    close(cyl["work"], car["work"], tol=1e-11)
    close(cyl["x_end"], car["x_end"])


# --- extremes ------------------------------------------------------------------------

def test_curl_on_the_axis_is_null():
    rec = solve_one_text("type: force-field\ncoordinates: cylindrical\nF: [0, \"1/r\", 0]\npoints: [[0, 0, 0], [1, 0, 0]]\n")
    assert rec["results"]["curl"][0] is None and rec["results"]["curl"][1] == [0.0, 0.0, 0.0]
    assert any("points[0]" in w for w in rec["warnings"])


def test_uniform_field_in_spherical_coordinates():
    """F = e3 = sin φ e_R + cos φ e_φ: conservative with V = −x3 = −R sin φ."""
    r = solve_one_text("type: force-field\ncoordinates: spherical\nF: [\"sin(phi)\", 0, \"cos(phi)\"]\n"
                       "path: {R: t, theta: 1, phi: \"pi/2\", t_span: [0, 3]}\n")["results"]
    assert r["conservative"] is True and r["potential"] == "-R*sin(phi)"
    close(r["work"], 3.0)


def test_zero_field_and_zero_length_path():
    r = solve_one_text("type: force-field\ncoordinates: polar\nF: [0, 0, 0]\npath: {r: 1, theta: t, t_span: [1, 1]}\n")["results"]
    assert r["conservative"] is True and r["potential"] == "0" and r["work"] == 0


def test_cartesian_default_is_unchanged():
    r = solve_one_text("type: force-field\nF: [x1, x2, 0]\n")["results"]
    assert "basis" not in r and r["conservative"] is True


# --- invalid input -------------------------------------------------------------------

@pytest.mark.parametrize("text, where, message", [
    ("coordinates: polar\nF: [x1, 0, 0]", "F", "unknown name 'x1'"),
    ("coordinates: polar\nF: [x3, 0, 0]", "F", "the variables are r, theta"),
    ("coordinates: spherical\nF: [r, 0, 0]", "F", "did you mean 'R'"),
    ("coordinates: cylindrical\nF: [r, 0, 0]\npath: {x1: t, x2: 0, x3: 0, t_span: [0, 1]}", "path.x1", "given by r, theta, x3"),
    ("coordinates: cylindrical\nF: [r, 0, 0]\npath: {r: t, theta: 0, t_span: [0, 1]}", "path.x3", "required field is missing"),
    ("coordinates: polr\nF: [r, 0, 0]", "coordinates", "polar"),
    # not text: was a TypeError (unhashable list) -> exit 3
    ("coordinates: [0, 0]\nF: [1, 0, 0]", "coordinates", "coordinates must be one of: cartesian, polar"),
    ("coordinates: {a: 1}\nF: [1, 0, 0]", "coordinates", "coordinates must be one of"),
])
def test_invalid_coordinates(text, where, message):
    msg = error_of("type: force-field\n" + text + "\n")
    assert msg.startswith("bad.yaml:"), msg
    assert where in msg and message in msg, msg
