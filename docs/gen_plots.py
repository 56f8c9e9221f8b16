"""Regenerate the plots embedded in the docs (``docs/img/*.png``).

    python docs/gen_plots.py

Solves each chosen example in-process and draws its panels with dyncli's own
plotting layer (``dyncli.render.plot``, the same figures as
``dyncli solve FILE --plot DIR/``), but stacked in one column
(``columns=1``), so that a figure is as wide as the docs' text column
(640 px; the column is 688 px at a 1280 px window) and its 9-point text
is shown at its own size, not shrunk below legibility
(tests/docs/test_browser.py measures it).  The API page's resonance curve
is drawn by the five lines that page shows, at the same width.  The PNGs
are shrunk with a 64-colour palette so the repository stays small; their
``Label font px`` text chunk (the smallest text, pixels) is kept.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
IMG = ROOT / "docs" / "img"

#: (problem file, index of the problem in it, picture name)
CHOSEN = [
    ("problems/rectilinear/case4-spring.yaml", 0, "case4-spring.png"),
    ("problems/vibration/base-excitation.yaml", 0, "base-excitation.png"),
    ("problems/impact/cone-fig28-4.yaml", 3, "cone-fig28-4.png"),
    ("problems/gyroscopic/euler-intermediate-axis.yaml", 0, "euler-intermediate-axis.png"),
    ("problems/particle/transfer-orbit.yaml", 0, "transfer-orbit.png"),
]


def panels_of(file: str, index: int) -> list:
    """The (title, Plot) panels of problem ``index`` of ``file``, as ``--plot`` draws them."""
    from dyncli import registry
    from dyncli.loader import load_paths
    from dyncli.run import solve_one

    problems, diags = load_paths([str(ROOT / file)])
    if diags:
        raise SystemExit(f"{file}: {diags}")
    lp = [p for p in problems if p.index == index][0]
    out = solve_one(lp)
    if out.result is None:
        raise SystemExit(f"{file}[{index}]: {out.message}")
    return [(lp.title, spec) for spec in registry.plots_for(lp.type, lp.model, out.result)]


def shrink(src: Path, dst: Path) -> None:
    """``src`` quantized to 64 colours into ``dst``, its text chunks kept."""
    from PIL import Image, PngImagePlugin

    im = Image.open(src)
    info = PngImagePlugin.PngInfo()
    for k, v in im.text.items():
        info.add_text(k, v)
    im.convert("RGB").quantize(colors=64, method=Image.Quantize.MEDIANCUT).save(dst, optimize=True, pnginfo=info)
    print(f"{dst.relative_to(ROOT)}: {dst.stat().st_size // 1024} KiB, {im.size[0]}x{im.size[1]} px")


def resonance(path: Path) -> None:
    """docs/api.md's sweep plotted in five lines, at the docs' column width."""
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt
    import numpy

    import dyncli
    from dyncli.render.plot import LABEL_PT, LABEL_PX_KEY, smallest_text_px

    plt.rcParams.update({"font.size": LABEL_PT, "axes.grid": True, "grid.alpha": 0.3})
    forced = {"type": "vibration", "m": 2, "k": 800, "zeta": 0.1, "force": {"amplitude": 10, "omega": 15}}
    df = dyncli.sweep(forced, {"force.omega": numpy.linspace(5, 40, 71)}).to_frame()
    u = df.attrs["units"]
    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    df.plot(x="force.omega", y="X", xlabel=f"ω [{u['force.omega']}]", ylabel=f"X [{u['X']}]", legend=False, ax=ax)
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Software": None, LABEL_PX_KEY: f"{smallest_text_px(fig, 100):.2f}"})
    plt.close(fig)


def main() -> int:
    sys.path.insert(0, str(ROOT))
    os.chdir(ROOT)
    from dyncli.render import plot as plotting

    IMG.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as d:
        for file, index, name in CHOSEN:
            tmp = Path(d) / name
            plotting.save(panels_of(file, index), str(tmp), columns=1)
            shrink(tmp, IMG / name)
        tmp = Path(d) / "api-resonance.png"
        resonance(tmp)
        shrink(tmp, IMG / "api-resonance.png")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
