"""Exact first and second time derivatives of user expressions by
forward-mode automatic differentiation (second-order "jets").

Every node of the validated expression IR (:mod:`dyncli.expr`) is evaluated
to a triple ``(f, f', f'')`` of numpy arrays with the chain rule written out
for each operation and function of the language, e.g. for ``sin(u)``::

    (sin u,  cos u · u',  cos u · u'' − sin u · u'²)

The derivatives are exact (no truncation error; only the rounding of the
arithmetic, like evaluating the derivative formula itself) and never use
finite differences.  Nothing is parsed from text and sympy is not imported:
this is the route the numeric solvers of ``kinematics`` and
``rotating-frame`` use (see ``benchmarks/kinematics_derivatives.py`` for the
comparison with :func:`dyncli.symbolic.diff`; sympy is imported only for
``--symbolic`` formula tables).

Where a derivative does not exist (``sqrt`` at 0, ``abs``/``sign``/``min``/
``max`` at a kink) the values follow the one-sided conventions of sympy's
derivatives (``d|u|/dt = sign(u) u'``, ``d sign(u)/dt = 0``) or become
non-finite, which the solvers report as ``null`` with a warning.
"""

from __future__ import annotations

import math
from types import ModuleType, SimpleNamespace
from typing import TYPE_CHECKING, Any, Callable, Mapping, Union

from dyncli.expr import Expr
from dyncli.expr import floatmath

if TYPE_CHECKING:
    import numpy as np

Jet = tuple  # (f, f', f'') — arrays or floats
#: the functions the rules call: numpy (arrays over t) or :mod:`floatmath` (one float t)
Backend = Union[SimpleNamespace, ModuleType]

_ZERO = 0.0
_NUMPY: SimpleNamespace | None = None


def numpy_backend() -> SimpleNamespace:
    """numpy's functions under the names the rules use (imports numpy)."""
    global _NUMPY
    if _NUMPY is None:
        import numpy as np

        _NUMPY = SimpleNamespace(
            sin=np.sin, cos=np.cos, tan=np.tan, arcsin=np.arcsin, arccos=np.arccos, arctan=np.arctan,
            sinh=np.sinh, cosh=np.cosh, tanh=np.tanh, exp=np.exp, log=np.log, sqrt=np.sqrt, fabs=np.abs,
            sign=np.sign, div=np.true_divide, power=np.power, arctan2=np.arctan2, where=np.where, f64=np.float64,
            ones=lambda t: np.ones_like(t, dtype=float), zeros=lambda t: np.zeros_like(t, dtype=float))
    return _NUMPY


def _const(v: float, X: Backend):
    c = (X.f64(v), _ZERO, _ZERO)
    return (lambda env: c), True


def _folded(fn, const: bool, ir: tuple, X: Backend):
    """(fn, const), with a constant of numbers alone (no variable at all) evaluated once, on the
    float backend: the same jet, computed at compile time (a number's jet does not change)."""
    if const and X is floatmath and _numbers_only(ir):
        try:
            c = fn({})
        except (ArithmeticError, ValueError):     # evaluated per call, as before
            return fn, const
        return (lambda env: c), True
    return fn, const


def _numbers_only(ir: tuple) -> bool:
    """The expression holds numbers (and parameters) only: no variable at all."""
    k = ir[0]
    if k in ("num", "param"):
        return True
    if k == "var":
        return False
    if k == "neg":
        return _numbers_only(ir[1])
    if k == "call":
        return all(_numbers_only(a) for a in ir[2])
    return _numbers_only(ir[1]) and _numbers_only(ir[2])


def _is_const_ir(ir: tuple, var: str) -> bool:
    k = ir[0]
    if k in ("num", "param"):
        return True
    if k == "var":
        return ir[1] != var
    if k == "neg":
        return _is_const_ir(ir[1], var)
    if k in ("add", "sub", "mul", "div", "pow"):
        return _is_const_ir(ir[1], var) and _is_const_ir(ir[2], var)
    if k == "call":
        return all(_is_const_ir(a, var) for a in ir[2])
    raise AssertionError(k)  # pragma: no cover


def _unary(name: str, u: Jet, X: Backend) -> Jet:
    f0, f1, f2 = u
    if name == "sin":
        s, c = X.sin(f0), X.cos(f0)
        return s, c * f1, c * f2 - s * f1 * f1
    if name == "cos":
        s, c = X.sin(f0), X.cos(f0)
        return c, -s * f1, -s * f2 - c * f1 * f1
    if name == "tan":
        T = X.tan(f0)
        d = 1.0 + T * T
        return T, d * f1, d * (f2 + 2.0 * T * f1 * f1)
    if name == "asin":
        w = 1.0 - f0 * f0
        d = X.div(1.0, X.sqrt(w))
        return X.arcsin(f0), d * f1, d * f2 + X.div(f0 * d, w) * f1 * f1
    if name == "acos":
        w = 1.0 - f0 * f0
        d = X.div(1.0, X.sqrt(w))
        return X.arccos(f0), -d * f1, -(d * f2 + X.div(f0 * d, w) * f1 * f1)
    if name == "atan":
        w = X.div(1.0, 1.0 + f0 * f0)
        return X.arctan(f0), w * f1, w * f2 - 2.0 * f0 * w * w * f1 * f1
    if name == "sinh":
        sh, ch = X.sinh(f0), X.cosh(f0)
        return sh, ch * f1, ch * f2 + sh * f1 * f1
    if name == "cosh":
        sh, ch = X.sinh(f0), X.cosh(f0)
        return ch, sh * f1, sh * f2 + ch * f1 * f1
    if name == "tanh":
        T = X.tanh(f0)
        d = 1.0 - T * T
        return T, d * f1, d * (f2 - 2.0 * T * f1 * f1)
    if name == "exp":
        E = X.exp(f0)
        return E, E * f1, E * (f2 + f1 * f1)
    if name in ("log", "log10"):
        scale = 1.0 if name == "log" else 1.0 / math.log(10.0)
        q = X.div(f1, f0)
        return X.log(f0) * scale, q * scale, (X.div(f2, f0) - q * q) * scale
    if name == "sqrt":
        S = X.sqrt(f0)
        h = X.div(0.5, S)
        return S, h * f1, h * f2 - h * h * h * 2.0 * f1 * f1
    if name == "abs":
        sg = X.sign(f0)
        return X.fabs(f0), sg * f1, sg * f2
    if name == "sign":
        return X.sign(f0), _ZERO * f1, _ZERO * f2
    raise AssertionError(name)  # pragma: no cover


def _mul(a: Jet, b: Jet) -> Jet:
    return a[0] * b[0], a[1] * b[0] + a[0] * b[1], a[2] * b[0] + 2.0 * a[1] * b[1] + a[0] * b[2]


def _div(a: Jet, b: Jet, X: Backend) -> Jet:
    q0 = X.div(a[0], b[0])
    q1 = X.div(a[1] - q0 * b[1], b[0])
    q2 = X.div(a[2] - 2.0 * q1 * b[1] - q0 * b[2], b[0])
    return q0, q1, q2


def _pow_const_exponent(a: Jet, n: float, X: Backend) -> Jet:
    if n == 0.0:
        return X.f64(1.0) + 0.0 * a[0], _ZERO, _ZERO
    if n == 1.0:
        return a
    a0 = X.f64(1.0) * a[0]
    if n == 2.0:
        return a0 * a0, 2.0 * a0 * a[1], 2.0 * (a[1] * a[1] + a0 * a[2])
    p1 = X.power(a0, n - 1.0)          # a^(n-1)
    f0 = X.power(a0, n)
    d1 = n * p1
    d2 = n * (n - 1.0) * X.power(a0, n - 2.0)
    return f0, d1 * a[1], d1 * a[2] + d2 * a[1] * a[1]


def _pow(a: Jet, b: Jet, b_const: bool, X: Backend) -> Jet:
    if b_const:
        return _pow_const_exponent(a, float(b[0]), X)
    # a**b = exp(b log a)  (a > 0; a <= 0 with a variable exponent is not real)
    a0 = X.f64(1.0) * a[0]
    la = X.log(a0)
    f0 = X.power(a0, b[0])
    q = X.div(a[1], a0)
    g1 = b[1] * la + b[0] * q
    g2 = b[2] * la + 2.0 * b[1] * q + b[0] * (X.div(a[2], a0) - q * q)
    return f0, f0 * g1, f0 * (g2 + g1 * g1)


def _atan2(y: Jet, x: Jet, X: Backend) -> Jet:
    D = x[0] * x[0] + y[0] * y[0]
    N = x[0] * y[1] - y[0] * x[1]
    dN = x[0] * y[2] - y[0] * x[2]
    dD = 2.0 * (x[0] * x[1] + y[0] * y[1])
    d1 = X.div(N, D)
    d2 = X.div(dN - d1 * dD, D)
    return X.arctan2(y[0], x[0]), d1, d2


def _select(args: list[Jet], pick_min: bool, X: Backend) -> Jet:
    out = args[0]
    for b in args[1:]:
        cond = (out[0] <= b[0]) if pick_min else (out[0] >= b[0])
        out = tuple(X.where(cond, out[i], b[i]) for i in range(3))
    return out


def compile_jet(ir: tuple, var: str = "t", X: Backend | None = None) -> Callable[[Mapping[str, Any]], Jet]:
    """Compile an IR tree into ``env -> (f, df/dvar, d²f/dvar²)`` (numpy's functions unless
    ``X`` is :mod:`floatmath`)."""
    fn, _ = _compile(ir, var, numpy_backend() if X is None else X)
    return fn


def _compile(ir: tuple, var: str, X: Backend):
    kind = ir[0]
    if kind == "num":
        return _const(ir[1], X)
    if kind == "param":
        return _const(ir[2], X)
    if kind == "var":
        name = ir[1]
        if name == var:
            if X is floatmath:              # one float: the unit seed as constants (no call per evaluation)
                return (lambda env: (env[name], 1.0, 0.0)), False

            def v(env):
                t = env[name]
                return t, X.ones(t), X.zeros(t)
            return v, False

        def other(env):
            return env[name], _ZERO, _ZERO
        return other, True
    if kind == "neg":
        a, c = _compile(ir[1], var, X)

        def neg(env):
            f = a(env)
            return -f[0], -f[1], -f[2]
        return _folded(neg, c, ir, X)
    if kind in ("add", "sub", "mul", "div", "pow"):
        a, ca = _compile(ir[1], var, X)
        b, cb = _compile(ir[2], var, X)
        if kind == "add":
            def add(env):
                f, g = a(env), b(env)
                return f[0] + g[0], f[1] + g[1], f[2] + g[2]
            return _folded(add, ca and cb, ir, X)
        if kind == "sub":
            def sub(env):
                f, g = a(env), b(env)
                return f[0] - g[0], f[1] - g[1], f[2] - g[2]
            return _folded(sub, ca and cb, ir, X)
        if kind == "mul":
            return _folded(lambda env: _mul(a(env), b(env)), ca and cb, ir, X)
        if kind == "div":
            return (lambda env: _div(a(env), b(env), X)), ca and cb
        return (lambda env: _pow(a(env), b(env), cb, X)), ca and cb
    if kind == "call":
        name = ir[1]
        parts = [_compile(x, var, X) for x in ir[2]]
        fns = [p[0] for p in parts]
        const = all(p[1] for p in parts)
        if name == "atan2":
            return (lambda env: _atan2(fns[0](env), fns[1](env), X)), const
        if name in ("min", "max"):
            pick_min = name == "min"
            return (lambda env: _select([f(env) for f in fns], pick_min, X)), const
        f0 = fns[0]
        return (lambda env: _unary(name, f0(env), X)), const
    raise AssertionError(kind)  # pragma: no cover


class Lru:
    """A mapping of at most ``size`` entries, the least recently used dropped
    first (thread-safe: the Python API may solve in several threads)."""

    def __init__(self, size: int):
        import threading
        from collections import OrderedDict

        self._d: OrderedDict[Any, Any]
        self.size, self._d, self._lock = size, OrderedDict(), threading.Lock()

    def get(self, key):
        with self._lock:
            v = self._d.get(key)
            if v is not None:
                self._d.move_to_end(key)
            return v

    def put(self, key, value) -> None:
        with self._lock:
            self._d[key] = value
            self._d.move_to_end(key)
            while len(self._d) > self.size:
                self._d.popitem(last=False)

    def __len__(self) -> int:
        return len(self._d)


#: compiled jets of the expressions in use: a sweep reuses a few; a program
#: solving 10,000 distinct problems must not keep 10,000 of them (~1 kB each)
CACHE_SIZE = 256
_CACHE = Lru(CACHE_SIZE)


def _compiled(e: Expr, var: str, X: Backend | None) -> Callable:
    # keyed by the IR's repr, not the tuple: 0.0 == -0.0 (a parameter k: -0.0 would share k: 0.0's
    # compiled constants, and atan2(k, -1) turn from -π to π)
    key = (repr(e.ir), var, X is None)
    fn = _CACHE.get(key)
    if fn is None:
        fn = compile_jet(e.ir, var, X)
        _CACHE.put(key, fn)
    return fn


def jet(e: Expr, t, var: str = "t", **env: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(e, de/dvar, d²e/dvar²)`` at ``var = t`` (arrays of the shape of ``t``)."""
    import numpy as np

    fn = _compiled(e, var, None)
    t = np.asarray(t, dtype=float)
    with np.errstate(all="ignore"):
        out = fn({**env, var: t})
    return tuple(np.broadcast_to(np.asarray(x, dtype=float), t.shape).copy() for x in out)  # type: ignore[return-value]  # 3 arrays: mypy reads tuple(generator) as variadic


def jet_at(e: Expr, t: float, var: str = "t") -> tuple[float, float, float]:
    """``(e, de/dvar, d²e/dvar²)`` at one time, in plain floats (:mod:`floatmath`: no numpy,
    numpy's values: inf or nan where the arrays give them).

    >>> from dyncli.expr import parse
    >>> jet_at(parse("t**3 + sin(t)", ("t",)), 0.0)
    (0.0, 1.0, 0.0)
    """
    out = _compiled(e, var, floatmath)({var: float(t)})
    return tuple(float(x) for x in out)  # type: ignore[return-value]  # 3 floats: mypy reads tuple(generator) as variadic


def vec_jet_at(exprs, t: float, var: str = "t") -> tuple[tuple[float, ...], ...]:
    """Jets of 3 component expressions at one time: (values, first derivatives, second
    derivatives), each a 3-tuple of floats."""
    comps = [jet_at(e, t, var) for e in exprs]
    return tuple(tuple(c[k] for c in comps) for k in range(3))


def vec_jet(exprs, t, var: str = "t") -> np.ndarray:
    """Jets of 3 component expressions: array of shape (3 orders, 3 components, len(t))."""
    import numpy as np

    t = np.atleast_1d(np.asarray(t, dtype=float))
    out = np.empty((3, 3, t.size))
    for i, e in enumerate(exprs):
        f0, f1, f2 = jet(e, t, var)
        out[0, i], out[1, i], out[2, i] = f0, f1, f2
    return out
