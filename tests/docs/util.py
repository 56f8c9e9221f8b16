"""Shared helpers of the docs tests."""

from __future__ import annotations

import importlib.util
import re
from functools import lru_cache

from tests.conftest import PROBLEMS, ROOT

DOCS = ROOT / "docs"
GALLERY = DOCS / "gallery.md"


def load_docs_module(name: str):
    """Import docs/<name>.py (docs/ is not a package)."""
    import sys

    key = f"_dyncli_docs_{name}"
    if key in sys.modules:
        return sys.modules[key]
    spec = importlib.util.spec_from_file_location(key, DOCS / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[key] = mod
    spec.loader.exec_module(mod)
    return mod


def gallery_files() -> list[str]:
    """Every file under problems/, as a path relative to the repository root."""
    return sorted(str(p.relative_to(ROOT)) for p in PROBLEMS.rglob("*") if p.is_file())


def problem_files() -> list[str]:
    """The gallery's problem files (the course example's key and answers are answer files)."""
    return [f for f in gallery_files() if f.endswith(".yaml") and not re.search(r"course-example/(key\.yaml|answers/)", f)]


@lru_cache(maxsize=1)
def gallery_text() -> str:
    return GALLERY.read_text(encoding="utf-8")
