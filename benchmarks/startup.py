"""Cold start-up of dyncli, measured in one run, as ratios.

Prints the median wall time of N fresh interpreter runs for:
  * python -c pass                                  (the interpreter floor)
  * python -c "import numpy, pydantic, yaml, typer, rich"   (the bare-import floor)
  * python -m dyncli --version                      (target: no numpy/scipy)
  * python -m dyncli solve <case-1 file>            (target: <= 1.3x bare-import floor)
  * python -m dyncli solve <case-1 file> --plot out.png   (the cost of matplotlib + drawing)
  * python -m dyncli solve <case-1 file with unit strings>  (the cost of pint)
  * python -m dyncli solve <each example type>      (one per type, if present)
and which heavy modules each dyncli run imported.

Each command runs once untimed first (so dyncli's own modules have their
.pyc, as in an installed copy: PYTHONDONTWRITEBYTECODE is removed from the
children's environment).  Wall time and CPU time (user + sys of the child,
the robust number on a shared machine) are both reported, each as a ratio to
``python -c pass`` and to the bare-import floor.

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


def _env() -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env.update(PYTHONPATH=str(ROOT), NO_COLOR="1")
    return env


def _once(cmd: list[str], env: dict) -> tuple[float, float]:
    import resource

    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    subprocess.run(cmd, cwd=ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime


def timed_rounds(cmds: list[list[str]], runs: int) -> list[tuple[float, float]]:
    """Median wall and CPU seconds of each command.  One warm-up run each,
    then ``runs`` rounds that run every command once (interleaved, so a
    change in the machine's load hits all of them alike)."""
    env = _env()
    for c in cmds:
        _once(c, env)
    samples: list[list[tuple[float, float]]] = [[] for _ in cmds]
    for _ in range(runs):
        for i, c in enumerate(cmds):
            samples[i].append(_once(c, env))
    return [(statistics.median(w for w, _ in s), statistics.median(c for _, c in s)) for s in samples]


def imported(args: list[str]) -> list[str]:
    code = (
        "import sys, runpy\n"
        f"sys.argv = ['dyncli'] + {args!r}\n"
        "try:\n    runpy.run_module('dyncli', run_name='__main__')\nexcept SystemExit:\n    pass\n"
        f"print('MODS:' + ','.join(m for m in {HEAVY!r} if m in sys.modules))\n"
    )
    env = _env()
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
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    py = sys.executable
    n = args.runs
    case1 = "problems/rectilinear/case1-constant-acceleration.yaml"
    spec: list[tuple[str, list[str], list[str] | None]] = [
        ("python -c pass", ["-c", "pass"], None),
        ("bare import numpy,pydantic,yaml,typer,rich", ["-c", "import numpy, pydantic, yaml, typer, rich"], None),
        ("dyncli --version", ["-m", "dyncli", "--version"], ["--version"]),
        ("dyncli --help", ["-m", "dyncli", "--help"], ["--help"]),
        ("dyncli solve case-1 (closed form)", ["-m", "dyncli", "solve", case1], ["solve", case1]),
        ("dyncli solve -f json case-1", ["-m", "dyncli", "solve", "-f", "json", case1], ["solve", "-f", "json", case1]),
    ]
    plot_out = str(Path(tempfile.mkdtemp(prefix="dyncli-startup-")) / "plot.png")
    spec.append(("dyncli solve case-1 --plot out.png", ["-m", "dyncli", "solve", case1, "--plot", plot_out],
                 ["solve", case1, "--plot", plot_out]))
    units_file = Path(plot_out).parent / "case1-units.yaml"
    units_file.write_text("type: rectilinear\na: '-4 m/s^2'\nv1: '72 km/h'\nfind: [{t: '2 s'}, {v: 0}, {s: '50 m'}]\n")
    spec.append(("dyncli solve case-1 with unit strings", ["-m", "dyncli", "solve", str(units_file)],
                 ["solve", str(units_file)]))
    for t, f in examples_per_type().items():
        rel = str(f.relative_to(ROOT))
        if rel != case1:
            spec.append((f"dyncli solve {t}", ["-m", "dyncli", "solve", rel], ["solve", rel]))
    times = timed_rounds([[py, *a] for _, a, _ in spec], n)
    rows = [(name, t, imported(args) if args else []) for (name, _, args), t in zip(spec, times)]
    floor, bare = times[0], times[1]
    (fw, fc), (bw, bc) = floor, bare
    print(f"{'command':<44} {'wall ms':>8} {'/pass':>6} {'/bare':>6} {'CPU ms':>7} {'/pass':>6} {'/bare':>6}  heavy modules")
    for name, (w, c), mods in rows:
        print(f"{name:<44} {w * 1000:8.1f} {w / fw:6.2f} {w / bw:6.2f} {c * 1000:7.1f} {c / fc:6.2f} {c / bc:6.2f}  "
              f"{','.join(mods) or '-'}")


if __name__ == "__main__":
    main()
