"""A scene's distance over hundreds of oscillations of a closed form: the disk rolling on an
incline held by a spring (the gallery's), released at the spring's free length from rest, moves
as s = s_eq − A cos ωt along the slope, A = m g sin β / k, ω² = k / (m + Ī/R²) — its centre's
distance is 2A per half period (the notes' vibration closed form, by hand here).  The distance's
pieces each span several half periods: every stop inside one must be found and every piece
resolved (the odometer was 1.3 % short at t = 200 s, silently, before its pieces were checked)."""

from __future__ import annotations

import math
import pytest

from tests.conftest import PROBLEMS, solve_text


def test_rolling_disk_distance_after_hundreds_of_periods():
    text = (PROBLEMS / "scenes" / "rolling-disk-spring.yaml").read_text()
    lines = [ln for ln in text.splitlines() if not ln.startswith(("at:", "find:"))]
    times = [0.7, 100.3, 200.0]
    rec = solve_text("\n".join(lines) + f"\nat: {times}\n", "disk.yaml")[0]
    assert rec.get("error") is None, rec.get("error")
    m, k, beta, g = 2.0, 250.0, math.radians(30), 9.81
    A, w = m * g * math.sin(beta) / k, math.sqrt(k / (1.5 * m))
    for t, d in zip(times, rec["results"]["distance"]["disk"]):
        n = math.floor(w * t / math.pi)
        ref = 2 * A * n + A * (1 - math.cos(w * t - n * math.pi))
        assert d == pytest.approx(ref, rel=1e-9), t
    assert not any("distance" in w for w in rec["warnings"])
