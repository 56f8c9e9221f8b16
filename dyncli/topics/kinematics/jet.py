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
from typing import Any, Callable, Mapping

import numpy as np

from dyncli.expr import Expr

Jet = tuple  # (f, f', f'') — arrays or floats

_ZERO = 0.0


def _const(v: float):
    c = (np.float64(v), _ZERO, _ZERO)
    return (lambda env: c), True


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


def _unary(name: str, u: Jet) -> Jet:
    f0, f1, f2 = u
    if name == "sin":
        s, c = np.sin(f0), np.cos(f0)
        return s, c * f1, c * f2 - s * f1 * f1
    if name == "cos":
        s, c = np.sin(f0), np.cos(f0)
        return c, -s * f1, -s * f2 - c * f1 * f1
    if name == "tan":
        T = np.tan(f0)
        d = 1.0 + T * T
        return T, d * f1, d * (f2 + 2.0 * T * f1 * f1)
    if name == "asin":
        w = 1.0 - f0 * f0
        d = 1.0 / np.sqrt(w)
        return np.arcsin(f0), d * f1, d * f2 + f0 * d / w * f1 * f1
    if name == "acos":
        w = 1.0 - f0 * f0
        d = 1.0 / np.sqrt(w)
        return np.arccos(f0), -d * f1, -(d * f2 + f0 * d / w * f1 * f1)
    if name == "atan":
        w = 1.0 / (1.0 + f0 * f0)
        return np.arctan(f0), w * f1, w * f2 - 2.0 * f0 * w * w * f1 * f1
    if name == "sinh":
        sh, ch = np.sinh(f0), np.cosh(f0)
        return sh, ch * f1, ch * f2 + sh * f1 * f1
    if name == "cosh":
        sh, ch = np.sinh(f0), np.cosh(f0)
        return ch, sh * f1, sh * f2 + ch * f1 * f1
    if name == "tanh":
        T = np.tanh(f0)
        d = 1.0 - T * T
        return T, d * f1, d * (f2 - 2.0 * T * f1 * f1)
    if name == "exp":
        E = np.exp(f0)
        return E, E * f1, E * (f2 + f1 * f1)
    if name in ("log", "log10"):
        scale = 1.0 if name == "log" else 1.0 / math.log(10.0)
        q = f1 / f0
        return np.log(f0) * scale, q * scale, (f2 / f0 - q * q) * scale
    if name == "sqrt":
        S = np.sqrt(f0)
        h = 0.5 / S
        return S, h * f1, h * f2 - h * h * h * 2.0 * f1 * f1
    if name == "abs":
        sg = np.sign(f0)
        return np.abs(f0), sg * f1, sg * f2
    if name == "sign":
        return np.sign(f0), _ZERO * f1, _ZERO * f2
    raise AssertionError(name)  # pragma: no cover


def _mul(a: Jet, b: Jet) -> Jet:
    return a[0] * b[0], a[1] * b[0] + a[0] * b[1], a[2] * b[0] + 2.0 * a[1] * b[1] + a[0] * b[2]


def _div(a: Jet, b: Jet) -> Jet:
    q0 = np.true_divide(a[0], b[0])
    q1 = np.true_divide(a[1] - q0 * b[1], b[0])
    q2 = np.true_divide(a[2] - 2.0 * q1 * b[1] - q0 * b[2], b[0])
    return q0, q1, q2


def _pow_const_exponent(a: Jet, n: float) -> Jet:
    if n == 0.0:
        return np.float64(1.0) + 0.0 * a[0], _ZERO, _ZERO
    if n == 1.0:
        return a
    a0 = np.float64(1.0) * a[0]
    if n == 2.0:
        return a0 * a0, 2.0 * a0 * a[1], 2.0 * (a[1] * a[1] + a0 * a[2])
    p1 = np.power(a0, n - 1.0)          # a^(n-1)
    f0 = np.power(a0, n)
    d1 = n * p1
    d2 = n * (n - 1.0) * np.power(a0, n - 2.0)
    return f0, d1 * a[1], d1 * a[2] + d2 * a[1] * a[1]


def _pow(a: Jet, b: Jet, b_const: bool) -> Jet:
    if b_const:
        return _pow_const_exponent(a, float(b[0]))
    # a**b = exp(b log a)  (a > 0; a <= 0 with a variable exponent is not real)
    a0 = np.float64(1.0) * a[0]
    la = np.log(a0)
    f0 = np.power(a0, b[0])
    q = np.true_divide(a[1], a0)
    g1 = b[1] * la + b[0] * q
    g2 = b[2] * la + 2.0 * b[1] * q + b[0] * (np.true_divide(a[2], a0) - q * q)
    return f0, f0 * g1, f0 * (g2 + g1 * g1)


def _atan2(y: Jet, x: Jet) -> Jet:
    D = x[0] * x[0] + y[0] * y[0]
    N = x[0] * y[1] - y[0] * x[1]
    dN = x[0] * y[2] - y[0] * x[2]
    dD = 2.0 * (x[0] * x[1] + y[0] * y[1])
    d1 = np.true_divide(N, D)
    d2 = np.true_divide(dN - d1 * dD, D)
    return np.arctan2(y[0], x[0]), d1, d2


def _select(args: list[Jet], pick_min: bool) -> Jet:
    out = args[0]
    for b in args[1:]:
        cond = (out[0] <= b[0]) if pick_min else (out[0] >= b[0])
        out = tuple(np.where(cond, out[i], b[i]) for i in range(3))
    return out


def compile_jet(ir: tuple, var: str = "t") -> Callable[[Mapping[str, Any]], Jet]:
    """Compile an IR tree into ``env -> (f, df/dvar, d²f/dvar²)``."""
    fn, _ = _compile(ir, var)
    return fn


def _compile(ir: tuple, var: str):
    kind = ir[0]
    if kind == "num":
        return _const(ir[1])
    if kind == "param":
        return _const(ir[2])
    if kind == "var":
        name = ir[1]
        if name == var:
            def v(env):
                t = env[name]
                return t, np.ones_like(t, dtype=float), np.zeros_like(t, dtype=float)
            return v, False

        def other(env):
            return env[name], _ZERO, _ZERO
        return other, True
    if kind == "neg":
        a, c = _compile(ir[1], var)
        return (lambda env: tuple(-x for x in a(env))), c
    if kind in ("add", "sub", "mul", "div", "pow"):
        a, ca = _compile(ir[1], var)
        b, cb = _compile(ir[2], var)
        if kind == "add":
            return (lambda env: tuple(x + y for x, y in zip(a(env), b(env)))), ca and cb
        if kind == "sub":
            return (lambda env: tuple(x - y for x, y in zip(a(env), b(env)))), ca and cb
        if kind == "mul":
            return (lambda env: _mul(a(env), b(env))), ca and cb
        if kind == "div":
            return (lambda env: _div(a(env), b(env))), ca and cb
        return (lambda env: _pow(a(env), b(env), cb)), ca and cb
    if kind == "call":
        name = ir[1]
        parts = [_compile(x, var) for x in ir[2]]
        fns = [p[0] for p in parts]
        const = all(p[1] for p in parts)
        if name == "atan2":
            return (lambda env: _atan2(fns[0](env), fns[1](env))), const
        if name in ("min", "max"):
            pick_min = name == "min"
            return (lambda env: _select([f(env) for f in fns], pick_min)), const
        f0 = fns[0]
        return (lambda env: _unary(name, f0(env))), const
    raise AssertionError(kind)  # pragma: no cover


_CACHE: dict[tuple, Callable] = {}


def jet(e: Expr, t, var: str = "t", **env: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(e, de/dvar, d²e/dvar²)`` at ``var = t`` (arrays of the shape of ``t``)."""
    key = (e.ir, var)
    fn = _CACHE.get(key)
    if fn is None:
        fn = _CACHE[key] = compile_jet(e.ir, var)
    t = np.asarray(t, dtype=float)
    with np.errstate(all="ignore"):
        out = fn({**env, var: t})
    return tuple(np.broadcast_to(np.asarray(x, dtype=float), t.shape).copy() for x in out)  # type: ignore[return-value]


def vec_jet(exprs, t, var: str = "t") -> np.ndarray:
    """Jets of 3 component expressions: array of shape (3 orders, 3 components, len(t))."""
    t = np.atleast_1d(np.asarray(t, dtype=float))
    out = np.empty((3, 3, t.size))
    for i, e in enumerate(exprs):
        f0, f1, f2 = jet(e, t, var)
        out[0, i], out[1, i], out[2, i] = f0, f1, f2
    return out
