"""The nutation cubic's root ξ3 (``elliptic._xi3``) by the plain-float Brent of
``elliptic._brent``, against scipy's ``brentq`` (the independent route it replaces).

_brent performs brentq's floating-point operations in the same order, so the roots are the
same double: the tolerance is 0 ulp, at the extremes of the tops' constants (the cubics of
random tops, and brackets spanning 1e-300 to 1e300).  And a top solved by the exact route no
longer imports scipy.optimize.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
from pathlib import Path

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from dyncli.topics.top import elliptic as E

ROOT = Path(__file__).resolve().parents[3]
RTOL = 4 * E.EPS


def _brentq(f, a, b):
    from scipy.optimize import brentq

    return brentq(f, a, b, xtol=1e-300, rtol=RTOL, maxiter=400)


def _brackets(monkeypatch, *top):
    """The (R, 0, hi) brackets that the Nutation of one top hands to _brent."""
    seen = []
    real = E._brent

    def spy(f, a, b, xtol, rtol, maxiter):
        seen.append((f, a, b))
        return real(f, a, b, xtol, rtol, maxiter)

    monkeypatch.setattr(E, "_brent", spy)
    try:
        E.Nutation(*top)
    except RuntimeError:        # a search that does not converge: compared below, both must fail
        pass
    monkeypatch.setattr(E, "_brent", real)
    return seen


def _outcome(fn):
    try:
        return fn()
    except RuntimeError:        # no convergence in maxiter (both implementations say so)
        return RuntimeError


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@example(lgA=0.0, cr=0.0, lgmgl=0.0, th=7.888609052210118e-31, thd=1.0, psd=1.0, w3=0.0)   # neither converges
@given(st.floats(-6, 2), st.floats(0, 2), st.floats(-8, 2),
       st.one_of(st.floats(0, math.pi), st.floats(-12, -1).map(lambda e: 10 ** e),
                 st.floats(-12, -1).map(lambda e: math.pi - 10 ** e)),
       st.floats(-1e3, 1e3), st.floats(-1e3, 1e3), st.floats(-1e5, 1e5))
def test_xi3_is_brentq_bit_for_bit(monkeypatch, lgA, cr, lgmgl, th, thd, psd, w3):
    A = 10 ** lgA
    for f, a, b in _brackets(monkeypatch, A, cr * A, 10 ** lgmgl, th, thd, psd, w3):
        assert _outcome(lambda: E._brent(f, a, b, 1e-300, RTOL, 400)) == _outcome(lambda: _brentq(f, a, b))


@settings(max_examples=300, deadline=None)
@given(st.floats(-300, 300), st.floats(0, 1, exclude_min=True), st.floats(-300, 300),
       st.floats(-3, 3), st.floats(1, 100))
def test_brent_is_brentq_at_extreme_scales(lgr, fr, lgs, c, widen):
    r, s = 10 ** lgr * fr, 10 ** lgs

    def f(z):
        return s * (z - r) * (1 + c * c * z * z)

    hi = max(2 * r, 1e-300) * widen
    try:
        want = _brentq(f, 0.0, hi)
    except ValueError:          # f overflows to nan inside the bracket: both refuse
        want = ValueError
    try:
        got = E._brent(f, 0.0, hi, 1e-300, RTOL, 400)
    except ValueError:
        got = ValueError
    assert got == want


def test_exact_route_does_not_import_scipy_optimize():
    code = ("import sys\nfrom tests.conftest import solve_one_text\n"
            "rec = solve_one_text('type: top\\nm: 0.5\\nL: 0.05\\nI11: 2e-3\\nI33: 1e-3\\ntheta: 0.5\\n"
            "phi_dot: 100\\nat: [0, 1]\\n')\n"
            "assert rec['method'] == 'exact', rec['method']\n"
            "print('scipy.optimize' in sys.modules)")
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True,
                         timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "False"
