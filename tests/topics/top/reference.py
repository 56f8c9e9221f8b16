"""Independent references for the heavy top (test-only).

* ``bounds_mp``: θ_min, θ_max as roots of the cubic in u = cosθ, built here
  from E, H·e3 and ω3 of the initial Euler angles and solved with mpmath;
* ``euler_angle_ode``: (38.18) integrated directly in the Euler angles
  (scipy DOP853 at rtol 1e-13) — a different formulation from the solver's
  quaternion/body-rate one (fails at θ = 0, so only away from the poles);
* ``dcm_ode``: the direction cosines of the body axes and the body rates,
  integrated with scipy DOP853 (again a different representation);
* ``slow_root_mp``: the slow steady-precession rate, a root of (38.22).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np


def invariants(A, C, mgL, th, thd, psd, phd):
    u = math.cos(th)
    s = math.sin(th)
    w3 = psd * u + phd
    E = 0.5 * A * (thd ** 2 + psd ** 2 * s ** 2) + 0.5 * C * w3 ** 2 + mgL * u
    H = A * psd * s ** 2 + C * w3 * u
    return E, H, w3


def bounds_mp(m, L, A, C, g, th, thd, psd, phd, dps=50):
    with mp.workdps(dps):
        m, L, A, C, g = (mp.mpf(x) for x in (m, L, A, C, g))
        th, thd, psd, phd = (mp.mpf(x) for x in (th, thd, psd, phd))
        u0, s = mp.cos(th), mp.sin(th)
        w3 = psd * u0 + phd
        E = A / 2 * (thd ** 2 + psd ** 2 * s ** 2) + C / 2 * w3 ** 2 + m * g * L * u0
        H = A * psd * s ** 2 + C * w3 * u0
        al, be, b, c = (2 * E - C * w3 ** 2) / A, 2 * m * g * L / A, H / A, C * w3 / A
        # u̇² = (α − βu)(1 − u²) − (b − cu)²
        coef = [be, -al - c ** 2, -be + 2 * b * c, al - b ** 2]
        r = sorted(mp.re(x) for x in mp.polyroots(coef, maxsteps=400, extraprec=400))
        r = [max(-1, min(1, x)) for x in r]     # a root at u = ±1 may come out a rounding outside
        return float(mp.acos(r[1])), float(mp.acos(r[0]))


def slow_root_mp(m, L, A, C, g, th, p, dps=50):
    with mp.workdps(dps):
        a = (mp.mpf(A) - mp.mpf(C)) * mp.cos(mp.mpf(th))
        r = mp.polyroots([a, -mp.mpf(C) * p, mp.mpf(m) * g * L], maxsteps=200, extraprec=200)
        return float(min(r, key=abs))


def euler_angle_ode(m, L, A, C, g, y0, times):
    """(38.18) in ψ, θ, φ: returns rows [ψ, θ, φ, ψ̇, θ̇, φ̇, ψ̈, θ̈] at the times."""
    from scipy.integrate import solve_ivp

    mgL = m * g * L

    def acc(y):
        ps, th, ph, psd, thd, phd = y
        s, c = math.sin(th), math.cos(th)
        w3 = psd * c + phd
        thdd = psd ** 2 * s * c - C / A * psd * s * w3 + mgL / A * s       # (38.18a)
        psdd = (-2 * psd * thd * c + C / A * w3 * thd) / s                # (38.18b)
        phdd = -(psdd * c - psd * thd * s)                                # (38.18c)
        return psdd, thdd, phdd

    def f(t, y):
        psdd, thdd, phdd = acc(y)
        return [y[3], y[4], y[5], psdd, thdd, phdd]

    T = max(times)
    sol = solve_ivp(f, (0, T), y0, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=sorted(times), dense_output=False)
    assert sol.status == 0
    out = []
    for k in range(len(sol.t)):
        y = sol.y[:, k]
        psdd, thdd, _ = acc(y)
        out.append(list(y) + [psdd, thdd])
    return np.array(out)


def rot_z(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def rot_x(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])


def euler313(psi, th, phi):
    return rot_z(psi) @ rot_x(th) @ rot_z(phi)


def dcm_ode(m, L, A, C, g, psi, th, phi, psd, thd, phd, times):
    """Direction cosines Q (columns = body axes) and body ω (DOP853)."""
    from scipy.integrate import solve_ivp

    mgL = m * g * L
    Q0 = euler313(psi, th, phi)
    # body ω: ω = θ̇ e''1 + ψ̇ sinθ e''2 + (ψ̇ cosθ + φ̇) e''3, e''_i = columns of Rz(ψ)Rx(θ)
    Epp = rot_z(psi) @ rot_x(th)
    om = thd * Epp[:, 0] + psd * math.sin(th) * Epp[:, 1] + (psd * math.cos(th) + phd) * Epp[:, 2]
    w0 = Q0.T @ om
    I = np.array([A, A, C])

    def f(t, y):
        Q = y[:9].reshape(3, 3)
        w = y[9:]
        gam = Q[2, :]                        # body components of e3
        M = np.cross([0, 0, L], -m * g * gam)  # x̄ × (−mg e3)
        wd = (M - np.cross(w, I * w)) / I
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([(Q @ W).ravel(), wd])

    sol = solve_ivp(f, (0, max(times)), np.concatenate([Q0.ravel(), w0]), method="DOP853",
                    rtol=1e-12, atol=1e-13, t_eval=sorted(times))
    assert sol.status == 0
    return [sol.y[:9, k].reshape(3, 3) for k in range(len(sol.t))], [sol.y[9:, k] for k in range(len(sol.t))]


def released_top_mp(m, L, A, C, g, th0, w3, times, dps=20, rates=False):
    """ψ, θ, φ of a top released at rest in θ, ψ (θ̇0 = ψ̇0 = 0, spin ω3) in closed form.

    With u = cosθ: u̇² = (u0 − u)[β(1 − u²) − c²(u0 − u)] = β(u − u1)(u2 − u)(u3 − u), u2 = u0,
    β = 2mgL/I11, c = I33 ω3/I11, so u = u1 + (u2 − u1) sn²(ω t + K, k), k² = (u2 − u1)/(u3 − u1),
    ω = √(β(u3 − u1))/2 (Jacobi elliptic, mpmath); ψ̇ = c(u0 − u)/(1 − u²), φ̇ = ω3 − ψ̇ u by quadrature
    (split at the quarter periods).  Returns a list of (ψ, θ, φ) as floats, with ``rates`` also
    (ψ̇, θ̇, φ̇), θ̇ = −u̇/sinθ with u̇ from mpmath's numerical derivative."""
    with mp.workdps(dps):
        m, L, A, C, g, th0, w3 = (mp.mpf(x) for x in (m, L, A, C, g, th0, w3))
        u0, be, c = mp.cos(th0), 2 * m * g * L / A, C * w3 / A
        d = mp.sqrt(c ** 4 - 4 * be * (c ** 2 * u0 - be))
        u1, u3 = (c ** 2 - d) / (2 * be), (c ** 2 + d) / (2 * be)
        k2 = (u0 - u1) / (u3 - u1)
        om = mp.sqrt(be * (u3 - u1)) / 2
        K = mp.ellipk(k2)

        def u(t):
            return u1 + (u0 - u1) * mp.ellipfun("sn", om * t + K, m=k2) ** 2

        def psid(t):
            x = u(t)
            return c * (u0 - x) / (1 - x * x)

        out = []
        for t in times:
            t = mp.mpf(t)
            pts = [K * j / om for j in range(int(mp.floor(om * t / K)) + 1)] + [t]
            psi = mp.quad(psid, pts)
            phi = w3 * t - mp.quad(lambda s: psid(s) * u(s), pts)
            row = (float(psi), float(mp.acos(u(t))), float(phi))
            if rates:
                x = u(t)
                row += (float(psid(t)), float(-mp.diff(u, t) / mp.sqrt(1 - x * x)), float(w3 - psid(t) * x))
            out.append(row)
        return out


def wperp_max(m, L, A, g, th, thd, psd, th_max):
    """|ω⊥|max = √(θ̇² + ψ̇² sin²θ) at θ_max, from the energy integral: the scale the top's ODE route
    uses for θ̇ and ψ̇ (their error relative to the transverse-rate scale)."""
    K0 = thd ** 2 + (psd * math.sin(th)) ** 2
    return math.sqrt(K0 + 2 * m * g * L / A * max(math.cos(th) - math.cos(th_max), 0.0))
