"""Per-student variants (docs/check.md).

Each parameter has its own random stream: numpy's ``Generator`` (PCG64)
seeded by ``SeedSequence(sha256(salt, student id, parameter name))``; draws
use only the bit generator's raw 64-bit outputs (:func:`below`), which numpy
keeps stable across releases, so an id's numbers never change.  The
k-th attempt takes the k-th draw of every stream, and the first attempt that
satisfies ``require`` is the student's variant (1,000 failed attempts are
invalid input in the key).  So a value depends only on (salt, student id,
parameter name): the same id always gets the same numbers, and adding a
parameter changes no other parameter's value (unless ``require`` uses it).

Distributions:

* ``{uniform: [lo, hi], step: s}``: the grid lo, lo+s, ... up to hi
  (without ``step``: continuous, rounded to 6 significant figures);
* ``{choice: [v1, v2, ...]}``: one of the values, equally likely;
* ``{integers: [lo, hi]}``: a whole number, both ends included;
* optional ``unit`` (e.g. ``km/h``): the drawn number is in that unit and is
  converted to SI in the problem (the student's sheet shows the unit).

``require`` is a condition in the expression language with comparisons
(``<  <=  >  >=  ==  !=``) joined by ``and``/``or``/``not``; each side is an
ordinary expression of the variant parameters, parsed by ``dyncli.expr``.
"""

from __future__ import annotations

import ast
import hashlib
import keyword
import math
from dataclasses import dataclass, field
from typing import Any, Callable

from dyncli.check.safe import shown
from dyncli.expr import did_you_mean

MAX_ATTEMPTS = 1000
MAX_CHOICES = 10_000
MAX_VARIANT_PARAMS = 100
PARAM_KEYS = ("uniform", "choice", "integers", "step", "unit")
VARIANT_KEYS = ("salt", "params", "require")


class VariantError(ValueError):
    """``require`` not met after MAX_ATTEMPTS draws (invalid key)."""


@dataclass
class Param:
    name: str
    kind: str                       # uniform | choice | integers
    lo: float = 0.0
    hi: float = 0.0
    step: float | None = None
    values: list[float] = field(default_factory=list)
    unit: str | None = None

    def draw(self, rng) -> float:
        if self.kind == "choice":
            return self.values[below(rng, len(self.values))]
        if self.kind == "integers":
            return int(self.lo) + below(rng, int(self.hi) - int(self.lo) + 1)
        if self.step:
            n = int(math.floor((self.hi - self.lo) / self.step * (1 + 1e-12))) + 1
            return float(f"{self.lo + self.step * below(rng, n):.12g}")
        u = (int(rng.bit_generator.random_raw()) >> 11) * 2.0 ** -53      # [0, 1), 53 random bits
        return float(f"{self.lo + (self.hi - self.lo) * u:.6g}")


@dataclass
class Variants:
    salt: str = ""
    params: list[Param] = field(default_factory=list)
    require: Callable[[dict], bool] | None = None
    require_text: str | None = None

    def draw(self, student: str) -> dict[str, float]:
        """The student's parameter values (``VariantError`` if ``require``
        never holds)."""
        streams = {p.name: _rng(self.salt, student, p.name) for p in self.params}
        for _ in range(MAX_ATTEMPTS):
            values = {p.name: p.draw(streams[p.name]) for p in self.params}
            if self.require is None or self.require(values):
                return values
        raise VariantError(f"variants.require '{shown(self.require_text)}' does not hold after "
                           f"{MAX_ATTEMPTS} draws for student '{shown(student)}'")

    def substitution(self, values: dict[str, float]) -> dict[str, Any]:
        """Values as ``params`` entries (a number, or 'number unit')."""
        units = {p.name: p.unit for p in self.params}
        return {n: (f"{v!r} {units[n]}" if units.get(n) else v) for n, v in values.items()}


def below(rng, n: int) -> int:
    """A whole number in [0, n), unbiased, from the stream's raw 64-bit
    outputs (rejection of the incomplete last block).  Only PCG64's raw
    output is used — numpy keeps it stable — so the draws never depend on
    how a numpy release implements ``Generator.integers``."""
    limit = (2 ** 64 // n) * n
    while True:
        r = int(rng.bit_generator.random_raw())
        if r < limit:
            return r % n


def _rng(salt: str, student: str, name: str):
    import numpy as np

    h = hashlib.sha256("\x1f".join((salt, student, name)).encode("utf-8")).digest()
    return np.random.Generator(np.random.PCG64(np.random.SeedSequence(int.from_bytes(h, "big"))))


# ---------------------------------------------------------------------------
# reading


class _Bad(Exception):
    def __init__(self, path: tuple, message: str):
        super().__init__(message)
        self.path, self.message = path, message


def read_variants(raw: Any, path: tuple, diag) -> Variants | None:
    """``variants:`` of a key; problems go to ``diag(path, message)``, every one
    of them (each parameter is read on its own)."""
    bad: list[_Bad] = []
    try:
        v = _read(raw, path, bad)
    except _Bad as exc:
        bad.append(exc)
    for b in bad:
        diag(b.path, b.message)
    return None if bad else v


def _known(raw: dict, allowed: tuple, path: tuple) -> None:
    for k in raw:
        if k not in allowed:
            raise _Bad(path + (k,), f"unknown key '{shown(k)}'{did_you_mean(str(k), allowed)}; "
                                    f"known: {', '.join(allowed)}")


def _read(raw: Any, path: tuple, bad: list) -> Variants:
    if not isinstance(raw, dict):
        raise _Bad(path, "variants must be a mapping {salt, params, require}")
    try:
        _known(raw, VARIANT_KEYS, path)
    except _Bad as exc:
        bad.append(exc)
    v = Variants()
    salt = raw.get("salt", "")
    if isinstance(salt, bool) or not isinstance(salt, (str, int, float)) or len(str(salt)) > 200:
        raise _Bad(path + ("salt",), "salt must be a short text (it seeds every draw with the student id)")
    v.salt = str(salt)
    ps = raw.get("params")
    if not isinstance(ps, dict) or not ps or len(ps) > MAX_VARIANT_PARAMS:
        raise _Bad(path + ("params",), f"params must be a mapping of 1 to {MAX_VARIANT_PARAMS} names: "
                                       "{uniform: [lo, hi], step: s} | {choice: [...]} | {integers: [lo, hi]}")
    for name, spec in ps.items():
        try:
            v.params.append(_param(name, spec, path + ("params", name)))
        except _Bad as exc:
            bad.append(exc)
    if "require" in raw and not bad:         # its names are the parameters read above
        v.require_text = raw["require"] if isinstance(raw["require"], str) else None
        v.require = condition(raw["require"], [p.name for p in v.params], path + ("require",))
    return v


def _num(x: Any, path: tuple) -> float:
    from dyncli.errors import InputError
    from dyncli.expr import constant

    if isinstance(x, bool) or not isinstance(x, (int, float, str)):
        raise _Bad(path, "expected a number")
    try:
        f = float(x) if not isinstance(x, str) else constant(x)
    except OverflowError:
        raise _Bad(path, "number is too large") from None
    except InputError as exc:
        raise _Bad(path, exc.message) from None
    if not math.isfinite(f) or abs(f) > 1e15:
        raise _Bad(path, "expected a finite number of magnitude at most 1e15")
    return f


def _pair(x: Any, path: tuple, what: str) -> tuple[float, float]:
    if not isinstance(x, list) or len(x) != 2:
        raise _Bad(path, f"{what} must be [lo, hi]")
    lo, hi = _num(x[0], path + (0,)), _num(x[1], path + (1,))
    if not lo <= hi:
        raise _Bad(path, f"{what}: lo must not exceed hi")
    return lo, hi


def _param(name: Any, spec: Any, path: tuple) -> Param:
    if not isinstance(name, str) or not name.isidentifier() or not name.isascii() or keyword.iskeyword(name):
        raise _Bad(path, f"'{shown(name)}' is not a parameter name (letters, digits, _)")
    if not isinstance(spec, dict):
        raise _Bad(path, "expected {uniform: [lo, hi], step: s}, {choice: [...]} or {integers: [lo, hi]}")
    _known(spec, PARAM_KEYS, path)
    kinds = [k for k in ("uniform", "choice", "integers") if k in spec]
    if len(kinds) != 1:
        raise _Bad(path, "give exactly one of uniform, choice, integers")
    p = Param(name, kinds[0])
    if "step" in spec and p.kind != "uniform":
        raise _Bad(path + ("step",), "step goes with uniform")
    if p.kind == "choice":
        vals = spec["choice"]
        if not isinstance(vals, list) or not vals or len(vals) > MAX_CHOICES:
            raise _Bad(path + ("choice",), f"choice must be a list of 1 to {MAX_CHOICES} numbers")
        p.values = [_num(x, path + ("choice", i)) for i, x in enumerate(vals)]
    else:
        p.lo, p.hi = _pair(spec[p.kind], path + (p.kind,), p.kind)
        if p.kind == "integers" and not (p.lo.is_integer() and p.hi.is_integer()):
            raise _Bad(path + ("integers",), "integers takes whole numbers [lo, hi]")
        if "step" in spec:
            p.step = _num(spec["step"], path + ("step",))
            if p.step <= 0 or (p.hi - p.lo) / p.step > 1e9:
                raise _Bad(path + ("step",), "step must be > 0 and give at most 1e9 grid points")
    if "unit" in spec:
        _unit(p, spec["unit"], path + ("unit",))
    return p


def _unit(p: Param, u: Any, path: tuple) -> None:
    from dyncli.check.quantities import unit_spec

    if not isinstance(u, str) or not u.strip() or len(u) > 40:
        raise _Bad(path, "unit must be a unit such as m/s, km/h, deg")
    try:
        unit_spec(u.strip())
    except ValueError as exc:
        raise _Bad(path, str(exc)) from None
    p.unit = u.strip()


# ---------------------------------------------------------------------------
# require: comparisons of expressions

_CMP = {ast.Lt: lambda a, b: a < b, ast.LtE: lambda a, b: a <= b, ast.Gt: lambda a, b: a > b,
        ast.GtE: lambda a, b: a >= b, ast.Eq: lambda a, b: a == b, ast.NotEq: lambda a, b: a != b}


def condition(text: Any, names: list[str], path: tuple) -> Callable[[dict], bool]:
    """Compile ``require``: Python's parser only finds the comparison and
    boolean structure (nothing is evaluated); each compared side is parsed by
    ``dyncli.expr`` with the variant parameters as its variables."""
    from dyncli.errors import InputError
    from dyncli.expr import MAX_LENGTH, parse

    if not isinstance(text, str) or not text.strip() or len(text) > MAX_LENGTH:
        raise _Bad(path, "require must be a condition such as \"v1**2/(2*abs(a)) < 100\"")
    src = text.strip()
    try:
        tree = ast.parse(src, mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        raise _Bad(path, f"require: syntax error in '{shown(src)}'") from None

    def side(node) -> Callable[[dict], float]:
        seg = ast.get_source_segment(src, node) or ""
        try:
            e = parse(seg, names)
        except InputError as exc:
            raise _Bad(path, f"require: {exc.message}") from None
        return lambda env: float(e(**{n: env[n] for n in e.variables}))

    def build(node, depth: int = 0) -> Callable[[dict], bool]:
        if depth > 20:
            raise _Bad(path, "require is nested too deeply")
        if isinstance(node, ast.BoolOp):
            parts = [build(v, depth + 1) for v in node.values]
            return (lambda env: all(p(env) for p in parts)) if isinstance(node.op, ast.And) \
                else (lambda env: any(p(env) for p in parts))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
            inner = build(node.operand, depth + 1)
            return lambda env: not inner(env)
        if isinstance(node, ast.Compare):
            sides = [side(node.left)] + [side(c) for c in node.comparators]
            ops = [_CMP[type(o)] for o in node.ops if type(o) in _CMP]
            if len(ops) != len(node.ops):
                raise _Bad(path, "require compares with < <= > >= == != only")

            def cmp(env):
                vals = [s(env) for s in sides]
                return all(math.isfinite(v) for v in vals) and all(op(a, b) for op, a, b in zip(ops, vals, vals[1:]))
            return cmp
        raise _Bad(path, "require must be a comparison (e.g. \"v1 < 2*v2\"), possibly joined by and/or/not")

    return build(tree)
