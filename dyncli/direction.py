"""Lengths and unit vectors that neither overflow nor underflow.

A direction given by the user (an axis, a normal, a screw axis) may have any
finite size: ``[1e200, 0, 0]`` and ``[0, 0, 1e-200]`` are the same kind of
direction as ``[1, 0, 0]``.  Squaring its components first (``sqrt(v·v)``,
which is what ``numpy.linalg.norm`` computes) overflows to ∞ beyond ~1e154 and
underflows to 0 below ~1e-154; :func:`unit` therefore scales by the largest
component first, ``w = v / max|vᵢ|`` (so ``1 <= |w| <= √3``), and returns
``w / |w|``.  :func:`norm` is ``math.hypot`` (correctly scaled, within 1 ulp).
Every place that normalises a direction uses these.

:func:`norm` and :func:`unit` work on plain floats (a closed form that never
needs an array never imports numpy); the row-wise :func:`norm_rows` and
:func:`unit_rows` import numpy when called.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Sequence

from dyncli.errors import InputError

if TYPE_CHECKING:
    import numpy as np


class DirectionError(InputError, ValueError):
    """A zero or non-finite direction: exit 2 from a solver (InputError), a
    located field error inside a pydantic validator (ValueError)."""


def norm(v: Sequence[float]) -> float:
    """|v| without overflow or underflow of the squares (``math.hypot``)."""
    return math.hypot(*(float(c) for c in v))


def unit(v: Sequence[float], path: str | None = None, what: str = "the direction") -> tuple[float, ...]:
    """``v / |v|`` computed as ``w / |w|`` with ``w = v / max|vᵢ|``, as a tuple of floats.

    Raises :class:`DirectionError` (on ``path``) when ``v`` is zero or not finite.

    >>> unit((0.0, 0.0, 1e-200)), unit([3e200, 0, 4e200])
    ((0.0, 0.0, 1.0), (0.6, 0.0, 0.8))
    """
    a = [float(c) for c in v]
    if not all(math.isfinite(c) for c in a):
        raise DirectionError(f"{what} must have finite components", path)
    m = max(map(abs, a), default=0.0)
    if m == 0.0:
        raise DirectionError(f"{what} must be a non-zero vector", path)
    w = [c / m for c in a]
    length = math.hypot(*w)
    return tuple(c / length for c in w)


def norm_rows(a: np.ndarray) -> np.ndarray:
    """The length of each row of ``a``, scaled by its largest component
    first (no overflow or underflow of the squares); a zero row gives 0."""
    import numpy as np

    a = np.asarray(a, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        m = np.max(np.abs(a), axis=-1)
        safe = np.where((m > 0) & np.isfinite(m), m, 1.0)
        w = a / safe[..., None]
        return np.where((m > 0) & np.isfinite(m), safe * np.sqrt(np.sum(w * w, axis=-1)), m)


def unit_rows(a: np.ndarray) -> np.ndarray:
    """Each row of ``a`` divided by its length, scaled as in :func:`unit`;
    a zero or non-finite row gives NaN."""
    import numpy as np

    a = np.asarray(a, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        m = np.max(np.abs(a), axis=-1, keepdims=True)
        w = a / m
        return w / np.sqrt(np.sum(w * w, axis=-1, keepdims=True))
