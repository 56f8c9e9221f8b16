"""The pendulum's closed forms, as small pure functions of plain numbers (notes §7, §16, §20).

θ is measured from the downward vertical; θ̈ = −(g/l) sin θ.  With ω₀ = √(g/l) the energy
integral is θ̇²/4 + ω₀² sin²(θ/2) = ω₀² k², k² = sin²(θ₀/2) + (θ̇₀/2ω₀)² = E/(2mgl):
k < 1 a swing of amplitude 2 arcsin k, k > 1 a rotation over the top, k = 1 the separatrix.
"""

from __future__ import annotations

import math

EPS = 2.0 ** -52


def natural_frequency(l: float, g: float) -> float:
    """ω₀ = √(g/l), the small-angle angular frequency.

    >>> natural_frequency(1.0, 4.0)
    2.0
    """
    return math.sqrt(g / l)


def small_angle_period(l: float, g: float) -> float:
    """T₀ = 2π√(l/g).

    >>> round(small_angle_period(1.0, 9.81), 12)
    2.006066680711
    """
    return 2.0 * math.pi * math.sqrt(l / g)


def modulus(theta0: float, theta_dot0: float, omega0: float) -> tuple[float, float, float]:
    """(k², 1 − k², the rounding uncertainty of 1 − k²).

    1 − k² = cos²(θ₀/2) − q² (q = θ̇₀/2ω₀) is formed as (|c| − |q|)(|c| + |q|), free of
    cancellation beyond the inputs' own; its uncertainty is what a half-ulp change of θ₀, θ̇₀,
    l and g moves it by (a few ε of |θ₀ sin θ₀/2 cos θ₀/2| and of q²).

    >>> modulus(0.0, 2.0, 1.0)[:2]          # θ̇₀ = 2ω₀ from the bottom: the separatrix, exactly
    (1.0, 0.0)
    """
    s, c, q = math.sin(0.5 * theta0), abs(math.cos(0.5 * theta0)), abs(theta_dot0 / (2.0 * omega0))
    k2 = s * s + q * q
    m1 = (c - q) * (c + q)
    tol = 4.0 * EPS * (abs(theta0) * abs(s) * c + 2.0 * q * q)
    return k2, m1, tol


def amplitude(k: float, m1: float) -> float:
    """θ_max = 2 arcsin k of a swing, as 2 atan2(k, √(1 − k²)) (accurate next to the top).

    >>> round(amplitude(math.sqrt(0.5), 0.5), 15) == round(math.pi / 2, 15)
    True
    """
    return 2.0 * math.atan2(k, math.sqrt(m1))


def tension(m: float, l: float, g: float, theta: float, theta_dot: float) -> float:
    """The rod's pull on the bob, m(l θ̇² + g cos θ) (normal component of §16 in polar form, §7).

    >>> tension(2.0, 1.0, 9.81, 0.0, 0.0)       # hanging at rest: the weight
    19.62
    """
    return m * (l * theta_dot * theta_dot + g * math.cos(theta))


def tension_rate(m: float, g: float, theta: float, theta_dot: float) -> float:
    """dT/dt = −3 m g θ̇ sin θ (the energy integral used in l θ̇²).

    >>> tension_rate(1.0, 9.81, 0.0, 3.0)       # the bottom: the tension is largest
    -0.0
    """
    return -3.0 * m * g * theta_dot * math.sin(theta)


def energy(m: float, l: float, g: float, k2: float) -> float:
    """E = ½ m l² θ̇² + m g l (1 − cos θ) = 2 m g l k² (zero at rest at the bottom, §20).

    >>> energy(1.0, 1.0, 9.81, 1.0)             # the separatrix: mg·2l, the height of the top
    19.62
    """
    return 2.0 * m * g * l * k2


def slack_angle(k2: float) -> float | None:
    """|θ| where the tension vanishes (a string would go slack): sin²(θ/2) = (1 + 4k²)/6, when the
    motion reaches it (k² ≥ 1/2 for a swing, k² < 5/4 over the top), else None.

    >>> slack_angle(0.25) is None, round(slack_angle(1.0), 6)    # a 60° swing; the separatrix
    (True, 2.300524)
    """
    s2 = (1.0 + 4.0 * k2) / 6.0
    if s2 >= 1.0 or s2 > k2:
        return None
    return 2.0 * math.asin(math.sqrt(s2))
