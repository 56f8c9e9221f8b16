"""``--format markdown`` and a solution's notebook view (``_repr_markdown_``,
``_repr_html_``): the terminal view's tables (:mod:`dyncli.render.view`)."""

from __future__ import annotations

from dyncli import printable as esc
from dyncli.render.view import Grid, View


def _head(g: Grid, i: int) -> str:
    unit = g.units[i] if i < len(g.units) else None
    return g.columns[i] + (f" [{unit}]" if unit else "")


def _md_cell(text: str) -> str:
    return esc.markdown(text, breaks=True) or " "


def markdown(views: list[View]) -> str:
    out: list[str] = []
    for v in views:
        out.append(f"### {esc.markdown(v.title)}")
        out.append("")
        out.append(f"*{_md_cell(v.kind)}* · " + " · ".join(_md_cell(m) for m in v.meta))
        for g in v.grids:
            out.append("")
            if g.title:
                out.append(f"**{_md_cell(g.title)}**")
                out.append("")
            out.append("| " + " | ".join(_md_cell(_head(g, i)) for i in range(len(g.columns))) + " |")
            out.append("|" + "|".join("---:" if a == "r" else "---" for a in g.align) + "|")
            out += ["| " + " | ".join(_md_cell(c) for c in row) + " |" for row in g.rows]
            if g.note:
                out += ["", f"*{_md_cell(g.note)}*"]
        for w in v.warnings:
            out += ["", f"> **warning:** {esc.markdown(w)}"]
        out.append("")
    return "\n".join(out)


def _h(text: str) -> str:
    return esc.html(text, breaks=True)


def html_view(views: list[View]) -> str:
    out: list[str] = []
    for v in views:
        out.append(f"<div class=\"dyncli-solution\"><p><strong>{esc.html(v.title)}</strong> · {_h(v.kind)}<br>"
                   f"<small>{_h('   '.join(v.meta))}</small></p>")
        for g in v.grids:
            cap = f"<caption>{_h(g.title)}</caption>" if g.title else ""
            head = "".join(f"<th>{_h(_head(g, i))}</th>" for i in range(len(g.columns)))
            body = "".join("<tr>" + "".join(f"<td style=\"text-align:{'right' if a == 'r' else 'left'}\">{_h(c)}</td>"
                                            for c, a in zip(row, g.align)) + "</tr>" for row in g.rows)
            note = f"<p><em>{_h(g.note)}</em></p>" if g.note else ""
            out.append(f"<table>{cap}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>{note}")
        out += [f"<p><strong>warning:</strong> {esc.html(w)}</p>" for w in v.warnings]
        out.append("</div>")
    return "\n".join(out)
