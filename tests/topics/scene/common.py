"""Shared by the scene gallery tests: each gallery file solved once per test session."""

from __future__ import annotations

import functools

from tests.conftest import PROBLEMS, solve_path

SCENES = PROBLEMS / "scenes"


@functools.lru_cache(maxsize=None)
def gallery(name: str) -> dict:
    """The record of ``problems/scenes/NAME`` (asserts one problem, solved without error)."""
    recs = solve_path(SCENES / name)
    assert len(recs) == 1
    rec = recs[0]
    assert rec.get("error") is None, rec.get("error")
    return rec
