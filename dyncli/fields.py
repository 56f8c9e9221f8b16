"""Field types for problem models (pydantic v2), shared by every topic.

Every numeric field takes a YAML number or a string holding a constant
expression (``"pi/6"``, ``"sqrt(k/m)"``) evaluated with the problem's
``params`` (passed as validation context ``{"params": {...}}``).

Declare a field as ``Annotated[<type>, <factory>(...)]``, a form mypy reads
(the factory's :class:`dyncli.fieldspec.FieldSpec`: pydantic's validator and JSON schema)::

    m: Annotated[float, Num(gt=0, dim="mass")]            # float > 0
    e: Annotated[float, Num(ge=0, le=1)]                  # 0 <= e <= 1
    mB: Annotated[float, Num(gt=0, allow_inf=True)]       # .inf allowed
    vA1: Annotated[Vector, Vec3()]                        # list of 3 -> tuple of 3 floats
    R: Annotated[Matrix, Tensor3()]                       # 3x3 list -> tuple of 3 rows
    a: Annotated[Expr, ExprField(("t", "s", "v"))]        # dyncli.expr.Expr
    omega: Annotated[ExprTriple, ExprVec3(("t",))]        # tuple of 3 Expr
    at: Annotated[list[float], Times()]                   # list of floats (may be empty)

``dim`` is the physical dimension (used by docs, schema and units support).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, ClassVar, Iterable, Optional

from pydantic import BaseModel, ConfigDict, Field, ValidationInfo
from pydantic.functional_validators import PlainValidator
from pydantic.json_schema import WithJsonSchema
from pydantic_core import PydanticCustomError

from dyncli import expr as _expr
from dyncli.errors import InputError
from dyncli.fieldspec import FieldSpec

NUMBER_SCHEMA: dict[str, Any] = {
    "anyOf": [
        {"type": "number"},
        {"type": "string", "description": "constant expression, e.g. \"pi/6\" or \"sqrt(k/m)\""},
    ]
}


#: the Python types of the fields the factories below validate (the first argument of ``Annotated``)
Vector = tuple[float, float, float]
Matrix = tuple        # 3 rows, each a tuple of 3 floats (bare ``tuple``: the type pydantic has always been given)
ExprTriple = tuple    # 3 :class:`dyncli.expr.Expr` (bare ``tuple``, as above)
Expr = _expr.Expr


class StrictModel(BaseModel):
    """Base for every input model: unknown fields are errors.  A field's declared ``dim`` is checked
    when the class is built: a misspelt dimension is an error naming the type and the field (it
    would otherwise turn the unit check off)."""

    model_config = ConfigDict(extra="forbid", frozen=False, arbitrary_types_allowed=True)

    #: keys users write that this model names otherwise: a key -> the field it means (the unknown
    #: key's message says to rename it) or a sentence saying how the model asks for it
    unknown_keys: ClassVar[dict[str, str]] = {}

    @classmethod
    def __pydantic_init_subclass__(cls, **kwargs: Any) -> None:
        super().__pydantic_init_subclass__(**kwargs)
        from dyncli.units import UnknownDimension, normalise_dim

        for name, info in cls.model_fields.items():
            for dim in _declared_dims([info.annotation, *info.metadata]):
                try:
                    normalise_dim(dim)
                except UnknownDimension as exc:
                    raise UnknownDimension(f"{_model_label(cls)}, field {name!r}: {exc}") from None


def _declared_dims(items: list[Any]) -> Iterable[str]:
    """The ``x-dimension`` of every field type in ``items`` (annotations and their metadata, nested
    in ``Optional[...]``, ``list[...]``, ``dict[...]``)."""
    from typing import get_args

    todo = list(items)
    while todo:
        item = todo.pop()
        if isinstance(item, (FieldSpec, WithJsonSchema)):
            dim = item.json_schema.get("x-dimension") if isinstance(item.json_schema, dict) else None
            if dim:
                yield dim
            continue
        todo.extend(get_args(item))


def _model_label(cls: type[BaseModel]) -> str:
    """``type 'rectilinear' (Rectilinear)`` for a problem model, the class name for a part of one."""
    from typing import get_args

    field = cls.model_fields.get("type")
    names = get_args(field.annotation) if field is not None else ()
    return f"type {names[0]!r} ({cls.__name__})" if names and isinstance(names[0], str) else f"model {cls.__name__}"


def _params(info: ValidationInfo | None) -> dict[str, float]:
    ctx = getattr(info, "context", None) or {}
    return ctx.get("params", {})


def _params_print(info: ValidationInfo | None) -> Any:
    """The fingerprint of the context's params (:func:`dyncli.docmemo.fingerprint`, the key of the
    constants' memo), made at the first expression of a validation and kept in its context (the
    params of one validation do not change); None when there is none to keep."""
    ctx = getattr(info, "context", None)
    if type(ctx) is not dict:
        return None
    params = ctx.get("params")
    if type(params) is not dict:
        return None
    got = ctx.get(_PRINT)
    if got is None or got[0] is not params:
        from dyncli.docmemo import Unkeyable, fingerprint

        try:
            got = ctx[_PRINT] = (params, fingerprint(params))
        except (Unkeyable, RecursionError):
            return None
    return got[1]


_PRINT = "params fingerprint"       # (a key no context is given by a caller)


def _err(msg: str) -> PydanticCustomError:
    # the message travels as context: pydantic renders "{msg}" with it and
    # never reads braces inside it (a quoted "f'{1}'" stays as written)
    return PydanticCustomError("dyncli", "{msg}", {"msg": msg})


def to_float(value: Any, info: ValidationInfo | None = None, *, allow_inf: bool = False, dim: str | None = None) -> float:
    """Number, constant expression or number-with-unit -> float in SI
    (raises PydanticCustomError)."""
    if isinstance(value, bool):
        raise _err(f"expected a number, got {value!r}")
    if isinstance(value, (int, float)):
        try:
            v = float(value)
        except OverflowError:
            raise _err("number is too large") from None
    elif isinstance(value, str):
        try:
            v = _expr.constant(value, _params(info), _params_print(info))
        except InputError as exc:
            from dyncli import units

            if not units.looks_like_quantity(value):
                raise _err(exc.message) from None
            try:
                v = units.parse_quantity(value, dim)
            except units.UnitError as uexc:
                raise _err(str(uexc)) from None
        except ValueError:
            raise _err(f"{value!r} is not a constant: it uses a variable") from None
    else:
        what = "a list" if isinstance(value, list) else "a mapping" if isinstance(value, dict) else "nothing (null)" if value is None else type(value).__name__
        raise _err(f"expected a number, got {what}")
    if math.isnan(v):
        raise _err("not a number (NaN) is not allowed")
    if math.isinf(v) and not allow_inf:
        raise _err("must be finite (got infinity)")
    return v


def Num(
    *,
    gt: float | None = None,
    ge: float | None = None,
    lt: float | None = None,
    le: float | None = None,
    allow_inf: bool = False,
    dim: str | None = None,
    description: str | None = None,
) -> FieldSpec:
    """A float field accepting numbers and constant expressions."""

    def validate(value: Any, info: ValidationInfo) -> float:
        # a finite float is its own value, a YAML int of at most 2**53 its float (to_float's
        # answers, without its questions: every problem's numbers come this way)
        t = type(value)
        v = value if t is float and -math.inf < value < math.inf else float(value) if t is int and \
            -_EXACT <= value <= _EXACT else to_float(value, info, allow_inf=allow_inf, dim=dim)
        if gt is not None and not v > gt:
            raise _err(f"must be > {_fmt(gt)}, got {_fmt(v)}")
        if ge is not None and not v >= ge:
            raise _err(f"must be >= {_fmt(ge)}, got {_fmt(v)}")
        if lt is not None and not v < lt:
            raise _err(f"must be < {_fmt(lt)}, got {_fmt(v)}")
        if le is not None and not v <= le:
            raise _err(f"must be <= {_fmt(le)}, got {_fmt(v)}")
        return v

    schema = dict(NUMBER_SCHEMA)
    extra = {}
    if dim:
        from dyncli.units import UnknownDimension, si_unit

        extra["x-dimension"] = dim
        try:
            extra["x-unit"] = si_unit(dim)
        except UnknownDimension:
            pass        # the model's class (StrictModel.__pydantic_init_subclass__) names the field
    if description:
        schema["description"] = description
    return FieldSpec(validate, {**schema, **extra})


_EXACT = 2 ** 53


def _fmt(v: float) -> str:
    return f"{v:.6g}"


def Vec3(*, nonzero: bool = False, unit: bool = False, dim: str | None = None, description: str | None = None) -> FieldSpec:
    """A vector: list of 3 numbers/expressions -> tuple of 3 floats
    (``unit``: a direction, returned normalised)."""

    def validate(value: Any, info: ValidationInfo) -> tuple[float, ...]:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            raise _err("expected a vector: a list of 3 numbers, e.g. [1, 0, 0]")
        if not isinstance(value, (list, tuple)) or len(value) != 3:
            n = len(value) if isinstance(value, (list, tuple)) else None
            raise _err("expected a vector: a list of 3 numbers" + (f", got {n} entries" if n is not None else ""))
        out = []
        for i, x in enumerate(value):
            try:
                out.append(to_float(x, info, dim=dim))
            except PydanticCustomError as exc:
                raise _err(f"component {i + 1}: {exc.message()}") from None
        if (nonzero or unit) and all(c == 0 for c in out):
            raise _err("must be a non-zero vector")
        if unit:   # normalised, scaled first: [0, 0, 2] and [0, 0, 1e-200] are e3 (dyncli.direction)
            from dyncli.direction import unit as _unit

            return tuple(float(c) for c in _unit(out))
        return tuple(out)

    schema = {"type": "array", "items": NUMBER_SCHEMA, "minItems": 3, "maxItems": 3}
    if dim:
        schema["x-dimension"] = dim
    if description:
        schema["description"] = description
    return FieldSpec(validate, schema)


def Tensor3(*, symmetric: bool = False, dim: str | None = None, description: str | None = None) -> FieldSpec:
    """A 3x3 list of rows -> tuple of 3 tuples of floats."""

    def validate(value: Any, info: ValidationInfo):
        if not isinstance(value, (list, tuple)) or len(value) != 3 or not all(
            isinstance(r, (list, tuple)) and len(r) == 3 for r in value
        ):
            raise _err("expected a 3x3 tensor: a list of 3 rows of 3 numbers")
        rows = []
        for i, r in enumerate(value):
            row = []
            for j, x in enumerate(r):
                try:
                    row.append(to_float(x, info, dim=dim))
                except PydanticCustomError as exc:
                    raise _err(f"entry ({i + 1},{j + 1}): {exc.message()}") from None
            rows.append(tuple(row))
        if symmetric:
            scale = max(1e-300, max(abs(x) for r in rows for x in r))
            for i in range(3):
                for j in range(i + 1, 3):
                    if abs(rows[i][j] - rows[j][i]) > 1e-9 * scale:
                        raise _err(f"must be symmetric: entry ({i + 1},{j + 1}) != ({j + 1},{i + 1})")
        return tuple(rows)

    schema = {"type": "array", "items": {"type": "array", "items": NUMBER_SCHEMA, "minItems": 3, "maxItems": 3}, "minItems": 3, "maxItems": 3}
    if dim:
        schema["x-dimension"] = dim
    if description:
        schema["description"] = description
    return FieldSpec(validate, schema)


def parse_expr_value(value: Any, variables: Iterable[str], info: ValidationInfo | None, dim: str | None = None) -> _expr.Expr:
    if isinstance(value, bool) or value is None or isinstance(value, (list, dict)):
        what = {True: "a boolean", False: "a boolean"}.get(value, None) if isinstance(value, bool) else (
            "nothing (null)" if value is None else "a list" if isinstance(value, list) else "a mapping")
        raise _err(f"expected a number or an expression string, got {what}")
    try:
        return _expr.parse(value, tuple(variables), _params(info))
    except InputError as exc:
        from dyncli import units

        if isinstance(value, str) and units.looks_like_quantity(value):
            try:  # a constant with a unit, e.g. "-9.81 m/s^2"
                return _expr.Expr(value, ("num", units.parse_quantity(value, dim)), tuple(variables))
            except units.UnitError as uexc:
                raise _err(str(uexc)) from None
        raise _err(exc.message) from None


def ExprField(variables: Iterable[str], *, dim: str | None = None, description: str | None = None) -> FieldSpec:
    """An expression in the given free variables -> :class:`dyncli.expr.Expr`."""
    variables = tuple(variables)

    def validate(value: Any, info: ValidationInfo) -> _expr.Expr:
        if isinstance(value, _expr.Expr):
            return value
        return parse_expr_value(value, variables, info, dim)

    desc = description or (f"number or expression in {', '.join(variables)}" if variables else "number or constant expression")
    schema = {"anyOf": [{"type": "number"}, {"type": "string"}], "description": desc}
    if dim:
        schema["x-dimension"] = dim
    return FieldSpec(validate, schema)


def ExprVec3(variables: Iterable[str], *, dim: str | None = None, description: str | None = None) -> FieldSpec:
    """Three expressions (components of a vector) -> tuple of 3 Expr."""
    variables = tuple(variables)

    def validate(value: Any, info: ValidationInfo):
        if not isinstance(value, (list, tuple)) or len(value) != 3:
            raise _err("expected a list of 3 numbers or expressions (components on the basis)")
        out = []
        for i, x in enumerate(value):
            if isinstance(x, _expr.Expr):
                out.append(x)
                continue
            try:
                out.append(parse_expr_value(x, variables, info, dim))
            except PydanticCustomError as exc:
                raise _err(f"component {i + 1}: {exc.message()}") from None
        return tuple(out)

    desc = description or f"3 numbers or expressions in {', '.join(variables)}"
    schema = {"type": "array", "items": {"anyOf": [{"type": "number"}, {"type": "string"}]}, "minItems": 3, "maxItems": 3, "description": desc}
    if dim:
        schema["x-dimension"] = dim
    return FieldSpec(validate, schema)


MAX_TIMES = 100_000


def Times(*, max_len: int = MAX_TIMES, description: str = "times at which to report the state",
          from_zero: bool = False) -> FieldSpec:
    """A list of time values (numbers or constant expressions); a single number is accepted as a
    one-element list; with ``from_zero`` every time is >= 0 (a motion given at t = 0)."""

    def validate(value: Any, info: ValidationInfo) -> list[float]:
        if value is None:
            return []
        if not isinstance(value, (list, tuple)):
            value = [value]
        if len(value) > max_len:
            raise _err(f"too many times ({len(value)}, at most {max_len})")
        fast = _plain_times(value, from_zero)
        if fast is not None:
            return fast
        out = []
        for i, x in enumerate(value):
            try:
                out.append(to_float(x, info, dim="time"))
            except PydanticCustomError as exc:
                raise _err(f"entry {i}: {exc.message()}") from None
            if from_zero and out[-1] < 0:
                raise _err(f"entry {i}: times must be >= 0 (the initial conditions hold at t = 0), got {out[-1]:g}")
        return out

    schema = {"type": "array", "items": NUMBER_SCHEMA, "description": description}
    return FieldSpec(validate, schema)


def _plain_times(value, from_zero: bool) -> list[float] | None:
    """``value`` as floats when every entry is a plain int or float, all finite (and ≥ 0 with
    ``from_zero``): what the entry-by-entry check gives such a list, decided at C speed (a list
    of 1e5 times); None otherwise (the entries then checked one by one, with their messages)."""
    if not set(map(type, value)) <= {float, int}:
        return None
    try:
        out = list(map(float, value))
        total = sum(out)
    except OverflowError:
        return None
    if not math.isfinite(total) or (from_zero and out and min(out) < 0):
        return None
    return out


def check_times(p) -> None:
    """A motion's report times, checked on its model ``p`` (fields ``t_end`` and ``at``): t_end
    defaults to max(at); every time of at in [0, t_end]; at defaults to [0, t_end]."""
    if p.t_end is None:
        if not p.at:
            raise InputError("give t_end or the times 'at' (t_end defaults to the largest time in 'at')", "t_end")
        p.t_end = max(p.at)
    for i, t in enumerate(p.at):
        if t < 0 or t > p.t_end:
            raise InputError(f"time {t:g} is outside [0, t_end = {p.t_end:g}]", f"at.{i}")
    if not p.at:
        p.at = [0.0, p.t_end]


#: the ``find`` queries of a motion (§11), validated where they are answered (dyncli.queries), each
#: error at its ``find.N.<field>``
FIND_SCHEMA = {"type": "array", "items": {"type": "object"},
               "description": "queries about the motion: {t: T}, {when: {RESULT: VALUE}, direction, occurrence}, "
                              "{max: RESULT}, {min: RESULT} (optional within: [t1, t2])"}


def Find() -> FieldSpec:
    """The ``find`` list of a type that reports a motion (§11); its entries are checked when they
    are answered, with their field paths."""
    return FieldSpec(None, FIND_SCHEMA)


# ---------------------------------------------------------------------------
# the fields every problem may have


ACCURACY_METHODS_DEFAULT = ("auto",)

#: the smallest accuracy.rtol: about 100 machine epsilons (2.2e-14).  Written as the round value 2.3e-14.  Below it a
#: double-precision step cannot honour the tolerance (scipy's integrators
#: raise it there with a warning); dyncli refuses it, for every type alike.
RTOL_MIN = 2.3e-14       # >= 100 * sys.float_info.epsilon, written as users would


def _rtol(value: Any, info: ValidationInfo) -> float:
    v = to_float(value, info)
    if not v > 0:
        raise _err(f"must be > 0, got {_fmt(v)}")
    if not v < 1:
        raise _err(f"must be < 1, got {_fmt(v)}")
    if not v >= RTOL_MIN:
        raise _err(f"{_fmt(v)} is below the smallest relative tolerance a double-precision step can honour: "
                   f"use rtol >= {RTOL_MIN:g} (about 100 machine epsilons)")
    return v


class Accuracy(StrictModel):
    """Accuracy controls for types with a numerical step (docs/getting-started.md, problem files)."""

    rtol: Annotated[float, PlainValidator(_rtol), WithJsonSchema({**NUMBER_SCHEMA, "exclusiveMaximum": 1, "minimum": RTOL_MIN})] = 1e-10
    atol: Annotated[float, Num(gt=0)] = 1e-12
    method: str = Field("auto", description="auto picks the cheapest exact route (closed form > quadrature > ODE)")
    estimate: bool = Field(False, description="also solve at a tighter tolerance and report the difference as error_estimate")
    max_steps: Optional[int] = Field(None, gt=0, description="cap on integrator steps (types that integrate; default set per type); a run that needs more fails fast with exit 1")
    max_cpu: Optional[float] = Field(None, gt=0, description="CPU seconds (the solving thread's user time) one solve may take (integrating routes); default 2 s unless max_steps is given; a run projected beyond it fails fast with exit 1")


class ProblemBase(StrictModel):
    """Fields every problem may have (docs/getting-started.md, problem files).

    Subclasses set ``type: Literal["name"]`` and may set the class variable
    ``accuracy_methods`` (the accepted ``accuracy.method`` values)."""

    title: str | None = None
    params: dict[str, Any] = Field(default_factory=dict, description="name: number-or-expression, usable in every expression")
    g: Annotated[float, Num(ge=0, dim="acceleration")] = 9.81
    accuracy: Accuracy = Field(default_factory=Accuracy)

    accuracy_methods: ClassVar[tuple[str, ...]] = ACCURACY_METHODS_DEFAULT

    def model_post_init(self, __context: Any) -> None:
        methods = type(self).accuracy_methods
        if self.accuracy.method not in methods:
            from dyncli.expr import did_you_mean

            raise InputError(
                f"unknown method {self.accuracy.method!r}{did_you_mean(self.accuracy.method, methods)}; "
                f"choose one of: {', '.join(methods)}",
                "accuracy.method",
            )
