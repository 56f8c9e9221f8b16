"""Case 4, a = a(s): the scan from s1 in one direction (6.14, 6.15) — the cells of v^2, where
the body stops (turning point, asymptotic equilibrium, singularity of a, or |s| -> infinity) and the
nodes that become exact references of v^2.

:class:`Scan` is a collaborator of the case's motion (:class:`.case4._Case4`): it reads the motion
only through the interface :class:`Motion` declares and hands back what it found as a
:class:`Swept` (the motion keeps the cells, the energy's references and the scale of a).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from dyncli.rootfind import distinct_sorted, root_in_bracket
from dyncli.topics.rectilinear._quad import NonFinite, integrate
from dyncli.topics.rectilinear.case4_legs import End
from dyncli.topics.rectilinear.constants import BIG, EPS
from dyncli.topics.rectilinear.enclose import hidden, safe_enclose


class Motion(Protocol):
    """What the scan reads of a case-4 motion: a on arrays (``A``, counted by the work meter) and
    at one position (``a1``), the start ``s1``, the scan's length scale ``scale`` and the smallest
    length of the problem ``scale_min``, the quadratures' rtol ``qr`` and ``irs`` (a and da/ds as
    expression IR, for the interval enclosures of :mod:`.enclose`; None where there are none)."""

    s1: float
    scale: float
    scale_min: float
    qr: float
    irs: tuple

    def A(self, s) -> Any: ...
    def a1(self, s: float) -> float: ...


@dataclass(frozen=True)
class Swept:
    """What the scan from s1 in one direction found: where the body stops (``end``); the nodes of
    the scan up to there with v² and a at them (``s``, ``v2``, ``a``: the cells of v², the stop
    appended); the nodes whose v² is well above its rounding (``ref_s``, ``ref_v2``: exact
    references of the energy; the stop itself, v² = 0 at a turning point or an asymptotic
    equilibrium, is not among them); and the largest |a| over the first half of the nodes
    (``amax``, None when a is finite at none of them)."""

    end: End
    s: Any
    v2: Any
    a: Any
    ref_s: Any
    ref_v2: Any
    amax: float | None


class Scan:
    """The scan of one case-4 motion ``m`` (its :class:`Motion`) from s1 in a direction: :meth:`run`."""

    def __init__(self, m: Motion):
        self.m = m

    # -- where does the body go from s1 in direction e? ------------------------
    def run(self, e: int, v2start: float) -> Swept:
        """Scan from s1 in direction ``e`` (+1/-1) with v² = ``v2start`` at s1."""
        ss = self._scan_nodes(e)
        ss, vals, conv, end = self._scan_cells(ss, e)
        ss, vals, end, overflow = self._scan_cut(ss, vals, conv, v2start, end)
        v2 = v2start + 2.0 * np.concatenate([[0.0], np.cumsum(vals)])
        av = self.m.A(ss)
        fin = np.isfinite(av)
        amax = float(np.max(np.abs(av[fin][:len(av) // 2 + 1]))) if fin.any() else None
        # rounding carried by v^2 at each node: eps times the sum of |cell integrals| so far
        cumabs = np.maximum(v2start + 2.0 * np.concatenate([[0.0], np.cumsum(np.abs(vals))]), 1e-300)
        found = self._scan_stop(e, ss, v2, av, cumabs)
        if found is not None:
            end = found
            keep = (ss - end.pos) * e < 0
            ss, v2, av = ss[keep], v2[keep], av[keep]
            ss = np.append(ss, end.pos)
            v2 = np.append(v2, 0.0 if end.kind in ("turn", "asym") else float(v2[-1]))
            av = np.append(av, self.m.a1(end.pos))
        if end is None:
            # (a finite position: the last node before v^2 overflows — nothing beyond it is tracked)
            end = End("inf", float(ss[-1]) if overflow else e * math.inf)
        # scan nodes where v^2 is well above its rounding error become references too
        # (v^2 at a node carries the rounding of every cell before it)
        cumabs = cumabs[:len(v2)]
        good = v2 >= 1e5 * EPS * cumabs
        good[0] = False
        if end.kind != "inf" and good.size:
            good[-1] = False        # turning point (added exactly by the motion) or singular cut
        return Swept(end, ss, v2, av, ss[good], v2[good], amax)

    def _scan_nodes(self, e: int):
        """The scan positions s1 + e c g, |s| <= BIG (g: geometric and linear offsets)."""
        s1, c = self.m.s1, self.m.scale
        # cells of v² (a starting table: turning points and dips are decided inside the cells by
        # root searches, and barriers between the nodes by the enclosures of a, _hidden_dips)
        g = distinct_sorted(np.concatenate([
            np.logspace(-15, -3, 97), np.linspace(0.0, 4.0, 2001)[1:], 4.0 * np.logspace(0, 300, 3001)]))
        cm = self.m.scale_min
        if cm < 1e-3 * c:
            # offsets below the scan scale down to the smallest length of the problem, 8 per decade
            dec = math.log10(c) - math.log10(cm)        # (c / cm overflows for c ~ 1e99, cm ~ 1e-290)
            g = distinct_sorted(np.concatenate([g, (cm / c) * np.logspace(-15, -3, 49),
                                          (cm / c) * np.logspace(-3, dec, int(8 * (dec + 3)) + 1)]))
        g = np.concatenate([[0.0], g[abs(s1) + c * g <= BIG]])
        return s1 + e * c * g

    def _scan_cells(self, ss, e: int):
        """The integral of a over each cell: (ss cut before a non-finite a, vals, conv, End or None)."""
        end = None
        while True:
            try:
                vals, errs, conv = integrate(lambda x, j: self.m.A(x), ss[:-1], np.diff(ss), self.m.qr, 0.0)
                break
            except NonFinite as exc:
                k = int(np.searchsorted(ss * e, exc.x * e, side="right"))
                ss = ss[:max(k, 2)]
                end = End("sing", float(ss[-1]))
                if k <= 2:
                    vals = np.zeros(len(ss) - 1)
                    conv = np.ones(len(ss) - 1, dtype=bool)
                    break
        return ss, vals, conv, end

    def _scan_cut(self, ss, vals, conv, v2start: float, end):
        """The cells cut where v^2 overflows or a is singular: (ss, vals, end, overflow)."""
        overflow = False
        with np.errstate(over="ignore", invalid="ignore"):
            v2c = v2start + 2.0 * np.concatenate([[0.0], np.cumsum(vals)])
        if not np.all(np.isfinite(v2c)):
            k = int(np.argmax(~np.isfinite(v2c)))
            if v2c[k] == math.inf and k >= 2 and np.all(conv[:k - 1]):
                # v^2 overflows the doubles (|v| > 1e154, e.g. a = s^3 from s1 = 1 near s ~ 1e77): a cap
                # like |s| = BIG, not a singularity of a — the scan (and the references) stop at the
                # last finite v^2; the leg beyond it has dt = ds/|v| = 0 in double precision
                ss, vals, conv = ss[:k], vals[:k - 1], conv[:k - 1]
                overflow, end = True, None      # (an overflow of a itself further out is never reached)
        bad = np.nonzero(~conv)[0]
        if bad.size:
            # a singular (non-integrable) point inside cell k — unless the body turns before it
            k = int(bad[0])
            v2k = v2start + 2.0 * np.concatenate([[0.0], np.cumsum(vals[:k])])
            if np.any(v2k[1:] <= 0):
                ss, vals = ss[:k + 1], vals[:k]
            else:
                ss, vals, end = self._cut_singular(ss, vals, k)
        return ss, vals, end, overflow

    def _scan_stop(self, e: int, ss, v2, av, cumabs):
        """Where v^2 first reaches 0 (a turning point or an asymptotic equilibrium), or None."""
        tolsep_k = 1e4 * EPS * cumabs
        n = len(ss)
        # first cell where v^2 becomes <= 0, and cells where v^2 has a small interior minimum
        neg = np.nonzero(v2[1:] <= 0)[0]
        first_neg = int(neg[0]) if neg.size else n
        # every local minimum of v² between nodes (a from −e to +e) is examined (issue #28: a narrow
        # barrier's dip below 0 is not announced by v² at the nodes; no threshold on them)
        dips = np.nonzero((av[:-1] * e < 0) & (av[1:] * e > 0))[0]
        # and where a barrier hides between two nodes (a from −e to +e and back, a at the nodes of
        # one sign or underflowing to 0), located by the enclosures of a (.enclose)
        inner = self._hidden_dips(e, ss, v2, av, first_neg)
        for k in sorted(set([first_neg] + [int(d) for d in dips if d < first_neg] + list(inner))):
            if k >= n - 1:
                break
            lo, hi = float(ss[k]), float(ss[k + 1])
            v2lo = float(v2[k])
            tolsep = float(tolsep_k[k + 1])

            def E(s, lo=lo, v2lo=v2lo):
                return v2lo + 2.0 * float(integrate(lambda x, j: self.m.A(x), [lo], [s - lo], self.m.qr, 0.0)[0][0])

            if k == first_neg:
                if v2[k + 1] == 0:
                    sT = hi
                else:
                    sT = root_in_bracket(E, lo, hi, v2lo, float(v2[k + 1]))
                # a dip inside the cell before the crossing is a turning point as well
                return self._classify(sT, e, tolsep)
            bl, bh, al, ah = inner.get(k, (lo, hi, float(av[k]), float(av[k + 1])))
            sm = root_in_bracket(self.m.a1, bl, bh, al, ah)
            v2m = E(sm)
            if v2m < -tolsep:
                return self._classify(root_in_bracket(E, lo, sm, v2lo, v2m), e, tolsep)
            if v2m <= tolsep:
                return End("asym", sm)
        return None

    def _hidden_dips(self, e: int, ss, v2, av, upto: int) -> dict:
        """{cell k: (s_lo, s_hi, a there)}: a bracket where a goes from −e to +e inside a cell whose
        nodes do not show it, in the cells before ``upto`` where the enclosure of a allows v² to reach
        0 (2 |Δs| max(−a e) ≥ v² at the cell's start); the points examined: the cell's ends and 9
        samples of each cell where its enclosure exceeds its samples (.enclose.hidden)."""
        ir, dir_ = self.m.irs
        out: dict[int, tuple] = {}
        if ir is None:
            return out
        for k in range(min(upto, len(ss) - 1)):
            lo, hi = float(ss[k]), float(ss[k + 1])
            if av[k] * e < 0 < av[k + 1] * e:
                continue                                # a dip the nodes show
            m, M = safe_enclose(ir, min(lo, hi), max(lo, hi), "s")
            worst = -m if e > 0 else M                  # the largest −a e the cell may hold
            if not 2 * max(worst, 0.0) * abs(hi - lo) >= v2[k]:
                continue
            leaves, _ = hidden(ir, dir_, self.m.A, min(lo, hi), max(lo, hi), cells=1, budget=200, var="s")
            k9 = np.linspace(0.0, 1.0, 9)
            pts = distinct_sorted(np.concatenate([[lo, hi]] + [u + (v - u) * k9 for u, v in leaves or [(lo, hi)]]))
            pts = pts if e > 0 else pts[::-1]
            y = self.m.A(pts) * e
            j = np.nonzero((y[:-1] < 0) & (y[1:] > 0))[0]
            if j.size:
                i = int(j[0])
                out[k] = (float(pts[i]), float(pts[i + 1]), float(y[i] * e), float(y[i + 1] * e))
        return out

    def _cut_singular(self, ss, vals, k):
        lo, hi = float(ss[k]), float(ss[k + 1])
        base = float(ss[k])
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if mid in (lo, hi):
                break
            try:
                _, _, cv = integrate(lambda x, j: self.m.A(x), [base], [mid - base], self.m.qr, 0.0)
                ok = bool(cv[0])
            except NonFinite:
                ok = False
            if ok:
                lo = mid
            else:
                hi = mid
        last = integrate(lambda x, j: self.m.A(x), [base], [lo - base], self.m.qr, 0.0)[0]
        return np.concatenate([ss[:k + 1], [lo]]), np.concatenate([vals[:k], last]), End("sing", lo)

    def _classify(self, sT: float, e: int, tolsep: float) -> End:
        aT = self.m.a1(sT)
        if aT * e < 0:
            return End("turn", sT)
        return End("asym", sT)
