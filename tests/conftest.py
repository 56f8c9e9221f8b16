"""Shared test helpers.

* ``solve_text(yaml_text)`` / ``solve_path(path)``: solve in-process and return
  the contract's JSON records (list of dicts), exactly as ``--format json``.
* ``run_cli(*args, input=None)``: run ``python -m dyncli`` in a subprocess;
  returns (exit code, stdout, stderr).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

# one BLAS thread, as the command runs (dyncli.single_threaded_blas): set before numpy is
# imported, here and in the xdist workers, which inherit the environment
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "problems"


def _records(problems, diags):
    from dyncli.render.jsonout import dumps
    from dyncli.run import outcome_record, solve_one

    if diags:
        raise AssertionError("; ".join(str(d) for d in diags))
    outs = [solve_one(lp) for lp in problems]
    return json.loads(dumps([outcome_record(o) for o in outs]))


def solve_text(text: str, name: str = "test.yaml") -> list[dict]:
    from dyncli.loader import split_problems, validate

    problems, diags = split_problems(name, text.encode(), ROOT)
    for p in problems:
        validate(p)
    return _records(problems, diags)


def solve_one_text(text: str) -> dict:
    """Solve a single-problem YAML text; return its record (asserts success)."""
    recs = solve_text(text)
    assert len(recs) == 1
    rec = recs[0]
    assert rec.get("error") is None, rec.get("error")
    return rec


def lookup(results, dotted: str):
    """The value at a dotted result path (``find.1.t``, ``reaction.axle.R.0.1``: list indices
    by number), or None where the path leads nowhere."""
    node = results
    for part in dotted.split("."):
        if isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            return None
    return node


def solve_path(path) -> list[dict]:
    from dyncli.loader import load_paths

    return _records(*load_paths([str(path)]))


def run_cli(*args: str, input: str | bytes | None = None, env: dict | None = None, timeout: float = 120):
    e = dict(os.environ)
    e["PYTHONPATH"] = str(ROOT) + os.pathsep + e.get("PYTHONPATH", "")
    e.setdefault("NO_COLOR", "1")
    e["COLUMNS"] = "160"
    if env:
        e.update(env)
    if isinstance(input, str):
        input = input.encode()
    p = subprocess.run([sys.executable, "-m", "dyncli", *args], input=input, capture_output=True,
                       cwd=ROOT, env=e, timeout=timeout)
    return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")


def error_of(text: str) -> str:
    """The diagnostic of an invalid single-problem YAML text (asserts invalid)."""
    from dyncli.loader import split_problems, validate
    from dyncli.run import solve_one

    problems, diags = split_problems("bad.yaml", text.encode(), ROOT)
    if diags:
        return str(diags[0])
    assert len(problems) == 1
    validate(problems[0])
    o = solve_one(problems[0])
    assert o.exit_code == 2, f"expected invalid input, got exit {o.exit_code}: {o.message}"
    return o.message


@pytest.fixture
def cli():
    return run_cli


# Hypothesis: CI runs a fixed (derandomized) set of examples so a green or red
# result is reproducible; local runs explore randomly.
from hypothesis import settings as _hsettings  # noqa: E402

_hsettings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    _hsettings.load_profile("ci")


@pytest.fixture(autouse=True)
def _mpmath_precision(request):
    """Each test runs with the mpmath precision its module asks for
    (``MPMATH_DPS = 50`` at module level; default 15), whatever other modules
    imported in the same worker set globally."""
    import mpmath

    dps = getattr(request.module, "MPMATH_DPS", None)
    if dps is None:
        yield
        return
    with mpmath.workdps(dps):
        yield
