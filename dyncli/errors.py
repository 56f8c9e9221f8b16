"""Exceptions that map to the contract's exit codes (see docs/cli.md).

* :class:`InputError`     -> exit 2 (invalid input or usage, unphysical values)
* :class:`NumericalError` -> exit 1 (a numerical step failed)
* anything else           -> exit 3 (a bug)
"""

from __future__ import annotations


class DyncliError(Exception):
    exit_code = 3


class InputError(DyncliError):
    """Invalid input. ``path`` is the dotted field path inside the problem
    (e.g. ``"find.0.v"``); the loader turns it into ``file:line:col``."""

    exit_code = 2
    messages: list[str]    # the lines of an error about several fields (set by dyncli.api)

    def __init__(self, message: str, path: str | tuple | None = None):
        super().__init__(message)
        self.message = message
        if isinstance(path, tuple):
            path = ".".join(str(p) for p in path)
        self.path = path or None

    def __str__(self) -> str:  # pragma: no cover - trivial
        return f"{self.path}: {self.message}" if self.path else self.message


class NumericalError(DyncliError):
    """A numerical step failed (no convergence, integrator gave up...)."""

    exit_code = 1
