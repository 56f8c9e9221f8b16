"""--format csv|markdown|latex, the JSON record's version and input hash,
and a solution's notebook views: the same rows as the terminal view."""

from __future__ import annotations

import csv
import hashlib
from html import escape
import io
import json
import math
import re
import shutil
import subprocess

import pytest

import dyncli
from dyncli.render.latex import tex_text, tex_unit
from tests.conftest import ROOT, run_cli

BASE = "problems/vibration/base-excitation.yaml"


def _norm(line: str) -> str:
    return " ".join(re.sub("[│┃║]", " ", line).split())


def _table_rows(sol) -> list[list[str]]:
    """The cells of every row of every table of the view."""
    from dyncli.render.view import build

    return [row for g in build(sol._problem, sol._result).grids for row in g.rows]


@pytest.mark.parametrize("path", [BASE, "problems/impact/oblique-smooth.yaml", "problems/vibration/sweep.yaml"])
def test_markdown_and_html_hold_the_terminal_rows(path):
    sol = dyncli.solve(str(ROOT / path))[0]
    text_lines = {_norm(ln) for ln in sol.table().splitlines()}
    md = sol._repr_markdown_()
    md_rows = {_norm(re.sub(r"\\(.)", r"\1", " ".join(c.strip() for c in ln.strip("|").split(" | ") if c.strip())))
               for ln in md.splitlines() if ln.startswith("| ")}   # markdown's backslash escapes (m\*) read back
    html = sol._repr_html_()
    for cells in _table_rows(sol):
        row = _norm(" ".join(c for c in cells if c))
        assert row in text_lines, f"terminal view lacks {row!r}"
        assert row in md_rows, f"markdown lacks {row!r}"
        assert all(f">{escape(c)}</td>" in html for c in cells), row


def test_markdown_structure():
    rc, out, err = run_cli("solve", BASE, "-f", "markdown")
    assert rc == 0, err
    lines = out.splitlines()
    assert lines[0] == "### Base-excited spring-mass-damper"
    tables = [i for i, ln in enumerate(lines) if re.fullmatch(r"\|(-{3}:?\|)+|\|(-{3}|-{3}:)(\|-{3}:?)*\|", ln)]
    assert len(tables) == 2
    for i in tables:   # header, rule and rows have the same number of cells
        n = lines[i].count("|")
        j = i + 1
        while j < len(lines) and lines[j].startswith("| "):
            assert lines[j].count("|") - lines[j].count("\\|") == n
            j += 1
        assert lines[i - 1].count("|") == n
    assert "| 0.1 | 0.201977 | 0.0214629 | 0.00169501 | 0.00197725 |" in lines      # x, v, w, distance


def test_latex_structure_ascii_booktabs_siunitx():
    rc, out, err = run_cli("solve", BASE, "problems/gyroscopic/top-steady-precession.yaml", "-f", "latex")
    assert rc == 0, err
    assert out.isascii()
    assert out.count(r"\begin{tabular}") == out.count(r"\end{tabular}") >= 3
    assert out.count(r"\toprule") == out.count(r"\bottomrule") == out.count(r"\midrule") == out.count(r"\begin{tabular}{") - out.count(r"\begin{tabular}[t]")
    assert r"\num{1.78718}" in out and r"\si{rad/s}" in out and r"$\omega_{n}$" in out
    body = re.sub(r"\\[{}$&%#_]", "", out)
    assert body.count("{") == body.count("}")
    assert body.count("$") % 2 == 0
    spec = None
    for line in out.splitlines():   # every row has as many cells as its tabular's column spec
        if line.startswith(r"\begin{tabular}{"):
            spec = len(line[len(r"\begin{tabular}{"):-1])
        elif line.endswith(r" \\") and spec and r"\begin{tabular}[t]" not in line:
            assert line.count("&") - line.count(r"\&") == spec - 1, line


def test_latex_symbols():
    assert tex_text("ωₙ") == r"$\omega_{n}$"
    assert tex_text("θ̇ [rad/s]") == r"$\dot{\theta}$ [rad/s]"
    assert tex_text("T₁ − T₂") == r"$T_{1}$ $-$ $T_{2}$"
    assert tex_text("50% & $x_1") == r"50\% \& \$x\_1"
    assert tex_unit("N·s/m") == r"\si{N.s/m}" and tex_unit("kg·m²") == r"\si{kg.m^2}"


@pytest.mark.skipif(not (shutil.which("pdflatex") or shutil.which("lualatex")), reason="no TeX engine installed")
def test_latex_compiles(tmp_path):
    rc, out, _ = run_cli("solve", BASE, "problems/impact/oblique-smooth.yaml", "-f", "latex")
    assert rc == 0
    (tmp_path / "doc.tex").write_text("\\documentclass{article}\n\\usepackage{booktabs}\n\\usepackage{siunitx}\n"
                                      "\\begin{document}\n" + out + "\\end{document}\n")
    engine = shutil.which("pdflatex") or shutil.which("lualatex")
    p = subprocess.run([engine, "-interaction=nonstopmode", "-halt-on-error", "doc.tex"], cwd=tmp_path,
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stdout[-3000:]


def test_csv_wide_and_long():
    rc, out, err = run_cli("solve", BASE, "problems/impact/oblique-smooth.yaml", "-f", "csv")
    assert rc == 0, err
    rows = list(csv.DictReader(io.StringIO(out)))
    head = out.splitlines()[0].split(",")
    assert head[:3] == ["file", "index", "type"] and "x.0" in head and "vA2.1" in head
    vib, imp = rows
    assert float(vib["omega_n"]) == 20.0 and vib["vA2.0"] == ""
    assert float(imp["vA2.1"]) == pytest.approx(-2.304, rel=1e-15)
    rc, out, err = run_cli("solve", BASE, "-f", "csv", "--long", "--sweep", "zeta=0.05,0.1")
    assert rc == 0, err
    rows = list(csv.DictReader(io.StringIO(out)))
    assert len(rows) == 2 * 6 and list(rows[0])[:5] == ["file", "index", "type", "zeta", "t"]
    assert [float(r["t"]) for r in rows[:6]] == [0, 0.1, 0.5, 1, 5, 20]
    assert {r["zeta"] for r in rows} == {"0.05", "0.1"} and rows[0]["G"] == rows[5]["G"]


def test_json_version_and_input_hash():
    rc, out, _ = run_cli("solve", BASE, "-f", "json")
    rec = json.loads(out)[0]
    assert rec["dyncli_version"] == dyncli.__version__
    import yaml

    raw = yaml.safe_load((ROOT / BASE).read_text())
    canonical = json.dumps(raw, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    assert rec["input_sha256"] == hashlib.sha256(canonical.encode()).hexdigest()
    rc, out2, _ = run_cli("solve", BASE, "-f", "json", "--set", "m=1")   # the same value: the same problem
    assert json.loads(out2)[0]["input_sha256"] != rec["input_sha256"] or raw["m"] == 1
    rc, out3, _ = run_cli("solve", BASE, "-f", "json", "--set", "m=2")
    assert json.loads(out3)[0]["input_sha256"] != rec["input_sha256"]


def test_api_results_and_record_agree_with_the_closed_form():
    s = dyncli.solve(str(ROOT / BASE))[0]
    r = 30 / 20
    assert s["G"] == pytest.approx(r**2 / math.hypot(1 - r**2, 2 * 0.05 * r), rel=1e-14)
    assert s.to_dict()["results"]["G"] == s["G"]


@pytest.mark.slow
def test_latex_and_ascii_spell_every_symbol_of_the_gallery():
    """Every character the gallery's tables use has a LaTeX and an ASCII
    spelling (no '?' placeholder) and the LaTeX stays balanced."""
    files = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "problems").glob("*/*.yaml"))
    rc, out, err = run_cli("solve", "-f", "latex", *files)
    assert rc == 0, err
    assert out.isascii() and "?" not in out
    body = re.sub(r"\\[{}$&%#_]", "", out)
    assert body.count("{") == body.count("}") and body.count("$") % 2 == 0
    rc, out, err = run_cli("solve", *files, env={"PYTHONIOENCODING": "ascii"})
    assert rc == 0 and out.isascii() and "?" not in out
