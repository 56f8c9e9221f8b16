"""Figures that read at the size they are shown (dyncli.render.plot):

* every text of a figure is 9 pt, and a PNG records its smallest text in
  pixels (``Label font px``) for a page to check it is not shrunk;
* beyond ten curves in a panel, every curve has its own colour AND marker;
* one panel per quantity and no empty slot: an odd last panel spans its row,
  ``columns=1`` stacks them at one panel's width;
* an orbit's attracting centre is marked (particle);
* the pictures the docs show (docs/img, docs/accuracy.png, the SVG) are no
  wider than the docs' text column lets them be at 9-point text — the browser
  test (tests/docs/test_browser.py) measures the same on the rendered pages.
"""

from __future__ import annotations

import importlib.util
import re

import pytest
from matplotlib.colors import to_hex

from dyncli.result import Line, Plot
from tests.conftest import ROOT
from tests.plots.util import Fig, line, panels, solved_path

#: the docs' text column at a 1280 px window (mkdocs-material), CSS px
COLUMN_PX = 688
MIN_TEXT_PX = 9 * 96 / 72


def _spec(n_lines: int, title: str = "p") -> Plot:
    return Plot(title, "t [s]", "y [m]", [Line(list(range(50)), [k * i for i in range(50)], f"curve {k}")
                                           for k in range(n_lines)])


def test_series_style_sixteen_distinct_pairs():
    from dyncli.render.plot import series_style

    styles = [series_style(n) for n in range(16)]
    assert len({to_hex(c) for c, _ in styles}) == 16
    assert len({m for _, m in styles}) == 16


def test_fifteen_curves_distinct_colours_and_markers():
    with Fig([("p", _spec(15))]) as f:
        (ax,) = f.axes
        lines = [line(ax, f"curve {k}") for k in range(15)]
        assert len({to_hex(ln.get_color()) for ln in lines}) == 15
        assert len({ln.get_marker() for ln in lines}) == 15


def test_few_curves_keep_plain_lines():
    with Fig([("p", _spec(3))]) as f:
        (ax,) = f.axes
        assert {line(ax, f"curve {k}").get_marker() for k in range(3)} == {"None"}


def test_every_text_nine_points():
    from matplotlib.text import Text

    from dyncli.render.plot import LABEL_PT

    with Fig([("p", _spec(4, "a title"))]) as f:
        texts = [t for t in f.fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
        assert texts and min(t.get_fontsize() for t in texts) >= LABEL_PT


def test_odd_last_panel_spans_its_row():
    with Fig([("p", _spec(1)), ("p", _spec(1)), ("p", _spec(1))]) as f:
        a, b, c = (ax.get_position() for ax in f.axes)
        assert abs(a.y0 - b.y0) < 1e-9 and c.y0 < a.y0                # two on the first row, one below
        assert c.width > 2 * a.width                                  # the last one fills its row


def test_one_column_for_the_docs(tmp_path):
    from PIL import Image

    from dyncli.render import plot as plotting

    out = tmp_path / "col.png"
    assert plotting.save([("p", _spec(2)), ("p", _spec(2))], str(out), columns=1) == 2
    with Image.open(out) as im:
        assert im.size == (640, 1040)
        assert float(im.text[plotting.LABEL_PX_KEY]) == pytest.approx(9 * 100 / 72)


def test_orbit_centre_marked():
    pans = panels(solved_path("particle/transfer-orbit.yaml"))
    with Fig(pans) as f:
        traj = f.axes[0]
        centre = line(traj, "attracting centre")
        # the file's force: inverse-square, center [0, 0, 0]; drawn on the orbit's plane x₃ = 0
        assert list(centre.get_xdata()) == [0.0] and list(centre.get_ydata()) == [0.0]
        assert centre.get_marker() == "*"


def _shown_images() -> list:
    docs = ROOT / "docs"
    out = []
    for page in docs.rglob("*.md"):
        for src in re.findall(r"!\[[^\]]*\]\(([^)\s]+)\)", page.read_text(encoding="utf-8")):
            if "://" not in src:
                out.append((page.relative_to(ROOT), (page.parent / src).resolve()))
    return out


def test_docs_pictures_fit_the_column_at_nine_points():
    from tests.docs.test_browser import label_px

    shown = _shown_images()
    assert len(shown) >= 6
    bad = []
    for page, img in shown:
        px = label_px(img)
        if img.suffix == ".svg":
            width = float(re.search(r'<svg[^>]*\bwidth="([\d.]+)"', img.read_text(encoding="utf-8")).group(1))
        else:
            from PIL import Image

            with Image.open(img) as im:
                width = im.size[0]
        if px is None:
            bad.append(f"{page}: {img.name} does not record its smallest text")
        elif px * min(1.0, COLUMN_PX / width) < MIN_TEXT_PX - 0.01:
            bad.append(f"{page}: {img.name}: {px} px text in {width:.0f} px, shown at most {COLUMN_PX} px wide")
    assert not bad, "\n".join(bad)


def test_work_precision_figure_redrawn_from_its_tables(tmp_path):
    from PIL import Image

    spec = importlib.util.spec_from_file_location("_wp", ROOT / "benchmarks" / "work_precision.py")
    wp = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(wp)
    rows = wp.rows_from_md(ROOT / "docs" / "accuracy.md")
    assert len({r[0].name for r in rows}) > 10          # more series than matplotlib's ten colours
    wp.plot(rows, tmp_path / "wp.png")
    with Image.open(tmp_path / "wp.png") as im:
        assert im.size[0] == 640 and float(im.text["Label font px"]) >= MIN_TEXT_PX
