"""Benchmark: a class of 300 answer files over 10 problems, checked in ONE
`dyncli check` command.  Prints the wall time and the number of solves
(expected: 10, one per distinct problem), and, for comparison, the in-process
time with the solve cache disabled (one solve per answer file).

Run from the project root:  python benchmarks/check_batch.py [N_FILES] [N_PROBLEMS]
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def make_class(tmp: Path, n_files: int, n_problems: int) -> list[str]:
    # problems and answer files in one folder: a problem path must stay inside
    # the folder of the answer file that names it (or a --root)
    (tmp / "problems").mkdir()
    for j in range(n_problems):
        a, v1 = -(j + 1.0), 10.0 + 2 * j
        (tmp / "problems" / f"p{j}.yaml").write_text(
            f"type: rectilinear\ntitle: P{j}\na: {a}\nv1: {v1}\nfind: [{{t: 1}}, {{v: 0}}]\n")
    names = []
    for i in range(n_files):
        j = i % n_problems
        a, v1 = -(j + 1.0), 10.0 + 2 * j
        s1 = v1 + a / 2          # s at t = 1
        t0 = -v1 / a             # time of v = 0
        wrong = 1.1 if i % 7 == 0 else 1.0   # every 7th student slips
        f = tmp / "problems" / f"student{i:03d}.yaml"
        f.write_text(f"problem: p{j}.yaml\ntolerance: {{sigfigs: 3}}\nanswers:\n"
                     f"  find.0.s: {s1 * wrong:.4g}\n  find.0.v: {v1 + a:.4g}\n  find.1.t: {t0:.4g}\n")
        names.append(str(f.relative_to(tmp)))
    return names


def main() -> None:
    n_files = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    n_problems = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        names = make_class(tmp, n_files, n_problems)
        env = dict(os.environ, PYTHONPATH=str(ROOT))
        t0 = time.perf_counter()
        p = subprocess.run([sys.executable, "-m", "dyncli", "check", *names, "-f", "json"],
                           cwd=tmp, env=env, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        doc = json.loads(p.stdout)
        n_answers = sum(doc["counts"].values())
        print(f"one command: {n_files} answer files, {n_problems} problems, {n_answers} answers")
        print(f"  exit code {p.returncode}, score {doc['score']:g}/{doc['max_score']:g}")
        print(f"  solves: {doc['solves']}")
        print(f"  wall time: {wall:.2f} s (including interpreter start-up)")

        t0 = time.perf_counter()
        p1 = subprocess.run([sys.executable, "-m", "dyncli", "check", names[0], "-f", "json"],
                            cwd=tmp, env=env, capture_output=True, text=True)
        one = time.perf_counter() - t0
        print(f"  one answer file alone: {one:.2f} s -> 300 separate commands would take ~{one * n_files:.0f} s")

        # in-process: cache on vs off
        os.chdir(tmp)
        from dyncli.check.problemfiles import ProblemFiles
        from dyncli.check.selfstudy import SelfStudy as Checker

        class Uncached(ProblemFiles):
            def solve(self, lp, validated=True):
                from dyncli.loader import validate
                from dyncli.run import solve_one

                if not validated:
                    validate(lp)
                self.solves += 1
                return solve_one(lp, self.options)

        class NoCache(Checker):
            def __init__(self):
                super().__init__()
                self.files = Uncached()

        Checker().check_paths(names)   # warm imports and caches of the OS
        best: dict[str, tuple[float, int]] = {}
        for _ in range(3):
            for cls in (Checker, NoCache):
                c = cls()
                t0 = time.perf_counter()
                c.check_paths(names)
                dt = time.perf_counter() - t0
                key = "cached" if cls is Checker else "no cache"
                if key not in best or dt < best[key][0]:
                    best[key] = (dt, c.solves)
        for key, (dt, solves) in best.items():
            print(f"  in-process {key}: {dt * 1000:.0f} ms, {solves} solves (best of 3)")
        print("  (a case-1 solve is a closed form, so the cache saves little here; it matters for ODE routes)")


if __name__ == "__main__":
    main()
