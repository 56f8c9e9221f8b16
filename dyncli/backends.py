"""Two backends for formulas written once for one float and for arrays: :data:`FLOAT_OPS`
(math, with numpy's conventions out of range — inf on overflow, nan for a domain error — so a
closed form at the few requested times needs no numpy import) and numpy itself
(:func:`array_ops`, imported when first asked for: plots' dense sampling, vectorised callers).
Each offers the numpy names the formulas call: sin, cos, arcsin, arctan, arctan2, tanh, cosh,
sqrt, abs, sign, floor, where, maximum, minimum, round, clip, ones_like, zeros_like, errstate, pi.  Neutral (no topic).

>>> FLOAT_OPS.cosh(1000.0), FLOAT_OPS.round(2.5), FLOAT_OPS.clip(3.0, -1.0, 1.0), ops_for(1.0) is FLOAT_OPS
(inf, 2.0, 1.0, True)
"""

from __future__ import annotations

import math
from contextlib import nullcontext
from types import SimpleNamespace

from dyncli.expr import floatmath as _fm


def _round(x: float) -> float:
    """x rounded half to even (as numpy's round), x itself when not finite."""
    return float(round(x)) if math.isfinite(x) else x


def _floor(x: float) -> float:
    """The largest whole number <= x, as a float (x itself when not finite)."""
    return float(math.floor(x)) if math.isfinite(x) else x


#: the plain-float backend
FLOAT_OPS = SimpleNamespace(sin=_fm.sin, cos=_fm.cos, arcsin=_fm.arcsin, arctan=_fm.arctan, arctan2=_fm.arctan2,
                            tanh=_fm.tanh, cosh=_fm.cosh, sqrt=_fm.sqrt, abs=abs, sign=_fm.sign, floor=_floor, where=_fm.where,
                            maximum=max, minimum=min, round=_round, ones_like=_fm.ones, zeros_like=_fm.zeros, pi=math.pi,
                            clip=lambda x, lo, hi: min(max(x, lo), hi), errstate=lambda **kw: nullcontext())


def array_ops():
    """The numpy backend (imports numpy)."""
    import numpy as np

    return np


def ops_for(x):
    """:data:`FLOAT_OPS` for a plain number (a Python or numpy float, an int), else numpy."""
    return FLOAT_OPS if isinstance(x, (float, int)) else array_ops()
