"""docs/course-example/: the key with variants, the two submissions, the
GitHub Actions and GitLab jobs and the Gradescope autograder, each run as a
course would run it.  Expected answers are derived by hand from
s = s1 + v1 τ + a τ²/2, v = v1 + a τ (notes §6, case 1) in the files' headers."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from tests.conftest import ROOT, run_cli

COURSE = ROOT / "docs" / "course-example"
G = 9.81


def _shim(tmp: Path) -> dict:
    """An environment whose `dyncli` runs this checkout (no network, no install)."""
    bin_ = tmp / "bin"
    bin_.mkdir(exist_ok=True)
    shim = bin_ / "dyncli"
    shim.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m dyncli "$@"\n')
    shim.chmod(0o755)
    env = dict(os.environ, PATH=f"{bin_}{os.pathsep}{os.environ['PATH']}", PYTHONPATH=str(ROOT), NO_COLOR="1")
    return env


def test_variants_of_the_two_students():
    from dyncli.check.problemfiles import ProblemFiles
    from dyncli.check.keyfile import read_key

    key = read_key(str(COURSE / "key.yaml"), ProblemFiles())
    assert not key.diagnostics
    assert key.variants.draw("alice@example.edu") == {"v0": 25.0, "a0": -3, "vb": 15.8}
    assert key.variants.draw("bob@example.edu") == {"v0": 15.5, "a0": -4, "vb": 10.7}


def test_key_grades_both_students(capsys):
    from dyncli.check.keycommand import run_key_check

    subs = [str(COURSE / "submissions" / f"{n}.yaml") for n in ("alice", "bob")]
    assert run_key_check(str(COURSE / "key.yaml"), subs, "json", reveal=True) == 1
    doc = json.loads(capsys.readouterr().out)
    a, b = ({q["id"]: q for q in s["questions"]} for s in doc["submissions"])
    # Alice: v0 = 25, a0 = -3, vb = 15.8
    assert a["1a"]["expected"] == pytest.approx(2 * 25 - 6) and a["1a"]["status"] == "correct"
    assert a["1b"]["expected"] == pytest.approx(25 / 3)
    assert a["1c"]["expected"] == pytest.approx(25 ** 2 / 6)
    assert a["1c"]["status"] == "partial" and a["1c"]["diagnosis"] == "factor_two" and a["1c"]["score"] == 1
    assert a["2a"]["expected"] == pytest.approx(15.8 ** 2 / (2 * G)) and a["2b"]["expected"] == pytest.approx(15.8 - 3 * G)
    # HW1.3 from s0 = the stopping distance: s = s0 + (6² - 2²)/(2·0.5)
    assert a["3"]["status"] == "carried" and a["3"]["expected"] == pytest.approx(25 ** 2 / 6 + (36 - 4) / 1.0)
    assert doc["submissions"][0]["score"] == 8
    # Bob: v0 = 15.5, a0 = -4, vb = 10.7; "2300 cm" is 23 m; a sign slip earns half; 3 is open
    assert b["1a"]["status"] == "correct" and b["1a"]["expected"] == pytest.approx(31 - 8)
    assert b["2a"]["expected"] == pytest.approx(10.7 ** 2 / (2 * G)) and b["2b"]["expected"] == pytest.approx(10.7 - 3 * G)
    assert b["2b"]["status"] == "partial" and b["2b"]["diagnosis"] == "sign" and b["2b"]["score"] == 0.5
    assert b["3"]["status"] == "missing" and doc["submissions"][1]["score"] == 7.5


def test_selftest_of_the_course_key():
    rc, out, err = run_cli("check", "--key", str(COURSE / "key.yaml"), "--selftest", "-n", "30")
    assert rc == 0, err
    assert "selftest passed: 31 variants" in out


def test_self_study_file():
    rc, out, err = run_cli("check", str(COURSE / "self-study.yaml"), "-f", "junit")
    assert rc == 1, err
    failed = [c for c in ET.fromstring(out).iter("testcase") if c.find("failure") is not None]
    assert [(c.get("name"), c.get("line")) for c in failed] == [("find.0.s", "19")]


def _instructor_repo(tmp: Path) -> Path:
    """The instructor's repository after the fetch step: the key, the problems and the
    submissions named by student id (the fetch step itself needs the network)."""
    repo = tmp / "repo"
    (repo / "submissions").mkdir(parents=True)
    for f in ("key.yaml", "hw1.yaml"):
        shutil.copy(COURSE / f, repo / f)
    for who in ("alice", "bob"):
        shutil.copy(COURSE / "submissions" / f"{who}.yaml", repo / "submissions" / f"{who}@example.edu.yaml")
    return repo


def _run(cmd: str, cwd: Path, env: dict) -> subprocess.CompletedProcess:
    return subprocess.run(["bash", "-c", cmd], cwd=cwd, env=env, capture_output=True, text=True, timeout=120)


def _check_reports(repo: Path) -> None:
    suites = {s.get("name"): s for s in ET.parse(repo / "reports" / "grades.xml").getroot().iter("testsuite")}
    assert len(suites) == 2 and all(s.get("tests") == "6" for s in suites.values())
    doc = json.loads((repo / "reports" / "grades.json").read_text())
    assert [(s["student"], s["score"]) for s in doc["submissions"]] == [("alice@example.edu", 8), ("bob@example.edu", 7.5)]


def test_ci_recipes_keep_the_key_out_of_students_jobs():
    """The key is graded in the instructor's repository: no recipe runs on a student's push or
    merge request, checks out another repository with a token, or hands a secret to dyncli."""
    import yaml

    for name in ("github-grade.yml", "gitlab-ci.yml"):
        text = (COURSE / "ci" / name).read_text()
        assert "KEY_REPO_TOKEN" not in text and "repository: me34010/hw1-key" not in text, name
        assert "SUBMISSIONS_TOKEN" in text and "contents/submission.yaml" in text or "files/submission.yaml" in text
        for line in text.splitlines():
            if "dyncli check" in line:
                assert "TOKEN" not in line and "secrets" not in line, line
    wf = yaml.safe_load((COURSE / "ci" / "github-grade.yml").read_text())
    triggers = wf[True] if True in wf else wf["on"]              # YAML 1.1 reads `on:` as true
    assert set(triggers) == {"workflow_dispatch", "schedule"}
    job = yaml.safe_load((COURSE / "ci" / "gitlab-ci.yml").read_text())["grade"]
    assert "schedule" in job["rules"][0]["if"] and "merge_request" not in json.dumps(job)


def test_github_actions_job(tmp_path):
    import yaml

    wf = yaml.safe_load((COURSE / "ci" / "github-grade.yml").read_text())
    steps = wf["jobs"]["grade"]["steps"]
    runs = [s["run"] for s in steps if "dyncli check" in s.get("run", "")]
    assert len(runs) == 3 and any("pip install ./dyncli-" in s.get("run", "") for s in steps)
    repo = _instructor_repo(tmp_path)
    env = dict(_shim(tmp_path))
    for cmd in runs:
        p = _run(cmd, repo, env)
        assert p.returncode == 0, p.stderr                  # `|| test $? -eq 1`: the steps pass
    _check_reports(repo)
    feedback = (repo / "reports" / "feedback" / "alice@example.edu.txt").read_text()
    assert "carried" in feedback and "expected" not in feedback


def test_gitlab_job(tmp_path):
    import yaml

    job = yaml.safe_load((COURSE / "ci" / "gitlab-ci.yml").read_text())["grade"]
    repo = _instructor_repo(tmp_path)
    lines = [line for line in job["script"] if line.startswith("dyncli check")]
    assert len(lines) == 2
    p = _run("set -e\n" + "\n".join(lines), repo, dict(_shim(tmp_path)))
    assert p.returncode == 0, p.stderr
    assert job["artifacts"]["reports"]["junit"] == "reports/grades.xml"
    _check_reports(repo)
    cases = {(c.get("file"), c.get("name")): c for c in ET.parse(repo / "reports" / "grades.xml").getroot().iter("testcase")}
    bob = "submissions/bob@example.edu.yaml"
    assert cases[(bob, "2b")].find("failure").get("type") == "partial"
    assert cases[(bob, "3")].find("failure").get("type") == "missing"


def _autograder(tmp: Path, submission: str | None, email: str = "alice@example.edu") -> Path:
    ag = tmp / "autograder"
    (ag / "source").mkdir(parents=True)
    (ag / "submission").mkdir()
    for f in ("key.yaml", "hw1.yaml"):
        shutil.copy(COURSE / f, ag / "source" / f)
    for f in ("setup.sh", "run_autograder"):
        shutil.copy(COURSE / "gradescope" / f, ag / "source" / f)
    if submission is not None:
        (ag / "submission" / "hw1-answers.yaml").write_text(submission)
    (ag / "submission_metadata.json").write_text(json.dumps({"users": [{"email": email, "name": "A"}]}))
    return ag


def test_gradescope_autograder(tmp_path):
    ag = _autograder(tmp_path, (COURSE / "submissions" / "alice.yaml").read_text())
    env = dict(_shim(tmp_path), AUTOGRADER_ROOT=str(ag))
    p = _run(f'bash "{ag}/source/setup.sh"', ag, env)       # dyncli importable: no install, no network
    assert p.returncode == 0 and "already installed" in p.stdout, p.stderr
    p = _run(f'bash "{ag}/source/run_autograder"', ag, env)
    assert p.returncode == 0, p.stderr
    doc = json.loads((ag / "results" / "results.json").read_text())
    tests = {t["name"].split(" ")[0]: t for t in doc["tests"]}
    # 2b is hidden: no top-level score (it would override the tests' total and count 2b before release)
    assert "score" not in doc and sum(t["score"] for t in doc["tests"]) == 8
    assert tests["1c"]["score"] == 1 and tests["1c"]["max_score"] == 2
    assert tests["2b"]["visibility"] == "after_published" and tests["1a"]["visibility"] == "visible"
    assert "expected" not in json.dumps(doc)
    # the hidden question is not summarised in the visible output
    assert doc["output"].startswith("5 of 5 visible answers") or "visible" in doc["output"]


@pytest.mark.parametrize("submission,email,needle", [
    (None, "alice@example.edu", "No submission found"),
    ("student: alice@example.edu\nanswers: {'1a': 39}\npoints: 100\n", "alice@example.edu", "not allowed"),
    ("student: bob@example.edu\nanswers: {'1a': 39}\n", "alice@example.edu", "does not match"),
])
def test_gradescope_autograder_bad_submissions(tmp_path, submission, email, needle):
    ag = _autograder(tmp_path, submission, email)
    env = dict(_shim(tmp_path), AUTOGRADER_ROOT=str(ag))
    p = _run(f'bash "{ag}/source/run_autograder"', ag, env)
    assert p.returncode == 0, p.stderr
    doc = json.loads((ag / "results" / "results.json").read_text())
    assert doc["score"] == 0 and needle in json.dumps(doc)
    if submission is not None:        # an invalid upload: its one-line error, every question 0 with it
        assert needle in doc["output"] and len(doc["tests"]) == 6
        assert all(t["score"] == 0 and needle in t["output"] for t in doc["tests"])


@pytest.mark.parametrize("named", [None, "answers.yaml"])
def test_gradescope_several_uploads(tmp_path, named):
    ag = _autograder(tmp_path, (COURSE / "submissions" / "alice.yaml").read_text())
    (ag / "submission" / "answers.yaml").write_text((COURSE / "submissions" / "alice.yaml").read_text())
    (ag / "submission" / "notes.txt").write_text("scratch")
    if named:
        with open(ag / "source" / "key.yaml", "a") as fh:
            fh.write(f"submission: {named}\n")
    env = dict(_shim(tmp_path), AUTOGRADER_ROOT=str(ag))
    p = _run(f'bash "{ag}/source/run_autograder"', ag, env)
    assert p.returncode == 0, p.stderr
    doc = json.loads((ag / "results" / "results.json").read_text())
    if named:                         # the key names the file to grade: the other uploads are ignored
        assert sum(t["score"] for t in doc["tests"]) == 8
    else:                             # two .yaml files: refused, naming them, every question 0
        assert doc["score"] == 0 and "answers.yaml, hw1-answers.yaml" in doc["output"]
        assert len(doc["tests"]) == 6 and all(t["score"] == 0 for t in doc["tests"])


def _fake_python(tmp: Path) -> Path:
    """A stand-in for Python >= 3.11 on a fresh image: `-m venv DIR` makes DIR/bin/pip (which
    records its arguments) and DIR/bin/dyncli (this checkout); no network, no install."""
    fake = tmp / "fakepy"
    fake.write_text(f"""#!/bin/sh
if [ "$1" = "-c" ]; then exit 0; fi
mkdir -p "$3/bin"
printf '#!/bin/sh\\necho "$@" > "%s/pip-args"\\n' "$3" > "$3/bin/pip"
printf '#!/bin/sh\\nPYTHONPATH="{ROOT}" exec "{sys.executable}" -m dyncli "$@"\\n' > "$3/bin/dyncli"
chmod +x "$3/bin/pip" "$3/bin/dyncli"
""")
    fake.chmod(0o755)
    return fake


def test_gradescope_setup_installs_the_bundled_wheel(tmp_path):
    # `pip3 install dyncli` cannot work (dyncli is not on PyPI): setup.sh installs the wheel zipped
    # with it into /autograder/dyncli-venv, and run_autograder uses that dyncli
    ag = _autograder(tmp_path, (COURSE / "submissions" / "alice.yaml").read_text())
    wheel = ag / "source" / "dyncli-0.1.0-py3-none-any.whl"
    wheel.write_bytes(b"")
    env = {"PATH": "/usr/bin:/bin", "AUTOGRADER_ROOT": str(ag), "DYNCLI_PYTHON": str(_fake_python(tmp_path)),
           "HOME": str(tmp_path)}
    p = _run(f'bash "{ag}/source/setup.sh"', ag, env)
    assert p.returncode == 0, p.stderr
    assert (ag / "dyncli-venv" / "pip-args").read_text().split() == ["install", "-q", str(wheel)]
    p = _run(f'bash "{ag}/source/run_autograder"', ag, env)
    assert p.returncode == 0, p.stderr
    assert sum(t["score"] for t in json.loads((ag / "results" / "results.json").read_text())["tests"]) == 8


def test_gradescope_setup_without_a_bundled_dyncli_says_what_to_zip(tmp_path):
    ag = _autograder(tmp_path, None)
    env = {"PATH": "/usr/bin:/bin", "AUTOGRADER_ROOT": str(ag), "DYNCLI_PYTHON": str(_fake_python(tmp_path)),
           "HOME": str(tmp_path)}
    p = _run(f'bash "{ag}/source/setup.sh"', ag, env)
    assert p.returncode == 1 and "no dyncli to install: zip the wheel" in p.stderr
    assert len(p.stderr.strip().splitlines()) == 1
