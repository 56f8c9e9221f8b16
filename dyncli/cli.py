"""The command line (thin): parses options and delegates to the layers below.

Exit codes (docs/cli.md): 0 solved, 1 a numerical step failed / check found a
wrong answer, 2 invalid input or usage, 3 internal error.
"""

from __future__ import annotations

import sys
from enum import Enum
from typing import List, Optional

import typer

from dyncli import __version__
from dyncli.check.emit import FORMATS as CHECK_FORMATS, GRADED_ONLY
from dyncli.render.emit import FORMATS as SOLVE_FORMATS

app = typer.Typer(
    name="dyncli",
    help="Solve engineering-dynamics problems written as YAML files (Rubin & Altus, Dynamics).",
    add_completion=True,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)

_state = {"debug": False}


# mypy cannot list the members of an Enum built from a list: the `ignore`s on Format and CheckFormat
Format = Enum("Format", {f: f for f in SOLVE_FORMATS}, type=str)  # type: ignore[misc]  # the renderer's one list of formats


def _version(value: bool):
    if value:
        print(f"dyncli {__version__}")
        raise typer.Exit(0)


@app.callback()
def _main(
    version: bool = typer.Option(False, "--version", callback=_version, is_eager=True, help="Print the version and exit."),
    debug: bool = typer.Option(False, "--debug", help="Show tracebacks of internal errors."),
):
    _state["debug"] = debug


def _err(msg: str) -> None:
    from dyncli.run import print_error

    print_error(msg)


@app.command()
def solve(
    files: List[str] = typer.Argument(..., help="Problem files (YAML); '-' reads stdin.", metavar="FILE..."),
    format: Format = typer.Option(Format.table,  # type: ignore[attr-defined]  # a member mypy cannot see (above)
                                  "--format", "-f", help="Output format."),
    symbolic: bool = typer.Option(False, "--symbolic", help="Print frame tables with formulas (types that support it)."),
    digits: int = typer.Option(6, "--digits", min=1, max=17, help="Significant digits in tables."),
    units: Optional[str] = typer.Option(None, "--units", help="Show table results in these units where compatible, e.g. 'deg,rpm,mm' (JSON stays SI)."),
    plot: Optional[str] = typer.Option(None, "--plot", help="Save the plots: DIR/ writes one DIR/<file-stem>-<index>.png per problem; a .png/.svg/.pdf file holds them all."),
    set_: List[str] = typer.Option([], "--set", metavar="PATH=VALUE",
                                   help="Override a field, dotted field (base.omega) or params name; repeatable."),
    sweep: List[str] = typer.Option([], "--sweep", metavar="PATH=LO:HI:N|V1,V2",
                                    help="Solve for each value (N points, ends included, or a list); several: their product."),
    long: bool = typer.Option(False, "--long", help="With --format csv: one row per time (a 't' column) for lists over 'at'."),
    wide: bool = typer.Option(False, "--wide", help="Tables at their natural width (piped output is otherwise "
                                                    "fitted to COLUMNS, or 100 columns)."),
):
    """Solve problem files and print the results."""
    from dyncli.run import solve_command

    raise typer.Exit(solve_command(files, format.value, symbolic=symbolic, digits=digits, units=units, plot=plot,
                                   sets=set_, sweeps=sweep, long=long, debug=_state["debug"], wide=wide))


@app.command()
def validate(
    files: List[str] = typer.Argument(..., help="Problem files (YAML); '-' reads stdin.", metavar="FILE..."),
    set_: List[str] = typer.Option([], "--set", metavar="PATH=VALUE", help="Override a field (as for solve)."),
):
    """Check problem files (schema and expressions) without solving; every error, one line each."""
    from dyncli.run import validate_command

    raise typer.Exit(validate_command(files, set_))


CheckFormat = Enum("CheckFormat", {f: f for f in CHECK_FORMATS}, type=str)  # type: ignore[misc]  # one emitter each (dyncli.check.emit)


class IdFrom(str, Enum):
    student = "student"
    filename = "filename"


@app.command()
def check(
    files: Optional[List[str]] = typer.Argument(
        None, metavar="FILES...",
        help="Answer files (self-study, §5), or with --key the students' submissions; '-' reads stdin. "
             "With --write-key: problem files."),
    format: CheckFormat = typer.Option(CheckFormat.table,  # type: ignore[attr-defined]  # a member mypy cannot see (Format)
                                       "--format", "-f", help="Report format."),
    reveal: bool = typer.Option(False, "--reveal", help="Show the expected values."),
    output: Optional[str] = typer.Option(None, "--output", "-o", help="Write the report (or key) to this file."),
    write_key: bool = typer.Option(False, "--write-key", help="Solve the given PROBLEM files and print an answer key."),
    key: Optional[str] = typer.Option(None, "--key", "-k", metavar="KEY",
                                      help="Graded work: the instructor's key; FILES are submissions."),
    selftest: bool = typer.Option(False, "--selftest", help="With --key: solve every variant and grade the key against itself."),
    n: int = typer.Option(100, "-n", min=0, max=100_000, help="With --selftest: number of student ids drawn."),
    student: Optional[str] = typer.Option(None, "--student", help="With --key: the student id of the submissions."),
    root: Optional[str] = typer.Option(None, "--root", metavar="DIR",
                                       help="Problem files may lie anywhere inside DIR (default: the folder of the file naming them)."),
    upload: bool = typer.Option(False, "--upload",
                                help="With --key: the files are one student's upload (Gradescope): grade the file "
                                     "the key's 'submission:' names, else the only .yaml; refuse, listing them, otherwise."),
    id_from: IdFrom = typer.Option(IdFrom.student, "--id-from",
                                   help="With --key: where a submission's student id comes from: its 'student:' "
                                        "(default) or its file name (a differing 'student:' is refused)."),

    roster: Optional[str] = typer.Option(None, "--roster", metavar="CSV",
                                         help="With --key: the class (a 'student' column): students without a "
                                              "submission are missing; submissions of others are reported."),
    stats: bool = typer.Option(False, "--stats", help="With --key: per question the class's mean, % correct, "
                                                      "statuses, diagnoses and the range of the true answers."),
    compare: Optional[str] = typer.Option(None, "--compare", metavar="PREVIOUS.json",
                                          help="With --key: every student whose score changed since this JSON report."),
):
    """Grade answers: graded work with --key KEY SUBMISSION..., self-study with ANSWERS... (exit 1 if any is wrong)."""
    files = files or []
    if key is not None:
        raise typer.Exit(_graded(key, files, format, reveal, output, write_key, selftest, n, student, root, upload,
                                 id_from, roster, stats, compare))
    keyonly = [name for name, given in (("--upload", upload), ("--roster", roster is not None), ("--stats", stats),
                                        ("--compare", compare is not None),
                                        (f"--format {format.value}", format.value in GRADED_ONLY),
                                        ("--selftest", selftest), ("--student", student is not None),
                                        ("--id-from", id_from is not IdFrom.student)) if given]
    if keyonly:
        _err(f"{keyonly[0]} goes with --key KEY")
        raise typer.Exit(2)
    if not files:
        _err("give answer files (self-study), or --key KEY and the submissions (graded work)")
        raise typer.Exit(2)
    from dyncli.check.command import run_check

    raise typer.Exit(run_check(files, format.value, reveal, output, write_key, _state["debug"], root))


def _graded(key, files, format, reveal, output, write_key, selftest, n, student, root, upload, id_from, roster,
            stats, compare) -> int:
    """``dyncli check --key``: graded work, the key's selftest, a whole course."""
    from dyncli.check.keycommand import run_key_check, run_selftest

    if write_key:
        _err("--write-key and --key do not go together")
        return 2
    if selftest:
        if files:
            _err("--selftest checks the key alone: give no submissions")
            return 2
        return run_selftest(key, n, root)
    if id_from is IdFrom.filename and student is not None:
        _err("--id-from filename and --student do not go together")
        return 2
    from dyncli.check.gradebook import CourseOptions

    course = CourseOptions(roster, stats, compare) if roster is not None or stats or compare is not None else None
    return run_key_check(key, files, format.value, reveal, output, student, root, id_from.value, upload, course)


class VariantFormat(str, Enum):
    yaml = "yaml"
    markdown = "markdown"
    html = "html"


@app.command()
def variant(
    key: str = typer.Argument(..., metavar="KEY", help="The instructor's key."),
    student: Optional[str] = typer.Option(None, "--student", help="The student id."),
    format: VariantFormat = typer.Option(VariantFormat.yaml, "--format", "-f", help="Sheet format."),
    template: bool = typer.Option(False, "--template", help="Print an empty submission instead."),
    root: Optional[str] = typer.Option(None, "--root", metavar="DIR", help="Problem files may lie anywhere inside DIR."),
    roster: Optional[str] = typer.Option(None, "--roster", metavar="CSV",
                                         help="Every student of this roster (a 'student' column): one file each in -o DIR."),
    output: Optional[str] = typer.Option(None, "--output", "-o", metavar="DIR", help="With --roster: the folder of the sheets."),
):
    """Print a student's problem set (their numbers), or an empty submission with --template."""
    if (student is None) == (roster is None):
        _err("give --student ID (one sheet on stdout) or --roster CSV -o DIR (one file per student)")
        raise typer.Exit(2)
    if roster is not None:
        if not output:
            _err("--roster needs -o DIR: the folder that receives one file per student")
            raise typer.Exit(2)
        from dyncli.check.roster import write_sheets

        raise typer.Exit(write_sheets(key, roster, output, format.value, template, root))
    if output:
        _err("-o DIR goes with --roster (one sheet prints on stdout)")
        raise typer.Exit(2)
    from dyncli.check.sheet import run_variant

    assert student is not None        # given exactly one of --student and --roster (checked above)
    raise typer.Exit(run_variant(key, student, format.value, template, root))


@app.command()
def types():
    """List the problem types with the notes' sections."""
    from dyncli import registry

    wn = max(len(n) for n in registry.TYPES)
    ws = max(len(i.sections) for i in registry.TYPES.values())
    for name, info in registry.TYPES.items():
        print(f"{name:<{wn}}  {info.sections:<{ws}}  {info.title}")


@app.command()
def schema(type_name: Optional[str] = typer.Argument(None, metavar="[TYPE]", help="One problem type (default: all)."),
           results: bool = typer.Option(False, "--results", help="The schema of the results (JSON output) instead.")):
    """Print the JSON Schema of problem files (for editors' YAML support), or of their results."""
    from dyncli.schema import json_schema, results_json_schema

    import json

    try:
        print(json.dumps(results_json_schema(type_name) if results else json_schema(type_name), indent=2, ensure_ascii=not results))
    except KeyError:
        from dyncli import registry
        from dyncli.expr import did_you_mean

        _err(f"unknown problem type {type_name!r}{did_you_mean(type_name or '', registry.TYPES)}; run 'dyncli types'")
        raise typer.Exit(2)


@app.command()
def new(type_name: str = typer.Argument(..., metavar="TYPE", help="Problem type.")):
    """Print a commented template problem file for TYPE."""
    from dyncli import registry
    from dyncli.expr import did_you_mean
    from dyncli.schema import template

    if type_name not in registry.TYPES:
        _err(f"unknown problem type {type_name!r}{did_you_mean(type_name, registry.TYPES)}; run 'dyncli types'")
        raise typer.Exit(2)
    sys.stdout.write(template(type_name))


def _quick_shutdown() -> None:
    """At the interpreter's exit (after every output is written and flushed), every object left
    is frozen (``gc.freeze``), so the shutdown's final cyclic collection does not walk the
    millions of lists of a large answer (a particle at 1e5 times: ~0.3 s of CPU); the memory goes
    back to the system with the process.  Registered once per process (in-process callers of
    :func:`main`, such as tests, are frozen only when their interpreter ends)."""
    if not _state.get("quick_shutdown"):
        import atexit
        import gc

        atexit.register(gc.freeze)
        _state["quick_shutdown"] = True


def main() -> None:
    """Entry point: click/typer handle usage errors (exit 2) and typer.Exit;
    a closed stdout pipe ends quietly (exit 0), a failed write to stdout is
    exit 2 with one line (:mod:`dyncli.stdio`); anything unexpected is a bug
    and maps to exit 3 with one line."""
    import warnings

    from dyncli import stdio

    # no library's warning reaches stderr as raw text (site-packages paths,
    # source lines): while a problem is solved its warnings become lines among
    # the results' warnings (dyncli.run.solve_one); anywhere else they are dropped
    warnings.simplefilter("ignore")
    stdio.setup()
    _quick_shutdown()
    code, pending = 0, None
    try:
        app()
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
    except KeyboardInterrupt:  # pragma: no cover - SIGINT exits 130 in dyncli.__main__
        code = 130
    except (stdio.ClosedPipe, stdio.OutputFailed) as exc:
        pending = exc
    except Exception as exc:  # noqa: BLE001
        import traceback

        _err(f"internal error in dyncli {__version__}: {type(exc).__name__}: {exc}. "
             "This is a bug: please report it (run with --debug for the traceback).")
        if _state["debug"] or "--debug" in sys.argv:
            traceback.print_exc()
        code = 3
    sys.exit(stdio.finish(code, pending))
