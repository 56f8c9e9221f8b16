"""Springs along the line of a ``rectilinear`` motion (notes §6, §19 (19.26a)): a fixed end at
``anchor`` (a position s), free length ``L``, stiffness ``k``, on a body of mass ``m``.

With d = s − anchor the spring's length is |d| and its force on the body is −k (|d| − L) sign(d);
``one_sided: compression`` keeps only the push (while |d| < L: a block dropped onto a spring),
``tension`` only the pull (while |d| > L: an elastic cord).  The springs' acceleration is added to
``a`` as an expression of the language itself, exactly as a student would write it by hand

    compression:  (k/m) max(L − |d|, 0) sign(d)
    tension:     −(k/m) max(|d| − L, 0) sign(d)
    two-sided:   −(k/m) (|d| − L) sign(d)          (−(k/m) d when L = 0)

so every route of the type treats it as any a(s) (case 4 when a uses nothing else: the energy
integral (6.14) with the kink at |d| = L).
"""

from __future__ import annotations

from typing import Annotated, Literal, Optional

from pydantic import Field, model_validator

from dyncli.expr import Expr
from dyncli.fields import Num, StrictModel
from dyncli.springs import one_sided_length
from dyncli.topics.rectilinear.setup import Spring


class LineSpring(StrictModel):
    """A linear spring along the line, fixed at ``anchor``: force −k (|d| − L) sign(d), d = s − anchor."""

    k: Annotated[float, Num(gt=0, dim="stiffness", description="stiffness [N/m]")]
    anchor: Annotated[float, Num(dim="length", description="position s of the spring's fixed end [m]")] = 0.0
    L: Annotated[float, Num(ge=0, dim="length", description="free length [m]")] = 0.0
    one_sided: Optional[Literal["compression", "tension"]] = Field(
        None, description="compression: only pushes (acts while |s − anchor| < L: a block dropped onto it); "
                          "tension: only pulls (|s − anchor| > L: an elastic cord); default two-sided")

    @model_validator(mode="after")
    def _one_sided_needs_length(self):
        one_sided_length(self.one_sided, self.L)
        return self


def _num(x: float) -> tuple:
    return ("num", float(x))


def _call(name: str, *args) -> tuple:
    return ("call", name, tuple(args))


def term(sp: Spring, m: float) -> tuple[tuple, str]:
    """The IR and the text of one spring's acceleration."""
    d = ("sub", ("var", "s"), _num(sp.anchor))
    km = _num(sp.k / m)
    sign, length = _call("sign", d), _call("abs", d)
    dt = f"(s - {sp.anchor:.17g})" if sp.anchor else "s"
    kt = f"{sp.k / m:.17g}"
    if sp.one_sided == "compression":
        ir: tuple = ("mul", ("mul", km, _call("max", ("sub", _num(sp.L), length), _num(0))), sign)
        return ir, f"{kt}*max({sp.L:.17g} - abs({dt}), 0)*sign({dt})"
    if sp.one_sided == "tension":
        ir = ("neg", ("mul", ("mul", km, _call("max", ("sub", length, _num(sp.L)), _num(0))), sign))
        return ir, f"-{kt}*max(abs({dt}) - {sp.L:.17g}, 0)*sign({dt})"
    if sp.L == 0:
        return ("neg", ("mul", km, d)), f"-{kt}*{dt}"
    return ("neg", ("mul", ("mul", km, ("sub", length, _num(sp.L))), sign)), f"-{kt}*(abs({dt}) - {sp.L:.17g})*sign({dt})"


def with_springs(a: Expr, springs: tuple[Spring, ...], m: float) -> Expr:
    """``a`` plus the springs' accelerations: one expression of t, s, v."""
    ir, text = a.ir, a.text
    for sp in springs:
        t_ir, t_text = term(sp, m)
        ir, text = ("add", ir, t_ir), f"{text} + {t_text}"
    return Expr(text, ir, a.allowed, frozenset(a.variables | {"s"}), a.params_used)
