"""Issue #29, raw output: user text (a title, a file name, swept text, a
``--set`` path, a long value) reaches every output format only through the
one escaper (dyncli/printable.py).  The class: no control character or ESC
sequence in any terminal or stderr line, one line per message, no markup
that acts in Markdown or HTML, LaTeX special characters escaped, no CSV cell
a spreadsheet runs as a formula (numbers keep their sign), and a long user
string shortened in messages."""

from __future__ import annotations

import csv
import io
import re

import pytest

import dyncli
from dyncli import printable as esc
from tests.conftest import ROOT, run_cli

ESC = "\x1b[31m"
HOSTILE = f"X{ESC}red <script>alert(1)</script> <img src=x onerror=alert(1)> [a](javascript:x) |*`\u202e"



def _problem(tmp_path, name: str = "p.yaml", title: str = HOSTILE):
    f = tmp_path / name
    # a vibration problem that warns (phi null), so warning lines carry the title
    f.write_text('type: vibration\ntitle: "' + title.replace("\\", "\\\\").replace('"', '\\"')
                 .replace("\x1b", "\\e").replace("\u202e", "\\u202e") + '"\nm: 1\nk: 100\n', encoding="utf-8")
    return f


def _no_control(text: str) -> None:
    bad = [c for c in text if not (c.isprintable() or c in "\n ")]
    assert not bad, f"raw control characters {bad!r} in {text[:300]!r}"


@pytest.mark.parametrize("fmt", ["table", "json", "yaml", "csv", "markdown", "latex"])
def test_every_format_and_its_stderr_hold_no_raw_control_characters(tmp_path, fmt):
    f = _problem(tmp_path)
    rc, out, err = run_cli("solve", str(f), "-f", fmt)
    assert rc == 0, err
    assert "warning" in (out + err)              # the warning line carries the title
    if fmt != "json":                            # JSON escapes them itself (\u001b)
        _no_control(out)
    _no_control(err)
    for line in err.strip().splitlines():
        assert line.startswith(str(f)), line     # one line per message: nothing forged


def test_validate_ok_lines_are_escaped(tmp_path):
    f = _problem(tmp_path)
    rc, out, err = run_cli("validate", str(f))
    assert rc == 0, err
    _no_control(out)
    assert len(out.strip().splitlines()) == 1


@pytest.mark.parametrize("fmt", ["markdown", "html"])
def test_markdown_and_html_write_markup_as_text(fmt):
    sol = dyncli.solve(str(ROOT / "problems/vibration/undamped.yaml"), title=HOSTILE)[0]
    text = sol._repr_markdown_() if fmt == "markdown" else sol._repr_html_()
    _no_control(text)
    for raw in ("<script>", "<img"):
        assert raw not in text, raw
    if fmt == "markdown":
        assert "](javascript" not in text.replace("\\](", ""), "a link that acts"
    assert "&lt;script&gt;" in text


def test_latex_escapes_its_special_characters_and_controls():
    assert esc.tex("50% & $5 #1 a_b {x} ~ ^ \\") == r"50\% \& \$5 \#1 a\_b \{x\} \textasciitilde{} \textasciicircum{} \textbackslash{}"
    from dyncli.render.latex import tex_text

    out = tex_text("a\x1bb\nc")
    _no_control(out.replace("\n", ""))
    assert "\n" not in out and "x1b" in out


@pytest.mark.parametrize("cell, expected", [
    ("=HYPERLINK(1)", "'=HYPERLINK(1)"), ("+1+cmd", "'+1+cmd"), ("-x1**2/2", "'-x1**2/2"), ("@SUM(A1)", "'@SUM(A1)"),
    ("\tx", "'\tx"), ("\rx", "'\rx"),
    ("-1.5", "-1.5"), ("-3", "-3"), ("+2e-05", "+2e-05"), ("-1.7976931348623157e+308", "-1.7976931348623157e+308"),
    ("plain", "plain"), ("", ""),
])
def test_csv_cell_neutralises_formulas_and_keeps_numbers(cell, expected):
    assert esc.csv_cell(cell) == expected


def test_csv_output_file_names_and_swept_text_are_not_formulas(tmp_path):
    import os
    import subprocess
    import sys

    _problem(tmp_path, "=HYPERLINK(1).yaml", title="@SUM(A1)")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-m", "dyncli", "solve", "=HYPERLINK(1).yaml", "-f", "csv",   # a relative name
                        "--sweep", "x0=-1,-0.5", "--sweep", "title=-cmd,+cmd"],
                       capture_output=True, text=True, cwd=tmp_path, env=env, timeout=120)
    assert p.returncode == 0, p.stderr
    rows = list(csv.reader(io.StringIO(p.stdout)))
    head = rows[0]
    assert rows[1][0] == "'=HYPERLINK(1).yaml"
    for row in rows[1:]:
        for name, cell in zip(head, row):
            assert not cell.startswith(("=", "+", "@", "\t", "\r")) and (
                not cell.startswith("-") or re.fullmatch(r"-[\d.e+-]+", cell)), (name, cell)
        assert row[head.index("x0")] in ("-1", "-0.5")          # a negative number stays a number


def test_set_path_with_newline_or_esc_cannot_forge_a_diagnostic_line():
    for path in ("k\nfake.yaml:1:1: forged", f"base.{ESC}omega", f"params.{ESC}w"):
        rc, out, err = run_cli("solve", "problems/vibration/base-excitation.yaml", "--set", f"{path}=3", "-f", "json")
        assert rc == 2
        _no_control(err)
        assert len(err.strip().splitlines()) == 1, err


def test_a_long_value_is_shortened_in_messages():
    for spec in ("x" * 100_001 + "=3", "title=" + "[" * 100_001):
        rc, out, err = run_cli("solve", "problems/vibration/base-excitation.yaml", "--set", spec)
        assert rc == 2
        assert len(err) < 2 * esc.MAX_LINE, err[:300]


def test_shorten_keeps_short_text_and_says_what_it_left_out():
    assert esc.shorten("abc") == "abc"
    s = esc.shorten("a" * 5000 + "END")
    assert len(s) <= esc.MAX_LINE + 60 and s.endswith("END") and "4,203 characters left out" in s
    assert esc.line("a\nb") == "a\\nb"
