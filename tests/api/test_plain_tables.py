"""dyncli's own tables (dyncli.render.plain, used whenever the output is not
a terminal) print exactly what rich prints from the same cells, for every
example of problems/ (at 100 columns, 80 columns and natural width, with and
without --units) and for the check reports; table output off a terminal
does not import rich; --units converts every table or says it cannot."""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncli.render import out as out_mod, plain
from tests.conftest import ROOT


def _rich_version() -> tuple[int, ...]:
    from importlib.metadata import version

    return tuple(int(x) for x in version("rich").split(".")[:2] if x.isdigit())


#: the layout dyncli draws off a terminal is rich's as of rich 15 (older releases break and pad a
#: few cells differently; on a terminal those releases draw their own layout, so nothing is lost)
SAME_AS_RICH = pytest.mark.skipif(_rich_version() < (15,), reason="the plain layout follows rich >= 15")


def _typer_imports_rich() -> bool:
    """Older typer releases import rich themselves (with rich installed)."""
    code = "import sys, typer; print(any(m == 'rich' or m.startswith('rich.') for m in sys.modules))"
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True).stdout.strip() == "True"

FILES = sorted(str(p) for p in (ROOT / "problems").rglob("*.yaml") if "course-example" not in p.parts)
UNITS = ["mm", "deg", "ms", "kN", "kJ", "g", "kW", "rpm"]


@pytest.fixture(scope="module")
def outcomes():
    from dyncli.loader import load_paths
    from dyncli.run import solve_one

    problems, _ = load_paths(FILES)
    return [o for o in (solve_one(lp) for lp in problems) if o.result is not None]


def _text(outs, width, fast: bool, units=None) -> str:
    from dyncli.render.table import render

    buf = io.StringIO()
    plain.ENABLED = fast
    try:
        out = out_mod.Out(buf, width, no_color=True)
        for o in outs:
            render(out, o.problem, o.result, 6, units)
    finally:
        plain.ENABLED = True
    return buf.getvalue()


@SAME_AS_RICH
@pytest.mark.parametrize("width", [100, 80, None])
@pytest.mark.parametrize("units", [None, UNITS])
def test_plain_layout_is_what_rich_prints(outcomes, width, units):
    fast, slow = _text(outcomes, width, True, units), _text(outcomes, width, False, units)
    assert fast.splitlines() == slow.splitlines()


def test_check_report_is_what_rich_prints():
    from dyncli.check.emit import table
    from tests.check.helpers import grade
    from tests.check.test_formats import ALICE

    out = []
    for fast in (True, False):
        buf = io.StringIO()
        plain.ENABLED = fast
        try:
            for width in (100, 60, None):
                table.draw(grade(ALICE, reveal=True), out_mod.Out(buf, width, no_color=True))
        finally:
            plain.ENABLED = True
        out.append(buf.getvalue())
    assert out[0] == out[1] and "find.0.v" in out[0]


def test_a_vector_is_never_cut():
    t = plain.Table(title="x", pad_edge=False)
    t.add_column("name")
    t.add_column("value")
    t.add_row("a", "A: [1.5, 2.5, 3.5], B: [4.25, 5.25, 6.25], C: [7, 8, 9]")
    [fitted] = plain.fit(t, 30)
    cells = fitted.columns[1].cells[0].split("\n")
    assert cells == ["A: [1.5, 2.5, 3.5],", "B: [4.25, 5.25, 6.25],", "C: [7, 8, 9]"]
    assert plain.wrap("[[1, 2, 3], [4, 5, 6]]", 10) == "[[1, 2, 3],\n[4, 5, 6]]"


def test_a_caption_stays_on_one_line():
    t = plain.Table(caption="a caption that is much wider than its table, in one phrase")
    t.add_column("a")
    t.add_row("1")
    lines = plain.lines(plain.fit(t, 40)[0])
    assert lines[-1] == "a caption that is much wider than its table, in one phrase"


# a combining dot only after a letter (as in θ̇): alone at the start of a line it has no cell
# to sit on, and the two layouts are free to differ there
_cells = st.text(alphabet="ab1.-[]/\\ \nωₙ̇全∞", max_size=12).filter(
    lambda x: not any(line.startswith("\u0307") or " \u0307" in line for line in x.split("\n")))


@settings(max_examples=150, deadline=None)
@SAME_AS_RICH
@given(_cells, _cells, st.lists(st.tuples(_cells, _cells), max_size=4),
       st.sampled_from([(True, "right", False), (False, "left", False), (True, "right", True)]),
       st.sampled_from([60, 20, None]))
def test_random_cells_match_rich(title, head, rows, style, width):
    """Brackets, backslashes, wide and combining characters, line breaks,
    tables wider than the output: the plain layout equals rich's drawing."""
    pad_edge, just, square = style

    def table():
        t = plain.Table(title=title or None, caption="a note" if square else None, pad_edge=pad_edge,
                        box=plain.SQUARE if square else plain.SIMPLE_HEAD, show_lines=square)
        t.add_column(head, justify=just)
        t.add_column("v", justify="left")
        for a, b in rows:
            t.add_row(a, b)
        return t

    out = []
    for fast in (True, False):
        buf = io.StringIO()
        plain.ENABLED = fast
        try:
            out_mod.Out(buf, width, no_color=True).print(table())
        finally:
            plain.ENABLED = True
        out.append(buf.getvalue())
    assert out[0] == out[1]


# ------------------------------------------------------------------ --units over every type

_BRACKET = re.compile(r"\[([^\[\]]+)\]")


def test_units_convert_every_table_or_say_so(outcomes):
    """Every example with --units mm,deg,ms,kN,kJ,g,kW,rpm: no unit left in a
    column header (``[m]``) or in the results' unit column that one of these
    would convert, unless a '--units: not applied to' note names the view."""
    from dyncli.render.table import render
    from dyncli.units import display_factor

    bad = []
    for o in outcomes:
        buf = io.StringIO()
        render(out_mod.Out(buf, None, no_color=True), o.problem, o.result, 6, UNITS)
        text = buf.getvalue()
        if "--units: not applied to" in text:
            continue
        lines = text.splitlines()
        heads = [ln for ln, nxt in zip(lines, lines[1:]) if nxt.strip().startswith("─")]   # header rows
        shown = {u for ln in heads for u in _BRACKET.findall(ln)}
        for ln in lines:
            cells = ln.split()
            if len(cells) >= 2 and cells[0] in o.result.results and o.result.units.get(cells[0]):
                shown.add(cells[-1])
        left = sorted(u for u in shown if display_factor(u, UNITS) is not None
                      and display_factor(u, UNITS)[1] != u)
        if left:
            bad.append(f"{o.problem.file}#{o.problem.index}: {left}")
    assert not bad, "\n".join(bad[:20])


def test_rectilinear_find_has_units_and_converts(outcomes):
    from dyncli.render.table import render

    o = next(o for o in outcomes if o.problem.file.endswith("case1-constant-acceleration.yaml"))
    buf = io.StringIO()
    render(out_mod.Out(buf, 100, no_color=True), o.problem, o.result)
    assert "t [s]" in buf.getvalue() and "s [m]" in buf.getvalue() and "v [m/s]" in buf.getvalue()
    buf = io.StringIO()
    render(out_mod.Out(buf, 100, no_color=True), o.problem, o.result, 6, ["mm"])
    row = next(ln.split() for ln in buf.getvalue().splitlines() if ln.split()[:2] == ["0", "2"])
    assert "s [mm]" in buf.getvalue() and row[2] == "32000"          # s = 32 m at t = 2 s (6.5b)


# ------------------------------------------------------------------ no rich off a terminal

def _env(**extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")}
    env.update(PYTHONPATH=str(ROOT), NO_COLOR="1", **extra)
    return env


_NO_RICH = """
import sys, runpy
sys.argv = ['dyncli'] + sys.argv[1:]
try:
    runpy.run_module('dyncli', run_name='__main__')
except SystemExit:
    pass
sys.stderr.write('\\nRICH=' + str(any(m == 'rich' or m.startswith('rich.') for m in sys.modules)) + '\\n')
"""


@pytest.mark.parametrize("args", [["solve", *FILES[:12]], ["solve", "problems/vibration/undamped.yaml", "--sweep",
                                                            "k=100:400:4"], ["solve", "--units", "mm", FILES[-1]]])
def test_table_output_off_a_terminal_does_not_import_rich(args):
    if _typer_imports_rich():
        pytest.skip("this typer imports rich itself (dyncli's own code does not)")
    p = subprocess.run([sys.executable, "-c", _NO_RICH, *args], cwd=ROOT, env=_env(), capture_output=True, text=True,
                       timeout=300)
    assert "RICH=False" in p.stderr, p.stderr[-2000:]
    assert p.stdout.strip()


def test_sweep_table_one_row_per_point():
    p = subprocess.run([sys.executable, "-m", "dyncli", "solve", "problems/vibration/undamped.yaml", "--sweep",
                        "k=100:400:4", "--units", "mm"], cwd=ROOT, env=_env(), capture_output=True, text=True,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    lines = p.stdout.splitlines()
    head = next(i for i, ln in enumerate(lines) if ln.split()[:1] == ["k"])
    rows = [ln.split() for ln in lines[head + 2:] if ln.strip()]
    assert [r[0] for r in rows] == ["100", "200", "300", "400"]
    assert "x.0 [mm]" in lines[head]


def _wrap_by_rescanning(text: str, width: int) -> str:
    """The rule of plain.wrap written the direct way (every remaining piece scanned again for its
    breaks, quadratic): the reference the one-pass wrap must reproduce."""
    def breaks(t):
        out, inner, opened = [], [], []
        for i, ch in enumerate(t):
            if ch in "[(":
                opened.append(i)
            elif ch in "])" and opened:
                inner.append((opened.pop(), i))
            elif ch == " ":
                out.append(i)
        atoms = [(a, b) for a, b in inner if not any(a < c and d < b for c, d in inner)]
        return [i for i in out if not any(a < i < b for a, b in atoms)]

    lines = []
    for line in text.split("\n"):
        while plain.cell_len(line) > width:
            allowed = breaks(line)
            if line.startswith("[") or re.match(r"^[^ ]+: [-\[\d]", line):
                allowed = [i for i in allowed if line[i - 1] == ","]
            cuts = [i for i in allowed if plain.cell_len(line[:i]) <= width] or allowed[:1]
            if not cuts:
                break
            lines.append(line[:cuts[-1]].rstrip())
            line = line[cuts[-1]:].lstrip()
        lines.append(line)
    return "\n".join(lines)


@settings(max_examples=400, deadline=None)
@given(st.text(alphabet="ab1,:[]() -x漢é\u0301", max_size=60), st.integers(1, 20),
       st.sampled_from(["", "[", "name: -"]))
def test_wrap_breaks_where_the_rule_says(body, width, head):
    text = head + body
    assert plain.wrap(text, width) == _wrap_by_rescanning(text, width)


def test_wrap_of_a_long_expression_is_linear():
    # a --symbolic expression of ~20,000 characters and thousands of brackets: fitted at width 1
    # (the narrowest a column can go) it is cut at every break; the rescanning rule took minutes
    text = " + ".join(f"a_{k} (x_{k} - sin(θ_{k} + v[{k}]))" for k in range(700))
    pieces = plain.wrap(text, 1).split("\n")
    assert "".join(pieces).replace(" ", "") == text.replace(" ", "")
    assert len(pieces) > 1000 and all(not p.startswith(" ") for p in pieces)
