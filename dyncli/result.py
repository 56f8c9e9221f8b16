"""The result every solver returns, and generic views the renderers draw.

A solver builds a :class:`Result`; the renderers (``dyncli.render``) know
nothing of any topic and draw it from these generic pieces:

* ``results``: the declared result names -> number, vector (3 floats),
  tensor (3x3), string, bool, None, list of these, or mapping of these;
* ``method`` ("closed-form", "quadrature", "ode:DOP853", ...), ``equations``
  (the notes' equation numbers), ``warnings``, ``error_estimate``;
* ``symbols``: display symbols for result names (``"omega_n": "ωₙ"``);
* ``units``: SI unit strings for result names (``"omega_n": "rad/s"``);
  both filled from the type's declaration (``dyncli/topics/<topic>/
  results.py``) by ``registry.solver`` after the solver returns, which also
  refuses a result key the type does not declare (a bug: exit 3);
* ``series``: groups of list-valued results that share an index, e.g.
  ``Series("t", times, ["x", "v", "w"])`` -> one table with a row per time;
* ``views``: extra tables (:class:`FrameTable`, :class:`Table`, :class:`Equations`), e.g. the
  δ/δt table of rotating-frame kinematics; ``covered`` names the results a
  type's views present in readable form, so the tables skip their raw nesting;
* ``scales``: results the tables show relative to a scale (``energy_residual``
  against the energies it balances); JSON, YAML and CSV keep the absolute value;
* ``notes``: conventions stated in the title of the results table (the range of a phase).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Sequence


@dataclass
class Series:
    index_name: str            # e.g. "t"
    index: list                # e.g. the requested times
    names: list[str]           # result names that are lists over ``index``
    title: str | None = None
    index_result: str | None = None   # result name holding the index itself (not repeated in the scalar table)
    frame_only: bool = False   # rows of frames, csv --long and xarray only: the tables show them through views
    index_marks: dict[int, str] | None = None   # the tables' marks after an index value (◀ G max): display only


@dataclass
class FrameTable:
    """Rows of vectors on a named basis (columns e'_1, e'_2, e'_3).

    ``rows`` is a list of (label, [c1, c2, c3]) with numbers or strings
    (formulas for ``--symbolic``)."""

    title: str
    rows: list[tuple[str, list[Any]]]
    basis: tuple[str, str, str] = ("e'₁", "e'₂", "e'₃")
    note: str | None = None


@dataclass
class Table:
    """A plain table: ``columns`` headers and ``rows`` of cells."""

    title: str
    columns: list[str]
    rows: list[list[Any]]
    note: str | None = None


@dataclass
class Equations:
    """Equations as formulas (``--symbolic``): ``rows`` of (label, text, LaTeX); the terminal,
    Markdown and HTML views print the text, ``--format latex`` the LaTeX in math mode."""

    title: str
    rows: list[tuple[str, str, str]]
    note: str | None = None


@dataclass
class Line:
    """One curve of a :class:`Plot` (``z`` for 3-D plots)."""

    x: list[float]
    y: list[float]
    label: str | None = None
    style: str | None = None  # matplotlib line style "-", "--", ":", "-."; None cycles per panel, "" = markers only
    z: list[float] | None = None
    marker: str | None = None  # e.g. "o" for marked points only (no line: style "")


@dataclass
class Plot:
    """A picture a topic wants drawn (``dyncli solve --plot FILE``).

    The plot renderer (``dyncli.render.plot``) draws these generically."""

    title: str
    xlabel: str
    ylabel: str
    lines: list[Line] = field(default_factory=list)
    zlabel: str | None = None         # set for 3-D plots
    hlines: Sequence[tuple[float, str | None]] = field(default_factory=list)   # (y, label)
    vlines: Sequence[tuple[float, str | None]] = field(default_factory=list)   # (x, label)
    logx: bool = False
    logy: bool = False
    equal_aspect: bool = False


@dataclass
class Result:
    results: dict[str, Any]
    method: str = "closed-form"
    equations: list[str] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)
    error_estimate: float | None = None
    symbols: dict[str, str] = field(default_factory=dict)
    units: dict[str, str] = field(default_factory=dict)
    series: list[Series] = field(default_factory=list)
    views: list[FrameTable | Table | Equations] = field(default_factory=list)
    plots: list[Plot] = field(default_factory=list)
    # free-form extra data for plots etc. (never rendered as results)
    extra: dict[str, Any] = field(default_factory=dict)
    # results the ``views`` present in the tables (the terminal and document views show the
    # views instead of the raw nesting; JSON, YAML and CSV hold every result as always)
    covered: list[str] = field(default_factory=list)
    # results the tables show relative to a scale (name -> the scale, in the result's SI unit), e.g.
    # an energy balance's residual against the energies it balances; JSON keeps the absolute value
    scales: dict[str, float] = field(default_factory=dict)
    # conventions the tables state above the results (one line each), e.g. the range of a phase
    notes: list[str] = field(default_factory=list)

    def warn(self, message: str) -> None:
        if message not in self.warnings:
            self.warnings.append(message)


@dataclass
class SolveOptions:
    """Options from the command line that a solver may use."""

    symbolic: bool = False
