"""Regenerate the oracle's stored references: ``python -m tests.oracle.generate`` (from the
repository root; ~1 min).  Writes ``tests/oracle/cases/<type>.json`` — every case's problem
document, its references (mpmath at 40 digits, sympy where a derivative is needed) as strings
and the tolerance each route's guarantee implies, with its reason.  Never imports dyncli: the
references are independent of the code under test (``test_oracle.py`` checks the imports)."""

from __future__ import annotations

import importlib
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
CASES = HERE / "cases"
# one module per group of types; each has cases() -> list of case dicts (tests.oracle.common)
MODULES = ["points", "rectilinear", "vibration", "particle", "constrained", "bodies", "systems",
           "gyro", "euler_top", "pendulum"]


def build(only: str | None = None) -> dict[str, list[dict]]:
    by_type: dict[str, list[dict]] = {}
    for name in MODULES:
        if only and name != only:
            continue
        mod = importlib.import_module(f"tests.oracle.ref_{name}")
        for c in mod.cases():
            c["module"] = f"tests/oracle/ref_{name}.py"
            by_type.setdefault(c["type"], []).append(c)
    return by_type


def main(argv: list[str]) -> int:
    only = argv[0] if argv else None
    by_type = build(only)
    CASES.mkdir(exist_ok=True)
    for type_, cases in sorted(by_type.items()):
        doc = {"generated_by": "python -m tests.oracle.generate", "type": type_, "cases": cases}
        (CASES / f"{type_}.json").write_text(json.dumps(doc, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
        print(f"{type_:22s} {len(cases):3d} cases")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
