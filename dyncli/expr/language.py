"""The words of the expression language: its limits, constants and functions,
the error it raises and the 'did you mean' hint (no parsing, no evaluation here)."""

from __future__ import annotations

import difflib
import math
from typing import Any, Iterable

from dyncli.errors import InputError

MAX_LENGTH = 2000
MAX_DEPTH = 64
MAX_CHAIN = 300   # terms of one + - or * / chain (a left spine in the AST)
MAX_NODES = 2000
MAX_PARAMS = 1000

CONSTANTS: dict[str, float] = {"pi": math.pi, "deg": math.pi / 180.0}

# name -> (min args, max args)  (max None = any number >= min)
FUNCTIONS: dict[str, tuple[int, int | None]] = {
    "sin": (1, 1), "cos": (1, 1), "tan": (1, 1),
    "asin": (1, 1), "acos": (1, 1), "atan": (1, 1), "atan2": (2, 2),
    "sinh": (1, 1), "cosh": (1, 1), "tanh": (1, 1),
    "exp": (1, 1), "log": (1, 1), "log10": (1, 1), "sqrt": (1, 1),
    "abs": (1, 1), "sign": (1, 1), "min": (2, None), "max": (2, None),
}

RESERVED = frozenset(CONSTANTS) | frozenset(FUNCTIONS)


class ExpressionError(InputError):
    """An expression that is not in the language (exit 2)."""


def did_you_mean(word: str, candidates: Iterable[str]) -> str:
    """``" (did you mean 'x'?)"`` or ``""``."""
    cands = sorted(set(candidates))
    close = difflib.get_close_matches(word, cands, n=1, cutoff=0.6)
    if not close:  # case slips: vb -> vB, Omega -> omega
        lower = {c.lower(): c for c in cands}
        hit = difflib.get_close_matches(word.lower(), sorted(lower), n=1, cutoff=0.6)
        close = [lower[hit[0]]] if hit else []
    return f" (did you mean '{close[0]}'?)" if close else ""


def kind_of(x: Any) -> str:
    """What a value of the wrong kind is, for an error message: "a mapping", "a list",
    "nothing (null)" or its type's name."""
    if isinstance(x, dict):
        return "a mapping"
    if isinstance(x, list):
        return "a list"
    if x is None:
        return "nothing (null)"
    return type(x).__name__
