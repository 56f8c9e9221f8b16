"""The hostile corpus (tests/fuzz/corpus/): documents and expressions.

Every corpus document is loaded and solved in-process; every hostile
expression is put into a field of every available type.  The only outcomes
are exit 0, 1 or 2 with a message, in at most 2 s of CPU each.
"""

from __future__ import annotations

import random

import pytest

from tests.fuzz.harness import CORPUS, available_types, dump_yaml, run_document, seeds_by_type
from tests.fuzz.test_expressions import hostile_expressions

DOCS = sorted(p for p in CORPUS.iterdir() if p.suffix in (".yaml", ".bin"))


@pytest.mark.parametrize("path", DOCS, ids=[p.name for p in DOCS])
def test_corpus_document(path):
    run_document(path.read_bytes(), path.name).check(path.name)


def _leaves(x, prefix=()):
    if isinstance(x, dict):
        for k, v in x.items():
            if k not in ("type", "title"):
                yield from _leaves(v, prefix + (k,))
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from _leaves(v, prefix + (i,))
    else:
        yield prefix


@pytest.mark.parametrize("type_name", [t for t in available_types() if t in seeds_by_type()])
def test_hostile_expressions_in_every_type(type_name):
    """Each hostile expression replaces one leaf of the type's first example."""
    import copy

    base = seeds_by_type()[type_name][0]
    leaves = list(_leaves(base))
    rnd = random.Random(type_name)
    for text in hostile_expressions():
        doc = copy.deepcopy(base)
        path = rnd.choice(leaves)
        node = doc
        for p in path[:-1]:
            node = node[p]
        node[path[-1]] = text
        src = dump_yaml(doc)
        run_document(src).check(src)
