"""Issue #28: case 4 (a = a(s)) must not pass a barrier it cannot climb.  A Gaussian barrier
V = exp(−((s − b)/w)²) per unit mass, w = 1e-4 (narrower than the scan's cells, so v² at the
nodes on either side is the same and positive), approached with v1² = 1.414² < 2 max V: the body
turns at s_T = b − w √ln(2/v1²) and comes back.  Reference: s(10) = 2(b − δ) − 10 v1 + 2 v1 I,
I = ∫_{b−δ}^{s_T} ds/√(v1² − 2V) (δ = 10 w; beyond it V < e^-100), mpmath at 30 digits."""

from __future__ import annotations

import mpmath as mp
import pytest

from tests.conftest import solve_one_text


def reference(b, w=1e-4, v1=1.414, t=10):
    with mp.workdps(30):
        w, v1, B = mp.mpf(w), mp.mpf(v1), mp.mpf(b)
        sT = B - w * mp.sqrt(mp.log(2 / v1 ** 2))
        d = 10 * w
        I = mp.quad(lambda s: 1 / mp.sqrt(v1 ** 2 - 2 * mp.exp(-((s - B) / w) ** 2)), [B - d, sT - w / 10, sT])
        return float(mp.re(2 * (B - d) - t * v1 + 2 * v1 * I))


@pytest.mark.parametrize("b", [1.00031, 0.7770123])
def test_a_narrow_barrier_between_the_scan_nodes_turns_the_body(b):
    rec = solve_one_text(f"type: rectilinear\nparams: {{w: 1.0e-4, b: {b!r}}}\n"
                         "a: \"2*(s-b)/w**2*exp(-((s-b)/w)**2)\"\ns1: 0\nv1: 1.414\nfind:\n  - {t: 10}\n")
    f = rec["results"]["find"][0]
    assert f["v"] == pytest.approx(-1.414, rel=1e-12)          # came back
    # within the estimate relative to the scale |s| + |v| t (≈ 28 m), itself ~1e-14
    assert abs(f["s"] - reference(b)) <= rec["error_estimate"] * 28


def test_a_barrier_hidden_between_two_scan_nodes_turns_the_body():
    # w = 1e-5 midway between the scan nodes 1.000 and 1.002: a underflows to 0 at both, the nodes
    # show no dip at all; the enclosures of a find it (the body went through at v = 1.414 before)
    b, w = 1.0011, 1e-5
    rec = solve_one_text(f"type: rectilinear\nparams: {{w: {w!r}, b: {b!r}}}\n"
                         "a: \"2*(s-b)/w**2*exp(-((s-b)/w)**2)\"\ns1: 0\nv1: 1.414\nfind:\n  - {t: 10}\n")
    f = rec["results"]["find"][0]
    assert f["v"] == pytest.approx(-1.414, rel=1e-12)
    assert abs(f["s"] - reference(b, w=w)) <= max(rec["error_estimate"], 1e-13) * 28
