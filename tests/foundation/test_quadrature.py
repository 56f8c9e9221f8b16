"""The quadrature runner (dyncli/quadrature.py): accuracy against closed-form integrals, its
error estimate against the true error, and the work budget (max_steps) shared with the ODE
routes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from dyncli.ode import OverBudget
from dyncli.quadrature import gauss_kronrod
from tests.conftest import solve_text


@pytest.mark.parametrize("f,a,b,exact", [
    (np.exp, 0.0, 1.0, math.e - 1.0),
    (lambda t: 1.0 / (1.0 + t * t), 0.0, 10.0, math.atan(10.0)),
    (lambda t: np.abs(np.sin(t)), 0.0, 10.0, 7.0 + math.cos(10.0)),   # kinks at kπ
    (np.sqrt, 0.0, 1.0, 2.0 / 3.0),                                         # endpoint singularity of f'
])
def test_accuracy_and_honest_estimate(f, a, b, exact):
    I, err, ok = gauss_kronrod(f, a, b, 1e-12, 1e-14)
    assert ok
    true = abs(I - exact)
    # converged to rtol (plus rounding of the sum: 64 ε of the integral), and the estimate covers the error
    assert true <= 1e-12 * abs(exact) + 64 * np.finfo(float).eps * abs(exact)
    assert err >= 0.5 * true or true <= 4 * np.finfo(float).eps * abs(exact)


def test_budget_refuses():
    with pytest.raises(OverBudget) as exc:
        gauss_kronrod(lambda t: np.abs(np.sin(50 * t)), 0.0, 100.0, 1e-13, 1e-15, max_steps=20)
    assert "budget of 20" in str(exc.value) and "accuracy.max_steps" in str(exc.value)


def test_distance_respects_max_steps():
    import mpmath as mp

    text = ("type: kinematics\ncoordinates: cartesian\nposition: {x1: 't', x2: 'sin(20*t)', x3: 0}\n"
            "at: [0]\ndistance: [0, 5]\naccuracy: {max_steps: 3}\n")
    rec = solve_text(text)[0]
    assert rec["exit_code"] == 1 and "accuracy.max_steps" in rec["error"]
    rec = solve_text(text.replace("max_steps: 3", "max_steps: 5000"))[0]
    mp.mp.dps = 30
    ref = mp.quad(lambda t: mp.sqrt(1 + 400 * mp.cos(20 * t) ** 2), mp.linspace(0, 5, 101))
    assert rec.get("error") is None
    assert abs(rec["results"]["distance"] - float(ref)) <= 1e-10 * float(ref)
    assert rec["error_estimate"] >= 0.5 * abs(rec["results"]["distance"] - float(ref)) / float(ref)


# --- many intervals at once (gauss_kronrod_many) ---------------------------------------------------

def _mp_integral(fn, a, b, points=()):
    """∫_a^b fn at 30 digits by mpmath (tanh-sinh), split at the integrand's kinks/peaks."""
    import mpmath as mp

    with mp.workdps(30):
        return float(mp.quad(fn, [mp.mpf(a), *[mp.mpf(p) for p in points], mp.mpf(b)]))


#: (numpy integrand, mpmath integrand, a, b, the points mpmath splits at): a kink in one interval,
#: a narrow peak in another, smooth ones around them
MANY = [
    (np.cos, lambda t: __import__("mpmath").cos(t), 0.0, 1.0, ()),
    (lambda t: np.abs(np.sin(5 * t)), lambda t: abs(__import__("mpmath").sin(5 * t)), 0.3, 1.1, (math.pi / 5,)),
    (lambda t: np.exp(-1e4 * (t - 0.37) ** 2), lambda t: __import__("mpmath").exp(-10000 * (t - 0.37) ** 2),
     0.0, 1.0, (0.37,)),
    (lambda t: 1.0 / (1.0 + t * t), lambda t: 1 / (1 + t * t), 2.0, 0.5, ()),         # reversed: −∫_0.5^2
    (np.exp, lambda t: __import__("mpmath").exp(t), 1.5, 1.5, ()),                       # zero width
]


def _many_f(calls):
    def f(i, t):
        calls.append(np.bincount(i, minlength=len(MANY)) // 15)
        out = np.empty_like(t)
        for j, (fn, *_rest) in enumerate(MANY):
            sel = i == j
            if np.any(sel):
                out[sel] = fn(t[sel])
        return out
    return f


def test_many_intervals_against_mpmath():
    from dyncli.quadrature import gauss_kronrod_many

    a = [m[2] for m in MANY]
    b = [m[3] for m in MANY]
    calls: list = []
    I, err, ok = gauss_kronrod_many(_many_f(calls), a, b, 1e-12, 1e-14)
    assert ok.all() and I.shape == err.shape == ok.shape == (len(MANY),)
    eps = np.finfo(float).eps
    for k, (_fn, mfn, lo, hi, pts) in enumerate(MANY):
        exact = _mp_integral(mfn, lo, hi, pts) if lo <= hi else -_mp_integral(mfn, hi, lo, pts)
        true = abs(I[k] - exact)
        assert true <= 1e-12 * abs(exact) + 64 * eps * abs(exact) + 1e-14, (k, I[k], exact)
        assert err[k] >= 0.5 * true or true <= 4 * eps * abs(exact) + 1e-300, (k, err[k], true)
    assert I[4] == 0.0 and err[4] == 0.0
    # every pass evaluates all the panels still open in one call; a smooth interval stops after
    # its first pass while the kink and the peak are refined
    per = np.array(calls)
    assert per[:, 0].sum() == 1 and per[:, 4].sum() == 0
    assert per[:, 1].sum() > 8 and per[:, 2].sum() > 8
    assert len(calls) == max(int(np.count_nonzero(per[:, k])) for k in range(len(MANY)))


#: kinks, a jump's neighbour (a square-root cusp) and a corner, each in the middle of a panel or
#: near its end: |K15 − G7| can vanish by accident on such a panel (∫|sin 5t| on [0.3, 1.1]: 18x
#: below the true error); QUADPACK's (200 d / A)^1.5 A guard keeps the estimate honest
KINKS = [
    (lambda t: np.abs(np.sin(5 * t)), lambda t: abs(__import__("mpmath").sin(5 * t)),
     [math.pi / 5 * k for k in range(1, 4)]),
    (lambda t: np.sqrt(np.abs(t - 0.7)), lambda t: __import__("mpmath").sqrt(abs(t - __import__("mpmath").mpf("0.7"))),
     [0.7]),
    (lambda t: np.abs(t - 0.61), lambda t: abs(t - __import__("mpmath").mpf("0.61")), [0.61]),
]


@pytest.mark.parametrize("k", range(len(KINKS)))
@pytest.mark.parametrize("a,b", [(0.3, 1.1), (0.0, 1.0), (0.1, 2.3)])
def test_estimate_covers_the_error_at_kinks(k, a, b):
    fn, mfn, kinks = KINKS[k]
    exact = _mp_integral(mfn, a, b, [p for p in kinks if a < p < b])
    eps = np.finfo(float).eps
    for rtol in (1e-4, 1e-6, 1e-8, 1e-10, 1e-12):
        I, err, ok = gauss_kronrod(fn, a, b, rtol, 1e-3 * rtol)
        true = abs(I - exact)
        assert ok
        assert true <= max(rtol * abs(exact), 1e-3 * rtol) + 64 * eps * abs(exact), (rtol, I, exact)
        # the estimate an estimate (its order of magnitude): at least half the true error
        assert err >= 0.5 * true or true <= 64 * eps * abs(exact), (rtol, err, true)


def test_many_intervals_refine_each_as_alone():
    """Each interval's integral, error and panels are those of gauss_kronrod on it alone (the
    sums to their rounding: the panels are added in another order)."""
    from dyncli.quadrature import gauss_kronrod, gauss_kronrod_many

    a = [m[2] for m in MANY]
    b = [m[3] for m in MANY]
    calls: list = []
    I, err, ok = gauss_kronrod_many(_many_f(calls), a, b, 1e-10, [1e-14, 1e-14, 1e-3, 1e-14, 0.0])
    per = np.array(calls).sum(axis=0)
    for k, (fn, _m, lo, hi, _p) in enumerate(MANY):
        n = []

        def g(t, fn=fn, n=n):
            n.append(t.size // 15)
            return fn(t)
        atol = [1e-14, 1e-14, 1e-3, 1e-14, 0.0][k]
        I1, e1, ok1 = gauss_kronrod(g, lo, hi, 1e-10, atol)
        assert ok1 == ok[k] and sum(n) == per[k], k
        assert abs(I1 - I[k]) <= 8 * np.finfo(float).eps * max(abs(I1), 1e-300), k
        assert abs(e1 - err[k]) <= 8 * np.finfo(float).eps * max(e1, abs(I1), 1e-300), k   # (|K15 − G7| of terms ~ I)


def test_many_intervals_budget_counts_all():
    from dyncli.quadrature import gauss_kronrod_many

    with pytest.raises(OverBudget) as exc:
        gauss_kronrod_many(lambda i, t: np.abs(np.sin(50 * t)), [0.0, 0.0], [100.0, 100.0], 1e-13, 1e-15,
                           max_steps=30)
    assert "budget of 30" in str(exc.value)


def test_noise_is_refused_by_the_solve_cpu_budget():
    """An integrand of rounding noise never converges; the runner looks at the solve's CPU budget
    once a pass (accuracy.max_cpu) and refuses at 2 × it, as the searches do, naming it — without a budget, the panel
    count refuses it (both exit 1)."""
    from types import SimpleNamespace

    from dyncli import cputime
    from dyncli.errors import NumericalError

    rng = np.random.default_rng(7)
    noise = lambda t: rng.standard_normal(np.shape(t))      # noqa: E731
    with cputime.solve_budget(SimpleNamespace(max_cpu=0.01, max_steps=None)):
        with pytest.raises(NumericalError, match="2 × the solve's CPU budget of 0.01 s") as exc:
            gauss_kronrod(noise, 0.0, 1.0, 1e-10, 0.0, max_steps=10**9, what="the noise")
        assert "accuracy.max_cpu" in str(exc.value) and "the noise" in str(exc.value)
        from dyncli.quadrature import gauss_kronrod_many

        with pytest.raises(NumericalError, match="CPU budget"):
            gauss_kronrod_many(lambda i, t: noise(t), [0.0, 1.0], [1.0, 2.0], 1e-10, 0.0, max_steps=10**9)
    with pytest.raises(OverBudget):
        gauss_kronrod(noise, 0.0, 1.0, 1e-10, 0.0, max_steps=2000)


@pytest.mark.parametrize("f, F, a, b", [
    (np.exp, math.expm1, 0.0, 2.0),
    (lambda t: 1.0 / (1.0 + t * t), math.atan, 0.0, 10.0),
    (lambda t: np.abs(np.sin(t)), lambda x: (math.floor(x / math.pi) * 2
                                             + (1 - math.cos(x - math.floor(x / math.pi) * math.pi))), 0.0, 10.0),
])
@pytest.mark.parametrize("rtol", [1e-6, 1e-10, 1e-13])
def test_dense_output_is_the_integral_to_its_estimate_and_inverts(f, F, a, b, rtol):
    """gauss_kronrod(dense=True): the antiderivative from the accepted panels' Kronrod
    interpolants, at 61 points, against the closed form: within the run's own error estimate
    (plus the rounding of a sum of its size); at b it is the integral itself; its inverse (f > 0)
    gives back an x where the antiderivative is the value asked, to the rounding of a panel's
    Chebyshev sum (so x to that over f: ~1e-11 at x = 0.013 where f = |sin x| is small)."""
    I, err, ok, A = gauss_kronrod(f, a, b, rtol, 0.0, dense=True)
    assert ok and A(b) == pytest.approx(I, rel=1e-15, abs=1e-15)
    floor = 64 * np.finfo(float).eps * abs(I)
    for x in np.linspace(a, b, 61):
        assert abs(A(float(x)) - (F(float(x)) - F(a))) <= err + floor, x
    for x in np.linspace(a + 0.013, b - 0.013, 23):
        y = A(float(x))
        back = A.inverse(y)
        assert abs(A(back) - y) <= floor, (x, back)
        assert abs(back - float(x)) <= 4 * floor / float(f(np.array([x]))[0]) + 4 * np.finfo(float).eps * abs(x)
