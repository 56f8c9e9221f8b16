"""The ODE route's work integrals W̄, W_N and arc length s are carried in the state without steering
the steps (dyncli.dop853.DOP853 ``controlled``: only q, q̇ — and φ when ω varies — enter the error
norm).  Against independent 20-digit references (mpmath's Taylor ODE solver of the notes' equation
of motion along the curve, the energies and arc lengths in closed form from its q, q̇), at three
rtols: each carried quantity is within the route's promise (100 × rtol of its scale) and within a
small factor of the error of the state it is a quadrature of — the same accuracy as before they
left the step control."""

from __future__ import annotations

import functools

import mpmath as mp
import pytest

from tests.conftest import solve_text

TIMES = [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0]
RTOLS = [1e-6, 1e-8, 1e-10]
#: a quadrature of the motion carries the error of the state it integrates, not more (measured:
#: 0.3-1.5 × the larger of q's and q̇'s errors on these cases)
FACTOR = 3.0

HOOP = """type: constrained-particle
m: 0.1
curve: {{x1: "0.5*sin(q)", x2: 0, x3: "-0.5*cos(q)"}}
rotation: {{axis: [0, 0, 1], omega: "{w}"}}
q0: 0.3
forces: [{{kind: gravity}}]
at: {times}
accuracy: {{rtol: {rtol}, atol: {atol}, method: ode}}
"""
PARABOLA = """type: constrained-particle
m: 0.2
curve: {{x1: "q", x2: 0, x3: "0.5*q**2"}}
q0: 1.0
forces: [{{kind: gravity}}, {{kind: damper, c: 0.3}}]
at: {times}
accuracy: {{rtol: {rtol}, atol: {atol}}}
"""


@functools.lru_cache(maxsize=None)
def hoop_reference(varying: bool):
    """A hoop of radius R turning at ω(t) about its vertical diameter: q̈ = sin q (ω² cos q − g/R)
    (the Euler force ω̇ k × x is normal to the hoop); W_N = E − E1, s = R (q − q0)."""
    with mp.workdps(20):
        g, R, m = mp.mpf("9.81"), mp.mpf("0.5"), mp.mpf("0.1")
        w = (lambda t: 6 + mp.sin(t)) if varying else (lambda t: mp.mpf(6))
        sol = mp.odefun(lambda t, y: [y[1], mp.sin(y[0]) * (w(t) ** 2 * mp.cos(y[0]) - g / R)], 0,
                        [mp.mpf("0.3"), mp.mpf(0)])
        ref = [sol(t) for t in TIMES]
        E = [m / 2 * R ** 2 * (qd ** 2 + w(t) ** 2 * mp.sin(q) ** 2) - m * g * R * mp.cos(q)
             for t, (q, qd) in zip(TIMES, ref)]
        return {"q": [float(q) for q, _ in ref], "q_dot": [float(qd) for _, qd in ref],
                "W_N": [float(e - E[0]) for e in E], "s": [float(R * (q - mp.mpf("0.3"))) for q, _ in ref]}


@functools.lru_cache(maxsize=None)
def parabola_reference():
    """A bead on the fixed parabola z = x²/2 with gravity and a linear damper (F = −c v):
    m (1 + q²) q̈ + m q q̇² = −m g q − c (1 + q²) q̇; W̄ = E − E1 (the damper's work), s the
    parabola's arc length in closed form."""
    with mp.workdps(20):
        g, m, c = mp.mpf("9.81"), mp.mpf("0.2"), mp.mpf("0.3")
        sol = mp.odefun(lambda t, y: [y[1], (-m * g * y[0] - c * (1 + y[0] ** 2) * y[1] - m * y[0] * y[1] ** 2)
                                      / (m * (1 + y[0] ** 2))], 0, [mp.mpf(1), mp.mpf(0)])
        ref = [sol(t) for t in TIMES]
        E = [m / 2 * (1 + q ** 2) * qd ** 2 + m * g * q ** 2 / 2 for q, qd in ref]
        arc = lambda q: (q * mp.sqrt(1 + q * q) + mp.asinh(q)) / 2  # noqa: E731
        return {"q": [float(q) for q, _ in ref], "q_dot": [float(qd) for _, qd in ref],
                "W_nc": [float(e - E[0]) for e in E], "s": [float(arc(q) - arc(1)) for q, _ in ref]}


def _error(got, ref) -> float:
    """The largest error relative to the quantity's scale over the times."""
    scale = max(abs(x) for x in ref)
    return max(abs(a - b) for a, b in zip(got, ref)) / scale


CASES = {"hoop turning at 6 rad/s": (lambda: hoop_reference(False), HOOP, {"w": "6"}, ("W_N", "s")),
         "hoop turning at 6 + sin t rad/s": (lambda: hoop_reference(True), HOOP, {"w": "6 + sin(t)"}, ("W_N", "s")),
         "parabola with a damper": (parabola_reference, PARABOLA, {}, ("W_nc", "s"))}


@pytest.mark.parametrize("rtol", RTOLS)
@pytest.mark.parametrize("case", list(CASES))
def test_carried_integrals_as_accurate_as_the_state(case, rtol):
    reference, text, extra, carried = CASES[case]
    ref = reference()
    rec = solve_text(text.format(times=TIMES, rtol=rtol, atol=rtol * 1e-3, **extra))[0]
    assert rec.get("error") is None, rec.get("error")
    assert rec["method"] == "ode:DOP853"
    r = rec["results"]
    state = max(_error(r["q"], ref["q"]), _error(r["q_dot"], ref["q_dot"]))
    assert state <= 100 * rtol
    for k in carried:
        err = _error(r[k], ref[k])
        assert err <= 100 * rtol, (k, err)
        assert err <= FACTOR * state, (k, err, state)


def test_fixed_curve_normal_force_does_no_work():
    """On a fixed curve N ⊥ v: the carried W_N stays at rounding."""
    r = solve_text(PARABOLA.format(times=TIMES, rtol=1e-8, atol=1e-11))[0]["results"]
    assert max(abs(w) for w in r["W_N"]) < 1e-13
