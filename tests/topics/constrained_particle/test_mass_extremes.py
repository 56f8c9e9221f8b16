"""The energy route is independent of the bead's mass over the whole double range: its energies are
held in a power-of-two unit balanced against the mass term, so a bead of 1e-301 kg (whose
energies, times a step of q, would be subnormal) runs the same route to the same accuracy, and
the normal force scales with m.  Reference: the pendulum's elliptic solution in mpmath at 50
digits, sin(q/2) = k sn(ωt + K | k²), as in test_long_times.py."""

from __future__ import annotations

import mpmath
import pytest

from tests.conftest import solve_one_text

TEXT = """type: constrained-particle
m: {m}
curve: {{x1: "0.5*sin(q)", x2: 0.5, x3: "-0.5*cos(q)"}}
q_range: [-pi, pi]
q0: 1
forces: [{{kind: gravity}}]
at: [0.5, 2]
find: [{{min: q}}]
"""


def _pendulum(t: float):
    with mpmath.workdps(50):
        k, w = mpmath.sin(mpmath.mpf(1) / 2), mpmath.sqrt(mpmath.mpf("9.81") / mpmath.mpf("0.5"))
        u = w * mpmath.mpf(t) + mpmath.ellipk(k * k)
        q = 2 * mpmath.asin(k * mpmath.ellipfun("sn", u, m=k * k))
        qd = 2 * k * w * mpmath.ellipfun("cn", u, m=k * k)
        # the hoop's normal force per unit mass along the radius: R q̇² + g cos q
        return q, qd, mpmath.mpf("0.5") * qd ** 2 + mpmath.mpf("9.81") * mpmath.cos(q), 2 * k * w


@pytest.mark.parametrize("m", ["1e-301", "1e-250", "1e-12", "1", "1e250", "1e300"])
def test_mass_drops_out(m):
    rec = solve_one_text(TEXT.format(m=m))
    assert rec["method"] == "quadrature", rec.get("warnings")
    r = rec["results"]
    mass = float(m)
    for i, t in enumerate((0.5, 2.0)):
        q, qd, n, top = _pendulum(t)
        assert abs(r["q"][i] - float(q)) <= rec["error_estimate"] + 1e-14
        assert abs(r["q_dot"][i] - float(qd)) <= (rec["error_estimate"] + 1e-14) * float(top)
        N = r["N"][i]
        size = max(abs(c) for c in N)
        assert abs(size / mass - float(n)) <= 1e-9 * float(n), (t, N, float(n))
    assert r["q"][0] < 0          # (the minimum query answered too: no budget exit)
