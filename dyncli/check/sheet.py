"""``dyncli variant KEY --student ID``: a student's problem set (docs/check.md).

* ``--format yaml``: ``{student, params: {name: value}, problems: [{title,
  type, problem (the mapping with this student's params), questions: [{id,
  answer, points, unit}]}]}``;
* ``--format markdown`` / ``html``: a sheet a student can work from
  (dyncli.check.sheetview): the statement, every number each problem uses,
  each question with its unit, never a result path;
* ``--template``: an empty submission (question ids, units, no values).

No value of any result is printed: the problems are solved only to name
the SI unit of an answer that has no ``unit`` in the key (once per question
when many sheets are written: dyncli.check.sheets).
"""

from __future__ import annotations

import json
import sys
from typing import Any

from dyncli.check.safe import oneline


def _groups(key) -> list[tuple[Any, list]]:
    """Questions grouped by their problem, in key order."""
    out: list[tuple[Any, list]] = []
    for q in key.questions:
        for lp, qs in out:
            if lp is q.problem:
                qs.append(q)
                break
        else:
            out.append((q.problem, [q]))
    return out


DIMENSIONLESS = ("", "1", "dimensionless")


def unit_of(q, grader, student: str, cache: dict | None = None) -> str:
    """The unit a bare number is read in: the question's ``unit``, else the
    SI unit the solver reports for that result (units only, no values);
    "dimensionless" for a pure number, "" when unknown.  ``cache``: the
    unit of each question, the same for every variant (solved once)."""
    if q.unit:
        return q.unit
    if cache is not None and q.id in cache:
        return cache[q.id]
    from dyncli.check.quantities import result_unit

    from dyncli.check.statement import declared_dimensionless

    t = grader.truth(q, student)
    ru = None if t.error else result_unit(t.units, q.answer)
    if ru is None and not t.error and declared_dimensionless(q.problem.type if q.problem else None, q.answer):
        ru = ""
    u = "" if ru is None else "dimensionless" if ru.strip() in DIMENSIONLESS else ru
    if cache is not None:
        cache[q.id] = u
    return u


def sheet(key, grader, student: str, cache: dict | None = None) -> dict:
    """A student's sheet: per problem its statement, the numbers it uses
    (drawn and fixed) and its questions with their units; no result path
    is needed to read it (``answer`` is kept in YAML for scripts)."""
    from dyncli.check.statement import given_data, param_units, param_values, render_text

    values = grader.params(student)
    var_units = {p.name: p.unit for p in key.variants.params} if key.variants is not None else {}
    problems = []
    for lp, qs in _groups(key):
        raw = grader.problem(qs[0], values, {}).raw
        carried = {q.carry[1]: q.carry[0] for q in qs if q.carry is not None}
        own = op if isinstance(lp.raw, dict) and isinstance(op := lp.raw.get("params"), dict) else {}
        vals, punits = param_values(own, values, var_units, carried)
        punits = {**param_units(lp.type, lp.raw, own), **punits}
        if carried and isinstance(raw, dict) and isinstance(raw.get("params"), dict):
            # the student fills in their own earlier answer, never the key's default
            raw = {**raw, "params": {**raw["params"], **{p: {"carried": src} for p, src in carried.items()}}}
        data = [(n, _datum(vals[n], punits.get(n))) for n in own]
        data += given_data(lp.type, lp.raw if isinstance(lp.raw, dict) else {}, vals, punits)
        ptext = key.problem_text(lp)
        problems.append({"title": lp.title, "type": lp.type,
                         **({"text": render_text(ptext, vals)} if ptext else {}),
                         "data": [list(d) for d in data], "problem": raw,
                         "questions": [_question(q, grader, student, cache, vals) for q in qs]})
    return {"student": student, "params": values, "problems": problems}


def _question(q, grader, student: str, cache, vals: dict) -> dict:
    from dyncli.check.statement import render_text

    u = unit_of(q, grader, student, cache)
    return {"id": q.id, "answer": q.answer, "points": q.points, **({"unit": u} if u else {}),
            **({"title": q.title} if q.title else {}),
            **({"text": render_text(q.text, vals)} if q.text else {}),
            **({"carry_from": q.carry[0]} if q.carry else {})}


def _datum(v: Any, unit: str | None) -> str:
    if isinstance(v, dict) and "carried" in v:
        return f"your answer to {oneline(v['carried'])}"
    if isinstance(v, str):
        return oneline(v)
    return f"{v:g}{' ' + unit if unit else ''}"


def render_template(key, grader, student: str, cache: dict | None = None) -> str:
    lines = [f"# Submission for {oneline(key.title or 'this problem set')}: fill in every answer.",
             "# A value may be a number, a constant expression (\"2*pi\") or a number with a unit (\"12 m/s\");",
             "# a bare number is read in the unit shown.  Nothing else belongs in this file.",
             f"student: {json.dumps(student)}", "answers:"]
    for q in key.questions:
        title = q.title or (q.problem.title if q.problem is not None else "")
        u = unit_of(q, grader, student, cache)
        unit = f"; unit {u}" if u and u != "dimensionless" else "; a pure number" if u else ""
        lines.append(f"  {json.dumps(q.id)}:      # {oneline(title)}: {oneline(q.answer)}{unit}; "
                     f"{q.points:g} point{'s' if q.points != 1 else ''}")
    return "\n".join(lines) + "\n"


def run_variant(key_name: str, student: str, fmt: str = "yaml", template: bool = False,
                root: str | None = None) -> int:
    from dyncli.check.keycommand import load_key
    from dyncli.check.safe import say
    from dyncli.check.grader import Grader
    from dyncli.check.variants import VariantError

    if not student or oneline(student) != student or len(student) > 200:
        say("--student must be the student's id (printable text, at most 200 characters)")
        return 2
    key, files = load_key(key_name, root)
    if key is None:
        return 2
    grader = Grader(key, files)
    try:
        if template:
            sys.stdout.write(render_template(key, grader, student))
            return 0
        doc = sheet(key, grader, student)
    except VariantError as exc:
        say(f"{key.file}: {exc}")
        return 2
    from dyncli.check.sheetview import render

    sys.stdout.write(render(key, doc, fmt))
    return 0
