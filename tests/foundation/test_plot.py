"""The generic plot renderer: deterministic files, expected artists/labels."""

from __future__ import annotations

import pytest

from dyncli.render import plot as plotting
from dyncli.result import Line, Plot


def _panels():
    p2 = Plot("s(t), v(t)", "t [s]", "s [m], v [m/s]",
              lines=[Line([0, 1, 2], [0, 1, 4], "s"), Line([0, 1, 2], [0, 2, 4], "v", style="--")],
              hlines=[(3.0, "bound")], vlines=[(1.5, "event")])
    p3 = Plot("trajectory", "x1 [m]", "x2 [m]", zlabel="x3 [m]", lines=[Line([0, 1], [0, 1], "path", z=[0, 1])])
    return [("demo", p2), ("demo", p3)]


@pytest.mark.parametrize("ext", ["png", "svg", "pdf"])
def test_deterministic_output(tmp_path, ext):
    a, b = tmp_path / f"a.{ext}", tmp_path / f"b.{ext}"
    assert plotting.save(_panels(), str(a)) == 2
    plotting.save(_panels(), str(b))
    assert a.read_bytes() == b.read_bytes()
    assert a.stat().st_size > 1000


def test_structure():
    fig = plotting.figure(_panels())
    ax2d, ax3d = fig.axes[:2]
    assert ax2d.get_xlabel() == "t [s]" and ax2d.get_ylabel().startswith("s [m]")
    assert [ln.get_label() for ln in ax2d.get_lines()][:2] == ["s", "v"]
    assert ax2d.get_legend() is not None
    assert ax3d.get_zlabel() == "x3 [m]"
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_bad_extension():
    from dyncli.errors import InputError

    with pytest.raises(InputError, match="png"):
        plotting.check_path("out.jpg")
