"""Evaluation of the IR: a tree of closures over numpy ufuncs (vectorised), and the
plain-float fold of a constant expression with clear errors."""

from __future__ import annotations

import math
from typing import Any, Callable, Mapping

from dyncli.errors import InputError
from dyncli.expr.language import ExpressionError


def _np_funcs():
    import numpy as np

    def _min(*a):
        return np.minimum.reduce(np.broadcast_arrays(*a)) if any(np.ndim(x) for x in a) else min(a)

    def _max(*a):
        return np.maximum.reduce(np.broadcast_arrays(*a)) if any(np.ndim(x) for x in a) else max(a)

    return {
        "sin": np.sin, "cos": np.cos, "tan": np.tan,
        "asin": np.arcsin, "acos": np.arccos, "atan": np.arctan, "atan2": np.arctan2,
        "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
        "exp": np.exp, "log": np.log, "log10": np.log10, "sqrt": np.sqrt,
        "abs": np.abs, "sign": np.sign, "min": _min, "max": _max,
    }


_FUNCS_CACHE: dict | None = None


def _funcs() -> dict:
    global _FUNCS_CACHE
    if _FUNCS_CACHE is None:
        _FUNCS_CACHE = _np_funcs()
    return _FUNCS_CACHE


def uses(ir: tuple, var: str) -> bool:
    """Whether the IR refers to the variable ``var``."""
    kind = ir[0]
    if kind == "var":
        return ir[1] == var
    if kind in ("num", "param"):
        return False
    if kind == "call":
        return any(uses(a, var) for a in ir[2])
    return any(uses(a, var) for a in ir[1:])


def compile_ir(ir: tuple) -> Callable[[Mapping[str, Any]], Any]:
    """The IR as one closure ``env -> value`` over numpy ufuncs (vectorised over arrays in ``env``);
    a variable missing from ``env`` is InputError."""
    import numpy as np

    kind = ir[0]
    if kind == "num":
        v = np.float64(ir[1])
        return lambda env: v
    if kind == "param":
        v = np.float64(ir[2])
        return lambda env: v
    if kind == "var":
        name = ir[1]

        def var(env, name=name):
            try:
                return env[name]
            except KeyError:
                raise InputError(f"variable '{name}' has no value here") from None

        return var
    if kind == "neg":
        a = compile_ir(ir[1])
        return lambda env: -a(env)
    if kind in ("add", "sub", "mul", "div", "pow"):
        a, b = compile_ir(ir[1]), compile_ir(ir[2])
        if kind == "add":
            return lambda env: a(env) + b(env)
        if kind == "sub":
            return lambda env: a(env) - b(env)
        if kind == "mul":
            return lambda env: a(env) * b(env)
        if kind == "div":
            return lambda env: np.true_divide(a(env), b(env))
        if ir[2][0] in ("num", "param"):
            # a constant exponent: numpy ≥ 2 takes x*x for 2 and the square root for 0.5 inside
            # power; older numpy took C's pow (7× slower on arrays, and pow(−inf, 0.5) = +inf) —
            # the same fast paths here make every numpy version give numpy 2's values
            c = float(ir[2][-1])
            if c == 2.0:
                return lambda env: np.square(np.float64(1.0) * a(env))
            if c == 0.5:
                return lambda env: np.sqrt(np.float64(1.0) * a(env))
        return lambda env: np.power(np.float64(1.0) * a(env), b(env))
    if kind == "call":
        f = _funcs()[ir[1]]
        args = [compile_ir(x) for x in ir[2]]
        if len(args) == 1:
            a0 = args[0]
            return lambda env: f(a0(env))
        return lambda env: f(*[g(env) for g in args])
    raise AssertionError(kind)  # pragma: no cover


def fold(ir: tuple, src: str = "") -> float:
    """Evaluate a constant IR with plain floats, with clear errors (``src``: the text they quote);
    ValueError when the IR uses a free variable."""

    def ev(n):   # the children are evaluated here, so the recursion is one frame per level
        k = n[0]
        if k == "num":
            return n[1]
        if k == "param":
            return n[2]
        if k == "neg":
            return -ev(n[1])
        if k in ("add", "sub", "mul", "div", "pow"):
            return _fold_arith(k, ev(n[1]), ev(n[2]), src)
        if k == "call":
            return _fold_call(n[1], [ev(x) for x in n[2]], src)
        if k == "var":
            raise ValueError("not constant")
        raise AssertionError(k)  # pragma: no cover

    v = ev(ir)
    if isinstance(v, float) and math.isinf(v) and src:
        raise ExpressionError(f"{src!r} overflows (result too large)")
    return float(v)


def _fold_arith(k: str, a, b, src: str):
    if k == "add":
        return a + b
    if k == "sub":
        return a - b
    if k == "mul":
        return a * b
    if k == "div":
        if b == 0:
            raise ExpressionError(f"division by zero in {src!r}")
        return a / b
    try:
        r = a ** b
    except OverflowError:
        raise ExpressionError(f"{src!r} overflows (result too large)") from None
    except ZeroDivisionError:
        raise ExpressionError(f"zero raised to a negative power in {src!r}") from None
    if isinstance(r, complex):
        raise ExpressionError(f"{src!r} is not a real number (negative base to a fractional power)")
    return r


def _fold_call(name: str, args: list, src: str):
    m = math
    try:
        if name == "sign":
            a = args[0]
            return float((a > 0) - (a < 0))
        if name == "abs":
            return abs(args[0])
        if name == "min":
            return min(args)
        if name == "max":
            return max(args)
        if name == "atan2":
            return m.atan2(args[0], args[1])
        fn = {"asin": m.asin, "acos": m.acos, "atan": m.atan}.get(name) or getattr(m, name)
        return fn(*args)
    except OverflowError:
        raise ExpressionError(f"{name}() overflows in {src!r}") from None
    except ValueError:
        raise ExpressionError(f"{name}({', '.join(repr(a) for a in args)}) is undefined (math domain error) in {src!r}") from None
