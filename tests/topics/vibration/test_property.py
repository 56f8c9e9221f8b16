"""Property: the returned x(t) satisfies the equation of motion (17.15a)
and the initial conditions (17.7) to near machine precision.

The check is independent of the closed form: (17.15a) with s = s0 sin(Ωt)
is the autonomous linear system z' = M z for z = (x, ẋ, sin Ωt, cos Ωt, 1),
whose exact flow over a step h is expm(M h), evaluated by mpmath at 40
digits.  Every returned state (x(tᵢ), ẋ(tᵢ)) must map to the next one,
(x(tᵢ₊₁), ẋ(tᵢ₊₁)), under that flow — no finite differences of the float
output are taken.
"""

from __future__ import annotations

import math

import mpmath as mp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from dyncli import registry
from dyncli.result import SolveOptions

TOL = 2e-13

Vibration = registry.model_class("vibration")
solve = registry.solver("vibration")


def _solve(data):
    model = Vibration.model_validate(data, context={"params": {}})
    return solve(model, SolveOptions()).results


def _flow(m, k, c, L, s0, Om, h):
    with mp.workdps(40):
        m, k, c, L, s0, Om, h = (mp.mpf(a) for a in (m, k, c, L, s0, Om, h))
        M = mp.zeros(5, 5)
        M[0, 1] = 1
        # m ẍ + k(x − s − L) + c(ẋ − ṡ) = 0,  s = s0 sin, ṡ = s0 Ω cos
        M[1, 0] = -k / m
        M[1, 1] = -c / m
        M[1, 2] = k * s0 / m
        M[1, 3] = c * s0 * Om / m
        M[1, 4] = k * L / m
        M[2, 3] = Om
        M[3, 2] = -Om
        return mp.expm(M * h)


zetas = st.one_of(
    st.just(0.0), st.just(1.0),
    st.floats(0.0, 3.0),
    st.floats(-1e-6, 1e-6).map(lambda d: 1.0 + d),
    st.floats(0.0, 3.0).map(lambda e: 10.0 ** e),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    m=st.floats(0.1, 10.0), k=st.floats(0.1, 100.0), zeta=zetas,
    L=st.floats(-2.0, 2.0), w0=st.floats(-1.0, 1.0), v0=st.floats(-3.0, 3.0),
    base=st.one_of(st.none(), st.tuples(st.floats(-0.5, 0.5), st.one_of(st.just(-1.0), st.floats(0.0, 3.0)))),
    steps=st.lists(st.floats(0.01, 1.5), min_size=1, max_size=4),
)
def test_response_satisfies_equation_of_motion(m, k, zeta, L, w0, v0, base, steps):
    wn = math.sqrt(k / m)
    data = {"type": "vibration", "m": m, "k": k, "zeta": zeta, "L": L, "x0": L + w0, "v0": v0}
    s0 = Om = 0.0
    if base is not None:
        s0, ratio = base
        Om = wn if ratio < 0 else ratio * wn          # -1: exactly at resonance
        data["base"] = {"amplitude": s0, "omega": Om}
    times = [0.0]
    for h in steps:
        times.append(times[-1] + h / wn)
    data["at"] = times
    R = _solve(data)
    x, v = R["x"], R["v"]
    c = R["c"]
    # initial conditions (17.7)
    scale_x = max(abs(L) + abs(w0), max(abs(a - L) for a in x), abs(s0), 1e-300)
    scale_v = max(max(abs(a) for a in v), abs(v0), wn * scale_x)
    assert abs(x[0] - (L + w0)) <= 1e-15 * scale_x
    assert abs(v[0] - v0) <= 4e-16 * scale_v
    # (17.15a): each returned state flows exactly into the next one
    with mp.workdps(40):
        for i in range(len(times) - 1):
            t0, t1 = times[i], times[i + 1]
            E = _flow(m, k, c, L, s0, Om, mp.mpf(t1) - mp.mpf(t0))
            z0 = mp.matrix([x[i], v[i], mp.sin(Om * mp.mpf(t0)), mp.cos(Om * mp.mpf(t0)), 1])
            z1 = E * z0
            assert abs(z1[0] - x[i + 1]) <= TOL * scale_x, (i, float(z1[0]), x[i + 1])
            assert abs(z1[1] - v[i + 1]) <= TOL * scale_v, (i, float(z1[1]), v[i + 1])
