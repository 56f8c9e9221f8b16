"""Hypothesis fuzzing of whole problem documents, in-process.

For every registered type whose modules exist, documents are grown from the
type's example files and template: structurally mutated (hostile values,
random expressions, deleted and unknown keys), numerically perturbed (leaves
scaled by 1e±300, 0, −1, 1 ± 1e-12 ... so that most documents stay valid and
reach the solver), and damaged as text (BOM, CRLF, tabs, inserted
characters).  The only allowed outcomes are exit 0, 1 or 2 with a message,
JSON without NaN, a table that renders, and at most 2 s of CPU per document
(see ``harness.Report.check``).
"""

from __future__ import annotations

import random

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.fuzz.harness import (available_types, dump_yaml, mutate, mutate_text, perturb_numbers,
                                random_expression, run_document, seeds_by_type)

TYPES = available_types()
SEEDS = seeds_by_type()
FUZZ = settings(max_examples=30, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow])


def _document(t: str, seed: int) -> str:
    rnd = random.Random(seed)
    base = rnd.choice(SEEDS[t])
    mode = rnd.random()
    if mode < 0.45:
        doc = perturb_numbers(base, rnd)
    elif mode < 0.9:
        doc = mutate(base, rnd)
    else:
        doc = mutate(perturb_numbers(base, rnd), rnd)
    text = dump_yaml(doc, rnd)
    if rnd.random() < 0.15:
        text = mutate_text(text, rnd)
    return text


@pytest.mark.parametrize("type_name", [t for t in TYPES if t in SEEDS])
@FUZZ
@given(seed=st.integers(0, 2**32 - 1))
def test_mutated_documents(type_name, seed):
    text = _document(type_name, seed)
    run_document(text).check(text)


@FUZZ
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(2, 4))
def test_multi_problem_files(seed, n):
    """``problems: [...]`` mixing types, broken and valid entries."""
    rnd = random.Random(seed)
    items = []
    for _ in range(n):
        t = rnd.choice([t for t in TYPES if t in SEEDS])
        base = rnd.choice(SEEDS[t])
        items.append(perturb_numbers(base, rnd) if rnd.random() < 0.6 else mutate(base, rnd))
    text = dump_yaml({"problems": items}, rnd)
    rep = run_document(text)
    rep.check(text)


_EXPR_FIELDS = {
    # (type, field, template) — a field of each available type that takes a
    # free-variable expression or a constant expression
    "rectilinear": ("a", {"type": "rectilinear", "a": None, "v1": 1, "find": [{"t": 1}, {"v": 2}, {"s": 3}]}),
    "vibration": ("m", {"type": "vibration", "m": None, "k": 4, "zeta": 0.1, "at": [0, 1]}),
    "impact": ("e", {"type": "impact", "mA": 1, "mB": 2, "vA1": [1, 0, 0], "n": [1, 1, 0], "e": None}),
}


@pytest.mark.parametrize("type_name", [t for t in _EXPR_FIELDS if t in TYPES])
@FUZZ
@given(seed=st.integers(0, 2**32 - 1))
def test_random_expressions_in_fields(type_name, seed):
    rnd = random.Random(seed)
    field, template = _EXPR_FIELDS[type_name]
    doc = dict(template)
    doc[field] = random_expression(rnd)
    if rnd.random() < 0.3:
        doc["params"] = {"k": random_expression(rnd), "q": rnd.choice([1, -1, 0, 1e300, "k*2"])}
    text = dump_yaml(doc)
    run_document(text).check(text)
