"""The expression language of problem files (docs/expressions.md).

A string such as ``"-9.81 - 0.002*v*abs(v)"`` is parsed with :func:`ast.parse`
(parsing only builds a tree, it runs nothing), checked node by node against a
whitelist, and converted into a small immutable IR of tuples.  The IR is then

* evaluated by a tree of closures over numpy ufuncs (vectorised over arrays),
* converted node by node into sympy objects (for exact derivatives and
  symbolic tables; sympy is imported only there), or
* folded to a float when it uses no free variable.

Nothing here ever calls ``eval``, ``exec``, ``sympify`` or ``parse_expr``.

The package: :mod:`.language` (limits, constants, functions, errors),
:mod:`.parser` (text -> IR), :mod:`.node` (:class:`Expr`), :mod:`.evaluate`
(numpy closures, constant folding), :mod:`.sympy_bridge` and :mod:`.params`.
Every public name is importable from ``dyncli.expr`` as before.

IR nodes::

    ("num", value)                  float literal or constant (pi, deg)
    ("var", name)                   free variable (t, s, v, x1 ...)
    ("param", name, value)          a params entry, already a float
    ("neg", a)
    ("add"|"sub"|"mul"|"div"|"pow", a, b)
    ("call", fname, (a, b, ...))
"""

from __future__ import annotations

from dyncli.expr.language import (
    CONSTANTS, FUNCTIONS, MAX_CHAIN, MAX_DEPTH, MAX_LENGTH, MAX_NODES, MAX_PARAMS, RESERVED,
    ExpressionError, did_you_mean, kind_of,
)
from dyncli.expr.evaluate import compile_ir, fold
from dyncli.expr.sympy_bridge import to_sympy
from dyncli.expr.node import Expr
from dyncli.expr.parser import constant, parse
from dyncli.expr.params import resolve_params

__all__ = [
    "CONSTANTS", "FUNCTIONS", "MAX_CHAIN", "MAX_DEPTH", "MAX_LENGTH", "MAX_NODES", "MAX_PARAMS", "RESERVED",
    "ExpressionError", "Expr", "compile_ir", "constant", "did_you_mean", "fold", "kind_of", "parse",
    "resolve_params", "to_sympy",
]
