"""Reading the instructor's key (docs/check.md) with source positions.

```yaml
title: Homework 1
tolerance: {rtol: 0.01}
variants: {salt: "...", params: {v1: {uniform: [15, 25], step: 0.5}}, require: "v1 < 24"}
questions:
  - {id: "1a", problem: hw1.yaml, index: 0, answer: find.0.s, points: 2,
     tolerance: {sigfigs: 3}, unit: m, partial: {sign: 0.5}, carry: {from: "0", param: v1},
     visible: true, title: "stopping distance"}
```

Every structural problem is a :class:`~dyncli.loader.Diagnostic` (exit 2):
unknown fields (with "did you mean"), duplicate ids, a carry from an
unknown question or in a cycle, a variant parameter no problem uses, a
carry parameter the problem does not have, bad numbers.
"""

from __future__ import annotations

import keyword
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from dyncli.check.tolerance import FieldError, Tolerance, parse_tolerance, read_points
from dyncli.check.diagnose import SLIPS
from dyncli.check.safe import oneline, shown, yaml_diagnostic
from dyncli.expr import did_you_mean
from dyncli.loader import Diagnostic, LoadedProblem, validate

TOP_KEYS = ("title", "tolerance", "variants", "questions", "submission", "problems")
Q_KEYS = ("id", "problem", "index", "answer", "points", "tolerance", "unit", "partial", "carry", "visible", "title",
          "feedback", "text")
FEEDBACK_KEYS = ("correct", "carried", "partial", "wrong", "missing", "invalid") + SLIPS
MAX_FEEDBACK = 1000
MAX_ID = 64
MAX_QUESTIONS = 1000


@dataclass(frozen=True)
class Policy:
    """Where graded work and self-study grade differently (docs/check.md), in
    one place.  Graded work (the default): the key's problems are the
    instructor's (a solver's message may quote a true answer: shown only with
    --reveal), a result path not in the results is the key's error, a true
    number zero up to round-off is graded as 0, and a null is no answer.
    Self-study: the student's own problem and paths, graded as written."""

    secret: bool = True              # a solver's message only with --reveal
    not_solved: str = "the key's problem could not be solved for this variant"
    unknown_path: bool = False       # a path not in the results: status 'unknown' with "did you mean"
    snap_zeros: bool = True          # round-off zeros graded as 0 (dyncli.check.zeros)
    null_is_answer: bool = False     # a null compares (matches an expected null), else 'not answered'


GRADED = Policy()
SELF_STUDY = Policy(secret=False, not_solved="the problem could not be solved", unknown_path=True,
                    snap_zeros=False, null_is_answer=True)


@dataclass
class Question:
    id: str
    answer: str = ""
    problem_ref: str | None = None
    problem_inline: dict | None = None
    index: int | None = None
    points: float = 1.0
    tol: Tolerance = field(default_factory=Tolerance)
    unit: str | None = None
    partial: dict[str, float] = field(default_factory=dict)
    carry: tuple[str, str] | None = None       # (from question id, param name)
    visible: bool = True
    title: str | None = None
    feedback: dict[str, str] = field(default_factory=dict)   # status or slip -> the instructor's text
    text: Any = None                           # the statement: parsed pieces (dyncli.check.statement)
    prefix: tuple = ()
    problem: LoadedProblem | None = None       # the key's problem (before variants)
    error: Diagnostic | None = None            # self-study: the problem could not be read
    invalid: str | None = None                 # self-study: the answer's own entry cannot be read


@dataclass
class Key:
    file: str
    base_dir: Path
    title: str | None = None
    tol: Tolerance = field(default_factory=Tolerance)
    variants: Any = None                       # dyncli.check.variants.Variants or None
    questions: list[Question] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    submission: str | None = None              # the file name a Gradescope upload must have
    texts: dict = field(default_factory=dict)  # (problem file, index) -> parsed statement of that problem
    policy: Policy = GRADED

    def problem_text(self, lp) -> Any:
        return self.texts.get((lp.file, lp.index)) if lp is not None else None

    def question(self, qid: str) -> Question | None:
        return next((q for q in self.questions if q.id == qid), None)

    @property
    def max_score(self) -> float:
        return sum(q.points for q in self.questions)


def read_key(name: str, files) -> Key:
    """Read and check the key file ``name``; ``files`` is the command's
    :class:`~dyncli.check.problemfiles.ProblemFiles` (problems read once)."""
    from dyncli.errors import InputError
    from dyncli.loader import read_source
    from dyncli.yamlsafe import YamlError, load as yaml_load

    base = Path(name).parent if name != "-" else Path.cwd()
    key = Key(name, base)
    try:
        display, data = read_source(name)
        doc = yaml_load(data)
    except YamlError as exc:
        key.diagnostics.append(yaml_diagnostic(name, exc, "a key (a mapping with 'questions: [...]')"))
        return key
    except InputError as exc:
        key.diagnostics.append(Diagnostic(name, None, None, None, exc.message.removeprefix(f"{name}: ")))
        return key
    key.file = display
    _Reader(key, doc, files).read()
    return key


class _Reader:
    def __init__(self, key: Key, doc, files):
        self.key, self.doc, self.files = key, doc, files
        self.rejected: set[str] = set()     # ids of questions already reported invalid

    def diag(self, path: tuple, message: str, key: bool = True) -> None:
        pos = self.doc.locate(path) if key else (self.doc.value_pos(path) or self.doc.locate(path))
        line, col = pos if pos else (None, None)
        dotted = ".".join(oneline(p) for p in path) or None
        self.key.diagnostics.append(Diagnostic(self.key.file, line, col, dotted, message))

    def read(self) -> None:
        data = self.doc.data
        if not isinstance(data, dict) or "questions" not in data:
            self.diag((), "expected a key: a mapping with 'questions: [...]' (and optional title, tolerance, variants)")
            return
        for k in data:
            if k not in TOP_KEYS:
                self.diag((k,), f"unknown key '{shown(k)}'{did_you_mean(str(k), TOP_KEYS)}; a key holds "
                                f"{', '.join(TOP_KEYS)}")
        if isinstance(data.get("title"), str):
            self.key.title = data["title"]
        if "submission" in data:
            sub = data["submission"]
            if not isinstance(sub, str) or not sub.strip() or "/" in sub or "\\" in sub or len(sub) > 200 \
                    or oneline(sub) != sub:
                self.diag(("submission",), "submission must be a file name such as answers.yaml (no folder)", key=False)
            else:
                self.key.submission = sub.strip()
        if "tolerance" in data:
            try:
                self.key.tol = parse_tolerance(data["tolerance"], Tolerance(), ("tolerance",))
            except FieldError as exc:
                self.diag(exc.path, exc.message, exc.key)
        items = data["questions"]
        if not isinstance(items, list) or not items or len(items) > MAX_QUESTIONS:
            self.diag(("questions",), f"expected a list of 1 to {MAX_QUESTIONS} questions "
                                      "(mappings with id, problem and answer)")
            return
        for i, item in enumerate(items):
            self.question(item, ("questions", i))
        self.check_ids()
        if "problems" in data:
            self.problem_texts(data["problems"])
        if "variants" in data:
            from dyncli.check.variants import read_variants

            self.key.variants = read_variants(data["variants"], ("variants",), self.diag)
        if not self.key.diagnostics:
            self.check_params()

    # -- one question -------------------------------------------------------
    def question(self, item: Any, path: tuple) -> None:
        if not isinstance(item, dict):
            self.diag(path, "expected a question: a mapping with id, problem and answer")
            return
        q = Question("", prefix=path)
        ok = True
        for k in item:
            if k not in Q_KEYS:
                self.diag(path + (k,), f"unknown key '{shown(k)}'{did_you_mean(str(k), Q_KEYS)}; "
                                       f"known: {', '.join(Q_KEYS)}")
                ok = False
        for need in ("id", "problem", "answer"):
            if need not in item:
                self.diag(path, f"missing '{need}'")
                ok = False
        try:
            self.fields(q, item, path)
        except FieldError as exc:
            self.diag(exc.path, exc.message, exc.key)
            ok = False
        if ok and q.problem is not None:
            if q.problem.model is None and q.problem.error is None:
                validate(q.problem)           # an inline problem (files are validated when read)
            if q.problem.error is not None:  # the key's own problem is invalid: say where
                if q.problem.error not in self.key.diagnostics:
                    self.key.diagnostics.append(q.problem.error)
                ok = False
        if ok:
            self.key.questions.append(q)
        elif q.id:
            self.rejected.add(q.id)

    def fields(self, q: Question, item: dict, path: tuple) -> None:
        from dyncli.check.submission import as_written

        qid = as_written(self.doc, path + ("id",), item.get("id"))
        if isinstance(qid, bool) or not isinstance(qid, (str, int)) or not str(qid).strip() \
                or len(str(qid)) > MAX_ID or oneline(qid) != str(qid):
            raise FieldError(path + ("id",), f"id must be a short name (1 to {MAX_ID} printable characters)", key=False)
        q.id = str(qid)
        ans = item.get("answer")
        if not isinstance(ans, str) or not ans.strip() or len(ans) > 200 or oneline(ans) != ans:
            raise FieldError(path + ("answer",), "answer must be a dotted path into the problem's results, e.g. find.0.s",
                       key=False)
        q.answer = ans.strip()
        self.problem(q, item, path)
        if "points" in item:
            try:
                q.points = read_points(item["points"])
            except ValueError as exc:
                raise FieldError(path + ("points",), str(exc), key=False) from None
        q.tol = parse_tolerance(item["tolerance"], self.key.tol, path + ("tolerance",)) if "tolerance" in item \
            else self.key.tol
        if "unit" in item:
            self.unit(q, item["unit"], path + ("unit",))
        if "partial" in item:
            q.partial = self.partial(item["partial"], path + ("partial",))
        if "carry" in item:
            q.carry = self.carry(item["carry"], path + ("carry",))
            from dyncli.check.submission import as_written

            q.carry = (str(as_written(self.doc, path + ("carry", "from"), item["carry"]["from"])), q.carry[1])
        if "visible" in item:
            if not isinstance(item["visible"], bool):
                raise FieldError(path + ("visible",), "visible must be true or false", key=False)
            q.visible = item["visible"]
        if "feedback" in item:
            q.feedback = self.feedback(item["feedback"], path + ("feedback",))
        if "title" in item:
            if not isinstance(item["title"], str):
                raise FieldError(path + ("title",), "title must be text", key=False)
            q.title = item["title"]
        if "text" in item:
            q.text = item["text"]      # checked against the problem's params in check_texts

    def problem(self, q: Question, item: dict, path: tuple) -> None:
        p = item.get("problem")
        if "index" in item:
            v = item["index"]
            if isinstance(v, bool) or not isinstance(v, int) or v < 0:
                raise FieldError(path + ("index",), "index must be a whole number >= 0", key=False)
            q.index = v
        pos = self.doc.value_pos(path + ("problem",)) or (None, None)
        where = Diagnostic(self.key.file, pos[0], pos[1], ".".join(map(str, path + ("problem",))), "")
        if isinstance(p, dict):
            t = p.get("type")
            title = tt if isinstance(tt := p.get("title"), str) else f"question {q.id}"
            q.problem = LoadedProblem(self.key.file, 0, t if isinstance(t, str) else None, title, p, self.doc,
                                      path + ("problem",), base_dir=self.key.base_dir)
            if q.index not in (None, 0):
                raise FieldError(path + ("index",), "an inline problem has only index 0", key=False)
            return
        if not isinstance(p, str) or not p.strip():
            raise FieldError(path + ("problem",), "problem must be a file path (relative to the key) or an inline "
                                            "problem mapping", key=False)
        ps, err = self.files.read(p.strip(), self.key.base_dir, where)
        if err is not None:
            raise FieldError(path + ("problem",), err.message, key=False)
        if q.index is None and len(ps) > 1:
            raise FieldError(path + ("problem",), f"'{shown(p)}' holds {len(ps)} problems: add 'index: N' "
                                            f"(0-{len(ps) - 1})", key=False)
        idx = q.index or 0
        if idx >= len(ps):
            raise FieldError(path + ("index",), f"'{shown(p)}' holds {len(ps)} problem(s): index must be 0-{len(ps) - 1}",
                       key=False)
        q.problem = ps[idx]

    def unit(self, q: Question, u: Any, path: tuple) -> None:
        from dyncli.check.quantities import unit_spec

        if not isinstance(u, str) or not u.strip() or len(u) > 40:
            raise FieldError(path, "unit must be a unit such as m, m/s, kg*m^2, deg", key=False)
        try:
            unit_spec(u.strip())
        except ValueError as exc:
            raise FieldError(path, str(exc), key=False) from None
        q.unit = u.strip()

    def partial(self, raw: Any, path: tuple) -> dict[str, float]:
        if not isinstance(raw, dict):
            raise FieldError(path, f"partial must be a mapping slip: fraction, slips: {', '.join(SLIPS)}", key=False)
        out = {}
        for k, v in raw.items():
            if k not in SLIPS:
                raise FieldError(path + (k,), f"unknown slip '{shown(k)}'{did_you_mean(str(k), SLIPS)}; "
                                        f"known: {', '.join(SLIPS)}")
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 <= v <= 1:
                raise FieldError(path + (k,), "a partial credit is a fraction from 0 to 1", key=False)
            out[k] = float(v)
        return out

    def feedback(self, raw: Any, path: tuple) -> dict[str, str]:
        if not isinstance(raw, dict) or not raw:
            raise FieldError(path, f"feedback must be a mapping status-or-slip: text ({', '.join(FEEDBACK_KEYS)})",
                       key=False)
        out = {}
        for k, v in raw.items():
            if k not in FEEDBACK_KEYS:
                raise FieldError(path + (k,), f"unknown feedback key '{shown(k)}'{did_you_mean(str(k), FEEDBACK_KEYS)}; "
                                        f"known: {', '.join(FEEDBACK_KEYS)}")
            if not isinstance(v, str) or not v.strip() or len(v) > MAX_FEEDBACK:
                raise FieldError(path + (k,), f"feedback text must be 1 to {MAX_FEEDBACK} characters", key=False)
            out[k] = v.strip()
        return out

    def problem_texts(self, raw: Any) -> None:
        from dyncli.check.statement import read_problem_texts

        read_problem_texts(self, raw, Question)

    def check_texts(self, names) -> None:
        from dyncli.check.statement import check_texts

        check_texts(self, names, Question)

    def carry(self, raw: Any, path: tuple) -> tuple[str, str]:
        if not isinstance(raw, dict) or set(raw) != {"from", "param"}:
            raise FieldError(path, "carry must be {from: QUESTION-ID, param: PARAMS-NAME}", key=False)
        src, par = raw["from"], raw["param"]
        if isinstance(src, bool) or not isinstance(src, (str, int)):
            raise FieldError(path + ("from",), "carry.from must be a question id", key=False)
        if not isinstance(par, str) or not par.isidentifier() or keyword.iskeyword(par):
            raise FieldError(path + ("param",), "carry.param must be a params name of this question's problem", key=False)
        return str(src), par

    # -- across questions ---------------------------------------------------
    def check_ids(self) -> None:
        seen: dict[str, Question] = {}
        for q in self.key.questions:
            if q.id in seen:
                self.diag(q.prefix + ("id",), f"duplicate question id '{shown(q.id)}'", key=False)
            seen[q.id] = q
        for q in self.key.questions:
            if q.carry is None:
                continue
            if q.carry[0] in self.rejected:
                continue
            if q.carry[0] not in seen:
                self.diag(q.prefix + ("carry", "from"), f"carry from '{shown(q.carry[0])}': no such question"
                          f"{did_you_mean(q.carry[0], seen)}", key=False)
            elif q.carry[0] == q.id or self.cycle(q, seen):
                self.diag(q.prefix + ("carry",), "carry forms a cycle: "
                          + " -> ".join(shown(x) for x in self.cycle(q, seen) or [q.id, q.id]))

    @staticmethod
    def cycle(q: Question, seen: dict[str, Question]) -> list[str] | None:
        chain = [q.id]
        cur = q
        while cur.carry is not None and cur.carry[0] in seen:
            nxt = cur.carry[0]
            if nxt in chain:
                return chain[chain.index(nxt):] + [nxt] if nxt == q.id else None
            chain.append(nxt)
            cur = seen[nxt]
        return None

    def check_params(self) -> None:
        """Every variant parameter and every carry parameter is a params
        name of the problems it is meant for."""
        def names(q: Question) -> set[str]:
            raw = q.problem.raw if q.problem is not None and isinstance(q.problem.raw, dict) else {}
            p = raw.get("params")
            return set(p) if isinstance(p, dict) else set()

        self.check_texts(names)
        for q in self.key.questions:
            if q.carry is not None and q.carry[1] not in names(q):
                self.diag(q.prefix + ("carry", "param"),
                          f"carry.param '{shown(q.carry[1])}' is not in the params of this question's problem"
                          f"{did_you_mean(q.carry[1], names(q))}", key=False)
        v = self.key.variants
        if v is None:
            return
        used = set().union(*(names(q) for q in self.key.questions))
        for p in v.params:
            if p.name not in used:
                self.diag(("variants", "params", p.name), f"no problem of this key has a parameter '{shown(p.name)}'"
                          f"{did_you_mean(p.name, used)} (a variant sets names of the problems' params)")
