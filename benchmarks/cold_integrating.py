"""Cold start of the integrating types against a student's script (issue 31, item 4).

For each case in ``benchmarks/cold_scripts/`` (a problem file NAME.yaml and the
script NAME.py a student would write: ``import numpy``, ``scipy.integrate.solve_ivp``
with DOP853 at dyncli's default rtol 1e-10, the same equations, the same report times),
the median CPU time (user + sys of the child) of

* ``python -m dyncli solve -f json NAME.yaml`` and
* ``python NAME.py``,

measured in interleaved rounds in one run, and their ratio (goal: <= 1.15).  Then
what dyncli adds on top of the script's imports, each measured the same way as the
CPU of a bare interpreter importing it, over ``python -c "import numpy,
scipy.integrate"``: typer (the command line), pydantic (the input models), PyYAML,
and the whole ``dyncli --version`` start-up.

Usage: python benchmarks/cold_integrating.py [--runs N]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))      # this checkout's dyncli

from startup import timed_rounds  # noqa: E402

GOAL = 1.15
HERE = Path(__file__).resolve().parent / "cold_scripts"
PY = sys.executable
PARTS = {
    "floor: import numpy, scipy.integrate": "import numpy, scipy.integrate",
    "+ typer": "import numpy, scipy.integrate, typer",
    "+ pydantic": "import numpy, scipy.integrate, pydantic; from pydantic import BaseModel",
    "+ yaml": "import numpy, scipy.integrate, yaml",
    "+ typer, pydantic, yaml": "import numpy, scipy.integrate, typer, yaml, pydantic; from pydantic import BaseModel",
}


def report(runs: int) -> None:
    """Measure and print every case and the import breakdown (``runs`` interleaved rounds)."""
    cases = sorted(p.stem for p in HERE.glob("*.yaml"))
    cmds = []
    for c in cases:
        cmds += [[PY, "-m", "dyncli", "solve", "-f", "json", str(HERE / f"{c}.yaml")], [PY, str(HERE / f"{c}.py")]]
    cmds += [[PY, "-c", code] for code in PARTS.values()] + [[PY, "-m", "dyncli", "--version"], [PY, "-c", "pass"]]
    res = [cpu for _, cpu in timed_rounds(cmds, runs)]
    print(f"cold CPU, median of {runs} interleaved rounds (goal: dyncli <= {GOAL} x the student's script)\n")
    print(f"{'case':<20} {'dyncli [ms]':>12} {'script [ms]':>12} {'ratio':>7} {'extra [ms]':>11}")
    for i, c in enumerate(cases):
        d, s = res[2 * i], res[2 * i + 1]
        print(f"{c:<20} {1e3 * d:12.1f} {1e3 * s:12.1f} {d / s:7.3f} {1e3 * (d - s):11.1f}"
              + ("" if d / s <= GOAL else "   (goal not met)"))
    k = 2 * len(cases)
    floor = res[k]
    print("\nwhat dyncli imports on top of the script's own imports (CPU over the floor):")
    for j, name in enumerate(PARTS):
        v = res[k + j]
        print(f"  {name:<40} {1e3 * v:8.1f} ms" + (f"   (+{1e3 * (v - floor):.1f} ms)" if j else ""))
    print(f"  {'dyncli --version (start-up alone)':<40} {1e3 * res[-2]:8.1f} ms   (bare interpreter {1e3 * res[-1]:.1f} ms)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=11)
    report(ap.parse_args().runs)


if __name__ == "__main__":
    main()
