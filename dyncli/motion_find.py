"""The ``find`` queries (problem files §11) answered for a motion known by its reported state.

Topic-agnostic.  A type that reports a motion gives :func:`answer_find` its ``state(t)`` (the
results it reports at an ``at`` time, as single values: a nested mapping whose leaves are
numbers, vectors as lists), the start and end of the motion, the ``breaks`` between which the
results are smooth (the pieces of a closed form, the steps of an ODE: see :mod:`dyncli.queries`
for how they are searched), the accuracy of the values (``rtol``) and, where known, which result
is the rate of which (``rates``: ``{"x": "v"}`` makes ``v.1`` the rate of ``x.1``; a callable
``(t, rest of the path) -> rate or None`` gives a rate the type does not report), so that a
turning point is a root of the rate (Brent), never a sampled peak.  The answers are the
:mod:`dyncli.queries` answers, each filled with the whole state at its time (``distance``
included when the type reports it).  :func:`resolved` does all this for a type whose solver
reports its motion at the times of ``at`` (declared by ``TypeSpec.motion``).

:func:`search_end` extends the motion to the end of a ``within`` window; :class:`Odometer`
is the ``distance`` result: ∫|v| dt over the breaks (Gauss–Legendre on each smooth piece), or
for one coordinate the sum of |Δs| between its turning points (:func:`turning_length`, exact to
rounding).

:func:`exact_breaks` cuts the pieces of a motion known as smooth functions of time between its
breaks (an ODE's steps) at the exact extremes of every result a query searches
(:func:`dyncli.rootfind.smooth_extremes`), so that the search takes each as monotone between
two cuts (``StateMotion(breaks_for=..., monotone=True)``) and no crossing inside a step is
stepped over.
"""

from __future__ import annotations

import math
from typing import Any, Callable, Iterable, Mapping, Sequence

from dyncli import cputime
from dyncli import queries as _q
from dyncli.errors import InputError, NumericalError

__all__ = ["StateMotion", "flatten", "answer_find", "search_end", "Odometer", "turning_length", "turns", "attach",
           "searched_paths", "exact_breaks", "series_values", "find_end", "check_resolved",
           "uniform_path_length"]


def flatten(node: Any, prefix: str = "") -> dict[str, float]:
    """{dotted path: number} of one instant (list items by their index from 0; booleans and
    text left out)."""
    out: dict[str, float] = {}
    if isinstance(node, float) or (isinstance(node, int) and not isinstance(node, bool)):
        if prefix:                                  # (numbers first: typing's Mapping check is slow)
            out[prefix[:-1]] = float(node)
    elif isinstance(node, (dict, Mapping)):
        for k, v in node.items():
            out.update(flatten(v, f"{prefix}{k}."))
    elif isinstance(node, (list, tuple)):
        for i, v in enumerate(node):
            out.update(flatten(v, f"{prefix}{i}."))
    return out


#: a ``find`` search stops once the solve has used this many times its CPU budget (its states are
#: solves; a search near its end is not cut short at the budget itself)
FIND_MARGIN = cputime.ADAPTIVE


class StateMotion:
    """A motion for :func:`dyncli.queries.answer` from ``state(t)`` (see the module's text)."""

    def __init__(self, state: Callable[[float], Mapping], t0: float, t_end: float,
                 breaks: Iterable[float] = (), rtol: float = 0.0, rates: Mapping[str, Any] | None = None,
                 batch: Callable[[list[float]], Sequence[Mapping]] | None = None, subdivide: int | None = None,
                 breaks_for: Callable[[str], list[float]] | None = None, monotone: bool = False):
        self.state, self.t0, self.t_end, self.rtol = state, float(t0), float(t_end), float(rtol)
        self.breaks_for = breaks_for                # a result's own breaks (its turning points), else None
        self.monotone = monotone                    # every result asked about monotone between its breaks
        self.subdivide = subdivide                  # 1 when the breaks are an ODE's steps
        self.period: float | None = None            # set when the motion repeats exactly (find's extremes)
        self.cuts_approximate = False               # breaks_for's cuts an interpolant's critical points (~1e-13)
        self.batch = batch                          # the states at many times in one run (optional)
        inner = sorted({float(b) for b in breaks if self.t0 < b < self.t_end})
        self.breaks = [self.t0] + inner + [self.t_end]
        self._rates = dict(rates or {})
        self._cache: dict[float, dict] = {}
        self._limit = 4096
        self._paths: list[str] | None = None

    def flat(self, t: float) -> dict[str, float]:
        got = self._cache.get(t)
        if got is None:
            if (limit := cputime.over(FIND_MARGIN)) is not None:   # (every state a solve: the budget bounds them)
                raise NumericalError(f"find: the search has used {FIND_MARGIN:g} × the solve's CPU budget of "
                                     f"{limit:g} s (accuracy.max_cpu) before its answers were decided: narrow it "
                                     "with within, or raise accuracy.max_cpu")
            if len(self._cache) > self._limit:      # bounded: a long search keeps only its recent instants
                self._cache.clear()
            got = self._cache[t] = flatten(self.state(float(t)))
        return got

    def clipped(self, t_end: float) -> "StateMotion":
        """The same motion from t0 to ``t_end`` (before its end), sharing the cache."""
        own = self.breaks_for
        w = StateMotion(self.state, self.t0, t_end, [b for b in self.breaks if b < t_end], self.rtol,
                        self._rates, self.batch, self.subdivide,
                        None if own is None else (lambda path: [b for b in own(path) if b < t_end] + [t_end]),
                        self.monotone)
        w._cache, w._limit, w.cuts_approximate = self._cache, self._limit, self.cuts_approximate
        return w

    def prefetch(self, upto: float | None = None) -> None:
        """The states at every sample of the search grid (up to ``upto``) in one ``batch`` call
        (when given)."""
        if self.batch is not None:
            T = [t for t in _q.sample_grid(self.breaks, self.t0, self.t_end, _q.subdivisions(self))
                 if t not in self._cache and (upto is None or t <= upto)]
            if not T:                               # (a batch of no times is no solve)
                return
            self._limit = 4096 + len(self._cache) + len(T)
            for t, st in zip(T, self.batch(T)):
                self._cache[t] = flatten(st)

    def paths(self) -> list[str]:
        if self._paths is None:
            self._paths = sorted(self.flat(self.t0))
        return self._paths

    def value(self, path: str, t: float) -> float:
        flat = self.flat(float(t))
        if path not in flat:
            raise KeyError(path)
        return flat[path]

    def rate(self, path: str, t: float) -> float | None:
        head, dot, rest = path.partition(".")
        d = self._rates.get(head)
        if d is None:
            return None
        if callable(d):                             # a rate the type knows but does not report
            got = d(float(t), rest)
            return None if got is None else float(got)
        return self.flat(float(t)).get(d + dot + rest)


def search_end(t_end: float, find: Any, constant: Callable[[Any], float]) -> float:
    """The end of the motion searched: ``t_end`` extended to a ``t`` query or a ``within``
    window that ends later (§11); malformed entries are left to the queries' own validation."""
    for q in find if isinstance(find, (list, tuple)) else ():
        if not isinstance(q, dict):
            continue
        w = q.get("within")
        raw = [w[1]] if isinstance(w, (list, tuple)) and len(w) == 2 else []
        raw += [q["t"]] if "t" in q else []
        for r in raw:
            try:
                v = float(constant(r))
            except (InputError, ValueError, TypeError):
                continue
            if math.isfinite(v):
                t_end = max(t_end, v)
    return t_end


def answer_find(raw: Any, motion: Any, constant: Callable[[Any], float], warn: Callable[[str], None] | None = None,
                full: Callable[[float], Mapping] | None = None, stopped: str | None = None,
                memo: Any = None) -> list[dict]:
    """One entry per query of ``raw`` (the problem's ``find`` list): ``{t, reached, at_end}`` and
    the whole state at ``t`` (``full(t)``, default ``motion.state``) when reached; a warning per
    query not reached (``stopped``: why the motion ends early, said in that warning).  ``memo``:
    the plain data ``constant`` depends on (the params as written), when given the parsed
    queries are remembered for equal ``raw`` and ``memo`` (:mod:`dyncli.docmemo`: the points of
    a sweep parse them once)."""
    if memo is None:
        qs = _q.parse_queries(raw, constant)
    else:
        from dyncli.docmemo import recall

        qs = recall("find", (raw, memo), lambda: _q.parse_queries(raw, constant))
    full = full or motion.state
    period = getattr(motion, "period", None)
    one = motion.clipped(motion.t0 + period) if period and motion.t_end - motion.t0 > period else None
    if any(isinstance(q, _q.Extreme) for q in qs) and hasattr(motion, "prefetch"):
        (one or motion).prefetch()                  # (a when query fetches as far as it searches)
    out, names = [], None
    # a periodic motion's extremes over the whole motion lie in its first period (the first of equal ones)
    notes: dict[int, str] = {}
    answers = [_q.answer([q], one)[0] if one is not None and isinstance(q, _q.Extreme) and q.within is None
               else _q.answer([q], motion, notes)[0] for q in qs]
    for k, ans in enumerate(answers):
        entry = dict(ans)
        if ans.get("reached") and ans.get("t") is not None:
            entry.update(full(ans["t"]))
            out.append(entry)
            continue
        names = list(full(motion.t0)) if names is None else names
        entry.update({n: None for n in names if n not in entry})     # every other entry null (§11)
        if warn is not None and k in notes:
            warn(f"find.{k}: not reached: {notes[k]}")
        elif warn is not None and isinstance(q := qs[k], _q.AtTime) and q.t < motion.t0:
            warn(f"find.{k}: t = {q.t:g} s is before the start of the motion (t = {motion.t0:g} s): "
                 "ask for a time from the start on")
        elif warn is not None:
            warn(f"find.{k}: not reached between t = {motion.t0:g} and t = {motion.t_end:.10g} s"
                 + (f" ({stopped})" if stopped else "; raise t_end to search further"))
        out.append(entry)
    return out



def searched_paths(find: Any) -> set[str] | None:
    """The result paths the searching queries (``when``, ``max``, ``min``) of ``find`` ask about;
    None when an entry is malformed (left to the queries' own validation)."""
    asked: set[str] = set()
    for q in find if isinstance(find, (list, tuple)) else ():
        if not isinstance(q, dict):
            return None
        if set(q) <= {"t"}:                             # a time query: no search
            continue
        when = q.get("when")
        paths = list(when) if isinstance(when, dict) else [q[k] for k in ("max", "min") if k in q]
        if not paths or not all(isinstance(x, str) for x in paths):
            return None
        asked.update(x.strip() for x in paths)
    return asked


def exact_breaks(find: Any, breaks: Sequence[float], values: Callable[[list[str], Any], Any],
                 known: Callable[[str], list[float] | None] | None = None,
                 warn: Callable[[str], None] | None = None, budget: int = 200_000
                 ) -> Callable[[str], list[float]] | None:
    """``breaks_for(path)`` for :class:`StateMotion` with ``monotone=True``: the ``breaks`` (between
    which the motion is smooth: an ODE's steps, its phase ends) with every extreme inside them of
    each result the queries of ``find`` search added — decided exactly, never by samples:
    ``known(path)``, the extremes the route decides itself (a coordinate of its steps'
    polynomials, :func:`dyncli.rootfind.polynomial_extremes`; None: not known), else the
    critical points of the result along the motion (:func:`dyncli.rootfind.smooth_extremes` on
    ``values(paths, ts)``: the results at the paths, an array (len(paths), len(ts)), at an array
    of times; None or KeyError for a path the motion does not report).  None when no query
    searches, a path is unknown, or a result is not resolved (not finite, not smooth to rounding
    in a step, or more than ``budget`` evaluations): the search then reads the steps' ends and
    ``warn`` says so (never silently)."""
    from dyncli.rootfind import smooth_extremes

    asked = searched_paths(find)
    B = sorted({float(b) for b in breaks})
    if not asked or len(B) < 2:
        return None
    own: dict[str, list[float]] = {}
    rest = []
    for path in sorted(asked):
        got = known(path) if known is not None else None
        if got is None:
            rest.append(path)
        else:
            own[path] = [float(t) for t in got]
    if rest:
        try:
            probe = values(rest, [B[0]])
        except KeyError:
            probe = None
        cuts, ok = smooth_extremes(lambda ts: values(rest, ts), B, budget=budget) if probe is not None else ([], False)
        if not ok:
            if warn is not None:
                warn(f"find: {', '.join(rest)} could not be followed as a smooth function of each step (a kink, a "
                     "value that is not finite, or a result not reported along the motion): its crossings are "
                     "searched between the steps' ends, where a level crossed and crossed back inside one step "
                     "is not seen")
            return None
        own.update(zip(rest, cuts))
    t0, t_end = B[0], B[-1]
    table = {path: sorted(set(B).union(t for t in cut if t0 < t < t_end)) for path, cut in own.items()}
    return lambda path: table[path] if path in table else B


def series_values(states: Callable[[list[float]], Mapping[str, Any]]) -> Callable[[list[str], Any], Any]:
    """``values(paths, ts)`` for :func:`exact_breaks` from ``states(ts)``, the results at many times
    as ``{name: one value per time}`` (a number or a vector per time): ``x.1`` is component 1 of
    the vectors of ``x``; KeyError for a path that is not such a number."""
    import numpy as np

    def values(paths: list[str], ts: Any):
        times = [float(t) for t in np.asarray(ts, dtype=float).reshape(-1)]
        got = states(times)
        rows = []
        for path in paths:
            head, _, rest = path.partition(".")
            col = got.get(head)
            if not isinstance(col, list) or len(col) != len(times):
                raise KeyError(path)
            try:
                arr = np.asarray(col, dtype=float)
            except (TypeError, ValueError):
                raise KeyError(path) from None
            if rest:
                if arr.ndim != 2 or not rest.isdigit() or int(rest) >= arr.shape[1]:
                    raise KeyError(path)
                arr = arr[:, int(rest)]
            elif arr.ndim != 1:
                raise KeyError(path)
            rows.append(arr)
        return np.stack(rows)
    return values

class Odometer:
    """∫ |v| dt from the first break: Gauss–Legendre with ``nodes`` points on every piece between
    consecutive breaks (the speed is smooth inside an ODE step or a closed-form piece: the rule
    is exact for polynomials of degree 2·nodes − 1), each piece first cut at its stops (where |v|
    has a kink) and then halved until its rule is resolved to ``rtol`` (:meth:`_unresolved`;
    ``resolved`` False when the budget ends that first: :func:`check_resolved` warns),
    accumulated once; ``speeds(ts)`` gives |v|
    at many times in one call — one column per point when it returns a 2-D array (len(ts), k).
    ``at(times)``: the distance at each time (≥ the first break), a list per point for k columns.
    ``arrays``: ``speeds`` takes a numpy array of times (no list of 1e6 floats made and read back).
    ``times``: the times ``at`` will be asked first (the reported ones), when few: the nodes of
    their partial pieces are evaluated with the pieces' own, in one call of ``speeds`` (the same
    values: every operation is node by node, each piece's sum its own)."""

    def __init__(self, speeds: Callable[[list[float]], Any], breaks: Iterable[float], nodes: int = 10,
                 arrays: bool = False, times: Sequence[float] | None = None, rtol: float = 1e-10):
        import numpy as np

        self.speeds, self.np, self.arrays, self.rtol = speeds, np, arrays, float(rtol)
        self.x, self.w = _leggauss(nodes)
        self.pts = np.array(sorted({float(b) for b in breaks}))
        self._early: tuple | None = None
        a, b = self.pts[:-1], self.pts[1:]
        self.budget = max(RESOLVE_NODES, 8 * a.size * self.x.size)   # nodes for the stops and the halvings
        if times is not None and 0 < len(times) <= EARLY:
            t = np.asarray([float(x) for x in times], dtype=float)
            k, lo, inside = self._where(t)
            S = self._nodes(np.concatenate([a, lo[inside]]), np.concatenate([b, t[inside]]))
            S, partial = S[:a.size], S[a.size:]
            self._early = (t, k, inside, self._sum(partial, lo[inside], t[inside]))
        else:
            S = self._nodes(a, b)
        self.resolved = True                        # (False once a refinement below runs out of budget)
        S = self._split_stops(S, None)              # |v| has a kink at each: a break of its own
        # each piece's speeds resolved by its rule: pieces whose Legendre series (from the node
        # values) has not decayed to rtol are halved until it has
        for _ in range(RESOLVE_HALVINGS + 1):
            # (a piece at the rounding of t cannot be halved: its error is at the rounding of
            # the distance, |v| × its width — a kink that close to a break is resolved enough)
            lo, hi = self.pts[:-1], self.pts[1:]
            bad = self._unresolved(S, rtol) & (hi - lo > 64 * EPS_T * np.maximum(np.abs(lo), 1.0))
            if not bad.any():
                break
            if S.shape[0] * self.x.size > self.budget or cputime.over(REFINE_SHARE) is not None:
                self.resolved = False               # (the caller says so)
                break
            a, b = lo[bad], hi[bad]
            S, kept = self._recut(S, (0.5 * (a + b)).tolist())
            S = self._split_stops(S, ~kept)         # (the halves may now hold a stop apart)
        else:
            self.resolved = False
        first = self._sum(S, self.pts[:-1], self.pts[1:])
        self.cum = np.concatenate([np.zeros((1,) + first.shape[1:]), np.cumsum(first, axis=0)])

    def _split_stops(self, S, only):
        """The pieces (``only``: a mask, default all) cut at their stops (:meth:`_stops`), and the
        pieces those cuts make cut at theirs in turn (a piece searched whole, unresolved, gives
        one stop of several), until none is left inside a piece, or the node budget is spent."""
        for _ in range(RESOLVE_HALVINGS):
            if cputime.over(REFINE_SHARE) is not None:
                self.resolved = False
                break
            stops = self._stops(S, only)
            if not stops or S.shape[0] * self.x.size > self.budget:
                break
            S, kept = self._recut(S, stops)
            only = ~kept
        return S

    def _recut(self, S, cuts):
        """The node speeds ``S`` of the pieces between ``self.pts`` after the ``cuts`` are added to
        the breaks: the pieces not cut keep their nodes' speeds (the same nodes, the same values),
        only the pieces cut are evaluated again (the partial pieces of ``times`` are then read
        afresh: their breaks have changed).  Returns (the speeds, which pieces were kept)."""
        np = self.np
        old = self.pts
        self.pts = np.array(sorted(set(old.tolist()) | set(cuts)))
        a, b = self.pts[:-1], self.pts[1:]
        j = np.minimum(np.searchsorted(old, a), old.size - 2)
        kept = (old[j] == a) & (old[j + 1] == b)
        S_new = np.empty((a.size,) + S.shape[1:])
        S_new[kept] = S[j[kept]]
        S_new[~kept] = self._nodes(a[~kept], b[~kept])
        self._early = None
        return S_new, kept

    def _unresolved(self, S, rtol: float):
        """Per piece: whether some column's speeds are not resolved by the rule to ``rtol`` — its
        error per unit time above rtol × (the piece's mean speed + the column's mean speed over
        the whole motion: a piece where the body nearly rests, whose speeds are mostly rounding,
        is held to the motion's scale, not to its own), or above the rounding of the largest speed
        of every column (the columns are one motion's points: a pinned centre whose speed is the
        rounding of the others' is resolved at that rounding).  The rule integrates exactly the
        Legendre series of degree < nodes interpolated at its nodes; what it misses are the coefficients beyond (its first error
        term is the degree 2·nodes one), foreseen from the series' last four: with c_{n−4} …
        c_{n−1} decaying by a ratio ρ per degree (the larger of the even and the odd terms'
        ratios; 1 where they do not decay), the error is about max(|c_{n−2}|, |c_{n−1}|) ρ^(n+1).
        A kink, a stop not split or a speed that varies faster than the piece's nodes follow
        decays slowly (ρ near 1): the piece is halved."""
        np = self.np
        S3 = S if S.ndim == 3 else S[:, :, None]
        c = np.abs(np.tensordot(S3, _legendre_tail(self.x.size), axes=([1], [0])))   # (pieces, k, 4)
        mean = np.abs(np.tensordot(S3, self.w, axes=([1], [0]))) * 0.5              # (pieces, k)
        width = np.diff(self.pts)
        span = float(self.pts[-1] - self.pts[0])
        overall = (mean * width[:, None]).sum(axis=0) / span if span > 0 else np.zeros(S3.shape[2])
        top = np.max(np.abs(S3), axis=(0, 1)) if S3.size else np.zeros(S3.shape[2])
        with np.errstate(invalid="ignore", divide="ignore"):
            rho2 = np.maximum(c[..., 2] / c[..., 0], c[..., 3] / c[..., 1])       # ρ², from both parities
            rho = np.sqrt(np.where(np.isfinite(rho2) & (rho2 < 1.0), rho2, 1.0))
            err = np.maximum(c[..., 2], c[..., 3]) * rho ** (self.x.size + 1)
            floor = 64 * EPS_T * np.maximum(top, float(top.max(initial=0.0)))    # the rounding of the largest
            bad = ~(err <= rtol * (mean + overall[None, :]) + floor[None, :])
        return bad.any(axis=1)

    def _where(self, t):
        """(the piece of each time, its start, whether the time is past it: a partial piece)."""
        k = self.np.clip(self.np.searchsorted(self.pts, t, side="right") - 1, 0, len(self.pts) - 1)
        lo = self.pts[k]
        return k, lo, t > lo

    def _nodes(self, a, b):
        """The speeds at the Gauss–Legendre nodes of each piece [a, b]: (pieces, nodes[, k])."""
        np = self.np
        T = (0.5 * (a + b))[:, None] + (0.5 * (b - a))[:, None] * self.x[None, :]
        S = np.asarray(self.speeds(T.ravel() if self.arrays else T.ravel().tolist()), dtype=float)
        return S.reshape(T.shape + S.shape[1:])

    def _sum(self, S, a, b):
        half = (0.5 * (b - a)).reshape((-1,) + (1,) * (S.ndim - 2))
        return half * self.np.tensordot(S, self.w, axes=([1], [0]))

    def _pieces(self, a, b):
        return self._sum(self._nodes(a, b), a, b)

    def _stops(self, S, only=None) -> list[float]:
        """Where a speed comes (nearly) to rest inside a piece — a turning point, where |v| has a
        kink the rule cannot follow (its error would be ~|a| h²): the time of the least speed on
        each piece whose node speeds dip below a quarter of their largest.  |v|² is smooth there
        (a polynomial on an ODE step), so its local minima — every one: two stops in one piece
        are two — are read off its Chebyshev interpolant on all those pieces at once
        (:func:`dyncli.rootfind.smooth_minima`: one call of ``speeds``, the derivative's roots); a
        piece whose interpolant is not resolved is searched on |v| by golden section
        (:func:`dyncli.rootfind.fminbound_many`: one call of ``speeds`` per iteration; the pieces
        its cut makes are searched again).  An error δ in a stop's place costs only ~|a| δ².  A
        least speed at the piece's end (a stop that is a break already, a body starting from
        rest) adds nothing.  ``only``: the pieces to look at (a mask), default all."""
        from dyncli.rootfind import fminbound_many, smooth_minima

        np = self.np
        S3 = S if S.ndim == 3 else S[:, :, None]
        dips = S3.min(axis=1) < 0.25 * S3.max(axis=1)
        dips &= S3.max(axis=1) > 64 * EPS_T * float(S3.max(initial=0.0))   # (not a point at rest: its
        if only is not None:                                                   # speeds the others' rounding)
            dips &= only[:, None]
        piece, col = np.nonzero(dips)
        if not piece.size:
            return []
        a, b = self.pts[piece], self.pts[piece + 1]

        def speed(u, k):
            ts = a[k] + u * (b[k] - a[k])
            got = np.asarray(self.speeds(ts if self.arrays else ts.tolist()), dtype=float)
            return got[np.arange(k.size), col[k]] if got.ndim > 1 else got

        xatol = 1e-12
        # |v|² in units of the piece's largest node speed (no underflow), its rounding that of the
        # column's largest speed anywhere (near a stop the speeds are mostly rounding: resolved there)
        top = S3.max(axis=1)[piece, col]
        noise = 2 * 64 * EPS_T * np.max(S3, axis=(0, 1))[col] / top
        minima, resolved = smooth_minima(lambda u, k: (speed(u, k) / top[k]) ** 2, piece.size, noise=noise)
        rest = np.flatnonzero(~resolved)            # not resolved (several turns, or rounding noise near a
        if rest.size:                               # stop): the least of |v| by golden section
            for k, u in zip(rest.tolist(), fminbound_many(lambda v, k: speed(v, rest[k]), rest.size, xatol).tolist()):
                minima[k] = np.array([u])
        k = np.repeat(np.arange(piece.size), [m.size for m in minima])
        u = np.concatenate(minima) if k.size else np.zeros(0)
        a, b = a[k], b[k]
        # a stop within √rtol/16 of the piece from an end is that end's (a kink δ from a break costs
        # ~|a| δ² of distance: rtol/256 of the piece's; cutting it off again would only make slivers)
        end = np.maximum(2 * (np.sqrt(np.finfo(float).eps) * u + xatol), math.sqrt(self.rtol) / 16)
        t = a + u * (b - a)
        keep = (u > end) & (u < 1.0 - end) & (a < t) & (t < b)
        return sorted(set(t[keep].tolist()))

    def at(self, times: Iterable[float]) -> list:
        np = self.np
        t = np.asarray([float(x) for x in times], dtype=float)
        if t.size == 0:
            return []
        early = self._early
        if early is not None and early[0].size == t.size and bool((early[0] == t).all()):
            k, inside = early[1], early[2]
            part = np.zeros_like(self.cum[k])
            part[inside] = early[3]
            return (self.cum[k] + part + 0.0).tolist()
        k, lo, inside = self._where(t)
        part = np.zeros_like(self.cum[k])
        if np.any(inside):
            a, b = lo[inside], t[inside]
            n = max(64, CHUNK // self.x.size // 64 * 64)        # the pieces a chunk of nodes holds
            part[inside] = (self._pieces(a, b) if a.size <= n else
                            np.concatenate([self._pieces(a[i:i + n], b[i:i + n]) for i in range(0, a.size, n)]))
        return (self.cum[k] + part + 0.0).tolist()


#: the halvings of a piece the odometer makes to resolve its speeds (a kink converges as h²: 20
#: levels take it from 1e-2 to below 1e-14 of the piece), and the node evaluations it may spend on
#: them (or 8 × its first pass's, when larger): beyond either, ``Odometer.resolved`` is False
RESOLVE_HALVINGS = 40
RESOLVE_NODES = 200_000
#: the odometer stops refining (and says so) once the solve has used this share of its CPU budget:
#: the distance is one result among many, never the reason a solve is refused (the adaptive work
#: that refuses does so at cputime.ADAPTIVE = 2 × the budget).  Half the budget made a solve of
#: 0.2 s warn now and then on a loaded machine (a test run on 2 CPUs), its whole budget does not
REFINE_SHARE = 1.0
EPS_T = 2.220446049250313e-16


def check_resolved(odo, warn: Callable[[str], None] | None) -> None:
    """``warn`` when the odometer ``odo`` (or the one it wraps) could not resolve every piece's
    speeds within its budget: its distance may then be off by more than rtol."""
    inner = getattr(odo, "one", odo)
    if warn is not None and not getattr(inner, "resolved", True):
        warn("distance: the speed could not be resolved on every piece within the quadrature's budget "
             f"({RESOLVE_HALVINGS} halvings, {RESOLVE_NODES:,} nodes, {REFINE_SHARE:g} of the solve's CPU budget; "
             "a speed with very many turning points, one that changes over a far shorter time than the "
             "motion, or rounding noise): the distance may be off by more than accuracy.rtol")


def _legendre_tail(nodes: int):
    """The matrix (nodes, 4) taking the speeds at the Gauss–Legendre nodes to the last four
    coefficients (degrees nodes − 4 … nodes − 1) of their Legendre series: c_m = (2m+1)/2 Σ w_j
    P_m(x_j) f(x_j), P_m by its three-term recurrence (no numpy.polynomial imported)."""
    got = _TAIL.get(nodes)
    if got is None:
        import numpy as np

        x, w = _leggauss(nodes)
        p0, p1 = np.ones_like(x), x.copy()
        P = [p0, p1]
        for m in range(1, nodes - 1):
            P.append(((2 * m + 1) * x * P[m] - m * P[m - 1]) / (m + 1))
        got = _TAIL[nodes] = np.stack([(2 * m + 1) / 2 * w * P[m] for m in range(nodes - 4, nodes)], axis=1)
    return got


_TAIL: dict = {}

#: the Gauss–Legendre nodes evaluated in one call of ``speeds`` by :meth:`Odometer.at`: the partial
#: pieces of 1e5 times are taken a chunk at a time (the same values: every operation is piece by
#: piece, and a chunk holds a multiple of 64 pieces, so the rows of the weights' matrix product
#: keep their place in the BLAS kernel's blocks), so their arrays are a few hundred kB reused, not
#: ~25 MB each freshly mapped (page faults)
CHUNK = 1 << 15
#: at most this many reported times have their partial pieces' nodes evaluated with the pieces'
EARLY = 256


def _leggauss(nodes: int):
    """Gauss–Legendre nodes and weights on [-1, 1], computed once per count (~0.1 ms each); the
    10 of the distance's rule from its table (no numpy.polynomial imported)."""
    got = _LEGGAUSS.get(nodes)
    if got is None:
        import numpy as np

        if nodes == 10:
            got = _LEGGAUSS[nodes] = (np.array(LEGGAUSS_10[0]), np.array(LEGGAUSS_10[1]))
        else:
            got = _LEGGAUSS[nodes] = np.polynomial.legendre.leggauss(nodes)
    return got


_LEGGAUSS: dict = {}

#: numpy.polynomial.legendre.leggauss(10), the doubles it gives: the nodes of the 10-point rule
#: (each the double nearest the exact root of P10) and its weights (within 8 units in the last
#: place of the exact ones); checked against mpmath in tests/foundation/test_odometer_stops.py
LEGGAUSS_10 = (
    (-0.9739065285171717, -0.8650633666889845, -0.6794095682990244, -0.4333953941292472, -0.14887433898163122,
     0.14887433898163122, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845, 0.9739065285171717),
    (0.06667134430868814, 0.1494513491505804, 0.219086362515982, 0.2692667193099965, 0.2955242247147528,
     0.2955242247147528, 0.2692667193099965, 0.219086362515982, 0.1494513491505804, 0.06667134430868814),
)


def uniform_path_length(v0: Sequence[float], a: Sequence[float], tau: float) -> float:
    """The length of the path ∫₀^τ |v0 + a s| ds of a point with the constant acceleration ``a``
    (plane vectors), τ ≥ 0, in closed form: with |v|² = |a|² (u² + k²), u = s + v0·a/|a|²,
    k = |v0 × a|/|a|², it is |a| [u √(u² + k²) + k² asinh(u/k)]/2 between u0 and u0 + τ, written
    without cancellation — the difference u1 s1 − u0 s0 as τ (s1 + u0 (u1 + u0)/(s1 + s0)), the
    asinh difference on one side of u = 0 as a log1p — so that a short piece of a fast motion, or
    a tiny acceleration, keeps its digits (a straight line, k = 0: the turning point's kink exact);
    in units of the largest of |v0| and |a| τ, so that no square underflows."""
    tau = float(tau)
    if not tau > 0.0:
        return 0.0
    # in units of the largest of the speeds |v0| and |a| τ over τ = 1 (no underflow of |a|²)
    vx, vy = float(v0[0]), float(v0[1])
    ax, ay = float(a[0]) * tau, float(a[1]) * tau
    c = max(abs(vx), abs(vy), abs(ax), abs(ay))
    if c == 0.0:
        return 0.0
    vx, vy, ax, ay = vx / c, vy / c, ax / c, ay / c
    A = ax * ax + ay * ay
    if A < 1e-20:       # |a| τ ≪ |v0| (= 1): |v| = |v0| + (v0·a) s/|v0| + O(A), its second order below rounding
        hv = math.hypot(vx, vy)
        return c * tau * (hv + 0.5 * (vx * ax + vy * ay) / hv)
    u0 = (vx * ax + vy * ay) / A
    u1 = u0 + 1.0
    k = abs(vx * ay - vy * ax) / A
    s0, s1 = math.hypot(u0, k), math.hypot(u1, k)
    first = s1 + u0 * (u1 + u0) / (s1 + s0)
    k2 = k * k
    second = 0.0
    if k2 > 0.0:
        if u0 >= 0.0:
            d = math.log1p((1.0 + (u1 + u0) / (s1 + s0)) / (u0 + s0))
        elif u1 <= 0.0:
            d = math.log1p((1.0 - (u1 + u0) / (s1 + s0)) / (s1 - u1))
        else:
            d = math.asinh(u1 / k) + math.asinh(-u0 / k)
        second = k2 * d if math.isfinite(d) else 0.0
    return c * tau * math.sqrt(A) * 0.5 * (first + second)


def turning_length(s: Callable[[float], float], turns: Iterable[float], times: Iterable[float],
                   t0: float = 0.0) -> list[float]:
    """The distance travelled since ``t0`` by one coordinate s(t) that is monotonic between the
    ``turns``: Σ|Δs| over the pieces, exact to the rounding of s (no quadrature); s is evaluated
    once at each turning point."""
    turns = sorted(float(t) for t in turns if t > t0)
    at_turn = [s(t) for t in turns]
    cum = [0.0]
    prev = s(t0)
    for v in at_turn:
        cum.append(cum[-1] + abs(v - prev))
        prev = v
    out = []
    import bisect

    for t in (float(x) for x in times):
        k = bisect.bisect_left(turns, t)            # turning points strictly before t
        last = at_turn[k - 1] if k else s(t0)
        out.append(cum[k] + abs(s(t) - last) + 0.0)
    return out


def _asked(q: Any) -> tuple[str, str | None]:
    """(the query as a short text, the result path it asks about or None)."""
    if not isinstance(q, dict):
        return str(q), None
    if "when" in q and isinstance(q["when"], dict) and len(q["when"]) == 1:
        (path, value), = q["when"].items()
        extra = "".join(f", {k} {q[k]}" for k in ("direction", "occurrence") if k in q)
        return f"{path} = {value}{extra}", str(path)
    for kind in ("max", "min"):
        if kind in q:
            w = q.get("within")
            return f"{kind} {q[kind]}" + (f" in [{w[0]}, {w[1]}]" if isinstance(w, (list, tuple)) and len(w) == 2
                                           else ""), str(q[kind])
    return ("t = " + str(q["t"])) if "t" in q else str(q), None


def attach(res: Any, raw: list, entries: list[dict]) -> None:
    """The answers as the result ``find`` and a table of them (the asked quantity's value at each
    answer; find.N in JSON holds the whole state)."""
    rows = []
    for i, (q, e) in enumerate(zip(raw, entries)):
        text, path = _asked(q)
        value = _value_of(e, path) if (path and e.get("reached")) else None
        rows.append([i, text, e.get("t"), value if value is not None else "—",
                     "yes" if e.get("at_end") else ("no" if e.get("at_end") is False else "—")])
    res.results["find"] = entries
    res.views.append(_table(rows))
    if "find" not in res.covered:
        res.covered.append("find")


def _value_of(entry: dict, path: str) -> float | None:
    """The number at ``path`` of one answer (a top-level number read directly, else through
    :func:`flatten`)."""
    got = entry.get(path)
    if isinstance(got, float) or (isinstance(got, int) and not isinstance(got, bool)):
        return float(got)
    return flatten(entry).get(path)


def _table(rows):
    from dyncli.result import Table

    return Table("find (§11): find.N holds the whole state at t", ["#", "query", "t [s]", "value", "at end"], rows)


def turns(rate: Callable[[float], float], breaks: Iterable[float], subdivide: int = _q.SUBDIVIDE) -> list[float]:
    """The roots of ``rate`` where it changes sign (Brent), over the :mod:`dyncli.queries` grid of
    the breaks: the turning points of the coordinate whose rate it is."""
    b = sorted(float(x) for x in breaks)
    T = _q.sample_grid(b, b[0], b[-1], subdivide)
    R = [rate(t) for t in T]
    out = []
    for k in range(len(T) - 1):
        if R[k] == 0.0 and k > 0:
            out.append(T[k])
        elif R[k] * R[k + 1] < 0:
            out.append(_q.root(rate, T[k], T[k + 1]))
    return out


def resolved(problem: Any, result: Any, solve: Callable[[Any], Any], rates: Mapping[str, str],
             fast: Iterable[str] = (), t0: float = 0.0) -> None:
    """The ``find`` answers of a type whose solver reports its motion at the times of ``at``: the
    motion at any times is the same solve with those times (one solve for a whole grid, and the
    route's own accuracy; its check solve off).  The results over time are the type's series
    over ``t``; ``rates`` names which is the rate of which; the search grid has at least
    :data:`PER_TURN` pieces per turn of the fastest of the ``fast`` rates (rad/s) seen on a first
    coarse grid (and per ``period`` when the type reports one), at most :data:`MAX_PIECES`; on an
    exact route (closed form, exact) each piece is cut at the exact extremes of every result
    searched (:func:`exact_breaks`: monotone between cuts, never sampled).  A
    route that knows its motion as one run's dense output leaves ``(breaks, states)`` in
    ``result.extra["dense_motion"]`` (:func:`_dense_find`: no solve again, every step cut at the
    exact extremes of each result searched)."""
    names = [n for s in result.series if s.index_name == "t" for n in s.names]
    acc = getattr(problem, "accuracy", None)
    base: dict[str, Any] = {"find": []}
    if acc is not None and getattr(acc, "estimate", False):
        base["accuracy"] = acc.model_copy(update={"estimate": False})

    def batch(ts) -> list[dict]:
        ts = [float(t) for t in ts]
        r = solve(problem.model_copy(update=dict(base, at=ts))).results
        return [{n: r[n][j] for n in names if isinstance(r.get(n), list) and len(r[n]) == len(ts)}
                for j in range(len(ts))]

    from dyncli.expr import constant, resolve_params

    params = resolve_params(getattr(problem, "params", {}) or {})
    const = lambda x: constant(x, params)            # noqa: E731
    t_end = find_end(problem, t0)
    rtol = float(getattr(acc, "rtol", 0.0) or 0.0) if not str(result.method).startswith(("closed", "exact")) else 0.0
    dense = getattr(result, "extra", {}).pop("dense_motion", None)
    if dense is not None and t_end > t0:
        _dense_find(problem, result, dense, names, rates, t0, t_end, rtol, const)
        return
    turns = _turns(result, batch, fast, t0, t_end) if t_end > t0 else 0.0
    if not turns * PER_TURN <= MAX_PIECES:      # (also a rate beyond a double)
        windowed = _windowed(problem, result, const, batch, solve, base, rates, fast, rtol, t0, t_end)
        _too_fast(problem, result, const, t_end, turns, batch, windowed)
    else:
        attach(result, problem.find, _search(problem, result, const, problem.find, batch, solve, base, rates, rtol,
                                             t0, t_end, turns))
    if rtol == 0.0:
        _phase_at_answers(problem, result, base, solve)


def _turns(result: Any, batch, fast: Iterable[str], lo: float, hi: float) -> float:
    """The turns of the motion over [lo, hi]: its fastest rate among ``fast`` on 65 probes (and
    its ``period``, when the type reports one)."""
    probe = [lo + (hi - lo) * k / 64 for k in range(65)]
    fastest = max([abs(float(x)) for st in batch(probe) for f in fast for x in _leaves(st.get(f))] + [0.0])
    turns = (hi - lo) * fastest / (2 * math.pi)
    period = result.results.get("period")
    if isinstance(period, (int, float)) and period and period > 0:
        turns = max(turns, (hi - lo) / period)
    return turns


def _search(problem: Any, result: Any, const, raw: list, batch, solve, base: dict, rates: Mapping[str, str],
            rtol: float, lo: float, hi: float, turns: float) -> list[dict]:
    """The answers of the queries ``raw`` over [lo, hi]: a grid of :data:`PER_TURN` pieces per turn
    (at least 64); on an exact route (``rtol`` 0) two per turn, each cut at its results' exact
    extremes (smooth_extremes halves a piece as it needs)."""
    if not hi > lo:
        breaks, own = [lo, lo], None
    elif rtol == 0.0:
        n = int(max(16, math.ceil(2 * turns)))
        breaks = [lo + (hi - lo) * k / n for k in range(n + 1)]
        own = exact_breaks(raw, breaks, series_values(
            lambda ts: solve(problem.model_copy(update=dict(base, at=[float(t) for t in ts]))).results),
            warn=result.warn)
    else:
        n = int(max(64, math.ceil(turns * PER_TURN)))
        breaks, own = [lo + (hi - lo) * k / n for k in range(n + 1)], None
    motion = StateMotion(lambda t: batch([t])[0], lo, hi, breaks, rtol=rtol, rates=rates, batch=batch,
                         subdivide=1 if own is not None else None, breaks_for=own, monotone=own is not None)
    return answer_find(raw, motion, const, result.warn)


def _phase_at_answers(problem: Any, result: Any, base: dict, solve: Callable[[Any], Any]) -> None:
    """An exact route's answers later than every time of ``at``: solved once more at their times,
    and the lost-phase warning of that solve (:func:`dyncli.phase.warn_lost`, left in its
    ``extra["phase_lost"]``), with its error_estimate, carried to the result."""
    at = [float(t) for t in getattr(problem, "at", []) or []]
    ts = [float(e["t"]) for e in result.results.get("find") or () if e.get("reached") and e.get("t") is not None]
    if not ts or max(ts) <= max(at, default=0.0):
        return
    r = solve(problem.model_copy(update=dict(base, at=ts)))
    lost = getattr(r, "extra", {}).get("phase_lost")
    if lost is not None:
        result.warn(lost)
        if result.error_estimate is not None and r.error_estimate is not None:
            result.error_estimate = max(result.error_estimate, r.error_estimate)


def find_end(problem: Any, t0: float = 0.0) -> float:
    """How far the ``find`` search of a type solved at the times of ``at`` runs: the largest of
    ``at`` and ``t_end``, extended to every ``within`` window and ``t`` query (§11)."""
    from dyncli.expr import constant, resolve_params

    params = resolve_params(getattr(problem, "params", {}) or {})
    at = [float(t) for t in getattr(problem, "at", []) or []]
    return search_end(max([t0] + at + [float(getattr(problem, "t_end", None) or t0)]), problem.find,
                      lambda x: constant(x, params))


def _dense_find(problem: Any, result: Any, dense: Any, names: list[str], rates: Mapping[str, str], t0: float,
                t_end: float, rtol: float, const) -> None:
    """The ``find`` answers on the route's own motion, ``dense = (breaks, states)`` or ``(breaks,
    states, more_rates)``: one run's steps (its ends ``breaks``, covering [t0, t_end]) and
    ``states(ts)``, the results at many times as ``{name: list}``, a smooth function of the step's
    polynomial between two breaks — each step cut at the exact extremes of every result searched
    (:func:`exact_breaks`); ``more_rates``: rates the type does not report (``{name: (t, rest of
    the path) -> rate}``, the equations of motion at the interpolated state), so that an
    extreme's time is polished as a root of its rate on the motion itself."""
    breaks, states = dense[0], dense[1]
    if len(dense) > 2 and dense[2]:
        rates = dict(rates, **dense[2])

    def batch(ts) -> list[dict]:
        ts = [float(t) for t in ts]
        r = states(ts)
        return [{n: r[n][j] for n in names if isinstance(r.get(n), list) and len(r[n]) == len(ts)}
                for j in range(len(ts))]

    B = sorted({t0, t_end} | {float(b) for b in breaks if t0 < b < t_end})
    own = exact_breaks(problem.find, B, series_values(states), warn=result.warn)
    motion = StateMotion(lambda t: batch([t])[0], t0, t_end, B, rtol=rtol, rates=rates, batch=batch,
                         subdivide=1 if own is not None else None, breaks_for=own, monotone=own is not None)
    motion.cuts_approximate = own is not None   # (an interpolant's critical points: a rate's root replaces them)
    attach(result, problem.find, answer_find(problem.find, motion, const, result.warn))


PER_TURN, MAX_PIECES = 8, 4_096


def _windowed(problem: Any, result: Any, const, batch, solve, base: dict, rates: Mapping[str, str],
              fast: Iterable[str], rtol: float, t0: float, t_end: float) -> dict[int, dict]:
    """The answers of the ``max``/``min`` queries with a ``within`` window, when the motion is too
    fast to search to t_end but the span of their windows is not: searched over that span alone
    (its own grid of :data:`PER_TURN` pieces per turn, cut at the exact extremes on an exact
    route) — the remedy the refusal names.  {query index: entry}; empty when the span is too
    fast too (or no such query)."""
    qs = _q.parse_queries(problem.find, const)
    wins = {q.index: q.within for q in qs if isinstance(q, _q.Extreme) and q.within is not None}
    if not wins:
        return {}
    lo = max(t0, min(w[0] for w in wins.values()))
    hi = min(t_end, max(w[1] for w in wins.values()))
    if not hi > lo:
        return {}
    turns = _turns(result, batch, fast, lo, hi)
    if not turns * PER_TURN <= MAX_PIECES:
        return {}
    # the other queries stand in as {t: lo}, so that each answer keeps its index (find.N)
    raw = [q if i in wins else {"t": lo} for i, q in enumerate(problem.find)]
    entries = _search(problem, result, const, raw, batch, solve, base, rates, rtol, lo, hi, turns)
    return {i: e for i, e in enumerate(entries) if i in wins}


def _too_fast(problem: Any, result: Any, const, t_end: float, turns: float, batch,
              windowed: Mapping[int, dict] | None = None) -> None:
    """The search would need more pieces than MAX_PIECES: the motion is too fast to search to
    t_end; ``{t}`` queries are answered, so are the ``max``/``min`` queries whose windows span
    little enough (``windowed``: :func:`_windowed`), the others not reached, and a warning says
    why."""
    qs = _q.parse_queries(problem.find, const)
    why = (f"the motion turns about {turns:.3g} times before t = {t_end:g} s, more than a search of "
           f"{MAX_PIECES // PER_TURN} turns resolves: narrow the window with within, or ask at times (at, {{t: T}})")
    entries, names = [], None
    for q in qs:
        if isinstance(q, _q.AtTime):
            entries.append(dict({"t": q.t, "reached": True, "at_end": None}, **batch([q.t])[0]))
        elif windowed and q.index in windowed:
            entries.append(windowed[q.index])
        else:
            names = names if names is not None else list(batch([float(getattr(problem, "t0", 0.0) or 0.0)])[0])
            entries.append(dict({n: None for n in names}, t=None, reached=False, at_end=None))
            result.warn(f"find.{q.index}: not searched — {why}")
    attach(result, problem.find, entries)



def _leaves(x: Any) -> list[float]:
    if isinstance(x, (list, tuple)):
        return [y for v in x for y in _leaves(v)]
    return [float(x)] if isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(float(x)) else []


def extended(problem: Any) -> Any:
    """``problem`` with ``t_end`` extended to the end of every ``within`` window and ``t`` query of
    its ``find`` (§11: the motion runs as far as the queries search), else itself."""
    from dyncli.expr import constant, resolve_params

    find = getattr(problem, "find", None)
    if not find or getattr(problem, "t_end", None) is None:
        return problem
    params = resolve_params(getattr(problem, "params", {}) or {})
    end = search_end(float(problem.t_end), find, lambda x: constant(x, params))
    return problem.model_copy(update={"t_end": end}) if end > problem.t_end else problem
