"""``dyncli variant KEY --student ID``: a student's problem set (docs/check.md).

* ``--format yaml``: ``{student, params: {name: value}, problems: [{title,
  type, problem (the mapping with this student's params), questions: [{id,
  answer, points, unit}]}]}``;
* ``--format markdown``: a sheet a student can read: the key's title, the
  student's numbers with units, each problem's title and its question ids;
* ``--template``: an empty submission (question ids, units, no values).

No value of any result is printed: the problems are solved only to name
the SI unit of an answer that has no ``unit`` in the key.
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


def unit_of(q, grader, student: str) -> str:
    """The unit a bare number is read in: the question's ``unit``, else the
    SI unit the solver reports for that result (units only, no values)."""
    if q.unit:
        return q.unit
    from dyncli.check.quantities import result_unit

    t = grader.truth(q, student)
    return "" if t.error else (result_unit(t.units, q.answer) or "")


def sheet(key, grader, student: str) -> dict:
    values = grader.params(student)
    problems = []
    for lp, qs in _groups(key):
        raw = grader.problem(qs[0], values, {}).raw
        carried = {q.carry[1]: q.carry[0] for q in qs if q.carry is not None}
        if carried and isinstance(raw, dict) and isinstance(raw.get("params"), dict):
            # the student fills in their own earlier answer, never the key's default
            raw = {**raw, "params": {**raw["params"], **{p: {"carried": src} for p, src in carried.items()}}}
        problems.append({"title": lp.title, "type": lp.type, "problem": raw,
                         "questions": [{"id": q.id, "answer": q.answer, "points": q.points,
                                        **({"unit": u} if (u := unit_of(q, grader, student)) else {}),
                                        **({"title": q.title} if q.title else {}),
                                        **({"carry_from": q.carry[0]} if q.carry else {})} for q in qs]})
    return {"student": student, "params": values, "problems": problems}


def render_yaml(doc: dict) -> str:
    import yaml

    from dyncli.check.key import plain

    return yaml.safe_dump(plain(doc), sort_keys=False, allow_unicode=True, width=100)


def render_markdown(key, doc: dict) -> str:
    units = {p.name: p.unit for p in key.variants.params} if key.variants is not None else {}
    lines = [f"# {oneline(key.title or 'Problem set')}", "", f"Student: `{oneline(doc['student'])}`", ""]
    if doc["params"]:
        lines += ["## Your numbers", "", "| parameter | value |", "|---|---|"]
        for n, v in doc["params"].items():
            lines.append(f"| `{n}` | {v:g}{' ' + units[n] if units.get(n) else ''} |")
        lines.append("")
    lines += ["## Problems", ""]
    for p in doc["problems"]:
        lines += [f"### {oneline(p['title'])}", ""]
        ps = p["problem"].get("params") if isinstance(p["problem"], dict) else None
        if isinstance(ps, dict) and ps:
            lines += ["Data: " + "; ".join(f"`{oneline(n)}` = {_datum(v, units.get(n))}" for n, v in ps.items()), ""]
        for q in p["questions"]:
            extra = f" ({oneline(q['title'])})" if q.get("title") else ""
            unit = f", in {oneline(q['unit'])}" if q.get("unit") else ""
            carry = f", uses your answer to `{oneline(q['carry_from'])}`" if q.get("carry_from") else ""
            pts = f"{q['points']:g} point{'s' if q['points'] != 1 else ''}"
            lines.append(f"- **{oneline(q['id'])}**{extra}: `{oneline(q['answer'])}`{unit}{carry}: {pts}")
        lines.append("")
    lines += ["Answer in a submission file (`dyncli variant KEY --student ID --template`): numbers, constant",
              "expressions (`\"2*pi\"`) or numbers with units (`\"12 m/s\"`).", ""]
    return "\n".join(lines)


def _datum(v: Any, unit: str | None) -> str:
    if isinstance(v, dict) and "carried" in v:
        return f"**your answer to {oneline(v['carried'])}**"
    if isinstance(v, float):
        return f"{v:g}{' ' + unit if unit else ''}"
    return oneline(v) + (f" {unit}" if unit and isinstance(v, int) else "")


def render_template(key, grader, student: str) -> str:
    lines = [f"# Submission for {oneline(key.title or 'this problem set')}: fill in every answer.",
             "# A value may be a number, a constant expression (\"2*pi\") or a number with a unit (\"12 m/s\");",
             "# a bare number is read in the unit shown.  Nothing else belongs in this file.",
             f"student: {json.dumps(student)}", "answers:"]
    for q in key.questions:
        title = q.title or (q.problem.title if q.problem is not None else "")
        u = unit_of(q, grader, student)
        unit = f"; unit {u}" if u else ""
        lines.append(f"  {json.dumps(q.id)}:      # {oneline(title)}: {oneline(q.answer)}{unit}; "
                     f"{q.points:g} point{'s' if q.points != 1 else ''}")
    return "\n".join(lines) + "\n"


def run_variant(key_name: str, student: str, fmt: str = "yaml", template: bool = False,
                root: str | None = None) -> int:
    from dyncli.check.keycommand import _err, load_key
    from dyncli.check.keymode import KeyGrader
    from dyncli.check.variants import VariantError

    if not student or oneline(student) != student or len(student) > 200:
        _err("--student must be the student's id (printable text, at most 200 characters)")
        return 2
    key, files = load_key(key_name, root)
    if key is None:
        return 2
    grader = KeyGrader(key, files)
    try:
        if template:
            sys.stdout.write(render_template(key, grader, student))
            return 0
        doc = sheet(key, grader, student)
    except VariantError as exc:
        _err(f"{key.file}: {exc}")
        return 2
    sys.stdout.write(render_yaml(doc) if fmt == "yaml" else render_markdown(key, doc))
    return 0
