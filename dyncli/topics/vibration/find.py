"""The ``find`` queries and ``distance`` of a vibration (§11), on the exact closed form.

The motion is the closed-form total response at any time (:func:`closed_form.response_at`, or the
force- or unbalance-excited :func:`forced.response_at`); its rates are exact (v is the rate of x, and the rates
of v and w follow from the equation of motion (17.15a)), so a turning point is a root of the rate
(Brent), never a sampled peak.  The queries search between the exact turning points of the
quantities they ask about (x: the roots of v; v: of the acceleration; w = x − s − L: of ẇ, the
same equation of motion without the base's s), found by the sign analysis of :mod:`.turns` on
the breaks (an eighth of the shortest period present, the damped free vibration's or the
excitation's): each quantity is monotone between them, so no crossing or extremum can hide.

``distance`` is Σ|Δx| between the turning points (the roots of v).  Free vibration: the turning
points in closed form (v ∝ e^(−ζωₙt) cos(ω*t + β) vanishes at ω*t + β = π/2 + kπ; at most one
when ζ ≥ 1) and the sum over them as a geometric series (each |w| at a turning point is the last
times e^(−ζωₙπ/ω*)) — O(1) at any time.  With a base motion or a force: the roots of v on the grid
of breaks, from the steady state plus the free vibration that makes up the initial conditions —
in plain floats with Newton and the exact acceleration for a short grid (no numpy import), on
arrays for a long one or once numpy is loaded, each root then polished by the plain-float search's
own cells and Newton (:func:`turns.float_root`), so both routes give the same doubles and an
answer does not depend on what the process solved before (a point's place in a sweep).
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass, replace

from dyncli import motion_find as mf
from dyncli.errors import InputError
from dyncli.expr import constant, resolve_params

from . import closed_form as cf
from . import forced, turns

_EPS = 2.220446049250313e-16

#: pieces per shortest period, and the most pieces a search takes (beyond: a coarser grid, warned)
PER_PERIOD, MAX_PIECES = 8, 20_000


@dataclass(frozen=True, slots=True)
class Setup:
    """What ``find`` and ``distance`` read of a vibration problem, in SI floats (built by the
    solver from its input): the mass, the free length, the initial state, the base motion
    s0 sin(Ωt) (0, 0 without one), the force (F0, ω) on the mass or None, the times of ``at``,
    the ``find`` queries as written, ``t_end`` and the file's ``params`` (for the queries' numbers)."""
    m: float
    L: float
    x0: float
    v0: float
    s0: float = 0.0
    Om: float = 0.0
    fo: tuple[float, float] | None = None
    at: tuple[float, ...] = ()
    find: tuple = ()
    t_end: float | None = None
    params: tuple = ()


class Response:
    """x(t), v(t), w(t) and the acceleration of one vibration problem, exact."""

    def __init__(self, p: Setup, omega_n, zeta):
        self.p, self.omega_n, self.zeta = p, omega_n, zeta
        self.L = p.L
        self.x0 = p.x0
        self.s0, self.Om = p.s0, p.Om
        self.fo = p.fo                   # (F0, ω) of a force on the mass or a rotating unbalance, or None
        self._fast = None
        self._roots: dict = {}           # (motion, d, t_end) -> turns.roots on the breaks to t_end

    def roots(self, mo: turns.Motion, d: int, t_end: float, arrays: bool | None = None):
        """:func:`turns.roots` of ``mo``'s d-th derivative on :meth:`breaks` to ``t_end``, found once
        per response (the distance and a query on x ask for the same turning points; both routes
        give the same doubles); ``arrays``: on numpy arrays (default: :func:`_on_arrays` of the
        grid's length)."""
        key = (mo, d, t_end)
        got = self._roots.get(key)
        if got is None:
            breaks = self.breaks(t_end)[0]
            if arrays is None:
                arrays = _on_arrays(len(breaks))
            got = self._roots[key] = turns.roots(mo, breaks, d, arrays)
        return got

    def at(self, t: float) -> tuple[float, float, float]:
        p = self.p
        if self.fo is None:
            return cf.response_at(t, omega_n=self.omega_n, zeta=self.zeta, L=self.L, x0=self.x0, v0=p.v0,
                                  s0=self.s0, Omega=self.Om)
        return forced.response_at(t, m=p.m, omega_n=self.omega_n, zeta=self.zeta, L=self.L, x0=self.x0,
                                  v0=p.v0, F0=self.fo[0], Om=self.fo[1])

    def fast_at(self):
        """:meth:`at` of a free vibration below critical damping with its constants hoisted
        (:func:`closed_form.free_response_fn`: the same doubles), or None for any other motion."""
        if self.fo is not None or self.s0 != 0.0:
            return None
        if self._fast is None:                  # (made once: the odometer and the search share it)
            self._fast = cf.free_response_fn(self.omega_n, self.zeta, self.L, self.x0, self.p.v0)
        return self._fast

    def scalar(self):
        """(x, v)(t) in plain floats: the steady state plus the free vibration that makes up the
        initial conditions (the general closed form at an undamped resonance)."""
        import cmath

        P, Om = self._steady()
        if P is None:
            return lambda t: self.at(t)[:2]
        iOP = 1j * Om * P
        w0, wd0 = self.x0 - self.L - P.imag, self.p.v0 - iOP.imag
        wn, z, L = self.omega_n, self.zeta, self.L

        def slow(t: float):
            e = cmath.exp(1j * Om * t)
            wh, vh = cf.free_at(t, w0, wd0, wn, z)
            return L + wh + (P * e).imag, vh + (iOP * e).imag
        if not 0.0 <= z < 1.0 or not all(map(math.isfinite, (w0, wd0, wn, Om))):
            return slow
        # the same arithmetic as cf.free_at and the complex products, with the constants hoisted
        ws, sig = cf.roots(wn, z)[0], z * wn
        b, K = wd0 + sig * w0, wn * (wn * w0) + sig * wd0
        Pr, Pi, Qr, Qi = P.real, P.imag, iOP.real, iOP.imag
        exp, cos, sin = math.exp, math.cos, math.sin

        def fast(t: float):
            try:
                return _fast(t)
            except ValueError:                     # sin/cos of an overflowed argument: nan as numpy gives
                return slow(t)

        def _fast(t: float):
            y = ws * t
            ex, c = exp(-sig * t), cos(y)
            ts = t * (sin(y) / y) if y else t
            u = Om * t
            ec, es = cos(u), sin(u)
            return L + ex * (w0 * c + b * ts) + (Pr * es + Pi * ec), ex * (wd0 * c - K * ts) + (Qr * es + Qi * ec)
        return fast

    def acceleration_at(self, t, x, v, X=math):
        """ẍ from (17.15a) at a known (x, v) (plain floats, or arrays with ``X = numpy``)."""
        s, sd = self.s0 * X.sin(self.Om * t), self.s0 * self.Om * X.cos(self.Om * t)
        f = 0.0 if self.fo is None else self.fo[0] * X.sin(self.fo[1] * t) / self.p.m
        wn = self.omega_n
        return -wn * wn * (x - s - self.L) - 2.0 * self.zeta * wn * (v - sd) + f

    def _steady(self):
        """(the complex amplitude P of the steady state x − L = Im(P e^(iΩt)), Ω), or (None, None)."""
        Om = self.fo[1] if self.fo is not None else self.Om
        r = Om / self.omega_n
        D = complex(1.0 - r * r, 2.0 * self.zeta * r)
        if D == 0:
            return None, None
        if self.fo is not None:
            return (self.fo[0] / (self.p.m * self.omega_n ** 2)) / D, Om
        return self.s0 * complex(1.0, 2.0 * self.zeta * r) / D, Om

    def motion(self) -> turns.Motion:
        """The equation of motion and initial conditions of w = x − s − L (:mod:`.turns`)."""
        p = self.p
        if self.fo is not None:
            return turns.Motion(self.omega_n, self.zeta, self.x0 - self.L, p.v0, self.fo[0] / p.m, self.fo[1])
        s0, Om = self.s0, self.Om
        return turns.Motion(self.omega_n, self.zeta, self.x0 - self.L, p.v0 - s0 * Om, s0 * Om * Om, Om, s0)

    def step(self) -> float:
        """1/PER_PERIOD of the shortest period of the motion [s]."""
        _, _, lam2 = cf.roots(self.omega_n, self.zeta)
        rate = max(self.omega_n, lam2 if self.zeta >= 1 else 0.0, self.Om, self.fo[1] if self.fo else 0.0)
        return 2.0 * math.pi / rate / PER_PERIOD

    def resolved_end(self, t_end: float) -> float:
        """The end of the span whose turning points a grid of MAX_PIECES breaks resolves (t_end,
        or MAX_PIECES eighths of the shortest period when the span is longer)."""
        h = self.step()
        return t_end if not h > 0 or t_end <= MAX_PIECES * h else MAX_PIECES * h

    def capped(self, t_end: float) -> bool:
        """Whether :meth:`breaks` over [0, t_end] is capped (without making the grid)."""
        h = self.step()
        return h > 0 and t_end > 0 and math.ceil(t_end / h) > MAX_PIECES

    def breaks(self, t_end: float) -> tuple[list[float], bool]:
        """Every 1/PER_PERIOD of the shortest period over [0, t_end] (and whether capped)."""
        h = self.step()
        n = math.ceil(t_end / h) if h > 0 and t_end > 0 else 1
        capped = n > MAX_PIECES
        n = min(max(n, 1), MAX_PIECES)
        return [t_end * k / n for k in range(n + 1)], capped


def report(p: Setup, res, omega_n, zeta) -> None:
    """``distance`` at the times of ``at`` and the ``find`` answers."""
    if not p.at and not p.find:
        return
    params = resolve_params(dict(p.params))
    const = lambda text: constant(text, params)      # noqa: E731
    t_end = mf.search_end(max([p.t_end or 0.0] + list(p.at)), p.find, const)
    resp = Response(p, omega_n, zeta)
    forced = not (resp.fo is None and resp.s0 == 0.0)
    t_odo = resp.resolved_end(t_end) if forced else t_end
    odo = _odometer(resp, t_odo)
    if t_odo < t_end:           # a forced motion's turning points are found one by one: not that far
        odo = _Odometer(lambda ts, many=odo.many: [None if t > t_odo else d
                                                    for t, d in zip(ts, many([min(t, t_odo) for t in ts]))])
        res.warn(f"distance is null after t = {t_odo:.6g} s: a forced motion's distance adds its turning "
                 f"points one by one, and beyond {MAX_PIECES} eighths of a period ({t_end:.6g} s asked) "
                 "they are not followed (ask for earlier times)")
    if p.at:
        res.results["distance"] = odo.many(list(p.at))
    if not p.find:
        return
    capped = resp.capped(t_end)
    asked = _asked_paths(list(p.find))
    # a capped grid has far too many turning points; a search with a window that a grid of
    # MAX_PIECES resolves has its window's turning points found exactly, added to the grid
    windows, unresolved = _windows(list(p.find), const, resp.step(), t_end) if capped and asked is not None \
        else ([], ["find"])
    exact = asked is not None and not capped    # (a capped grid: far too many turning points)
    if exact and asked is not None and t_end > 0:   # every turning point of each quantity asked is a break: monotone between
        own, capped = _turning_points(resp, lambda: resp.breaks(t_end)[0], t_end, asked)
        breaks = sorted(set([0.0, t_end]).union(*own.values()))
    else:
        breaks = resp.breaks(t_end)[0]
    if windows and asked is not None:
        inside, more = _window_turning_points(resp, windows, asked)
        breaks = sorted(set(breaks).union(*inside.values(), *windows))
        own = {path: breaks for path in inside}
        exact, capped = True, bool(unresolved) or more
    if capped:
        which = f" ({', '.join(unresolved)}: no `within` window of at most {MAX_PIECES} eighths)" \
            if windows and unresolved and unresolved != ["find"] else ""
        res.warn(f"find: the motion to t = {t_end:g} s spans more than {MAX_PIECES} eighths of a period{which}; "
                 "turning points closer than the coarser grid may be missed (shorten the window with within)")

    # a capped grid (far more turning points than cells) is read as monotone between its breaks: the
    # answers are the grid's, as the warning says (a search for dips inside each of 20,000 cells that
    # each hold many periods cost seconds for nothing better)
    motion = _Motion(resp, odo, t_end, breaks, 1 if exact or capped else None, monotone=exact or capped)
    at = motion.at          # (resp.at, or a free vibration's with its constants hoisted: the same doubles)

    def state(t: float) -> dict:
        xx, v, w = at(t)
        return {"x": xx, "v": v, "w": w, "distance": odo(t)}

    if exact and t_end > 0:
        motion.own = {path: [0.0] + sorted(t for t in ts if 0.0 < t < t_end) + [motion.t_end]
                      for path, ts in own.items()}
    find = list(p.find)
    mf.attach(res, find, mf.answer_find(find, motion, const, res.warn, full=state, memo=p.params))


def _windows(find, const, h: float, t_end: float) -> tuple[list[tuple[float, float]], list[str]]:
    """(the ``within`` windows of the searches (when, max, min) that a grid of 1/PER_PERIOD of the
    shortest period, ``h``, no longer than MAX_PIECES resolves; the searches left to the capped
    grid, find.N: no window, or one too long)."""
    out, unresolved = [], []
    for i, q in enumerate(find):
        if not isinstance(q, dict) or not any(k in q for k in ("when", "max", "min")):
            continue
        w = q.get("within")
        try:
            a, b = (min(max(float(const(x)), 0.0), t_end) for x in w) if isinstance(w, (list, tuple)) \
                and len(w) == 2 else (0.0, 0.0)
        except (InputError, ValueError, TypeError, ArithmeticError):
            a = b = 0.0
        if h > 0 and b > a and math.ceil((b - a) / h) <= MAX_PIECES:
            out.append((a, b))
        else:
            unresolved.append(f"find.{i}")
    return out, unresolved


def _derivatives(resp: Response) -> dict:
    """{quantity: (the motion, the derivative whose roots are its turning points)}: x and the
    distance turn where v = 0, v where the acceleration does, w = x − s − L where ẇ does (the
    same equation without the base motion s)."""
    mo = resp.motion()
    wo = replace(mo, s0=0.0) if mo.s0 != 0.0 else mo
    return {"x": (mo, 1), "distance": (mo, 1), "v": (mo, 2), "w": (wo, 1)}


def _window_turning_points(resp: Response, windows: list[tuple[float, float]], asked: set[str]):
    """As :func:`_turning_points`, only inside each window (its own grid of 1/PER_PERIOD of the
    shortest period): a search late in a long motion asks for no turning point before it."""
    which = _derivatives(resp)
    h = resp.step()
    out: dict[str, list[float]] = {}
    capped = False
    for path in sorted(asked):
        m, d = which[path]
        got: list[float] = []
        for a, b in windows:
            n = max(math.ceil((b - a) / h), 1)
            grid = [a + (b - a) * k / n for k in range(n + 1)]
            roots, _touch, more = turns.roots(m, grid, d, _on_arrays(len(grid)))
            got += roots
            capped = capped or more
        out[path] = sorted(set(got))
    return out, capped


def _turning_points(resp: Response, grid, t_end: float, asked: set[str]):
    """({quantity: its turning points in (0, t_end)} for every quantity in ``asked``, whether a
    search ran out of cells): of x (the roots of v; also the kinks of distance), of v (the roots of the
    acceleration) and of w (the roots of ẇ; w = x − L without a base motion, so x's), each in
    closed form for an underdamped free vibration, else by the sign analysis of :mod:`.turns` on
    the breaks ``grid()`` (made only then)."""
    breaks = None
    which = _derivatives(resp)
    found: dict = {}
    out, capped = {}, False
    for path in sorted(asked):
        key = which[path]
        if key not in found:
            got = turns.free_roots(key[0], key[1], t_end)
            if got is None:
                if breaks is None:
                    breaks = grid()
                    arrays = _on_arrays(len(breaks))
                got, _, more = resp.roots(key[0], key[1], t_end, arrays)
                capped = capped or more
            found[key] = got
        out[path] = found[key]
    return out, capped


def _asked_paths(find) -> set[str] | None:
    """The quantities the queries ask about (x, v, w, distance), or None when a query is not one
    of them (malformed: left to the queries' own messages).  Each is monotone between its
    turning points (distance between those of x), so a search over those points alone is exact."""
    ok, asked = {"x", "v", "w", "distance"}, set()
    for q in find if isinstance(find, (list, tuple)) else ():
        if not isinstance(q, dict):
            return None
        when = q.get("when")
        paths = list(when) if isinstance(when, dict) else [q[k] for k in ("max", "min") if k in q]
        if not all(isinstance(x, str) and x in ok for x in paths):
            return None
        asked.update(paths)
    return asked


_STATE = {"x": 0, "v": 1, "w": 2}        # the place of each quantity in Response.at's (x, v, w)


class _Motion:
    """The motion searched by ``find`` (:mod:`dyncli.queries`): each quantity and its exact rate
    computed alone (a search asks for one at a time), no state dictionaries."""

    t0 = 0.0
    rtol = 0.0

    def __init__(self, resp: Response, odo, t_end: float, breaks: list[float], subdivide: int | None,
                 monotone: bool = False):
        self.resp, self.odo, self.t_end = resp, odo, float(t_end)
        self.monotone = monotone        # the breaks hold every turning point of each quantity asked
        self.own: dict[str, list[float]] = {}     # each quantity's own breaks (its turning points)
        self.breaks = [0.0] + sorted({float(b) for b in breaks if 0.0 < b < t_end}) + [self.t_end]
        self.subdivide = subdivide
        self.period = None
        self.at = resp.fast_at() or resp.at
        self.samples: dict = {}         # (path, times) -> values: the queries on one result share its grid

    def paths(self) -> list[str]:
        return ["distance", "v", "w", "x"]

    def breaks_for(self, path: str) -> list[float]:
        """The breaks searched for ``path``: its own turning points when known, else all."""
        return self.own.get(path, self.breaks)

    def function(self, path: str):
        """t -> the value of ``path`` (:meth:`value` without its dispatch): a free vibration's x, v
        or w alone (:func:`closed_form.free_quantity_fn`, the same doubles), else from :meth:`at`."""
        if path == "distance":
            return self.odo
        i = _STATE.get(path)
        if i is None:
            return None
        r = self.resp
        if r.fo is None and r.s0 == 0.0:
            got = cf.free_quantity_fn(r.omega_n, r.zeta, r.L, r.x0, r.p.v0, i)
            if got is not None:
                return got
        at = self.at
        return lambda t: at(t)[i]

    def value(self, path: str, t: float) -> float:
        if path == "distance":
            return self.odo(t)
        i = _STATE.get(path)
        if i is None:
            raise KeyError(path)
        return self.at(t)[i]

    def rate(self, path: str, t: float) -> float | None:
        r = self.resp
        if path == "x":
            return self.at(t)[1]
        if path == "v":
            return r.acceleration_at(t, *self.at(t)[:2])
        if path == "w":
            return self.at(t)[1] - r.s0 * r.Om * math.cos(r.Om * t)
        return abs(self.at(t)[1]) if path == "distance" else None

    def clipped(self, t_end: float) -> "_Motion":
        out = _Motion(self.resp, self.odo, t_end, self.breaks, self.subdivide, self.monotone)
        out.own = {k: [b for b in v if b < t_end] + [float(t_end)] for k, v in self.own.items()}
        return out


def _odometer(resp: Response, t_end: float):
    """distance(t) for 0 <= t <= t_end."""
    if resp.fo is None and resp.s0 == 0.0:
        return _free_odometer(resp)
    tps = _forced_turns(resp, t_end) if t_end > 0 else []
    xv = resp.scalar()              # (plain floats on every route: the same doubles, numpy loaded or not)
    xs = [xv(t)[0] for t in tps]
    return _Odometer(_turning_length(resp, tps, xs))


def _turning_length(resp: Response, tps: list[float], xs: list[float]):
    """distance(times) of a motion whose x is monotone between the turning points ``tps`` (x
    there ``xs``): Σ|Δx| accumulated once, then one evaluation of x per time asked
    (:func:`dyncli.motion_find.turning_length`, the same sums, without a call per turning point)."""
    import bisect

    x0 = resp.at(0.0)[0]
    cum, prev = [0.0], x0
    for v in xs:
        cum.append(cum[-1] + abs(v - prev))
        prev = v
    at_turns = dict(zip(tps, xs))

    def many(times) -> list[float]:
        out = []
        for t in (float(u) for u in times):
            k = bisect.bisect_left(tps, t)          # turning points strictly before t
            last = xs[k - 1] if k else x0
            x = at_turns[t] if t in at_turns else resp.at(t)[0]
            out.append(cum[k] + abs(x - last) + 0.0)
        return out
    return many


class _Odometer:
    """distance(t) for one time, ``many(times)`` for a list."""

    def __init__(self, many, one=None):
        self.many = many
        self.one = one

    def __call__(self, t: float) -> float:
        return self.one(t) if self.one is not None else self.many([t])[0]


def _free_odometer(resp: Response):
    """Free vibration: the turning points and the distance in closed form."""
    wn, z = resp.omega_n, resp.zeta
    w0, wd0 = resp.x0 - resp.L, resp.p.v0
    ws, _, _ = cf.roots(wn, z)
    w = lambda t: cf.free_at(t, w0, wd0, wn, z)[0]    # noqa: E731
    if z < 1.0:
        # v = e^(−ζωₙt)(ẇ0 cos ω*t − K sin ω*t / ω*), K = ωₙ²w0 + ζωₙẇ0: R cos(ω*t + β)
        K = wn * (wn * w0) + z * wn * wd0
        beta = math.atan2(K / ws, wd0)
        y1 = (0.5 * math.pi - beta) % math.pi         # the first root of ω*t + β = π/2 + kπ in (0, π]
        if y1 == 0.0:
            y1 = math.pi
        t1, half = y1 / ws, math.pi / ws
        decay = z * wn * half                         # ln of the ratio of successive |w| at turning points
        fast = resp.fast_at()                         # the same doubles as free_at, constants hoisted
        if fast is not None:
            w = lambda t: fast(t)[2]                  # noqa: E731
        w1 = w(t1)
        a1, first = abs(w1), abs(w1 - w0)
        c1, em1 = a1 * (1.0 + math.exp(-decay)), math.expm1(-decay)     # (the series' constants)

        def odometer(t: float) -> float:
            if (w0 == 0.0 and wd0 == 0.0) or t <= t1:
                return abs(w(t) - w0)
            k = math.floor((t - t1) / half)           # turning points t1 + j·half, j = 0..k, at or before t
            tk = t1 + k * half
            inner = 2.0 * a1 * k if decay == 0.0 else c1 * math.expm1(-k * decay) / em1
            return first + inner + abs(w(t) - w(tk))
        return _Odometer(lambda ts: [odometer(t) for t in ts], odometer)
    # ζ ≥ 1: v vanishes at most once (a sum of two decaying exponentials)
    v = lambda t: cf.free_at(t, w0, wd0, wn, z)[1]    # noqa: E731
    cache: dict[float, list[float]] = {}

    def distance(t: float) -> float:
        if t not in cache:
            turn = []
            if t > 0 and v(0.0) * v(t) < 0:
                from dyncli.rootfind import root

                turn = [root(v, 0.0, t)]
            cache[t] = turn
        knots = [0.0] + cache[t] + [t]
        return sum(abs(w(b) - w(a)) for a, b in zip(knots, knots[1:])) + 0.0
    return _Odometer(lambda ts: [distance(t) for t in ts], distance)


#: up to this many grid points the turning points are found in plain floats (no numpy import:
#: a closed-form problem starts at the import floor), beyond it on arrays
SCALAR_GRID = 2048
#: grid points a process searches in plain floats before it imports numpy for the rest: about as
#: much work as numpy's import (~0.1 s), so a single problem never pays it and a sweep or a batch
#: of long searches (a forced motion's distance, every point) pays it once
FLOAT_BUDGET = 20_000
_spent = [0]


def _on_arrays(n: int) -> bool:
    """Whether n points go on numpy arrays: when they are many, when numpy is loaded already (a
    sweep through the Python API), or once this process has searched FLOAT_BUDGET points in plain
    floats (a sweep from the command line) — one vectorised pass then costs less than n calls."""
    if n > SCALAR_GRID or "numpy" in sys.modules or _spent[0] + n > FLOAT_BUDGET:
        return True
    _spent[0] += n
    return False


def _forced_turns(resp: Response, t_end: float) -> list[float]:
    """The roots of v in (0, t_end) with a base motion or a force, decided exactly by the sign
    analysis of :mod:`.turns` on the grid of breaks (on arrays when numpy is loaded already or
    the grid is long; in plain floats otherwise: a cold closed-form solve stays at the import
    floor)."""
    found, _, _ = resp.roots(resp.motion(), 1, t_end)
    return [t for t in found if 0.0 < t < t_end]
