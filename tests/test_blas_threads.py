"""The command runs with one BLAS thread (dyncli.single_threaded_blas): its matrices are a few rows,
where a BLAS thread pool only waits — and on a loaded machine OpenBLAS's spinning threads made a
stacked 9 × 9 inverse take 100 ms of wall time for 2 ms of work (a fuzz corpus document ran past
the 10 s hang limit under two test suites at once).  ``import dyncli`` leaves the environment as
it is; a thread count the user set is kept."""

from __future__ import annotations

import os
import subprocess
import sys

from tests.conftest import ROOT

PROBE = ("import os, sys; sys.orig_argv = [sys.executable, '-m', 'dyncli']; import dyncli; "
         "print(os.environ.get('OPENBLAS_NUM_THREADS'), 'numpy' in sys.modules)")
LIBRARY = "import os, dyncli; print(os.environ.get('OPENBLAS_NUM_THREADS'))"


def _run(code: str, **env) -> str:
    base = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS",
                                                             "MKL_NUM_THREADS")}
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                         env={**base, "PYTHONPATH": str(ROOT), **env})
    assert out.returncode == 0, out.stderr
    return out.stdout.strip()


def test_the_command_sets_one_blas_thread_before_numpy():
    assert _run(PROBE) == "1 False"


def test_a_thread_count_the_user_set_is_kept():
    assert _run(PROBE, OPENBLAS_NUM_THREADS="3") == "3 False"


def test_import_dyncli_leaves_the_environment():
    assert _run(LIBRARY) == "None"
