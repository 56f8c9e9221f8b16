"""A particle reported at many times, and the Coulomb oscillator's stops (issue 29).

The CPU time (user + sys of a fresh process, ``time.process_time`` is not visible from the
parent: the children's rusage) of ``dyncli solve -f json FILE`` to /dev/null for

* a projectile with quadratic drag and a spring-and-damper oscillator, each with ``at:`` a
  list of 1e3, 1e4 and 1e5 times over its run, and the growth exponent of the CPU between the
  two largest (CPU ~ N^k); the goal is 2 s at 1e5 times;
* the Coulomb oscillator of the issue (spring and friction, 99 stops; goal: < 1 s).

Medians of interleaved rounds (a change in the machine's load hits every case alike).

Measured (1e5 times, the release before → this one interleaved, median of 5 on 2 CPUs, load
3–7): projectile 2.45 → 1.44 s, spring and damper 2.28 → 1.44 s (goal met); 1e4 times 0.45–0.47
→ 0.37–0.41 s; the Coulomb oscillator 0.52 → 0.49 s.  The numbers' text is now pydantic_core's
serializer's (repr's digits, ~0.15 s for the 2.7 million numbers, was ~0.9 s by repr; see
docs/accuracy.md, Cost).

Usage: python -m benchmarks.many_times [--runs 3] [--sizes 1000,10000,100000]
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))      # this checkout's dyncli
sys.path.insert(0, str(Path(__file__).resolve().parent))

GOAL_MANY, GOAL_COULOMB = 2.0, 1.0

CASES = {
    "projectile with drag": ("m: 0.5\nx0: [0, 0, 0]\nv0: [20, 15, 0]\nforces:\n  - {kind: gravity}\n"
                             "  - {kind: drag, c: 0.02}\nt_end: 2.5\n", 2.5),
    "spring and damper": ("m: 1.0\nx0: [1.5, 0, 0]\nv0: [0, 0.3, 0]\nforces:\n  - {kind: spring, k: 40, L: 1}\n"
                          "  - {kind: damper, c: 0.2}\nt_end: 10\n", 10.0),
}

COULOMB = """type: particle
m: 1.0
x0: [2.5, 0, 0]
forces:
  - {kind: spring, k: 104.0, L: 2}
  - {kind: friction, mu: 1, N: 0.26}
at: [31.07]
"""


def document(body: str, t_end: float, n: int) -> str:
    """The particle of ``body`` reported at ``n`` equally spaced times in [0, t_end]."""
    times = ", ".join(repr(t_end * k / (n - 1)) for k in range(n))
    return f"type: particle\n{body}at: [{times}]\n"


def cpu(files: list[str], runs: int) -> list[float]:
    """Median CPU seconds of ``dyncli solve -f json FILE`` per file, interleaved rounds."""
    import os
    import resource
    import subprocess

    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[1]), NO_COLOR="1")
    samples: list[list[float]] = [[] for _ in files]
    for _ in range(runs):
        for i, f in enumerate(files):
            r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([sys.executable, "-m", "dyncli", "solve", "-f", "json", f], env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
            samples[i].append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
    return [statistics.median(s) for s in samples]


def report(runs: int, sizes: list[int]) -> None:
    with tempfile.TemporaryDirectory(prefix="dyncli-many-") as d:
        files, keys = [], []
        for name, (body, t_end) in CASES.items():
            for n in sizes:
                f = Path(d) / f"{name.split()[0]}-{n}.yaml"
                f.write_text(document(body, t_end, n), encoding="utf-8")
                files.append(str(f))
                keys.append((name, n))
        f = Path(d) / "coulomb.yaml"
        f.write_text(COULOMB, encoding="utf-8")
        files.append(str(f))
        res = cpu(files, runs)
    print(f"a particle at many times, dyncli solve -f json to /dev/null (CPU s, median of {runs}; goal "
          f"{GOAL_MANY:g} s at 1e5 times)")
    for (name, n), c in zip(keys, res):
        print(f"   {name:<22} {n:>7} times  CPU {c:6.2f} s  {c / n * 1e6:8.1f} us/time"
              + (f"  /{GOAL_MANY:g} s goal {c / GOAL_MANY:5.2f}" if n >= 100_000 else ""))
    for name in CASES:
        (n1, c1), (n2, c2) = [(n, c) for (nm, n), c in zip(keys, res) if nm == name][-2:]
        k = math.log(c2 / c1) / math.log(n2 / n1) if c1 > 0 and c2 > 0 else float("nan")
        print(f"   {name:<22} growth {n1}->{n2}: CPU ~ N^{k:.2f}")
    print(f"   Coulomb oscillator (spring + friction, 99 stops)  CPU {res[-1]:6.2f} s  /{GOAL_COULOMB:g} s goal "
          f"{res[-1] / GOAL_COULOMB:5.2f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--sizes", default="1000,10000,100000")
    a = ap.parse_args()
    report(a.runs, [int(x) for x in a.sizes.split(",")])


if __name__ == "__main__":
    main()
