"""Writes the course example's class: ``roster.csv`` (40 students: alice, bob
and 38 more) and ``class/*.yaml``, the submissions of 36 of the 38 (two
never submit) plus one of a student who is not on the roster.  Answers are
the true answers rounded to 3 or 4 significant figures, with the slips a
class makes (a sign, a factor 2, centimetres written as metres, a wrong
number, an open question), chosen by a fixed seed; question 3 is computed
from the student's own answer to 1c (carried forward).

Run once from the repository root (the files are committed):
``PYTHONPATH=. python docs/course-example/make_class.py``.
"""

from __future__ import annotations

import csv
import random
from pathlib import Path

HERE = Path(__file__).parent
NAMES = ("amara ben chloe dmitri elif farah gustav hana ines jonas kenji lena mateo nadia oskar priya quentin "
         "rosa sami tereza umar vera wen xavier yara zoltan anouk bruno carmen dario emeka fiona goran hugo "
         "ilse jamal kira luca").split()
NO_SUBMISSION = ("kira@example.edu", "luca@example.edu")
STRANGER = "eve@elsewhere.edu"


def _round(x: float, sig: int) -> float:
    return float(f"{x:.{sig}g}")


def answer(rng: random.Random, x: float) -> object:
    r = rng.random()
    if r < 0.70:
        return _round(x, rng.choice((3, 4)))
    if r < 0.78:
        return _round(-x, 3)
    if r < 0.85:
        return _round(2 * x, 3)
    if r < 0.89:
        return _round(100 * x, 3)              # centimetres written as metres
    if r < 0.92:
        return f"{_round(100 * x, 3):g} cm"     # the same, with its unit: correct
    if r < 0.97:
        return _round(x * rng.uniform(1.2, 1.8), 3)
    return None                               # left open


def main() -> None:
    from dyncli.check.keyfile import read_key
    from dyncli.check.grader import Grader, scalar
    from dyncli.check.problemfiles import ProblemFiles

    files = ProblemFiles()
    key = read_key(str(HERE / "key.yaml"), files)
    if key.diagnostics:
        raise SystemExit("\n".join(map(str, key.diagnostics)))
    grader = Grader(key, files)
    ids = [f"{n}@example.edu" for n in NAMES]
    with open(HERE / "roster.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["student", "name", "section"])
        for i, sid in enumerate(["alice@example.edu", "bob@example.edu"] + ids):
            w.writerow([sid, sid.split("@")[0].capitalize(), "A" if i % 2 == 0 else "B"])
    rng = random.Random(20261127)
    for sid in [i for i in ids if i not in NO_SUBMISSION] + [STRANGER]:
        lines = [f"student: {sid}", "answers:"]
        given: dict[str, object] = {}
        for q in key.questions:
            if q.carry is not None and isinstance(given.get(q.carry[0]), float):
                x = scalar(grader.truth(q, sid, carried=given[q.carry[0]]).value)   # from their own 1c
            else:
                x = scalar(grader.truth(q, sid).value)
            a = given[q.id] = answer(rng, x)
            if a is not None:
                lines.append(f'  "{q.id}": ' + (f'"{a}"' if isinstance(a, str) else f"{a!r}"))
        (HERE / "class" / f"{sid.split('@')[0]}.yaml").write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
