"""The separatrix of a torque-free asymmetric body (H² = 2T·I2) is decided
exactly (issue 16): ω0 given with √3 lands on it — period null, k² = 1 —
and ω(t) follows the hyperbolic (sech/tanh) limit, checked against mpmath
odefun (docs/types/euler.md)."""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text
from tests.topics.euler.test_euler import mp_reference


R3, R2 = float(mp.sqrt(3)), float(mp.sqrt(2))


@pytest.mark.parametrize("I,w0,wf", [
    ([1, 2, 3], ["sqrt(3)", 0.5, 1], [R3, 0.5, 1]),          # 1·1·3 = 3·1·1
    ([3, 2, 1], [1, 0.5, "sqrt(3)"], [1, 0.5, R3]),
    ([1, 3, 4], ["sqrt(2)", -1, 1], [R2, -1, 1]),             # 1·2·2 = 4·1·1
])
def test_separatrix_given_with_square_roots(I, w0, wf):
    times = [0.5, 1.0]
    text = f"type: euler\nI: {I}\nomega0: {[str(x) for x in w0]}\nat: {times}\n".replace("'", '"')
    r = solve_one_text(text)["results"]
    assert r["period"] is None and r["m"] == 1.0
    ref = mp_reference(I, wf, times)
    for got, want in zip(r["omega"], ref):
        for g, w in zip(got, want):
            assert abs(g - w) <= 1e-13 * max(abs(x) for x in wf)


def test_near_separatrix_keeps_its_period():
    r = solve_one_text('type: euler\nI: [1, 2, 3]\nomega0: ["sqrt(3)*(1 + 1e-12)", 0.5, 1]\nat: [1]\n')["results"]
    assert r["period"] is not None and r["m"] < 1.0


def test_magnitudes_beyond_doubles_are_reported_not_printed_as_nan():
    """|H̄|, T of omega0 beyond a double: exit 2 naming omega0; T representable but the elliptic
    constants overflowing (ω'₀ ~ 1e154 with I ~ 1e-14): exit 1 with a message, not nan results."""
    from tests.conftest import error_of, solve_text

    msg = error_of("type: euler\nI: [1, 2, 3]\nomega0: [1e200, 1, 1]\n")
    assert "omega0" in msg and "beyond a double" in msg
    rec = solve_text("type: euler\nI: [6.7e-14, 6.4e-14, 5.4e-14]\nomega0: [-8.8e154, 2.3e-63, -3.5e8]\nat: [0, 1]\n")[0]
    assert rec["error"] is not None and rec["exit_code"] == 1 and "not representable in doubles" in rec["error"]
