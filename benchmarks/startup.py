"""Cold start-up of dyncli, measured in one run, as ratios.

Prints the median wall time of N fresh interpreter runs for:
  * python -c pass                                  (the interpreter floor)
  * python -c "import numpy, pydantic, yaml, typer, rich"   (the bare-import floor)
  * python -m dyncli --version                      (target: no numpy/scipy)
  * python -m dyncli solve <case-1 file>            (target: <= 1.3x bare-import floor)
  * python -m dyncli solve <case-1 file> --plot out.png   (the cost of matplotlib + drawing)
  * python -m dyncli solve <each example type>      (one per type, if present)
and which heavy modules each dyncli run imported.

Usage: python benchmarks/startup.py [--runs N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("numpy", "scipy", "sympy", "pydantic", "matplotlib", "pint")


def timed(cmd: list[str], runs: int) -> float:
    env = dict(os.environ, PYTHONPATH=str(ROOT), NO_COLOR="1")
    ts = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        ts.append(time.perf_counter() - t0)
    return statistics.median(ts)


def imported(args: list[str]) -> list[str]:
    code = (
        "import sys, runpy\n"
        f"sys.argv = ['dyncli'] + {args!r}\n"
        "try:\n    runpy.run_module('dyncli', run_name='__main__')\nexcept SystemExit:\n    pass\n"
        f"print('MODS:' + ','.join(m for m in {HEAVY!r} if m in sys.modules))\n"
    )
    env = dict(os.environ, PYTHONPATH=str(ROOT), NO_COLOR="1")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=env, capture_output=True, text=True).stdout
    line = [ln for ln in out.splitlines() if ln.startswith("MODS:")]
    return line[-1][5:].split(",") if line and line[-1][5:] else []


def examples_per_type() -> dict[str, Path]:
    import yaml

    out: dict[str, Path] = {}
    for f in sorted((ROOT / "problems").rglob("*.yaml")):
        try:
            data = yaml.safe_load(f.read_text())
        except Exception:  # noqa: BLE001
            continue
        if isinstance(data, dict) and isinstance(data.get("type"), str):
            out.setdefault(data["type"], f)
    return out


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args()
    py = sys.executable
    n = args.runs
    floor = timed([py, "-c", "pass"], n)
    bare = timed([py, "-c", "import numpy, pydantic, yaml, typer, rich"], n)
    rows = [("python -c pass", floor, []), ("bare import numpy,pydantic,yaml,typer,rich", bare, [])]
    rows.append(("dyncli --version", timed([py, "-m", "dyncli", "--version"], n), imported(["--version"])))
    case1 = "problems/rectilinear/case1-constant-acceleration.yaml"
    rows.append(("dyncli solve case-1 (closed form)", timed([py, "-m", "dyncli", "solve", case1], n), imported(["solve", case1])))
    with tempfile.TemporaryDirectory() as tmp:
        out = str(Path(tmp) / "plot.png")
        rows.append(("dyncli solve case-1 --plot out.png", timed([py, "-m", "dyncli", "solve", case1, "--plot", out], n),
                     imported(["solve", case1, "--plot", out])))
    for t, f in examples_per_type().items():
        rel = str(f.relative_to(ROOT))
        if rel == case1:
            continue
        rows.append((f"dyncli solve {t}", timed([py, "-m", "dyncli", "solve", rel], max(3, n // 2)), imported(["solve", rel])))
    print(f"{'command':<48} {'median ms':>9} {'/pass':>7} {'/bare':>7}  heavy modules imported")
    for name, t, mods in rows:
        print(f"{name:<48} {t * 1000:9.1f} {t / floor:7.2f} {t / bare:7.2f}  {','.join(mods) or '-'}")


if __name__ == "__main__":
    main()
