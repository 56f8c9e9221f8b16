"""Work-precision of every numerical route against exact / 50-digit references.

For each route (tests/accuracy/cases.py: rectilinear quadrature and events,
rectilinear ODE with events, particle ODE, top, vibration's DOP853 route,
kinematics and force-field quadrature — whichever types exist) and each
rtol in 1e-3 ... 1e-13 (atol = 1e-3 rtol), solve in-process and print

* time (median of a few solves, ms), true error (max abs vs the reference),
  the error_estimate dyncli reports and its ratio to the true error,
* nfev: right-hand-side / integrand evaluations counted in scipy
  (solve_ivp, quad), or, for routes with their own quadrature, the number of
  points at which the problem's expressions were evaluated,

and the same problem solved by a plain scipy script (solve_ivp DOP853 or
quad, same rtol/atol) as the baseline, with the time ratio dyncli/scipy per
route.  Writes docs/accuracy.png (error vs time) and docs/accuracy.md.

Usage: python benchmarks/work_precision.py [--quick] [--no-write]
       python benchmarks/work_precision.py --replot   # docs/accuracy.png again from docs/accuracy.md's tables

The figure is sized for the docs' text column (640 px wide, every text 9 pt,
shown at its own size) and tells its routes apart by colour AND marker
(dyncli.render.plot.series_style: sixteen distinct pairs).
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

RTOLS = [1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13]


class Counter:
    """Counts scipy RHS/integrand evaluations and expression points."""

    def __init__(self):
        self.scipy = 0
        self.points = 0

    def install(self):
        import numpy as np
        import scipy.integrate as si

        from dyncli import expr

        self._orig = (si.solve_ivp, si.quad, expr.Expr.__call__, si.DOP853)
        orig_ivp, orig_quad, orig_call, orig_dop = self._orig
        me = self

        class DOP853(orig_dop):      # used directly by routes that step by hand (top)
            def __init__(self_, fun, *a, **k):
                def f(t, y):
                    me.scipy += 1
                    return fun(t, y)
                super().__init__(f, *a, **k)

        def solve_ivp(*a, **k):
            sol = orig_ivp(*a, **k)
            me.scipy += int(getattr(sol, "nfev", 0))
            return sol

        def quad(func, *a, **k):
            def f(*x):
                me.scipy += 1
                return func(*x)
            return orig_quad(f, *a, **k)

        def call(self_, **env):
            me.points += int(max([np.size(v) for v in env.values()] or [1]))
            return orig_call(self_, **env)

        si.solve_ivp, si.quad, expr.Expr.__call__, si.DOP853 = solve_ivp, quad, call, DOP853

    def uninstall(self):
        import scipy.integrate as si

        from dyncli import expr

        si.solve_ivp, si.quad, expr.Expr.__call__, si.DOP853 = self._orig

    def nfev(self) -> tuple[int, str]:
        return (self.scipy, "") if self.scipy else (self.points, "*")


def solve_timed(case, rtol, repeats):
    """The record (as --format json) and the median time of the solver call
    alone (the validated model is reused: no YAML, no validation)."""
    from dyncli import registry
    from dyncli.loader import split_problems, validate
    from dyncli.result import SolveOptions
    from tests.conftest import solve_text

    text = case.text(rtol)
    cnt = Counter()
    cnt.install()
    try:
        rec = solve_text(text)[0]
    finally:
        cnt.uninstall()
    (lp,), _ = split_problems("wp.yaml", text.encode(), ROOT)
    validate(lp)
    fn = registry.solver(lp.type)
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        try:
            fn(lp.model, SolveOptions())
        except Exception:  # noqa: BLE001 - the failure is in rec already
            pass
        ts.append(time.perf_counter() - t0)
    return rec, statistics.median(ts), cnt.nfev()


def baseline_timed(case, rtol, repeats):
    atol = rtol * case.atol_factor
    err, nfev = case.scipy_baseline(rtol, atol)
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        case.scipy_baseline(rtol, atol)
        ts.append(time.perf_counter() - t0)
    return float(err), statistics.median(ts), nfev


def fmt(x, spec=".1e"):
    if x is None:
        return "—"
    if isinstance(x, float) and math.isinf(x):
        return "missed"
    return format(x, spec)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="three rtols, one repeat")
    ap.add_argument("--no-write", action="store_true", help="do not write docs/accuracy.{png,md}")
    ap.add_argument("--replot", action="store_true", help="redraw docs/accuracy.png from docs/accuracy.md (no timing)")
    args = ap.parse_args()
    if args.replot:
        plot(rows_from_md(ROOT / "docs" / "accuracy.md"), ROOT / "docs" / "accuracy.png")
        print("wrote docs/accuracy.png")
        return
    warnings.simplefilter("ignore")
    from tests.accuracy.cases import available_cases

    rtols = [1e-3, 1e-7, 1e-11] if args.quick else RTOLS
    repeats = 1 if args.quick else 3
    rows = []     # (case, rtol, time, err, est, nfev, mark, btime, berr, bnfev, method)
    t_start = time.perf_counter()
    for case in available_cases():
        print(f"\n## {case.name}")
        print(f"{'rtol':>7} {'ms':>8} {'error':>9} {'estimate':>9} {'est/err':>7} {'nfev':>7} | "
              f"{'scipy ms':>8} {'error':>9} {'nfev':>6} {'t ratio':>7}")
        for rtol in rtols:
            rec, t, (nfev, mark) = solve_timed(case, rtol, repeats)
            if rec.get("error"):
                print(f"{rtol:7.0e}  failed: {rec['error']}")
                rows.append((case, rtol, None, None, None, None, "", None, None, None, "failed"))
                continue
            err = case.error(rec)
            est = rec.get("error_estimate")
            bt = berr = bn = None
            if case.scipy_baseline:
                berr, bt, bn = baseline_timed(case, rtol, repeats)
            ratio = (est / case.comparable(err)) if (est is not None and err > 0) else None
            print(f"{rtol:7.0e} {t * 1000:8.2f} {err:9.1e} {fmt(est):>9} {fmt(ratio, '.2g'):>7} {nfev:>6}{mark or ' '} | "
                  f"{fmt(bt * 1000 if bt is not None else None, '.2f'):>8} {fmt(berr):>9} {bn if bn is not None else '—':>6} "
                  f"{fmt(t / bt if bt else None, '.1f'):>7}")
            rows.append((case, rtol, t, err, est, nfev, mark, bt, berr, bn, rec["method"]))
    print(f"\n(* = points at which the problem's expressions were evaluated: the route has its own quadrature)"
          f"\ntotal {time.perf_counter() - t_start:.0f} s")
    summary = route_summary(rows)
    print("\nper route: median time ratio dyncli/scipy, worst estimate/true-error ratio (error > 1e-13)")
    for name, tr, worst in summary:
        print(f"  {name:<44} time ratio {fmt(tr, '.1f'):>6}   worst est/err {fmt(worst, '.2g')}")
    if not args.no_write:
        plot(rows, ROOT / "docs" / "accuracy.png")
        write_md(rows, summary, ROOT / "docs" / "accuracy.md", rtols)
        print("wrote docs/accuracy.png and docs/accuracy.md")


def route_summary(rows):
    out = []
    names = []
    for r in rows:
        if r[0].name not in names:
            names.append(r[0].name)
    for n in names:
        rs = [r for r in rows if r[0].name == n and r[2] is not None]
        trs = [r[2] / r[7] for r in rs if r[7]]
        ests = [r[4] / r[0].comparable(r[3]) for r in rs if r[4] is not None and r[3] > 1e-13]
        out.append((n, statistics.median(trs) if trs else None, min(ests) if ests else None))
    return out


def rows_from_md(path: Path) -> list[tuple]:
    """The rows of the plot read back from the tables write_md wrote (the
    measured times and errors, no new timing)."""
    from types import SimpleNamespace

    def num(cell: str):
        cell = cell.strip().rstrip("*")
        if cell in ("", "—"):
            return None
        return math.inf if cell == "missed" else float(cell)

    rows, case = [], None
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("### "):
            case = SimpleNamespace(name=line[4:].strip())
        elif case is not None and line.startswith("| 1e"):
            c = [x.strip() for x in line.strip("|").split("|")]
            if len(c) < 9 or c[1] == "failed":         # (another table of the page: not this plot's)
                continue
            t, err, bt, berr = num(c[2]), num(c[3]), num(c[7]), num(c[8])
            rows.append((case, float(c[0]), t / 1000, err, num(c[4]), None, "",
                         bt / 1000 if bt is not None else None, berr, None, c[1]))
    return rows


def plot(rows, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    from dyncli.render.plot import LABEL_PT, LABEL_PX_KEY, series_style, smallest_text_px

    plt.rcParams.update({"font.size": LABEL_PT})
    names = []
    for r in rows:
        if r[0].name not in names:
            names.append(r[0].name)
    fig = plt.figure(figsize=(6.4, 4.75 + 0.2 * (len(names) + 2)), dpi=100)
    ax = fig.add_axes([0.13, 1 - 4.0 / fig.get_figheight(), 0.84, 3.5 / fig.get_figheight()])
    for i, n in enumerate(names):
        col, mk = series_style(i)
        rs = [r for r in rows if r[0].name == n and r[2] is not None]
        ax.loglog([r[2] * 1000 for r in rs], [max(r[3], 1e-17) for r in rs], "-", marker=mk, color=col,
                  markersize=6, label=n)
        bs = [r for r in rs if r[7] is not None and math.isfinite(r[8])]
        if bs:
            ax.loglog([r[7] * 1000 for r in bs], [max(r[8], 1e-17) for r in bs], "--", marker=mk, color=col,
                      markersize=6, markerfacecolor="none", alpha=0.7)
    ax.set_xlabel("time per solver call [ms] (in-process)")
    ax.set_ylabel("true error (max abs vs 50-digit reference)")
    ax.set_title("Work-precision, rtol 1e-3 … 1e-13: dyncli (solid, filled)\nvs a plain scipy script "
                 "(dashed, hollow; same colour and marker)")
    ax.grid(True, which="both", alpha=0.3)
    handles, labels = ax.get_legend_handles_labels()
    handles += [Line2D([], [], color="0.3", linestyle="-", marker="o"),
                Line2D([], [], color="0.3", linestyle="--", marker="o", markerfacecolor="none")]
    labels += ["dyncli", "plain scipy (solve_ivp DOP853 / quad)"]
    fig.legend(handles, labels, loc="upper left", bbox_to_anchor=(0.02, 1 - 4.55 / fig.get_figheight()),
               ncol=1, frameon=False, fontsize=LABEL_PT)
    fig.savefig(path, dpi=100, metadata={"Software": None, LABEL_PX_KEY: f"{smallest_text_px(fig, 100):.2f}"})
    plt.close(fig)


def write_md(rows, summary, path: Path, rtols) -> None:
    """Rewrite the generated part of docs/accuracy.md: from "## Work-precision" to the summary.
    The hand-written parts before it (how to choose `accuracy`, what the numbers guarantee) and
    from "## Cost" on (benchmarks/runner_cost.py, benchmarks/startup_types.py) are kept."""
    old = path.read_text(encoding="utf-8") if path.exists() else "# Accuracy\n"
    head = old.split("\n## Work-precision\n", 1)[0].rstrip("\n") + "\n"
    lines = [
        head,
        "## Work-precision",
        "",
        "![work-precision](accuracy.png)",
        "",
        "Time is per call of the type's solver, in-process (no start-up, YAML or validation; it",
        "includes every other result the type reports; `estimate: false`, so no second solve);",
        "*true error* is the case's error against the reference (tests/accuracy/cases.py: relative",
        "to each quantity's scale where the type's estimate is, else absolute); *est/err* is the",
        "reported `error_estimate` over the true error in the estimate's own terms (≥ 1 means the",
        "estimate is conservative); *nfev* counts",
        "scipy right-hand-side/integrand evaluations, or (\\*) the points at which the problem's",
        "expressions were evaluated on routes with their own quadrature.  *scipy* is the same problem",
        "solved by a plain scipy script (`solve_ivp(method='DOP853')` or `quad`, same rtol/atol);",
        "*missed* means its sign-change event detection stepped over the crossing.",
        "",
    ]
    names = []
    for r in rows:
        if r[0].name not in names:
            names.append(r[0].name)
    for n in names:
        rs = [r for r in rows if r[0].name == n]
        lines += [f"### {n}", "", "| rtol | method | time [ms] | true error | error_estimate | est/err | nfev | "
                  "scipy time [ms] | scipy error | scipy nfev |", "|---|---|---|---|---|---|---|---|---|---|"]
        for case, rtol, t, err, est, nfev, mark, bt, berr, bn, method in rs:
            if t is None:
                lines.append(f"| {rtol:.0e} | failed | | | | | | | | |")
                continue
            ratio = est / case.comparable(err) if est is not None and err > 0 else None
            lines.append(f"| {rtol:.0e} | {method} | {t * 1000:.2f} | {err:.1e} | {fmt(est)} | {fmt(ratio, '.2g')} | "
                         f"{nfev}{mark} | {fmt(bt * 1000 if bt is not None else None, '.2f')} | {fmt(berr)} | "
                         f"{bn if bn is not None else '—'} |")
        lines.append("")
    lines += ["## Summary per route", "", "| route | median time ratio dyncli / scipy | smallest est/err (errors > 1e-13) |", "|---|---|---|"]
    for n, tr, worst in summary:
        lines.append(f"| {n} | {fmt(tr, '.1f')} | {fmt(worst, '.2g')} |")
    lines += ["", "The time ratio includes dyncli's events/queries bookkeeping and every other result of the",
              "type; the plain script does none of these (the cost at equal error is below).  Regenerate with",
              "`python benchmarks/work_precision.py` (about 2 minutes).", ""]
    if "\n## Cost\n" in old:           # written by hand from benchmarks/runner_cost.py and startup_types.py: kept
        lines.append("## Cost\n" + old.split("\n## Cost\n", 1)[1].rstrip("\n") + "\n")
    path.write_text("\n".join(lines), encoding="utf-8")


if __name__ == "__main__":
    main()
