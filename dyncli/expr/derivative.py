"""The exact derivative of an expression, by the rules of calculus applied to dyncli's
expression IR node by node (no sympy): x'(t) of a path, which is only evaluated (inside
the work quadrature, 19.4), never printed, so no simplification is needed beyond folding
the zeros and ones the rules produce.  ``min``/``max`` (whose derivative selects an
argument) keep sympy's route (``dyncli.symbolic.diff``).

>>> from dyncli.expr import parse
>>> d = derivative(parse("3*sin(2*t) + t**2", ("t",)), "t")
>>> round(float(d.evaluate(t=0.5)), 12) == round(6 * __import__("math").cos(1.0) + 1.0, 12)
True
"""

from __future__ import annotations

import math

from dyncli.expr.evaluate import uses

ENABLED = True          # tests set this False to force sympy's derivative (the oracle)

_ZERO, _ONE = ("num", 0.0), ("num", 1.0)


class _NoRule(Exception):
    pass


def _num(v: float) -> tuple:
    return ("num", float(v))


def _is(n: tuple, v: float) -> bool:
    return n[0] == "num" and n[1] == v


def _add(a, b):
    return b if _is(a, 0.0) else a if _is(b, 0.0) else ("add", a, b)


def _sub(a, b):
    return _neg(b) if _is(a, 0.0) else a if _is(b, 0.0) else ("sub", a, b)


def _neg(a):
    return _num(-a[1]) if a[0] == "num" else ("neg", a)


def _mul(a, b):
    if _is(a, 0.0) or _is(b, 0.0):
        return _ZERO
    return b if _is(a, 1.0) else a if _is(b, 1.0) else ("mul", a, b)


def _div(a, b):
    return _ZERO if _is(a, 0.0) else a if _is(b, 1.0) else ("div", a, b)


def _call(name, *args):
    return ("call", name, tuple(args))


def _d_call(name: str, args: tuple, var: str) -> tuple:
    if name in ("min", "max"):
        raise _NoRule(name)
    u = args[0]
    du = d_ir(u, var)
    if name == "atan2":        # atan2(y, x)' = (x y' − y x')/(x² + y²)
        y, x = args
        return _div(_sub(_mul(x, d_ir(y, var)), _mul(y, d_ir(x, var))), ("add", ("mul", x, x), ("mul", y, y)))
    if _is(du, 0.0) or name == "sign":
        return _ZERO
    outer = {
        "sin": lambda: _call("cos", u),
        "cos": lambda: _neg(_call("sin", u)),
        "tan": lambda: ("div", _ONE, ("pow", _call("cos", u), _num(2))),
        "asin": lambda: ("div", _ONE, _call("sqrt", ("sub", _ONE, ("mul", u, u)))),
        "acos": lambda: ("neg", ("div", _ONE, _call("sqrt", ("sub", _ONE, ("mul", u, u))))),
        "atan": lambda: ("div", _ONE, ("add", _ONE, ("mul", u, u))),
        "sinh": lambda: _call("cosh", u),
        "cosh": lambda: _call("sinh", u),
        "tanh": lambda: ("div", _ONE, ("pow", _call("cosh", u), _num(2))),
        "exp": lambda: _call("exp", u),
        "log": lambda: ("div", _ONE, u),
        "log10": lambda: ("div", _ONE, ("mul", u, _num(math.log(10.0)))),
        "sqrt": lambda: ("div", _ONE, ("mul", _num(2), _call("sqrt", u))),
        "abs": lambda: _call("sign", u),
    }[name]()
    return _mul(outer, du)


def _d_pow(a: tuple, b: tuple, var: str) -> tuple:
    da = d_ir(a, var)
    if not uses(b, var):                              # (a**n)' = n a**(n-1) a'
        if _is(da, 0.0):
            return _ZERO
        if b[0] == "num":
            n = b[1]
            if n == 0.0:
                return _ZERO
            return _mul(_mul(b, _ONE if n == 1.0 else ("pow", a, _num(n - 1.0))), da)
        return _mul(_mul(b, ("pow", a, ("sub", b, _ONE))), da)
    # (a**b)' = a**b (b' log a + b a'/a)
    return _mul(("pow", a, b), _add(_mul(d_ir(b, var), _call("log", a)), _div(_mul(b, da), a)))


def d_ir(n: tuple, var: str) -> tuple:
    """The IR of d(n)/d(var)."""
    k = n[0]
    if k in ("num", "param"):
        return _ZERO
    if k == "var":
        return _ONE if n[1] == var else _ZERO
    if k == "neg":
        return _neg(d_ir(n[1], var))
    if k == "call":
        return _d_call(n[1], n[2], var)
    a, b = n[1], n[2]
    if k == "add":
        return _add(d_ir(a, var), d_ir(b, var))
    if k == "sub":
        return _sub(d_ir(a, var), d_ir(b, var))
    if k == "mul":
        return _add(_mul(d_ir(a, var), b), _mul(a, d_ir(b, var)))
    if k == "div":                                     # a'/b − a b'/b²
        return _sub(_div(d_ir(a, var), b), _div(_mul(a, d_ir(b, var)), ("mul", b, b)))
    if k == "pow":
        return _d_pow(a, b, var)
    raise _NoRule(k)  # pragma: no cover


def _names(n: tuple) -> set:
    if n[0] == "var":
        return {n[1]}
    if n[0] in ("num", "param"):
        return set()
    kids = n[2] if n[0] == "call" else n[1:]
    return set().union(*(_names(a) for a in kids))


def derivative(e, var: str):
    """d(e)/d(var) as an Expr: these rules, or sympy's for ``min``/``max``."""
    if ENABLED:
        try:
            ir = d_ir(e.ir, var)
        except (_NoRule, RecursionError):
            pass
        else:
            from dyncli.expr import Expr

            return Expr(f"d({e.text})/d{var}", ir, e.allowed, frozenset(_names(ir)))
    from dyncli import symbolic

    return symbolic.diff(e, var)
