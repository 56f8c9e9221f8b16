"""Parameter limits that break naive formulas, across types, against 50-digit
(mpmath) references.  Each test's docstring names the formula it protects.
Only limits the topics' own tests do not already cover are here (see
tests/<topic>/ for ζ → 1, resonance, grazing impact, e/η at 0 and 1,
separatrix spin, (I11 − I33) cos θ → 0, p → p_min, terminal velocity and
turning points).
"""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import solve_one_text

mp.mp.dps = 50


def rel(got, ref) -> float:
    ref = mp.mpf(ref)
    return float(abs(mp.mpf(got) - ref) / max(abs(ref), mp.mpf("1e-300")))


# --- t = t1: a query equal to the initial state ---------------------------------------

RECT_CASES = {
    "case 1": "a: -4",
    "case 2": "a: '3*sin(2*t)'",
    "case 3": "a: '-0.5*v'",
    "case 4": "a: '-4*s'",
    "general": "a: '-4*s - 0.4*v + sin(t)'",
}


@pytest.mark.parametrize("case", list(RECT_CASES))
def test_rectilinear_query_at_t1_is_the_initial_state(case):
    """protects (6.5)-(6.15) and (6.2c,e): {t: t1} is answered at t1 itself with s1, v1 exactly
    (no integration over a zero-length interval); {v: v1} and {s: s1}, values held at the
    start, count only when the motion reaches them again (§11): never at t1, never a rounding
    step later."""
    rec = solve_one_text(f"type: rectilinear\n{RECT_CASES[case]}\nt1: 0.7\ns1: 0.3\nv1: 2.5\nt_max: 20\n"
                         "find: [{t: 0.7}, {v: 2.5}, {s: 0.3}]\n")
    q = rec["results"]["find"][0]
    assert q["reached"] is True and q["t"] == 0.7 and q["s"] == 0.3 and q["v"] == 2.5, (case, q)
    for q in rec["results"]["find"][1:]:
        assert not q["reached"] or q["t"] > 0.7 + 1e-6, (case, q)


def test_rectilinear_case1_position_root_without_cancellation():
    """protects (6.5b) solved for t: t = 2ΔS/(v1 + √(v1² + 2aΔS)), not
    (−v1 + √(v1² + 2aΔS))/a, which loses every digit when a·ΔS ≪ v1²."""
    a, v1, S = mp.mpf("1e-12"), mp.mpf(1), mp.mpf(1)
    t_ref = 2 * S / (v1 + mp.sqrt(v1 ** 2 + 2 * a * S))
    rec = solve_one_text("type: rectilinear\na: 1e-12\nv1: 1\nfind: [{s: 1}]\n")
    q = rec["results"]["find"][0]
    assert rel(q["t"], t_ref) < 1e-14
    assert rel(q["v"], v1 + a * t_ref) < 1e-15


def test_rectilinear_case1_velocity_root_with_tiny_acceleration_is_beyond_t_max():
    """protects (6.5a) t = (V − v1)/a with a → 0: the time 1e300 s is beyond
    t_max, so reached: false (with a warning), never inf or an overflow."""
    rec = solve_one_text("type: rectilinear\na: 1e-300\nv1: 1\nfind: [{v: 2}]\n")
    q = rec["results"]["find"][0]
    assert q["reached"] is False and q["t"] is None
    assert rec["warnings"]


@pytest.mark.parametrize("at0", [0.0])
def test_vibration_at_zero_is_the_initial_state(at0):
    """protects (17.22)-(17.24) at t = 0 in every regime: x(0) = x0, v(0) = v0
    exactly-to-rounding, including ζ = 1 ± 1e-12 where the two exponentials
    nearly cancel."""
    for zeta in ("0", "0.3", "0.999999999999", "1", "1.000000000001", "5"):
        rec = solve_one_text(f"type: vibration\nm: 2\nk: 50\nzeta: {zeta}\nL: 0.1\nx0: 0.13\nv0: -0.4\nat: [{at0}]\n")
        r = rec["results"]
        assert abs(r["x"][0] - 0.13) <= 1e-15 and abs(r["v"][0] + 0.4) <= 4e-15, (zeta, r["x"], r["v"])


# --- zero-length paths ---------------------------------------------------------------------

def test_kinematics_zero_length_distance():
    """protects (4.5) s = ∫|v| dt over [t1, t1]: exactly 0, with no quadrature warning."""
    rec = solve_one_text("type: kinematics\ncoordinates: cylindrical\nposition: {r: 2, theta: '3*t', x3: 't'}\n"
                         "at: [1]\ndistance: [1, 1]\n")
    assert rec["results"]["distance"] == 0.0


def test_force_field_zero_length_path():
    """protects (19.x) W = ∫F·dx over a path with t1 = t2: exactly 0."""
    rec = solve_one_text("type: force-field\nF: ['x2', '-x1', 'x3']\npoints: [[1, 0, 0]]\n"
                         "path: {x1: 'cos(t)', x2: 'sin(t)', x3: 0, t_span: [0.5, 0.5]}\n")
    assert rec["results"]["work"] == 0.0


# --- mass ratios 1e±16 ------------------------------------------------------------------------

@pytest.mark.parametrize("big", ["1e16", "1e-16"])
def test_particles_mass_ratio_relative_energy(big):
    """protects (27.8): T_rel = Σ ½ mᵢ ṗᵢ·ṗᵢ from relative velocities, not
    T − ½ m v̄·v̄, which cancels to noise when one mass is 1e16 times the other;
    and (24.12) x̄ by mass fractions."""
    m1, m2 = mp.mpf(big), mp.mpf(1)
    x1, x2 = mp.mpf(0), mp.mpf(1)
    v1, v2 = mp.mpf(3), mp.mpf(-2)
    M = m1 + m2
    com = (m1 * x1 + m2 * x2) / M
    mu = m1 * m2 / M
    T_rel = mu * (v1 - v2) ** 2 / 2
    rec = solve_one_text(f"type: particles\nparticles:\n  - {{m: {big}, x: [0, 0, 0], v: [3, 0, 0]}}\n"
                         "  - {m: 1, x: [1, 0, 0], v: [-2, 0, 0]}\n")
    r = rec["results"]
    assert rel(r["com"][0], com) < 1e-15
    assert rel(r["T_rel"], T_rel) < 1e-14
    assert rel(r["T"], r["T_com"] + r["T_rel"]) < 1e-14


# --- p → ∞: the center of percussion ---------------------------------------------------------

@pytest.mark.parametrize("h", ["5e-324", "0"])
def test_rigid_impulse_center_of_percussion_at_infinity(h):
    """protects (33.10) p = k²/h as h → 0: null with a warning once k²/h is
    beyond the double range (never inf), and ω₂ = hR/(mk²) (33.8) exactly 0
    or tiny."""
    rec = solve_one_text(f"type: rigid-impulse\nm: 3\nk: 0.5\nR: 6\nh: {h}\ns: 0\n")
    r = rec["results"]
    assert r["percussion"] is None and rec["warnings"]
    assert abs(r["omega2"][2]) <= float(mp.mpf(h) * 6 / (3 * mp.mpf("0.25"))) * (1 + 1e-15)


@pytest.mark.parametrize("k,h", [("1e150", "1e-7"), ("0.5", "1e-300")])
def test_rigid_impulse_percussion_large_but_finite(k, h):
    """protects (33.10) p = k²/h computed as (k/h)·k: a k²/h near the top of
    the double range (1e307, 2.5e299) is reported to full precision."""
    rec = solve_one_text(f"type: rigid-impulse\nm: 1\nk: {k}\nR: 1\nh: {h}\ns: 0\n")
    k, h = mp.mpf(k), mp.mpf(h)
    p = rec["results"]["percussion"]
    if p is None:     # 1e307 is representable: the code must report it
        pytest.fail(f"percussion null for k²/h = {mp.nstr(k * k / h, 5)} (representable)")
    assert rel(p[1], k * k / h) < 1e-14


# --- spin change: the moved masses end on the axis ------------------------------------------

def test_spin_change_masses_onto_axis_with_tiny_I0():
    """protects (36.22) ω = ω0 I_before/I_after when I_after = I0 → 0: the
    ratio 1e300 overflows to a finite-or-null result (never inf in JSON)."""
    rec = solve_one_text("type: spin-change\naxis: [0, 0, 1]\nomega0: 2\nI0: 1e-300\n"
                         "masses: [{m: 1, before: [1, 0, 0], after: [0, 0, 3]}]\n")
    r = rec["results"]
    ref = 2 * (mp.mpf("1e-300") + 1) / mp.mpf("1e-300")
    assert r["omega"] is None or rel(r["omega"], ref) < 1e-14


# --- motor bodies at α = π/2 (cos α = 6e-17) ------------------------------------------------

@pytest.mark.parametrize("alpha", ["pi/2", "1e-300", "0"])
def test_motor_bodies_alpha_limits(alpha):
    """protects (36.40) Ω = −IA1 p sin α / (IA1 sin²α + (mA L² + IA2) cos²α + IB2)
    at α = π/2 and α → 0 against 50 digits (the double π/2 has cos = 6.1e-17)."""
    IA1, IA2, mA, L, IB2, p = (mp.mpf(x) for x in ("0.01", "0.005", "2", "0.3", "0.1", "100"))
    a = {"pi/2": mp.mpf(math.pi / 2), "1e-300": mp.mpf("1e-300"), "0": mp.mpf(0)}[alpha]
    s, c = mp.sin(a), mp.cos(a)
    Om = -IA1 * p * s / (IA1 * s ** 2 + (mA * L ** 2 + IA2) * c ** 2 + IB2)
    rec = solve_one_text(f"type: motor-bodies\nIA1: 0.01\nIA2: 0.005\nmA: 2\nL: 0.3\nIB2: 0.1\nalpha: {alpha}\np: 100\n")
    got = rec["results"]["Omega"]
    assert abs(mp.mpf(got) - Om) <= mp.mpf("1e-15") * max(abs(Om), mp.mpf("1e-300")) + mp.mpf("1e-320")
