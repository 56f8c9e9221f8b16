"""Every number a problem file's comments state is checked.

A problem file of ``problems/`` explains its worked example in its header comment, with the
values derived by hand from the notes' formulas.  Each derived value is restated in a
``# check:`` line (``# check[i]:`` for problem ``i`` of a ``problems:`` list) as
``name = value``, where ``name`` is either a dotted result path (``find.1.t``, ``vA2.0``) or
a constant expression in the expression language (an intermediate step of the derivation,
``3*cos(0.2) + sin(0.2) = 3.1388691``); ``phi1 [deg] = -28.1088`` states a result in degrees.
This module checks

* each result path against the solved file, to half a unit in the last stated digit (plus the
  documented envelope of a numerical route, 100 × rtol, docs/accuracy.md);
* each expression against its own value, evaluated by ``dyncli.expr`` (never by ``eval``);
* that no comment states a decimal number of four or more significant digits that no
  ``# check:`` line restates (a stated number is checked, or not stated; integers such as
  2700 kg/m³ or 6371 km are the problem's inputs);
* that docs/gallery.md states only numbers that the named file's ``# check:`` lines restate.
"""

from __future__ import annotations

import math
import re

import pytest

from tests.conftest import PROBLEMS, ROOT, lookup, solve_path

FILES = sorted(PROBLEMS.rglob("*.yaml"))
CHECK = re.compile(r"^#\s*check(?:\[(\d+)\])?:\s*(.*)$")
NUMBER = re.compile(r"(?<![\w.§(])[-−]?(?:\d+\.\d+|\d+)(?:e[-+]?\d+)?(?![\w.)])")


def _half_unit(tok: str) -> float:
    mant, _, exp = tok.lower().partition("e")
    decimals = len(mant.split(".")[1]) if "." in mant else 0
    return 0.5 * 10.0 ** (int(exp or 0) - decimals)


def _digits(tok: str) -> int:
    return len(re.sub(r"\D", "", tok.lower().split("e")[0]).lstrip("0"))


def checks(path):
    """[(problem index, name, stated token)] of a file's ``# check:`` lines."""
    out = []
    for ln in path.read_text(encoding="utf-8").splitlines():
        m = CHECK.match(ln.strip())
        if m:
            for entry in m.group(2).split(","):
                name, _, tok = entry.partition("=")
                out.append((int(m.group(1) or 0), name.strip(), tok.strip()))
    return out


def stated_numbers(path):
    """Numbers of four or more significant digits in comments other than ``# check:`` lines."""
    found = []
    for ln in path.read_text(encoding="utf-8").splitlines():
        if "#" not in ln or CHECK.match(ln.strip()):
            continue
        comment = ln.split("#", 1)[1]
        found += [t.replace("−", "-") for t in NUMBER.findall(comment)
                  if _digits(t) >= 4 and any(c in t for c in ".e")]    # not an integer input
    return found


@pytest.mark.parametrize("path", FILES, ids=[p.relative_to(ROOT).as_posix() for p in FILES])
def test_stated_values(path):
    from dyncli.expr import constant

    entries = checks(path)
    recs = solve_path(path) if entries else []
    bad = []
    for idx, name, tok in entries:
        stated = float(tok)
        rec = recs[idx]
        name, deg = (name[:-5].strip(), True) if name.endswith("[deg]") else (name, False)
        got = lookup(rec["results"], name)
        if deg and isinstance(got, (int, float)):
            got = math.degrees(got)
        if got is None:
            try:
                got = constant(name)
            except Exception as exc:             # noqa: BLE001 - reported below
                bad.append(f"[{idx}] {name}: neither a result nor a constant expression ({exc})")
                continue
            envelope = 0.0
        else:
            numerical = rec["method"] not in ("closed-form", "exact")
            envelope = 100 * 1e-10 * abs(stated) if numerical else 0.0
        if not isinstance(got, (int, float)) or abs(got - stated) > _half_unit(tok) * (1 + 1e-9) + envelope:
            bad.append(f"[{idx}] {name}: stated {tok}, the value is {got!r}")
    assert not bad, f"{path.name}: " + "; ".join(bad)


@pytest.mark.parametrize("path", FILES, ids=[p.relative_to(ROOT).as_posix() for p in FILES])
def test_every_stated_number_is_checked(path):
    checked = {tok for _i, _n, tok in checks(path)}
    checked |= {tok[1:] for tok in checked if tok.startswith("-")}     # a magnitude stated: -x is checked
    unchecked = sorted(set(stated_numbers(path)) - checked)
    assert not unchecked, (f"{path.name} states {unchecked} in a comment without a '# check:' line "
                           "restating it (check it, or do not state it)")


def _gallery_rows():
    rows = []
    for ln in (ROOT / "docs" / "gallery.md").read_text(encoding="utf-8").splitlines():
        m = re.search(r"`(problems/[\w/.-]+\.yaml)`", ln)
        if m and ln.startswith("|"):
            rows.append((m.group(1), ln))
    return rows


def test_gallery_states_only_checked_numbers():
    """A number the gallery page states about an example is one its file's '# check:' lines
    restate (to the digits the page gives)."""
    assert _gallery_rows()
    bad = []
    for rel, row in _gallery_rows():
        text = row.split("|")[2] if row.count("|") >= 3 else row
        toks = [t.replace("−", "-") for t in NUMBER.findall(text.replace("−", "-"))
                if _digits(t) >= 4 and any(c in t for c in ".e")]
        if not toks:
            continue
        values = [float(tok) for _i, _n, tok in checks(ROOT / rel)]
        for t in toks:
            if not any(abs(v - float(t)) <= _half_unit(t) * (1 + 1e-9) for v in values):
                bad.append(f"{rel}: {t}")
    assert not bad, "docs/gallery.md states numbers no '# check:' line restates: " + ", ".join(bad)
