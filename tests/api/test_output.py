"""Output that does not change when piped, and the environment's failures:
a terminal (pty) and a pipe hold the same rows; no wrapping at 80 columns,
no trailing spaces; COLUMNS=0; a closed pipe (exit 0, quiet); a full disk
(exit 2, one line); an ASCII-only stdout; SIGINT at start-up (exit 130,
nothing else); option values checked; every validation error listed."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time

import pytest

from tests.conftest import ROOT, run_cli

WIDE = "problems/particle/spring-friction-rest.yaml"     # a series table 128 columns wide
BASE = "problems/vibration/base-excitation.yaml"


def _env(**extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "LINES")}
    env.update(PYTHONPATH=str(ROOT), NO_COLOR="1", **extra)
    return env


def _run(args, **extra):
    p = subprocess.run([sys.executable, "-m", "dyncli", *args], cwd=ROOT, env=_env(**extra), capture_output=True,
                       timeout=120)
    return p.returncode, p.stdout, p.stderr.decode("utf-8", "replace")


def test_piped_tables_at_natural_width_with_wide_without_trailing_spaces():
    rc, out, err = _run(["solve", WIDE, "--wide"])
    assert rc == 0, err
    text = out.decode()
    assert "(continued)" not in text
    assert max(len(ln) for ln in text.splitlines()) > 100
    assert not [ln for ln in text.splitlines() if ln != ln.rstrip()]


@pytest.mark.parametrize("columns, width", [(None, 100), ("80", 80)])
def test_piped_tables_fit_columns_or_100(columns, width):
    """Piped: every table within COLUMNS, or 100 columns when it is not set (a wide series
    continues below); vectors are never cut."""
    extra = {"COLUMNS": columns} if columns else {}
    files = [WIDE, "problems/inertia/coin.yaml"] if width == 100 else [WIDE]   # coin: vectors 80 wide
    rc, out, err = _run(["solve", *files], **extra)
    assert rc == 0, err
    text = out.decode()
    from dyncli.render.plain import cell_len

    rows = [ln for ln in text.splitlines() if ln.startswith(" ")]      # a caption wider than its table is flush left
    assert max(cell_len(ln) for ln in rows) <= width
    assert max(cell_len(ln) for ln in text.splitlines() if ln.startswith("warning:")) <= width
    for ln in text.splitlines():
        assert ln.count("[") == ln.count("]"), ln              # a vector whole on its line


def test_columns_zero_still_prints():
    rc, out, err = _run(["solve", BASE], COLUMNS="0")
    assert rc == 0 and b"omega_n" in out, err


def _pty_output(args: list[str], cols: int) -> str:
    import fcntl
    import pty
    import struct
    import termios

    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 50, cols, 0, 0))
    p = subprocess.Popen([sys.executable, "-m", "dyncli", *args], cwd=ROOT, env=_env(TERM="xterm"),
                         stdout=slave, stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    p.wait(timeout=60)
    os.close(master)
    text = b"".join(chunks).decode("utf-8", "replace").replace("\r", "")
    return re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", text)


@pytest.mark.parametrize("path", [WIDE, BASE])
def test_terminal_and_pipe_hold_the_same_rows(path):
    rc, piped, _ = _run(["solve", path], COLUMNS="200")
    assert rc == 0
    term = _pty_output(["solve", path], cols=200)
    strip = [ln.rstrip() for ln in term.splitlines()]
    assert [ln for ln in strip if ln] == [ln for ln in piped.decode().splitlines() if ln]


def test_closed_pipe_ends_quietly():
    p = subprocess.Popen([sys.executable, "-m", "dyncli", "solve", BASE, "--sweep", "k=100:1000:3000", "-f", "csv"],
                         cwd=ROOT, env=_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read().decode()
    assert p.wait(timeout=120) == 0
    assert err == ""


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full")
def test_full_disk_is_exit_2_with_one_line():
    for fmt in ("json", "table"):
        with open("/dev/full", "w") as full:
            p = subprocess.run([sys.executable, "-m", "dyncli", "solve", BASE, "-f", fmt], cwd=ROOT, env=_env(),
                               stdout=full, stderr=subprocess.PIPE, timeout=120)
        assert p.returncode == 2
        assert p.stderr.decode().splitlines() == ["dyncli: cannot write the output: No space left on device"]


TITLED = "type: vibration\ntitle: 'ω∞ — test'\nm: 1\nk: 400\nzeta: 0.05\nv0: 1\nat: [0, 1]\n"


@pytest.mark.parametrize("env", [{"PYTHONIOENCODING": "ascii"}, {"LC_ALL": "C", "PYTHONCOERCECLOCALE": "0",
                                                                  "PYTHONUTF8": "0"}])
def test_ascii_stdout(env):
    p = subprocess.run([sys.executable, "-m", "dyncli", "solve", "-f", "json", "-"], input=TITLED.encode(), cwd=ROOT,
                       env=_env(**env), capture_output=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)[0]["title"] == "ω∞ — test"
    for fmt in ("table", "markdown", "yaml", "csv"):
        p = subprocess.run([sys.executable, "-m", "dyncli", "solve", "-f", fmt, "-"], input=TITLED.encode(), cwd=ROOT,
                           env=_env(**env), capture_output=True, timeout=120)
        assert p.returncode == 0 and p.stderr == b"", (fmt, p.stderr)
        if env.get("PYTHONIOENCODING") == "ascii":
            text = p.stdout.decode("ascii")
            assert "omega" in text, fmt
            if fmt == "table":
                assert "omegainf - test" in text and "omega_n" in text


def test_sigint_during_start_up_is_exit_130_and_silent():
    """An interrupt while dyncli imports its modules (typer, rich, ...)."""
    code = ("import builtins, os, signal, sys\n"
            "sys.argv = ['dyncli', 'solve', 'problems/vibration/base-excitation.yaml']\n"
            "real = builtins.__import__\n"
            "def imp(name, *a, **k):\n"
            "    if name == 'typer':\n"
            "        os.kill(os.getpid(), signal.SIGINT)\n"
            "    return real(name, *a, **k)\n"
            "builtins.__import__ = imp\n"
            "from dyncli.__main__ import main\n"
            "main()\n")
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=_env(), capture_output=True, timeout=60)
    assert (p.returncode, p.stdout, p.stderr) == (130, b"", b"")


def test_sigint_at_any_moment_never_shows_dyncli_code():
    """Interrupts at random moments: exit 130 (or death by SIGINT) and nothing
    on stderr once dyncli's code runs; before that the interpreter's own
    start-up (site, runpy) is Python's, which dyncli cannot change."""
    for delay in (0.05, 0.1, 0.2, 0.3, 0.5):
        p = subprocess.Popen([sys.executable, "-m", "dyncli", "solve", BASE], cwd=ROOT,
                             env=_env(), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        time.sleep(delay)
        p.send_signal(2)
        out, err = p.communicate(timeout=60)
        if p.returncode == 0 or f"{os.sep}dyncli{os.sep}".encode() not in err:
            continue   # finished before the signal, or interrupted in the interpreter's start-up (site, runpy)
        assert p.returncode in (130, -2) and err == b"", (delay, p.returncode, err.decode())


@pytest.mark.parametrize("args, message", [
    (["--units", "blah"], "--units: unknown unit 'blah'"),
    (["--units", "degg"], "--units: unknown unit 'degg' (did you mean 'deg'?)"),
    (["--long"], "--long works only with --format csv (one row per time): add --format csv"),
    (["--set", "k"], "--set 'k': expected PATH=VALUE, e.g. --set k=500"),
])
def test_option_values_are_checked(args, message):
    rc, out, err = run_cli("solve", BASE, *args)
    assert rc == 2 and out == ""
    assert err.strip() == message


def test_symbolic_says_where_it_has_no_effect():
    rc, out, err = run_cli("solve", BASE, "problems/kinematics/helix-cylindrical.yaml",
                           "--symbolic")
    assert rc == 0
    assert "--symbolic: no symbolic view for vibration" in err
    rc, out, err = run_cli("solve", BASE, "--symbolic", "-f", "json")
    assert rc == 0 and "not in --format json" in err
    json.loads(out)


def test_symbolic_types_list_is_right():
    """The types declared ``symbolic`` are exactly those whose result changes with --symbolic."""
    import yaml

    from dyncli.loader import load_paths
    from dyncli.result import SolveOptions
    from dyncli.registry import having
    from dyncli.run import solve_one

    SYMBOLIC_TYPES = having("symbolic")

    seen: dict[str, bool] = {}
    for f in sorted((ROOT / "problems").rglob("*.yaml")):
        t = (yaml.safe_load(f.read_text()) or {}).get("type") if isinstance(yaml.safe_load(f.read_text()), dict) else None
        if t is None or t in seen or t in ("particle", "force-field", "rectilinear", "euler", "top") and t not in SYMBOLIC_TYPES:
            continue
        lp = load_paths([str(f)])[0][0]
        a, b = solve_one(lp), solve_one(lp, SolveOptions(symbolic=True))
        if a.result is not None and b.result is not None:
            seen[t] = len(b.result.views) != len(a.result.views)
    assert {t for t, changed in seen.items() if changed} == set(SYMBOLIC_TYPES) & set(seen)


def test_validate_lists_every_error_one_line_each(tmp_path):
    f = tmp_path / "bad.yaml"
    f.write_text("type: vibration\nm: -1\nk: abc\nzeta: [1]\nv00: 3\nbase: {amplitude: 1, omega: -3, foo: 1}\n")
    for cmd in ("validate", "solve"):
        rc, out, err = run_cli(cmd, str(f))
        assert rc == 2
        lines = err.strip().splitlines()
        assert [ln.split(": ")[1] for ln in lines] == ["m", "k", "zeta", "v00", "base.omega", "base.foo"], err
        assert all(ln.startswith(f"{f}:") for ln in lines)


def test_shell_completion_is_offered():
    rc, out, _ = run_cli("--help")
    assert rc == 0 and "--install-completion" in out and "--show-completion" in out


def test_completion_of_format_values():
    code = "import sys\nsys.argv[0] = 'dyncli'\nfrom dyncli.__main__ import main\nmain()\n"
    p = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=60,
                       env=_env(_DYNCLI_COMPLETE="complete_bash", COMP_WORDS="dyncli solve x --format ", COMP_CWORD="4"))
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["table", "json", "yaml", "csv", "markdown", "latex"]
