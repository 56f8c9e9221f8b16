"""Helpers for the check tests: grade YAML text in-process."""

from __future__ import annotations

from pathlib import Path

from dyncli.check.answers import read_answer_file
from dyncli.check.results import Report
from dyncli.check.selfstudy import SelfStudy

FIX = Path(__file__).resolve().parent / "fixtures"


def grade(text: str, name: str = "answers.yaml", base: Path = FIX, checker: SelfStudy | None = None,
          reveal: bool = False) -> Report:
    checker = checker or SelfStudy(reveal=reveal)
    af = read_answer_file(name, text.encode(), base)
    report = Report(reveal=reveal)
    report.submissions.append(checker.check_file(af))
    report.solves = checker.solves
    return report


def statuses(report: Report) -> dict[str, str]:
    return {a.answer: a.status for f in report.submissions for a in f.questions}


def answer(report: Report, key: str):
    for f in report.submissions:
        for a in f.questions:
            if a.answer == key:
                return a
    raise KeyError(key)
