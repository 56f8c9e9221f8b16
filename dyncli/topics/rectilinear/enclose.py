"""Interval enclosures of an expression of t over a cell (issue #28: what sampling cannot see).

``enclose(ir, lo, hi)`` bounds every value of the expression for t in [lo, hi] (interval
arithmetic on the IR, node by node, rounded outward; (-inf, inf) where it cannot say: a possible
pole, a value outside a function's domain).  :func:`hidden` bisects a stretch of time where the
enclosure of a exceeds what samples of a show, so that a feature narrower than any grid (a pulse
1e-6 of the span wide) is located by bounds, not by luck.
"""

from __future__ import annotations

import math

import numpy as np

INF = math.inf
WHOLE = (-INF, INF)
_PI = math.pi


def _out(lo: float, hi: float) -> tuple[float, float]:
    if math.isnan(lo) or math.isnan(hi):
        return WHOLE
    return (math.nextafter(math.nextafter(lo, -INF), -INF), math.nextafter(math.nextafter(hi, INF), INF))


def _m(x: float, y: float) -> float:
    return 0.0 if x == 0 or y == 0 else x * y


def _mul(a, b):
    p = (_m(a[0], b[0]), _m(a[0], b[1]), _m(a[1], b[0]), _m(a[1], b[1]))
    return _out(min(p), max(p))


def _f(fn, x: float) -> float:
    try:
        return fn(x)
    except OverflowError:
        return INF
    except ValueError:
        return math.nan


def _mono(fn, a, dom=(-INF, INF)):
    """A function increasing on its domain ``dom`` (closed)."""
    if a[0] < dom[0] or a[1] > dom[1]:
        return WHOLE
    return _out(_f(fn, a[0]), _f(fn, a[1]))


def _sin(a):
    lo, hi = a
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi - lo >= 2 * _PI:
        return (-1.0, 1.0)
    ys = [math.sin(lo), math.sin(hi)]
    k = math.ceil((lo - _PI / 2) / (2 * _PI) - 1e-9)
    top = _PI / 2 + 2 * _PI * k <= hi * (1 + 1e-15) + 1e-15
    k = math.ceil((lo + _PI / 2) / (2 * _PI) - 1e-9)
    bottom = -_PI / 2 + 2 * _PI * k <= hi * (1 + 1e-15) + 1e-15
    lo_, hi_ = _out(min(ys), max(ys))
    return (-1.0 if bottom else max(lo_, -1.0), 1.0 if top else min(hi_, 1.0))


def _pow(a, b):
    if b[0] != b[1]:                                 # a variable exponent: exp(b log a)
        return _mono(math.exp, _mul(b, _mono(math.log, a, (0.0, INF))))
    n = b[0]
    p = lambda x: _f(lambda y: math.pow(y, n), x)    # noqa: E731
    if n == int(n) and abs(n) < 2 ** 53:
        if n == 0:
            return (1.0, 1.0)
        if n < 0:
            q = _pow(a, (-n, -n))
            return WHOLE if q[0] <= 0 <= q[1] else _mul((1.0, 1.0), _out(1 / q[1], 1 / q[0]))
        if int(n) % 2 == 1:
            return _out(p(a[0]), p(a[1]))
        if a[0] >= 0:
            return _out(p(a[0]), p(a[1]))
        if a[1] <= 0:
            return _out(p(a[1]), p(a[0]))
        return _out(0.0, max(p(a[0]), p(a[1])))
    if a[0] < 0:
        return WHOLE
    if n > 0:
        return _out(p(a[0]), p(a[1]))
    return WHOLE if a[0] == 0 else _out(p(a[1]), p(a[0]))


def _call(name: str, args: list):
    a = args[0]
    if name in ("min", "max"):
        pick = min if name == "min" else max
        return (pick(x[0] for x in args), pick(x[1] for x in args))
    if name == "sin":
        return _sin(a)
    if name == "cos":
        return _sin(_out(a[0] + _PI / 2, a[1] + _PI / 2))
    if name == "tan":
        if not (math.isfinite(a[0]) and math.isfinite(a[1])):
            return WHOLE
        k = math.floor((a[0] - _PI / 2) / _PI)
        return WHOLE if _PI / 2 + _PI * (k + 1) <= a[1] + 1e-12 else _mono(math.tan, a)
    if name == "cosh":
        c = _mono(math.cosh, (0.0, max(abs(a[0]), abs(a[1]))))
        return (1.0 if a[0] <= 0 <= a[1] else min(_f(math.cosh, a[0]), _f(math.cosh, a[1])) * (1 - 1e-15), c[1])
    if name == "abs":
        if a[0] >= 0:
            return a
        if a[1] <= 0:
            return (-a[1], -a[0])
        return (0.0, max(-a[0], a[1]))
    if name == "sign":
        return (float(np.sign(a[0])), float(np.sign(a[1])))
    if name == "acos":
        r = _mono(math.asin, a, (-1.0, 1.0))
        return _out(_PI / 2 - r[1], _PI / 2 - r[0])
    if name == "atan2":
        return (-_PI, _PI)
    fn, dom = {"asin": (math.asin, (-1.0, 1.0)), "atan": (math.atan, WHOLE), "sinh": (math.sinh, WHOLE),
               "tanh": (math.tanh, WHOLE), "exp": (math.exp, WHOLE), "log": (math.log, (0.0, INF)),
               "log10": (math.log10, (0.0, INF)), "sqrt": (math.sqrt, (0.0, INF))}[name]
    if name in ("log", "log10") and a[0] == 0:
        return (-INF, _f(fn, a[1]))
    return _mono(fn, a, dom)


def enclose(n: tuple, t: tuple[float, float], var: str = "t") -> tuple[float, float]:
    """Bounds of the expression ``n`` (IR) for every value of its variable ``var`` in ``t``."""
    k = n[0]
    if k == "num":
        return (n[1], n[1])
    if k == "param":
        return (n[2], n[2])
    if k == "var":
        return t if n[1] == var else WHOLE
    if k == "neg":
        a = enclose(n[1], t, var)
        return (-a[1], -a[0])
    if k == "call":
        return _call(n[1], [enclose(x, t, var) for x in n[2]])
    a, b = enclose(n[1], t, var), enclose(n[2], t, var)
    if k == "add":
        return _out(a[0] + b[0], a[1] + b[1])
    if k == "sub":
        return _out(a[0] - b[1], a[1] - b[0])
    if k == "mul":
        return _mul(a, b)
    if k == "div":
        return WHOLE if b[0] <= 0 <= b[1] else _mul(a, _out(1 / b[1], 1 / b[0]))
    return _pow(a, b)


def safe_enclose(ir: tuple, lo: float, hi: float, var: str = "t") -> tuple[float, float]:
    try:
        r = enclose(ir, (lo, hi), var)
    except (OverflowError, ZeroDivisionError, ValueError, RecursionError):
        return WHOLE
    return WHOLE if (math.isnan(r[0]) or math.isnan(r[1])) else r


def hidden(ir: tuple, dir_: tuple | None, A, lo: float, hi: float, cells: int = 64, budget: int = 4000,
           var: str = "t"):
    """The cells of [lo, hi] where a (IR ``ir``, its derivative's IR ``dir_`` or None; ``A`` its
    evaluator on arrays) may hold what samples do not show: each of ``cells`` starting cells is
    halved while the enclosure of a over it (the narrower of the natural one and the mean-value
    form a(mid) + a'(cell)·[−h/2, h/2]) exceeds the range of 9 samples by more than 4 times that
    range (and 1e-12 of a's scale), to 40 halvings: ((u, v) leaves that were halved at least once, budget spent).
    A cell the enclosure cannot bound (a pole, a domain's edge) is left to the sampling analysis.
    ``var``: the expression's variable (t in case 2, s in case 4)."""
    k9 = np.linspace(0.0, 1.0, 9)

    def samples(us, vs):
        us, vs = np.asarray(us, dtype=float), np.asarray(vs, dtype=float)
        with np.errstate(all="ignore"):
            y = np.asarray(A((us[:, None] + (vs - us)[:, None] * k9[None, :]).ravel()), dtype=float)
        return y.reshape(us.size, 9)

    edges = np.linspace(lo, hi, cells + 1)
    Y = samples(edges[:-1], edges[1:])
    fin = np.isfinite(Y)
    tau = max(1e-12 * float(np.max(np.abs(Y[fin]), initial=0.0)), 1e-290)
    stack = [(float(u), float(v), Y[j], 0) for j, (u, v) in enumerate(zip(edges[:-1], edges[1:]))][::-1]
    out: list[tuple[float, float]] = []
    spent = False
    while stack:
        u, v, y, depth = stack.pop()
        if not np.all(np.isfinite(y)):
            continue
        m, M = safe_enclose(ir, u, v, var)
        if dir_ is not None:
            d = safe_enclose(dir_, u, v, var)
            h = 0.5 * (v - u)
            mid = float(y[4])
            if math.isfinite(d[0]) and math.isfinite(d[1]):
                r = max(abs(d[0]), abs(d[1])) * h * (1 + 1e-12)
                m, M = max(m, mid - r), min(M, mid + r)
        if not (math.isfinite(m) and math.isfinite(M)):
            continue
        ymin, ymax = float(np.min(y)), float(np.max(y))
        if (max(M - ymax, ymin - m) <= 4 * (ymax - ymin) + tau or depth >= 40
                or v - u <= 8 * np.finfo(float).eps * max(abs(u), abs(v))):
            if depth:
                out.append((u, v))
            continue
        if (budget := budget - 1) < 0:
            spent = True
            out.append((u, v))
            continue
        w = 0.5 * (u + v)
        y2 = samples([u, w], [w, v])
        stack += [(w, v, y2[1], depth + 1), (u, w, y2[0], depth + 1)]
    return sorted(out), spent
