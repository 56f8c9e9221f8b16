"""Oracle cases: the gyroscope of §37 and the steady precession of a top (§38).

* gyroscope, p q < 0, released at rest 1e-6 rad from the unstable θ = π/2: it circulates along
  the separatrix; reference by Taylor integration of (37.12) (mpmath.odefun, 30 digits);
* precession at p = 1e8 rad/s (the slow root 1e-6 of the fast one: the quadratic's cancellation),
  at p = p_min (1 + 1e-9) (two roots 4e-5 apart: next to the bifurcation where they vanish), and
  at θ = π/2 as a double (cos θ = 6e-17: the quadratic degenerates to a line)."""

from __future__ import annotations

import math

import mpmath as mp

from tests.oracle.common import case, closed, condition, estimated, same, x


def _gyroscope():
    I1, I2, p, q = x(0.01), x(0.006), x(-100), x(1)
    th0 = x(math.pi / 2 - 1e-6)
    times = [0.5, 1, 2]
    with mp.workdps(30):
        f = lambda t, y: [y[1], (I1 * p * q * mp.cos(y[0]) - (I2 - I1) * q ** 2 * mp.sin(y[0]) * mp.cos(y[0])) / I2]  # noqa: E731
        sol = mp.odefun(f, 0, [th0, mp.mpf(0)])
        ys = [sol(x(t)) for t in times]
    a, b = (I1 - I2) * q ** 2 / I2, 2 * I1 * p * q / I2
    wsc = mp.sqrt(2 * abs(a) + 2 * abs(b))
    checks = []
    for i, y in enumerate(ys):
        checks += [estimated(f"theta.{i}", y[0], mp.pi, reason="θ relative to π"),
                   estimated(f"theta_dot.{i}", y[1], wsc, reason="θ̇ relative to √(θ̇0² + 2|a| + 2|b|)")]
    return [case("released 1e-6 rad from the unstable pi/2", "gyroscope", {
        "I1": 0.01, "I2": 0.006, "p": -100, "q": 1, "theta0": float(th0), "theta_dot0": 0, "at": times},
        checks, "p q < 0: θ = π/2 is unstable (λ = 12.9 /s); from 1e-6 rad beside it the axis circulates, "
        "returning next to π/2 − 2π after 2 s")]


def _omegas(m, L, I11, I33, th, p, g=x(9.81)):
    a, b, c = (I33 - I11) * mp.cos(th), I33 * p, -m * g * L
    d = mp.sqrt(b ** 2 - 4 * a * c)
    r1, r2 = 2 * c / (-b - d), (-b - d) / (2 * a)        # the slow root without cancellation, the fast one
    return r1, r2, mp.sqrt(4 * a * c) / I33 if a * c > 0 else None


def _precession():
    m, L, I11, I33 = x(0.5), x(0.05), x(0.006), x(0.002)
    out = []
    th = x(math.pi / 6)
    slow, fast, _ = _omegas(m, L, I11, I33, th, x(1e8))
    out.append(case("p = 1e8 rad/s", "precession", {"m": 0.5, "L": 0.05, "I11": 0.006, "I33": 0.002,
                                                    "theta": math.pi / 6, "p": 1e8},
                    [closed("Omega_slow", slow, cond=4, reason="the small root formed without cancellation"),
                     closed("Omega_fast", fast, cond=4)],
                    "the roots of (38.22) 1.2e-6 and 5.8e10 rad/s: 16 orders apart", same_=[same("exists", True)]))
    _, _, pmin = _omegas(m, L, I11, I33, th, x(1))
    p = x(float(pmin * (1 + mp.mpf("1e-9"))))
    slow, fast, _ = _omegas(m, L, I11, I33, th, p)
    cs = condition(lambda pp: _omegas(m, L, I11, I33, th, pp)[0], [p])
    cf = condition(lambda pp: _omegas(m, L, I11, I33, th, pp)[1], [p])
    out.append(case("p = p_min (1 + 1e-9)", "precession", {"m": 0.5, "L": 0.05, "I11": 0.006, "I33": 0.002,
                                                           "theta": math.pi / 6, "p": float(p)},
                    [closed("Omega_slow", slow, cond=cs, reason="condition in p next to the double root"),
                     closed("Omega_fast", fast, cond=cf, reason="condition in p next to the double root"),
                     closed("p_min", pmin, cond=4)],
                    "4.5e-5 above the spin below which no steady precession exists: the two rates 9e-5 apart",
                    same_=[same("exists", True)]))
    th2 = x(math.pi / 2)
    slow2, _, _ = _omegas(m, L, I11, I33, th2, x(200))
    out.append(case("horizontal axis", "precession", {"m": 0.5, "L": 0.05, "I11": 0.006, "I33": 0.002,
                                                      "theta": math.pi / 2, "p": 200},
                    [closed("Omega_slow", slow2, cond=4, reason="m g L/(I33 p) to 1e-16")],
                    "θ = π/2 as a double (cos θ = 6.1e-17): the slow rate m g L/(I33 p) = 0.613 rad/s",
                    same_=[same("exists", True)]))
    return out


def cases():
    return _gyroscope() + _precession()
