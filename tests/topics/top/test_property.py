"""Property test: random heavy tops conserve E, H·e3 and ω3, and θ stays
within the bounds [θ_min, θ_max] from the cubic in cosθ."""

from __future__ import annotations

import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.conftest import solve_one_text
from tests.topics.top import reference as ref

TIMES = [0.0, 0.05, 0.1, 0.15, 0.2]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    m=st.floats(0.1, 5.0), L=st.floats(0.01, 0.3),
    extra=st.floats(0.05, 3.0), ratio=st.floats(0.05, 1.95),
    th=st.floats(0.02, math.pi - 0.02),
    thd=st.floats(-5, 5), psd=st.floats(-10, 10), phd=st.floats(-150, 150),
)
def test_random_tops_conserve_and_stay_in_bounds(m, L, extra, ratio, th, thd, psd, phd):
    g = 9.81
    Ibar = extra * m * L * L          # central transverse moment
    A = Ibar + m * L * L              # about O (31.7)
    C = ratio * Ibar                  # central axial moment, triangle inequality
    rec = solve_one_text(
        f"type: top\nm: {m!r}\nL: {L!r}\nI11: {A!r}\nI33: {C!r}\ntheta: {th!r}\ntheta_dot: {thd!r}\n"
        f"psi_dot: {psd!r}\nphi_dot: {phd!r}\nat: {TIMES}\naccuracy: {{rtol: 1.0e-10, atol: 1.0e-12}}\n")
    r = rec["results"]
    mgL = m * g * L
    E0, H0, W0 = ref.invariants(A, C, mgL, th, thd, psd, phd)
    w2 = thd ** 2 + (psd * math.sin(th)) ** 2 + (psd * math.cos(th) + phd) ** 2
    Es = 0.5 * (A + C) * w2 + mgL
    Hs = (A + C) * math.sqrt(w2) + math.sqrt(4 * A * mgL)
    lo, hi = r["theta_min"], r["theta_max"]
    assert lo <= th + 1e-15 and hi >= th - 1e-15
    for k in range(len(TIMES)):
        assert lo - 1e-8 <= r["theta"][k] <= hi + 1e-8
        if r["psi_dot"][k] is None or math.sin(r["theta"][k]) < 1e-3:
            continue  # ψ̇ is ill-conditioned next to the vertical
        E, H, W = ref.invariants(A, C, mgL, r["theta"][k], r["theta_dot"][k], r["psi_dot"][k], r["phi_dot"][k])
        assert abs(E - E0) <= 1e-7 * Es
        assert abs(H - H0) <= 1e-7 * Hs
        assert abs(W - W0) <= 1e-9 * (math.sqrt(w2) + 1e-300) + 1e-12
    assert r["drift"] < 1e-7
    assert rec["error_estimate"] is not None
    # bounds agree with the independent mpmath roots
    lo_r, hi_r = ref.bounds_mp(m, L, A, C, g, th, thd, psd, phd)
    assert abs(lo - lo_r) < 1e-9 and abs(hi - hi_r) < 1e-9
