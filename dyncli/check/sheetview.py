"""A student's sheet as text (docs/check.md, "Sheets"): YAML, Markdown or a
self-contained printable HTML page.  Views only read the sheet built by
:func:`dyncli.check.sheet.sheet`; no result value and no result path
appears in Markdown or HTML.  Every user string is escaped: one printable
line in Markdown (:func:`~dyncli.check.safe.oneline`), ``html.escape`` in
HTML (no script, no external resource)."""

from __future__ import annotations

import re
from html import escape

from dyncli.check.safe import oneline


def render(key, doc: dict, fmt: str) -> str:
    if fmt == "yaml":
        return render_yaml(doc)
    return render_html(key, doc) if fmt == "html" else render_markdown(key, doc)


def render_yaml(doc: dict) -> str:
    import yaml

    from dyncli.check.key import plain

    return yaml.safe_dump(plain(doc), sort_keys=False, allow_unicode=True, width=100)


def _points(p: float) -> str:
    return f"{p:g} point{'s' if p != 1 else ''}"


def unit_phrase(u: str | None) -> str:
    """"in m", "dimensionless" (a pure number), or "" when unknown."""
    if not u:
        return ""
    return "dimensionless" if u == "dimensionless" else f"in {u}"


def _numbers(key, doc: dict) -> list[tuple[str, str]]:
    units = {p.name: p.unit for p in key.variants.params} if key.variants is not None else {}
    return [(n, f"{v:g}{' ' + units[n] if units.get(n) else ''}") for n, v in doc["params"].items()]


def _question_line(q: dict) -> tuple[str, str]:
    """(head, statement) of one question: "1a (2 points, in m)", its text or title."""
    extra = [_points(q["points"])]
    if unit_phrase(q.get("unit")):
        extra.append(unit_phrase(q.get("unit")))
    if q.get("carry_from"):
        extra.append(f"uses your answer to {q['carry_from']}")
    return f"{q['id']} ({', '.join(extra)})", q.get("text") or q.get("title") or ""


def render_markdown(key, doc: dict) -> str:
    lines = [f"# {oneline(key.title or 'Problem set')}", "", f"Student: `{oneline(doc['student'])}`", ""]
    nums = _numbers(key, doc)
    if nums:
        lines += ["## Your numbers", "", "| parameter | value |", "|---|---|"]
        lines += [f"| `{oneline(n)}` | {oneline(v)} |" for n, v in nums] + [""]
    lines += ["## Problems", ""]
    for i, p in enumerate(doc["problems"], 1):
        lines += [f"### {i}. {oneline(p['title'])}", ""]
        if p.get("text"):
            lines += [oneline(p["text"]), ""]
        if p["data"]:
            lines += ["Data: " + "; ".join(f"`{oneline(n)}` = {_bold_carry(oneline(v))}" for n, v in p["data"]), ""]
        for q in p["questions"]:
            head, text = _question_line(q)
            lines.append(f"- **{oneline(head)}**" + (f": {oneline(text)}" if text else ""))
        lines.append("")
    lines += ["Answer in a submission file (`dyncli variant KEY --student ID --template`): numbers, constant",
              "expressions (`\"2*pi\"`) or numbers with units (`\"12 m/s\"`).", ""]
    return "\n".join(lines)


def _bold_carry(v: str) -> str:
    return re.sub(r"your answer to (\S+)", r"**your answer to \1**", v)


_CSS = """body{font-family:system-ui,sans-serif;max-width:46em;margin:2em auto;line-height:1.45;color:#111}
h1{font-size:1.5em;margin-bottom:.2em}h2{font-size:1.2em;border-bottom:1px solid #999}
h3{font-size:1.05em}table{border-collapse:collapse}td,th{border:1px solid #999;padding:.2em .6em;text-align:left}
.data{color:#333}.q{margin:.4em 0}.answer{display:inline-block;min-width:12em;border-bottom:1px solid #666;
margin-left:.5em}@media print{body{margin:0;max-width:none}h3{break-after:avoid}.problem{break-inside:avoid}}"""


def render_html(key, doc: dict) -> str:
    """One self-contained page (inline CSS, no script, no external resource)."""
    e = escape
    title = key.title or "Problem set"
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           '<meta name="viewport" content="width=device-width, initial-scale=1">',
           f"<title>{e(title)}: {e(doc['student'])}</title><style>{_CSS}</style></head><body>",
           f"<h1>{e(title)}</h1>", f"<p>Student: <code>{e(doc['student'])}</code></p>"]
    nums = _numbers(key, doc)
    if nums:
        out.append("<h2>Your numbers</h2><table><tr><th>parameter</th><th>value</th></tr>")
        out += [f"<tr><td><code>{e(n)}</code></td><td>{e(v)}</td></tr>" for n, v in nums]
        out.append("</table>")
    out.append("<h2>Problems</h2>")
    for i, p in enumerate(doc["problems"], 1):
        out.append(f'<section class="problem"><h3>{i}. {e(p["title"])}</h3>')
        if p.get("text"):
            out.append(f"<p>{e(p['text'])}</p>")
        if p["data"]:
            out.append('<p class="data">Data: ' + "; ".join(
                e(f"{n} = {v}") for n, v in p["data"]) + "</p>")
        for q in p["questions"]:
            head, text = _question_line(q)
            out.append(f'<p class="q"><b>{e(head)}</b>' + (f": {e(text)}" if text else "")
                       + '<br>Answer:<span class="answer">&nbsp;</span></p>')
        out.append("</section>")
    out.append("<p>Answer in a submission file (<code>dyncli variant KEY --student ID --template</code>): numbers, "
               "constant expressions (<code>\"2*pi\"</code>) or numbers with units (<code>\"12 m/s\"</code>).</p>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"
