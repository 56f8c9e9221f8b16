"""The δ/δt table machinery shared by ``rotating-frame`` and ``kinematics``.

A "frame table" lists vectors by their components on a rotating basis
(e'_1, e'_2, e'_3), one row per vector: ω, p, δp/δt, ω×p, ṗ (11.4), ...
The same functions build the numeric rows (numpy arrays, one entry per
requested time) and the symbolic rows (sympy objects, ``--symbolic``): the
vector algebra below works on any objects that support ``+ - *``.
"""

from __future__ import annotations

from typing import Any, Sequence

from dyncli.result import FrameTable

Vec = tuple  # (c1, c2, c3)

#: at most this many per-time tables are printed (the results hold every time)
MAX_TABLES = 12
#: CPU seconds sympy may take for the formula table of ``--symbolic`` (:mod:`dyncli.cputime`)
SYMBOLIC_SECONDS = 2.0


def symbolic_within(build, res, what: str):
    """``build()`` (the formula table: sympy's derivatives and printing) within SYMBOLIC_SECONDS of
    CPU; beyond it None, with a warning on ``res`` (the numeric tables and results are complete)."""
    from dyncli import cputime, symbolic

    symbolic.warm()                  # the limit measures sympy's work, not its first import
    try:
        with cputime.limit(SYMBOLIC_SECONDS):
            return build()
    except (cputime.CpuTimeout, RecursionError):
        res.warn(f"--symbolic: the formulas of {what} need more than {SYMBOLIC_SECONDS:g} s of CPU (sympy): "
                 "the formula table is left out; the numeric results and tables are complete")
        return None


def cross(a: Sequence, b: Sequence) -> Vec:
    """a × b from components on one right-handed orthonormal basis (11.8)."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def add(*vs: Sequence) -> Vec:
    out = tuple(vs[0])
    for v in vs[1:]:
        out = tuple(x + y for x, y in zip(out, v))
    return out


def scale(k: Any, v: Sequence) -> Vec:
    return tuple(k * x for x in v)


def numeric_tables(title: str, times, rows: list[tuple[str, Any]], basis, limit: int = MAX_TABLES) -> list[FrameTable]:
    """One :class:`FrameTable` per time.  ``rows``: (label, array of shape
    (3, N) or list of per-time vectors / None)."""
    out = []
    n = len(times)
    for i in range(min(n, limit)):
        tab_rows = []
        for label, comps in rows:
            c = comps[i] if isinstance(comps, list) else [float(comps[k][i]) for k in range(3)]
            tab_rows.append((label, list(c) if c is not None else ["—", "—", "—"]))
        note = None
        if i == limit - 1 and n > limit:
            note = f"(tables for the remaining {n - limit} times are omitted; the results list every time)"
        out.append(FrameTable(f"{title}, {_fmt_t(times[i])}", tab_rows, tuple(basis), note))
    return out


def _fmt_t(t) -> str:
    """"t = 1.5", or a label given instead of a time ("at the instant")."""
    return t if isinstance(t, str) else f"t = {t:.6g}"


# ---------------------------------------------------------------------------
# symbolic (sympy imported lazily: only --symbolic reaches here)


def exact_sym(e):
    """The sympy object of an expression with params kept as symbols and
    short decimals made exact (0.3 -> 3/10), so that simplification works on
    exact arithmetic; :func:`formula` prints them as decimals again."""
    from fractions import Fraction

    import sympy as sp

    from dyncli import symbolic

    x = symbolic.sym(e, keep_params=True)
    reps = {}
    for f in x.atoms(sp.Float):
        text = repr(float(f))
        if "e" not in text and len(text.replace("-", "").replace(".", "").strip("0")) <= 10:
            q = Fraction(text)
            reps[f] = sp.Rational(q.numerator, q.denominator)
    return x.xreplace(reps) if reps else x


#: entries with more operations than this skip trigsimp (it costs seconds on
#: long entries and, measured on 3-1-3 rotations, never shortened them)
SIMPLIFY_MAX_OPS = 40


def simplify_entry(x):
    """A bounded, readable simplification of one table entry (:func:`dyncli.symbolic.shortest`)."""
    from dyncli.symbolic import shortest

    return shortest(x, SIMPLIFY_MAX_OPS)


def _decimals(x):
    """Non-integer rational coefficients -> decimals (exponents kept exact)."""
    import sympy as sp

    if x.is_Rational and not x.is_Integer:
        return sp.Float(x, 15)
    if x.is_Pow:
        return sp.Pow(_decimals(x.base), x.exp)
    if x.args:
        return x.func(*[_decimals(a) for a in x.args])
    return x


def formula(x) -> str:
    """Compact one-line text of a sympy expression for a table cell."""
    import sympy as sp

    return sp.sstr(_decimals(sp.Integer(0) + x), full_prec=False)


def symbolic_table(title: str, rows: list[tuple[str, Sequence]], basis, note: str | None = None) -> FrameTable:
    tab_rows = [(label, [formula(simplify_entry(c)) for c in comps]) for label, comps in rows]
    return FrameTable(title, tab_rows, tuple(basis), note)
