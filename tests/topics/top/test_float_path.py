"""The top's exact route at the requested times in plain floats (no numpy: issue 19's cold start)
against the same algorithm on numpy arrays (plots' dense sampling, more than FLOAT_TIMES times).

The two backends run one algorithm (dyncli.topics.top.elliptic.ExactTop over FLOAT_OPS or numpy);
math's and numpy's sin/arcsin and the two Carlson loops may differ by an ulp, which the phase
λt + τ0 carries as ~2ε(1 + λt) into sn, cn, dn, amplified by at most ~1/m1 next to the separatrix.
The bound allows 8ε(1 + λt)/min(m1, 1) relative to each quantity's scale (angles: π, rates: the
transverse rate of the initial state with the pendulum rate √(4mgL/I11)); 0.2 of it was observed
over 3000 random tops, most results being bit-identical.  The accuracy of both against 60-digit
references is test_exact.py's.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import example, given, settings
from hypothesis import strategies as st

from dyncli.topics.top.elliptic import ExactTop
from tests.conftest import solve_one_text

NAMES = ("psi", "theta", "phi", "psi_dot", "theta_dot", "phi_dot", "S")
RATE = st.floats(-100, 100).filter(lambda x: x == 0 or abs(x) >= 1e-30)


def _agree(ex, t, wsc):
    """One float time against a one-element array: the same finiteness, within the module's bound."""
    f = ex.evaluate(t)
    assert all(type(x) is float for x in f)
    a = [float(x[0]) for x in ex.evaluate(np.array([t]))]
    m1 = 1.0 if ex.steady else ex.nut.m1
    lam = 0.0 if ex.steady else ex.nut.lam
    tol = 8 * 2.0 ** -52 * (1 + lam * t) / min(m1, 1.0)
    for i, (x, y) in enumerate(zip(f, a)):
        assert math.isfinite(x) == math.isfinite(y), (NAMES[i], x, y)
        if math.isfinite(x):
            scale = math.pi if i < 3 else wsc
            assert abs(x - y) <= tol * max(abs(x), abs(y), scale), (NAMES[i], x, y)


@settings(max_examples=200, deadline=None)
@given(A=st.floats(1e-4, 1.0), ratio=st.floats(1e-6, 2.0), mgL=st.one_of(st.just(0.0), st.floats(1e-8, 10.0)),
       th=st.one_of(st.sampled_from([0.0, math.pi, 1e-9, math.pi - 1e-9]), st.floats(0.0, math.pi)),
       thd=st.one_of(st.just(0.0), RATE), psd=st.one_of(st.just(0.0), RATE),
       phd=st.one_of(st.just(0.0), st.floats(-1e4, 1e4)), t=st.one_of(st.just(0.0), st.floats(0.0, 1e3)))
@example(A=1.0, ratio=1.0, mgL=1.0, th=7.888609052210118e-31, thd=1.0, psd=0.0, phd=1.0, t=0.0)   # cubic: no root
def test_one_time_in_floats_is_the_array_path(A, ratio, mgL, th, thd, psd, phd, t):
    try:
        ex = ExactTop(A, ratio * A, mgL, 0.1, th, 0.2, psd, thd, phd)
    except RuntimeError:
        # the nutation cubic's root search cannot converge (θ ~1e-30 rad from an unstable vertical):
        # the route declares the top not representable and integrates it (exact_route.py, test_exact.py)
        return
    if not ex.nut.finite or (not ex.steady and ex.nut.m1 < 1e-6):
        return          # beyond doubles (the solver's fallback) or next to the separatrix (test_exact.py)
    _agree(ex, t, math.sqrt(thd * thd + (psd * math.sin(th)) ** 2 + 4 * mgL / A))


def test_turning_points_and_pole_passages_in_floats():
    """The float path's divisions at their zeros: released at rest (sn = 0 at t = 0), a sleeping top
    (v = 0), a planar pendulum swinging over the top (B = B' = 0: v = 0 and w = 0 at the passages,
    where ψ̇, φ̇ are nan on both paths), a steady precession."""
    cases = [(2e-3, 1e-3, 0.245, 0.0, 0.4, 0.0, 0.0, 0.0, 150.0),      # at rest at θ_min
             (2e-3, 1e-3, 0.245, 0.0, 0.0, 0.0, 0.0, 0.0, 100.0),      # sleeping
             (2e-3, 1e-3, 0.245, 0.0, 1.0, 0.0, 0.0, 30.0, 0.0)]       # over the top: B = B' = 0
    for A, C, mgL, ps, th, ph, psd, thd, phd in cases:
        ex = ExactTop(A, C, mgL, ps, th, ph, psd, thd, phd)
        wsc = math.sqrt(thd * thd + 4 * mgL / A)
        times = [0.0, 0.01, 0.3]
        if not ex.steady:
            P = 2.0 * ex.K / ex.nut.lam
            times += [P, 0.5 * P, 1.75 * P]
        for t in times:
            _agree(ex, t, wsc)


def test_few_and_many_times_give_the_same_motion():
    """FLOAT_TIMES times (plain floats, no numpy) and one more (arrays) report the same motion and
    reaction at the shared times, within the bound above."""
    from dyncli.topics.top.exact_route import FLOAT_TIMES

    txt = ("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 0.3\ntheta_dot: -2\n"
           "psi_dot: 16.918\nphi_dot: 50\n")
    ts = [0.013 * k for k in range(FLOAT_TIMES)]
    few = solve_one_text(txt + f"at: {ts}\n")["results"]
    many = solve_one_text(txt + f"at: {ts + [0.5]}\n")["results"]
    for name in ("psi", "theta", "phi", "theta_dot", "R"):
        a, b = np.array(few[name], dtype=float), np.array(many[name], dtype=float)[:FLOAT_TIMES]
        assert np.allclose(a, b, rtol=1e-13, atol=1e-13 * np.max(np.abs(a))), name
