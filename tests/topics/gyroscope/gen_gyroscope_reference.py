"""Generate tests/topics/gyroscope/gyroscope_reference_data.py: θ(t), θ̇(t) of the gyroscope (§37)
at high precision (mpmath), by two routes independent of dyncli's elliptic solution:

* ``ode``: mpmath.odefun (Taylor series, 30 digits) on (37.12),
  θ̈ = ((I1 − I2) q² sinθ + I1 p q) cosθ / I2 — short times;
* ``quad``: the first integral (37.15b) θ̇² = G(θ) by mpmath.quad (40 digits): the turning
  points θ_lo, θ_hi are the zeros of G next to θ0, the period T = 2∫dθ/√G between them (or
  ∫ over 2π for a circulating θ), t reduced modulo T in 40-digit arithmetic and θ found by
  bisection-type root finding on t(θ) = ∫dθ/√G — long times (1e3, 1e6 s).

The inputs are the doubles themselves (exact as mpf).  Run:
    python tests/topics/gyroscope/gen_gyroscope_reference.py
"""

from __future__ import annotations

import pprint
from pathlib import Path

import mpmath as mp

# name: (route, I1, I2, p, q, theta0, theta_dot0, times)
CASES = {
    "zero_to_pi": ("ode", 0.01, 0.006, 100.0, 1.0, 0.0, 0.0, [0.05, 0.1, 0.2, 0.33]),
    "pq_negative": ("ode", 0.01, 0.006, -100.0, 1.0, 0.3, 2.0, [0.05, 0.13, 0.4]),
    "circulating": ("ode", 0.01, 0.006, 1.0, 1.0, 0.3, 50.0, [0.1, 0.5, 1.0]),
    "circulating_back": ("ode", 0.006, 0.006, 1.0, 3.0, 4.0, -7.1, [0.3, 1.7]),
    "band": ("ode", 0.005, 0.006, 0.1, 3.0, 0.17, 0.3, [0.2, 1.0, 2.5]),
    "equal_moments": ("ode", 0.006, 0.006, 1.0, 3.0, 1.0, 0.1, [0.4, 1.3]),
    "prolate_rest": ("ode", 0.011, 0.006, -1.0, 3.0, -1.0, 0.0, [0.5, 2.0]),
    "separatrix_near": ("ode", 0.01, 0.006, 1.0, 1.0, -1.5707953267948966, 0.0, [1.0, 2.0, 3.0]),
    "p_1e6": ("ode", 0.01, 0.006, 1.0e6, 1.0, 0.1, 0.0, [1e-4, 1e-3, 0.01]),
    "long": ("quad", 0.01, 0.006, -100.0, 1.0, 0.3, 2.0, [1.0e3, 1.0e6]),
    "long_circulating": ("quad", 0.01, 0.006, 1.0, 1.0, 0.3, 50.0, [1.0e3, 1.0e6]),
    "long_p_1e6": ("quad", 0.01, 0.006, 1.0e6, 1.0, 0.1, 0.0, [10.0, 1.0e3]),
}


def coefficients(I1, I2, p, q):
    I1, I2, p, q = (mp.mpf(x) for x in (I1, I2, p, q))
    return (I1 - I2) * q * q / I2, 2 * I1 * p * q / I2


def by_ode(I1, I2, p, q, th0, thd0, times):
    mp.mp.dps = 30
    a, b = coefficients(I1, I2, p, q)
    f = mp.odefun(lambda t, y: [y[1], (a * mp.sin(y[0]) + b / 2) * mp.cos(y[0])], 0, [mp.mpf(th0), mp.mpf(thd0)])
    return [[float(v) for v in f(mp.mpf(t))] for t in times]


def _first_zero(G, th0, direction):
    """The first zero of G from θ0 along direction (within 2π), or None."""
    n = 4000
    h = direction * 2 * mp.pi / n
    prev = th0
    for k in range(1, n + 1):
        x = th0 + k * h
        if G(x) < 0:
            return mp.findroot(G, (prev, x), solver="anderson")
        prev = x
    return None


def by_quad(I1, I2, p, q, th0, thd0, times):
    mp.mp.dps = 40
    a, b = coefficients(I1, I2, p, q)
    th0, thd0 = mp.mpf(th0), mp.mpf(thd0)
    s0 = mp.sin(th0)

    def G(th):
        s = mp.sin(th)
        return thd0 ** 2 + a * (s - s0) * (s + s0) + b * (s - s0)

    def tau(x, y):
        return mp.quad(lambda th: 1 / mp.sqrt(abs(G(th))), [x, (x + y) / 2, y])

    if thd0 == 0:       # released at a turning point: the other one along θ̈(θ0)
        up = (a * s0 + b / 2) * mp.cos(th0) > 0
        other = _first_zero(G, th0 + (1 if up else -1) * mp.mpf(10) ** -25, 1 if up else -1)
        lo, hi = (th0, other) if up else (other, th0)
    else:
        hi, lo = _first_zero(G, th0, 1), _first_zero(G, th0, -1)
    rows = []
    if hi is None or lo is None:          # circulation, one revolution per period
        sg = 1 if thd0 > 0 else -1
        T = tau(th0, th0 + 2 * mp.pi)
        for t in times:
            n = mp.floor(mp.mpf(t) / T)
            r = mp.mpf(t) - n * T
            th = mp.findroot(lambda x: tau(th0, x) - r, (th0, th0 + 2 * mp.pi), solver="illinois") if sg > 0 else \
                mp.findroot(lambda x: tau(x, th0) - r, (th0 - 2 * mp.pi, th0), solver="illinois")
            rows.append([float(th + sg * 2 * mp.pi * n), float(sg * mp.sqrt(G(th)))])
        return rows
    half = tau(lo, hi)
    T = 2 * half
    ph0 = tau(lo, th0) if thd0 > 0 or (thd0 == 0 and th0 == lo) else T - tau(lo, th0)
    for t in times:
        s = mp.fmod(ph0 + mp.mpf(t), T)
        target, sg = (s, 1) if s <= half else (T - s, -1)
        th = mp.findroot(lambda x: tau(lo, x) - target, (lo, hi), solver="illinois")
        rows.append([float(th), float(sg * mp.sqrt(max(G(th), 0)))])
    return rows


def main():
    out = {}
    for name, (route, *args, times) in CASES.items():
        rows = (by_ode if route == "ode" else by_quad)(*args, times)
        out[name] = {"input": list(args), "times": times, "route": route, "rows": rows}
        print(name, rows)
    text = ('"""Gyroscope reference values (mpmath), written by gen_gyroscope_reference.py: per case the\n'
            'inputs (I1, I2, p, q, θ0, θ̇0), times, route and rows [θ, θ̇] (rounded to doubles)."""\n\n'
            "CASES = " + pprint.pformat(out, width=110) + "\n")
    (Path(__file__).parent / "gyroscope_reference_data.py").write_text(text)


if __name__ == "__main__":
    main()
