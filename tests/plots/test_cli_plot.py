"""`dyncli solve --plot` end to end, and matplotlib kept out of every
non-plot code path."""

from __future__ import annotations

import json
import subprocess
import sys

from tests.conftest import ROOT, run_cli


def test_cli_plot_svg(tmp_path):
    out = tmp_path / "all.svg"
    rc, stdout, stderr = run_cli("solve", "problems/impact/rough-admissible.yaml", "problems/vibration/sweep.yaml",
                                 "problems/rectilinear/case1-constant-acceleration.yaml", "--plot", str(out))
    assert rc == 0, stderr
    assert "wrote 4 plot panel(s)" in stderr
    svg = out.read_text()
    assert svg.startswith("<?xml") and "<svg" in svg
    # the text of titles/labels is in the file (svg.fonttype "path" draws glyphs, so check the ids)
    assert svg.count('id="axes_') == 4
    assert "Date" not in svg                     # deterministic metadata
    assert "rough impact" in stdout.lower()      # the table output is unchanged


def test_cli_plot_type_without_plots(tmp_path):
    out = tmp_path / "none.png"
    rc, _, stderr = run_cli("solve", "problems/impact/wall.yaml", "--plot", str(out))
    assert rc == 0 and "none of these problem types draws a plot" in stderr
    assert not out.exists()


def test_cli_plot_bad_extension():
    rc, _, stderr = run_cli("solve", "problems/impact/rough-admissible.yaml", "--plot", "out.jpg")
    assert rc == 2 and ".png" in stderr


_PROBE = r"""
import sys, runpy, json, glob
files = sorted(glob.glob("problems/**/*.yaml", recursive=True))
sys.argv = ["dyncli", "solve", "--format", "json", *files]
try:
    runpy.run_module("dyncli", run_name="__main__")
except SystemExit:
    pass
mods = [m for m in sys.modules if m == "matplotlib" or m.startswith("matplotlib.") or m.endswith(".plots")]
print("MODS:" + json.dumps(mods))
"""


def test_no_matplotlib_without_plot():
    """Solving every example file without --plot imports neither matplotlib
    nor any topic's plots module (solvers never import them)."""
    p = subprocess.run([sys.executable, "-c", _PROBE], cwd=ROOT, capture_output=True, text=True, timeout=900,
                       env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "NO_COLOR": "1"})
    line = [ln for ln in p.stdout.splitlines() if ln.startswith("MODS:")]
    assert line, p.stderr[-2000:]
    assert json.loads(line[-1][5:]) == []
