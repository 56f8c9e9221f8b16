"""Vectorised adaptive Gauss-Legendre quadrature (numpy only) and root polishing.

``integrate(f, lo, width)`` integrates ``f`` over many intervals
``[lo_j, lo_j + width_j]`` at once.  Every interval is estimated with a
20-point Gauss-Legendre rule and checked against the embedded-quality 10-point
rule (|G20 - G10| bounds the error of G20 generously); intervals that fail the
tolerance are bisected, all of them together in one vectorised batch.  ``f`` is
called as ``f(x, j)`` with an array of abscissae and the array of task indices
they belong to, so one integrand can depend on its interval (weights such as
``(t - tau)``).  Widths are passed separately from the start points so that a
short interval next to a large coordinate keeps its exact length.

The integrands in this package are smooth after the substitutions that remove
the endpoint singularities (terminal velocity, turning points), so this simple
rule converges quickly; non-smooth integrands (``abs``, ``sign``) are handled
by bisection down to the resolution of the floating-point numbers.
"""

from __future__ import annotations


import numpy as np

from dyncli.topics.rectilinear.constants import EPS

_X20, _W20 = np.polynomial.legendre.leggauss(20)
_X10, _W10 = np.polynomial.legendre.leggauss(10)
_XN = np.concatenate([_X20, _X10])


class NonFinite(Exception):
    """The integrand is not finite at ``x`` (task ``task``)."""

    def __init__(self, x: float, task: int):
        super().__init__(f"integrand not finite at {x!r}")
        self.x = float(x)
        self.task = int(task)


class NotIntegrable(NonFinite):
    """Bisection reached the resolution of the doubles at ``x`` and the piece
    there still carries a sizeable part of the integral (a pole such as
    1/(t - c)): the integral does not exist."""

    def __init__(self, x: float, task: int):
        Exception.__init__(self, f"integrand not integrable near {x!r}")
        self.x = float(x)
        self.task = int(task)


def integrate(f, lo, width, rtol=1e-12, atol=0.0, max_rounds: int = 60, max_panels: int | None = None,
              info: dict | None = None):
    """Integrals of ``f`` over ``[lo_j, lo_j + width_j]``.

    Returns ``(values, errors, converged)`` arrays.  ``rtol`` and ``atol``
    (absolute) may be scalars or one per task; a subinterval is accepted when its error estimate is
    below ``rtol`` times the integral of |f| over it, or below its share of
    ``atol``.  Raises :class:`NonFinite` when ``f`` is not finite somewhere.

    With ``max_panels``, one call evaluates at most about that many panels
    (30 points each): when the next round would exceed it, the remaining
    pieces are accepted with their error estimates (not converged), and the
    worst unconverged piece is followed into its singularity (:func:`_zoom`):
    a non-integrable one raises :class:`NotIntegrable`.
    ``info`` (a dict), when given, receives ``x_bad``: the middle of the
    unconverged piece with the largest error estimate."""
    # (over 60 lines on purpose: one vectorised adaptive loop over a dozen parallel arrays of pieces;
    # split, they would travel as arguments)
    lo = np.atleast_1d(np.asarray(lo, dtype=float))
    width = np.broadcast_to(np.asarray(width, dtype=float), lo.shape).astype(float)
    m = lo.size
    vals = np.zeros(m)
    errs = np.zeros(m)
    conv = np.ones(m, dtype=bool)
    if m == 0:
        return vals, errs, conv
    W = np.where(width == 0, 1.0, np.abs(width))
    atol = np.broadcast_to(np.asarray(atol, dtype=float), lo.shape)
    rtol = np.broadcast_to(np.asarray(rtol, dtype=float), lo.shape)
    a = lo.copy()
    off = np.zeros(m)          # offset of the subinterval start from lo (exact-ish)
    h = width.copy()
    task = np.arange(m)
    nz = h != 0
    a, off, h, task = a[nz], off[nz], h[nz], task[nz]
    panels = 0
    worst = (0.0, 0.0, -1, 0.0, 0.0)     # (error, x, task, start, width) of the worst unconverged piece
    for rnd in range(max_rounds + 1):
        if task.size == 0:
            break
        half = 0.5 * h
        x = a[:, None] + (off + half)[:, None] + half[:, None] * _XN[None, :]
        jj = np.broadcast_to(task[:, None], x.shape)
        fx = np.asarray(f(x.ravel(), jj.ravel()), dtype=float)
        fx = np.broadcast_to(fx, (x.size,)).reshape(x.shape)
        bad = ~np.isfinite(fx)
        if bad.any():
            r, c = np.argwhere(bad)[0]
            raise NonFinite(x[r, c], task[r])
        g20 = half * (fx[:, :20] @ _W20)
        g10 = half * (fx[:, 20:] @ _W10)
        absint = np.abs(half) * (np.abs(fx[:, :20]) @ _W20)
        e = np.abs(g20 - g10)
        e = np.maximum(e, 50 * EPS * absint)
        share = atol[task] * np.abs(h) / W[task]
        rt = rtol[task]
        ok = (e <= np.maximum(rt * absint, share))
        # cannot bisect further: accept (flag non-convergence if the error is large)
        tiny = np.abs(h) <= 64 * EPS * np.maximum(np.abs(a + off), np.abs(a + off + h)) + 1e-300
        panels += task.size
        last = rnd == max_rounds or task.size > 20000 or (max_panels is not None and panels + 2 * np.count_nonzero(~(ok | tiny)) > max_panels)
        acc = ok | tiny | last
        loose = e <= 100 * np.maximum(rt * absint, share)
        bad = ~loose & acc
        if bad.any():
            conv[task[bad]] = False
            k = int(np.argmax(np.where(bad, e, -1.0)))
            if (max_panels is not None or info is not None) and (e[k] > worst[0] or worst[2] < 0):
                worst = (float(e[k]), float(a[k] + off[k] + half[k]), int(task[k]), float(a[k] + off[k]), float(h[k]))
        np.add.at(vals, task[acc], g20[acc])
        np.add.at(errs, task[acc], e[acc])
        keep = ~acc
        a, off, h, task = a[keep], off[keep], h[keep], task[keep]
        hh = 0.5 * h
        a = np.concatenate([a, a])
        off = np.concatenate([off, off + hh])
        h = np.concatenate([hh, hh])
        task = np.concatenate([task, task])
    if worst[2] >= 0:
        if info is not None:
            info["x_bad"] = worst[1]
        if max_panels is not None:
            # follow the singularity from a window 2^16 times the worst piece (inside its task)
            j = worst[2]
            t_lo, t_hi = sorted((float(lo[j]), float(lo[j] + width[j])))
            half_w = 2.0 ** 15 * abs(worst[4])
            z_lo = max(t_lo, worst[1] - half_w)
            z_hi = min(t_hi, worst[1] + half_w)
            _zoom(f, z_lo, z_hi - z_lo, j)
    return vals, errs, conv


def _zoom(f, lo: float, h: float, task: int, levels: int = 60) -> None:
    """Follow the worst unconverged piece into its singularity by bisection
    (keeping the half with the larger integral of |f|) and raise
    :class:`NotIntegrable` when that integral does not shrink: over ten
    halvings it falls by 2^-10 for a bounded f, by 2^-5 for an integrable
    |t - c|^(-1/2), and not at all for 1/(t - c) (scale invariance of the
    rule) or worse."""
    hist = []
    for _ in range(levels):
        hh = 0.5 * h
        if not (abs(hh) > 64 * EPS * max(abs(lo), abs(lo + h)) + 1e-300):
            break
        q = 0.5 * hh
        x = np.concatenate([lo + q + q * _X20, lo + hh + q + q * _X20])
        fx = np.asarray(f(x, np.full(x.shape, task)), dtype=float)
        fx = np.broadcast_to(fx, x.shape)
        if not np.all(np.isfinite(fx)):
            k = int(np.argmax(~np.isfinite(fx)))
            raise NonFinite(x[k], task)
        ab = abs(q) * (np.abs(fx).reshape(2, 20) @ _W20)
        side = int(ab[1] > ab[0])
        lo, h = lo + side * hh, hh
        hist.append(float(ab[side]))
        if len(hist) > 10 and hist[-11] > 0 and hist[-1] < 0.3 * hist[-11]:
            return                     # shrinking: integrable here
    if len(hist) > 10 and hist[-1] >= 0.3 * hist[-11]:
        raise NotIntegrable(lo + 0.5 * h, task)


def integrate1(f, lo: float, width: float, rtol: float = 1e-12, atol: float = 0.0):
    """One integral of a vectorised ``f(x)``: ``(value, error, converged)``."""
    v, e, c = integrate(lambda x, j: f(x), [lo], [width], rtol, atol)
    return float(v[0]), float(e[0]), bool(c[0])
