"""Oracle cases: the torque-free body (euler) and the heavy symmetric top (top).

* euler: an axisymmetric body at 1e8 rad/s on moments of 1e-20 kg m² (closed form), and a body
  spun 1e-7 rad from its intermediate axis (the separatrix: m = 1 − 1e-14), against a Taylor
  integration of Euler's equations (mpmath.odefun, 30 digits);
* top: a top released 0.01 rad from the vertical spinning 1e-6 above and below the sleeping
  top's critical spin C²ω3² = 4 A m g L (the bifurcation): its nutation bounds from the cubic
  (α − βu)(1 − u²) − (b − cu)² (mpmath.polyroots, 40 digits), with the condition number of the
  bounds in the inputs measured at 40 digits; and the nutating top of the template by Taylor
  integration of (38.18)."""

from __future__ import annotations

import math

import mpmath as mp

from tests.oracle.common import case, closed, condition, estimated, x

G = x(9.81)


def _axisymmetric():
    I1, I3, w10, w30 = x(1e-20), x(2e-20), x(1e8), x(3e8)
    lam = (I3 - I1) / I1 * w30
    times = [x(1e-8), x(1e-6)]
    checks = []
    for i, t in enumerate(times):
        cond = 16 * (1 + lam * t)
        checks += [closed(f"omega.{i}.0", w10 * mp.cos(lam * t), scale=w10, cond=cond, reason="phase λt rounded"),
                   closed(f"omega.{i}.1", w10 * mp.sin(lam * t), scale=w10, cond=cond, reason="phase λt rounded"),
                   closed(f"omega.{i}.2", w30)]
    checks += [closed("T", (I1 * w10 ** 2 + I3 * w30 ** 2) / 2, cond=4)]
    return case("1e-20 kg m² at 1e8 rad/s", "euler", {"I": [1e-20, 1e-20, 2e-20], "omega0": [1e8, 0, 3e8],
                                                       "at": [1e-8, 1e-6]}, checks,
                "a body the size of a molecule spinning at 3e8 rad/s: λ = 3e8 rad/s, λt = 3 and 300")


def _intermediate():
    I = [x(1), x(2), x(3)]
    w0 = [x(1e-7), x(10), x(1e-7)]
    times = [1, 3, 6]
    with mp.workdps(30):
        f = lambda t, w: [(I[1] - I[2]) * w[1] * w[2] / I[0], (I[2] - I[0]) * w[2] * w[0] / I[1],  # noqa: E731
                          (I[0] - I[1]) * w[0] * w[1] / I[2]]
        sol = mp.odefun(f, 0, w0)
        ws = [sol(x(t)) for t in times]
    lam = 10 * mp.sqrt(mp.mpf(1) / 3)            # the growth rate off the intermediate axis
    checks = []
    for i, t in enumerate(times):
        cond = 16 * (1 + lam * t) * 4
        checks += [closed(f"omega.{i}.{j}", ws[i][j], scale=10, cond=cond,
                          reason="the elliptic phase λt rounded, x4 for the separatrix's elliptic functions")
                   for j in range(3)]
    return case("spun 1e-7 rad from the intermediate axis", "euler", {"I": [1, 2, 3], "omega0": [1e-7, 10, 1e-7],
                                                                      "at": times}, checks,
                "I = 1, 2, 3, ω0 = (1e-7, 10, 1e-7): the body flips over (ω2 → −10) after ~3 s; m = 1 − 1e-14")


def _bounds(m, L, A, C, th0, phd0):
    u0 = mp.cos(th0)
    be = 2 * m * G * L / A
    al = be * u0
    w3 = phd0
    b, c = C * w3 * u0 / A, C * w3 / A
    roots = sorted(mp.re(r) for r in mp.polyroots([be, -al - c ** 2, -be + 2 * b * c, al - b ** 2],
                                                   maxsteps=400, extraprec=400))
    inside = [r for r in roots if -1 <= r <= 1 + mp.mpf("1e-30")]
    # u0 is a root (released at rest in θ); the other turning point is the nearest root on [−1, 1]
    others = sorted((r for r in inside if abs(r - u0) > mp.mpf("1e-35")), key=lambda r: abs(r - u0))
    u1 = others[0]
    return sorted([mp.acos(u0), mp.acos(min(u1, 1))])


def _sleeping():
    m, L, A, C, th0 = x(0.5), x(0.05), x(2e-3), x(1e-3), x(0.01)
    wc = mp.sqrt(4 * A * m * G * L) / C
    out = []
    for sign, what in ((1, "above"), (-1, "below")):
        phd = x(float(wc * (1 + sign * mp.mpf("1e-6"))))
        lo, hi = _bounds(m, L, A, C, th0, phd)
        c_lo = condition(lambda *a: _bounds(*a)[0], [m, L, A, C, th0, phd])
        c_hi = condition(lambda *a: _bounds(*a)[1], [m, L, A, C, th0, phd])
        out.append(case(f"sleeping top 1e-6 {what} the critical spin", "top", {
            "m": 0.5, "L": 0.05, "I11": 2e-3, "I33": 1e-3, "psi": 0, "theta": 0.01, "phi": 0, "psi_dot": 0,
            "theta_dot": 0, "phi_dot": float(phd), "at": [0]},
            [closed("theta_min", lo, cond=16 * c_lo, reason="x the bounds' condition in the inputs"),
             closed("theta_max", hi, cond=16 * c_hi, reason="x the bounds' condition in the inputs")],
            f"released 0.01 rad from the vertical at ω3 = ω_c (1 {'+' if sign > 0 else '−'} 1e-6), ω_c = "
            f"{mp.nstr(wc, 8)} rad/s: the band of nutation next to the bifurcation of the sleeping top"))
    return out


def _nutating():
    m, L, A, C = x(0.5), x(0.05), x(2e-3), x(1e-3)
    th0, phd0 = x(0.5), x(100)
    w3 = phd0
    pz = C * w3 * mp.cos(th0)
    times = [0.05, 0.2]
    with mp.workdps(30):
        def rates(th):
            s, c = mp.sin(th), mp.cos(th)
            psd = (pz - C * w3 * c) / (A * s ** 2)
            return psd, w3 - psd * c

        def f(t, y):
            psd, phd = rates(y[1])
            s, c = mp.sin(y[1]), mp.cos(y[1])
            return [psd, y[3], phd, (A * psd ** 2 * s * c - C * w3 * psd * s + m * G * L * s) / A]
        sol = mp.odefun(f, 0, [mp.mpf(0), th0, mp.mpf(0), mp.mpf(0)])
        ys = [sol(x(t)) for t in times]
    rows = {"psi": [y[0] for y in ys], "theta": [y[1] for y in ys], "phi": [y[2] for y in ys],
            "phi_dot": [rates(y[1])[1] for y in ys]}
    checks = []
    for k, vals in rows.items():
        sc = max(abs(v) for v in vals)
        checks += [estimated(f"{k}.{i}", v, sc, reason=f"relative to max |{k}|") for i, v in enumerate(vals)]
    return case("the template's nutating top", "top", {
        "m": 0.5, "L": 0.05, "I11": 2e-3, "I33": 1e-3, "psi": 0, "theta": 0.5, "phi": 0, "psi_dot": 0,
        "theta_dot": 0, "phi_dot": 100, "at": times}, checks,
        "released at θ = 0.5 with spin 100 rad/s: ψ, θ, φ, φ̇ at 0.05 and 0.2 s (exact route)")


def cases():
    return [_axisymmetric(), _intermediate()] + _sleeping() + [_nutating()]


assert math
