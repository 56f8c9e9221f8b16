"""The worked examples of the notes named in the gallery, checked against
values derived here from the notes' formulas (mpmath at 30 digits), not
against the program's output.

The topic tests (tests/<topic>/) check every gallery file in depth; this
module is the gallery's own summary: one headline check per worked example,
and the full check of ``problems/impact/cone-fig28-4.yaml`` (Fig. 28.4).
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, solve_path

REL = 1e-12


@pytest.fixture(autouse=True)
def _precision():
    """30 digits for the references, restored afterwards (mpmath's precision is
    global: other test modules in the same process set their own)."""
    with mp.workdps(30):
        yield


def close(a, b, rel=REL, abs_=1e-13):
    if isinstance(b, (list, tuple)):
        assert isinstance(a, (list, tuple)) and len(a) == len(b), (a, b)
        for x, y in zip(a, b):
            close(x, y, rel, abs_)
        return
    assert a == pytest.approx(float(b), rel=rel, abs=abs_), (a, float(b))


def one(path):
    recs = solve_path(PROBLEMS / path)
    assert len(recs) == 1 and recs[0].get("error") is None
    return recs[0]["results"]


# --- §6 case 1 (6.5a,b) ---------------------------------------------------
def test_rectilinear_case1_braking_car():
    r = one("rectilinear/case1-constant-acceleration.yaml")
    a, v1 = mp.mpf(-4), mp.mpf(20)
    t_stop = -v1 / a                                  # v = v1 + a t = 0
    s_stop = v1 * t_stop + a * t_stop**2 / 2
    q = r["find"]
    close([q[0]["s"], q[0]["v"]], [v1 * 2 + a * 2, v1 + a * 2])
    close([q[1]["t"], q[1]["s"]], [t_stop, s_stop])
    close(q[2]["t"], t_stop)


# --- §17 base excitation (17.30), (17.33)-(17.34) -----------------------------
def test_vibration_base_excitation_amplification():
    r = one("vibration/base-excitation.yaml")
    wn = mp.sqrt(mp.mpf(400) / 1)
    rr, z = mp.mpf(30) / wn, mp.mpf("0.05")
    D = (1 - rr**2) + 2j * z * rr                     # w_p = s0 r² e^{iωt}/D
    G, phi = rr**2 / abs(D), -mp.arg(D)
    X = (1 + 2j * z * rr) / D                          # x − L = s0 (1 + 2iζr)/D e^{iωt}
    close([r["G"], r["phi"], r["g"], r["Phi"]], [G, phi, abs(X), mp.arg(X)])


# --- §23 plastic impact (23.13) ----------------------------------------------
def test_plastic_impact_23_13():
    r = one("impact/plastic-23-13.yaml")
    mA, mB, v0 = mp.mpf(2), mp.mpf(3), mp.mpf(5)
    v = mA * v0 / (mA + mB)
    close(r["vA2"], [v, 0, 0])
    close(r["vB2"], [v, 0, 0])
    close(r["impulse"], [-mA * mB * v0 / (mA + mB), 0, 0])
    close(r["energy_loss"], mA * mB / (mA + mB) * v0**2 / 2)


# --- §28, Fig. 28.4: the admissible range (28.50) -----------------------------
def _cone_reference(theta, eta, phi):
    rho = (1 - eta) / (1 + eta)
    c, s = mp.cos(theta), mp.sin(theta)
    q = mp.sqrt(1 - rho**2 * c**2)
    phi1 = -mp.acos(rho * c**2 + q * s) / 2            # (28.50a), as printed
    phi2 = mp.acos(rho * c**2 - q * s) / 2             # (28.50b)
    n, t = mp.matrix([1, 0, 0]), mp.matrix([0, 1, 0])
    dv1 = mp.matrix([c, s, 0])                          # (28.40), |Δv1| = 1
    f = -(mp.cos(phi) * n + mp.sin(phi) * t)            # (28.41)
    m_star = mp.mpf(1) / 2                              # mA = mB = 1
    F = m_star * (1 + eta) * (-(f.T * dv1)[0]) * f      # (28.26)
    return phi1, phi2, F


@pytest.mark.parametrize("index", range(9))
def test_impact_cone_fig28_4(index):
    rec = solve_path(PROBLEMS / "impact/cone-fig28-4.yaml")[index]
    r = rec["results"]
    eta = [mp.mpf(0), mp.mpf("0.5"), mp.mpf(1)][index // 3]
    theta = [15, 45, 75][index % 3] * mp.pi / 180
    phi1, phi2, F = _cone_reference(theta, eta, theta)
    close(r["theta"], theta)
    close([r["phi1"], r["phi2"]], [phi1, phi2], rel=1e-11, abs_=1e-12)
    assert phi1 - 1e-20 <= theta <= phi2 + 1e-20          # (28.52); equality for η = 0
    close(r["impulse"], [F[0], F[1], F[2]])
    close(r["vA2"], [mp.cos(theta) + F[0], mp.sin(theta) + F[1], 0])   # vA2 = vA1 + F̂/mA
    close(r["vB2"], [-F[0], -F[1], 0])                                  # vB2 = vB1 − F̂/mB
    assert r["admissible"] is True
    assert [r["P1"], r["P2"], r["P3"], r["P4"]] == [True] * 4


def test_impact_cone_limits():
    """η = 0: φ1 = 0, φ2 = θ;  η = 1: φ1,2 = (θ ∓ π/2)/2 (from (28.50))."""
    for th in (15, 45, 75):
        theta = th * mp.pi / 180
        p1, p2, _ = _cone_reference(theta, mp.mpf(0), theta)
        assert abs(p1) < 1e-25 and abs(p2 - theta) < 1e-25
        p1, p2, _ = _cone_reference(theta, mp.mpf(1), theta)
        assert abs(p1 - (theta - mp.pi / 2) / 2) < 1e-25 and abs(p2 - (theta + mp.pi / 2) / 2) < 1e-25


# --- §30 the dumbbell (30.39) ------------------------------------------------
def test_dumbbell_30_39():
    r = one("inertia/dumbbell-fig30-3.yaml")
    M, L, a = mp.mpf(2), mp.mpf("0.5"), 30 * mp.pi / 180
    ML2 = M * L**2
    ref = [[2 * ML2 * mp.cos(a)**2, -ML2 * mp.sin(2 * a), 0],
           [-ML2 * mp.sin(2 * a), 2 * ML2 * mp.sin(a)**2, 0],
           [0, 0, 2 * ML2]]
    close(r["I_about"], ref)
    close(r["principal_moments"], [0, 2 * ML2, 2 * ML2], abs_=1e-14)


# --- §31 transfer theorem (31.7) ---------------------------------------------
def test_box_about_corner_31_7():
    r = one("inertia/box-about-corner.yaml")
    m, a, b, c = 6, mp.mpf("0.4"), mp.mpf("0.3"), mp.mpf("0.2")
    ref = [[m * (b**2 + c**2) / 3, -m * a * b / 4, -m * a * c / 4],
           [-m * a * b / 4, m * (a**2 + c**2) / 3, -m * b * c / 4],
           [-m * a * c / 4, -m * b * c / 4, m * (a**2 + b**2) / 3]]
    close(r["I_about"], ref)


# --- §33 the struck body (33.5)-(33.10) --------------------------------------
def test_struck_bar_33_10():
    r = one("impact/struck-bar.yaml")
    m, R, h, k2 = mp.mpf(3), mp.mpf(6), mp.mpf("0.6"), mp.mpf("0.12")
    close(r["v2"], [R / m, 0, 0])
    close(r["omega2"], [0, 0, h * R / (m * k2)])
    close(r["percussion"], [0, k2 / h, 0])


# --- §36 spinning arms (36.22) -----------------------------------------------
def test_spinning_arms_36_22():
    r = one("rigid-bodies/spinning-arms.yaml")
    a0, a, w0 = 60 * mp.pi / 180, 30 * mp.pi / 180, mp.mpf(2)
    close(r["omega"], (mp.sin(a0) / mp.sin(a))**2 * w0)


# --- §36 motor-driven disks (36.40) ------------------------------------------
def test_motor_disks_36_40():
    r = one("rigid-bodies/motor-disks.yaml")
    IA1, IA2, mA, L, IB2, al, p = (mp.mpf("0.01"), mp.mpf("0.005"), mp.mpf(2), mp.mpf("0.3"),
                                   mp.mpf("0.1"), 30 * mp.pi / 180, mp.mpf(100))
    Omega = -IA1 * p * mp.sin(al) / (IA1 * mp.sin(al)**2 + (mA * L**2 + IA2) * mp.cos(al)**2 + IB2)
    close(r["Omega"], Omega)


# --- §39 the coin's inertia (39.10) ------------------------------------------
def test_coin_inertia_39_10():
    r = one("inertia/coin.yaml")
    m, R, h = mp.mpf("0.01"), mp.mpf("0.012"), mp.mpf("0.002")
    I1 = m * R**2 / 2 * (mp.mpf(1) / 2 + h**2 / (6 * R**2))
    close(r["principal_moments"], sorted([I1, I1, m * R**2 / 2]))


# --- §37 the gyroscope (37.12)-(37.17) ---------------------------------------
def test_gyroscope_0_to_pi_37_17():
    r = one("gyroscopic/gyroscope-0-to-pi.yaml")
    I1, I2, p, q = mp.mpf("0.01"), mp.mpf("0.006"), mp.mpf(100), mp.mpf(1)
    close([r["theta_min"], r["theta_max"]], [0, mp.pi], abs_=1e-12)     # (37.17)
    # the first integral (37.15b) from rest at θ = 0:
    #   I2 θ̇² = [(I1 − I2) q² sin θ + 2 I1 p q] sin θ
    for th, thd in zip(r["theta"], r["theta_dot"]):
        s = mp.sin(th)
        assert thd**2 == pytest.approx(float(((I1 - I2) * q**2 * s + 2 * I1 * p * q) * s / I2), rel=1e-7, abs=1e-9)


# --- §38 steady precession (38.22)-(38.27) -----------------------------------
def _precession_reference(m, L, I11, I33, theta, p, g=mp.mpf("9.81")):
    a, b, c = (I11 - I33) * mp.cos(theta), I33 * p, m * g * L         # a Ω² − b Ω + c = 0 (38.22)
    roots = sorted(mp.polyroots([a, -b, c]), key=abs)
    p_min = 2 * mp.sqrt(a * c) / I33                                   # (38.24)
    R = []
    for W in roots:                                                    # (38.20): R = m ā + m g e3, on e''
        e3 = mp.matrix([0, mp.sin(theta), mp.cos(theta)])
        Om, xb = W * e3, mp.matrix([0, 0, L])
        abar = _cross(Om, _cross(Om, xb))
        R.append([m * abar[i] + m * g * e3[i] for i in range(3)])
    return roots, p_min, c / b, b / a, R


def _cross(u, v):
    return mp.matrix([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]])


def test_precession_fast_top_38_23_27():
    r = one("gyroscopic/precession-fast-top.yaml")
    (slow, fast), p_min, approx_slow, approx_fast, (R_slow, R_fast) = _precession_reference(
        mp.mpf("0.5"), mp.mpf("0.05"), mp.mpf("0.006"), mp.mpf("0.002"), mp.pi / 6, mp.mpf(200))
    assert r["exists"] is True
    close([r["Omega_slow"], r["Omega_fast"]], [slow, fast])
    close(r["p_min"], p_min)
    close([r["Omega_slow_approx"], r["Omega_fast_approx"]], [approx_slow, approx_fast])
    close(r["R_slow"], R_slow, abs_=1e-12)
    close(r["R_fast"], R_fast, abs_=1e-10)


def test_precession_below_pmin_38_24():
    r = one("gyroscopic/precession-below-pmin.yaml")
    _, p_min, *_ = _precession_reference(mp.mpf("0.5"), mp.mpf("0.05"), mp.mpf("0.006"), mp.mpf("0.002"),
                                         mp.pi / 6, mp.mpf(200))
    assert 20 < p_min
    assert r["exists"] is False
    assert r["Omega_slow"] is None and r["Omega_fast"] is None


# --- §39 the flipping coin (39.10)-(39.22) -----------------------------------
def test_flipping_coin_39():
    r = one("gyroscopic/euler-flipping-coin.yaml")
    m, R, h = mp.mpf("0.005"), mp.mpf("0.012"), mp.mpf("0.002")
    I1, I3 = m * R**2 / 4 + m * h**2 / 12, m * R**2 / 2               # (39.10)
    w1, w2, w3 = mp.mpf(40), mp.mpf(0), mp.mpf(3)
    lam = (I3 - I1) / I1 * w3                                          # (39.15)
    close(r["lambda"], lam)
    close(r["psi_dot"], mp.sqrt(w1**2 + w2**2 + (I3 / I1 * w3)**2))   # (39.20): |H̄|/I1
    close(r["theta"], mp.atan2(mp.sqrt(w1**2 + w2**2), I3 / I1 * w3))  # (39.21)
    # ω'1 + i ω'2 = (ω'01 + i ω'02) e^{iλt}, ω'3 constant (39.12)-(39.17)
    for t, w in zip([0, mp.mpf("0.5"), 1], r["omega"]):
        z = (w1 + 1j * w2) * mp.exp(1j * lam * t)
        close(w, [mp.re(z), mp.im(z), w3], rel=1e-11, abs_=1e-11)
