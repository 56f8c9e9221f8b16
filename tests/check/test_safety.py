"""Problem references that may not be opened, bounded numbers and cheap
feedback (issue findings: ../ and absolute paths, symlinks, NUL bytes,
5,000-character names, points 1e308, 401-digit integers, 200 unknown keys,
--write-key on an euler problem)."""

from __future__ import annotations


import pytest

from tests.check.helpers import FIX, grade
from tests.check.keyhelpers import KEY, KEYDATA, check_json, write_sub
from tests.conftest import run_cli

BRAKE = (FIX / "brake.yaml").read_text()


def _one_error(r) -> str:
    errs = [str(c.error) for f in r.submissions for c in f.groups if c.error is not None] + \
        [str(d) for f in r.submissions for d in f.diagnostics]
    assert len(errs) == 1, errs
    assert "\n" not in errs[0]
    return errs[0]


@pytest.mark.parametrize("ref,needle", [
    ("/etc/passwd", "is absolute"),
    ("../outside.yaml", "leads outside"),
    ("sub/../../outside.yaml", "leads outside"),
    ("p\x00.yaml", "control character"),
    ("a" * 5000 + ".yaml", "too long"),
    ("notes.txt", "not a .yaml/.yml problem file"),
    ("missing.yaml", "not found"),
])
def test_problem_paths_are_fenced(tmp_path, ref, needle):
    d = tmp_path / "answers"
    d.mkdir()
    (tmp_path / "outside.yaml").write_text(BRAKE)
    text = "problem: " + __import__("json").dumps(ref) + "\nanswers: {find.1.t: 5}\n"
    r = grade(text, base=d)
    assert r.exit_code == 2
    msg = _one_error(r)
    assert needle in msg and len(msg) < 400


def test_symlink_out_of_the_folder_is_refused(tmp_path):
    d = tmp_path / "answers"
    d.mkdir()
    secret = tmp_path / "secret.yaml"
    secret.write_text("type: TOP-SECRET-VALUE\n")
    (d / "p.yaml").symlink_to(secret)
    r = grade("problem: p.yaml\nanswers: {find.1.t: 5}\n", base=d)
    msg = _one_error(r)
    assert "leads outside" in msg and "TOP-SECRET" not in msg


def test_content_of_a_non_problem_file_is_never_echoed(tmp_path):
    (tmp_path / "cfg.yaml").write_text("type: hunter2-password\nuser: root\n")
    (tmp_path / "bad.yaml").write_text("password: [unclosed hunter2\n")
    for name in ("cfg.yaml", "bad.yaml"):
        r = grade(f"problem: {name}\nanswers: {{find.1.t: 5}}\n", base=tmp_path)
        msg = _one_error(r)
        assert "is not a problem file" in msg and "hunter2" not in msg and "root" not in msg


def test_cli_nul_and_long_names_are_one_line_exit_2(tmp_path):
    for ref in ('"p\\0.yaml"', "a" * 5000 + ".yaml"):
        (tmp_path / "a.yaml").write_text(f"problem: {ref}\nanswers: {{case: 1}}\n")
        rc, out, err = run_cli("check", str(tmp_path / "a.yaml"), "-f", "json")
        assert rc == 2 and len(err.strip().splitlines()) == 2     # the message and the score line
        assert "Traceback" not in err and len(err) < 1000


def test_root_widens_the_fence(tmp_path):
    d = tmp_path / "answers"
    d.mkdir()
    (tmp_path / "p.yaml").write_text(BRAKE)
    (d / "a.yaml").write_text("problem: ../p.yaml\nanswers: {find.1.t: 5}\n")
    rc, _, err = run_cli("check", str(d / "a.yaml"))
    assert rc == 2 and "leads outside" in err
    rc, _, err = run_cli("check", str(d / "a.yaml"), "--root", str(tmp_path))
    assert rc == 0, err


@pytest.mark.parametrize("field", ["points", "rtol", "atol"])
@pytest.mark.parametrize("value", ["1e308", "9" * 401, "-1"])
def test_bounded_numbers_section5(field, value):
    spec = f"{{value: 32, {field}: {value}}}"
    r = grade(f"problem: brake.yaml\nanswers:\n  find.0.s: {spec}\n")
    a = next(a for f in r.submissions for a in f.questions)
    assert a.status == "invalid" and r.exit_code == 2 and "\n" not in a.message


def test_points_1e308_exit_2_in_json_and_gradescope(tmp_path):
    (tmp_path / "brake.yaml").write_text(BRAKE)
    (tmp_path / "a.yaml").write_text("problem: brake.yaml\nanswers:\n  find.0.s: {value: 32, points: 1e308}\n"
                                     "  find.1.t: {value: 5, points: " + "9" * 401 + "}\n")
    for fmt in ("json", "gradescope", "table"):
        rc, out, err = run_cli("check", str(tmp_path / "a.yaml"), "-f", fmt)
        assert rc == 2 and "points must be a number from 0 to" in err and "Traceback" not in err
        assert "inf" not in out and "nan" not in out


@pytest.mark.parametrize("extra", ["tolerance: {rtol: " + "9" * 401 + "}", "tolerance: {atol: 1e400}"])
def test_bounded_numbers_in_a_key(tmp_path, capsys, extra):
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "key.yaml").write_text(KEY.read_text().replace("tolerance: {rtol: 0.01}", extra))
    code, _, err = check_json(tmp_path / "key.yaml", [write_sub(tmp_path, "a.yaml", "x", {"1a": 1})], capsys)
    assert code == 2 and "tolerance" in err and "Traceback" not in err


def test_200_unknown_keys_are_cheap(monkeypatch):
    """Counted, not timed: the result paths are indexed once, and each unknown key is compared
    with at most MAX_HINT_CANDIDATES of them (not with all ~2,000)."""
    import dyncli.expr
    from dyncli.check import paths

    answers = "\n".join(f"  find.{i}.zz{i}: 1" for i in range(200))
    text = "problem: {type: rectilinear, a: -4, v1: 20, find: [" + ", ".join(f"{{t: {i + 1}}}" for i in range(400)) \
           + "]}\nanswers:\n" + answers + "\n"
    compared: list[int] = []
    indexed: list[int] = []
    hint, build = dyncli.expr.did_you_mean, paths.PathIndex.__init__
    monkeypatch.setattr(dyncli.expr, "did_you_mean", lambda key, cands: compared.append(len(cands)) or hint(key, cands))
    monkeypatch.setattr(paths.PathIndex, "__init__", lambda self, ps: indexed.append(len(ps)) or build(self, ps))
    r = grade(text)
    assert sum(1 for f in r.submissions for a in f.questions if a.status == "unknown") == 200
    assert len(compared) == 200 and max(compared) <= paths.MAX_HINT_CANDIDATES, compared[:5]
    assert len(indexed) == 1 and indexed[0] > 1000, indexed


def test_write_key_on_an_euler_problem_with_numpy_results():
    rc, out, err = run_cli("check", "--write-key", "problems/gyroscopic/euler-flipping-coin.yaml")
    assert rc == 0, err
    assert "problem: problems/gyroscopic/euler-flipping-coin.yaml" in out and "np.float64" not in out
    rc, out2, err = run_cli("check", "-", input=out)
    assert rc == 0, err


def test_key_file_problem_refs_are_fenced(tmp_path, capsys):
    (tmp_path / "k").mkdir()
    (tmp_path / "hw.yaml").write_text((KEYDATA / "hw.yaml").read_text())
    (tmp_path / "k" / "key.yaml").write_text(KEY.read_text().replace("problem: hw.yaml", "problem: ../hw.yaml"))
    sub = write_sub(tmp_path, "a.yaml", "x", {"1a": 1})
    code, _, err = check_json(tmp_path / "k" / "key.yaml", [sub], capsys)
    assert code == 2 and "leads outside" in err
    code, _, err = check_json(tmp_path / "k" / "key.yaml", [sub], capsys, root=str(tmp_path))
    assert code == 1, err


HOSTILE = "t\n::error file=x.yaml,line=1::forged\x1b]0;title\x07\r\u2028end"


@pytest.mark.parametrize("fmt", ["table", "junit", "github", "gradescope", "json"])
def test_section5_echoed_strings_stay_on_one_line(tmp_path, capsys, fmt):
    import json as _json

    from dyncli.check.command import run_check

    (tmp_path / "brake.yaml").write_text(BRAKE)
    (tmp_path / "a.yaml").write_text("title: " + _json.dumps(HOSTILE) + "\nproblem: brake.yaml\nanswers:\n  "
                                     + _json.dumps(HOSTILE) + ": 1\n  find.0.s: " + _json.dumps("3 " + HOSTILE) + "\n")
    capsys.readouterr()
    run_check([str(tmp_path / "a.yaml")], fmt)
    out, err = capsys.readouterr()
    for stream in (out, err):
        assert "\x1b" not in stream and "\x07" not in stream and "\r" not in stream and "\u2028" not in stream
        assert not any(line.startswith("::error file=x.yaml") for line in stream.splitlines())
