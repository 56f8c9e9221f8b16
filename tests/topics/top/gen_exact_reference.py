"""Generate tests/topics/top/exact_reference_data.py: the heavy top at high precision (mpmath).

An implementation independent of dyncli's (no Carlson forms, no cubic about u0, no
argument reduction in doubles): with u = cosθ, the roots u1 ≤ u2 ≤ u3 of
f(u) = (α − βu)(1 − u²) − (b − cu)² by mpmath.polyroots at 60 digits (close roots: the
phase at a turning point depends on their square root),

    u(t) = u1 + (u2 − u1) sn²(λt + σ0 | m),  m = (u2 − u1)/(u3 − u1),  λ = √(β(u3 − u1))/2,

σ0 from u0 (mpmath.ellipf) on the branch given by the sign of u̇0; ψ and φ by mpmath.quad of
ψ̇ = (b − cu)/(1 − u²) and φ̇ = ω3 − ψ̇u split at the turning points, whole periods
T = 2K/λ taken out in 40-digit arithmetic; θ̇ = −u̇/sinθ; R on e'' from Table 38.1's
ā with θ̈, ψ̈ from (38.18a, b).  Run:  python tests/topics/top/gen_exact_reference.py
"""

from __future__ import annotations

import pprint
from pathlib import Path

import mpmath as mp

DPS = 60

# name: (m, L, I11, I33, psi, theta, phi, psi_dot, theta_dot, phi_dot, times)
CASES = {
    "nutating": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.3, 1.2, -0.2, -2.0, 1.5, 40.0, [0.1, 0.37, 1.0, 3.3]),
    "near_vertical_stable": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.0, 1e-6, 0.0, 0.0, 0.0, 200.0, [0.05, 0.2, 1.0]),
    "near_vertical_falls": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.0, 1e-6, 0.0, 0.0, 0.0, 20.0, [0.05, 0.5, 1.5]),
    "spin5000": (0.5, 0.04, 1.2e-3, 4e-4, 0.0, 1.0, 0.0, 0.0, 0.0, 5000.0, [0.5, 1.0, 2.0]),
    "spin1e6": (0.5, 0.04, 1.2e-3, 4e-4, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0e6, [1e-3, 0.01, 0.1]),
    "oblate": (1.0, 0.05, 0.01, 0.018, 0.0, 1.2, 0.0, 2.0, -0.4, 30.0, [0.2, 1.0, 2.5]),
    "negative_spin": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.0, 2.0, 0.0, 1.0, 0.7, -60.0, [0.3, 1.1]),
    "long": (0.5, 0.05, 2.0e-3, 1.0e-3, 0.3, 1.2, -0.2, -2.0, 1.5, 40.0, [1.0e3, 1.0e6]),
}
G = 9.81


def solution(m, L, A, C, psi0, th0, phi0, psd0, thd0, phd0):
    m, L, A, C, g = (mp.mpf(x) for x in (m, L, A, C, G))
    psi0, th0, phi0, psd0, thd0, phd0 = (mp.mpf(x) for x in (psi0, th0, phi0, psd0, thd0, phd0))
    mgL = m * g * L
    u0, s0 = mp.cos(th0), mp.sin(th0)
    w3 = psd0 * u0 + phd0
    al = thd0 ** 2 + psd0 ** 2 * s0 ** 2 + 2 * mgL / A * u0
    be, b, c = 2 * mgL / A, (A * psd0 * s0 ** 2 + C * w3 * u0) / A, C * w3 / A
    r = sorted(mp.re(x) for x in mp.polyroots([be, -al - c ** 2, -be + 2 * b * c, al - b ** 2],
                                              maxsteps=800, extraprec=800))
    u1, u2, u3 = r
    u1, u2 = min(u1, u0), max(u2, u0)
    k2 = (u2 - u1) / (u3 - u1)
    lam = mp.sqrt(be * (u3 - u1)) / 2
    K = mp.ellipk(k2)
    x = mp.sqrt(min(max((u0 - u1) / (u2 - u1), 0), 1))
    sig = mp.ellipf(mp.asin(x), k2)
    if -s0 * thd0 < 0:          # u̇0 < 0: on the falling branch (σ in (K, 2K))
        sig = 2 * K - sig

    def u(t):
        return u1 + (u2 - u1) * mp.ellipfun("sn", lam * t + sig, m=k2) ** 2

    def udot(t):
        z = lam * t + sig
        sn, cn, dn = (mp.ellipfun(f, z, m=k2) for f in ("sn", "cn", "dn"))
        return 2 * (u2 - u1) * sn * cn * dn * lam

    def psid(t):
        x = u(t)
        return (b - c * x) / (1 - x * x)

    T = 2 * K / lam

    def integral(f, t):
        """∫_0^t f (T-periodic), split at the turning points t_k = (kK − σ0)/λ."""
        n = mp.floor(t / T)
        rest = t - n * T
        ta = (K - sig) / lam
        full = mp.quad(f, [ta, ta + T / 2, ta + T]) if n else 0
        tk = [(k * K - sig) / lam for k in range(0, 6)]
        pts = [mp.mpf(0)] + [z for z in tk if 0 < z < rest] + [rest]
        return n * full + mp.quad(f, pts)

    def state(t):
        t = mp.mpf(t)
        x = u(t)
        th = mp.acos(x)
        s, cth = mp.sin(th), x
        ps = psi0 + integral(psid, t)
        ph = phi0 + w3 * t - integral(lambda z: psid(z) * u(z), t)
        psd, thd = psid(t), -udot(t) / s
        phd = w3 - psd * x
        thdd = psd ** 2 * s * cth - C / A * psd * s * w3 + mgL / A * s                  # (38.18a)
        psdd_s = -2 * psd * thd * cth + C / A * w3 * thd                              # ψ̈ sinθ (38.18b)
        a = [L * psdd_s + 2 * L * psd * thd * cth, -L * thdd + L * psd ** 2 * s * cth, -L * thd ** 2 - L * psd ** 2 * s ** 2]
        R = [m * a[0], m * (g * s + a[1]), m * (g * cth + a[2])]
        return [float(v) for v in (ps, th, ph, psd, thd, phd)] + [[float(v) for v in R]]

    return state, float(mp.acos(u2)), float(mp.acos(u1))


def main():
    out = {}
    with mp.workdps(DPS):
        for name, case in CASES.items():
            *args, times = case
            state, tmin, tmax = solution(*args)
            out[name] = {"input": list(args), "times": times, "theta_min": tmin, "theta_max": tmax,
                         "rows": [state(t) for t in times]}
            print(name, "done")
    path = Path(__file__).with_name("exact_reference_data.py")
    path.write_text('"""Heavy-top reference values at 60 digits (mpmath), written by gen_exact_reference.py:\n'
                    'per case the inputs (m, L, I11, I33, ψ, θ, φ, ψ̇, θ̇, φ̇), times, θ_min, θ_max and rows\n'
                    '[ψ, θ, φ, ψ̇, θ̇, φ̇, R on e\'\'] (rounded to doubles)."""\n\nCASES = '
                    + pprint.pformat(out, width=110, sort_dicts=False) + "\n")


if __name__ == "__main__":
    main()
