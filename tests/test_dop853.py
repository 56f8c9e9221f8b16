"""dyncli's own DOP853 (dyncli/dop853.py) against scipy's, the independent implementation it
transcribes: the same steps, states, function-evaluation counts and interpolated values, bit for
bit, over problems that exercise every branch of the step-size control (rejected steps, the
rtol floor, a first step given, a step cap, backward integration, a step that ends on t_bound,
a system at rest, an empty interval); and a cold run of an explicit route that does not import
scipy.integrate (the point of the copy: issue #31, item 4).

scipy changed its starting-step rule in 1.14 (capped by the interval and max_step); dyncli
follows the newer rule, so the bit-for-bit comparison needs scipy >= 1.14 (older versions are
compared by the accuracy both deliver instead)."""

from __future__ import annotations

import inspect
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy import integrate as si
from scipy.integrate._ivp import common as scipy_common

from dyncli.dop853 import DOP853, OdeSolution

ROOT = Path(__file__).resolve().parents[1]
NEW_START = "t_bound" in inspect.signature(scipy_common.select_initial_step).parameters


def kepler(t, y):
    r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
    return [y[2], y[3], -y[0] / r3, -y[1] / r3]


def van_der_pol(t, y):
    return [y[1], 5 * (1 - y[0] ** 2) * y[1] - y[0]]


def forced(t, y):
    return np.array([y[1], -y[0] + 0.1 * np.sin(3 * t)])


def at_rest(t, y):
    return np.zeros_like(y)


CASES = [(kepler, [0.1, 0.0, 0.0, np.sqrt(1.9 / 0.1)], 0.0, 20.0),    # e = 0.9: rejected steps at perigee
         (van_der_pol, [2.0, 0.0], 0.0, 10.0),
         (forced, [1.0, 0.0], 0.0, -7.0),                                 # backward
         (forced, [0.0, 0.0], 1.0, 6.0),
         (at_rest, [1.0, 2.0], 0.0, 3.0)]
OPTIONS = [{}, {"first_step": 1e-3}, {"max_step": 0.05}]


def _pair(f, y0, t0, t1, rtol, kw):
    return (si.DOP853(f, t0, y0, t1, rtol=rtol, atol=1e-12, **kw),
            DOP853(f, t0, y0, t1, rtol=rtol, atol=1e-12, **kw))


@pytest.mark.skipif(not NEW_START, reason="scipy < 1.14 starts with another first step")
@pytest.mark.filterwarnings("ignore:At least one element of `rtol` is too small")
@pytest.mark.parametrize("case", range(len(CASES)))
@pytest.mark.parametrize("rtol", [1e-3, 1e-6, 1e-10, 1e-13, 1e-16])
def test_every_step_is_scipys_bit_for_bit(case, rtol):
    f, y0, t0, t1 = CASES[case]
    for kw in OPTIONS:
        theirs, ours = _pair(f, y0, t0, t1, rtol, kw)
        steps = 0
        while theirs.status == "running":
            assert theirs.step() == ours.step()
            steps += 1
            assert (ours.t, ours.t_old, ours.status) == (theirs.t, theirs.t_old, theirs.status)
            assert np.array_equal(ours.y, theirs.y) and np.array_equal(ours.f, theirs.f)
            if steps % 5 == 1:
                ts = np.linspace(theirs.t_old, theirs.t, 7)
                assert np.array_equal(ours.dense_output()(ts), theirs.dense_output()(ts))
                assert np.array_equal(ours.dense_output()(ts[3]), theirs.dense_output()(ts[3]))
        assert ours.nfev == theirs.nfev and ours.status == "finished"


@pytest.mark.skipif(not NEW_START, reason="scipy < 1.14 starts with another first step")
def test_the_piecewise_interpolant_is_scipys():
    theirs, ours = _pair(kepler, CASES[0][1], 0.0, 5.0, 1e-9, {})
    ts, d_theirs, d_ours = [0.0], [], []
    while theirs.status == "running":
        theirs.step(), ours.step()
        ts.append(theirs.t)
        d_theirs.append(theirs.dense_output()), d_ours.append(ours.dense_output())
    q = np.concatenate([ts, np.random.default_rng(1).uniform(0.0, 5.0, 200)])     # at step ends too
    assert np.array_equal(OdeSolution(ts, d_ours)(q), si.OdeSolution(ts, d_theirs)(q))
    assert all(np.array_equal(OdeSolution(ts, d_ours)(t), si.OdeSolution(ts, d_theirs)(t)) for t in ts)
    back = ts[::-1]
    assert np.array_equal(OdeSolution(back, d_ours[::-1])(q), si.OdeSolution(back, d_theirs[::-1])(q))


def test_accuracy_against_the_closed_form():
    # x'' = -x from (1, 0): cos t, -sin t; DOP853's global error at rtol 1e-10 is ~1e-10 over 20 s
    s = DOP853(lambda t, y: [y[1], -y[0]], 0.0, [1.0, 0.0], 20.0, rtol=1e-10, atol=1e-12)
    while s.status == "running":
        s.step()
    assert s.t == 20.0 and np.allclose(s.y, [np.cos(20.0), -np.sin(20.0)], rtol=0, atol=2e-9)


def test_refusals_and_corner_cases():
    with pytest.raises(ValueError, match="finite"):
        DOP853(forced, 0.0, [np.nan, 0.0], 1.0)
    with pytest.raises(ValueError, match="1-dimensional"):
        DOP853(forced, 0.0, [[1.0, 0.0]], 1.0)
    with pytest.raises(ValueError, match="max_step"):
        DOP853(forced, 0.0, [1.0, 0.0], 1.0, max_step=0.0)
    empty = DOP853(forced, 2.0, [1.0, 0.0], 2.0)           # an empty interval: one step, finished
    assert empty.step() is None and empty.status == "finished"
    assert np.array_equal(empty.dense_output()(np.array([2.0, 2.0])), [[1.0, 1.0], [0.0, 0.0]])
    with pytest.raises(RuntimeError):
        empty.step()


def test_an_explicit_route_does_not_import_scipy_integrate():
    code = ("import sys, runpy\n"
            "sys.argv = ['dyncli', 'solve', '-f', 'json', 'benchmarks/cold_scripts/particle_drag.yaml']\n"
            "try:\n    runpy.run_module('dyncli', run_name='__main__')\nexcept SystemExit:\n    pass\n"
            "print('MODS', [m for m in sys.modules if m.startswith('scipy')], file=sys.stderr)\n")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    rec = json.loads(out.stdout)
    rec = rec[0] if isinstance(rec, list) else rec
    assert rec["method"].startswith("ode") and rec.get("error") is None
    assert "MODS []" in out.stderr, out.stderr


def test_an_interpolant_made_later_is_the_same():
    """``dense_later`` (the interpolant built on its first call) gives dense_output's values."""
    s = DOP853(kepler, 0.0, CASES[0][1], 5.0, rtol=1e-8, atol=1e-12)
    while s.status == "running":
        s.step()
        now, later = s.dense_output(), s.dense_later()
        ts = np.linspace(s.t_old, s.t, 5)
        assert np.array_equal(now(ts), later(ts)) and np.array_equal(now(ts[2]), later(ts[2]))


def test_uncontrolled_components_do_not_steer_the_steps():
    """``controlled=2``: van der Pol with ∫ y0² dt carried along takes the 2-state run's steps (the
    same number and times to rounding: the BLAS products of a 3-column state may round otherwise,
    and the error estimate's cancellation magnifies that into the step sizes), not those of the
    3-state run that controls the integral too; the carried integral matches a separate tight
    quadrature of the same motion."""
    def augmented(t, y):
        return van_der_pol(t, y[:2]) + [y[0] * y[0]]

    def run(s):
        ts = []
        while s.status == "running":
            s.step()
            ts.append(s.t)
        return np.array(ts), s

    t2, plain = run(DOP853(van_der_pol, 0.0, [2.0, 0.0], 10.0, rtol=1e-8, atol=1e-11))
    tc, carried = run(DOP853(augmented, 0.0, [2.0, 0.0, 0.0], 10.0, rtol=1e-8, atol=1e-11, controlled=2))
    t3, _ = run(DOP853(augmented, 0.0, [2.0, 0.0, 0.0], 10.0, rtol=1e-8, atol=1e-11))
    assert len(tc) == len(t2) != len(t3) and carried.nfev == plain.nfev
    assert np.allclose(tc, t2, rtol=1e-5, atol=0) and np.allclose(carried.y[:2], plain.y, rtol=1e-9, atol=1e-12)
    tight = si.solve_ivp(augmented, (0.0, 10.0), [2.0, 0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-14)
    assert abs(carried.y[2] - tight.y[2, -1]) <= 1e-6 * abs(tight.y[2, -1])
    # every component controlled (controlled >= n) is the default: scipy's steps
    assert DOP853(augmented, 0.0, [2.0, 0.0, 0.0], 1.0, controlled=3).controlled is None
