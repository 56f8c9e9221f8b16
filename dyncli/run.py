"""Orchestration shared by ``solve``, ``validate`` and ``check``: load,
validate, solve, and map failures to the contract's exit codes."""

from __future__ import annotations

import traceback
import warnings
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, cast

from dyncli.errors import InputError, NumericalError
from dyncli.loader import Diagnostic, LoadedProblem
from dyncli.result import Result, SolveOptions


@dataclass
class Outcome:
    problem: LoadedProblem
    result: Result | None
    exit_code: int
    message: str | None = None     # one line for stderr when exit_code != 0
    trace: str | None = None       # traceback for --debug (exit 3 only)


def solve_one(lp: LoadedProblem, options: SolveOptions | None = None) -> Outcome:
    """The outcome of ``lp``, kept on it for the problems that take a parameter from its results
    (dyncli.chain); a chained problem is first given those values and validated."""
    if lp.chain and lp.error is None:
        from dyncli import chain, chain_solve

        try:
            ready = chain_solve.resolve(lp, lambda src: solve_one(src, options))
        except chain.Failure as exc:
            outcome = Outcome(lp, None, exc.code, exc.message)
        else:
            outcome = _solve(ready, options)
    else:
        outcome = _solve(lp, options)
    lp.outcome = (lp.raw, outcome)
    return outcome


def _solve(lp: LoadedProblem, options: SolveOptions | None = None) -> Outcome:
    from dyncli import registry

    options = options or SolveOptions()
    if lp.error is not None:
        return Outcome(lp, None, 2, str(lp.error))
    try:
        assert lp.type is not None     # read whenever the problem loaded without an error
        fn = registry.solver(lp.type)
        with warnings.catch_warnings(record=True) as caught:
            # no library warning reaches the user as raw text: floating-point
            # RuntimeWarnings (overflow, invalid value) are dropped (the solvers
            # detect non-finite values and report them as results' warnings or
            # exit codes); any other (scipy's IntegrationWarning...) becomes one
            # line among the results' warnings
            warnings.filters[:0] = _quiet_filters()  # type: ignore[index]  # typeshed: a Sequence; at run time the module's list
            result = fn(lp.model, options)
        if isinstance(result, Result):
            _library_warnings(result, caught)
            _degrees_warnings(result, lp)
    except InputError as exc:
        from dyncli.angles import degrees_hint

        hint = degrees_hint(type(lp.model), lp.raw, exc.path)
        return Outcome(lp, None, 2, str(lp.diagnostic(exc.path, exc.message + hint)))
    except NumericalError as exc:
        d = Diagnostic(lp.file, None, None, None, f"{_named(lp)}numerical step failed: {exc}")
        pos = lp.doc.locate(lp.prefix) if lp.doc else None
        if pos:
            d.line, d.col = pos
        return Outcome(lp, None, 1, str(d))
    except (KeyboardInterrupt, SystemExit):
        raise
    except OverflowError as exc:
        # float arithmetic overflows only on the size of the given numbers (a
        # sum of masses of 1e308): invalid input for doubles, not a bug
        return Outcome(lp, None, 2, _too_large(lp, exc))
    except RecursionError as exc:  # pragma: no cover - defensive
        return Outcome(lp, None, 3, _internal(lp, exc), traceback.format_exc())
    except Exception as exc:  # noqa: BLE001 - map every bug to exit 3
        return Outcome(lp, None, 3, _internal(lp, exc), traceback.format_exc())
    if not isinstance(result, Result):  # pragma: no cover - defensive
        return Outcome(lp, None, 3, _internal(lp, TypeError("solver returned no Result")))
    return Outcome(lp, result, 0)


_QUIET: list = []


def _quiet_filters() -> list:
    """The filters of a solve, made once: "always" for every warning, and
    "ignore" for RuntimeWarning and the four for developers (Deprecation,
    PendingDeprecation, Future, Import, Resource)."""
    if not _QUIET:
        with warnings.catch_warnings():
            warnings.resetwarnings()
            warnings.simplefilter("always")
            for quiet in (RuntimeWarning, DeprecationWarning, PendingDeprecationWarning, FutureWarning,
                          ImportWarning, ResourceWarning):
                warnings.simplefilter("ignore", quiet)
            _QUIET.extend(warnings.filters)
    return _QUIET


def _named(lp: LoadedProblem) -> str:
    """``"title: "`` to put before a message about the problem, or nothing when
    the title is only the file's name, which the message starts with already
    (else a mapping's problem would read ``<dict>: <dict>: ...``)."""
    from pathlib import Path

    own = lp.title not in (Path(lp.file).name, "stdin" if lp.file == "<stdin>" else None)
    return f"{lp.title}: " if own else ""


def _library_warnings(result: Result, caught) -> None:
    from dyncli.printable import printable

    for w in caught:
        first = str(w.message).strip().splitlines()[0] if str(w.message).strip() else type(w.message).__name__
        result.warn(printable(f"numerical library ({w.category.__name__}): {first[:200]}"))


def _too_large(lp: LoadedProblem, exc: OverflowError) -> str:
    d = Diagnostic(lp.file, None, None, None,
                   f"{_named(lp)}a number overflowed a double while solving ({exc}): the problem's values are "
                   "too large for floating point (a sum, product or power beyond 1.8e308); give them in units "
                   "that keep the results below about 1e300")
    pos = lp.doc.locate(lp.prefix) if lp.doc else None
    if pos:
        d.line, d.col = pos
    return str(d)


def _degrees_warnings(result: Result, lp: LoadedProblem) -> None:
    """A bare angle beyond a full turn (``theta: 30`` meant as degrees): named, with ``30*deg``;
    and a parameter named ``g`` that is not the problem's gravity (``params: {g: 1.62}`` with no
    ``g`` of the problem: the expressions read 1.62, the motion falls at 9.81)."""
    from dyncli.angles import degrees_warnings

    for w in degrees_warnings(lp.model, lp.raw):
        result.warn(w)
    raw: dict = lp.raw if isinstance(lp.raw, dict) else {}
    params = raw.get("params")
    gravity = getattr(lp.model, "g", None)
    if isinstance(params, dict) and "g" in params and "g" not in raw and isinstance(gravity, float):
        written = (getattr(lp.model, "params", None) or {}).get("g")
        value = float(written) if isinstance(written, (int, float)) and not isinstance(written, bool) else None
        if value != gravity:
            result.warn(f"params.g is a parameter of the expressions, not the gravity: the motion has g = {gravity:g} "
                        "m/s² (the default); to use the parameter as gravity, write g: g at the top level")


def _internal(lp: LoadedProblem, exc: BaseException) -> str:
    from dyncli import __version__
    from dyncli.printable import printable

    return printable(
        f"{lp.file}: internal error in dyncli {__version__} solving problem #{lp.index} ({lp.type}): "
        f"{type(exc).__name__}: {exc}. This is a bug: please report it with the problem file "
        "(run with --debug for the traceback)."
    )


def worst(codes: list[int]) -> int:
    """Overall exit code: 3 > 2 > 1 > 0."""
    return max(codes, default=0)


def outcome_record(o: Outcome) -> dict[str, Any]:
    from dyncli.render.jsonout import problem_record

    return problem_record(o.problem, o.result, o.message, o.exit_code)


# ------------------------------------------------------------------ commands

COMMON_UNITS = ("deg", "rad", "rev", "rpm", "mm", "cm", "m", "km", "s", "ms", "min", "h", "g", "kg", "N", "kN",
                "J", "kJ", "W", "kW", "Hz", "m/s", "km/h", "mph", "N*m", "N/m", "lbf", "ft", "in")


def print_error(msg: str) -> None:
    """One message on stderr, always through the escaper: control characters
    visible (a --set path or a title cannot forge a second line or drive the
    terminal), a very long line shortened (:func:`dyncli.printable.line`)."""
    import sys

    from dyncli.printable import line

    print(line(msg), file=sys.stderr)


def _err_lines(text: str) -> None:
    """Messages of one problem, one per line (each :class:`Diagnostic` line
    is made printable where it is built): each line escaped and shortened."""
    import sys

    from dyncli.printable import lines

    print(lines(text), file=sys.stderr)


def parse_units(text: str | None) -> list[str] | None:
    """``--units deg,rpm,mm`` -> the list; an unknown unit is InputError."""
    if text is None:
        return None
    wanted = [u.strip() for u in text.split(",") if u.strip()]
    if not wanted:
        raise InputError("--units: give one or more unit names, e.g. --units deg,rpm,mm")
    from dyncli.expr import did_you_mean
    from dyncli.units import clean_unit, registry

    ureg = registry()
    for w in wanted:
        try:
            ureg.parse_units(clean_unit(w))
        except Exception:  # noqa: BLE001 - pint's errors vary by version
            raise InputError(f"--units: unknown unit {w!r}{did_you_mean(w, COMMON_UNITS)}") from None
    return wanted


def _symbolic_notes(fmt: str, types: list) -> None:
    if fmt in ("json", "yaml", "csv"):
        print_error(f"--symbolic: formulas appear only in the table, markdown and latex views, not in --format {fmt}")
        return
    from dyncli import registry

    with_view = registry.having("symbolic")
    lacking = sorted({t for t in types if t and t not in with_view})
    if lacking:
        print_error(f"--symbolic: no symbolic view for {', '.join(lacking)} (types with one: {', '.join(with_view)})")


def _options_and_problems(files: list[str], sets: list[str], sweeps: list[str], lazy: bool = False):
    """Parse the overrides, load and expand: (problems, exit codes so far)
    or None after printing a usage error (exit 2); ``lazy``: (problems made
    one at a time, codes, the problems' types)."""
    from dyncli.loader import load_paths
    from dyncli.overrides import OverrideError, expand, parse_set, parse_sweep

    try:
        assigns = [parse_set(s) for s in sets] + [parse_sweep(s) for s in sweeps]
    except OverrideError as exc:
        print_error(exc.message)
        return None
    problems, diags = load_paths(files)
    for d in diags:
        print_error(str(d))
    types = [lp.type for lp in problems]
    try:
        problems = expand(problems, assigns, lazy)
    except OverrideError as exc:
        print_error(exc.message)
        return None
    return (problems, [2 for _ in diags], types) if lazy else (problems, [2 for _ in diags])


def solve_command(files, fmt: str, *, symbolic=False, digits=6, units=None, plot=None, sets=(), sweeps=(),
                  long=False, debug=False, wide=False) -> int:
    """``dyncli solve``: the exit code."""
    import sys

    from dyncli.render import emit
    from dyncli.render.stream import RecordStream

    try:
        wanted = parse_units(units)
        if long and fmt != "csv":
            raise InputError("--long works only with --format csv (one row per time): add --format csv")
    except InputError as exc:
        print_error(exc.message)
        return 2
    streamed = fmt in ("json", "yaml", "csv") and not plot      # one point held at a time: collections stay cheap
    with _no_gc(bool(sweeps) and not streamed):
        with _no_gc(True):          # (a file of 1e5 times: every value's position recorded)
            loaded = _options_and_problems(files, list(sets), list(sweeps), lazy=True)
        if loaded is None:
            return 2
        problems, codes, types = loaded
        if symbolic:
            _symbolic_notes(fmt, types)
        stream = RecordStream(fmt, long) if streamed else None
        notes: list[str] = []
        table = emit.TableWriter(digits, wanted, wide, sweep=bool(sweeps)) if fmt == "table" else None
        # made one at a time (overrides.expand: no problem reads another's outcome), a streamed
        # problem's outcome is let go once written: freed while collections are off, not walked after
        forget = stream is not None and not isinstance(problems, list)
        outcomes = _solve_all(problems, SolveOptions(symbolic=symbolic), codes, debug,
                              table if table is not None else stream, notes, keep=stream is None, forget=forget)
        if stream is not None:
            stream.close()
        elif table is not None:
            table.close()
        else:
            sys.stdout.write(emit.dumps(fmt, outcomes, digits, wanted, long))
    if plot:
        codes.append(_plot(outcomes, plot))
    if fmt in ("json", "yaml", "csv") or (fmt == "table" and sweeps):      # a sweep's table: rows only
        for w in notes:
            print_error(w)
    return worst(codes)


def _solve_all(problems, options, codes: list[int], debug: bool, writer=None, notes=None, keep=True,
               forget=False) -> list[Outcome]:
    """Solve each problem, its messages to stderr, its output to ``writer``
    (the table, or a :class:`~dyncli.render.stream.RecordStream` that takes
    failures too) as it is solved; the outcomes kept when ``keep`` (else only
    the results' warnings, in ``notes``: a streamed sweep holds one point);
    ``forget``: nothing reads a problem's outcome after it is written (``lp.outcome`` cleared)."""
    outcomes: list[Outcome] = []
    for lp in problems:
        with _no_gc(True):          # one problem's results (1e5 times: millions of lists) built and written
            _one(lp, options, codes, debug, writer, notes, keep, outcomes)      # without collections walking them
            if forget:
                lp.outcome = None
    return outcomes


def _one(lp, options, codes, debug, writer, notes, keep, outcomes) -> None:
    """:func:`_solve_all` of one problem."""
    import sys

    o = solve_one(lp, options)
    codes.append(o.exit_code)
    if keep:
        outcomes.append(o)
    if notes is not None and o.result is not None:
        notes += [f"{lp.file}: {lp.title}: warning: {w}" for w in o.result.warnings]
    if o.message:
        _err_lines(o.message)
        if o.trace and debug:
            from dyncli.printable import lines

            print(lines(o.trace), file=sys.stderr)
    if writer is not None and hasattr(writer, "add"):
        writer.add(o)
    elif writer is not None and o.result is not None:
        writer.write(lp, o.result)


@contextmanager
def _no_gc(on: bool):
    """No cyclic garbage collection while many problems (a sweep) are solved
    and printed: every collection walks all the results kept so far (a
    quarter to a third of a 10,000-point sweep's time); reference counting
    still frees everything that is not kept."""
    import gc

    was = gc.isenabled()
    if on:
        gc.disable()
    try:
        yield
    finally:
        if on and was:
            gc.enable()


def _plot(outcomes: list[Outcome], path: str) -> int:
    """``--plot PATH``: DIR/ writes one DIR/<file-stem>-<index>.png per problem; a
    .png/.svg/.pdf file holds every panel."""
    from dyncli import registry
    from dyncli.render import plot as plotting

    groups = [(o.problem.file, o.problem.index,
               [(o.problem.title, spec) for spec in registry.plots_for(cast(str, o.problem.type), o.problem.model, o.result)])
              for o in outcomes if o.result is not None]
    n = sum(len(g[2]) for g in groups)
    try:
        plotting.check_path(path)
        if not n:
            print_error("--plot: none of these problem types draws a plot")
        elif plotting.is_dir_target(path):
            written = plotting.save_each(groups, path)
            print_error(f"wrote {n} plot panel(s) to {len(written)} file(s) in {path}")
        else:
            plotting.save([pan for g in groups for pan in g[2]], path)
            print_error(f"wrote {n} plot panel(s) to {path}")
    except InputError as exc:
        print_error(exc.message)
        return 2
    return 0


def validate_command(files, sets=()) -> int:
    """``dyncli validate``: every error of every problem, one line each."""
    loaded = _options_and_problems(files, list(sets), [])
    if loaded is None:
        return 2
    problems, codes = loaded
    for lp in problems:
        if lp.error is not None:
            _err_lines(str(lp.error))
            codes.append(2)
        else:
            from dyncli.printable import line

            taken = ", ".join(f"{n} from problem {ln.source}'s {ln.path}" for n, ln in lp.chain.items())
            print(line(f"{lp.file}: {lp.title} ({lp.type}): ok" + (f" (params {taken}: checked when solved)" if taken else "")))
    return worst(codes)
