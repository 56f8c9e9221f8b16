"""`dyncli check` reports piped or written to a file (self-study and key mode):
without trailing spaces, like the tables of `solve`; written to a file at
their natural width (no folding), piped at COLUMNS (the same as the file when
COLUMNS is wide enough) or 100 columns, the feedback folded between words."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys

from tests.check.keyhelpers import KEY, params_of, truth, write_sub
from tests.conftest import ROOT

FIX = ROOT / "tests" / "check" / "fixtures"
FEEDBACK = "relative error"


def _run(*args, columns: str | None = "10000"):
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")}
    env.update(PYTHONPATH=str(ROOT), NO_COLOR="1", **({"COLUMNS": columns} if columns else {}))
    p = subprocess.run([sys.executable, "-m", "dyncli", "check", *args], cwd=ROOT, env=env,
                       capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def _natural(text: str) -> None:
    lines = text.splitlines()
    assert not [ln for ln in lines if ln != ln.rstrip()], "trailing spaces"
    row = next(ln for ln in lines if FEEDBACK in ln)
    assert "exceeds the tolerance" in row and len(row) > 80, row     # the feedback is not folded
    assert "(continued)" not in text


def _folded(text: str) -> None:
    from dyncli.render.plain import cell_len

    lines = text.splitlines()
    assert not [ln for ln in lines if ln != ln.rstrip()], "trailing spaces"
    assert max(cell_len(ln) for ln in lines) <= 100
    assert any("exceeds the" in ln for ln in lines) and any(ln.strip().startswith("(rtol") for ln in lines)


def _self_study(tmp_path):
    shutil.copy(FIX / "brake.yaml", tmp_path / "brake.yaml")
    ans = tmp_path / "answers.yaml"
    ans.write_text("problem: brake.yaml\nanswers:\n  find.0.s: 31\n  find.1.t: 5\n")
    return str(ans)


def test_self_study_piped_and_to_a_file(tmp_path):
    ans = _self_study(tmp_path)
    rc, out, err = _run(ans, "--reveal")
    assert rc == 1, err
    _natural(out)
    rc, folded, err = _run(ans, "--reveal", columns=None)
    assert rc == 1, err
    _folded(folded)
    rc, out2, err = _run(ans, "--reveal", "-o", str(tmp_path / "report.txt"))
    assert rc == 1 and out2 == "", err
    assert (tmp_path / "report.txt").read_text(encoding="utf-8") == out


def test_key_mode_piped_and_to_a_file(tmp_path):
    ref = truth(**{k: v for k, v in params_of("s1").items() if k in ("v0", "a0")})
    wrong = {q: v * 1.5 for q, v in ref.items()}
    sub = write_sub(tmp_path, "s1.yaml", "s1", wrong)
    rc, out, err = _run("--key", str(KEY), sub, "--reveal")
    assert rc == 1, err
    _natural(out)
    rc, folded, err = _run("--key", str(KEY), sub, "--reveal", columns=None)
    assert rc == 1, err
    _folded(folded)
    rc, _, err = _run("--key", str(KEY), sub, "--reveal", "-o", str(tmp_path / "report.txt"))
    assert rc == 1, err
    assert (tmp_path / "report.txt").read_text(encoding="utf-8") == out
