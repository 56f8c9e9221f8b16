"""Case 3, a = a(v): one branch of the velocity from v1 in one direction — where it ends
(terminal velocity, singularity of a, or |v| -> infinity), the substitution v(u) that removes
the logarithmic singularity there, and t(u), s(u) on a grid of u (6.8, 6.10).
The solver is :mod:`.case3`."""

from __future__ import annotations

import math

import numpy as np

from dyncli.rootfind import distinct_sorted, root_in_bracket
from dyncli.topics.rectilinear._quad import NonFinite, integrate
from dyncli.topics.rectilinear.constants import BIG, EPS
from dyncli.topics.rectilinear.work import QUAD


def _first_zero(A, v1: float, e: int, c: float, g_hi: float):
    """The smallest g in [1e-15, g_hi] where a(v1 + e c g) has a root or touches 0, decided by the
    sign analysis of :func:`dyncli.rootfind.all_roots` (its critical points, not samples) on the
    three stretches of the scan: g = 10^y to 1e-3, g itself to 4, g = 4·10^y beyond; None if none."""
    from dyncli.rootfind import all_roots

    pieces = [(lambda y: 10.0 ** y, -15.0, math.log10(min(1e-3, g_hi))),
              (lambda y: y, 1e-3, min(4.0, g_hi)),
              (lambda y: 4.0 * 10.0 ** y, 0.0, math.log10(g_hi / 4.0) if g_hi > 4.0 else 0.0)]
    for gmap, lo, hi in pieces:
        if not hi > lo:
            continue
        roots, touches, _ = all_roots(lambda y, gmap=gmap: A(v1 + e * c * gmap(np.asarray(y, dtype=float))),
                                      lo, hi, limit=1)
        found = sorted(roots + touches)
        if found:
            return float(gmap(found[0]))
    return None


class Branch:
    """v moving from v1 in direction e (+1/-1)."""

    def __init__(self, c3, e: int, scale: float):
        self.c3 = c3
        self.e = e
        self.v1 = c3.v1
        self.c = scale
        self._find_end()
        self._build_grid()

    # -- where does v go? -------------------------------------------------
    def _find_end(self) -> None:
        c3, e, v1, c = self.c3, self.e, self.v1, self.c
        # a starting table (issue 28 audit): it only bounds the search; the first root of a is
        # decided by all_roots below (_first_zero), non-finite a by the quadratures' NonFinite
        g = distinct_sorted(np.concatenate([
            np.logspace(-15, -3, 97), np.linspace(0.0, 4.0, 2001)[1:],
            4.0 * np.logspace(0, 300, 3001)]))
        g = g[np.abs(v1) + c * g <= BIG]
        vs = v1 + e * c * g
        av = c3.A(vs)
        s1 = np.sign(c3.a_v1)
        bad = ~np.isfinite(av)
        stop = (np.sign(av) != s1) | bad
        self.kind = "inf"
        self.v_end = e * math.inf
        # the first root (or touch) of a decided exactly, not by the samples: two roots 1e-6 apart
        # between samples (a = (v − 3 − 1e-6)(v − 3 − 2e-6) from v1 = 0) were passed through (issue 28)
        g_hi = float(g[int(np.argmax(stop))]) if stop.any() else (float(g[-1]) if g.size else 0.0)
        gz = _first_zero(c3.A, v1, e, c, g_hi) if g_hi > 0 else None
        if gz is not None:
            k = int(np.searchsorted(g, gz))
            self.v_end = v1 + e * c * gz
            self._end_kind(c3, av, k)
            vs, av = vs[:k], av[:k]
        elif stop.any():
            k = int(np.argmax(stop))
            lo = float(vs[k - 1]) if k > 0 else v1
            alo = float(av[k - 1]) if k > 0 else c3.a_v1
            hi = float(vs[k])
            if bad[k]:
                # bisect to the edge of the domain where a is finite
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    if mid in (lo, hi):
                        break
                    am = c3.a1(mid)
                    if math.isfinite(am) and np.sign(am) == s1:
                        lo = mid
                    else:
                        hi = mid
                self.v_end = hi
            elif av[k] == 0:
                self.v_end = hi
            else:
                self.v_end = root_in_bracket(c3.a1, lo, hi, alo, float(av[k]))
            self._end_kind(c3, av, k)
            vs, av = vs[:k], av[:k]
        # a double zero (a touches 0 without a sign change) before the end
        aa = np.abs(av)
        if aa.size >= 3:
            cand = np.nonzero((aa[1:-1] <= aa[:-2]) & (aa[1:-1] <= aa[2:])
                              & (aa[1:-1] < 1e-3 * np.maximum(aa[:-2], aa[2:])))[0] + 1
            for k in cand.tolist():
                from dyncli.rootfind import minimize_bounded

                lo, hi = sorted((float(vs[k - 1]), float(vs[k + 1])))
                x, fx = minimize_bounded(lambda x: abs(c3.a1(x)), lo, hi, 1e-14 * max(abs(lo), abs(hi), 1e-300))
                if abs(fx) <= 1e-12 * max(abs(c3.a_v1), float(aa.max())):
                    self.v_end, self.kind = x, "zero"
                    break

    def _end_kind(self, c3, av, k: int) -> None:
        """A terminal velocity ("zero") or a singularity of a ("pole") at v_end."""
        a_end = c3.a1(self.v_end)
        amax = float(np.max(np.abs(av[:k]))) if k > 0 else abs(c3.a_v1)
        amax = max(amax, abs(c3.a_v1))
        self.kind = "zero" if (math.isfinite(a_end) and (abs(a_end) <= 1e-6 * amax
                                                         or _grows_away(c3.a1, self.v_end, a_end))) else "pole"

    # -- parametrisation ---------------------------------------------------
    def v_of(self, u):
        if self.kind == "inf":
            return self.v1 + self.e * self.c * np.expm1(u)
        # v* - D0 e^-u near v* (u large); v1 - D0 expm1(-u) near v1, where the first form
        # cancels catastrophically when |v*| >> |v - v1| (v* = -3e76 for k = 1e-152)
        u = np.asarray(u, dtype=float)
        em = np.exp(-u)
        out = np.asarray(self.v_end - self.D0 * em, dtype=float)
        near = em >= 0.5
        if near.any():
            if out.ndim == 0:
                return np.float64(self.v1 - self.D0 * np.expm1(-u))
            out[near] = self.v1 - self.D0 * np.expm1(-u[near])
        return out

    def dvdu(self, u):
        if self.kind == "inf":
            return self.e * self.c * np.exp(u)
        return self.D0 * np.exp(-u)

    def u_of(self, v: float) -> float:
        if self.kind == "inf":
            return math.log1p(self.e * (v - self.v1) / self.c)
        r = (v - self.v1) / self.D0
        if abs(r) < 0.5:
            return -math.log1p(-r)          # near v1 (no cancellation in v* - v)
        return math.log(self.D0 / (self.v_end - v))

    def _f(self, x, j):
        """j even: dt/du, j odd: v dt/du."""
        v = self.v_of(x)
        w = self.dvdu(x) / self.c3.A(v)
        return np.where(j % 2 == 0, w, v * w)

    def integ(self, ulo, uhi):
        """(dt, ds, err_t, err_s) arrays over the cells [ulo, uhi]."""
        ulo = np.atleast_1d(ulo)
        uhi = np.atleast_1d(uhi)
        lo = np.repeat(ulo, 2)
        w = np.repeat(uhi - ulo, 2)
        rtol = np.full(lo.shape, self.c3.qr)
        if self.kind != "inf":
            # relative rounding noise of a near v* is ~ eps |v*| / |v* - v|; integrating
            # to that level moves the state by ~ eps |v*| only (see module docstring)
            d = abs(self.D0) * np.exp(-np.maximum(lo, lo + w))
            rtol = np.maximum(rtol, 64 * EPS * max(abs(self.v_end), abs(self.D0)) / np.maximum(d, 1e-300))
        self.c3.work.charge(QUAD)
        vals, errs, conv = integrate(self._f, lo, w, np.minimum(rtol, 0.5), 0.0)
        self.c3.check(conv)
        return vals[0::2], vals[1::2], errs[0::2], errs[1::2]

    def _build_grid(self) -> None:
        if self.kind == "inf":
            room = BIG - abs(self.v1)      # |v1| beyond the blow-up threshold already: no room
            ratio = room / self.c if room > 0 else 0.0
            # room / c overflows for a tiny scale c (v1 ~ 1e-299): log(room) - log(c) then
            umax = math.log1p(ratio) if math.isfinite(ratio) else math.log(room) - math.log(self.c)
        else:
            self.D0 = self.v_end - self.v1
            dmin = max(8 * EPS * abs(self.v_end), 1e-290)
            # D0 = 0 (v1 already at v* to the last bit, e.g. v1 = 1e-308 with v* = 0): no room
            umax = max(math.log(max(abs(self.D0) / dmin, 1.0)), 1e-3)
        base = [0.0, 1 / 64, 1 / 16, 1 / 8, 1 / 4, 1 / 2]
        # quadrature panels in u (a starting table the adaptive quadrature refines; no decision)
        grid = distinct_sorted(np.concatenate([base, np.arange(1.0, umax, 1.0), [umax]]))
        grid = grid[grid <= umax]
        # the turning point of s (v = 0) on this branch is a grid node
        e = self.e
        if self.v1 != 0 and -self.v1 * e > 0 and (self.kind == "inf" or self.v_end * e > 0):
            u0 = self.u_of(0.0)
            if 0 < u0 < umax:
                grid = distinct_sorted(np.concatenate([grid, [u0]]))
        while True:
            try:
                dt, ds, et, es = self.integ(grid[:-1], grid[1:])
                break
            except NonFinite as exc:
                keep = grid[grid < exc.x]
                if keep.size >= 2:
                    grid = keep
                elif exc.x > 1e-12:
                    grid = np.array([0.0, 0.5 * exc.x])
                else:
                    grid = np.array([0.0])
                    dt = ds = et = es = np.zeros(0)
                    break
        self.u = grid
        self.tau = np.concatenate([[0.0], np.cumsum(dt)])
        self.ds = np.concatenate([[0.0], np.cumsum(ds)])
        self.etau = np.concatenate([[0.0], np.cumsum(et)])
        self.eds = np.concatenate([[0.0], np.cumsum(es)])
        # finite time to reach v*?  local exponent from dt/du near the end
        self.finite_time = False
        self.T_end = math.inf
        if self.kind == "zero" and self.u[-1] > 4:
            u2 = float(self.u[-1])
            w2 = float(self._f(np.array([u2]), np.array([0]))[0])
            w1 = float(self._f(np.array([u2 - 2.0]), np.array([0]))[0])
            if w1 != 0 and w2 / w1 >= 0:
                pm1 = math.log(max(w2 / w1, 1e-300)) / 2.0
                if pm1 < -0.1:
                    self.finite_time = True
                    self.T_end = float(self.tau[-1]) + w2 / -pm1
        elif self.kind in ("pole", "inf"):
            self.T_end = float(self.tau[-1])

    def at(self, u: float):
        """(tau, s - s1, v, (err_tau, err_s)) at parameter u."""
        k = int(np.searchsorted(self.u, u, side="right")) - 1
        k = min(max(k, 0), len(self.u) - 1)
        tau, ds = float(self.tau[k]), float(self.ds[k])
        et_, es_ = float(self.etau[k]), float(self.eds[k])
        if u != self.u[k]:
            dt, dds, et, es = self.integ(float(self.u[k]), u)
            tau += float(dt[0])
            ds += float(dds[0])
            et_ += float(et[0])
            es_ += float(es[0])
        return tau, ds, float(self.v_of(np.float64(u))), (et_, es_)


def _grows_away(a1, v_end: float, a_end: float) -> bool:
    """|a| grows away from v_end (a zero: v1 was within rounding of it, so
    every |a| seen was tiny) rather than falls (a pole)."""
    h = 2.0 ** -40 * max(abs(v_end), 1e-300)
    side = [a1(v_end - h), a1(v_end + h)]
    return all(math.isfinite(x) and abs(x) > abs(a_end) for x in side)

