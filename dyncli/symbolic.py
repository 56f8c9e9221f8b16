"""Exact derivatives and formula text for expressions (sympy, imported lazily).

The route never touches raw text: an :class:`~dyncli.expr.Expr` IR is turned
into sympy objects node by node (:func:`dyncli.expr.to_sympy`), sympy
differentiates/simplifies, and the result is converted back into the same IR
(:func:`from_sympy`) and evaluated by dyncli's own vectorised evaluator.  No
``lambdify`` (which generates and execs code), no ``sympify``.

Typical use::

    from dyncli import symbolic
    d1 = symbolic.diff(expr, "t")            # Expr of dexpr/dt
    d2 = symbolic.diff(expr, "t", 2)
    sym = symbolic.sym(expr)                 # sympy object
    text = symbolic.pretty(sym)              # "3*cos(2*t) + t**2"
    e = symbolic.expr_from_sympy(sym_obj, variables=("t",))   # back to Expr
"""

from __future__ import annotations

import math
from typing import Any, Iterable

from dyncli.expr import Expr, to_sympy

_SYMBOLS: dict[str, Any] = {}


def symbol(name: str):
    import sympy as sp

    s = _SYMBOLS.get(name)
    if s is None:
        s = _SYMBOLS[name] = sp.Symbol(name, real=True)
    return s


def sym(e: Expr, keep_params: bool = False):
    """The sympy expression of ``e`` (variables as real symbols)."""
    names = set(e.allowed) | set(e.variables)
    return to_sympy(e.ir, {n: symbol(n) for n in names}, keep_params)


def diff(e: Expr, var: str, n: int = 1) -> Expr:
    """Exact ``n``-th derivative of ``e`` with respect to ``var``."""
    import sympy as sp

    d = sp.diff(sym(e), symbol(var), n)
    return expr_from_sympy(d, e.allowed, text=f"d{'^' + str(n) if n > 1 else ''}({e.text})/d{var}{'^' + str(n) if n > 1 else ''}")


def expr_from_sympy(obj, variables: Iterable[str] = (), text: str | None = None) -> Expr:
    """Convert a sympy expression back into an :class:`Expr`."""
    variables = tuple(variables)
    ir, used = from_sympy(obj)
    unknown = used - set(variables)
    if unknown:
        raise ValueError(f"unexpected symbols {sorted(unknown)}")
    return Expr(text or pretty(obj), ir, variables, frozenset(used), frozenset())


def from_sympy(obj) -> tuple[tuple, set[str]]:
    """sympy -> (IR, set of variable names).  Covers what differentiating
    the language's functions produces (Heaviside, DiracDelta, Abs, sign,
    Min/Max, Piecewise-free results).

    (Over 60 lines on purpose: ``conv`` is one dispatch over sympy's node types, read as a
    table from top to bottom; split up, the table would be scattered over helpers.)"""
    import sympy as sp

    used: set[str] = set()

    def num(v) -> tuple:
        return ("num", float(v))

    def conv(x) -> tuple:
        # over 60 lines on purpose: one dispatch table over sympy's node types (see the docstring)
        a: Any                                   # a converted argument, or a sympy one
        if isinstance(x, sp.Symbol):
            used.add(x.name)
            return ("var", x.name)
        if x is sp.pi:
            return ("num", math.pi)
        if x is sp.E:
            return ("num", math.e)
        if isinstance(x, (sp.Integer, sp.Float, sp.Rational)) or x.is_Number:
            if x in (sp.zoo, sp.oo, -sp.oo, sp.nan):
                raise ValueError("non-finite constant")
            return num(x)
        if isinstance(x, sp.NumberSymbol):
            return num(sp.N(x, 20))
        if isinstance(x, sp.Add):
            args = [conv(a) for a in x.args]
            out = args[0]
            for a in args[1:]:
                out = ("add", out, a)
            return out
        if isinstance(x, sp.Mul):
            args = [conv(a) for a in x.args]
            out = args[0]
            for a in args[1:]:
                out = ("mul", out, a)
            return out
        if isinstance(x, sp.Pow):
            base, ex = x.args
            if ex == sp.Rational(1, 2):
                return ("call", "sqrt", (conv(base),))
            if ex == -1:
                return ("div", ("num", 1.0), conv(base))
            return ("pow", conv(base), conv(ex))
        if isinstance(x, sp.exp):
            return ("call", "exp", (conv(x.args[0]),))
        if isinstance(x, sp.log):
            if len(x.args) == 2:
                return ("div", ("call", "log", (conv(x.args[0]),)), ("call", "log", (conv(x.args[1]),)))
            return ("call", "log", (conv(x.args[0]),))
        if isinstance(x, sp.Abs):
            return ("call", "abs", (conv(x.args[0]),))
        if isinstance(x, sp.sign):
            return ("call", "sign", (conv(x.args[0]),))
        if isinstance(x, sp.Heaviside):
            a = conv(x.args[0])
            return ("mul", ("num", 0.5), ("add", ("num", 1.0), ("call", "sign", (a,))))
        if isinstance(x, sp.DiracDelta):
            return ("num", 0.0)  # zero almost everywhere (derivative of a kink)
        if isinstance(x, (sp.Min, sp.Max)):
            name = "min" if isinstance(x, sp.Min) else "max"
            return ("call", name, tuple(conv(a) for a in x.args))
        if isinstance(x, sp.atan2):
            return ("call", "atan2", (conv(x.args[0]), conv(x.args[1])))
        fname = {
            sp.sin: "sin", sp.cos: "cos", sp.tan: "tan", sp.asin: "asin", sp.acos: "acos",
            sp.atan: "atan", sp.sinh: "sinh", sp.cosh: "cosh", sp.tanh: "tanh",
        }.get(type(x))
        if fname:
            return ("call", fname, (conv(x.args[0]),))
        # functions the language lacks but derivatives may produce
        a = x.args[0] if x.args else None
        if isinstance(x, sp.sec):
            return ("div", ("num", 1.0), ("call", "cos", (conv(a),)))
        if isinstance(x, sp.csc):
            return ("div", ("num", 1.0), ("call", "sin", (conv(a),)))
        if isinstance(x, sp.cot):
            return ("div", ("call", "cos", (conv(a),)), ("call", "sin", (conv(a),)))
        if isinstance(x, sp.Piecewise):
            raise ValueError("piecewise expression")
        raise ValueError(f"cannot convert {type(x).__name__}")

    return conv(obj), used


def pretty(obj, width: int | None = None) -> str:
    """Compact one-line formula text (sympy's ``sstr``), e.g. ``3*cos(2*t)``."""
    import sympy as sp

    return sp.sstr(obj)


def simplify(obj):
    """A cheap, readable simplification (trigsimp + cancel), bounded in effort."""
    import sympy as sp

    try:
        out = sp.trigsimp(sp.expand(obj))
    except Exception:  # noqa: BLE001 - simplification is cosmetic
        out = obj
    return out


def shortest(x, max_ops: int):
    """A bounded, readable simplification of one entry: expand + trigsimp + factor_terms for
    entries of at most ``max_ops`` operations, factor_terms alone for longer ones (trigsimp takes
    seconds on them); the shortest form wins (operations, then characters)."""
    import sympy as sp

    x = sp.Integer(0) + x                   # plain python numbers -> sympy objects
    if x.is_Number:
        return x
    try:
        cands = [x, sp.factor_terms(x)]
        if sp.count_ops(x) <= max_ops:
            y = sp.trigsimp(sp.expand(x))
            cands += [y, sp.factor_terms(y)]
        return min(cands, key=lambda e: (sp.count_ops(e), len(sp.sstr(e))))
    except Exception:  # noqa: BLE001 - simplification is cosmetic
        return x


_WARM: list[bool] = []


def warm() -> None:
    """Import sympy and the parts it loads lazily on first use (simplification,
    integration, trigonometric rewriting), once per process, so that a CPU-time
    limit around sympy's work (dyncli.cputime) measures the work and not a first
    import — which, in a fresh install, also compiles sympy's byte code."""
    if _WARM:
        return
    import sympy as sp

    x = sp.Symbol("x")
    sp.simplify(sp.sin(x) ** 2 + sp.cos(x) ** 2 + sp.cancel((x ** 2 - 1) / (x - 1)))
    sp.integrate(x * sp.exp(x), x)
    sp.sstr(sp.diff(sp.sqrt(x), x))
    _WARM.append(True)
