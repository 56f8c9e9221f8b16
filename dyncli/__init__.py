"""dyncli — a command-line problem solver for engineering dynamics.

Kept import-light on purpose: ``dyncli --version`` must not import numpy.
The Python API (``dyncli.solve``, ``dyncli.sweep``, ``dyncli.Solution``,
``dyncli.InputError``, ``dyncli.NumericalError``; docs/api.md) is loaded on
first use.
"""

import sys as _sys


def _interrupted(signum, frame):  # pragma: no cover - exercised in a subprocess
    import os

    os._exit(130)


def quiet_interrupts() -> None:
    """SIGINT (Ctrl-C) ends the process with exit 130 and nothing printed
    (the command's handler; never installed by ``import dyncli``).  Through the interpreter's
    built-in ``_signal`` (loaded before any Python code runs): importing ``signal`` took the
    first interrupts of a loaded machine inside ``signal.py``, with a traceback."""
    sig = _sys.modules.get("_signal") or __import__("signal")

    sig.signal(sig.SIGINT, _interrupted)


#: the BLAS thread counts the command sets to 1 where the user has not set them: its matrices have
#: a few rows (a scene's 9 × 9, a few hundred at a time at most), where a BLAS thread pool only
#: waits — and on a loaded machine OpenBLAS's threads spin: a stacked 9 × 9 inverse took 100 ms of
#: wall time for 2 ms of work (numpy 1.26's OpenBLAS 0.3.23, two test suites at once), unseen by
#: the solve's CPU budget, which counts its own thread
BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def single_threaded_blas() -> None:
    """One BLAS thread for the command (never set by ``import dyncli``; a variable the user set
    is kept).  Only before numpy is imported: its BLAS reads them when it loads."""
    if "numpy" in _sys.modules:
        return
    import os

    for name in BLAS_THREADS:
        os.environ.setdefault(name, "1")


def _started_as_command() -> bool:
    """True when this import is the ``dyncli`` command's own start-up
    (``python -m dyncli`` or the ``dyncli`` script), never for ``import dyncli``."""
    orig = getattr(_sys, "orig_argv", [])
    if len(orig) >= 3 and orig[1:3] == ["-m", "dyncli"]:
        return True
    name = (_sys.argv[0] if _sys.argv else "").replace("\\", "/").rsplit("/", 1)[-1].lower()
    return name in ("dyncli", "dyncli.exe", "dyncli-script.py")


if _started_as_command():
    # the first thing the command does: an interrupt (Ctrl-C) from here on
    # ends it with exit 130 and nothing printed (dyncli.__main__); before this
    # line only the interpreter's own start-up runs (docs/cli.md, "Interrupts")
    quiet_interrupts()
    single_threaded_blas()

__version__ = "0.1.0"

_LAZY = {
    "solve": "dyncli.api",
    "sweep": "dyncli.api",
    "Solution": "dyncli.api",
    "InputError": "dyncli.errors",
    "NumericalError": "dyncli.errors",
}
__all__ = ["__version__", *_LAZY]


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'dyncli' has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(_LAZY))
