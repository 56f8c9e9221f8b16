"""Plots (``dyncli solve FILE --plot out.png|svg|pdf`` or ``--plot DIR/``).

Generic: draws the :class:`~dyncli.result.Plot` specs that solvers attach to
their results; knows nothing of any topic.  matplotlib is imported lazily
with the non-interactive Agg backend.  Output is deterministic (fixed DPI,
no timestamps or random ids in the metadata) so tests can compare files.
Readable in grayscale: each curve of a panel gets its own line style and
marker as well as its own colour; beyond ten curves the colours go on past
matplotlib's ten and every curve without a marker of its own gets a distinct
one (:func:`series_style`, also used by the benchmarks' figures).

What makes a panel readable rather than a picture to decode:

* a 3-D path that stays in a plane of the basis (a projectile in x₁x₃, a
  satellite in x₂x₃) is drawn in 2-D on that plane, equal aspect, with the
  constant coordinate named in the title (:func:`planar_axes`);
* a curve with more oscillations than the panel has room for (more than
  :data:`MAX_CYCLES`) is drawn as its band, the min and max over each pixel
  column, with a note in the title, instead of an aliased solid block
  (:func:`dense_band`);
* legends sit below the axes, never over the curves;
* every text is at least :data:`LABEL_PT` points at the figure's size, and a
  PNG records its smallest text in pixels (``Label font px`` in its text
  chunk), so a page that shows it scaled can be checked for legibility;
* no empty slot: with two columns an odd last panel spans the whole row, and
  ``columns=1`` stacks the panels for a narrow page (the docs' column).

``--plot DIR/`` writes one file per solved problem, ``DIR/<file-stem>-<index>.png``
(:func:`save_each`); a file name puts every panel of the run in one figure.
"""

from __future__ import annotations

from pathlib import Path

from dyncli.errors import InputError
from dyncli.printable import printable

FORMATS = {".png", ".svg", ".pdf"}
_STYLES = ["-", "--", "-.", ":"]
#: a curve with more local maxima than this in a panel is drawn as a band
MAX_CYCLES = 60
#: columns of the band at most; each column spans at least two cycles, so
#: the band is the envelope of the oscillation, not a moiré of its samples
BAND_BINS = 300
#: a coordinate whose range is below this fraction of the path's size is constant
PLANAR_RTOL = 1e-9
#: the size of every text of a figure (titles, labels, ticks, legends), points
LABEL_PT = 9
#: the PNG text chunk holding the smallest text of the figure, pixels at its natural size
LABEL_PX_KEY = "Label font px"
#: sixteen colours told apart by eye: matplotlib's ten, then six more unlike any of them
COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
           "#bcbd22", "#17becf", "#000000", "#000080", "#b8860b", "#00a86b", "#ff00ff", "#800000"]
#: as many markers, each unlike the others in shape
MARKERS = ["o", "s", "^", "v", "D", "P", "X", "*", "<", ">", "h", "p", "d", "8", "H", "x"]


def series_style(n: int) -> tuple[str, str]:
    """(colour, marker) of the n-th curve: sixteen pairs, all colours and all
    markers different."""
    return COLOURS[n % len(COLOURS)], MARKERS[n % len(MARKERS)]


def is_dir_target(path: str) -> bool:
    """``--plot`` names a directory: ends with a separator, is an existing
    directory, or has no suffix at all."""
    p = Path(path)
    return path.endswith(("/", "\\")) or p.is_dir() or p.suffix == ""


def check_path(path: str) -> Path:
    p = Path(path)
    if is_dir_target(path):
        return p
    if p.suffix.lower() not in FORMATS:
        raise InputError(f"--plot {path}: use a .png, .svg or .pdf file name, or a directory (DIR/)")
    return p


def _config_dir() -> None:
    """Before matplotlib is first imported: when its configuration
    directory (``MPLCONFIGDIR``, else the XDG/home default) cannot be
    written (a read-only or missing HOME), point ``MPLCONFIGDIR`` at a
    private temporary directory, removed at exit, instead of letting
    matplotlib print its multi-line complaint; its log stays quiet below
    errors."""
    import logging
    import os
    import sys

    logging.getLogger("matplotlib").setLevel(logging.ERROR)
    if "matplotlib" in sys.modules:
        return
    want = os.environ.get("MPLCONFIGDIR")
    try:
        if not want:
            xdg = os.environ.get("XDG_CONFIG_HOME") or str(Path.home() / ".config")
            want = str(Path(xdg) / "matplotlib") if sys.platform.startswith(("linux", "freebsd")) \
                else str(Path.home() / ".matplotlib")
        os.makedirs(want, exist_ok=True)
        usable = os.access(want, os.W_OK | os.X_OK)
    except (OSError, RuntimeError):   # RuntimeError: no home directory
        usable = False
    if not usable:
        import atexit
        import shutil
        import tempfile

        tmp = tempfile.mkdtemp(prefix="dyncli-mpl-")
        atexit.register(shutil.rmtree, tmp, True)
        os.environ["MPLCONFIGDIR"] = tmp


# ---------------------------------------------------------------------------
# what to draw: planar paths, dense oscillations


def planar_axes(lines) -> tuple[int, int, list[tuple[int, float]]] | None:
    """For 3-D lines: (i, j, [(k, value)...]) when every point has coordinate
    k equal to ``value`` (within PLANAR_RTOL of the path's size), so the path
    is drawn on the (i, j) plane (two constant coordinates: a path on a
    line); None for a truly 3-D path."""
    import numpy as np

    cols = []
    for ln in lines:
        if ln.z is None or not len(ln.x):
            continue
        cols.append(np.array([ln.x, ln.y, ln.z], float))
    if not cols:
        return None
    P = np.concatenate(cols, axis=1)
    P = P[:, np.all(np.isfinite(P), axis=0)]
    if P.shape[1] == 0:
        return None
    span = P.max(axis=1) - P.min(axis=1)
    size = float(np.max(span))
    flat = [k for k in range(3) if span[k] <= PLANAR_RTOL * max(size, 1e-300)]
    if not flat or size == 0.0:
        return None
    k = flat[-1]
    i, j = [c for c in range(3) if c != k]
    return i, j, [(c, float(np.median(P[c]))) for c in flat]


def count_cycles(y) -> int:
    """Local maxima of a sampled curve (its oscillations); 0 for a curve that
    is constant up to rounding (its noise is not an oscillation)."""
    import numpy as np

    y = np.asarray(y, float)
    y = y[np.isfinite(y)]
    if y.size < 3 or np.ptp(y) <= 1e-9 * np.max(np.abs(y)):
        return 0
    d = np.diff(y)
    d = d[d != 0]
    return int(np.count_nonzero((d[:-1] > 0) & (d[1:] < 0)))


def dense_band(x, y, bins: int = BAND_BINS):
    """(centres, lo, hi): the min and max of y over ``bins`` equal columns of x
    (the first and last centres at the ends of x, so the band spans it)."""
    import numpy as np

    x, y = np.asarray(x, float), np.asarray(y, float)
    ok = np.isfinite(x) & np.isfinite(y)
    x, y = x[ok], y[ok]
    edges = np.linspace(x.min(), x.max(), bins + 1)
    k = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, bins - 1)
    lo = np.full(bins, np.inf)
    hi = np.full(bins, -np.inf)
    np.minimum.at(lo, k, y)
    np.maximum.at(hi, k, y)
    keep = np.isfinite(lo)
    centres = 0.5 * (edges[:-1] + edges[1:])
    centres[0], centres[-1] = edges[0], edges[-1]
    return centres[keep], lo[keep], hi[keep]


# ---------------------------------------------------------------------------
# drawing


#: a panel's cell on the figure, inches
CELL_W, CELL_H = 6.4, 5.2


def _place(fig, ax, grid: tuple[int, int, int], k: int, title_lines: int, legend_rows: int) -> float:
    """Put panel ``k`` (0-based) of ``grid`` = (rows, columns, panels) in its
    cell with margins for its title (above) and tick labels, axis label and
    legend (below): a fixed layout, computed without drawing (tight or
    constrained layout would lay out every text twice).  An odd last panel
    of two columns spans the row.  Returns the axes height in inches."""
    rows, cols, n = grid
    r, c = divmod(k, cols)
    span = cols if k == n - 1 and c == 0 else 1
    left, right = 0.85, 0.3
    top = 0.2 + 0.17 * title_lines
    bottom = 0.62 + (0.1 + 0.18 * legend_rows if legend_rows else 0.0)
    w, h = span * CELL_W - left - right, CELL_H - top - bottom
    W, H = cols * CELL_W, rows * CELL_H
    y0 = H - (r + 1) * CELL_H + bottom
    ax.set_position([(c * CELL_W + left) / W, y0 / H, w / W, h / H])
    return h


def _line_style(n: int, ln, style: str, many: bool) -> dict:
    """matplotlib keywords of curve ``n``: its colour, and its own marker
    when the panel has more curves than colours are told apart (``many``)."""
    colour, marker = series_style(n)
    kw = dict(label=ln.label, linestyle=style if style else "none", color=colour, linewidth=1.4, markersize=5,
              marker=ln.marker if ln.marker is not None or not many else marker)
    if kw["marker"] == "*":
        kw["markersize"] = 11      # a star has little ink at the size of a dot
    if kw["marker"] is not None and ln.marker is None and len(ln.x) > 12:
        kw["markevery"] = max(1, len(ln.x) // 8)
    return kw


def _draw_panel(fig, grid, k, ptitle, spec):
    plane = planar_axes(spec.lines) if spec.zlabel is not None else None
    three_d = spec.zlabel is not None and plane is None
    ax = fig.add_subplot(grid[0], grid[1], k, projection="3d" if three_d else None)
    many = len(spec.lines) > 10
    title = spec.title
    xlabel, ylabel = spec.xlabel, spec.ylabel
    if plane is not None:
        i, j, consts = plane
        labels = (spec.xlabel, spec.ylabel, spec.zlabel)
        xlabel, ylabel = labels[i], labels[j]
        fixed = ", ".join(f"{labels[c].split(' [')[0]} = {v:.4g}" for c, v in consts)
        title += ("\nplanar: drawn on its plane, " if len(consts) == 1 else "\non a straight line: ") + fixed
    banded = []
    for n, ln in enumerate(spec.lines):
        style = ln.style if ln.style is not None else _STYLES[n % len(_STYLES)]
        kw = _line_style(n, ln, style, many)
        colour = kw["color"]
        if three_d:
            ax.plot(ln.x, ln.y, ln.z or [0.0] * len(ln.x), **kw)
            continue
        x, y = ln.x, ln.y
        if plane is not None:
            P = (ln.x, ln.y, ln.z or [0.0] * len(ln.x))
            x, y = P[plane[0]], P[plane[1]]
        if style and not spec.logx and len(x) > 4 * BAND_BINS and count_cycles(y) > MAX_CYCLES:
            cycles = count_cycles(y)
            c, lo, hi = dense_band(x, y, max(8, min(BAND_BINS, cycles // 2)))
            ax.fill_between(c, lo, hi, color=colour, alpha=0.35, linewidth=0,
                            label=(ln.label or "") + " (band: min–max per column)")
            banded.append(cycles)
            continue
        ax.plot(x, y, **kw)
    for y, label in spec.hlines:
        ax.axhline(y, color="0.4", linestyle=":", linewidth=1.0, label=label)
    for x, label in spec.vlines:
        ax.axvline(x, color="0.4", linestyle="--", linewidth=1.0, label=label)
    if banded:
        title += f"\n{max(banded)} oscillations: too many to draw one by one, shaded as their band"
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if three_d:
        ax.set_zlabel(spec.zlabel)
    if spec.logx:
        ax.set_xscale("log")
    if spec.logy:
        ax.set_yscale("log")
    if (spec.equal_aspect or plane is not None) and not three_d:
        ax.set_aspect("equal", adjustable="datalim")
    full = f"{printable(ptitle)}\n{title}" if ptitle else title
    ax.set_title(full, fontsize=LABEL_PT, parse_math=False)   # a user's '$' is a dollar sign, not mathtext
    labs = [lb for lb in ax.get_legend_handles_labels()[1] if lb and not lb.startswith("_")]
    ncol = _legend_columns(labs)
    h = _place(fig, ax, grid, k - 1, full.count("\n") + 1, (len(labs) + ncol - 1) // ncol)
    if labs:
        ax.legend(fontsize=LABEL_PT, loc="upper center", bbox_to_anchor=(0.5, -0.52 / h), ncol=ncol, frameon=False)
    return ax


def _legend_columns(labels: list[str]) -> int:
    """2 when the longest label fits half a cell (a character is about 0.6 em
    wide, the line sample and gaps about 0.5 in), else 1."""
    longest = max((len(lb) for lb in labels), default=0)
    return 2 if longest * 0.6 * LABEL_PT / 72 + 0.5 <= CELL_W / 2 else 1


def figure(panels: list[tuple[str, object]], columns: int | None = None):
    """Build a matplotlib Figure with one panel per (problem title, Plot),
    in ``columns`` columns (default: 1 for one panel, else 2)."""
    import warnings

    _config_dir()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # no library warning reaches the user as raw text
        return _figure(panels, columns)


def _figure(panels: list[tuple[str, object]], columns: int | None):
    import matplotlib

    matplotlib.use("Agg", force=True)
    import matplotlib.pyplot as plt

    plt.rcParams.update({"svg.hashsalt": "dyncli", "font.size": LABEL_PT, "axes.grid": True, "grid.alpha": 0.3})
    n = len(panels)
    cols = max(1, min(columns or 2, n))
    rows = (n + cols - 1) // cols
    fig = plt.figure(figsize=(CELL_W * cols, CELL_H * rows), dpi=100)
    for k, (ptitle, spec) in enumerate(panels):
        _draw_panel(fig, (rows, cols, n), k + 1, ptitle, spec)
    return fig


def smallest_text_px(fig, dpi: float) -> float:
    """The size of the smallest visible text of ``fig``, pixels at ``dpi``."""
    from matplotlib.text import Text

    sizes = [t.get_fontsize() for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
    return min(sizes, default=LABEL_PT) * dpi / 72


def _write(panels, p: Path, label: str, columns: int | None = None) -> None:
    _config_dir()          # before the first import of matplotlib
    import matplotlib.pyplot as plt

    fig = figure(panels, columns)
    fmt = p.suffix.lower()[1:]
    meta = {"png": {"Software": None, LABEL_PX_KEY: f"{smallest_text_px(fig, 100):.2f}"},
            "svg": {"Date": None, "Creator": None},
            "pdf": {"CreationDate": None, "ModDate": None, "Producer": None, "Creator": None}}[fmt]
    import warnings

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            fig.savefig(p, format=fmt, metadata=meta, dpi=100)
    except OSError as exc:
        raise InputError(f"--plot {label}: cannot write ({exc.strerror})") from None
    finally:
        plt.close(fig)


def save(panels: list[tuple[str, object]], path: str, columns: int | None = None) -> int:
    """Draw every panel into the file ``path`` (in ``columns`` columns, see
    :func:`figure`); returns the number of panels."""
    p = check_path(path)
    if not panels:
        return 0
    _write(panels, p, path, columns)
    return len(panels)


def file_name(problem_file: str, index: int, ext: str = ".png") -> str:
    """``<file-stem>-<index><ext>`` (stdin is ``stdin``)."""
    stem = Path(problem_file).stem if problem_file not in ("-", "<stdin>") else "stdin"
    return f"{stem}-{index}{ext}"


def save_each(groups: list[tuple[str, int, list]], directory: str, ext: str = ".png") -> list[Path]:
    """One file per problem: ``groups`` is [(problem file, index, panels)];
    writes ``directory/<file-stem>-<index><ext>`` for each problem with
    panels (two problems of the same stem and index in different folders get
    ``-2``, ``-3``... suffixes) and returns the paths written."""
    d = Path(directory)
    try:
        d.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"--plot {directory}: cannot create the directory ({exc.strerror})") from None
    written: list[Path] = []
    seen: set[str] = set()
    for file, index, pans in groups:
        if not pans:
            continue
        name = file_name(file, index, ext)
        k = 2
        while name in seen:
            name = file_name(file, index, f"-{k}{ext}")
            k += 1
        seen.add(name)
        _write(pans, d / name, directory)
        written.append(d / name)
    return written
