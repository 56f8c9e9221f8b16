"""The ``--symbolic`` tables of a scene: its equations (:mod:`.symbolic`) as the notes write
them (text) and as LaTeX (``--format latex``), with the symbols' values beside them."""

from __future__ import annotations

import re

from dyncli.result import Equations

_POW = {"2": "²", "3": "³", "4": "⁴"}


def text(x, S) -> str:
    """One-line text in the notes' letters: products by a space, squares as ², no ``*``."""
    import sympy as sp

    shown = (sp.Integer(0) + x).xreplace({s: sp.Symbol(S.text[s]) for s in S.text if s in getattr(x, "free_symbols", ())})
    out = sp.sstr(shown, full_prec=False)
    out = re.sub(r"\*\*(\d)\b", lambda m: _POW.get(m.group(1), "^" + m.group(1)), out)
    out = out.replace("**", "^").replace("*", " ")
    return re.sub(r"Abs\(([^()]*)\)", r"|\1|", out)


def tex(x, S) -> str:
    import sympy as sp

    return sp.latex(sp.Integer(0) + x, symbol_names={s: S.tex[s] for s in S.tex})


def _side(eq, S, fmt) -> str:
    """The left side; a sum of coefficient × acceleration printed coefficient first."""
    if not eq.terms:
        return fmt(eq.lhs, S)
    parts = []
    for c, x in eq.terms:
        cs = fmt(c, S)
        if c.is_Add or re.search(r".[+-]|/", cs.replace("e-", "")):    # a sum or a quotient, however sympy holds it
            cs = f"({cs})" if fmt is text else rf"\left({cs}\right)"
        parts.append(f"{cs} {fmt(x, S)}")
    return " + ".join(parts)


def _row(eq, S):
    rel_tex = {"=": "=", "≤": r"\le"}[eq.rel]
    return (eq.label, f"{_side(eq, S, text)} {eq.rel} {text(eq.rhs, S)}",
            f"{_side(eq, S, tex)} {rel_tex} {tex(eq.rhs, S)}")


def views(D) -> list[Equations]:
    """The tables: balance laws, laws of the loads, constraints, reduced equations, energy."""
    S = D.S
    out = [Equations("Balance laws (16.7, 29.5, 32.15), joint forces by name",
                     [_row(e, S) for e in D.balance] + [_row(e, S) for e in D.laws],
                     note="R: pin force on the first-named body; N, F: normal and friction forces; T: tension; "
                          "M: couple; every force on the body whose equation it is in")]
    if D.constraints:
        out.append(Equations("Constraint equations φ(q, t) = 0", [_row(e, S) for e in D.constraints]))
    if D.reduced:
        note = "; ".join(["projected onto the joints' null space: q̇ = N ṡ, N^T M N s̈ = N^T (f − M q̈ₚ)"] + D.notes)
        coords = ", ".join(S.text[D.C.q[j]] for j in D.independent)
        out.append(Equations(f"Reduced equation of motion in {coords} (the joint forces eliminated)",
                             [_row(e, S) for e in D.reduced + D.closure], note=note))
    elif D.notes:
        out[-1].note = "; ".join(D.notes)
    if D.energy:
        out.append(Equations("Energy integral (34.20)", [_row(e, S) for e in D.energy]))
    values = [("", f"{S.text[s]} = {v:.6g}", f"{tex(s, S)} = {v:.6g}") for s, v in S.values.items()]
    out.append(Equations("Values of the symbols (SI units)", values))
    return out
