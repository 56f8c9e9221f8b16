"""The quadrature runner: globally adaptive Gauss–Kronrod (G7/K15) on arrays, with the work
budget of the numerical routes (docs/accuracy.md).  Topic-agnostic: the integrand is any
vectorised f(t) -> array.

* Every pass evaluates all the panels still being refined in one call of ``f`` (the 15
  Kronrod nodes of each panel), so an integrand written with numpy costs one call per pass.
* Many intervals at once (:func:`gauss_kronrod_many`: a motion's pieces, each with its own
  integrand ``f(i, t)`` and tolerance): the panels of all of them in the same call per pass,
  each interval refined and stopped on its own, as if it were integrated alone.
* Panels are bisected until Σ e ≤ max(atol, rtol·|I|); the error returned is that sum.  Each
  panel's e is |K15 − G7|, raised to QUADPACK's (200·d/A)^1.5·A (A = ∫|f − its mean| over the
  panel) where that is larger — the difference can vanish by accident on a panel holding a kink
  or a jump — and at least the rounding of its sum, 50 ε ∫|f| (QUADPACK's rule): an integral
  whose terms cancel below that stops there, its error saying so.
* Work budget: each panel evaluated counts one step against ``max_steps`` (default
  ``MAX_PANELS``); a run that needs more is refused (:class:`dyncli.ode.OverBudget`, exit 1,
  the runner's one message), as on the ODE routes.
* A non-finite value of the integrand is an input error (the expression is undefined there,
  exit 2); a sum that overflows is a numerical one (exit 1).
* CPU: each pass looks at the solve's CPU budget (:mod:`dyncli.cputime`, ``accuracy.max_cpu``):
  the work is adaptive, not projected to its end, so a quadrature that has used
  ``cputime.ADAPTIVE`` (2) × the budget (an integrand of rounding noise, which no bisection
  resolves) is refused then, exit 1, as the root and find searches are.
* A panel that cannot be halved any more (its width at the rounding of t) ends the run as not
  converged: the caller warns.
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from dyncli import cputime
from dyncli.errors import InputError, NumericalError

MAX_PANELS = 50_000         # default budget: panels evaluated (15 evaluations each)
_EPS = float(np.finfo(float).eps)

_XGK = np.array([0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                 0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                 0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                 0.207784955007898467600689403773245, 0.000000000000000000000000000000000])
_WGK = np.array([0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                 0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                 0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                 0.204432940075298892414161999234649, 0.209482141084727828012999174891714])
_WG = np.array([0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                0.381830050505118944950369775488975, 0.417959183673469387755102040816327])
NODES = np.concatenate([-_XGK[:-1], _XGK[::-1]])               # 15 nodes on [-1, 1]
_WK = np.concatenate([_WGK[:-1], _WGK[::-1]])
_WG15 = np.zeros(15)
_WG15[[1, 3, 5, 13, 11, 9]] = np.concatenate([_WG[:3], _WG[:3]])
_WG15[7] = _WG[3]


def gauss_kronrod(f, a: float, b: float, rtol: float, atol: float, *, max_steps: int | None = None,
                  what: str = "the integrand", path: str | None = None, dense: bool = False):
    """∫_a^b f by globally adaptive G7/K15 (``f`` evaluated on arrays of t).
    Returns (integral, error estimate = Σ of the panels' errors, converged): the rule of
    :func:`gauss_kronrod_many` on one interval, with the bookkeeping in plain floats (a quadrature
    called hundreds of times a solve: half the cost of the many-interval arrays for one).
    ``dense`` (a < b): a fourth item, the :class:`Antiderivative` ∫_a^x f for every x in [a, b]
    from the accepted panels, with no further evaluation of ``f``.

    A non-finite value of ``f`` or of the sum is an :class:`InputError` on ``path`` naming
    ``what``; more than ``max_steps`` panels (default MAX_PANELS) is :class:`OverBudget`.

    >>> import numpy as np
    >>> I, err, ok = gauss_kronrod(np.cos, 0.0, np.pi / 2, 1e-12, 1e-14)
    >>> abs(I - 1.0) < 1e-14, ok
    (True, True)
    """
    from dyncli.ode import OverBudget

    if b == a:
        return (0.0, 0.0, True) + ((Antiderivative(a, [], []),) if dense else ())
    if b < a:                                    # ∫_a^b = −∫_b^a
        if dense:
            raise ValueError("a dense quadrature runs forward: a < b")
        I, err, ok = gauss_kronrod(f, b, a, rtol, atol, max_steps=max_steps, what=what, path=path)
        return -I, err, ok
    limit = int(max_steps or MAX_PANELS)
    lo, hi = np.array([a]), np.array([b])
    done_val = done_err = 0.0
    panels = 0
    kept: list = []                  # dense: the accepted panels' (lo, hi, values at the nodes)
    one = lambda _i, t: f(t)     # noqa: E731  (the many-interval integrand f(i, t) of _panels)

    def out(I, E, ok, *last):
        if not dense:
            return I, E, ok
        kept.append(last)
        return I, E, ok, Antiderivative(a, *(np.concatenate(col) for col in zip(*kept)))

    while True:
        c, h = 0.5 * (lo + hi), 0.5 * (hi - lo)
        panels += len(c)
        if panels > limit:
            raise OverBudget(b, panels + len(c), limit, float(c[0]))
        _within_cpu(panels, what, path)
        K, diff, floor, y = _pass(one, None, c, h, what, path, panels)
        err = np.maximum(diff, floor)
        total = done_val + float(K.sum())
        total_err = done_err + float(err.sum())
        tol = max(atol, rtol * abs(total))
        if total_err <= tol:
            return out(total, total_err, True, lo, hi, y)
        # split the panels that carry more than their share of the error, unless it is rounding
        # alone (a sum that cancels: no bisection can lower it; the error says what is left)
        refinable = diff > floor
        split = refinable & (err > tol * (2 * h) / (b - a))
        if not np.any(split):
            if not np.any(refinable):
                return out(total, total_err, True, lo, hi, y)
            split = refinable & (err >= err[refinable].max())
        done_val += float(K[~split].sum())
        done_err += float(err[~split].sum())
        if np.any(h[split] <= 4 * np.finfo(float).eps * max(abs(a), abs(b), 1.0)):
            return out(done_val + float(K[split].sum()), done_err + float(err[split].sum()), False, lo, hi, y)
        if dense:
            kept.append((lo[~split], hi[~split], y[~split]))
        lo, hi, c = lo[split], hi[split], c[split]
        lo, hi = np.concatenate([lo, c]), np.concatenate([c, hi])


class Antiderivative:
    """F(x) = ∫_a^x f of a dense :func:`gauss_kronrod` run: on each accepted panel the degree-14
    polynomial through f's 15 Kronrod values (the rule's own interpolant: over the whole panel
    it integrates to the panel's K15 sum, so F is continuous and F(b) is the integral), integrated
    exactly — a Chebyshev series per panel, evaluated by Clenshaw in plain floats.  Within a panel
    its error is that of the interpolant, of the order of the panel's |K15 − G7|.

    ``F(x)`` for a ≤ x ≤ b; ``f(x)`` the interpolant; ``inverse(y)``: the x where F(x) = y for an
    F that increases (f > 0: a time as the integral of dt/dx), by Newton within a panel kept
    inside its bracket (bisection where a step leaves it), to the rounding of x.

    >>> import math, numpy as np
    >>> F = gauss_kronrod(np.exp, 0.0, 2.0, 1e-13, 0.0, dense=True)[3]
    >>> abs(F(1.3) - math.expm1(1.3)) < 1e-13, abs(F.inverse(math.expm1(0.7)) - 0.7) < 1e-14
    (True, True)
    """

    def __init__(self, a: float, lo, hi, y=None):
        order = np.argsort(lo, kind="stable")
        self.a = float(a)
        self.lo = [float(v) for v in np.asarray(lo, float)[order]]
        self.hi = [float(v) for v in np.asarray(hi, float)[order]]
        if not self.lo:
            self.c: list = []
            self.ci: list = []
            self.F0 = [0.0]
            return
        fit, integ = _cheb_maps()
        Y = np.asarray(y, float)[order]
        C = Y @ fit.T                            # the interpolants' Chebyshev coefficients
        H = 0.5 * (np.asarray(self.hi) - np.asarray(self.lo))
        CI = (Y @ integ.T) * H[:, None]          # ∫ from the panel's start, in x
        self.c, self.ci = C.tolist(), CI.tolist()
        whole = [_clenshaw(ci, 1.0) for ci in self.ci]
        self.F0 = [0.0]
        for w in whole:
            self.F0.append(self.F0[-1] + w)

    def _panel(self, x: float) -> int:
        return min(max(bisect.bisect_right(self.lo, x) - 1, 0), len(self.lo) - 1)

    def _u(self, k: int, x: float) -> float:
        h = 0.5 * (self.hi[k] - self.lo[k])
        return min(max((x - self.lo[k]) / h - 1.0, -1.0), 1.0)

    def __call__(self, x: float) -> float:
        if not self.lo or x <= self.a:
            return 0.0
        k = self._panel(x)
        return self.F0[k] + _clenshaw(self.ci[k], self._u(k, x))

    def f(self, x: float) -> float:
        k = self._panel(x)
        return _clenshaw(self.c[k], self._u(k, x))

    def inverse(self, y: float) -> float:
        if not self.lo or y <= 0.0:
            return self.a
        if y >= self.F0[-1]:
            return self.hi[-1]
        k = min(max(bisect.bisect_right(self.F0, y) - 1, 0), len(self.lo) - 1)
        lo, hi, ci, c = self.lo[k], self.hi[k], self.ci[k], self.c[k]
        h, target = 0.5 * (hi - lo), y - self.F0[k]
        whole = self.F0[k + 1] - self.F0[k]
        ul, uh = -1.0, 1.0
        u = 2.0 * target / whole - 1.0 if whole > 0 else 0.0
        for _ in range(100):
            r = _clenshaw(ci, u) - target
            if r > 0:
                uh = u
            else:
                ul = u
            d = h * _clenshaw(c, u)
            step = r / d if d > 0 else math.inf
            nu = u - step
            if not ul < nu < uh:                 # outside the bracket: halve it
                nu = 0.5 * (ul + uh)
            if abs(nu - u) <= 2 * _EPS or uh - ul <= 4 * _EPS:
                u = nu
                break
            u = nu
        return lo + h * (u + 1.0)


_MAPS: list = []


def _cheb_maps():
    """(values at the 15 nodes -> Chebyshev coefficients of their interpolant, -> coefficients of
    its integral from −1), built once."""
    if not _MAPS:
        from numpy.polynomial import chebyshev as C

        fit = np.linalg.inv(C.chebvander(NODES, NODES.size - 1))
        integ = np.stack([C.chebint(fit[:, j], lbnd=-1.0) for j in range(NODES.size)], axis=1)
        _MAPS.extend([fit, integ])
    return _MAPS[0], _MAPS[1]


def _clenshaw(c: list, u: float) -> float:
    """Σ c_k T_k(u) in plain floats."""
    b1 = b2 = 0.0
    u2 = 2.0 * u
    for ck in reversed(c[1:]):
        b1, b2 = u2 * b1 - b2 + ck, b1
    return u * b1 - b2 + c[0]


def gauss_kronrod_many(f, a, b, rtol: float, atol, *, max_steps: int | None = None,
                       what: str = "the integrand", path: str | None = None):
    """∫ over each interval [a_i, b_i] at once: ``f(i, t)`` the integrand of interval ``i[j]`` at
    ``t[j]`` (two arrays of one shape, the intervals mixed), so that every pass evaluates the
    panels still being refined in *all* the intervals in one call.  Each interval is refined as
    :func:`gauss_kronrod` refines its one (bisected until its own Σ of the panels' errors ≤ max(atol_i,
    rtol·|I_i|), ``atol`` a number or one per interval; the panels that carry more than their
    share of the error split, each term at least its rounding), and stops on its own: an interval
    whose first pass meets its tolerance costs that pass only.  Returns three arrays (integral,
    error estimate, converged), one entry per interval (b_i < a_i: −∫_{b_i}^{a_i}).  The budget
    ``max_steps`` counts the panels of all the intervals together.

    >>> import numpy as np
    >>> I, err, ok = gauss_kronrod_many(lambda i, t: np.cos(t) * (i + 1), [0.0, 0.0], [np.pi / 2, np.pi], 1e-12, 1e-14)
    >>> bool(abs(I[0] - 1.0) < 1e-14 and abs(I[1]) < 1e-14 and ok.all())
    True
    """
    from dyncli.ode import OverBudget

    a = np.asarray(a, dtype=float).reshape(-1)
    b = np.asarray(b, dtype=float).reshape(-1)
    m = a.size
    atol = np.broadcast_to(np.asarray(atol, dtype=float), (m,))
    sign = np.where(b < a, -1.0, 1.0)
    lo0, hi0 = np.minimum(a, b), np.maximum(a, b)
    width = hi0 - lo0
    tiny = 4 * _EPS * np.maximum(np.maximum(np.abs(a), np.abs(b)), 1.0)    # a panel that cannot be halved
    I, E, ok = np.zeros(m), np.zeros(m), np.ones(m, dtype=bool)
    done_val, done_err = np.zeros(m), np.zeros(m)
    own = np.nonzero(width > 0)[0]
    lo, hi = lo0[own], hi0[own]
    limit = int(max_steps or MAX_PANELS)
    panels = 0
    while own.size:
        c, h = 0.5 * (lo + hi), 0.5 * (hi - lo)
        panels += len(c)
        if panels > limit:
            raise OverBudget(float(hi0[own].max()), panels + len(c), limit, float(c[0]))
        _within_cpu(panels, what, path)
        K, diff, floor, _y = _pass(f, own, c, h, what, path, panels)
        err = np.maximum(diff, floor)
        total = done_val + np.bincount(own, K, minlength=m)
        total_err = done_err + np.bincount(own, err, minlength=m)
        tol = np.maximum(atol, rtol * np.abs(total))
        live = np.zeros(m, dtype=bool)
        live[own] = True
        # split the panels that carry more than their share of their interval's error, unless it
        # is rounding alone (a sum that cancels: no bisection can lower it; the error says what is left)
        refinable = diff > floor
        split = refinable & (err > tol[own] * (2 * h) / width[own])
        some_split = np.bincount(own, split, minlength=m) > 0
        some_refinable = np.bincount(own, refinable, minlength=m) > 0
        worst = np.full(m, -np.inf)
        np.maximum.at(worst, own[refinable], err[refinable])
        fallback = live & ~some_split & some_refinable
        split |= fallback[own] & refinable & (err >= worst[own])
        halt = np.zeros(m, dtype=bool)
        np.logical_or.at(halt, own[split], h[split] <= tiny[own[split]])
        finished = live & ((total_err <= tol) | ~some_refinable | halt)
        I[finished], E[finished] = total[finished], total_err[finished]
        ok[finished] = ~halt[finished] | (total_err[finished] <= tol[finished])
        keep = ~finished[own]
        done_val += np.bincount(own, np.where(keep & ~split, K, 0.0), minlength=m)
        done_err += np.bincount(own, np.where(keep & ~split, err, 0.0), minlength=m)
        go = keep & split
        own, lo, hi, c = own[go], lo[go], hi[go], c[go]
        own, lo, hi = np.concatenate([own, own]), np.concatenate([lo, c]), np.concatenate([c, hi])
    return sign * I, E, ok


def _within_cpu(panels: int, what: str, path: str | None) -> None:
    """NumericalError once the solve has used ``cputime.ADAPTIVE`` × its CPU budget (checked once
    a pass: the work is adaptive, not projected to its end)."""
    if (limit := cputime.over(cputime.ADAPTIVE)) is not None:
        raise NumericalError(
            f"the quadrature of {what}{f' ({path})' if path else ''} used {cputime.ADAPTIVE:g} × the solve's "
            f"CPU budget of {limit:g} s (accuracy.max_cpu) after {panels} panels without reaching accuracy.rtol "
            "(an integrand that is rounding noise at the inputs' scales, or one with very many kinks): check "
            "the scales of the inputs, loosen accuracy.rtol, or raise accuracy.max_cpu")


#: a pass over more panels than this is evaluated in slices, the CPU budget looked at between them
#: (a pass costs as much as all the passes before it: one look per pass could overshoot the budget 2x)
SLICE = 1024


def _pass(f, own, c, h, what: str, path: str | None, panels: int):
    """:func:`_panels` of one pass, in slices of :data:`SLICE` panels when it is larger."""
    if len(c) <= SLICE:
        return _panels(f, own, c, h, what, path)
    parts = []
    for k in range(0, len(c), SLICE):
        if k:
            _within_cpu(panels, what, path)
        parts.append(_panels(f, None if own is None else own[k:k + SLICE], c[k:k + SLICE], h[k:k + SLICE], what, path))
    return tuple(np.concatenate(col) for col in zip(*parts))


def _panels(f, own, c, h, what: str, path: str | None):
    """One pass over the panels of centres ``c`` and half-widths ``h`` (of the intervals ``own``,
    or None for one interval):
    (K15 sums, each panel's error — |K15 − G7| or QUADPACK's (200 d / A)^1.5 A, the larger —,
    the rounding of each sum, 50 ε ∫|f|: QUADPACK's rule, no error is below it; the values at
    the nodes, one row a panel)."""
    x = c[:, None] + h[:, None] * NODES[None, :]
    idx = None if own is None else np.repeat(own, NODES.size)        # (None: one interval)
    y = np.asarray(f(idx, x.ravel()), dtype=float).reshape(x.shape)
    if not np.all(np.isfinite(y)):
        bad = x[~np.isfinite(y)][0]
        raise InputError(f"{what} is not finite at t = {bad:.6g} inside the interval "
                         "(the position or its derivative is undefined there)", path)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # overflow: reported below
        mean = y @ _WK
        K = mean * h
        diff = np.abs(K - (y @ _WG15) * h)
        floor = 50 * _EPS * (np.abs(y) @ _WK) * np.abs(h)
        # QUADPACK's guard: |K15 − G7| can vanish by accident on a panel with a kink or a jump;
        # its (200 d / A)^1.5 A, A = ∫|f − mean|, is larger there (never below d here)
        spread = (np.abs(y - 0.5 * mean[:, None]) @ _WK) * np.abs(h)
        guard = spread * np.minimum(1.0, (200.0 * diff / spread) ** 1.5)
        diff = np.where(spread > 0, np.maximum(diff, guard), diff)
    if not (np.all(np.isfinite(K)) and np.all(np.isfinite(diff)) and np.all(np.isfinite(floor))):
        raise NumericalError(f"the integral of {what} is not finite: it overflows a double (beyond ~1.8e308)")
    return K, diff, floor, y


def quad(f, a: float, b: float, **kw):
    """QUADPACK's adaptive quadrature of a scalar ``f`` (scipy's ``quad``, imported here only,
    lazily): (integral, error estimate).  For integrands that are not vectorised (a curve's
    speed evaluated point by point); ``kw``: scipy's (``limit``, ``epsabs``, ``epsrel``)."""
    from scipy.integrate import quad as scipy_quad

    return scipy_quad(f, a, b, **kw)[:2]
