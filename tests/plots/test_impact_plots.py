"""impact: the admissible friction-angle bounds φ₁(θ), φ₂(θ) like Fig. 28.4."""

from __future__ import annotations

import math

import numpy as np

from tests.plots.util import Fig, distinct_styles, line, panels, render_both, solved_path, solved_text


def test_rough_admissible_renders(tmp_path):
    pans = panels(solved_path("impact/rough-admissible.yaml"))
    assert len(pans) == 1
    render_both(tmp_path, pans)


def test_bounds_and_point():
    solved = solved_path("impact/rough-admissible.yaml")
    eta = 0.5
    with Fig(panels(solved)) as f:
        (ax,) = f.axes
        assert "θ" in ax.get_xlabel() and "[rad]" in ax.get_xlabel()
        assert "φ" in ax.get_ylabel() and "[rad]" in ax.get_ylabel()
        assert "Rough impact inside the admissible cone" in ax.get_title()
        upper, lower = line(ax, "φ₂"), line(ax, "φ₁")
        assert distinct_styles(ax, ["φ₂", "φ₁", "this impact"])
        # independent: at θ = 0, (28.50) gives φ₂ = −φ₁ = ½ acos((1−η)/(1+η));
        # at θ = π/2, φ₁ = 0 and φ₂ = π/2
        half = 0.5 * math.acos((1 - eta) / (1 + eta))
        assert math.isclose(upper.get_ydata()[0], half, rel_tol=1e-12)
        assert math.isclose(lower.get_ydata()[0], -half, rel_tol=1e-12)
        assert upper.get_xdata()[-1] == math.pi / 2
        assert math.isclose(upper.get_ydata()[-1], math.pi / 2, rel_tol=1e-12)
        assert abs(lower.get_ydata()[-1]) < 1e-15
        # (28.52): φ₁ ≤ θ ≤ φ₂ along the whole curve
        th = np.asarray(upper.get_xdata())
        assert np.all(np.asarray(lower.get_ydata()) <= th + 1e-15)
        assert np.all(th <= np.asarray(upper.get_ydata()) + 1e-15)
        pt = line(ax, "this impact")
        assert pt.get_linestyle() == "None" and pt.get_marker() == "o"
        assert math.isclose(pt.get_xdata()[0], math.atan(1 / 3), rel_tol=1e-12)
        assert pt.get_ydata()[0] == 0.2
        assert "(admissible)" in pt.get_label()


def test_inadmissible_point_is_outside():
    with Fig(panels(solved_path("impact/rough-inadmissible.yaml"))) as f:
        pt = line(f.axes[0], "this impact")
        assert "NOT admissible" in pt.get_label()


def test_smooth_impact_draws_nothing():
    assert panels(solved_path("impact/oblique-smooth.yaml")) == []


def test_no_impact_draws_bounds_without_point():
    solved = solved_text("type: impact\nmA: 1\nmB: 1\nvA1: [-1, 1, 0]\nn: [1, 0, 0]\neta: 0.3\nphi: 0.1\n")
    with Fig(panels(solved)) as f:
        ax = f.axes[0]
        assert "no impact" in ax.get_title()
        assert not [ln for ln in ax.get_lines() if ln.get_label().startswith("this impact")]
