"""force-field `conservative` (issue 16): decimal coefficients that agree
only to rounding (0.1*3 vs 0.3) are conservative, while a small but real curl
(1e-10) is not — the numeric check is relative to the field's derivatives
(docs/types/force-field.md).  Reference: the curl by hand."""

from __future__ import annotations

import pytest

from tests.conftest import solve_one_text


def _verdict(F):
    r = solve_one_text(f"type: force-field\nF: {F}\npoints: [[1, 2, 3]]\n")["results"]
    return r["conservative"], r["curl"][0]


@pytest.mark.parametrize("F", ['["0.1*3*x2", "0.3*x1", "0"]', '["2*cos(pi/3)*x2", "x1", "0"]',
                               '["0.1*3e-12*x2", "0.3e-12*x1", "0"]', '["x2/3", "x1*(1/3)", "0"]'])
def test_rounding_level_curl_is_conservative(F):
    assert _verdict(F)[0] is True


@pytest.mark.parametrize("F,curl3", [('["1e-10*x2", "0", "0"]', -1e-10), ('["1e-200*x2", "0", "0"]', -1e-200),
                                     ('["x2*(1 + 1e-6)", "x1", "0"]', -1e-6)])
def test_small_real_curl_is_not_conservative(F, curl3):
    ok, curl = _verdict(F)
    assert ok is False
    assert curl[2] == pytest.approx(curl3, rel=1e-6)
