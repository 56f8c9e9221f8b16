"""top: θ(t) with the nutation bounds θ_min, θ_max, and the trace of the axis."""

from __future__ import annotations

import math

import numpy as np

from tests.conftest import ROOT
from tests.plots.util import Fig, distinct_styles, line, panels, render_both, solved_path, solved_text


def _xy(ln):
    return [np.asarray(a, float) for a in ln.get_data()]


def _hlines(ax):
    return sorted(ln.get_ydata()[0] for ln in ax.get_lines() if ln.get_label().startswith("θ_m"))


def _released_theta_max(m, L, I11, I33, w3, th0, g=9.81):
    """Released with spin only (θ̇ = ψ̇ = 0): H·e3 = I33 ω3 cos θ0 and the energy
    ½ I11 ψ̇² sin²θ + mgL cos θ = mgL cos θ0 give, with u = cos θ ≠ u0,
    2 I11 mgL (1 − u²) = (I33 ω3)² (u0 − u): the other turning point."""
    a, b = 2 * I11 * m * g * L, (I33 * w3) ** 2
    u0 = math.cos(th0)
    roots = np.roots([a, -b, b * u0 - a])
    return math.acos(max(r.real for r in roots if r.real < u0 - 1e-12))


def test_nutating_top_bounds_and_axis_trace(tmp_path):
    pans = panels(solved_path("gyroscopic/top-nutating.yaml"))
    assert len(pans) == 2
    render_both(tmp_path, pans)
    th_max = _released_theta_max(0.5, 0.05, 2.0e-3, 1.0e-3, 100.0, 0.5)
    with Fig(pans) as f:
        ax, ax2 = f.axes
        assert ax.get_xlabel() == "t [s]" and ax.get_ylabel() == "θ [rad]"
        assert "Nutating top released with spin only" in ax.get_title()
        lo, hi = _hlines(ax)
        assert math.isclose(lo, 0.5, rel_tol=1e-9) and math.isclose(hi, th_max, rel_tol=1e-7)
        t, th = _xy(line(ax, "θ(t)"))
        assert t[0] == 0 and t[-1] == 2.0 and len(t) >= 600
        assert np.all(th >= lo - 1e-7) and np.all(th <= hi + 1e-7)
        assert th.max() > hi - 1e-5 and th.min() < lo + 1e-5       # it reaches both bounds
        pts = line(ax, "requested")
        assert list(pts.get_xdata()) == [0, 0.05, 0.1, 0.2, 0.5, 1, 2]
        assert distinct_styles(ax, ["θ(t)", "requested"])
        # the trace of the axis from above lies between the circles sin θ_min, sin θ_max
        x, y = _xy(line(ax2, "axis"))
        r = np.hypot(x, y)
        assert np.all(r >= math.sin(lo) - 1e-7) and np.all(r <= math.sin(hi) + 1e-7)
        assert math.isclose(x[0], math.sin(0.5), rel_tol=1e-12) and y[0] == 0     # ψ(0) = 0
        assert ax2.get_aspect() == 1.0
        assert distinct_styles(ax2, ["axis", "circle sin θ = sin θ_max", "circle sin θ = sin θ_min", "start"])


def test_steady_precession_is_not_rounding_noise():
    """Steady precession (slow root of 38.22): θ stays at π/6; the θ axis shows at least
    0.02 rad instead of magnifying rounding noise."""
    text = (ROOT / "problems/gyroscopic/top-steady-precession.yaml").read_text()
    text = text.replace("at: [0, 1, 2, 5]", "at: [0, 0.5]")
    solved = solved_text(text)[:1]
    with Fig(panels(solved)) as f:
        ax = f.axes[0]
        lo, hi = ax.get_ylim()
        assert hi - lo >= 0.02
        th = np.asarray(line(ax, "θ(t)").get_ydata(), float)
        assert np.ptp(th) < 1e-6 and abs(th[0] - math.pi / 6) < 1e-12


def test_default_span_without_at(tmp_path):
    solved = solved_text("type: top\nm: 0.5\nL: 0.05\nI11: 2.0e-3\nI33: 1.0e-3\ntheta: 0.5\nphi_dot: 100\n")
    pans = panels(solved)               # no 'at': a few nutations from the rates of the problem
    render_both(tmp_path, pans[:1])
    with Fig(pans) as f:
        t, th = _xy(line(f.axes[0], "θ(t)"))
        # fast-top nutation period ≈ 2π I11/(I33 ω3) = 0.126 s: three of them
        assert 0.3 < t[-1] < 0.5
        assert not [ln for ln in f.axes[0].get_lines() if ln.get_label().startswith("requested")]
