"""The ``find`` queries of a motion (problem files §11), for every type that reports one.

Topic-agnostic, in plain floats.  :func:`parse_queries` validates the raw list; :func:`answer`
answers it against any motion with: ``t0``, ``t_end`` (floats); ``breaks`` (increasing floats
from t0 to t_end: step ends or natural pieces; the results are smooth between two breaks);
optional ``subdivide`` (the pieces each break interval is cut into, default SUBDIVIDE);
``paths()`` (the valid scalar result paths); ``value(path, t) -> float`` (KeyError for an
unknown path); optional ``function(path)`` (``t -> value(path, t)`` as one callable, or None:
a search calls it without the dispatch of ``value``); optional ``rate(path, t) -> float | None`` (the time derivative when known);
optional ``rtol`` (the values' relative accuracy, default 0: exact to rounding; it widens the
tolerance within which a value touches VALUE and two extremes are equal); optional ``monotone``
(True when every result asked about is monotone between two breaks — the breaks hold all its
turning points, decided exactly by the type — so that its extremes are samples and no touch or
pair of crossings hides between two: no search inside a span); optional ``breaks_for(path)``
(the breaks of one result when they differ by result, such as its own turning points); optional
``cuts_approximate`` (True when those turning points are an interpolant's critical points, good
to ~1e-13, not exact: an extreme's time is then the root of its rate where known).  Each answer is
``{"t", "reached", "at_end"}``; the caller adds the state at ``t``.

An ``event`` query is answered from the motion's own list of events, ``events()`` — (t, joint,
what) in time order — with ``event_kinds`` and ``joint_names`` for its checks (a scene's one-sided
joints); a motion without ``events`` refuses it.

Every break interval is cut into :data:`SUBDIVIDE` pieces and sampled at their ends.  ``when``:
a sign change of value - VALUE between samples is one Brent solve to full double accuracy
(4 eps relative in t); a sample within tolerance of VALUE, or one closer to it than both
neighbours (with ``rate``: a rate turning toward VALUE and away) starts a search for the
closest approach in that span: within tolerance a touch (reaching it), beyond two crossings.
A value held at the start counts only when reached again; the direction of a crossing or a
touch is that of the approach (``up``: from below).  ``max``/``min``: the window's ends and the
turning points, roots of ``rate`` (Brent) when known, else Brent's minimiser (golden section
and parabolas) on each span whose middle sample beats both neighbours; of equal extremes (within
tolerance) the first.  No text is evaluated: numbers go through the ``constant`` callable.
"""

from __future__ import annotations

import re

import math
from dataclasses import dataclass
from functools import partial
from typing import Any, Callable, Iterable, Union

from dyncli.errors import InputError, NumericalError
from dyncli.rootfind import NotANumber, root
from dyncli.expr import did_you_mean

__all__ = ["AtTime", "When", "Extreme", "Event", "Query", "parse_queries", "answer", "SUBDIVIDE"]

SUBDIVIDE = 4       #: pieces each break interval is cut into before the sign tests
_EPS, _TINY = 2.220446049250313e-16, 5e-324
_KEYS = {"t": ("t",), "when": ("when", "direction", "occurrence"), "max": ("max", "within"), "min": ("min", "within"),
         "event": ("event", "joint", "occurrence", "after")}
_ALL_KEYS = ("t", "when", "direction", "occurrence", "max", "min", "within", "event", "joint", "after")
_OWNERS = {"direction": "when", "occurrence": "when or event", "within": "max and min", "joint": "event",
           "after": "event"}
#: what students call an event, for the "did you mean" of an event query
_EVENT_WORDS = {"rolls": "sticks", "rolling": "sticks", "stops_slipping": "sticks", "slides": "slips",
                "slip": "slips", "slipping": "slips", "lifts": "separates", "lifts_off": "separates",
                "separate": "separates", "leaves_wall": "separates", "hits": "impact", "strikes": "impact",
                "collides": "impact", "lands": "impact", "bounces": "impact", "stops": "rests", "rest": "rests",
                "at_rest": "rests", "goes_slack": "slack", "tight": "taut", "leave": "leaves", "falls_off": "leaves",
                "wrap": "wraps", "catches": "wraps", "hits_peg": "wraps", "catches_peg": "wraps", "unwrap": "unwraps",
                "leaves_peg": "unwraps", "straightens": "unwraps"}
_EXPR = "a number or a constant expression such as \"pi/2\" or \"30*deg\""


@dataclass(frozen=True)
class AtTime:
    """``{t: T}``: the state at time T; ``index`` is the query's place in ``find``."""
    t: float
    index: int = 0


@dataclass(frozen=True)
class When:
    """``{when: {PATH: VALUE}, direction, occurrence}``: the n-th time PATH reaches VALUE."""
    path: str
    value: float
    direction: str = "any"                      # "up", "down" or "any"
    occurrence: int = 1
    index: int = 0


@dataclass(frozen=True)
class Extreme:
    """``{max: PATH}`` or ``{min: PATH}`` (``kind``), ``within: [t1, t2]`` (None: the whole motion)."""
    path: str
    kind: str
    within: tuple[float, float] | None = None
    index: int = 0


@dataclass(frozen=True)
class Event:
    """``{event: WHAT, joint: NAME, occurrence: n}``: the n-th event WHAT (of joint NAME, or of any
    joint) of a motion that reports events (a scene's one-sided joints: separates, slips, ...)."""
    what: str
    joint: str | bool | None = None        # (a bool: YAML's reading of a bare on, off, yes, no)
    occurrence: int = 1
    index: int = 0
    after: bool = False                    # the state just after the event (the next phase's start)


#: the names YAML 1.1 reads as true or false (a joint named `on` written bare in a query)
_YAML_BOOL = {True: ("on", "yes", "y", "true"), False: ("off", "no", "n", "false")}


Query = Union[AtTime, When, Extreme, Event]


def _kind(x: Any) -> str:
    kinds = {dict: "a mapping", list: "a list", tuple: "a list", type(None): "nothing (null)", bool: f"the boolean {x}"}
    return kinds.get(type(x)) or f"{type(x).__name__} {x!r}"


def _number(constant: Callable[[Any], float], raw: Any, where: str, what: str) -> float:
    """A finite number or constant expression, else InputError at ``where``."""
    if isinstance(raw, (bool, dict, list, tuple)) or raw is None:
        raise InputError(f"{what} must be {_EXPR}, got {_kind(raw)}", where)
    try:
        v = float(constant(raw))
    except InputError as exc:
        raise InputError(f"{what} must be {_EXPR}: {exc.message}", where) from None
    if not math.isfinite(v):
        raise InputError(f"{what} must be finite, got {v}", where)
    return v


def _path(raw: Any, where: str, what: str) -> str:
    if not isinstance(raw, str) or not raw.strip():
        raise InputError(f"{what} must be a result path such as x.2, x.A.1 or theta, got {_kind(raw)}", where)
    return raw.strip()


def parse_queries(raw: list, constant: Callable[[Any], float] | None = None) -> list[Query]:
    """The raw ``find`` list validated; ``constant(text) -> float`` evaluates a number or constant
    expression (``lambda x: dyncli.expr.constant(x, params)``; default: without params).  Raises
    :class:`InputError` at ``find.<i>.<field>`` with one message naming the field and the fix."""
    if constant is None:
        from dyncli.expr import constant as default

        constant = default
    if raw is None:
        return []
    if not isinstance(raw, (list, tuple)):
        raise InputError("find must be a list of queries such as [{t: 1.5}, {when: {x.1: 0}}, {max: x.2}], "
                         f"got {_kind(raw)}", "find")
    return [_parse_one(q, i, constant) for i, q in enumerate(raw)]


def _parse_one(q: Any, i: int, constant: Callable[[Any], float]) -> Query:
    base = f"find.{i}"
    if not isinstance(q, dict):
        raise InputError("a query is a mapping such as {t: 1.5}, {when: {x.1: 0}}, {max: x.2} or "
                         f"{{min: x.2, within: [0, 1]}}, got {_kind(q)}", base)
    for key in q:
        if key not in _ALL_KEYS:
            raise InputError(f"unknown key {str(key)!r}{did_you_mean(str(key), _ALL_KEYS)}; a query has one of t, "
                             "when (with direction, occurrence), max or min (with within), or event (with joint, "
                             "occurrence, after)", f"{base}.{key}")
    kinds = [k for k in ("t", "when", "max", "min", "event") if k in q]
    if len(kinds) != 1:
        raise InputError(f"a query asks one thing: give '{kinds[0]}' and '{kinds[1]}' as two queries" if kinds else
                         f"a query needs one of t, when, max, min or event, not only {', '.join(q) or 'nothing'}",
                         f"{base}.{kinds[1]}" if kinds else base)
    kind = kinds[0]
    for key in q:
        if key not in _KEYS[kind]:
            raise InputError(f"'{key}' goes with {_OWNERS[key]} only, not with '{kind}': remove it", f"{base}.{key}")
    if kind == "t":
        return AtTime(_number(constant, q["t"], f"{base}.t", "the time t"), index=i)
    if kind == "when":
        return _parse_when(q, base, i, constant)
    if kind == "event":
        what = q["event"]
        if not isinstance(what, str) or not what.strip():
            raise InputError(f"event names what happens, such as event: sticks or event: separates, got {_kind(what)}",
                             f"{base}.event")
        joint = q.get("joint")
        if joint is not None and not isinstance(joint, bool) and (not isinstance(joint, str) or not joint.strip()):
            raise InputError(f"joint names the joint whose event is asked (a key under joints), got {_kind(joint)}",
                             f"{base}.joint")
        after = q.get("after", False)
        if not isinstance(after, bool):
            raise InputError(f"after must be true (the state just after the event) or false (just before, the "
                             f"default), got {_kind(after)}", f"{base}.after")
        return Event(what.strip(), joint.strip() if isinstance(joint, str) else joint, _occurrence(q, base), index=i,
                     after=after)
    within = _parse_within(q["within"], base, constant) if "within" in q else None
    return Extreme(_path(q[kind], f"{base}.{kind}", f"the result of {kind}"), kind, within, index=i)


def _parse_within(w: Any, base: str, constant: Callable[[Any], float]) -> tuple[float, float]:
    if not isinstance(w, (list, tuple)) or len(w) != 2:
        raise InputError("within is a time window [t1, t2], such as within: [0, 2], got "
                         + (f"a list of {len(w)}" if isinstance(w, (list, tuple)) else _kind(w)), f"{base}.within")
    t1, t2 = (_number(constant, x, f"{base}.within.{k}", f"the window's {'end' if k else 'start'}")
              for k, x in enumerate(w))
    if t2 < t1:
        raise InputError(f"within [{w[0]}, {w[1]}] is reversed: write [{w[1]}, {w[0]}]", f"{base}.within")
    return t1, t2


def _parse_when(q: dict, base: str, i: int, constant: Callable[[Any], float]) -> When:
    w = q["when"]
    if not isinstance(w, dict) or len(w) != 1:
        raise InputError("when takes one result and its value, such as when: {x.1: 0}, got "
                         + (f"{len(w)} entries" if isinstance(w, dict) else _kind(w)), f"{base}.when")
    (key, val), = w.items()
    path = _path(key, f"{base}.when", "the result in when")
    value = _number(constant, val, f"{base}.when.{path}", f"the value of {path}")
    d = q.get("direction", "any")
    if d not in ("up", "down", "any"):
        hint = did_you_mean(d, ("up", "down", "any")) if isinstance(d, str) else ""
        raise InputError(f"direction must be up, down or any, got {d!r}{hint}" if isinstance(d, str) else
                         f"direction must be up, down or any, got {_kind(d)}", f"{base}.direction")
    return When(path, value, d, _occurrence(q, base), index=i)


def _occurrence(q: dict, base: str) -> int:
    n = q.get("occurrence", 1)
    n = int(n) if isinstance(n, float) and n.is_integer() else n
    if isinstance(n, bool) or not isinstance(n, int):
        raise InputError(f"occurrence must be a whole number 1, 2, 3 ... (the n-th crossing), got {_kind(n)}",
                         f"{base}.occurrence")
    if n < 1:
        shown = str(n) if abs(n) < 10 ** 12 else f"{float(n):.3g}"
        raise InputError(f"occurrence must be 1 or more: it counts from 1 (the first crossing), got {shown}",
                         f"{base}.occurrence")
    return n


def answer(queries: Iterable[Query], motion: Any, notes: dict[int, str] | None = None) -> list[dict]:
    """One ``{"t", "reached", "at_end"}`` per query, in order (``t`` and ``at_end`` None when not
    reached; ``at_end`` None for ``t`` and ``when``).  An unknown result path is an InputError at
    ``find.<i>.when`` / ``.max`` / ``.min`` naming it.  ``notes`` (a dict, when given) gets why a
    ``when`` query was not reached where the search knows more than "not met": ``{index: text}``."""
    out = []
    for q in queries:
        if isinstance(q, AtTime):
            ok = motion.t0 <= q.t <= motion.t_end
            out.append({"t": float(q.t) if ok else None, "reached": ok, "at_end": None})
            continue
        if isinstance(q, Event):
            t = _event(motion, q)
            out.append({"t": t, "reached": t is not None, "at_end": None} | ({"after": True} if q.after else {}))
            continue
        _check_path(motion, q.path, f"find.{q.index}.{'when' if isinstance(q, When) else q.kind}")
        try:
            t, at_end = (_when(motion, q, notes), None) if isinstance(q, When) else _extreme(motion, q)
        except NotANumber as exc:
            raise NumericalError(f"find.{q.index}: {q.path} is not a number near t = {exc.x:.6g} s (the motion "
                                 "overflows the doubles there): search a shorter span (t_end or within)") from None
        out.append({"t": t, "reached": t is not None, "at_end": at_end})
    return out


def _event(motion: Any, q: Event) -> float | None:
    """The time of the n-th event asked (None when fewer happen): the motion's ``events()``, a list
    of (t, joint, what) in time order, with ``event_kinds`` and ``joint_names`` for the checks."""
    where = f"find.{q.index}"
    events = getattr(motion, "events", None)
    if events is None:
        raise InputError("event queries are for scenes (the events of their one-sided joints); ask "
                         "when: {RESULT: VALUE} for the moment a result reaches a value", f"{where}.event")
    kinds = motion.event_kinds
    if q.what not in kinds:
        near = _EVENT_WORDS.get(q.what.lower())
        hint = f" (did you mean '{near}'?)" if near in kinds else did_you_mean(q.what, kinds)
        raise InputError(f"no event {q.what!r}{hint}; the events are {', '.join(kinds)}", f"{where}.event")
    names, joint = motion.joint_names, q.joint
    if isinstance(joint, bool):       # `joint: on` read by YAML as true: the joint so named, when one is
        named = [n for n in names if n.lower() in _YAML_BOOL[joint]]
        if len(named) != 1:
            raise InputError(f"joint names the joint whose event is asked (a key under joints), got the boolean "
                             f"{joint} (YAML reads a bare on, off, yes or no as a boolean: quote the name, "
                             "joint: \"on\")", f"{where}.joint")
        joint = named[0]
    if joint is not None and joint not in names:
        raise InputError(f"no joint {joint!r}{did_you_mean(joint, names)}; the joints are {', '.join(names) or 'none'}",
                         f"{where}.joint")
    hits = [t for t, j, what in events() if what == q.what and (joint is None or j == joint)]
    return float(hits[q.occurrence - 1]) if len(hits) >= q.occurrence else None


def _check_path(motion: Any, path: str, where: str) -> None:
    known = list(motion.paths())
    parts = sorted(k for k in known if k.startswith(path + "."))
    if path not in known and parts:                   # a vector (or a body's results): one number of it
        raise InputError(f"'{path}' is not one number: search one of its components, such as "
                         + ", ".join(parts[:3]) + (" ..." if len(parts) > 3 else ""), where)
    m = re.fullmatch(r"([A-Za-z_]+)\.?([1-3])", path)
    if path not in known and m and (comp := f"{m[1]}.{int(m[2]) - 1}") in known:
        raise InputError(f"no result '{path}': the notes' {m[1]}{m[2]} (component {m[2]} on e1, e2, e3) is "
                         f"'{comp}' here, components counting from 0 ({m[1]}.0, {m[1]}.1, {m[1]}.2)", where)
    if path not in known:
        raise InputError(f"no result '{path}' to search{did_you_mean(path, known)}; the scalar results are "
                         + ", ".join(sorted(known)[:8]) + (" ..." if len(known) > 8 else ""), where)


def sample_grid(breaks: Iterable[float], lo: float, hi: float, n: int = SUBDIVIDE) -> list[float]:
    """lo, the breaks inside (lo, hi) and hi, each interval cut into n (SUBDIVIDE) equal pieces."""
    pts = [lo, *sorted(map(float, [b for b in breaks if lo < b < hi])), hi]
    if n == 1:                                        # the breaks themselves, without repeats
        return [x for i, x in enumerate(pts) if i == 0 or x > pts[i - 1]]
    out = [lo]
    for a, b in zip(pts, pts[1:]):
        out += [x for x in (a + (b - a) * k / n for k in range(1, n)) if a < x < b] + [b]
    return [x for i, x in enumerate(out) if i == 0 or x > out[i - 1]]


def subdivisions(motion: Any) -> int:
    """How many pieces each break interval is cut into: ``motion.subdivide`` (1 for the steps of
    an ODE, already short beside the motion) or SUBDIVIDE."""
    return int(getattr(motion, "subdivide", SUBDIVIDE) or SUBDIVIDE)


def _value_fn(motion: Any, path: str) -> Callable[[float], float]:
    """t -> the value of ``path`` as a float: ``motion.function(path)`` when the motion gives one
    (the numbers of ``value``, without its dispatch per call), else ``value(path, t)``."""
    own = getattr(motion, "function", None)
    fn = own(path) if callable(own) else None
    return fn if fn is not None else (lambda t: float(motion.value(path, t)))


def _samples(motion: Any, path: str, f: Callable[[float], float], T: list[float]) -> list[float]:
    """``f`` (the value of ``path``) at each time of ``T``; remembered in ``motion.samples`` (a
    dict, when the motion keeps one) under the path and the times, so that two queries on one
    result read its grid once (the same values).  The list returned is not to be changed."""
    memo = getattr(motion, "samples", None)
    if type(memo) is not dict:
        return list(map(f, T))
    key = (path, tuple(T))
    got = memo.get(key)
    if got is None:
        got = memo[key] = list(map(f, T))
    return got


def _rate_fn(motion: Any, path: str, t0: float):
    rate = getattr(motion, "rate", None)
    return None if not callable(rate) or rate(path, t0) is None else (lambda t: float(rate(path, t)))


def _tol(motion: Any, scale: float) -> float:
    return max(8 * _EPS, float(getattr(motion, "rtol", 0.0) or 0.0)) * scale


def _sign(x: float, tol: float) -> int:
    return 0 if abs(x) <= tol else (1 if x > 0 else -1)


def _when(motion: Any, q: When, notes: dict[int, str] | None = None) -> float | None:
    """The time of the n-th crossing or touch of ``q.value`` in ``q.direction``, or None: the
    grid is searched in growing prefixes (doubling), stopping at the prefix that holds the answer
    well inside it (a long search for an early event samples no further than it needs).  Not
    reached because the motion only creeps toward the value (:meth:`_Crossings._stays`): said in
    ``notes[q.index]``."""
    path, V = q.path, q.value
    T = sample_grid(_breaks(motion, path), float(motion.t0), float(motion.t_end), subdivisions(motion))
    want, rate = {"up": 1, "down": -1}.get(q.direction), _rate_fn(motion, path, motion.t0)
    ahead = getattr(motion, "prefetch", None)
    f = _value_fn(motion, path)
    F: list[float] = []
    m = min(len(T), FIRST_PREFIX)
    while True:
        if callable(ahead) and m < len(T):
            ahead(T[m - 1])
        F += _samples(motion, path, f, T[len(F):m])
        scan = _Crossings(f, V, rate, T[:m], [y - V for y in F], _tol(motion, max([abs(V), *map(abs, F)])),
                          final=m == len(T))
        safe = T[-1] if m == len(T) else T[m - 4]     # events are local to ±2 samples: final before this
        hits = [t for t, d in scan.events(want, q.occurrence, safe, _monotone(motion)) if (want is None or d == want) and t <= safe]
        if len(hits) >= q.occurrence:
            return hits[q.occurrence - 1]
        if m == len(T):
            if scan.approach is not None and notes is not None:
                notes[q.index] = (f"{path} only approaches {V:.10g}: within the tolerance of it ({scan.tol:.2g}) from "
                                  f"t = {scan.approach:.6g} s on without meeting it (an asymptote, reached as t → ∞)")
            return None
        m = min(len(T), 2 * m)


#: a monotone search's sample closer to VALUE than its neighbours and within this many tolerances of
#: it is searched for a touch (a cut on a kink lies ~1e-13 s off it: NEAR_CUT × 8 eps ≈ 1e-11 relative)
NEAR_CUT = 1e4

#: samples of a ``when`` search's first prefix (then doubled until the answer or the end)
FIRST_PREFIX = 256


class _Crossings:
    """The crossings and touches of g = value - VALUE = 0 over the samples G at the times T:
    ``events()`` lists (time, +1 reaching from below / -1 from above) in time order.

    The spans that may hold an event are listed first (from the samples alone); each is then
    solved in the order of its start — an event lies at or after its span's start — so a search
    for the n-th event stops once it has n and no span left starts before the n-th (the events
    it returns up to there are those of the full scan)."""

    def __init__(self, f, V, rate, T, G, tol, final: bool = True):
        self.g = lambda t: f(t) - V       # noqa: E731
        self.f, self.V = f, V
        self.rate, self.T, self.G, self.tol = rate, T, G, tol
        self.S: list[int] = []
        self.found: list[tuple[float, int]] = []
        self.spans: list[tuple[float, int, Callable[[], None]]] = []
        self.approach: float | None = None        # (_stays) came within tolerance of VALUE only
        self.final = final                        # T ends where the search ends (not a prefix of it)

    def events(self, want: int | None = None, occurrence: int | None = None,
               safe: float = math.inf, monotone: bool = False) -> list[tuple[float, int]]:
        """The events, all of them, or (``occurrence``) at least every one up to the
        ``occurrence``-th in direction ``want`` at or before ``safe``; ``monotone``: g is monotone
        between two samples (no dip to look for inside a span)."""
        if monotone:        # only the spans of the signs, met in order of their start: solved as met
            return self._events_in_order(want, occurrence, safe)
        tol = self.tol
        self.S = [0 if abs(x) <= tol else (1 if x > 0 else -1) for x in self.G]     # (_sign)
        self._dips()
        self._signs()
        spans = sorted(self.spans, key=lambda s: (s[0], s[1]))
        for i, (_, _, solve) in enumerate(spans):
            solve()
            if occurrence is not None and i + 1 < len(spans):
                hits = sorted(t for t, d in self.found if (want is None or d == want) and t <= safe)
                if len(hits) >= occurrence and spans[i + 1][0] > hits[occurrence - 1]:
                    break
        return sorted(self.found)

    def _events_in_order(self, want: int | None, occurrence: int | None, safe: float) -> list[tuple[float, int]]:
        """:meth:`events` of a monotone g: the spans of :meth:`_sign_spans` come in order of their
        start, so each is solved when met and the search stops at the first span that starts
        after the ``occurrence``-th event (the same spans solved, and the same events, as
        :meth:`events` solving the sorted list)."""
        import heapq

        solved = False
        for start, solve in heapq.merge(self._sign_spans(), self._near_cuts(), key=lambda span: span[0]):
            if solved and occurrence is not None:
                hits = sorted(t for t, d in self.found if (want is None or d == want) and t <= safe)
                if len(hits) >= occurrence and start > hits[occurrence - 1]:
                    break
            solve()
            solved = True
        return sorted(self.found)

    def _near_cuts(self):
        """(start, solve) of each sample of a monotone g that comes closer to VALUE than its
        neighbours, on their side, and within NEAR_CUT tolerances of it: a cut on an extreme that
        may lie a little off it — one on a kink (|t − 1| at 1) is placed to ~1e-13 s, its value
        that much off 0, beyond the rounding — searched as a dip (the closest approach, a touch)."""
        T, G, tol = self.T, self.G, self.tol
        near = NEAR_CUT * tol
        for j in range(1, len(G) - 1):
            a, x, b = G[j - 1], G[j], G[j + 1]
            if tol < abs(x) <= near and (a > 0) == (x > 0) == (b > 0) and abs(x) < abs(a) and abs(x) <= abs(b):
                yield T[j - 1], partial(self.dip, T[j - 1], T[j + 1], 1 if x > 0 else -1)

    def _later(self, start: float, solve: Callable[[], None]) -> None:
        """A span from ``start`` that may hold events: ``solve`` finds them (when asked)."""
        self.spans.append((start, len(self.spans), solve))

    def first_reach(self, a: float, b: float, s: int) -> float:
        """The first time in [a, b] with s*g <= 0 (s*g(a) > 0 >= s*g(b)): the root of s*g with
        an exact zero counted as negative (:func:`_hr_psi`, written out: one call per value)."""
        f, V = self.f, self.V

        def psi(t: float) -> float:
            y = s * (f(t) - V)
            return y if y != 0 else -_TINY

        return root(psi, a, b)

    def crossing(self, a: float, b: float, s: int) -> None:
        """The crossing from side s at a to the other side at b."""
        self.found.append((self.first_reach(a, b, s), -s))

    def dip(self, a: float, b: float, s: int, run: Iterable[int] = ()) -> None:
        """g at a and b on side s (the samples ``run`` between on VALUE): a touch, two crossings?"""
        rate, g = self.rate, self.g
        tm, hm = _peak(lambda t: -s * g(t), (lambda t: -s * rate(t)) if rate else None, a, b)
        # a kink; of equal closest approaches a sample on VALUE first (a monotone route's cut: the
        # extreme's exact time, where Brent's minimiser's is good to ~√eps)
        tm, hm = max([(self.T[j], -s * self.G[j]) for j in run] + [(tm, hm)], key=lambda c: c[1])
        sm = _sign(-s * hm, self.tol)                 # the side of the closest approach
        if sm == 0:                                   # touches VALUE: reaching it counts
            t1 = self.first_reach(a, tm, s) if hm >= 0 and rate is None else tm
            self.found.append((t1 if tm - t1 > 1e-6 * (b - a) else tm, -s))   # a plateau: its start
        elif sm == -s:                                # through VALUE and back
            self.found += [(self.first_reach(a, tm, s), -s), (self.first_reach(tm, b, -s), s)]

    def _dips(self) -> None:
        """Spans of samples on one side closer to VALUE than their neighbours (with the rate: a
        rate turning toward VALUE and away again) may hide a touch or two crossings."""
        T, G, S = self.T, self.G, self.S
        covered: set[int]
        n, covered = len(T), set()
        for j in range(1, n - 1):
            if S[j - 1] == S[j] == S[j + 1] != 0 and abs(G[j]) < abs(G[j - 1]) and abs(G[j]) <= abs(G[j + 1]):
                self._later(T[j - 1], partial(self.dip, T[j - 1], T[j + 1], S[j]))
                covered.update((j - 1, j))
        R = [self.rate(t) for t in T] if self.rate else None
        for k in range(n - 1):
            s = S[k]
            if k in covered or s == 0 or S[k + 1] != s:
                continue
            if R is not None and s * R[k] < 0 < s * R[k + 1]:
                self._later(T[k], partial(self.dip, T[k], T[k + 1], s))
            elif R is None and ((k == 0 and abs(G[0]) <= abs(G[1])) or (k == n - 2 and abs(G[-1]) < abs(G[-2]))):
                self._later(T[k], partial(self.dip, T[k], T[k + 1], s))   # a dip just inside an end

    def _signs(self) -> None:
        """Sign changes between samples off VALUE, runs of samples on it (within tolerance)."""
        for start, solve in self._sign_spans():
            self._later(start, solve)

    def _sign_spans(self):
        """(start, solve) of each span of :meth:`_signs`, in order of the samples (so of start)."""
        T, G, tol = self.T, self.G, self.tol
        sp: int | None = None                         # the last sample off VALUE: its side, index
        ip = -1                                       # (read only once sp is set)
        for i, x in enumerate(G):
            if abs(x) <= tol:                         # on VALUE (_sign 0)
                continue
            s = 1 if x > 0 else -1
            if sp is not None and s != sp:            # crossed (possibly through samples on VALUE)
                yield T[ip], partial(self.crossing, T[ip], T[i], sp)
            elif sp is not None and i - ip > 1:       # came to VALUE and went back: a touch
                yield T[ip], partial(self.dip, T[ip], T[i], sp, range(ip + 1, i))
            sp, ip = s, i                             # (sp None before: a value held at the start)
        if sp is not None and ip < len(T) - 1:        # reaches VALUE and stays on it to the end
            yield T[ip], partial(self._stays, ip, sp)

    def _stays(self, ip: int, sp: int) -> None:
        """The event of a motion that comes within the tolerance of VALUE after the sample ``ip``
        and stays there to the end (met, or passed by its rounding, at its first sample on or past
        VALUE, else at the tolerance's edge) — when it stops there (its rate exactly 0; without a
        rate, met exactly or held on equal samples: a body that stops and sticks) or meets it at
        the end of the search at the speed it came.  A motion that only creeps toward VALUE, its
        rounding within the tolerance (on VALUE, or an ulp past it) while it still moves toward
        it — an asymptote: a critically damped return, (1 + t)e^-t — never reaches it: no event,
        and ``approach`` keeps the time it came within the tolerance."""
        T, G, n, rate = self.T, self.G, len(self.T), self.rate
        j = next((j for j in range(ip + 1, n) if sp * G[j] <= 0), None)
        edge = root(lambda t: sp * self.g(t) - self.tol, T[ip], T[ip + 1])     # within tolerance from here
        t = self.first_reach(T[ip], T[j], sp) if j is not None else edge
        after = range(ip + 1 if j is None else j, min(n, (ip + 1 if j is None else j) + 4))
        if rate is not None:                          # stopped on VALUE: the rate exactly 0
            stopped = any(rate(T[k]) == 0 for k in after)
        else:                                         # a plateau, or met exactly (no rate to tell)
            stopped = j is not None or any(G[k] == G[k + 1] for k in range(ip + 1, n - 1))
        # met at the end: the search ends before the motion, at the speed it came, crosses the
        # tolerance it entered at ``edge`` (a creeping motion slows down: its band lasts ~ its time constant)
        speed = abs(rate(edge)) if rate is not None else abs(G[ip] - self.g(edge)) / max(edge - T[ip], _TINY)
        # (4: a tangency at the end approaches quadratically, its band crossed in twice that)
        if stopped or (self.final and T[-1] - edge <= 4 * self.tol / max(speed, _TINY)):
            self.found.append((t, -sp))
        elif self.approach is None:
            self.approach = edge


def _extreme(motion: Any, q: Extreme) -> tuple[float | None, bool | None]:
    """The first time of the largest (``max``) or smallest value in the window, and at_end."""
    t0, t_end = float(motion.t0), float(motion.t_end)
    w1, w2 = max((q.within or (t0,))[0], t0), min((q.within or (0, t_end))[1], t_end)
    if w1 > w2:
        return None, None
    sense, path, monotone = (1.0 if q.kind == "max" else -1.0), q.path, _monotone(motion)
    rate = _rate_fn(motion, q.path, w1)
    f = _value_fn(motion, path)
    h = lambda t: sense * f(t)     # noqa: E731
    hr = (lambda t: sense * rate(t)) if rate else None
    T = sample_grid(_breaks(motion, path), w1, w2, subdivisions(motion))
    Y = _samples(motion, path, f, T)
    H = list(Y) if sense > 0 else [-y for y in Y]       # (h at each: ±1.0·y is ±y)
    cands = [(T[0], H[0]), (T[-1], H[-1])]
    if monotone:                                      # the turning points are samples: no search
        peaks = [j for j in range(1, len(T) - 1) if H[j] >= H[j - 1] and H[j] >= H[j + 1]]
        cands += [(T[j], H[j]) for j in peaks]
        best = max(c[1] for c in cands)
        tol = _tol(motion, _scale(H, best))
        # the first of the best peaks polished (the answer; a cut is the extreme's time to the
        # companion matrix's ~1e-12, its value to rounding, so no later peak can overtake it):
        # h rises to T[j] and falls after it, so its largest value in [T[j-1], T[j+1]] is the
        # one there (a root of the rate, else Brent's minimiser), kept when no lower than H[j]
        j = next((j for j in peaks if H[j] >= best - tol), None)
        if j is not None:
            tm, hm = _peak(h, hr, T[j - 1], T[j + 1])
            rooted = hr is not None and hr(T[j - 1]) > 0 >= hr(T[j + 1])     # (_peak took the rate's root)
            if rooted and getattr(motion, "cuts_approximate", False) and hm >= H[j] - tol:
                # cuts at an interpolant's critical points (~1e-13): the rate's root replaces them
                cands = [c for c in cands if c[0] != T[j]] + [(tm, max(hm, H[j]))]
            elif (hm >= H[j]) if rooted else (hm > H[j] + tol):
                # (Brent's minimiser's time is good to ~√eps only: on a flat top its value ties the
                # cut's to rounding, and the cut — the extreme to ~1e-13 — stands unless beaten)
                cands.append((tm, hm))
    else:
        cands += _turning(h, hr, T, H)
    best = max(c[1] for c in cands)
    if any(c[1] != c[1] for c in cands):               # NaN: no largest value to speak of
        raise NumericalError(f"find: {path} is not a number along the motion (between t = {w1:g} and {w2:g} s): "
                             "no largest or smallest value; check the inputs that define it")
    if not math.isfinite(best):                       # ±inf: the extreme is beyond the doubles
        raise NumericalError(f"find: the {q.kind} of {path} between t = {w1:g} and {w2:g} s is beyond the range "
                             "of a double (1.8e308): check the inputs that scale it")
    scale = _scale(H, best)
    tol = _tol(motion, scale)
    t = min(c[0] for c in cands if c[1] >= best - tol)
    if monotone:
        t = _plateau_start(h, hr, T, H, t, best - tol, 8 * _EPS * scale)
    return t, (t == w1 or t == w2)


def _plateau_start(h, hr, T: list[float], H: list[float], t: float, floor: float, rounding: float) -> float:
    """The start of the plateau that holds the extreme at the sample ``t`` (h monotone between
    samples): when h is flat there — the next sample equal to it, or ``t`` the window's end, and
    its rate hr (when known) exactly 0 — the samples before it whose span is flat (h at its middle
    equal to the plateau) and whose value ties with it to rounding, within tolerance of the best
    (``floor``).  A body that stops and sticks holds its least speed from the stop on, while the
    stop itself carries the rounding of the phase before it (|v| ~1e-15): its least kinetic
    energy is at the stop, not at the end of the motion."""
    k = next((k for k, x in enumerate(T) if x == t), None)
    if k is None or (k + 1 < len(T) and H[k + 1] != H[k]) or (hr is not None and hr(t) != 0):
        return t                                      # a strict peak, or still moving: its own time
    while k > 0 and H[k - 1] >= floor and abs(H[k] - H[k - 1]) <= rounding and h(0.5 * (T[k - 1] + T[k])) == H[k]:
        k -= 1
    return T[k]


def _scale(H: list[float], best: float) -> float:
    """The size of the values the extreme is told apart at: the largest finite |value| (an
    infinite sample elsewhere would make every candidate tie with the best)."""
    return max([abs(x) for x in H if math.isfinite(x)] + [abs(best) if math.isfinite(best) else 0.0])


def _turning(h, hr, T: list[float], H: list[float]) -> list[tuple[float, float]]:
    """(time, value) of each largest value of h inside the samples T (values H): the roots of its
    rate hr where it turns from rising (Brent), else Brent's minimiser around each sample that
    beats its neighbours (and just inside the ends)."""
    n, rooted, cands = len(T), set(), []
    HR = [hr(t) for t in T] if hr else []
    for k in range(len(HR) - 1):
        if HR[k] > 0 >= HR[k + 1]:                    # h turns from rising to not rising
            assert hr is not None                     # (HR is empty without it)
            tm = _turn(hr, T[k], T[k + 1], T[k + 2] if k + 2 < len(T) and HR[k + 1] == 0 else None)
            cands.append((tm, h(tm)))
            rooted.add(k)
    for j in range(1, n - 1):
        if H[j] > H[j - 1] and H[j] >= H[j + 1] and not ({j - 1, j} & rooted):
            tm, hm = _peak(h, None, T[j - 1], T[j + 1])
            # Brent's minimiser's time where it beats the sample; on a tie (a flat top: a body
            # that stopped and stays) any time of the flat would do, and the sample is its first
            cands.append((tm, hm) if hm > H[j] else (T[j], H[j]))
    if hr is None and n > 2:                          # a peak just inside an end
        cands += [_peak(h, None, a, b) for a, b, ha, hb in ((T[0], T[1], H[0], H[1]), (T[-2], T[-1], H[-1], H[-2]))
                  if ha >= hb]
    return cands


def _breaks(motion: Any, path: str) -> list[float]:
    """The breaks searched for ``path``: ``motion.breaks_for(path)`` when the motion has its own
    for each result (the turning points of that result alone), else ``motion.breaks``."""
    own = getattr(motion, "breaks_for", None)
    return motion.breaks if own is None else own(path)


def _monotone(motion: Any) -> bool:
    """Whether the motion's results asked about are monotone between its breaks (``monotone``)."""
    return bool(getattr(motion, "monotone", False))


def _turn(hr: Callable[[float], float], a: float, b: float, c: float | None) -> float:
    """Where hr turns from positive to negative after a: the middle of the run of exact zeros
    there (a rate computed as √(2K/m) from an energy is exactly 0 over a few rounding steps
    around a turning point, symmetric about it), a single root when there is none.  The run
    starts in [a, b]; ``c``: the next sample when hr(b) is 0 (the run may go on past b)."""
    first = root(lambda t: _hr_psi(hr, t), a, b)
    if hr(first) != 0:
        return first
    end = c if c is not None else b
    if hr(end) >= 0:                                  # no negative rate in reach: the run's start
        return first
    last = root(lambda t: y if (y := hr(t)) != 0 else _TINY, first, end)
    return 0.5 * (first + last)


def _hr_psi(hr: Callable[[float], float], t: float) -> float:
    """hr(t), an exact zero counted as negative: a root is the first time hr stops being positive."""
    return y if (y := hr(t)) != 0 else -_TINY


def _peak(h, hr, a: float, b: float) -> tuple[float, float]:
    """The largest value of h inside [a, b] and its time: the root of its rate hr (Brent) when
    hr is given and turns from positive to not positive over [a, b], else Brent's minimiser."""
    if hr is not None and hr(a) > 0 >= hr(b):
        t = root(lambda t: _hr_psi(hr, t), a, b)
        return t, h(t)
    from dyncli.rootfind import fminbound_unit

    u = fminbound_unit(lambda u: -h(a + u * (b - a)), 1e-12)
    t = min(max(a + u * (b - a), a), b)
    return t, h(t)
