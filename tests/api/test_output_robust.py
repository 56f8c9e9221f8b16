"""Issue #29, output robustness: an output file is written atomically; a
COLUMNS too narrow to show a value is treated as unknown; no library's
warning reaches stderr as raw text; an interrupt is handled from the first
line of the dyncli package when it starts as the command."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading

import pytest

from dyncli import stdio
from tests.conftest import ROOT, run_cli


def test_write_file_replaces_the_file_whole_and_leaves_no_temporary(tmp_path):
    out = tmp_path / "report.json"
    out.write_text("old", encoding="utf-8")
    stdio.write_file(str(out), json.dumps({"x": 1}))
    assert json.loads(out.read_text(encoding="utf-8")) == {"x": 1}
    assert [p.name for p in tmp_path.iterdir()] == ["report.json"]


def test_write_file_failing_midway_keeps_the_old_file(tmp_path, monkeypatch):
    out = tmp_path / "report.json"
    out.write_text("old", encoding="utf-8")

    def boom(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", boom)
    with pytest.raises(OSError):
        stdio.write_file(str(out), "new")
    assert out.read_text(encoding="utf-8") == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["report.json"]


def test_concurrent_writers_leave_one_whole_file(tmp_path):
    out = tmp_path / "report.json"
    texts = [json.dumps({"run": i, "pad": "x" * (50_000 + i)}) for i in range(20)]
    threads = [threading.Thread(target=stdio.write_file, args=(str(out), t)) for t in texts]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert out.read_text(encoding="utf-8") in texts      # valid JSON: one writer's whole text


@pytest.mark.parametrize("columns", ["1", "20", "39"])
def test_columns_below_a_usable_width_is_unknown(columns):
    rc, out, err = run_cli("solve", "problems/vibration/base-excitation.yaml", env={"COLUMNS": columns})
    assert rc == 0, err
    assert "…" not in out and "0.05" in out and "20" in out


def test_no_library_warning_reaches_stderr_on_an_expression_sweep():
    rc, out, err = run_cli("solve", "problems/rectilinear/general-forced-damped.yaml", "--sweep", "a=-4*s,-s,-2*s",
                           "-f", "json")
    assert rc == 0, err
    assert "site-packages" not in err and "Warning" not in err and "Pydantic" not in err
    assert all(line.startswith("problems/") for line in err.strip().splitlines())


_PROBE = ("import sys; sys.argv[0] = {argv0!r}\n"
          "import dyncli, signal\n"
          "print(signal.getsignal(signal.SIGINT) is dyncli._interrupted)\n")


@pytest.mark.parametrize("argv0, installed", [("/usr/bin/dyncli", True), ("notebook.py", False)])
def test_the_interrupt_handler_is_the_package_first_act_only_as_the_command(argv0, installed):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-c", _PROBE.format(argv0=argv0)], capture_output=True, text=True,
                       cwd=ROOT, env=env, timeout=60)
    assert p.stdout.strip() == str(installed), p.stderr


def test_python_m_dyncli_installs_it_before_importing_anything_heavy():
    code = ("import runpy, sys, signal\n"
            "sys.argv = ['dyncli', '--version']\n"
            "import dyncli\n"
            "assert 'numpy' not in sys.modules and 'typer' not in sys.modules\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, env=env, timeout=60)
    assert p.returncode == 0, p.stderr
    p = subprocess.run([sys.executable, "-m", "dyncli", "--version"], capture_output=True, text=True, cwd=ROOT,
                       env=env, timeout=60)
    assert p.returncode == 0 and not p.stderr, p.stderr      # no runpy warning about dyncli.__main__
