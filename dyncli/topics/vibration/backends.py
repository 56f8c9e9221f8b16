"""The two backends of :mod:`dyncli.topics.vibration.closed_form`'s formulas: numpy arrays
(plots, sweeps, benchmarks; numpy imported when first asked for) and plain floats with math and
cmath (the few times of a problem: no numpy import), with numpy's conventions for values out of
range (inf on overflow, nan for sin(inf)) instead of exceptions.  Each is a namespace of the
functions the formulas call: exp, cos, sin, sinc, phi1 (real), cexp, sinhc (complex), ones, zeros.
"""

from __future__ import annotations

import cmath
import math
from types import SimpleNamespace


def _sinc(y):
    """sin(y)/y, 1 at 0 (y real array)."""
    import numpy as np

    y = np.asarray(y, dtype=float)
    out = np.ones_like(y)
    nz = y != 0
    out[nz] = np.sin(y[nz]) / y[nz]
    return out


def _phi1(z):
    """(1 - e^{-z})/z = -expm1(-z)/z, 1 at 0 (z ≥ 0 real array)."""
    import numpy as np

    z = np.asarray(z, dtype=float)
    out = np.ones_like(z)
    nz = z != 0
    out[nz] = -np.expm1(-z[nz]) / z[nz]
    return out


def _sinhc(u):
    """sinh(u)/u for complex u (1 at 0), accurate for small |u|."""
    import numpy as np

    u = np.asarray(u, dtype=complex)
    out = np.empty_like(u)
    small = np.abs(u) < 1e-4
    us = u[small]
    u2 = us * us
    out[small] = 1.0 + u2 / 6.0 * (1.0 + u2 / 20.0)
    ub = u[~small]
    out[~small] = np.sinh(ub) / ub
    return out


def arrays() -> SimpleNamespace:
    """The numpy backend (imports numpy)."""
    import numpy as np

    return SimpleNamespace(exp=np.exp, cos=np.cos, sin=np.sin, sinc=_sinc, phi1=_phi1, cexp=np.exp,
                           sinhc=_sinhc, ones=np.ones_like, zeros=np.zeros_like)


def _f_exp(x: float) -> float:
    """e^x, inf on overflow (numpy's convention)."""
    try:
        return math.exp(x)
    except OverflowError:
        return math.inf


def _f_trig(fn):
    def g(x: float) -> float:
        return fn(x) if math.isfinite(x) else math.nan      # sin(±inf) is nan, as in numpy
    return g


def _f_sinc(y: float) -> float:
    """sin(y)/y, 1 at 0.

    >>> _f_sinc(0.0), _f_sinc(math.pi / 2) == 2 / math.pi
    (1.0, True)
    """
    return 1.0 if y == 0 else _f_trig(math.sin)(y) / y


def _f_phi1(z: float) -> float:
    """(1 - e^{-z})/z = -expm1(-z)/z, 1 at 0 (z ≥ 0).

    >>> _f_phi1(0.0), _f_phi1(math.inf)
    (1.0, 0.0)
    """
    return 1.0 if z == 0 else -math.expm1(-z) / z


def _f_cexp(z: complex) -> complex:
    """e^z, not finite where numpy's is not (instead of an exception)."""
    try:
        return cmath.exp(z)
    except (OverflowError, ValueError):
        return complex(math.nan, math.nan)


def _f_sinhc(u: complex) -> complex:
    """sinh(u)/u for complex u (1 at 0), accurate for small |u|.

    >>> _f_sinhc(0j), abs(_f_sinhc(1j) - math.sin(1.0)) < 1e-16
    ((1+0j), True)
    """
    if abs(u) < 1e-4:
        u2 = u * u
        return 1.0 + u2 / 6.0 * (1.0 + u2 / 20.0)
    try:
        return cmath.sinh(u) / u
    except (OverflowError, ValueError):
        return complex(math.nan, math.nan)


#: the plain-float backend (math, cmath)
FLOATS = SimpleNamespace(exp=_f_exp, cos=_f_trig(math.cos), sin=_f_trig(math.sin), sinc=_f_sinc, phi1=_f_phi1,
                          cexp=_f_cexp, sinhc=_f_sinhc, ones=lambda x: 1.0 + 0.0 * x, zeros=lambda x: 0.0 * x)
