"""``find`` decided exactly on the ODE routes (issue #28 item 1): a level crossed up and down
inside one ODE step is found, never stepped over.

Every case below was answered "not reached" (exit 0, only a "not reached" warning) by the search
that sampled the step ends (and, for the top, a grid of 32 points per turn of its fastest rate):
the quantity asked dips through the level and back inside one step whose ends lie on the same
side.  Now each step is cut at the exact extremes of the quantity along the step's dense
polynomial (``dyncli.rootfind.polynomial_extremes`` for a coordinate,
``dyncli.rootfind.smooth_extremes`` for any other result), so it is monotone between two cuts.

References, never dyncli's output:

* ``particle`` and ``constrained-particle`` (a straight wire): the force 2(t − 1) on m = 1 from
  v(0) = 1 − ε gives v = −ε + (t − 1)², T = ½v²; T = ½(ε/2)² where (t − 1)² = ε ± ε/2, and the
  coordinate q = −εt + ((t − 1)³ + 1)/3 (closed forms, in mpmath).
* ``particles``: two unit masses joined by a spring k = ½, L = 0: the relative motion is
  harmonic (ω = √(2k) = 1), so x₀(t) = Vt + (w/ω) sin ωt exactly; with w = V(1 + δ) particle 0
  steps back for a moment around t = π (mpmath).
* ``top``: a top released with ψ̇₀ = −δ loops: ψ̇ < 0 for ~4e-4 s at each lowest point of the
  nutation, and ψ steps back by 2e-8 rad there; the reference is a second integration of the
  reduced equations (38.18) with p_ψ and ω₃ held, written here (scipy's DOP853 at rtol 1e-13).

Tolerances: a crossing's time is off by the error of the quantity (``tests.tolerances.ode``
times its scale) over its rate there.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from .refs import entry, solve
from tests.tolerances import ode

MPMATH_DPS = 30


# --- the numerics: exact extremes of a smooth function between breaks --------------------------

def test_smooth_extremes_finds_every_critical_point_and_a_kink():
    from dyncli.rootfind import smooth_extremes

    B = np.linspace(0.0, 10.0, 41)
    cuts, ok = smooth_extremes(lambda t: np.stack([np.sin(3 * t), np.exp(-t), 1 + 0 * t]), B)
    assert ok
    want = [(2 * k + 1) * math.pi / 6 for k in range(10)]          # the extremes of sin 3t in (0, 10)
    assert len(cuts[0]) == len(want) and max(abs(a - b) for a, b in zip(cuts[0], want)) < 1e-12
    assert cuts[1] == [] and cuts[2] == []                          # monotone, constant: no cut
    cuts, ok = smooth_extremes(lambda t: np.abs(np.sin(t)), B)      # kinks at π, 2π, 3π: cut at each
    assert ok
    for k in (1, 2, 3):
        assert min(abs(c - k * math.pi) for c in cuts[0]) < 1e-12
    cuts, ok = smooth_extremes(lambda t: 1 / (t - 2.5), B[:11])     # a pole: not resolved
    assert not ok


# --- particle and constrained-particle: T dips to 0 and back inside one step -----------------

EPS = 1e-2


def _t_crossings():
    """The four times T = ½(ε/2)² (closed form)."""
    with mp.workdps(MPMATH_DPS):
        return _t_crossings_mp()


def _t_crossings_mp():
    e = mp.mpf(EPS)
    return [float(1 + s * mp.sqrt(e * f)) for s, f in ((-1, 1.5), (-1, 0.5), (1, 0.5), (1, 1.5))]


def _q(t):
    e = mp.mpf(EPS)
    return -e * t + ((t - 1) ** 3 + 1) / 3


def _q_crossings():
    """The level halfway through q's backward step (its local max at 1 − √ε, min at 1 + √ε) and
    the three times q reaches it (mpmath)."""
    with mp.workdps(MPMATH_DPS):
        return _q_crossings_mp()


def _q_crossings_mp():
    e = mp.mpf(EPS)
    r1, r2 = 1 - mp.sqrt(e), 1 + mp.sqrt(e)
    Q = (_q(r1) + _q(r2)) / 2
    f = lambda t: _q(t) - Q                                         # noqa: E731
    return float(Q), [float(mp.findroot(f, ab, solver="bisect")) for ab in ((0.5, r1), (r1, r2), (r2, 1.5))]


def _v(t: float) -> float:
    return -EPS + (t - 1) ** 2


@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_particle_kinetic_energy_dips_inside_one_step(rtol):
    X = 0.5 * (EPS / 2) ** 2
    R, _ = solve(f"""
type: particle
m: 1
x0: [0, 0, 0]
v0: [{1 - EPS!r}, 0, 0]
forces:
  - {{kind: custom, F: ["2*(t-1)", "0", "0"]}}
t_end: 2
find:
  - {{when: {{T: {X!r}}}}}
  - {{when: {{T: {X!r}}}, occurrence: 2}}
  - {{when: {{T: {X!r}}}, occurrence: 3}}
  - {{when: {{T: {X!r}}}, occurrence: 4}}
  - {{max: T, within: [0.95, 1.05]}}
accuracy: {{rtol: {rtol!r}}}
""")
    for k, t in enumerate(_t_crossings()):
        # T's error is |v| times v's (ode(rtol) of v's scale 1), its rate |v a|: Δt ≤ ode(rtol)/|a|
        assert abs(entry(R, k)["t"] - t) <= ode(rtol) / abs(2 * (t - 1)), k
    top = entry(R, 4)                                               # the local maximum ½ε² at t = 1
    assert top["t"] == pytest.approx(1.0, abs=math.sqrt(ode(rtol)))
    assert top["T"] == pytest.approx(0.5 * EPS ** 2, rel=ode(rtol) / EPS)


#: a bead on a straight wire pushed by F = 2(t − 1): q̇ = −ε + (t − 1)², q = _q(t)
BEAD = f"""
type: constrained-particle
m: 1
curve: {{x1: q, x2: 0, x3: 0}}
q_dot0: {1 - EPS!r}
forces:
  - {{kind: custom, F: ["2*(t-1)", "0", "0"]}}
"""


@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_constrained_particle_dips_inside_one_step(rtol):
    X = 0.5 * (EPS / 2) ** 2
    Q, qs = _q_crossings()
    R, _ = solve(BEAD + f"""t_end: 2
find:
  - {{when: {{T: {X!r}}}, occurrence: 3}}
  - {{when: {{T: {X!r}}}, occurrence: 4}}
  - {{when: {{q: {Q!r}}}, occurrence: 2}}
  - {{when: {{q: {Q!r}}}, occurrence: 3}}
  - {{when: {{x.0: {Q!r}}}, occurrence: 3}}
accuracy: {{rtol: {rtol!r}, method: ode}}
""")
    t3, t4 = _t_crossings()[2:]
    assert abs(entry(R, 0)["t"] - t3) <= ode(rtol) / abs(2 * (t3 - 1))
    assert abs(entry(R, 1)["t"] - t4) <= ode(rtol) / abs(2 * (t4 - 1))
    for k, t in ((2, qs[1]), (3, qs[2]), (4, qs[2])):
        # q's error (ode(rtol) of its scale ~1) over its rate there
        assert abs(entry(R, k)["t"] - t) <= ode(rtol) / abs(_v(t)), k


# --- particles: a particle steps back for a moment inside one step ---------------------------

@pytest.mark.parametrize("rtol", [1e-6, 1e-8])
def test_particles_backward_step_inside_one_step(rtol):
    V, delta = 1.0, 1e-3
    w = V * (1 + delta)
    x = lambda t: V * t + w * mp.sin(t)                              # noqa: E731
    v = lambda t: V + w * mp.cos(t)                                  # noqa: E731
    with mp.workdps(MPMATH_DPS):
        r1, r2 = (mp.findroot(v, ab, solver="bisect") for ab in ((mp.pi - 0.3, mp.pi), (mp.pi, mp.pi + 0.3)))
        X = (x(r1) + x(r2)) / 2
        want = [mp.findroot(lambda t: x(t) - X, ab, solver="bisect") for ab in ((2, r1), (r1, r2), (r2, 4.5))]
        speeds = [float(abs(v(t))) for t in want]
    R, _ = solve(f"""
type: particles
particles:
  - {{m: 1, x: [0, 0, 0], v: [{V + w!r}, 0, 0]}}
  - {{m: 1, x: [0, 1, 0], v: [{V - w!r}, 0, 0]}}
pairs:
  - {{between: [0, 1], kind: spring, k: 0.5, L: 0}}
t_end: 5
find:
  - {{when: {{x_motion.0.0: {float(X)!r}}}}}
  - {{when: {{x_motion.0.0: {float(X)!r}}}, occurrence: 2}}
  - {{when: {{x_motion.0.0: {float(X)!r}}}, occurrence: 3}}
accuracy: {{rtol: {rtol!r}}}
""")
    for k, (t, speed) in enumerate(zip(want, speeds)):
        # x's error (ode(rtol) of its scale, 5 m over the run) over the speed there
        assert abs(entry(R, k)["t"] - float(t)) <= ode(rtol) * 5 / speed, k


# --- top: a looping top's ψ steps back by 2e-8 rad inside one step ---------------------------

def _top_reference(delta: float, t_end: float):
    """ψ(t) and ψ̇(t) of the top below from (38.18) with p_ψ, ω₃ held (scipy, rtol 1e-13)."""
    from scipy.integrate import solve_ivp

    m, L, A, C, g, th0, phd0 = 0.5, 0.05, 2e-3, 1e-3, 9.81, 0.5, 100.0
    w3 = -delta * math.cos(th0) + phd0
    c = C * w3 / A
    b = -delta * math.sin(th0) ** 2 + c * math.cos(th0)
    kg = m * g * L / A

    def rhs(t, y):
        s, co = math.sin(y[0]), math.cos(y[0])
        psd = (b - c * co) / (s * s)
        return [y[1], s * (psd * (psd * co - c) + kg), psd]

    sol = solve_ivp(rhs, (0.0, t_end), [th0, 0.0, 0.0], method="DOP853", rtol=1e-13, atol=1e-16, dense_output=True)
    psi = lambda t: float(sol.sol(t)[2])                                            # noqa: E731
    psd = lambda t: (b - c * math.cos(sol.sol(t)[0])) / math.sin(sol.sol(t)[0]) ** 2  # noqa: E731
    return psi, psd


@pytest.mark.parametrize("route, rtol", [("ode", 1e-10), ("exact", 1e-13), ("projected", 1e-10)])
def test_top_psi_steps_back_inside_one_step(route, rtol):
    """ψ steps back near the second lowest point, inside one step of the ODE route (reduced form,
    its dense output cut at ψ's exact extremes), inside one step of the quaternion form (method
    projected: the tracker carries ψ from each step's start on the step's interpolant; solved again
    on a grid of 8 pieces per turn, 4 points each, occurrences 2 and 3 were "not reached") and
    inside one piece of the exact route's search (elliptic functions, solved again on pieces: four
    points each, occurrences 2 and 3 were "not reached").  Tolerance: ψ's error over ψ̇ there — the
    route's at its rtol (ODE), the reference's at 1e-13 (exact)."""
    from scipy.optimize import brentq

    delta = 1e-4
    psi, psd = _top_reference(delta, 0.2)
    ts = np.linspace(0.1, 0.16, 60001)                               # ψ̇'s roots near the second lowest point
    P = [psd(t) for t in ts]
    r1, r2 = (brentq(psd, ts[k], ts[k + 1], xtol=1e-16) for k in range(len(ts) - 1) if P[k] * P[k + 1] < 0)
    X = 0.5 * (psi(r1) + psi(r2))
    want = [brentq(lambda t: psi(t) - X, a, b, xtol=1e-16) for a, b in ((0.1, r1), (r1, r2), (r2, 0.16))]
    method = {"ode": f"accuracy: {{rtol: {rtol!r}, method: DOP853}}",
              "projected": f"accuracy: {{rtol: {rtol!r}, method: projected}}"}.get(route, "")
    R, _ = solve(f"""
type: top
m: 0.5
L: 0.05
I11: 2.0e-3
I33: 1.0e-3
theta: 0.5
psi_dot: {-delta!r}
phi_dot: 100
at: [0.2]
find:
  - {{when: {{psi: {X!r}}}}}
  - {{when: {{psi: {X!r}}}, occurrence: 2}}
  - {{when: {{psi: {X!r}}}, occurrence: 3}}
{method}
""")
    for k, t in enumerate(want):
        assert entry(R, k)["reached"], k
        # ψ's error (ode(rtol) of its scale, 0.5 rad) over ψ̇ there
        assert abs(entry(R, k)["t"] - t) <= ode(rtol) * 0.5 / abs(psd(t)), k


@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_constrained_particle_distance_counts_a_step_back_inside_one_step(rtol):
    """The bead above steps back between its turning points 1 ∓ √ε, inside one ODE step (its
    motion is a cubic: the steps are long).  The distance Σ|Δs| between the turning points of s
    read the signs of q̇ at the step ends only and gave the net displacement (exit 0); the roots
    of q̇ are now bracketed at the critical points of its polynomial.  Reference: the closed form
    q(t) = −ε t + ((t − 1)³ + 1)/3 (mpmath)."""
    R, _ = solve(BEAD + f"""at: [0, 2]
accuracy: {{rtol: {rtol!r}, method: ode}}
""")
    with mp.workdps(MPMATH_DPS):
        r1, r2 = 1 - mp.sqrt(mp.mpf(EPS)), 1 + mp.sqrt(mp.mpf(EPS))
        want = float((_q(r1) - _q(0)) + (_q(r1) - _q(r2)) + (_q(2) - _q(r2)))
    # three legs, each q's error (ode(rtol) of its scale ~1) at its ends
    assert abs(R["distance"][1] - want) <= 6 * ode(rtol)


# --- euler (ODE route, an applied moment): ω₁ steps back inside one piece of the old grid -------

def _euler_omega(eps, t):
    """ω₁ of a body spun about e'₁ (ω₂ = ω₃ = 0 stay 0) by M₁ = I₁(3(t − 1)² − ε): the closed form
    1 + (t − 1)³ + 1 − εt."""
    return 1 + (t - 1) ** 3 + 1 - eps * t


@pytest.mark.parametrize("rtol", [1e-10, 1e-12])
def test_euler_omega_steps_back_between_samples(rtol):
    """ω₁ rises, falls by ~1e-8 over 4e-3 s around t = 1 and rises again (the moment dips below 0
    for a moment).  The sampled search (4 points per piece of a 64-piece grid over [0, 2]) saw one
    crossing of the level halfway through the fall: occurrences 2 and 3 'not reached' and
    T_t's 'not reached' (exit 0), the local maximum of ω₁ 3e-8 s off (Brent's minimiser on the
    flat top).  Now one run's dense output, every step cut at ω₁'s exact extremes, an extreme
    polished as a root of ω̇ from Euler's equations.  Reference: the closed form (mpmath).
    Tolerance: ω's error (ode(rtol) of its scale, 2) over |ω̇₁| at the crossing; the extreme's
    time: ω̇₁'s error over ω̈₁ = 6(t − 1) there."""
    eps = 1e-5
    with mp.workdps(MPMATH_DPS):
        r1, r2 = 1 - mp.sqrt(mp.mpf(eps) / 3), 1 + mp.sqrt(mp.mpf(eps) / 3)
        W = (_euler_omega(eps, r1) + _euler_omega(eps, r2)) / 2
        want = [mp.findroot(lambda t: _euler_omega(eps, t) - W, ab, solver="bisect")
                for ab in ((mp.mpf("0.5"), r1), (r1, r2), (r2, mp.mpf("1.5")))]
        rates = [float(abs(3 * (t - 1) ** 2 - eps)) for t in want]
        top = float(_euler_omega(eps, r1))
    W = float(W)
    R, _ = solve(f"""
type: euler
I: [1, 2, 3]
omega0: [1, 0, 0]
M: ["3*(t-1)**2 - {eps!r}", "0", "0"]
t_end: 2
find:
  - {{when: {{omega.0: {W!r}}}}}
  - {{when: {{omega.0: {W!r}}}, occurrence: 2}}
  - {{when: {{omega.0: {W!r}}}, occurrence: 3}}
  - {{max: omega.0, within: [0.5, 1.0]}}
  - {{when: {{T_t: {0.5 * W * W!r}}}, occurrence: 2}}
accuracy: {{rtol: {rtol!r}}}
""")
    for k, (t, rate) in enumerate(zip(want, rates)):
        assert abs(entry(R, k)["t"] - float(t)) <= ode(rtol) * 2 / rate, k
    # T_t = ½ω₁² (I₁ = 1) crosses ½W² where ω₁ crosses W
    assert abs(entry(R, 4)["t"] - float(want[1])) <= ode(rtol) * 2 / rates[1]
    e = entry(R, 3)
    assert e["at_end"] is False
    assert abs(e["t"] - float(r1)) <= ode(rtol) * 2 / (6 * abs(float(r1) - 1))
    assert e["omega"][0] == pytest.approx(top, abs=ode(rtol) * 2)


# --- gyroscope (ODE route): θ̇ dips for a moment each time θ passes π/2 ---------------------------

def _gyro(delta):
    """The gyroscope below (I1 = 1, I2 = 2, q = 1, p = 1 − δ, θ₀ = 0, θ̇₀ = √2): θ circulates with
    θ̇² = C − V(θ), V = ½ sin²θ − p sin θ, C = 2 (37.13); V has a minimum at sin θ* = p, a maximum
    δ²/2 higher at θ = π/2: θ̇ dips by ~1e-7 over 0.09 rad there.  (θ̇ at the level X halfway
    into the dip, the four θ where θ̇ = X in one turn, the time of a whole turn; mpmath.)"""
    p, C = 1 - mp.mpf(delta), mp.mpf(2)
    thd = lambda th: mp.sqrt(C - (mp.sin(th) ** 2 / 2 - p * mp.sin(th)))     # noqa: E731
    X = (thd(mp.asin(p)) + thd(mp.pi / 2)) / 2
    disc = mp.sqrt(p * p + 2 * (C - X * X))                                    # V(θ) = C − X²: sin θ = p ∓ disc
    thetas = [mp.asin(p - disc), mp.asin(p + disc), mp.pi - mp.asin(p + disc), mp.pi - mp.asin(p - disc)]
    time = lambda th: mp.quad(lambda x: 1 / thd(x), [0, th])                  # noqa: E731
    turn = mp.quad(lambda x: 1 / thd(x), [0, mp.pi / 2, mp.pi, 3 * mp.pi / 2, 2 * mp.pi])
    return p, X, thd, thetas, time, turn


@pytest.mark.parametrize("rtol", [1e-10, 1e-12])
def test_gyroscope_theta_dot_dips_between_samples(rtol):
    """The sampled search (4 points per piece, 8 pieces per turn of θ̇) found the dip's two
    crossings in the first turn only: the 2nd and 3rd turns' crossings were given the wrong
    occurrence (5 s off) or 'not reached' (exit 0); the dip's minimum was the window's end.  Now
    one run's dense output, every step cut at θ̇'s exact extremes, an extreme polished as a root of
    θ̈ (37.12).  Reference: t(θ) = ∫dθ/θ̇ from the first integral (mpmath quadrature, 30 digits).
    Tolerance: a crossing's time is off by θ̇'s error over θ̈ there plus θ's error over θ̇ (each
    ode(rtol) of its scale: 1.6 rad/s, 20 rad over 16 s)."""
    delta = 1e-3
    with mp.workdps(MPMATH_DPS):
        p, X, thd, thetas, time, turn = _gyro(delta)
        first = [time(th) for th in thetas]
        want = [(t + k * turn, th) for k in range(3) for t, th in zip(first, thetas)]
        slope = [float(abs((p - mp.sin(th)) * mp.cos(th) / 2)) for _, th in want]    # |θ̈| (37.12)
        speed = [float(thd(th)) for _, th in want]
        bottom, t_bottom = float(thd(mp.pi / 2)), float(time(mp.pi / 2) + turn)
        X = float(X)
    assert float(want[-1][0]) < 16
    queries = "\n".join(f"  - {{when: {{theta_dot: {X!r}}}, occurrence: {k + 1}}}" for k in range(len(want)))
    R, _ = solve(f"""
type: gyroscope
I1: 1
I2: 2
p: {float(p)!r}
q: 1
theta_dot0: {math.sqrt(2)!r}
t_end: 16
find:
{queries}
  - {{min: theta_dot, within: [{float(want[4][0])!r}, {float(want[7][0])!r}]}}
accuracy: {{rtol: {rtol!r}, method: DOP853}}
""")
    for k, ((t, _), a, v) in enumerate(zip(want, slope, speed)):
        assert abs(entry(R, k)["t"] - float(t)) <= ode(rtol) * (1.6 / a + 20 / v), k
    e = entry(R, len(want))
    assert e["at_end"] is False
    assert e["theta_dot"] == pytest.approx(bottom, abs=ode(rtol) * 1.6)
    # the bottom's time: θ̇'s error over its curvature there, θ̈' = θ̇·d/dθ((p − sinθ)cosθ/2) = θ̇(1 − p)/2
    assert abs(e["t"] - t_bottom) <= math.sqrt(2 * ode(rtol) * 1.6 / (bottom * delta / 2)) + ode(rtol) * 20 / bottom


# --- constrained-particle, energy quadrature: the bead's height steps back between samples ----

def test_constrained_particle_quadrature_height_steps_back_between_samples():
    """A bead on the wire x₃ = q³/3 − εq (x₁ = q) pulled back by F₁ = −x₁, released from rest at
    q = 1: its height wiggles by (4/3)ε^1.5 = 1.3e-6 m over |q| < √ε = 0.01 each time it passes
    q = 0.  The energy route's search (an eighth of the period, cut in four) found the three
    crossings of x₃ = 0 on the first pass and one on the way back: occurrences 5 and 6 'not
    reached' (exit 0).  Now each leg is cut at the exact extremes of the result in the leg's
    quadrature variable (smooth_extremes), taken to time by the leg's own quadrature.  Reference:
    q = cos θ, t(θ) = ∫₀^θ √(1 + (cos²θ' − ε)²) dθ' (the energy integral with K = ½ sin²θ, M = 1 +
    x₃'²; mpmath, 30 digits); x₃ = 0 at q = 0, ±√(3ε).  Tolerance: the route's time error, its
    quadratures' 1e-13 over the period (~7 s) times the few legs run, at most 1e-11 s."""
    eps = 1e-4
    with mp.workdps(MPMATH_DPS):
        e = mp.mpf(eps)
        time = lambda th: mp.quad(lambda a: mp.sqrt(1 + (mp.cos(a) ** 2 - e) ** 2), [0, th])   # noqa: E731
        qs = [mp.sqrt(3 * e), mp.mpf(0), -mp.sqrt(3 * e)]
        want = [time(mp.acos(q)) for q in qs] + [time(2 * mp.pi - mp.acos(q)) for q in reversed(qs)]
        top = time(mp.acos(-mp.sqrt(e)))                        # the wiggle's top, q = −√ε on the way out
        window = (float(time(mp.acos(mp.sqrt(e)))), float(time(mp.acos(-2 * mp.sqrt(e)))))
        height = float(2 * e ** mp.mpf(1.5) / 3)
        period = float(4 * time(mp.pi / 2))
    R, warns = solve(f"""
type: constrained-particle
m: 1
curve: {{x1: q, x2: 0, x3: "q**3/3 - {eps!r}*q"}}
q_range: [-2, 2]
q0: 1
forces: [{{kind: custom, F: ["-x1", "0", "0"]}}]
t_end: 8
find:
""" + "".join(f"  - {{when: {{x.2: 0}}, occurrence: {k + 1}}}\n" for k in range(6)) + f"""\
  - {{max: x.2, within: [{window[0]!r}, {window[1]!r}]}}
accuracy: {{rtol: 1e-10}}
""")
    assert R["period"] == pytest.approx(period, rel=1e-12)
    for k, t in enumerate(want):
        assert abs(entry(R, k)["t"] - float(t)) <= 1e-11, k
    e = entry(R, 6)
    assert e["at_end"] is False and abs(e["t"] - float(top)) <= 1e-9       # (an extreme: its time to √(1e-13))
    assert e["x"][2] == pytest.approx(height, rel=1e-9)
    assert not [w for w in warns if "sampl" in w]


def test_top_next_to_the_vertical_says_its_search_is_sampled():
    """Within sinθ = 1e-3 of the vertical the ODE route's search still reads samples (ψ swings by ~π
    in ~θ_min/ω there, faster than a step's interpolant resolves): said in a warning.  The top
    passes 8.5e-6 rad from the vertical at t = 0.0862 s (the gallery's top-near-vertical); its
    lowest θ is found there (the root of θ̇ on the samples' bracket), 8.5 µrad to the two digits
    the gallery documents."""
    R, warns = solve("""
type: top
m: 0.5
L: 0.05
I11: 2.0e-3
I33: 1.0e-3
theta: 0.3
theta_dot: -2
psi_dot: 16.918
phi_dot: 50
at: [0.2]
find: [{min: theta}]
accuracy: {method: DOP853, rtol: 1e-10}
""")
    assert any("searched on samples" in w for w in warns)
    e = entry(R, 0)
    assert e["theta"] == pytest.approx(8.5e-6, rel=0.01)
