"""True answers that are zero up to round-off (docs/check.md).

A closed form whose terms cancel gives 8.3e-17 where the physics gives 0.
Graded as it stands, such a value breaks both rules: ``sigfigs`` judges an
answer against its own tiny magnitude (the exact answer 0 fails), and a
diagnosis finds "a power of ten" in any small answer.  So a true number
with ``|x| <= ROUNDOFF * scale`` — ``scale`` the largest finite number in the
problem's results — is graded as exactly 0: correct within the tolerance's
absolute part (``atol``; with ``sigfigs: n``, ``0.51·10^(1-n)``), never
diagnosed, and flagged by ``--selftest``.
"""

from __future__ import annotations

import math
from typing import Any

ROUNDOFF = 1e-12


def scale_of(results: Any, limit: int = 100_000) -> float:
    """The largest finite |number| in ``results`` (0 if none)."""
    best, stack, seen = 0.0, [results], 0
    while stack and seen < limit:
        x = stack.pop()
        seen += 1
        if isinstance(x, dict):
            stack.extend(x.values())
        elif isinstance(x, list):
            stack.extend(x)
        elif isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x):
            best = max(best, abs(float(x)))
    return best


def snap(value: Any, scale: float) -> tuple[Any, bool]:
    """``value`` with round-off zeros made exactly 0.0; whether any was."""
    if isinstance(value, list):
        out = [snap(v, scale) for v in value]
        return [v for v, _ in out], any(f for _, f in out)
    if isinstance(value, dict):
        pairs = {k: snap(v, scale) for k, v in value.items()}
        return {k: v for k, (v, _) in pairs.items()}, any(f for _, f in pairs.values())
    if isinstance(value, float) and value != 0 and math.isfinite(value) and abs(value) <= ROUNDOFF * scale:
        return 0.0, True
    return value, False
