"""The parsed expression, :class:`Expr`: evaluation, constant value, sympy form."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

from dyncli.expr.evaluate import compile_ir, fold
from dyncli.expr.sympy_bridge import to_sympy


@dataclass(frozen=True)
class Expr:
    """A parsed, validated expression.

    ``variables`` are the free variables it actually uses (a subset of the
    ones the field allows); ``params_used`` the params names it refers to.
    """

    text: str
    ir: tuple
    allowed: tuple[str, ...] = ()
    variables: frozenset = frozenset()
    params_used: frozenset = frozenset()
    _fn: Callable | None = field(default=None, repr=False, compare=False)

    # -- evaluation -----------------------------------------------------
    @property
    def is_constant(self) -> bool:
        return not self.variables

    def scalar_fn(self) -> Callable[[Mapping[str, Any]], Any]:
        """The compiled evaluator ``f(env)`` itself, for a hot loop of scalar calls: no
        keyword packing and no per-call ``np.errstate`` (the caller runs inside one)."""
        fn = self._fn
        if fn is None:
            fn = compile_ir(self.ir)
            object.__setattr__(self, "_fn", fn)
        return fn

    def __call__(self, **env: Any) -> Any:
        """Evaluate with numpy, vectorised over array arguments.  The result
        broadcasts against the arguments (a constant stays a scalar; use
        :meth:`evaluate` for an array of the arguments' shape)."""
        fn = self.scalar_fn()
        import numpy as np

        with np.errstate(all="ignore"):
            return fn(env)

    def evaluate(self, **env: Any):
        """Like calling, but always returns a float array broadcast to the
        shape of the arguments."""
        import numpy as np

        val = self(**env)
        shapes = [np.shape(v) for v in env.values()]
        shape = np.broadcast_shapes(*shapes) if shapes else ()
        return np.broadcast_to(np.asarray(val, dtype=float), shape).copy()

    def value(self) -> float:
        """The value of a constant expression."""
        if self.variables:
            raise ValueError("not a constant expression")
        return fold(self.ir)

    # -- symbolic ---------------------------------------------------------
    def to_sympy(self, symbols: Mapping[str, Any] | None = None, keep_params: bool = False):
        """Build the sympy expression node by node (never from text).

        ``symbols`` maps variable names to sympy symbols (created as real
        symbols when missing).  With ``keep_params`` params appear as symbols
        instead of their values."""
        return to_sympy(self.ir, symbols or {}, keep_params)

    def __str__(self) -> str:
        return self.text
