"""The work along a path (19.4): adaptive quadrature (the quadrature runner, :mod:`dyncli.quadrature`) of
F(x(t))·x'(t), with x'(t) differentiated exactly by the rules of calculus on the
expression IR (no sympy: :mod:`dyncli.expr.derivative`); the integrand
runs on the expressions' compiled scalar closures and stops at its first non-finite value.
The work along a straight segment (the single-valuedness check of V): composite
Gauss-Legendre in numpy, no scipy."""

from __future__ import annotations

import math

from dyncli.errors import InputError, NumericalError
from dyncli.result import Result
from dyncli.expr.derivative import derivative
from dyncli.topics.force_field.setup import Path


class _NotFinite(Exception):
    def __init__(self, t: float):
        super().__init__(t)
        self.t = t


def _scalar(exprs):
    """Each expression as its compiled closure of an environment dict (float in, float out; the
    caller holds one np.errstate): :meth:`dyncli.expr.Expr.scalar_fn`."""
    return [(lambda env, fn=e.scalar_fn(): float(fn(env))) for e in exprs]


def _integrand(fld, xs, dxs):
    """F(x(t))·x'(t) as a function of one float t; raises :class:`_NotFinite` at a non-finite value."""
    import numpy as np

    X, DX = _scalar(xs), _scalar(dxs)
    exprs = getattr(fld, "exprs", None)      # Cartesian F(x1, x2, x3); else the field's own F_at(x)
    F = _scalar(exprs) if exprs is not None else None

    def f(t):
        # scalar closures (no per-call array set-up): called once per quadrature node
        env = {"t": t}
        x = [g(env) for g in X]
        if F is not None:
            envx = {"x1": x[0], "x2": x[1], "x3": x[2]}
            Fx = [Fi(envx) for Fi in F]
        else:
            Fx = fld.F_at(np.array(x))
        out = float(sum(Fi * dxi(env) for Fi, dxi in zip(Fx, DX)))
        if not math.isfinite(out):
            raise _NotFinite(t)
        return out

    return f


def path_work(fld, path: Path, rtol: float, atol: float, res: Result, max_steps: int | None = None):
    """Work along the path by the quadrature runner (adaptive Gauss–Kronrod,
    :mod:`dyncli.quadrature`, panels counted against ``max_steps``): (U, error [J], x_start,
    x_end).  Sets ``res.method`` and ``res.error_estimate``: the error relative to the work's
    scale, the larger of |U| and max|F·x'|·|t2 − t1| (a closed path's work may vanish)."""
    import numpy as np

    from dyncli.quadrature import gauss_kronrod

    xs = (path.x1, path.x2, path.x3)
    try:
        dxs = [derivative(e, "t") for e in xs]
    except ValueError as exc:
        raise InputError(f"cannot differentiate the path exactly: {exc}", "path") from None
    t1, t2 = path.t1, path.t2

    def pos(t):
        return np.array([float(e.evaluate(t=t)) for e in xs])

    f = _integrand(fld, xs, dxs)
    x_start, x_end = pos(t1), pos(t2)
    if not (np.all(np.isfinite(x_start)) and np.all(np.isfinite(x_end))):
        raise InputError("the path is not defined at the ends of t_span (a coordinate is not finite there): "
                         "choose t_span inside the times where the path exists", "path.t_span")
    res.method = "quadrature"
    if t1 == t2:
        res.error_estimate = 0.0
        return 0.0, 0.0, x_start, x_end
    fmax = [0.0]

    def fv(ts):
        out = np.empty(len(ts))
        for k, t in enumerate(ts):
            if k % CPU_EVERY == 0:
                _within_cpu(t1, t2)
            out[k] = f(float(t))
        fmax[0] = max(fmax[0], float(np.max(np.abs(out))))
        return out

    with np.errstate(all="ignore"):
        try:
            U, err, ok = gauss_kronrod(fv, t1, t2, max(rtol, 1e-14), atol, max_steps=max_steps,
                                       what="the work integrand F·dx/dt", path="path")
        except _NotFinite as exc:   # at once, at the first node where it happens
            raise NumericalError(f"the work integrand F·dx/dt is not finite at t = {exc.t:.6g} (F is singular "
                                 "on the path, or the path or F overflows there)") from None
    if not ok:
        res.warn(f"quadrature of the work: the requested tolerance is not reached (estimated error {err:.3g} J); "
                 "F·dx/dt may have a singularity or many kinks on the path")
    if not (math.isfinite(U) and math.isfinite(err)):
        raise NumericalError("the work integral is not finite (F is singular on the path?)")
    scale = max(abs(U), fmax[0] * abs(t2 - t1))
    res.error_estimate = float(err) / scale if scale > 0 else float(err)
    return float(U), float(err), x_start, x_end


#: the integrand's nodes between two looks at the solve's CPU (:mod:`dyncli.cputime`)
CPU_EVERY = 1024


def _within_cpu(t1: float, t2: float) -> None:
    """NumericalError once the solve has used more than its CPU budget (``accuracy.max_cpu``,
    default 2 s: the quadrature's work is adaptive, so it is not projected to its end)."""
    from dyncli import cputime

    if (limit := cputime.over()) is not None:
        raise NumericalError(
            f"the work along the path over t in [{t1:g}, {t2:g}] took more than the CPU budget of {limit:g} s "
            "(accuracy.max_cpu) before reaching accuracy.rtol (F·dx/dt with many kinks or a singularity on the "
            "path): shorten path.t_span, loosen accuracy.rtol, or raise accuracy.max_cpu")


def segment_work(fld, a, b, panels: int = 8, order: int = 16) -> tuple[float, float]:
    """(U, error): the work of F along the straight segment a -> b, ∫₀¹ F(a + s d)·d ds with
    d = b − a, by composite Gauss-Legendre (``panels`` panels of ``order`` nodes, one vectorised
    evaluation of ``fld.F_at``), and the error as the difference from half as many panels.  NaN when F
    is not finite on the segment.

    >>> import numpy as np
    >>> class Lin:                                   # F = (x1, 0, 0): the work from 0 to 1 is 1/2
    ...     F_at = staticmethod(lambda x: np.stack([x[0], 0 * x[0], 0 * x[0]]))
    >>> U, err = segment_work(Lin, np.zeros(3), np.array([1.0, 0, 0]))
    >>> round(U, 15), err < 1e-15
    (0.5, True)
    """
    import numpy as np

    x, w = np.polynomial.legendre.leggauss(order)
    d = b - a

    def rule(n):
        edges = np.linspace(0.0, 1.0, n + 1)
        s = (0.5 * (edges[:-1] + edges[1:])[:, None] + 0.5 * np.diff(edges)[:, None] * x).ravel()
        with np.errstate(all="ignore"):
            f = np.asarray(fld.F_at(a[:, None] + s * d[:, None]), dtype=float).T @ d
        return float(np.sum(f * np.tile(w, n)) * 0.5 / n) if np.all(np.isfinite(f)) else math.nan

    fine, coarse = rule(panels), rule(max(panels // 2, 1))
    return fine, abs(fine - coarse)
