"""The energy route (dyncli/energy_route.py): ṡ² = K(s) integrated by quadrature, against
references computed independently of it — closed forms, and mpmath at 30 digits (Jacobi
elliptic functions, the complete integral K(k), odefun).

What the method guarantees, and so what these tests hold it to (docs/accuracy.md, quadrature
row): the reported ``error_estimate`` (relative to each quantity's scale: s to the motion's
extent, ṡ to its largest speed) covers the true error.  The estimate itself is bounded by the
tolerance asked for, times the number of periods evaluated, unless K's own rounding near a
turning point is larger (it is measured, and reported: the 179.9° and π − 1e-6 pendulums
written as cos θ − cos θ0).
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from dyncli.energy_route import EnergyMotion
from dyncli.errors import InputError, NumericalError
from dyncli.ode import OverBudget

W2 = 9.81 / 0.75                # g/L of the pendulums
OM = math.sqrt(W2)


def _pendulum_ref(theta0, t):
    """θ, θ̇ of the pendulum released from rest at θ0: θ = 2 asin(k sn(K(k) − ωt, k)),
    θ̇ = −2kω cn(K(k) − ωt, k), k = sin(θ0/2), at 30 digits."""
    with mp.workdps(30):
        k = mp.sin(mp.mpf(theta0) / 2)
        u = mp.ellipk(k * k) - mp.sqrt(mp.mpf(9.81) / mp.mpf(0.75)) * mp.mpf(t)
        sn, cn = mp.ellipfun("sn", u, m=k * k), mp.ellipfun("cn", u, m=k * k)
        return float(2 * mp.asin(k * sn)), float(-2 * k * cn * mp.sqrt(mp.mpf(9.81) / mp.mpf(0.75)))


def _pendulum_period(theta0):
    with mp.workdps(30):
        k = mp.sin(mp.mpf(theta0) / 2)
        return float(4 * mp.ellipk(k * k) / mp.sqrt(mp.mpf(9.81) / mp.mpf(0.75)))


def _check(m, times, ref, s_scale, v_scale):
    """The largest relative error of s and ṡ at the times, each against its scale."""
    err = 0.0
    for t in times:
        s, v = m.state(t)
        s_ref, v_ref = ref(t)
        err = max(err, abs(s - s_ref) / s_scale, abs(v - v_ref) / v_scale)
    return err


@pytest.mark.parametrize("deg", [30.0, 90.0, 179.9])
@pytest.mark.parametrize("rtol", [1e-10, 1e-12])
@pytest.mark.parametrize("with_prime", [True, False])
def test_pendulum_from_rest(deg, rtol, with_prime):
    th0 = math.radians(deg)
    m = EnergyMotion(lambda s: 2 * W2 * (np.cos(s) - math.cos(th0)), th0, 0.0, rtol=rtol,
                     K_prime=(lambda s: -2 * W2 * np.sin(s)) if with_prime else None)
    P = _pendulum_period(th0)
    assert m.kind == "oscillation" and m.turning_points == pytest.approx([-th0, th0], rel=1e-12)
    err = _check(m, np.linspace(0.0, 3 * P, 31), lambda t: _pendulum_ref(th0, t), th0, 2 * OM * math.sin(th0 / 2))
    est = m.error_estimate
    assert abs(m.period - P) <= est * P
    assert err <= est
    # the estimate: the tolerance × the periods evaluated (3) × 2π, or K's measured rounding near θ0
    assert est <= (1e-6 if deg > 179 else 1e-8 if rtol < 1e-11 else 1e3 * rtol)


def test_pendulum_breaks_are_the_turning_times():
    th0 = math.radians(90.0)
    m = EnergyMotion(lambda s: 2 * W2 * (np.cos(s) - math.cos(th0)), th0, 0.0)
    P = _pendulum_period(th0)
    b = m.breaks(1.01 * P)
    assert b == pytest.approx([P / 4, P / 2, 3 * P / 4, P], rel=1e-12)   # the bottom, −θ0, the bottom, θ0
    assert m.state(P / 2)[0] == pytest.approx(-th0, rel=1e-14, abs=0)
    assert abs(m.state(P / 2)[1]) <= 1e-6


def test_pendulum_over_the_top():
    """K > 0 everywhere: no turning point, θ grows without bound (reference: mpmath odefun)."""
    w0 = 1.2 * 2 * OM              # above the separatrix speed 2ω at the bottom
    m = EnergyMotion(lambda s: w0 ** 2 - 2 * W2 * (1 - np.cos(s)), 0.0, w0, K_prime=lambda s: -2 * W2 * np.sin(s))
    assert m.kind == "runaway" and m.turning_points == [] and m.period is None
    times = [0.05, 0.4, 1.1, 1.6]
    with mp.workdps(30):
        f = mp.odefun(lambda t, y: [y[1], -mp.mpf(9.81) / mp.mpf(0.75) * mp.sin(y[0])], 0, [mp.mpf(0), mp.mpf(w0)])
        ref = {t: (float(f(t)[0]), float(f(t)[1])) for t in times}
    s_end = ref[times[-1]][0]
    assert s_end > 3 * math.pi                    # over the top, and round again
    err = _check(m, times, ref.get, s_end, w0)
    assert err <= m.error_estimate <= 1e-7


@pytest.mark.parametrize("v0,a", [(3.0, 2.0), (3.0, -2.0), (-3.0, 2.0), (0.0, 2.0), (0.0, -2.0)])
def test_uniform_acceleration(v0, a):
    s0 = 1.0
    m = EnergyMotion(lambda s: v0 * v0 + 2 * a * (s - s0), s0, v0)
    times = [0.0, 0.3, 1.0, 1.5, 2.9, 10.0, 100.0]
    scale_s = abs(s0) + abs(v0) * 100 + abs(a) * 100 ** 2 / 2
    err = _check(m, times, lambda t: (s0 + v0 * t + a * t * t / 2, v0 + a * t), scale_s, abs(v0) + abs(a) * 100)
    assert m.kind == "runaway"
    if v0 * a < 0:                                # one turning point, at s0 − v0²/2a, at t = −v0/a
        assert m.turning_points == pytest.approx([s0 - v0 * v0 / (2 * a)], rel=1e-14)
        assert m.breaks(50.0)[0] == pytest.approx(-v0 / a, rel=1e-12)
    assert err <= m.error_estimate <= 1e-9


@pytest.mark.parametrize("s0,v0", [(0.1, 0.5), (1 / 3, 0.0), (-0.2, -0.3), (0.0, 1.0)])
def test_harmonic_oscillator(s0, v0):
    w = 1.7
    A = math.sqrt(s0 * s0 + (v0 / w) ** 2)
    ph = math.atan2(-v0 / w, s0)
    m = EnergyMotion(lambda s: w * w * (A * A - s * s) if v0 else w * w * (s0 * s0 - s * s), s0, v0)
    assert m.kind == "oscillation" and m.turning_points == pytest.approx([-A, A], rel=1e-14)
    assert m.period == pytest.approx(2 * math.pi / w, rel=1e-12)
    ref = lambda t: (A * math.cos(w * t + ph), -A * w * math.sin(w * t + ph))  # noqa: E731
    err = _check(m, np.linspace(0, 30, 41), ref, A, A * w)
    assert err <= m.error_estimate <= 1e-7


def test_release_at_equilibria():
    m = EnergyMotion(lambda s: 2 * W2 * (1 + np.cos(s)), math.pi, 0.0)   # the inverted pendulum
    assert m.kind == "rest" and m.state(7.0) == (math.pi, 0.0) and m.breaks(10.0) == []
    m = EnergyMotion(lambda s: -s * s, 0.0, 0.0)                            # the bottom of a well
    assert m.kind == "rest" and m.state(3.0) == (0.0, 0.0)


@pytest.mark.parametrize("product", [True, False])
def test_near_the_separatrix(product):
    """θ0 = π − 1e-6: a long period, 4K(k)/ω with k → 1 (mpmath).  cos θ − cos θ0 cancels near θ0
    (K's rounding is 1e-7 of K there): the estimate says so; written as a product it does not."""
    th0 = math.pi - 1e-6
    K = ((lambda s: 4 * W2 * np.sin((th0 - s) / 2) * np.sin((th0 + s) / 2)) if product
         else (lambda s: 2 * W2 * (np.cos(s) - math.cos(th0))))
    m = EnergyMotion(K, th0, 0.0, K_prime=lambda s: -2 * W2 * np.sin(s))
    P = _pendulum_period(th0)
    assert P > 7 * 2 * math.pi / OM
    assert abs(m.period - P) / P <= m.error_estimate
    err = _check(m, np.linspace(0.0, 2 * P, 17), lambda t: _pendulum_ref(th0, t), th0, 2 * OM)
    assert err <= m.error_estimate <= (1e-5 if product else 1e-2)


def test_separatrix_is_approached_in_infinite_time():
    """E exactly at the separatrix: θ = 4 atan(e^(ωt)) − π, θ̇ = 2ω/cosh(ωt) → π, never reached."""
    m = EnergyMotion(lambda s: 4 * W2 * np.cos(s / 2) ** 2, 0.0, 2 * OM, K_prime=lambda s: -2 * W2 * np.sin(s))
    assert m.kind == "asymptotic" and m.asymptote == pytest.approx(math.pi, rel=1e-15) and m.period is None
    ref = lambda t: (4 * math.atan(math.exp(OM * t)) - math.pi, 2 * OM / math.cosh(OM * t))  # noqa: E731
    err = _check(m, [0.01, 0.3, 1.0, 3.0, 10.0, 30.0], ref, math.pi, 2 * OM)
    assert err <= m.error_estimate <= 1e-3
    s, v = m.state(1e6)                           # π to rounding, still on its way
    assert abs(s - math.pi) <= 2 * math.ulp(math.pi) and 0 <= v <= 1e-300


def test_wall_refuses_the_motion_past_it():
    m = EnergyMotion(lambda s: 1.0 - s, 0.0, 1.0, lo=-3.0)       # up to s = 1, back down to the wall at −3
    assert m.kind == "wall" and m.turning_points == pytest.approx([1.0])
    assert m.t_wall == pytest.approx(6.0, rel=1e-12)               # s = t − t²/4 reaches −3 at t = 6
    assert m.state(3.0)[0] == pytest.approx(3.0 - 9.0 / 4.0, rel=1e-12)
    with pytest.raises(NumericalError, match="end of its range"):
        m.state(6.5)


def test_escape_in_finite_time_is_refused():
    m = EnergyMotion(lambda s: 1 + s ** 4, 0.0, 1.0)
    assert m.state(1.0)[0] > 0
    with pytest.raises(NumericalError, match="runs to infinity"):
        m.state(3.0)


@pytest.mark.parametrize("K,s0,v0,kw,match", [
    (lambda s: 1 - s * s, 2.0, 0.0, {}, "cannot be negative"),
    (lambda s: math.nan, 0.0, 1.0, {}, "not finite"),
    (lambda s: 1.0, 0.0, 2.0, {}, "differs from sdot0"),
    (lambda s: 1.0, math.inf, 1.0, {}, "finite"),
    (lambda s: 1.0, 0.0, 1.0, {"rtol": 0.0}, "rtol"),
    (lambda s: 1.0, 0.0, 1.0, {"rtol": 1.5}, "rtol"),
    (lambda s: 1 - s * s, 0.0, 1.0, {"lo": 0.5}, "outside"),
])
def test_invalid_inputs(K, s0, v0, kw, match):
    with pytest.raises(InputError, match=match):
        EnergyMotion(K, s0, v0, **kw)


def test_state_needs_a_time_and_respects_the_budget():
    m = EnergyMotion(lambda s: 1 - s * s, 1.0, 0.0)
    with pytest.raises(InputError):
        m.state(-1.0)
    with pytest.raises(OverBudget):
        EnergyMotion(lambda s: 1 - s * s + 1e-3 * np.abs(np.sin(300 * s)), 0.0, math.sqrt(1 + 0.0), max_steps=2,
                     rtol=1e-12)


def test_rod_falling_to_the_floor_with_a_math_only_K():
    """A rod pivoted at its foot, released from rest at 0.1 rad from the vertical, falls to the
    floor (a wall at π/2): t_wall = ∫ dθ/√K against mpmath's tanh-sinh quadrature at 30 digits.
    K is written with math.cos (one float at a time)."""
    th0, w = 0.1, 3 * 9.81 / 2.0
    m = EnergyMotion(lambda th: w * (math.cos(th0) - math.cos(th)), th0, 0.0, hi=math.pi / 2)
    with mp.workdps(30):
        ref = float(mp.quad(lambda th: 1 / mp.sqrt(w * (mp.cos(th0) - mp.cos(th))), [th0, 1, mp.pi / 2]))
    assert m.kind == "wall" and m.turning_points == [th0]
    assert abs(m.t_wall - ref) / ref <= m.error_estimate
    assert m.breaks(10.0)[-1] == m.t_wall
    s, v = m.state(m.t_wall)
    assert s == pytest.approx(math.pi / 2, rel=1e-12) and v == pytest.approx(math.sqrt(w * math.cos(th0)), rel=1e-9)


def test_starting_against_a_wall():
    """Released (or thrown) into the end of the range: refused at once past t = 0."""
    m = EnergyMotion(lambda s: 1 - 2 * s, 0.0, -1.0, lo=0.0)
    assert m.kind == "wall" and m.t_wall == 0.0 and m.state(0.0) == (0.0, -1.0)
    with pytest.raises(NumericalError, match="end of its range"):
        m.state(0.1)


def test_a_minimum_of_K_inside_one_step_of_the_march_is_found_from_K_prime():
    """Issue #28: a Gaussian barrier (w = 3e-3) narrower than the march's step, K at the step's
    ends (and the three-value test) above 0: K' from − to + across the step decides that K has a
    minimum there, which is examined — the body turns at s_T = b − w √ln(2/v²) (closed form)."""
    w, b, v2 = 3e-3, 0.7770123, 1.999
    m = EnergyMotion(lambda s: v2 - 2 * np.exp(-((s - b) / w) ** 2), 0.0, math.sqrt(v2),
                     K_prime=lambda s: 4 * (s - b) / w ** 2 * np.exp(-((s - b) / w) ** 2))
    assert m.turning_points == pytest.approx([b - w * math.sqrt(math.log(2 / v2))], abs=1e-15)
    assert m.state(1.0)[1] < 0              # it came back


@pytest.mark.parametrize("theta0", [0.5, 2.0, 3.0])
def test_the_rate_crosses_zero_at_the_turning_point_linearly(theta0):
    """Near a turning point ṡ = θ̈ (t − t*) to first order: read from 2x/(dt/dx) (the time
    integrand's interpolant, no cancellation), not √K (whose rounding √δK would hold ṡ at 0
    within ~1e-9 s of t*, and then put a rate's root anywhere in it).  t* is the turning
    time (half the period from rest), against mpmath's complete elliptic integral."""
    m = EnergyMotion(lambda s: 2 * W2 * (np.cos(s) - math.cos(theta0)), theta0, 0.0, rtol=1e-12)
    T = _pendulum_period(theta0)
    (t_star,) = [t for t in m.turning_times(0.75 * T)]
    assert t_star == pytest.approx(T / 2, rel=1e-11)
    acc = W2 * math.sin(theta0)             # |θ̈| at the turning point
    for d in (1e-9, 1e-7, 1e-5):
        for sgn in (-1.0, 1.0):
            _s, sd = m.state(t_star + sgn * d)
            assert sd == pytest.approx(sgn * acc * d, rel=1e-4), (d, sgn, sd)


def test_turning_times_are_the_legs_that_end_at_a_root():
    """s = cos t from rest at s = 1: the turning points at t = kπ; from s = 0 moving, at π/2 + kπ."""
    m = EnergyMotion(lambda s: 1.0 - s * s, 1.0, 0.0, rtol=1e-12)
    assert m.turning_times(10.0) == pytest.approx([math.pi, 2 * math.pi, 3 * math.pi], rel=1e-12)
    m = EnergyMotion(lambda s: 1.0 - s * s, 0.0, 1.0, rtol=1e-12)
    assert m.turning_times(10.0) == pytest.approx([math.pi / 2 + k * math.pi for k in range(3)], rel=1e-12)
