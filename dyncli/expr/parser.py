"""Parsing: text -> checked :func:`ast.parse` tree -> the IR of tuples (nothing is run)."""

from __future__ import annotations

import ast
import math
import re
from typing import Any, Iterable, Mapping

from dyncli.expr.evaluate import fold
from dyncli.expr.language import (
    CONSTANTS, FUNCTIONS, MAX_CHAIN, MAX_DEPTH, MAX_LENGTH, MAX_NODES, ExpressionError, kind_of, did_you_mean,
)
from dyncli.expr.node import Expr

_BINOPS = {ast.Add: "add", ast.Sub: "sub", ast.Mult: "mul", ast.Div: "div", ast.Pow: "pow"}

_FORBIDDEN_NAMES = {
    ast.Attribute: "attribute access",
    ast.Subscript: "subscripts",
    ast.Lambda: "lambdas",
    ast.ListComp: "comprehensions",
    ast.SetComp: "comprehensions",
    ast.DictComp: "comprehensions",
    ast.GeneratorExp: "comprehensions",
    ast.Compare: "comparisons",
    ast.BoolOp: "boolean operators",
    ast.IfExp: "conditional expressions",
    ast.NamedExpr: "assignment expressions",
    ast.Starred: "starred arguments",
    ast.JoinedStr: "strings",
    ast.List: "lists",
    ast.Tuple: "tuples",
    ast.Dict: "dicts",
    ast.Set: "sets",
    ast.Await: "await",
    ast.Yield: "yield",
    ast.YieldFrom: "yield",
    ast.Slice: "slices",
}



def parse(
    text: Any,
    variables: Iterable[str] = (),
    params: Mapping[str, float] | None = None,
) -> Expr:
    """Parse ``text`` (a YAML number or a string) into an :class:`Expr`.

    Raises :class:`ExpressionError` naming the offending token."""
    allowed = tuple(variables)
    params = dict(params or {})
    if isinstance(text, bool):
        raise ExpressionError(f"expected a number or an expression, got the boolean {text!r}")
    if isinstance(text, (int, float)):
        try:
            v = float(text)
        except OverflowError:
            raise ExpressionError("number is too large") from None
        return Expr(str(text), ("num", v), allowed)
    if not isinstance(text, str):
        raise ExpressionError(
            f"expected a number or an expression string, got {kind_of(text)}"
        )
    src = text.strip()
    if not src:
        raise ExpressionError("empty expression")
    if len(src) > MAX_LENGTH:
        raise ExpressionError(f"expression is too long ({len(src)} characters, at most {MAX_LENGTH})")
    for i, ch in enumerate(src):
        if ord(ch) > 127:
            raise ExpressionError(
                f"non-ASCII character {ch!r} at column {i + 1} in {src!r}; "
                "write expressions with plain ASCII letters, digits and + - * / ( )"
            )
    if "^" in src:
        raise ExpressionError(f"'^' in {src!r}: use ** for powers")
    for p in params:
        if p in allowed:
            raise ExpressionError(
                f"params name '{p}' is also a variable of this field; rename the parameter"
            )
    try:
        tree = ast.parse(src, mode="eval")
    except SyntaxError as exc:
        col = (exc.offset or 1)
        tok = src[col - 1: col + 9] if 0 < col <= len(src) else ""
        raise ExpressionError(
            f"syntax error in {src!r} at column {col}" + (f" near {tok!r}" if tok else "")
        ) from None
    except (RecursionError, MemoryError, ValueError):
        raise ExpressionError(f"expression {src[:40]!r}... is nested too deeply") from None
    conv = _Converter(src, allowed, params)
    ir = conv.convert(tree.body, 0)
    expr = Expr(src, ir, allowed, frozenset(conv.used_vars), frozenset(conv.used_params))
    if expr.is_constant:
        # fold now: catches overflow (9**9**9) and domain errors early
        fold(ir, src)
    return expr


def constant(text: Any, params: Mapping[str, float] | None = None, params_print: Any = None) -> float:
    """Parse and evaluate a constant expression or number to a float
    (may be +-inf for a YAML ``.inf``; never NaN).  ``params_print``: the fingerprint of
    ``params`` (:func:`dyncli.docmemo.fingerprint`) when the caller made it already (one per
    problem, not one per field)."""
    if type(text) is float and text == text:        # a plain number (not NaN): the value of its Expr
        return text
    if type(text) is str and (params is None or type(params) is dict):
        from dyncli.docmemo import recall       # remembered per (text, params), type-exactly

        # (the fingerprint of (text, params), made of params' own)
        whole = None if params_print is None else (tuple, ((str, text), params_print))
        return recall("constant", (text, params), lambda: _constant(text, params), print_=whole)
    return _constant(text, params)


def _constant(text: Any, params: Mapping[str, float] | None) -> float:
    v = parse(text, (), params).value()
    if math.isnan(v):
        raise ExpressionError("not a number (NaN)")
    return v


_DECIMAL_COMMA = re.compile(r"(?<![\w.])(\d+),(\d+)(?![\w.])")


def _decimal_comma(text: str) -> None:
    """A comma between two numbers is a decimal comma (2,5) or a thousands
    separator (1,000): say which way to write it."""
    m = _DECIMAL_COMMA.search(text)
    if m is None:
        return
    a, b = m.groups()
    if len(b) == 3:
        raise ExpressionError(f"{a},{b}: numbers take no commas: write {a}{b} "
                              f"(or {a}.{b} if the comma is a decimal comma)")
    raise ExpressionError(f"{a},{b}: use a decimal point ({a}.{b})")


class _Converter:
    def __init__(self, src: str, allowed: tuple[str, ...], params: Mapping[str, float]):
        self.src = src
        self.allowed = allowed
        self.params = params
        self.used_vars: set[str] = set()
        self.used_params: set[str] = set()
        self.count = 0

    def _seg(self, node: ast.AST) -> str:
        seg = ast.get_source_segment(self.src, node) or ""
        return seg if len(seg) <= 40 else seg[:37] + "..."

    def _fail(self, node: ast.AST, what: str) -> ExpressionError:
        col = getattr(node, "col_offset", 0) + 1
        return ExpressionError(f"not allowed ({what}): {self._seg(node)!r} at column {col} of {self.src!r}")

    def convert(self, node: ast.AST, depth: int, chain: int = 0) -> tuple:
        # the recursion stays in this one method (the helpers only check a node), so the
        # Python stack per level of the expression is what it always was
        self.count += 1
        if depth > MAX_DEPTH:
            raise ExpressionError(f"expression {self.src[:40]!r} is nested too deeply (more than {MAX_DEPTH} levels)")
        if self.count > MAX_NODES:
            raise ExpressionError(f"expression has too many terms (more than {MAX_NODES})")
        d = depth + 1
        if isinstance(node, ast.Constant):
            return self._constant(node)
        if isinstance(node, ast.Name):
            return self._name(node)
        if isinstance(node, ast.UnaryOp):
            if isinstance(node.op, ast.USub):
                return ("neg", self.convert(node.operand, d))
            if isinstance(node.op, ast.UAdd):
                return self.convert(node.operand, d)
            raise self._fail(node, "operator")
        if isinstance(node, ast.BinOp):
            op, same = self._binop(node, chain)
            if same:
                return (op, self.convert(node.left, depth, chain + 1), self.convert(node.right, d))
            return (op, self.convert(node.left, d), self.convert(node.right, d))
        if isinstance(node, ast.Call):
            return ("call", self._call(node), tuple(self.convert(a, d) for a in node.args))
        if isinstance(node, ast.Tuple):
            _decimal_comma(self._seg(node))
        for cls, what in _FORBIDDEN_NAMES.items():
            if isinstance(node, cls):
                raise self._fail(node, what)
        raise self._fail(node, type(node).__name__)

    def _constant(self, node: ast.Constant) -> tuple:
        v = node.value
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            what = "strings" if isinstance(v, (str, bytes)) else f"the constant {v!r}"
            raise self._fail(node, what)
        try:
            fv = float(v)
        except OverflowError:
            raise ExpressionError(f"number {self._seg(node)!r} is too large") from None
        if math.isinf(fv):
            raise ExpressionError(f"number {self._seg(node)!r} is too large")
        return ("num", fv)

    def _name(self, node: ast.Name) -> tuple:
        name = node.id
        if name in self.allowed:
            self.used_vars.add(name)
            return ("var", name)
        if name in self.params:
            self.used_params.add(name)
            return ("param", name, float(self.params[name]))
        if name in CONSTANTS:
            return ("num", CONSTANTS[name]) if name != "pi" else ("num", math.pi)
        if name in FUNCTIONS:
            raise ExpressionError(f"function '{name}' used without arguments in {self.src!r}")
        allowed_txt = ", ".join(self.allowed) if self.allowed else "none"
        hint = did_you_mean(name, list(self.allowed) + list(self.params) + list(CONSTANTS) + list(FUNCTIONS))
        if not hint and name == self.src and not self.allowed:   # a word where a number is expected: m: two
            raise ExpressionError(
                f"'{name}' is not a number: write it in digits (e.g. 2 or 0.5), or define '{name}' under params"
            )
        ptxt = (", params: " + ", ".join(sorted(self.params))) if self.params else ""
        raise ExpressionError(
            f"unknown name '{name}' in {self.src!r}{hint}; variables allowed here: {allowed_txt}{ptxt}"
            + ("" if hint else f"; define '{name}' under params to use it")
        )

    def _binop(self, node: ast.BinOp, chain: int) -> tuple[str, bool]:
        """(the IR operator, whether the left operand continues the same + - or * / chain)."""
        if isinstance(node.op, ast.BitXor):
            raise ExpressionError(f"'^' in {self.src!r}: use ** for powers")
        op = _BINOPS.get(type(node.op))
        if op is None:
            sym = {ast.Mod: "%", ast.FloorDiv: "//", ast.MatMult: "@", ast.LShift: "<<",
                   ast.RShift: ">>", ast.BitOr: "|", ast.BitAnd: "&"}.get(type(node.op), "?")
            raise ExpressionError(f"operator '{sym}' not allowed in {self.src!r}; use + - * / **")
        # a + b + c + ... nests to the left: count chain length, not depth
        family = "add" if op in ("add", "sub") else "mul" if op in ("mul", "div") else None
        left = node.left
        same = family is not None and isinstance(left, ast.BinOp) and _BINOPS.get(type(left.op)) in (
            ("add", "sub") if family == "add" else ("mul", "div"))
        if same and chain + 1 > MAX_CHAIN:
            raise ExpressionError(f"expression has too many terms in one sum or product (more than {MAX_CHAIN})")
        return op, same

    def _call(self, node: ast.Call) -> str:
        """The name of the called function, once the call is checked (arguments unconverted)."""
        if not isinstance(node.func, ast.Name):
            raise self._fail(node.func, "attribute access" if isinstance(node.func, ast.Attribute) else "calling the result of an expression")
        fname = node.func.id
        if fname not in FUNCTIONS:
            raise ExpressionError(
                f"unknown function '{fname}' in {self.src!r}{did_you_mean(fname, FUNCTIONS)}; "
                f"functions: {' '.join(FUNCTIONS)}"
            )
        if node.keywords:
            raise self._fail(node.keywords[0].value, "keyword arguments")
        lo, hi = FUNCTIONS[fname]
        n = len(node.args)
        if n < lo or (hi is not None and n > hi):
            want = f"{lo}" if lo == hi else f"at least {lo}"
            raise ExpressionError(f"{fname}() takes {want} argument(s), got {n} in {self.src!r}")
        return fname
