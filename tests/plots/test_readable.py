"""What makes a plot readable, independent of the topic (dyncli.render.plot),
and ``--plot DIR/`` writing one file per problem.

* a 3-D path in a plane of the basis is drawn in 2-D on that plane; a truly
  3-D path stays 3-D;
* a curve with more oscillations than the panel can show is shaded as its
  band (min-max over columns of at least two cycles), which contains every
  sample, with a note in the title; a slow curve is drawn as a line;
* legends sit below the axes (outside the data);
* ``--plot DIR/`` writes DIR/<file-stem>-<index>.png for each problem with
  plots, none for a problem without, and no plot re-solves a problem whose
  solver offers a sampler.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from dyncli.result import Line, Plot
from tests.conftest import run_cli
from tests.plots.util import Fig


def test_planar_path_drawn_in_2d():
    t = np.linspace(0, 2 * math.pi, 200)
    spec = Plot("path", "x₁ [m]", "x₂ [m]", [Line(np.cos(t).tolist(), [0.0] * 200, "path", z=np.sin(t).tolist())],
                zlabel="x₃ [m]")
    with Fig([("p", spec)]) as f:
        (ax,) = f.axes
        assert ax.name == "rectilinear" and ax.get_xlabel() == "x₁ [m]" and ax.get_ylabel() == "x₃ [m]"
        assert "x₂ = 0" in ax.get_title()
        assert ax.get_aspect() == 1.0


def test_true_3d_path_stays_3d():
    t = np.linspace(0, 4 * math.pi, 200)
    spec = Plot("helix", "x₁", "x₂", [Line(np.cos(t).tolist(), np.sin(t).tolist(), "h", z=(0.1 * t).tolist())],
                zlabel="x₃")
    with Fig([("p", spec)]) as f:
        assert f.axes[0].name == "3d"


def test_fast_oscillation_is_a_band_holding_every_sample():
    from dyncli.render import plot as P

    t = np.linspace(0, 20, 4000)
    y = np.exp(-0.1 * t) * np.sin(30 * t)              # 95 cycles
    spec = Plot("fast", "t [s]", "x [m]", [Line(t.tolist(), y.tolist(), "x(t)", style="-")])
    with Fig([("p", spec)]) as f:
        (ax,) = f.axes
        assert "oscillations" in ax.get_title() and "band" in ax.get_title()
        assert not [ln for ln in ax.get_lines() if ln.get_label().startswith("x(t)")]
        (band,) = [c for c in ax.collections if c.get_label().startswith("x(t)")]
        leg = ax.get_legend()
        assert leg is not None and leg.get_bbox_to_anchor().y0 < ax.bbox.y0     # below the axes
    c, lo, hi = P.dense_band(t, y, P.count_cycles(y) // 2)
    k = np.clip(np.searchsorted(np.linspace(0, 20, len(c) + 1), t, side="right") - 1, 0, len(c) - 1)
    assert np.all(lo[k] <= y) and np.all(y <= hi[k])
    assert c[0] == 0 and c[-1] == 20


def test_slow_curve_is_a_line():
    t = np.linspace(0, 20, 4000)
    spec = Plot("slow", "t [s]", "x [m]", [Line(t.tolist(), np.sin(t).tolist(), "x(t)", style="-")])
    with Fig([("p", spec)]) as f:
        (ax,) = f.axes
        assert [ln for ln in ax.get_lines() if ln.get_label() == "x(t)"] and "band" not in ax.get_title()


def test_plot_dir_writes_one_file_per_problem(tmp_path):
    out = tmp_path / "out"
    rc, _, stderr = run_cli("solve", "problems/impact/cone-fig28-4.yaml", "problems/vibration/underdamped.yaml",
                            "problems/impact/wall.yaml", "--plot", str(out) + "/")
    assert rc == 0, stderr
    names = sorted(p.name for p in out.iterdir())
    assert names == [f"cone-fig28-4-{i}.png" for i in range(9)] + ["underdamped-0.png"]   # wall.yaml: no plot
    assert "to 10 file(s)" in stderr
    from PIL import Image

    w, h = Image.open(out / "underdamped-0.png").size
    assert w <= 1400 and h <= 1200                     # one problem's panels, not the whole run's


@pytest.mark.parametrize("rel", ["particle/projectile-quadratic-drag.yaml", "rectilinear/case4-spring.yaml",
                                 "gyroscopic/euler-intermediate-axis.yaml", "vibration/base-excitation.yaml"])
def test_plots_do_not_solve_again(rel, monkeypatch):
    """The views read the result (its sampler); the topic's solve() is not called."""
    import importlib

    from tests.plots.util import specs, solved_path

    solved = solved_path(rel)
    lp = solved[0][0]
    from dyncli import registry

    mod = importlib.import_module(registry.TYPES[lp.type].package + ".solver")

    def boom(*a, **k):
        raise AssertionError("a plot solved the problem again")

    monkeypatch.setattr(mod, "solve", boom)
    assert specs(solved)


def test_rectilinear_span_follows_the_motion():
    from dyncli.topics.rectilinear.plots import span

    lo, hi, far = span(0.0, [1.0, -1.0, 1.81, 4.3, 14.6, 100.0], None, 1000.0)
    assert lo == -1.0 and 14.6 < hi < 20 and far == [100.0]          # the ball at terminal speed: t = 100 named
    lo, hi, far = span(0.0, [1.0, 2.0, 3.0], None, 1000.0)
    assert (lo, far) == (0.0, []) and math.isclose(hi, 3.3)
    P = 2 * math.pi / 5
    lo, hi, far = span(0.0, [1.0, -0.7, 50.0, 0.22], P, 1000.0)     # a spring: 50 s is 40 periods away
    assert far == [50.0] and hi - lo >= 2 * P and hi < 5
    lo, hi, far = span(0.0, [], None, 4.0)
    assert (lo, hi, far) == (0.0, 4.0, [])


def test_rounding_noise_is_not_an_oscillation():
    from dyncli.render import plot as P

    y = 0.5235987755982988 + 1e-16 * np.sin(np.arange(5000) * 1.7)
    assert P.count_cycles(y) == 0
    assert P.count_cycles(np.sin(np.linspace(0, 20 * math.pi, 5000))) == 10


def test_near_critical_envelope_not_drawn():
    """ζ = 1 − 1e-12: A ≈ 7e5 m for a motion of 1 m; drawing L ± A e^(−ζωₙt)
    would squash x(t) into a line."""
    from tests.plots.util import panels, solved_path

    pans = panels(solved_path("vibration/near-critical.yaml"))
    spec = pans[0][1]
    assert "not drawn" in spec.title and not [ln for ln in spec.lines if (ln.label or "").startswith("envelope")]
    ys = [v for ln in spec.lines for v in ln.y if v == v]
    assert max(ys) - min(ys) < 2.0
