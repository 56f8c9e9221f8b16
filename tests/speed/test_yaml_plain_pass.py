"""The cheap passes of the YAML reader (issue #31 item 2: one cheap pass per problem file).

A text in the block style every problem file is written in is read by its lines
(``yamlsafe._Lines``, no parser); a document of plain data (no anchor, alias or tag, text keys,
nothing to refuse) is built by ``yamlsafe._Plain`` straight from the parser's events; anything
else is handed, with the events read so far, to the general builder (``yamlsafe._one_pass``).
Checked here, with no timing:

* both passes build the same :class:`~dyncli.yamlsafe.Document` as the general builder —
  type-exact data, value and key positions, number texts, and the same runs of plain numbers —
  for every example of problems/, for texts made to reach each of their exits, and (the lines'
  reader) for thousands of examples changed at random (a reader of lines that accepts a text
  the parser refuses, or reads it otherwise, fails here);
* every example of problems/ is read by the lines' reader, and by the plain pass alone; a text
  the plain pass hands over is still parsed once (one loader made, no event read twice) with the
  general builder's values or errors.
"""

from __future__ import annotations

import pytest
import yaml

from tests.conftest import ROOT

EXAMPLES = sorted((ROOT / "problems").rglob("*.yaml"))


def _image(doc) -> tuple:
    """Everything a Document holds, type-exact (True, 1 and 1.0 apart)."""
    from dyncli.docmemo import fingerprint

    return (fingerprint(doc.data), dict(doc.pos.eager), {k: (list(v[0]), v[1]) for k, v in doc.pos.runs.items()},
            dict(doc.key_pos), dict(doc.text.eager), {k: (list(v[0]), v[1]) for k, v in doc.text.runs.items()})


def _lines(text: str):
    """The lines' reader's Document, or None when it leaves the text to the parser."""
    from dyncli import yamlsafe

    return yamlsafe._lines_pass(text)


def _general(text: str):
    from dyncli import yamlsafe

    return yamlsafe._one_pass(text, yaml.CSafeLoader)


def _plain(text: str):
    """The plain pass's Document, or None when it hands the text over."""
    from dyncli import yamlsafe

    ld = yaml.CSafeLoader(text)
    try:
        return yamlsafe._Plain(ld.get_event).document()
    except yamlsafe._Bail:
        return None
    finally:
        ld.dispose()


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_example_read_by_the_plain_pass_as_the_general_builder_reads_it(path):
    text = path.read_text(encoding="utf-8")
    doc, lines = _plain(text), _lines(text)
    assert doc is not None and lines is not None
    assert _image(doc) == _image(_general(text)) == _image(lines)


PLAIN = [
    "a: 1\nb: 1.5\nc: -0.0\nd: true\ne: null\nf: ~\ng: 'q'\nh: \"1\"\ni: 012\nj: 0x1F\nk: 1_000\nl: 1:30\n"
    "m: .inf\nn: -.inf\no: 1e5\np: 1.0e+5\nq: Yes\nr: off\ns: ''\nt:\n",
    "at: [0, -0, +5, 12, -0.0, +1.5, 1., 3.25e+3, 00.5, 1e5, 012, 0x1F, true, null, '9', 10, [1, 2.5], {a: 1}, 11]\n",
    "a:\n  - 1\n  - 2.5\n  - x\n  - - 3\n    - 4\n  - {b: [5, 6], c: {d: 7}}\nb: []\nc: {}\n",
    "problems:\n  - type: x\n    k: 1  # c\n  - type: y\n    params: {m: 2}\n    base: {amplitude: 0.01, omega: \"sqrt(k/m)\"}\n",
    "- 1\n- 2\n",
    "plain text\n",
    "---\n",
    "---\na: 1\n...\n",
    "é: ü\nt: |\n  two\n  lines\nu: >\n  folded\n  text\n",
    "'<<': 1\n\"quoted key\": 2\n",
]

HANDED_OVER = [
    "a: &x 1\nb: *x\n",                       # an anchor and an alias
    "a: !!str 5\n",                           # a tag
    "a: !!map {b: 1}\n",
    "1: a\n",                                 # a key that is not text
    "true: a\n",
    "~: a\n",
    "[1, 2]: a\n",                            # a key that is a list
    "a: 1\na: 2\n",                           # a duplicate key
    "<<: {a: 1}\n",                           # a merge key
    "<key>: 1\nb: 2\n",
    "a: 2017-01-01\n",                        # a date
    "a: !!float ''\n",
    "a: 1\n---\nb: 2\n",                      # several documents
    "",                                       # empty
    "# only a comment\n",
    "a: [1, &y 2, *y]\n",
    "a: [1, 2, !!int 3]\n",
    "a: " + "9" * 5000 + "\n",                # an int of more digits than Python reads
    "a: [1, " + "9" * 5000 + "]\n",
]


@pytest.mark.parametrize("text", PLAIN + HANDED_OVER)
def test_the_plain_pass_builds_what_the_general_builder_builds_or_hands_over(text):
    from dyncli import yamlsafe

    doc = _plain(text)
    try:
        general = _image(_general(text))
    except (yamlsafe.YamlError, yaml.YAMLError) as exc:
        assert doc is None and text in HANDED_OVER
        with pytest.raises(yamlsafe.YamlError):
            yamlsafe.load(text)
        assert str(exc)
        return
    if text in PLAIN:
        assert doc is not None
    if doc is not None:
        assert _image(doc) == general
    if _lines(text) is not None:
        assert _image(_lines(text)) == general
    assert _image(yamlsafe.load(text)) == general


@pytest.mark.parametrize("text", HANDED_OVER + [
    "a: 1\nb: [1, 2\n",                       # a syntax error met by the plain pass
    "a: &x 1\nb: [1, 2\n",                    # ... by the general builder, after the hand-over
    "a: 1\nb: !!float ''\nc: [1, 2\n",        # a refused value, then a syntax error: the syntax error
])
def test_a_handed_over_text_is_parsed_once_with_the_same_outcome(text, monkeypatch):
    from dyncli import yamlsafe

    def outcome():
        try:
            return _image(yamlsafe.load(text))
        except yamlsafe.YamlError as exc:
            return (exc.message, exc.line, exc.col)

    monkeypatch.setattr(yamlsafe, "_plain_pass", lambda t, loader: yamlsafe._one_pass(t, loader))
    expected = outcome()                      # the general builder alone
    monkeypatch.undo()
    made: list = []

    class Counting(yaml.CSafeLoader):
        def __init__(self, stream):
            made.append(stream)
            super().__init__(stream)

    monkeypatch.setattr(yaml, "CSafeLoader", Counting)
    assert outcome() == expected
    assert len(made) == 1


def test_the_caps_bite_as_before(monkeypatch):
    """Near a cap the plain pass hands over: the general builder's messages, at the same place."""
    from dyncli import yamlsafe

    monkeypatch.setattr(yamlsafe, "MAX_NODES", 50)
    for text in ("a: [" + ", ".join(["x"] * 60) + "]\n", "".join(f"k{i}: {i}\n" for i in range(30))):
        with pytest.raises(yamlsafe.YamlError) as err:
            yamlsafe.load(text)
        assert "more than 50 values" in err.value.message
    assert yamlsafe.load("".join(f"k{i}: {i}\n" for i in range(20))).data["k19"] == 19
    monkeypatch.setattr(yamlsafe, "MAX_DEPTH", 5)
    with pytest.raises(yamlsafe.YamlError) as err:
        yamlsafe.load("a: " + "[" * 8 + "]" * 8 + "\n")
    assert "nested" in err.value.message
    assert yamlsafe.load("a: [[1]]\n").data == {"a": [[1]]}


LINES = [
    "a: 1\nb: x y  # c\nc: 'q r'\nd: \"s # t\"\ne: [1, 2.5, x, 'y', [3], {f: 4}]\ng: {h: 1, i: [2, 3]}\n",
    "# c\n\nk:\n  - 1\n  - -2.5\n  - a: 2\n    b: 3\n  - [4]\n  - x\n  - 5\nl:\n  m: {n: -1}\n",
    "e: ü\nt: Frequency sweep, ζ = 0.2\nu: [1, ü, 2]\nv: a#b\nw: 1:30\nx: .inf\ny: 012\nz: 0x1F\n",
    "a: true\nb: ~\nc: null\nd: 1e5\ne: 1.0e+5\nf: -.5\ng: 1_000\nh: on\ni: ''\nj: []\nk: {}\n",
    "problems:\n  - type: x\n    k: 1\n  -   type: y\n      m: [0, 1, 2]\n",
]
NOT_LINES = [
    "a:\n  b\n",                               # a scalar on the next line
    "a: x\n  y\n",                              # a scalar over two lines
    "a:\nb: 1\n",                              # an empty value
    "a:\n- 1\n",                               # a list at its key's indent
    "a: [1,\n  2]\n",                           # a flow list over lines
    "a: \"x\\ty\"\n",                           # an escape
    "a: 'it''s'\n",
    "a: |\n  text\n",
    "a: &x 1\n",
    "a: !!str 1\n",
    "a: 1\n\tb: 2\n",
    "a: [1, 2,]\n",
    "a: {b: }\n",
    "a: b: c\n",
    "- 1\n",
    "1: a\n",
    "true: a\n",
    "a: 1\na: 2\n",
    "---\na: 1\n",
    "a: 2017-01-01\n",
    "a: [1]x\n",
    "a: x\n   # a comment more indented\nb: y\n",
]


@pytest.mark.parametrize("text", LINES + NOT_LINES)
def test_the_lines_reader_reads_the_block_style_as_the_parser_does_or_leaves_it(text):
    from dyncli import yamlsafe

    got = _lines(text)
    if text in LINES:
        assert got is not None
    try:
        general = _image(_general(text))
    except (yamlsafe.YamlError, yaml.YAMLError):
        assert got is None
        return
    if got is not None:
        assert _image(got) == general
    assert _image(yamlsafe.load(text)) == general


def test_the_lines_reader_on_examples_changed_at_random():
    """Examples (their comments dropped) with a few characters inserted, deleted or copied: each
    text the lines' reader reads, the general builder reads the same (never an error)."""
    import random

    from dyncli import yamlsafe

    rng = random.Random(31)
    texts = ["\n".join(ln for ln in p.read_text(encoding="utf-8").split("\n") if not ln.lstrip().startswith("#"))
             for p in EXAMPLES]
    pieces = list(" \n-:#,[]{}'\"&*!|>?%@`.0123456789eE+_xé~") + ["  ", "- ", ": ", " #", "\n  ", "true", "null",
                                                                    "1e5", "0x1F", "1:30", "2017-01-01"]
    read = 0
    for _ in range(3000):
        t = rng.choice(texts)
        for _ in range(rng.randint(1, 3)):
            i, op = rng.randrange(len(t) + 1), rng.random()
            if op < 0.4:
                t = t[:i] + rng.choice(pieces) + t[i:]
            elif op < 0.8:
                t = t[:i] + t[i + rng.randint(1, 3):]
            else:
                j = rng.randrange(len(t) + 1)
                t = t[:i] + t[j:j + 5] + t[i:]
        got = yamlsafe._lines_pass(t)
        if got is None:
            continue
        read += 1
        assert _image(got) == _image(_general(t)), repr(t)
    assert read > 500
