"""The one bracketed root finder of dyncli (docs/accuracy.md; issue #26): Brent's method in
plain floats, step for step the operations of scipy's ``brentq`` (so a root is the same double),
without importing scipy.optimize (~0.1 s at start-up).  Topic-agnostic: every topic finds its
roots here (the top's nutation cubic, the constrained particle's turning points and
equilibria, the particle's events, rectilinear's legs and crossings), never with scipy's
root finders directly (``tests/test_one_runner.py``)."""

from __future__ import annotations

import functools
import math
import struct
import sys

from dyncli import cputime
from dyncli.errors import NumericalError

#: a root search (:func:`all_roots`) stops once the solve has used this many times its CPU budget
SEARCH_MARGIN = cputime.ADAPTIVE

#: scipy's defaults and smallest rtol of ``brentq``
XTOL = 2e-12
RTOL = 4 * sys.float_info.epsilon
MAXITER = 100


def brentq(f, a: float, b: float, *, xtol: float = XTOL, rtol: float = RTOL, maxiter: int = MAXITER) -> float:
    """Root of ``f`` in the bracket [a, b] (f(a), f(b) of opposite signs, else ValueError):
    scipy's ``brentq`` with its arguments, its checks and its errors (a NaN value: ValueError;
    ``maxiter`` exhausted: RuntimeError), in plain floats (:func:`brent`).

    >>> brentq(lambda x: x * x - 2.0, 0.0, 2.0) == 2 ** 0.5
    True
    """
    if xtol <= 0:
        raise ValueError(f"xtol too small ({xtol:g} <= 0)")
    if rtol < RTOL:
        raise ValueError(f"rtol too small ({rtol:g} < {RTOL:g})")
    return brent(f, float(a), float(b), xtol, rtol, int(maxiter), signs=True)


class NotANumber(ValueError):
    """The function's value at ``x`` is NaN (brentq's ValueError, with the place kept)."""

    def __init__(self, x: float):
        super().__init__(f"The function value at x={x:g} is NaN; solver cannot converge.")
        self.x = x


def brent(f, xa, xb, xtol, rtol, maxiter, *, signs=False):
    """Root of ``f`` bracketed by [xa, xb] by Brent's method (bisection guarding inverse
    quadratic / secant steps), in plain floats: step for step the operations of scipy's
    ``brentq``, so the root is the same double.  Converged when the bracket half-width is
    below (xtol + rtol|x|)/2.  ``signs``: end values of one sign are refused (ValueError), as
    brentq does (without: the caller guarantees the bracket)."""
    def fx(x):
        y = float(f(x))
        if math.isnan(y):           # as brentq: refused, not iterated on
            raise NotANumber(x)
        return y

    xpre, xcur = xa, xb
    fpre, fcur = fx(xpre), fx(xcur)
    if fpre == 0:
        return xpre
    if fcur == 0:
        return xcur
    if signs and math.copysign(1.0, fpre) == math.copysign(1.0, fcur):
        raise ValueError("f(a) and f(b) must have different signs")
    xblk = fblk = spre = scur = 0.0
    for _ in range(maxiter):
        if fpre != 0 and fcur != 0 and (math.copysign(1.0, fpre) != math.copysign(1.0, fcur)):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):           # keep the best estimate in xcur
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2
        sbis = (xblk - xcur) / 2
        if fcur == 0 or abs(sbis) < delta:
            return xcur
        stry = math.nan                     # no interpolation: bisect
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            try:
                if xpre == xblk:            # secant
                    stry = -fcur * (xcur - xpre) / (fcur - fpre)
                else:                       # inverse quadratic
                    dpre = (fpre - fcur) / (xpre - xcur)
                    dblk = (fblk - fcur) / (xblk - xcur)
                    stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            except ZeroDivisionError:       # C's ±inf or nan: the test below fails, so bisect
                pass
        if 2 * abs(stry) < min(abs(spre), 3 * abs(sbis) - delta):
            spre, scur = scur, stry         # a good short step
        else:                               # bisect
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = fx(xcur)
    raise RuntimeError(f"Failed to converge after {maxiter} iterations, value is {xcur}")   # as brentq



def root_in_bracket(g, x0: float, x1: float, g0: float | None = None, g1: float | None = None) -> float:
    """Root of ``g`` in the bracket ``[x0, x1]`` to machine precision (:func:`brentq`; endpoint
    values may be given to save calls).  Ends of one sign (a bracket up to rounding): the end
    closer to zero.  A root many orders of magnitude below the bracket's width is approached by
    bisection in the ordering of the doubles first."""
    _brentq = brentq

    if g0 is None:
        g0 = g(x0)
    if g0 == 0:
        return x0
    if g1 is None:
        g1 = g(x1)
    if g1 == 0:
        return x1
    if (g0 > 0) == (g1 > 0):
        # the caller guarantees a bracket up to rounding: return the closer end
        return x0 if abs(g0) <= abs(g1) else x1
    try:
        return float(_brentq(g, x0, x1, xtol=1e-300, rtol=RTOL, maxiter=200))
    except RuntimeError:
        pass
    except NotANumber:
        raise
    except ValueError:
        # the ends as ``g`` gives them are of one sign, where the caller's values (summed another
        # way) were not: a bracket up to rounding, as above (fuzz seed 1313963)
        ga, gb = g(x0), g(x1)
        return x0 if abs(ga) <= abs(gb) else x1
    # Brent's bisection steps halve the bracket arithmetically: a root many
    # orders of magnitude smaller than the bracket (a root near 0 in [0, h])
    # needs ~log2(h/root) of them and exhausts maxiter.  Bisect the bracket in
    # the ordering of the doubles themselves (≤ 64 steps to adjacent doubles)
    # until its ends are within a factor 4 of each other, then polish.
    a, b, ga = float(x0), float(x1), g0
    if a > b:
        a, b, ga = b, a, g1
    for _ in range(130):
        if a > 0 and b <= 4 * a or b < 0 and a >= 4 * b:
            break
        m = _float_mid(a, b)
        if m in (a, b):
            return a if abs(ga) <= abs(g(b)) else b
        gm = g(m)
        if gm == 0:
            return m
        if (gm > 0) == (ga > 0):
            a, ga = m, gm
        else:
            b = m
    try:
        return float(_brentq(g, a, b, xtol=1e-300, rtol=RTOL, maxiter=200))
    except RuntimeError as exc:
        from dyncli.errors import NumericalError

        raise NumericalError(f"the root finder did not converge in the bracket [{a!r}, {b!r}] ({exc}); "
                             "the function is probably too noisy there: loosen accuracy.rtol or move the target") from None


def _float_key(x: float) -> int:
    (b,) = struct.unpack("<q", struct.pack("<d", x))
    return b if b >= 0 else -(b & 0x7FFFFFFFFFFFFFFF)


def _float_mid(a: float, b: float) -> float:
    """The double halfway between ``a`` and ``b`` in the ordering of all doubles
    (the geometric mean for same-sign ends; about ±1e-154 across zero)."""
    k = (_float_key(a) + _float_key(b)) // 2
    bits = k if k >= 0 else (-k) | 0x8000000000000000
    return struct.unpack("<d", struct.pack("<Q", bits))[0]


def roots_in_brackets(F, a, b, fa, fb, maxit: int = 200):
    """Roots of ``F`` in many brackets ``[a_j, b_j]`` at once (sign change
    from ``fa`` to ``fb``): the Illinois variant of regula falsi with a
    bisection every third step (at least linear convergence, superlinear for
    simple roots), to adjacent doubles.  ``F(x, k)`` evaluates the brackets
    ``k`` at the points ``x`` in one vectorised call; one call per iteration
    for all brackets replaces one scalar root search per bracket."""
    import numpy as np

    a = np.array(a, dtype=float)
    b = np.array(b, dtype=float)
    ga = np.array(fa, dtype=float)
    gb = np.array(fb, dtype=float)
    wa, wb = ga.copy(), gb.copy()          # Illinois weights
    side = np.zeros(a.size, dtype=int)
    root = np.where(np.abs(ga) <= np.abs(gb), a, b)
    done = (ga == 0) | (gb == 0) | ((ga > 0) == (gb > 0))
    root[ga == 0] = a[ga == 0]
    root[(gb == 0) & (ga != 0)] = b[(gb == 0) & (ga != 0)]
    for it in range(maxit):
        mid = a + 0.5 * (b - a)
        act = ~done & (mid != a) & (mid != b)
        if not act.any():
            break
        k = np.nonzero(act)[0]
        ak, bk = a[k], b[k]
        with np.errstate(all="ignore"):
            x = (ak * wb[k] - bk * wa[k]) / (wb[k] - wa[k])
        lo, hi = np.minimum(ak, bk), np.maximum(ak, bk)
        bis = (it % 3 == 2) | ~(x > lo) | ~(x < hi)
        x = np.where(bis, mid[k], x)
        fx = np.asarray(F(x, k), dtype=float)
        fx = np.broadcast_to(fx, x.shape)
        z = fx == 0
        root[k[z]] = x[z]
        done[k[z]] = True
        same = ((fx > 0) == (ga[k] > 0)) & ~z
        other = ~same & ~z
        ks, ko = k[same], k[other]
        # moved a: halve b's weight if a moved last time too (Illinois)
        wb[ks] = np.where(side[ks] == 1, 0.5 * wb[ks], wb[ks])
        a[ks], ga[ks], wa[ks], side[ks] = x[same], fx[same], fx[same], 1
        wa[ko] = np.where(side[ko] == -1, 0.5 * wa[ko], wa[ko])
        b[ko], gb[ko], wb[ko], side[ko] = x[other], fx[other], fx[other], -1
    rest = ~done
    root[rest] = np.where(np.abs(ga[rest]) <= np.abs(gb[rest]), a[rest], b[rest])
    return root


def newton_in_brackets(FD, a, b, fa, fb, maxit: int = 100):
    """Roots of ``f`` in many brackets ``[a_j, b_j]`` at once when its slope comes with it:
    ``FD(x, k) -> (f, f')`` on the points ``x`` of the brackets ``k``.  Newton's step from the
    bracket end where |f| is smaller (the secant of the ends while that end has no slope yet),
    bisection when the step would leave the bracket that the signs maintain, to a step below
    4 ulp: quadratic for simple roots, a few vectorised calls where :func:`roots_in_brackets`
    needs about one per bit."""
    import numpy as np

    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    ga, gb = np.array(fa, dtype=float), np.array(fb, dtype=float)
    da, db = np.full(a.size, np.nan), np.full(b.size, np.nan)
    root = np.where(np.abs(ga) <= np.abs(gb), a, b)
    k = np.nonzero((ga != 0) & (gb != 0))[0]
    for _ in range(maxit):
        A, B, GA, GB = a[k], b[k], ga[k], gb[k]
        at_a = np.abs(GA) <= np.abs(GB)
        e, ge, de = np.where(at_a, A, B), np.where(at_a, GA, GB), np.where(at_a, da[k], db[k])
        with np.errstate(all="ignore"):
            step = np.where(np.isnan(de), (A * GB - B * GA) / (GB - GA), e - ge / de)
        conv = np.abs(step - e) <= 4 * sys.float_info.epsilon * np.abs(e)    # the step is below rounding
        root[k[conv]] = e[conv]
        keep = ~conv
        k, A, B, GA, GB, e, step = k[keep], A[keep], B[keep], GA[keep], GB[keep], e[keep], step[keep]
        if not k.size:
            break
        lo, hi = np.minimum(A, B), np.maximum(A, B)
        mid = lo + 0.5 * (hi - lo)
        x = np.where((step > lo) & (step < hi), step, mid)
        fx, dx = (np.broadcast_to(np.asarray(u, dtype=float), x.shape) for u in FD(x, k))
        same = (fx > 0) == (GA > 0)
        a[k], ga[k], da[k] = np.where(same, x, A), np.where(same, fx, GA), np.where(same, dx, da[k])
        b[k], gb[k], db[k] = np.where(same, B, x), np.where(same, GB, fx), np.where(same, db[k], dx)
        root[k] = x
        stop = (fx == 0) | (mid == lo) | (mid == hi)
        k = k[~stop]
    return root


def root(f, xa: float, xb: float, xtol: float = 1e-300, rtol: float = 4 * sys.float_info.epsilon,
         maxiter: int = 2000) -> float:
    """The root of ``f`` bracketed by [xa, xb] to full double accuracy (4 ε relative in x): the
    project's one Brent (:func:`brent`) with the tolerances every ``find`` query uses."""
    return brent(f, xa, xb, xtol, rtol, maxiter)


def minimize_bounded(f, lo: float, hi: float, xatol: float):
    """The minimum of ``f`` on [lo, hi] by Brent's bounded method (scipy's
    ``minimize_scalar(method="bounded")``, imported here only, lazily): (x, f(x))."""
    from scipy.optimize import minimize_scalar

    r = minimize_scalar(f, bounds=(lo, hi), method="bounded", options={"xatol": xatol})
    return float(r.x), r.fun


def _critical(S, noise):
    """The real critical points in (−1, 1) of each Chebyshev series, a row of ``S`` (sorted), None
    for a series whose derivative's companion matrix is not finite.  Each series is first cut
    after its last coefficient above its ``noise`` (the coefficients below the rounding of the
    values interpolated are that rounding); the companion matrices of one size go to numpy's
    eigvals in one stack (the roots as numpy's chebroots gives them)."""
    import numpy as np

    big = np.abs(S) > np.asarray(noise)[:, None]
    kept = np.where(big.any(axis=1), S.shape[1] - 1 - np.argmax(big[:, ::-1], axis=1), 0)   # the degree kept
    out: list = [np.array([])] * len(S)             # (degree below 2: a line, monotone)
    for n in {int(v) for v in kept if v >= 2}:
        idx = np.flatnonzero(kept == n)
        D = S[idx, :n + 1] @ _derivative_matrix(n).T          # p' (degree n − 1), a row each
        size = n - 1
        if size == 1:
            r = (-D[:, 0] / D[:, 1])[:, None]
            ok = np.isfinite(r[:, 0])
        else:
            base, ratio = _companion_parts(size)
            with np.errstate(all="ignore"):
                mats = np.repeat(base[None], len(idx), axis=0)
                mats[:, :, -1] -= (D[:, :-1] / D[:, -1:]) * ratio * .5
            ok = np.all(np.isfinite(mats), axis=(1, 2))
            r = np.full((len(idx), size), np.nan, dtype=complex)
            if np.any(ok):
                try:
                    r[ok] = np.linalg.eigvals(mats[ok][:, ::-1, ::-1])
                except np.linalg.LinAlgError:
                    ok[:] = False
        for i, row, good in zip(idx, r, ok):
            out[i] = np.sort(np.real(row[(np.abs(np.imag(row)) <= 1e-8) & (np.abs(np.real(row)) < 1)])) if good else None
    return out


@functools.lru_cache(maxsize=64)
def _derivative_matrix(n: int):
    """The (n, n + 1) matrix taking a Chebyshev series of degree n to its derivative's
    (numpy's chebder of each unit series; kept: never written to)."""
    import numpy as np
    from numpy.polynomial import chebyshev as C

    D = C.chebder(np.eye(n + 1), axis=0)
    D.flags.writeable = False
    return D


@functools.lru_cache(maxsize=8)
def _nodes(deg: int):
    """(the deg + 1 Chebyshev points of the first kind, their Vandermonde matrix): made once a
    degree (a search of many small intervals starts a cell on each)."""
    from numpy.polynomial import chebyshev as C

    x1 = C.chebpts1(deg + 1)
    x1.flags.writeable = False
    V = C.chebvander(x1, deg)
    V.flags.writeable = False
    return x1, V


def all_roots(f, a: float, b: float, *, cells: int = 16, deg: int = 32, max_depth: int = 48,
              limit: int | None = None, floor: float = 0.0, budget: int = 20_000, batch: int = 64,
              f1=None):
    """Every root of a smooth ``f`` (on arrays) in [a, b], decided by the sign analysis of its
    critical points, not by sampling: (roots, touches, bad).  On each cell f is replaced by its
    Chebyshev interpolant p of degree ``deg``, the cell halved until p's last coefficients are at
    the rounding of f's values (or below ``floor``).  Between consecutive critical points of p
    (the real roots of p') p is monotone, so f has at most one root there: the signs of f itself
    at the cell's ends and at those points decide every root, refined by Brent (``roots``: sign
    changes).  A critical point where f is within its rounding of 0 without a sign change is a
    double root (``touches``) unless halving the cell around it decides its sign.  ``bad``: cells
    where f is not finite or not resolved (midpoints; also a cell halved ``max_depth`` times and
    still not resolved, wider than the rounding of x), or beyond ``budget`` cells; ``limit``:
    stop once more than that many roots are found (the cells taken in order from ``a``).  The
    cells waiting on the stack are read ``batch`` at a time (:class:`_Cells`: one call of f for
    the nodes of the cell taken and the next ``batch`` − 1, one for the separators of those
    resolved): the same cells, the same values, the same roots as one at a time (``batch=1``:
    a search that stops at its first root reads no cell beyond it)."""
    import numpy as np

    eps = sys.float_info.epsilon
    edges = np.linspace(a, b, cells + 1)           # the starting cells (halved where needed)
    stack, tiny = [(float(u), float(v), 0) for u, v in zip(edges[:-1], edges[1:])][::-1], 64 * eps * max(abs(a), abs(b), 1e-300)
    roots, touches, bad = list[float](), list[float](), []      # (the sign changes, the double roots, the unresolved cells)
    read = _Cells(f, deg, floor, batch)
    one = f1 or (lambda x: float(np.asarray(f(np.array([x])), dtype=float)[0]))
    while stack and (limit is None or len(roots) + len(touches) <= limit):
        u, v, depth = stack.pop()
        m, h = 0.5 * (u + v), 0.5 * (v - u)
        if budget % 64 == 0 and (cpu := cputime.over(SEARCH_MARGIN)) is not None:
            raise NumericalError(f"a root search has used {SEARCH_MARGIN:g} × the solve's CPU budget of {cpu:g} s "
                                 f"(accuracy.max_cpu; {len(roots)} roots found so far): check the scales of the "
                                 "inputs, or raise accuracy.max_cpu")
        if (budget := budget - 1) < 0:
            bad.append(m)
            continue
        cell, split = read.cell(u, v, stack), depth < max_depth and h > tiny
        if cell.kind == "infinite":             # (a cell with no finite value at all: not halved)
            if split and cell.some_finite:
                stack += [(m, v, depth + 1), (u, m, depth + 1)]
            else:
                bad.append(m)
            continue
        if cell.kind == "unresolved":
            if split:
                stack += [(m, v, depth + 1), (u, m, depth + 1)]
                continue
            if h > tiny:                        # halved max_depth times and still not resolved: not decided
                bad.append(m)
                continue
            read.separate((cell, u, v))
        if cell.kind == "overflow":             # (a huge f: its derivative's companion matrix overflows)
            bad.append(m)
            continue
        sep, fs, noise = cell.sep, cell.fs, cell.noise
        undecided = [j for j in range(1, len(sep) - 1)
                     if abs(fs[j]) <= noise and fs[j] * fs[j - 1] > 0 and fs[j] * fs[j + 1] > 0]
        s = sep[undecided[0]] if undecided else u
        if undecided and split and (d := 0.125 * min(s - u, v - s)) > 0:
            # a near-tangency: a cell around it (the rounding shrinks with f's size there)
            stack += [(s + d, v, depth + 1), (s - d, s + d, depth + 1), (u, s - d, depth + 1)]
            continue
        touches += [sep[j] for j in undecided]
        for j in range(len(sep) - 1):
            if fs[j] == 0 and (j > 0 or not roots or roots[-1] != sep[j]):
                roots.append(sep[j])
            elif fs[j] * fs[j + 1] < 0:
                try:
                    roots.append(brent(one, sep[j], sep[j + 1],
                                       4 * eps * max(abs(sep[j]), abs(sep[j + 1])), 4 * eps, 200))
                except NotANumber as nan:   # f undefined inside the bracket (off its domain): a bad place
                    bad.append(nan.x)
        roots += [v] if fs[-1] == 0 and v == b else []
    return sorted(set(roots)), sorted(touches), bad


class _Cell:
    """What all_roots reads of one cell: ``kind`` "infinite" (a value not finite; ``some_finite``),
    "unresolved" (p's last coefficients above the rounding), "overflow" (p' has no finite
    companion matrix) or "ok", with the separators ``sep`` (the ends and p's critical points) and
    f there (``fs``), ``noise`` the rounding of f on the cell."""

    __slots__ = ("kind", "some_finite", "c", "noise", "sep", "fs")

    def __init__(self, kind, some_finite=False, c=None, noise=0.0):
        self.kind, self.some_finite, self.c, self.noise = kind, some_finite, c, noise
        self.sep = self.fs = None


class _Cells:
    """all_roots' reading of its cells, ``batch`` at a time: the cell popped and the cells on top
    of the stack not read yet, their nodes in one call of f and the separators of those resolved
    in one more (each cell's numbers exactly as read alone)."""

    def __init__(self, f, deg, floor, batch):
        self.f, self.deg, self.floor, self.batch = f, deg, floor, batch
        self.x1, self.V = _nodes(deg)
        self.read: dict[tuple[float, float], _Cell] = {}

    def cell(self, u, v, stack) -> _Cell:
        got = self.read.pop((u, v), None)
        if got is not None:
            return got
        import numpy as np

        group = [(u, v)]
        for w in reversed(stack):
            if len(group) >= self.batch or (w[0], w[1]) in self.read:
                break
            group.append((w[0], w[1]))
        x1, n = self.x1, self.deg + 1
        X = np.concatenate([0.5 * (p + q) + 0.5 * (q - p) * x1 for p, q in group])
        with np.errstate(all="ignore"):
            Y = np.broadcast_to(np.asarray(self.f(X), dtype=float), X.shape).reshape(len(group), n)
        eps = sys.float_info.epsilon
        with np.errstate(all="ignore"):
            C = Y @ self.V / n
            C[:, 1:] *= 2
            noise = 16 * eps * np.max(np.abs(Y), axis=1)
            ok = ~(np.max(np.abs(C[:, -3:]), axis=1)
                   > np.maximum(np.maximum(1e-13 * np.max(np.abs(C), axis=1), noise), self.floor))
        finite = np.isfinite(Y)
        cells = [_Cell("ok" if ok[i] else "unresolved", c=C[i], noise=float(noise[i])) if finite[i].all()
                 else _Cell("infinite", bool(finite[i].any())) for i in range(len(group))]
        self.separate(*[(c, p, q) for c, (p, q) in zip(cells, group) if c.kind == "ok"])
        for c, key in zip(cells[1:], group[1:]):
            self.read[key] = c
        return cells[0]

    def separate(self, *cells) -> None:
        """The separators of the cells ((cell, u, v): the ends and p's critical points between)
        and f there, in one call."""
        import numpy as np

        if not cells:
            return
        todo = []
        crit = _critical(np.array([c.c for c, _, _ in cells]), [c.noise for c, _, _ in cells])
        for (c, u, v), r in zip(cells, crit):
            if r is None:
                c.kind = "overflow"
                continue
            m, h = 0.5 * (u + v), 0.5 * (v - u)
            c.sep = [u] + [float(m + h * t) for t in r if u < m + h * t < v] + [v]
            todo.append(c)
        if not todo:
            return
        with np.errstate(all="ignore"):
            fs = [float(w) for w in np.asarray(self.f(np.array([x for c in todo for x in c.sep])), dtype=float)]
        k = 0
        for c in todo:
            c.fs, k = fs[k:k + len(c.sep)], k + len(c.sep)


def distinct_sorted(a):
    """The sorted distinct values of a float array (flattened), as ``numpy.unique`` gives them for
    finite values, without ``numpy.unique``'s import of ``numpy.ma`` (5 ms of a cold solve whose
    search grids are the only use)."""
    import numpy as np

    g = np.sort(np.ravel(np.asarray(a, dtype=float)))
    if g.size < 2:
        return g
    keep = np.empty(g.size, dtype=bool)
    keep[0] = True
    np.not_equal(g[1:], g[:-1], out=keep[1:])
    return g[keep]


@functools.lru_cache(maxsize=8)
def _series(deg: int):
    """(the deg + 1 Chebyshev points of the first kind, the matrix taking a polynomial's values
    there to its Chebyshev coefficients): interpolation in one product (kept: never written to)."""
    from numpy.polynomial import chebyshev as C

    x = C.chebpts1(deg + 1)
    to_series = C.chebvander(x, deg) / (deg + 1)
    to_series[:, 1:] *= 2
    return x, to_series


@functools.lru_cache(maxsize=8)
def _derivative_series(deg: int):
    """(the points of :func:`_series`, the matrix taking a polynomial's values there to the
    Chebyshev coefficients of its derivative): interpolation and differentiation in one product."""
    import numpy as np
    from numpy.polynomial import chebyshev as C

    x, to_series = _series(deg)
    return x, to_series @ C.chebder(np.eye(deg + 1), axis=0).T


def polynomial_extremes(pieces, deg: int = 15, components=None) -> list[list[list[float]]]:
    """The critical points of polynomial curves, decided exactly, never by samples: for each
    piece ``(f, a, b)`` of ``pieces`` (an ODE step's dense output on its step: ``f`` on an array
    of n times gives an array of shape (components, n), each component a polynomial of degree at
    most ``deg``), the critical points inside (a, b) of each component.  Each component is
    interpolated at deg + 1 Chebyshev points — its exact Chebyshev series, to rounding — and the
    critical points are the real roots of that series' derivative (its companion matrix, as
    :func:`all_roots` does on each cell).  A derivative whose constant coefficient exceeds the
    sum of the others' magnitudes has no root on the interval (|T_k| <= 1): none is looked for
    (all pieces at once, in arrays: only the few near an extreme find roots).  Roots of the
    derivative with a small imaginary part (a near-double root, whose real pair the rounding may
    have made complex) are kept too: between consecutive points returned each component is
    monotone.  A component constant to its rounding (its derivative's coefficients within
    4 deg² eps of its size) or not finite on the piece gives none.  ``components``: the indices
    of the components wanted (the lists of each piece then in that order), default all."""
    import numpy as np

    pieces = list(pieces)
    if not pieces:
        return []
    x, W = _derivative_series(deg)
    ab = np.array([(a, b) for _, a, b in pieces], dtype=float)
    m, h = 0.5 * (ab[:, 0] + ab[:, 1]), 0.5 * (ab[:, 1] - ab[:, 0])
    with np.errstate(all="ignore"):
        y = _piece_values(pieces, m, h, x)
        if components is not None:
            y = y[:, list(components), :]
        d = y @ W                                       # (pieces, components, deg): the derivative's series
        noise = 4 * deg * deg * sys.float_info.epsilon * np.max(np.abs(y), axis=-1)   # the rounding of y, differentiated
        look = (np.all(np.isfinite(d), axis=-1) & (np.abs(d[..., 0]) <= np.sum(np.abs(d[..., 1:]), axis=-1))
                & (np.max(np.abs(d), axis=-1) > noise))
    out: list[list[list[float]]] = [[[] for _ in range(d.shape[1])] for _ in pieces]
    for i, j in zip(*np.nonzero(look)):
        try:
            with np.errstate(all="ignore"):
                r = cheb_roots(np.trim_zeros(d[i, j], "b"))
        except np.linalg.LinAlgError:
            continue
        keep = (np.abs(np.imag(r)) <= 1e-6) & (np.abs(np.real(r)) < 1)
        a, b = ab[i]
        out[i][j] = sorted({float(m[i] + h[i] * t) for t in np.real(r[keep]) if a < m[i] + h[i] * t < b})
    return out


def _piece_values(pieces, m, h, x):
    """(pieces, components, len(x)): each piece's ``f`` at ``m + h x`` — DOP853 steps' dense
    outputs (:class:`dyncli.dop853.DenseOutput`, one shape) all at once through
    :class:`dyncli.dop853.DenseStack` (the same arithmetic on the same doubles: the same values),
    anything else one call per piece."""
    import numpy as np

    from dyncli.dop853 import DenseOutput, DenseStack

    fs = [f for f, _, _ in pieces]
    if len(fs) > 1 and all(type(f) is DenseOutput for f in fs) and len({f.F.shape for f in fs}) == 1:
        t = np.concatenate([mk + hk * x for mk, hk in zip(m, h)])
        rows = DenseStack(fs)(np.repeat(np.arange(len(fs)), x.size), t)
        return rows.reshape(len(fs), x.size, -1).transpose(0, 2, 1)
    return np.stack([np.atleast_2d(np.asarray(f(mk + hk * x), dtype=float)) for f, mk, hk in zip(fs, m, h)])


def check_extremes_budget() -> None:
    """Raise NumericalError once the solve has used SEARCH_MARGIN × its CPU budget (a search of
    extremes, checked between its rounds of evaluations)."""
    if (cpu := cputime.over(SEARCH_MARGIN)) is not None:
        raise NumericalError(f"a search of extremes has used {SEARCH_MARGIN:g} × the solve's CPU budget of "
                             f"{cpu:g} s (accuracy.max_cpu): narrow it with within, or raise accuracy.max_cpu")


def smooth_extremes(q, breaks, deg: int = 32, max_depth: int = 60, budget: int = 200_000):
    """The critical points of a smooth function of time between each pair of consecutive
    ``breaks`` (an ODE's steps, inside which a quantity of the state is a smooth function of the
    step's polynomial), decided by the sign analysis of its derivative, never by samples:
    (cuts, resolved).  ``q(ts)`` gives the values at an array of times, an array of shape
    (components, n) or (n,).  Each piece is replaced by the Chebyshev interpolant of degree
    ``deg`` of every component, the piece halved (all pieces at once, one call of ``q`` per
    halving) until the interpolants' last coefficients are at the rounding of the values, as
    :func:`all_roots` resolves its cells; the critical points of each component are the real
    roots of its interpolant's derivative (its companion matrix, only where the derivative's
    constant coefficient does not exceed the others' magnitudes: |T_k| <= 1), and the ends of
    the halved cells are cuts too (a kink, |v| at a stop, lies on one).  ``cuts``: per component,
    the sorted cuts strictly inside the breaks — between two consecutive cuts or breaks each
    component is monotone to its rounding.  ``resolved`` is False when a piece is not finite or
    not resolved after ``max_depth`` halvings (wider than the rounding of t) or when the halvings
    need more than ``budget`` evaluations of q: the caller cannot take the components as monotone."""
    import numpy as np
    from numpy.polynomial import chebyshev as C

    eps = sys.float_info.epsilon
    B = distinct_sorted(np.asarray(list(breaks), dtype=float))
    x1, V = _series(deg)
    cells = np.stack([B[:-1], B[1:]], axis=1) if B.size > 1 else np.zeros((0, 2))
    active = None                                        # (components, cells): still to resolve there
    cuts: list[set[float]] = []
    depth, used, scale = 0, 0, None
    while cells.shape[0]:
        check_extremes_budget()
        m, h = 0.5 * (cells[:, 0] + cells[:, 1]), 0.5 * (cells[:, 1] - cells[:, 0])
        used += cells.shape[0] * (deg + 1) if depth else 0
        if used > budget:
            return [sorted(c) for c in cuts], False
        with np.errstate(all="ignore"):
            Y = np.asarray(q((m[:, None] + h[:, None] * x1[None, :]).ravel()), dtype=float)
        Y = Y.reshape((-1, cells.shape[0], deg + 1))     # (components, cells, deg + 1)
        if scale is None:                                # each component's size over the whole motion
            scale = np.max(np.abs(Y), axis=(1, 2))[:, None]
            cuts = [set() for _ in range(Y.shape[0])]
            active = np.ones(Y.shape[:2], dtype=bool)
        assert active is not None
        if not np.all(np.isfinite(Y[active])):
            return [sorted(c) for c in cuts], False
        c = Y @ V                                        # Chebyshev coefficients (components, cells, deg + 1)
        noise = 16 * eps * scale                         # the rounding of the values
        tail = np.max(np.abs(c[..., -3:]), axis=-1)
        fine = ((tail <= np.maximum(1e-13 * np.max(np.abs(c), axis=-1), noise))
                | (np.sum(np.abs(c[..., 1:]), axis=-1) <= noise)       # (constant to rounding)
                | (h <= 64 * eps * np.maximum(np.abs(m), 1e-300))[None, :]   # as narrow as the rounding of t
                | ~active)
        if depth >= max_depth and not np.all(fine):
            return [sorted(c) for c in cuts], False
        d = C.chebder(c, axis=-1)                        # the derivative's series (components, cells, deg)
        look = (active & fine & (np.abs(d[..., 0]) <= np.sum(np.abs(d[..., 1:]), axis=-1))
                & (np.sum(np.abs(c[..., 1:]), axis=-1) > deg * noise))     # (constant to rounding: none)
        for j, i in zip(*np.nonzero(look)):
            try:
                with np.errstate(all="ignore"):
                    r = cheb_roots(np.trim_zeros(d[j, i], "b"))
            except np.linalg.LinAlgError:
                return [sorted(c) for c in cuts], False
            keep = (np.abs(np.imag(r)) <= 1e-6) & (np.abs(np.real(r)) < 1)
            # (a critical point within 1e-8 of the cell's end is that end's: the cell is monotone
            # to rounding up to it — its variation there ~1e-16 of h² q'' — and the end is a cut)
            cuts[j].update(float(m[i] + h[i] * t) for t in _polished(d[j, i], np.real(r[keep])) if abs(t) < 1 - 1e-8)
        split = ~np.all(fine, axis=0)
        mid = m[split]
        for j, comp in enumerate(cuts):                  # a halved cell's middle: a cut of what is halved
            comp.update(mid[~fine[j, split]].tolist())
        cells = np.concatenate([np.stack([cells[split, 0], mid], axis=1), np.stack([mid, cells[split, 1]], axis=1)])
        active = np.concatenate([~fine[:, split], ~fine[:, split]], axis=1)
        depth += 1
    lo, hi = (B[0], B[-1]) if B.size else (0.0, 0.0)
    inner = set(B.tolist())
    return [sorted(t for t in comp if lo < t < hi and t not in inner) for comp in cuts], True



def _polished(d, r):
    """The roots ``r`` in (−1, 1) of the Chebyshev series ``d`` after two Newton steps on the series
    itself (the companion matrix's eigenvalues carry its conditioning: ~1e-11 of the interval at
    a simple root), a step that would leave (−1, 1) or is not finite not taken.  Root by root in
    plain floats (:func:`cheb_value`: numpy's chebval, the same double; a few roots of a short
    series, where numpy's cost per call would be most of the work)."""
    import numpy as np

    c = [float(x) for x in d]
    dc = cheb_derivative(c)
    out = []
    for x in np.asarray(r, dtype=float).tolist():
        for _ in range(2):
            num, den = cheb_value(x, c), cheb_value(x, dc)
            if den == 0:                # (numpy's step: ±inf or NaN, never taken)
                continue
            step = num / den
            new = x - step
            if math.isfinite(new) and abs(new) < 1 and abs(step) < 1e-3:
                x = new
        out.append(x)
    return np.array(out, dtype=float)


def cheb_roots(c):
    """numpy.polynomial.chebyshev.chebroots of a 1-D series of floats ``c``: the same companion
    matrix (chebcompanion's, its constant part made once per size), the same eigenvalues (numpy's
    eigvals), sorted — the same roots, without the series' checks and copies made twice (a
    step's few roots: most of the call)."""
    import numpy as np

    c = np.asarray(c, dtype=float)
    if c.size == 0:
        raise ValueError("Coefficient array is empty")
    if c[-1] == 0:                      # (trailing zeros off, the first kept: numpy's trimseq)
        nz = np.flatnonzero(c)
        c = c[:nz[-1] + 1] if nz.size else c[:1]
    if c.size < 2:
        return np.array([], dtype=float)
    if c.size == 2:
        return np.array([-c[0] / c[1]])
    base, ratio = _companion_parts(c.size - 1)
    mat = base.copy()
    mat[:, -1] -= (c[:-1] / c[-1]) * ratio * .5
    r = np.linalg.eigvals(mat[::-1, ::-1])
    r.sort()
    return r


@functools.lru_cache(maxsize=32)
def _companion_parts(n: int):
    """(the constant part of chebcompanion's n × n matrix, its scl / scl[-1]), as numpy makes them
    (kept: never written to)."""
    import numpy as np

    mat = np.zeros((n, n), dtype=float)
    scl = np.array([1.] + [np.sqrt(.5)] * (n - 1))
    top = mat.reshape(-1)[1::n + 1]
    bot = mat.reshape(-1)[n::n + 1]
    top[0] = np.sqrt(.5)
    top[1:] = 1 / 2
    bot[...] = top
    return mat, scl / scl[-1]


def cheb_value(x: float, c: list) -> float:
    """numpy.polynomial.chebyshev.chebval(x, c) at one float x of a series ``c`` (a list of
    floats): Clenshaw's recurrence, the same operations in the same order (each one elementwise
    in numpy): the same double."""
    if len(c) == 1:
        c0, c1 = c[0], 0
    elif len(c) == 2:
        c0, c1 = c[0], c[1]
    else:
        x2 = 2 * x
        c0, c1 = c[-2], c[-1]
        for i in range(3, len(c) + 1):
            c0, c1 = c[-i] - c1, c0 + c1 * x2
    return c0 + c1 * x


def cheb_derivative(c: list) -> list:
    """numpy.polynomial.chebyshev.chebder(c) of a series ``c`` (a list of floats), in plain
    floats: the same operations in the same order (the same doubles)."""
    n = len(c)
    if n <= 1:
        return [c[0] * 0] if c else []
    c = list(c)
    n -= 1
    der = [0.0] * n
    for j in range(n, 2, -1):
        der[j - 1] = (2 * j) * c[j]
        c[j - 2] += (j * c[j]) / (j - 2)
    if n > 1:
        der[1] = 4 * c[2]
    der[0] = c[1]
    return der

def newton_system(F, jac, x0, *, scale, max_step: float = 0.5, tol: float = 1e-12, maxit: int = 60):
    """A root of the square system F(x) = 0 by Newton's method with the analytic Jacobian
    ``jac``: least-squares steps (a singular Jacobian, a continuum of roots, takes the
    minimum-norm step), each limited to ``max_step`` in the units ``scale`` (a vector of
    per-component scales).  Converged when the step is below ``tol`` of those units; returns
    (x, converged)."""
    import numpy as np

    x = np.array(x0, dtype=float)
    scale = np.asarray(scale, dtype=float)
    for _ in range(maxit):
        r = np.asarray(F(x), dtype=float)
        if not np.all(np.isfinite(r)):
            return x, False
        J = np.asarray(jac(x), dtype=float)
        if not np.all(np.isfinite(J)):
            raise _not_finite()
        step = np.linalg.lstsq(J, -r, rcond=1e-13)[0]
        big = float(np.max(np.abs(step) / scale, initial=0.0))
        if big > max_step:
            step *= max_step / big
        x = x + step
        if big <= tol:
            return x, True
    return x, False


def newton_systems(F, jac, X0, *, scale, max_step: float = 0.5, tol: float = 1e-12, maxit: int = 60):
    """:func:`newton_system` from many starts at once, each row of ``X0`` its own iteration (the
    same steps, stopped and limited row by row): ``F(X)`` and ``jac(X)`` take the rows still
    iterating, (k, N) → (k, N) and (k, N, N).  The least-squares steps of all rows in one stacked
    SVD (:func:`lstsq_many`, lstsq's own cut of the singular values below ``rcond`` of the
    largest).  Returns (X, converged: a boolean per row); a row whose F is not finite stops there,
    not converged, as :func:`newton_system` does."""
    import numpy as np

    X = np.array(X0, dtype=float)
    scale = np.asarray(scale, dtype=float)
    ok = np.zeros(len(X), dtype=bool)
    live = np.arange(len(X))
    for _ in range(maxit):
        if not live.size:
            break
        R = np.asarray(F(X[live]), dtype=float)
        fin = np.all(np.isfinite(R), axis=1)
        live, R = live[fin], R[fin]
        if not live.size:
            break
        step = lstsq_many(np.asarray(jac(X[live]), dtype=float), -R, rcond=1e-13)
        big = np.max(np.abs(step) / scale, axis=1)
        over = big > max_step
        step[over] *= (max_step / big[over])[:, None]
        X[live] += step
        done = big <= tol
        ok[live[done]] = True
        live = live[~done]
    return X, ok


def _not_finite():
    """The LinAlgError lstsq raises for a matrix that is not finite, raised before LAPACK sees it
    (LAPACK prints its complaint about it to stdout, behind the renderers)."""
    import numpy as np

    return np.linalg.LinAlgError("SVD did not converge in Linear Least Squares (a matrix that is not finite)")


def lstsq_many(A, B, rcond: float):
    """The minimum-norm least-squares solutions of A[k] x = B[k] for a stack of matrices,
    as ``numpy.linalg.lstsq(A[k], B[k], rcond)`` (LAPACK's gelsd: singular values at or below
    rcond times the largest taken as zero), by one stacked SVD; a matrix that is not finite
    raises LinAlgError, as lstsq would (without handing it to LAPACK, which prints a complaint
    to stdout first)."""
    import numpy as np

    fin = np.all(np.isfinite(A), axis=(1, 2))
    out = np.empty((len(A), A.shape[2]))
    if np.any(fin):
        U, s, Vt = np.linalg.svd(A[fin], full_matrices=False)
        keep = s > rcond * s[:, :1]
        inv = np.divide(1.0, s, out=np.zeros_like(s), where=keep)
        out[fin] = np.einsum("kji,kj->ki", Vt, inv * np.einsum("kji,kj->ki", U, B[fin]))
    if not np.all(fin):
        raise _not_finite()
    return out


def fminbound_unit(f, xatol: float, maxfun: int = 500) -> float:
    """Brent's minimiser on [0, 1] (golden section with parabolic steps; Brent 1973, ch. 5), in plain
    floats: the ``find`` queries' extremes of a result with no rate, and the distance's stops."""
    c, sqrt_eps = 0.5 * (3.0 - math.sqrt(5.0)), math.sqrt(2.220446049250313e-16)
    a, b, v, w, x = 0.0, 1.0, c, c, c
    fv = fw = fx = f(x)
    d = e = 0.0
    for _ in range(maxfun):
        xm, tol1 = 0.5 * (a + b), sqrt_eps * abs(x) + xatol / 3.0
        if abs(x - xm) <= 2 * tol1 - 0.5 * (b - a):
            break
        golden = True
        if abs(e) > tol1:                             # a parabola through x, w, v
            r, q = (x - w) * (fx - fv), (x - v) * (fx - fw)
            p, q = (x - v) * q - (x - w) * r, 2.0 * (q - r)
            p, q = (-p if q > 0 else p), abs(q)
            r, e = e, d
            if abs(p) < abs(0.5 * q * r) and q * (a - x) < p < q * (b - x):
                d, golden = p / q, False
                if (x + d - a) < 2 * tol1 or (b - x - d) < 2 * tol1:
                    d = tol1 if xm >= x else -tol1
        if golden:
            d = c * (e := (a - x) if x >= xm else (b - x))
        u = x + (d if abs(d) >= tol1 else (tol1 if d >= 0 else -tol1))
        fu = f(u)
        if fu <= fx:
            a, b = (x, b) if u >= x else (a, x)
            v, fv, w, fw, x, fx = w, fw, x, fx, u, fu
        else:
            a, b = (u, b) if u < x else (a, u)
            if fu <= fw or w == x:
                v, fv, w, fw = w, fw, u, fu
            elif fu <= fv or v == x or v == w:
                v, fv = u, fu
    return x


def fminbound_many(f, n: int, xatol: float, maxiter: int = 200):
    """The minimiser on [0, 1] of each of ``n`` unimodal functions at once, by golden-section
    search: ``f(u, k)`` evaluates the functions ``k`` (an index array) at the points ``u`` in one
    vectorised call — one call per iteration for every function still searching, where
    :func:`fminbound_unit` makes ~30 scalar calls per function.  Stopped as Brent's minimiser
    stops, when the bracket around the best point is within 2·(√eps·|u| + xatol/3) of it (a
    kink, |v| at a stop, is found as well as a smooth minimum: golden section compares values,
    it fits no parabola).  Returns the best point of each (an array of n)."""
    import numpy as np

    g = 0.5 * (3.0 - math.sqrt(5.0))                  # the golden section, 0.382
    sqrt_eps = math.sqrt(sys.float_info.epsilon)
    a, b = np.zeros(n), np.ones(n)
    c, d = np.full(n, g), np.full(n, 1.0 - g)         # a < c < d < b
    k = np.arange(n)
    both = np.asarray(f(np.concatenate([c, d]), np.concatenate([k, k])), dtype=float)
    fc, fd = both[:n].copy(), both[n:].copy()
    live = np.ones(n, dtype=bool)
    for _ in range(maxiter):
        best = np.where(fc <= fd, c, d)
        live &= (b - a) > 2 * (sqrt_eps * np.abs(best) + xatol / 3.0)
        k = np.flatnonzero(live)
        if not k.size:
            break
        left = fc[k] <= fd[k]                         # the minimum is in [a, d]: drop (d, b]
        kl, kr = k[left], k[~left]
        b[kl], d[kl], fd[kl] = d[kl], c[kl], fc[kl]
        c[kl] = b[kl] - (1.0 - g) * (b[kl] - a[kl])
        a[kr], c[kr], fc[kr] = c[kr], d[kr], fd[kr]     # else in [c, b]: drop [a, c)
        d[kr] = a[kr] + (1.0 - g) * (b[kr] - a[kr])
        u = np.where(left, c[k], d[k])
        fu = np.asarray(f(u, k), dtype=float)
        fc[kl], fd[kr] = fu[left], fu[~left]
    return np.where(fc <= fd, c, d)


def smooth_minima(f, n: int, deg: int = 20, noise=0.0):
    """The local minima inside (0, 1) of each of ``n`` smooth functions at once — read off each
    function's interpolant, never sampled: ``f(u, k)`` as :func:`fminbound_many`'s (one
    vectorised call for all).  Each function is replaced by its Chebyshev interpolant of degree
    ``deg`` at the deg + 1 Chebyshev points of the first kind; where that series is resolved
    (its last three coefficients within 1e-13 of the largest, or at the rounding of the values:
    a polynomial of degree ≤ deg − 3, such as |v|² of a DOP853 step's velocity, degree 14,
    exactly) its local minima are the real roots of its derivative inside (−1, 1) (its
    companion matrix, polished by :func:`_polished`) where the second derivative is not
    negative.  ``noise``: the values' absolute rounding, one number or one per function (a
    series whose tail is at that level is resolved as far as the values allow).  Returns
    ``(minima, resolved)``: a list per function of its interior minima's u
    (every one: two stops in one piece are two cuts), and a boolean array (the caller searches
    the others by :func:`fminbound_many`).  One call of ``f`` where golden-section search makes
    ~40 per minimum."""
    import numpy as np
    from numpy.polynomial import chebyshev as C

    x, V = _series(deg)
    k = np.arange(n)
    with np.errstate(all="ignore"):
        Y = np.asarray(f(np.tile(0.5 + 0.5 * x, n), np.repeat(k, x.size)), dtype=float).reshape(n, x.size)
        c = Y @ V
        d = C.chebder(c, axis=-1)
        big = np.max(np.abs(c), axis=-1)
        floor = np.maximum(16 * sys.float_info.epsilon * np.max(np.abs(Y), axis=-1), np.asarray(noise, dtype=float))
        level = np.maximum(1e-13 * big, floor)         # a coefficient at or below it: rounding
        resolved = np.all(np.isfinite(c), axis=-1) & (np.max(np.abs(c[:, -3:]), axis=-1) <= level)
        # |T_k| <= 1: a derivative whose constant term exceeds the rest has no root (nor has a
        # constant one)
        look = resolved & (np.abs(d[:, 0]) <= np.sum(np.abs(d[:, 1:]), axis=-1)) & np.any(d[:, 1:] != 0, axis=-1)
    minima: list = [np.zeros(0) for _ in range(n)]
    for i in np.flatnonzero(look):
        # the derivative's series up to the last coefficient of c above the rounding (a DOP853
        # step's |v|², degree 14, gives a 13 × 13 companion matrix, not 19 × 19: the roots of
        # the rest move at the rounding, and the polish below is on the whole series)
        above = np.flatnonzero(np.abs(c[i]) > level[i])
        try:
            with np.errstate(all="ignore"):
                r = cheb_roots(np.trim_zeros(d[i][:max(int(above[-1]) if above.size else 1, 1)], "b"))
        except (np.linalg.LinAlgError, ValueError):
            resolved[i] = False
            continue
        r = np.real(r[(np.abs(np.imag(r)) <= 1e-6) & (np.abs(np.real(r)) < 1)])
        if not r.size:
            continue
        r = _polished(d[i], r)
        dd = cheb_derivative(d[i].tolist())
        curv = np.array([cheb_value(x, dd) for x in r.tolist()], dtype=float)
        minima[i] = np.sort(0.5 + 0.5 * r[~(curv < 0)])
    return minima, resolved
