"""``--format latex``: the terminal view's tables for reports, with booktabs
rules and siunitx numbers and units (``\\num``, ``\\si``).

The output is a fragment to ``\\input`` into a document whose preamble has
``\\usepackage{booktabs}`` and ``\\usepackage{siunitx}``.  Every character
is ASCII: Greek letters, subscripts and accents of the notes' symbols
become math (``ωₙ`` -> ``$\\omega_{n}$``, ``θ̇`` -> ``$\\dot{\\theta}$``),
so pdfLaTeX compiles it without any input-encoding package.
"""

from __future__ import annotations

import re
import unicodedata

from dyncli.printable import tex_char
from dyncli.render.view import Grid, View

PREAMBLE = "\\usepackage{booktabs}\n\\usepackage{siunitx}\n"

_MATH = {"·": r"\cdot", "×": r"\times", "−": "-", "∞": r"\infty", "′": "'", "″": "''", "∥": r"\parallel",
         "→": r"\to", "∂": r"\partial", "√": r"\surd", "≈": r"\approx", "≤": r"\le", "≥": r"\ge",
         "°": r"^{\circ}", "ℓ": r"\ell", "∫": r"\int", "±": r"\pm", "∇": r"\nabla", "⊥": r"\perp",
         "Ω": r"\Omega", "µ": r"\mu", "⊗": r"\otimes", "∠": r"\angle", "½": r"\frac{1}{2}",
         "◀": r"\triangleleft", "ϕ": r"\phi", "ϑ": r"\vartheta", "ε": r"\varepsilon", "ς": r"\varsigma"}
_TEXT = {"§": r"\S{}", "—": "---", "–": "--", "…": r"\ldots{}", "‘": "`", "’": "'", "“": "``", "”": "''", "\u00a0": "~"}
_ACCENT = {"\u0307": r"\dot", "\u0308": r"\ddot", "\u0302": r"\hat", "\u0303": r"\tilde", "\u0304": r"\bar",
           "\u20d7": r"\vec"}
_NO_CAPITAL = set("ABEZHIKMNOPTX")   # Greek capitals that look Latin: no LaTeX command


def _greek(ch: str) -> str | None:
    name = unicodedata.name(ch, "")
    m = re.match(r"GREEK (SMALL|CAPITAL) LETTER (\w+)$", name)
    if not m:
        return None
    word = m.group(2).lower()
    if word == "omicron":
        return "o" if m.group(1) == "SMALL" else "O"
    if m.group(1) == "CAPITAL":
        latin = unicodedata.normalize("NFKD", ch)
        cap = word.capitalize()
        return {"Alpha": "A", "Beta": "B", "Epsilon": "E", "Zeta": "Z", "Eta": "H", "Iota": "I", "Kappa": "K",
                "Mu": "M", "Nu": "N", "Rho": "P", "Tau": "T", "Chi": "X"}.get(cap, "\\" + cap if latin else None)
    return "\\" + ("lambda" if word == "lamda" else word)


def _char(ch: str) -> tuple[bool, str]:
    """(is math, LaTeX) for one character."""
    if ord(ch) < 128:
        return False, tex_char(ch) or ch
    if ch in _TEXT:
        return False, _TEXT[ch]
    if ch in _MATH:
        return True, _MATH[ch]
    g = _greek(ch)
    if g:
        return True, g
    name = unicodedata.name(ch, "")
    base = unicodedata.normalize("NFKD", ch)
    if "SUBSCRIPT" in name or "SUPERSCRIPT" in name:
        inner = "".join(_char(c)[1] for c in base) if base != ch else "?"
        return True, ("_{" if "SUBSCRIPT" in name else "^{") + inner.replace("-", "-") + "}"
    if base != ch and all(ord(c) < 128 or unicodedata.combining(c) for c in base):
        return False, tex_text(base)
    return False, "?"


def tex_text(s: str) -> str:
    """Text-mode LaTeX for a string with the notes' symbols (ASCII only)."""
    tokens: list[list] = []   # [is_math, text]
    for ch in unicodedata.normalize("NFD", s):
        if ch in _ACCENT and tokens:
            is_math, prev = tokens[-1]
            tokens[-1] = [True, f"{_ACCENT[ch]}{{{prev if is_math or prev.isalpha() else prev}}}"]
            continue
        if unicodedata.combining(ch):
            continue
        is_math, text = _char(ch)
        if text.startswith(("_{", "^{")) and tokens and not tokens[-1][0] and tokens[-1][1][-1:].isalpha():
            last = tokens[-1][1]   # attach a subscript to the letter before it, inside the math
            tokens[-1][1] = last[:-1]
            tokens.append([True, last[-1]])
        tokens.append([is_math, text])
    out, math = [], []
    for is_math, text in tokens:
        if is_math:
            math.append(text)
            continue
        if math:
            out.append("$" + "".join(math) + "$")
            math = []
        out.append(text)
    if math:
        out.append("$" + "".join(math) + "$")
    return "".join(t for t in out if t)


_NUM = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?")


def tex_cell(cell: str) -> str:
    """A value cell: numbers as ``\\num``, vectors' numbers each, tensors as a
    stacked column; other text as :func:`tex_text`."""
    if "\n" in cell:
        return r"\begin{tabular}[t]{@{}l@{}}" + r" \\ ".join(tex_cell(r) for r in cell.split("\n")) + r"\end{tabular}"
    if _NUM.fullmatch(cell):
        return rf"\num{{{cell}}}"
    if cell.startswith("[") and cell.endswith("]") and all(_NUM.fullmatch(p.strip()) for p in cell[1:-1].split(",")):
        return "[" + ", ".join(rf"\num{{{p.strip()}}}" for p in cell[1:-1].split(",")) + "]"
    if cell == "—":
        return "---"
    return tex_text(cell)


def tex_unit(unit: str) -> str:
    """An SI unit text (``N·s/m``, ``kg·m²``) as siunitx's literal form."""
    if not unit:
        return ""
    u = unit.replace("·", ".").replace("²", "^2").replace("³", "^3").replace("⁻¹", "^-1").replace("°", r"\degree")
    if not re.fullmatch(r"[A-Za-z0-9./^\-\\ ()]+", u):
        return tex_text(unit)
    return rf"\si{{{u}}}"


def _head(g: Grid, i: int) -> str:
    unit = g.units[i] if i < len(g.units) else None
    return tex_text(g.columns[i]) + (f" [{tex_unit(unit)}]" if unit else "")


def grid(g: Grid) -> list[str]:
    out = [r"\begin{center}"]
    if g.title:
        out.append(rf"\textbf{{{tex_text(g.title)}}}\par\smallskip")
    out.append(r"\begin{tabular}{" + "".join(g.align) + "}")
    out.append(r"\toprule")
    out.append(" & ".join(_head(g, i) for i in range(len(g.columns))) + r" \\")
    out.append(r"\midrule")
    for k, row in enumerate(g.rows):
        cells = []
        for i, c in enumerate(row):
            if g.tex is not None and i == len(row) - 1:
                cells.append(rf"$\displaystyle {g.tex[k]}$")
            elif i == g.unit_column:
                cells.append(tex_unit(c))
            elif g.unit_column is not None and i < 2:   # result name, symbol
                cells.append(tex_text(c))
            else:
                cells.append(tex_cell(c))
        out.append(" & ".join(cells) + r" \\")
    out.append(r"\bottomrule")
    out.append(r"\end{tabular}")
    if g.note:
        out.append(rf"\par\smallskip\emph{{{tex_text(g.note)}}}")
    out.append(r"\end{center}")
    return out


def latex(views: list[View]) -> str:
    out = ["% dyncli tables: \\input this into a document whose preamble has",
           "% \\usepackage{booktabs} and \\usepackage{siunitx}", ""]
    for v in views:
        out.append(rf"\subsection*{{{tex_text(v.title)}}}")
        out.append(tex_text(v.kind) + r" \quad " + r" \quad ".join(tex_text(m) for m in v.meta) + r"\par")
        for g in v.grids:
            out += grid(g)
        for w in v.warnings:
            out.append(rf"\par\textbf{{warning:}} {tex_text(w)}")
        out.append("")
    return "\n".join(out) + "\n"
