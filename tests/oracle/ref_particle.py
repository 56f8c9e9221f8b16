"""Oracle cases: a particle under forces — Kepler orbits (the exact route) at e = 0.97 over five
revolutions, next to the parabola (e = 1 ∓ 1e-6) where Kepler's equation cancels, at the scale of
satellites (1e7 … 1e8 m, 1e6 s); and the ODE route on a tiny particle (1e-9 kg) with linear drag,
whose motion is known in closed form."""

from __future__ import annotations

import mpmath as mp

from tests.oracle.common import bisect, case, estimated, norm, ode, x

G, R0 = x(9.81), x(6371000)
MU = G * R0 ** 2


def conic(rp, vp):
    """(state(t) -> (x, v, a) and the elements) of the orbit from perigee [rp, 0, 0] at [0, vp, 0]."""
    en = vp ** 2 / 2 - MU / rp
    h = rp * vp
    e = mp.sqrt(1 + 2 * en * h ** 2 / MU ** 2)
    a = -MU / (2 * en)
    n = mp.sqrt(MU / abs(a) ** 3)

    def state(t):
        M = n * t
        if e < 1:
            E = bisect(lambda E: E - e * mp.sin(E) - M, M - 1, M + 1)
            d = 1 - e * mp.cos(E)
            b = a * mp.sqrt(1 - e ** 2)
            X = [a * (mp.cos(E) - e), b * mp.sin(E), 0]
            V = [-a * n * mp.sin(E) / d, b * n * mp.cos(E) / d, 0]
        else:
            F = bisect(lambda F: e * mp.sinh(F) - F - M, 0, mp.asinh(M / e) + mp.cbrt(6 * M) + 1)
            d = e * mp.cosh(F) - 1
            A, b = abs(a), abs(a) * mp.sqrt(e ** 2 - 1)
            X = [A * (e - mp.cosh(F)), b * mp.sinh(F), 0]
            V = [-A * n * mp.sinh(F) / d, b * n * mp.cosh(F) / d, 0]
        r = norm(X)
        return X, V, [-MU * c / r ** 3 for c in X]
    return state, {"e": e, "a": a, "period": 2 * mp.pi / n if e < 1 else None}


def _orbit_checks(state, times):
    sts = [state(t) for t in times]
    out = []
    for q, name in enumerate(("x", "v", "a")):
        sc = max(norm(s[q]) for s in sts)
        for i, s in enumerate(sts):
            out += [estimated(f"{name}.{i}.{j}", s[q][j], sc, reason=f"exact route; |{name}| over the times")
                    for j in range(2)]
    return out


def _orbit(name, rp, vp, times, note):
    state, el = conic(x(rp), x(vp))
    doc = {"m": 1000, "x0": [rp, 0, 0], "v0": [0, vp, 0],
           "forces": [{"kind": "inverse-square", "center": [0, 0, 0], "R0": 6371000}], "at": times}
    checks = _orbit_checks(state, [x(t) for t in times]) + [estimated("orbit.e", el["e"], 1)]
    return case(name, "particle", doc, checks, note)


def _orbits():
    rp = 7e6
    vp = float(mp.sqrt(MU * (1 + mp.mpf("0.97")) / rp))
    _, el = conic(x(rp), x(vp))
    P = el["period"]
    times = [0, float(2.5 * P), float(5 * P), float(5 * P + 100)]
    ecc = _orbit("e = 0.97, five revolutions", rp, vp, times,
                 "r_p = 7000 km, a = 2.3e8 m, period 1.1e6 s: apogee after 2.5 turns, perigee after 5 and 100 s past it")
    near = []
    for e, what in (("0.999999", "ellipse"), ("1.000001", "hyperbola")):
        vpe = float(mp.sqrt(MU * (1 + mp.mpf(e)) / rp))
        tp = rp / vpe                                  # the perigee passage's time scale, ~740 s
        near.append(_orbit(f"e = {e}, next to the parabola", rp, vpe, [float(tp), float(30 * tp), float(1000 * tp)],
                           f"an {what} with 1 − e = ∓1e-6 through perigee: Kepler's equation at M ≈ 0 with e ≈ 1"))
    return [ecc] + near


def _drag():
    m, c, v0 = x(1e-9), x(2e-9), [x(3), 0, x(4)]
    k = c / m
    vinf = [0, 0, -G / k]
    times = [x(0.5), x(2)]

    def X(t):
        return [vinf[j] * t + (v0[j] - vinf[j]) * (1 - mp.exp(-k * t)) / k for j in range(3)]

    def V(t):
        return [vinf[j] + (v0[j] - vinf[j]) * mp.exp(-k * t) for j in range(3)]
    rtol = 1e-10
    xs, vs = max(norm(X(t)) for t in times), max(norm(V(t)) for t in times + [0])
    checks = [ode(f"x.{i}.{j}", X(t)[j], rtol, xs) for i, t in enumerate(times) for j in (0, 2)]
    checks += [ode(f"v.{i}.{j}", V(t)[j], rtol, vs) for i, t in enumerate(times) for j in (0, 2)]
    return [case("a 1e-9 kg particle with linear drag", "particle", {
        "m": 1e-9, "x0": [0, 0, 0], "v0": [3, 0, 4], "forces": [{"kind": "gravity"}, {"kind": "damper", "c": 2e-9}],
        "at": [0.5, 2], "accuracy": {"rtol": rtol}}, checks,
        "m = 1e-9 kg, c = 2e-9 N s/m (c/m = 2 /s) under gravity: the ODE route, forces of 1e-8 N")]


def cases():
    return _orbits() + _drag()
