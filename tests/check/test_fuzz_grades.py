"""Standing fuzz test: no grade above what the values earn.

A submission whose answers are all one arbitrary number x (any magnitude,
either sign, bare or with a unit) scores nothing on a question unless x is
that question's right answer — within its tolerance, or one of the slips the
key gives partial credit for.  In particular no question is ever `carried`:
copying one number everywhere shows no physics.  The right answers are the
closed forms of notes §6 case 1, by hand (tests/check/keyhelpers.truth and
the course example's header), never the grader's own solves.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.check.keyhelpers import KEY, params_of, truth

COURSE = Path(__file__).resolve().parents[2] / "docs" / "course-example"
SLIPS = [1.0, -1.0, 2.0, 0.5] + [10.0 ** k for k in range(-9, 10) if k]

numbers = st.one_of(
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e300, max_value=1e300),
    st.builds(lambda m, e: m * 10.0 ** e, st.floats(-10, 10), st.integers(-12, 12)),
    st.integers(-10 ** 6, 10 ** 6).map(float))
ids = st.text(alphabet="abcdefghijklmnopqrstuvwxyz0123456789@._-", min_size=1, max_size=20)


def _course_truth(student: str) -> dict[str, float]:
    p = params_of(student, COURSE / "key.yaml")
    v0, a0, vb = p["v0"], p["a0"], p["vb"]
    stop = v0 ** 2 / (2 * -a0)
    return {"1a": 2 * v0 + a0 * 2, "1b": v0 / -a0, "1c": stop, "2a": vb ** 2 / (2 * 9.81),
            "2b": vb - 9.81 * 3, "3": stop + (36 - 4) / 1.0}


def _earned(x: float, t: float, rel: float) -> bool:
    """Whether x is t, or a slip of t, within ``rel`` (generous: a superset of what grading accepts)."""
    return any(math.isclose(x, t * f, rel_tol=rel, abs_tol=1e-12) for f in SLIPS)


def _grade(key: Path, student: str, text: str):
    from dyncli.check.keyfile import read_key
    from dyncli.check.grader import Grader
    from dyncli.check.problemfiles import ProblemFiles
    from dyncli.check.submission import read_submission

    files = ProblemFiles()
    k = read_key(str(key), files)
    assert not k.diagnostics
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "s.yaml"
        p.write_text(text)
        return Grader(k, files).grade(read_submission(str(p)))


def _all_one(ids_: list[str], value: str, student: str) -> str:
    return f"student: {student!r}\nanswers:\n" + "".join(f"  {q!r}: {value}\n" for q in ids_)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(x=numbers, student=ids, unit=st.sampled_from(["", " m", " km", " mm"]))
def test_course_example_one_number_everywhere(x, student, unit):
    ref = _course_truth(student)
    value = f'"{x!r}{unit}"' if unit else repr(x)
    si = x * {"": 1.0, " m": 1.0, " km": 1e3, " mm": 1e-3}[unit]
    sr = _grade(COURSE / "key.yaml", student, _all_one(list(ref), value, student))
    assert not sr.diagnostics
    for q in sr.questions:
        assert q.status != "carried", (q.id, x, q.message)
        if q.score > 0:
            assert _earned(si, ref[q.id], 0.02), (q.id, x, ref[q.id], q.status)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(x=numbers, student=ids)
def test_test_key_one_number_everywhere(x, student):
    p = params_of(student)
    ref = truth(p["v0"], p["a0"])
    # 1d is answered in mm (the key's unit): truth() gives it in mm, as a bare number is read
    sr = _grade(KEY, student, _all_one(list(ref), repr(x), student))
    for q in sr.questions:
        assert q.status != "carried", (q.id, x, q.message)
        if q.score > 0:
            assert _earned(x, ref[q.id], 0.02), (q.id, x, ref[q.id], q.status)
