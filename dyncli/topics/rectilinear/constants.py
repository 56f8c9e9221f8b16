"""The numeric constants of the rectilinear routes and how their messages write a number.

* :data:`EPS` — the spacing of doubles at 1 (2⁻⁵²): the rounding every error estimate,
  tolerance floor and separatrix sensitivity of the quadratures (cases 2–4) is measured in.
* :data:`BIG` — the largest magnitude of the state the quadrature routes follow: case 3 declares
  a finite-time blow-up when |v| exceeds it, case 4 an escape to infinity when |s| does (and
  refuses a start |s1| beyond half of it).
* :func:`fmt` — a number in the text of a warning or a ``reached: false`` reason: ten
  significant digits, the form every route of the type uses.
"""

from __future__ import annotations

import sys

#: the spacing of doubles at 1 (the unit of rounding of every estimate in the quadrature routes)
EPS: float = sys.float_info.epsilon

#: the largest |v| (case 3) or |s| (case 4) the quadrature routes follow: beyond it a blow-up or escape
BIG: float = 1e100


def fmt(x: float) -> str:
    """``x`` as the type's messages write it: ten significant digits (``f"{x:.10g}"``)."""
    return f"{x:.10g}"
