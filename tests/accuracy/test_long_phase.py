"""The exact top and gyroscope at long times (issue 28): t = 1e3, 1e5, 1e6 s within 1e-12 of
each quantity's scale against a 40-digit mpmath evaluation written here, independently of
dyncli (no Carlson forms, no cubic about u0, no double-double: the phase λt + σ0 and its
reduction are mpmath numbers; mpmath.ellipfun, ellipk, ellipf, polyroots, quad), and the
error_estimate ≥ the true error (a property).

* top: with u = cosθ, u(t) = u1 + (u2 − u1) sn²(λt + σ0 | m), m = (u2 − u1)/(u3 − u1),
  λ = √(β(u3 − u1))/2 from the roots of (α − βu)(1 − u²) − (b − cu)² (mpmath.polyroots); ψ̇ = (b − cu)/(1 − u²), φ̇ = ω3 − ψ̇u, ψ and φ by mpmath.quad over one
  period 2K/λ times the whole periods plus the rest;
* gyroscope (librating cases): about the centre θc = ±π/2 the motion passes through,
  z = tan((θ − θc)/2) obeys ż² = A4 z⁴ + A2 z² + A0, z = z1 sn(λt + u0 | m), λ² = A4 x2,
  m = x1/x2 (x1 < x2 the roots of A4 x² + A2 x + A0, z1² = x1).
"""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text

DPS = 40
G = 9.81
TIMES = [1.0e3, 1.0e5, 1.0e6]
GOAL = 1e-12

# (m, L, I11, I33, ψ0, θ0, φ0, ψ̇0, θ̇0, φ̇0)
TOPS = {
    "nutating": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.3, 1.2, -0.2, -2.0, 1.5, 40.0),
    "released": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.0, 0.5, 0.0, 0.0, 0.0, 100.0),
    "oblate": (1.0, 0.05, 0.01, 0.018, 0.0, 1.2, 0.0, 2.0, -0.4, 30.0),
}
# (I1, I2, p, q, θ0, θ̇0, σ): the motion librates through the centre θc = σπ/2
GYROS = {
    "zero_to_pi": (0.01, 0.006, 100.0, 1.0, 0.0, 0.0, 1),
    "pq_negative": (0.01, 0.006, -100.0, 1.0, 0.3, 2.0, -1),
    "slow": (0.01, 0.006, 1.0, 1.0, 1.0, 0.5, 1),
}


def _top_reference(m, L, A, C, psi0, th0, phi0, psd0, thd0, phd0, times):
    """Rows (ψ, θ, φ, ψ̇, θ̇, φ̇) at ``times`` and the rate scale √(α + β) ≥ |ω⊥|."""
    m, L, A, C, g = (mp.mpf(x) for x in (m, L, A, C, G))
    psi0, th0, phi0, psd0, thd0, phd0 = (mp.mpf(x) for x in (psi0, th0, phi0, psd0, thd0, phd0))
    u0, s0 = mp.cos(th0), mp.sin(th0)
    w3 = psd0 * u0 + phd0
    be = 2 * m * g * L / A
    al = thd0 ** 2 + psd0 ** 2 * s0 ** 2 + be * u0
    b, c = (A * psd0 * s0 ** 2 + C * w3 * u0) / A, C * w3 / A
    u1, u2, u3 = sorted(mp.re(x) for x in mp.polyroots([be, -al - c ** 2, -be + 2 * b * c, al - b ** 2],
                                                       maxsteps=400, extraprec=400))
    u1, u2 = min(u1, u0), max(u2, u0)
    k2 = (u2 - u1) / (u3 - u1)
    lam = mp.sqrt(be * (u3 - u1)) / 2
    K = mp.ellipk(k2)
    sig = mp.ellipf(mp.asin(mp.sqrt((u0 - u1) / (u2 - u1))), k2)
    if thd0 > 0:                # u̇0 < 0: u = u1 + Δ sn² decreases on (K, 2K)
        sig = 2 * K - sig

    def u_of(z):
        return u1 + (u2 - u1) * mp.ellipfun("sn", z, m=k2) ** 2

    def psid(z):
        x = u_of(z)
        return (b - c * x) / (1 - x * x)

    def integral(f, t):
        """∫_0^t f(u(λt' + σ0)) dt' = (1/λ) ∫_σ0^{σ0+λt} f dz (f has the period 2K in z)."""
        z1 = sig + lam * t
        n = mp.floor((z1 - sig) / (2 * K))
        full = mp.quad(f, [0, K, 2 * K])
        a, bnd = sig, z1 - n * 2 * K
        knots = [a] + [k * K for k in range(int(mp.floor(a / K)) + 1, int(mp.ceil(bnd / K)))] + [bnd]
        return (n * full + mp.quad(f, knots)) / lam

    rows = []
    for t in times:
        t = mp.mpf(t)
        z = lam * t + sig
        x = u_of(z)
        sn, cn, dn = (mp.ellipfun(f, z, m=k2) for f in ("sn", "cn", "dn"))
        udot = 2 * (u2 - u1) * sn * cn * dn * lam
        th = mp.acos(x)
        psd = psid(z)
        ps = psi0 + integral(psid, t)
        ph = phi0 + w3 * t - integral(lambda zz: psid(zz) * u_of(zz), t)
        rows.append([ps, th, ph, psd, -udot / mp.sin(th), w3 - psd * x])
    return rows, mp.sqrt(al + be)


def _top_text(args, times):
    m, L, A, C, ps, th, ph, psd, thd, phd = args
    return (f"type: top\nm: {m!r}\nL: {L!r}\nI11: {A!r}\nI33: {C!r}\npsi: {ps!r}\ntheta: {th!r}\nphi: {ph!r}\n"
            f"psi_dot: {psd!r}\ntheta_dot: {thd!r}\nphi_dot: {phd!r}\nat: {times}\n")


def _top_errors(rec, rows, wscale):
    r = rec["results"]
    out = {}
    for k, name in enumerate(("psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot")):
        want = [row[k] for row in rows]
        scale = max(abs(w) for w in want)
        if name in ("psi_dot", "theta_dot"):
            scale = max(scale, wscale)
        out[name] = float(max(abs(mp.mpf(x) - w) for x, w in zip(r[name], want)) / scale)
    return out


@pytest.fixture(scope="module")
def top_references():
    with mp.workdps(DPS):
        return {name: _top_reference(*args, TIMES) for name, args in TOPS.items()}


@pytest.mark.parametrize("name", sorted(TOPS))
def test_exact_top_at_long_times_against_40_digits(name, top_references):
    rows, wscale = top_references[name]
    rec = solve_one_text(_top_text(TOPS[name], TIMES))
    assert rec["method"] == "exact"
    with mp.workdps(DPS):
        err = _top_errors(rec, rows, wscale)
    assert max(err.values()) <= GOAL, err
    assert rec["error_estimate"] >= max(err.values()), (rec["error_estimate"], err)
    # the phase is exact for the inputs as binary numbers (above), but they are decimals rounded to
    # doubles: the estimate counts 4ε·λt for that (tests/topics/top/test_long_times.py), well below
    # the double phase's 16ε·λt and short of the 1e-6 of a lost-digits warning
    assert rec["error_estimate"] <= 5e-15 * 1e6 * 40 and not any("smaller t" in w for w in rec["warnings"])


def _gyro_reference(I1, I2, p, q, th0, thd0, sigma, times):
    """Rows (θ, θ̇) at ``times`` (libration through the centre θc = σπ/2, exactly)."""
    I1, I2, p, q, th0, thd0 = (mp.mpf(x) for x in (I1, I2, p, q, th0, thd0))
    thc = sigma * mp.pi / 2
    a, b = (I1 - I2) * q * q / I2, 2 * I1 * p * q / I2
    c0 = thd0 ** 2 - a * mp.sin(th0) ** 2 - b * mp.sin(th0)
    bc = b * mp.sin(thc)                               # G = a cos²χ + bc cos χ + c0, χ = θ − θc
    A0, A4, A2 = (a + bc + c0) / 4, (a - bc + c0) / 4, (c0 - a) / 2
    x1, x2 = sorted(mp.re(r) for r in mp.polyroots([A4, A2, A0], extraprec=200)) if A4 > 0 else \
        sorted((mp.re(r) for r in mp.polyroots([A4, A2, A0], extraprec=200)), reverse=True)
    # x1: the positive root reached from x0 = z0²; x2 the other (negative when A4 < 0)
    k2 = x1 / x2
    lam = mp.sqrt(A4 * x2)
    chi0 = th0 - thc
    chi0 = chi0 - 2 * mp.pi * mp.nint(chi0 / (2 * mp.pi))
    z0 = mp.tan(chi0 / 2)
    z1 = mp.sqrt(x1)
    zd0 = thd0 * (1 + z0 * z0) / 2
    u0 = mp.ellipf(mp.asin(max(-1, min(1, z0 / z1))), k2)
    if zd0 < 0:                       # sn decreasing: the branch u in (K, 3K)
        u0 = 2 * mp.ellipk(k2) - u0
    rows = []
    for t in times:
        w = lam * mp.mpf(t) + u0
        sn, cn, dn = (mp.re(mp.ellipfun(f, w, m=k2)) for f in ("sn", "cn", "dn"))   # m < 0: real, typed mpc
        z, zd = z1 * sn, z1 * lam * cn * dn
        th = thc + 2 * mp.atan(z)
        thd = 2 * zd / (1 + z * z)
        rows.append((th, thd))
    return rows, mp.sqrt(thd0 ** 2 + 2 * abs(a) + 2 * abs(b))


@pytest.mark.parametrize("name", sorted(GYROS))
def test_exact_gyroscope_at_long_times_against_40_digits(name):
    I1, I2, p, q, th0, thd0, _ = GYROS[name]
    with mp.workdps(DPS):
        rows, sthd = _gyro_reference(*GYROS[name], TIMES)
    rec = solve_one_text(f"type: gyroscope\nI1: {I1!r}\nI2: {I2!r}\np: {p!r}\nq: {q!r}\ntheta0: {th0!r}\n"
                         f"theta_dot0: {thd0!r}\nat: {TIMES}\n")
    assert rec["method"] == "exact"
    r = rec["results"]
    with mp.workdps(DPS):
        # θ against its range π modulo 2π (θ is reported continuously from θ0), θ̇ against its scale
        eth = max(abs(mp.mpf(x) - w[0] - 2 * mp.pi * mp.nint((mp.mpf(x) - w[0]) / (2 * mp.pi)))
                  for x, w in zip(r["theta"], rows)) / mp.pi
        ethd = max(abs(mp.mpf(x) - w[1]) for x, w in zip(r["theta_dot"], rows)) / sthd
    err = float(max(eth, ethd))
    assert err <= GOAL, (eth, ethd)
    assert rec["error_estimate"] >= err, (rec["error_estimate"], err)
    # (+ the inputs' rounding, 4ε·λt: well below the double phase's 16ε·λt, no lost-digits warning)
    assert rec["error_estimate"] <= 5e-8 and not any("smaller t" in w for w in rec["warnings"])


@pytest.mark.parametrize("t", ["1", "1e6", "1e10", "1e13"])
@pytest.mark.parametrize("name", sorted(GYROS))
def test_exact_gyroscope_estimate_bounds_the_error_from_the_decimal_inputs(name, t):
    # the phase is exact for the inputs as binary numbers; against the decimals they stand for,
    # λ/4K is known to a few ε, counted in error_estimate (4ε·λt) and warned beyond 1e-6
    decimals = [repr(x) for x in GYROS[name][:6]] + [GYROS[name][6]]
    with mp.workdps(50):
        rows, sthd = _gyro_reference(*decimals, [t])
    rec = solve_one_text(_gyro_text(name, [float(t)]))
    r = rec["results"]
    with mp.workdps(50):
        d = mp.mpf(r["theta"][0]) - rows[0][0]
        eth = abs(d - 2 * mp.pi * mp.nint(d / (2 * mp.pi))) / mp.pi
        err = float(max(eth, abs(mp.mpf(r["theta_dot"][0]) - rows[0][1]) / sthd))
    assert err <= rec["error_estimate"], (err, rec["error_estimate"])
    assert any("smaller t" in w for w in rec["warnings"]) == (rec["error_estimate"] > 1e-6)


def _gyro_text(name, times, extra=""):
    I1, I2, p, q, th0, thd0, _ = GYROS[name]
    return (f"type: gyroscope\nI1: {I1!r}\nI2: {I2!r}\np: {p!r}\nq: {q!r}\ntheta0: {th0!r}\n"
            f"theta_dot0: {thd0!r}\nat: {times}\n{extra}")


def _gyro_error(rec, rows):
    """θ relative to π, θ̇ to its largest value at the reported times (the route's own scales)."""
    r = rec["results"]
    eth = max(abs(float(x - w[0])) for x, w in zip(r["theta"], rows)) / float(mp.pi)
    ethd = max(abs(float(x - w[1])) for x, w in zip(r["theta_dot"], rows)) / max(abs(float(w[1])) for w in rows)
    return max(eth, ethd)


@pytest.mark.parametrize("name", ["zero_to_pi", "slow"])
@pytest.mark.parametrize("rtol", [1e-6, 1e-8, 1e-10])
def test_gyroscope_ode_default_estimate_bounds_the_error_over_many_periods(name, rtol):
    # issue 28: over ~200 periods the error is the phase's (quadratic in t); rtol × steps alone read
    # 5-30 times below it; the drift of (37.13) times the phase run bounds it
    times = [10.0, 100.0]
    with mp.workdps(DPS):
        rows, _ = _gyro_reference(*GYROS[name], times)
    rec = solve_one_text(_gyro_text(name, times, f"accuracy: {{method: DOP853, rtol: {rtol}}}\n"))
    err = _gyro_error(rec, rows)
    assert rec["error_estimate"] >= err, (rec["error_estimate"], err)


def test_an_ode_route_that_misses_its_promise_says_so():
    # the drift of (37.13), a measured error, is 4.6e-4 > 100 × rtol
    rec = solve_one_text(_gyro_text("zero_to_pi", [100.0], "accuracy: {method: DOP853, rtol: 1e-6}\n"))
    msg = [w for w in rec["warnings"] if "requested accuracy was not met" in w]
    assert msg and "100 × rtol = 0.0001" in msg[0], rec["warnings"]
    rec = solve_one_text(_gyro_text("zero_to_pi", [1.0], "accuracy: {method: DOP853, rtol: 1e-10}\n"))
    assert not any("requested accuracy" in w for w in rec["warnings"]), rec["warnings"]


def test_exact_routes_say_when_the_estimate_exceeds_rtol(monkeypatch):
    # without the double-double phase (as if its 40-digit constants were unavailable) the estimate at
    # t = 1e6 s is the double phase's ε·16·λt ~ 5e-8: above the default rtol, and said
    from dyncli.topics.gyroscope import phase as gphase
    from dyncli.topics.top import phase as tphase

    monkeypatch.setattr(gphase, "long_phase", lambda *a: None)
    monkeypatch.setattr(tphase, "long_phase", lambda *a: None)
    for text in (_gyro_text("slow", [1e6]), _top_text(TOPS["nutating"], [1e6])):
        rec = solve_one_text(text)
        assert rec["error_estimate"] > 1e-10
        msg = [w for w in rec["warnings"] if "requested accuracy was not met" in w]
        assert msg and f"{rec['error_estimate']:.2g}" in msg[0], rec["warnings"]
    monkeypatch.undo()
    rec = solve_one_text(_gyro_text("slow", [1e6]))      # (the inputs' rounding, 4ε·λt: 1.5e-9)
    assert 1e-10 < rec["error_estimate"] < 3e-9
    rec = solve_one_text(_top_text(TOPS["nutating"], [1e6]))      # (the inputs' rounding, 4ε·λt: 1.2e-8)
    assert 1e-9 < rec["error_estimate"] < 2e-8
    # a request below what the evaluation can promise (rtol 2.3e-14, the floor): said as well
    rec = solve_one_text(_gyro_text("zero_to_pi", [1e6], "accuracy: {rtol: 2.3e-14}\n"))
    assert any("requested accuracy was not met" in w for w in rec["warnings"]), rec["warnings"]
