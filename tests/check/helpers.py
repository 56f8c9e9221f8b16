"""Helpers for the check tests: grade YAML text in-process."""

from __future__ import annotations

from pathlib import Path

from dyncli.check.answers import read_answer_file
from dyncli.check.engine import Checker, Report

FIX = Path(__file__).resolve().parent / "fixtures"


def grade(text: str, name: str = "answers.yaml", base: Path = FIX, checker: Checker | None = None,
          reveal: bool = False) -> Report:
    checker = checker or Checker(reveal=reveal)
    af = read_answer_file(name, text.encode(), base)
    report = Report(reveal=reveal)
    report.files.append(checker.check_file(af))
    report.solves = checker.solves
    return report


def statuses(report: Report) -> dict[str, str]:
    return {a.key: a.status for f in report.files for _, a in f.answers()}


def answer(report: Report, key: str):
    for f in report.files:
        for _, a in f.answers():
            if a.key == key:
                return a
    raise KeyError(key)
