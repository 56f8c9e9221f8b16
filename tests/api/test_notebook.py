"""docs/notebook.ipynb runs headless in a Jupyter kernel (nbclient, ipykernel,
matplotlib's Agg backend): it solves, sweeps to a DataFrame, plots and shows a
solution.  Skipped only when no kernel can start on this machine.

A check cell appended here (not in the notebook) reports the DataFrame's
columns and units and the plot's curves; the values are checked against the
closed form of the notes (17.15a): X = (F0/k)/|D|, D = 1 − r² + 2iζr."""

from __future__ import annotations

import json
import math

import nbclient
import nbformat
import pytest

from tests.conftest import ROOT

NOTEBOOK = ROOT / "docs" / "notebook.ipynb"
CHECK = """import io, json
buf = io.BytesIO(); fig.savefig(buf, format="png")
print(json.dumps({"columns": list(df.columns), "units": df.attrs["units"], "rows": len(df),
                  "curves": [[list(map(float, l.get_xdata())), list(map(float, l.get_ydata())), l.get_label()]
                             for l in ax.lines],
                  "xlabel": ax.get_xlabel(), "ylabel": ax.get_ylabel(), "png": buf.tell(),
                  "t": sol["t"], "frame_t": sol.to_frame()["t"].tolist()}))"""


@pytest.fixture(scope="module")
def executed(_env):
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell(CHECK))
    client = nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(NOTEBOOK.parent)}})
    client.reset_execution_trackers()
    kernel = client.setup_kernel()
    try:
        kernel.__enter__()
    except Exception as exc:  # noqa: BLE001 - any reason the kernel cannot start: say it and skip
        pytest.skip(f"no Jupyter kernel could start here ({type(exc).__name__}: {exc})")
    try:
        for i, cell in enumerate(nb.cells):
            client.execute_cell(cell, i)
    finally:
        kernel.__exit__(None, None, None)
    return nb


@pytest.fixture(scope="module")
def _env():
    mp = pytest.MonkeyPatch()
    mp.setenv("MPLBACKEND", "Agg")                       # headless
    mp.setenv("PYTHONPATH", str(ROOT))                   # the kernel imports this checkout's dyncli
    yield
    mp.undo()


def _report(nb) -> dict:
    out = nb.cells[-1].outputs
    text = "".join(o.get("text", "") for o in out if o.get("output_type") == "stream" and o.get("name") == "stdout")
    return json.loads(text)


def test_every_cell_runs_without_error(executed):
    errors = [o for c in executed.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert not errors, errors
    code = [c for c in executed.cells if c.cell_type == "code"]
    assert all(c.execution_count for c in code)


def test_the_solution_displays_as_tables(executed):
    shown = next(c for c in executed.cells if c.cell_type == "code" and c.source.strip().endswith("\nsol"))
    data = next(o.data for o in shown.outputs if o.output_type == "execute_result")
    assert "<table>" in data["text/html"] and "Force-excited spring-mass-damper" in data["text/html"]


def test_dataframe_columns_and_units(executed):
    r = _report(executed)
    assert r["rows"] == 3 * 141
    assert r["columns"][:2] == ["zeta", "force.omega"]          # the swept paths first, in sweep order
    for c in ("omega_n", "c", "r", "X", "phi", "F_T", "magnification", "transmissibility"):
        assert c in r["columns"]
    assert set(r["units"]) == set(r["columns"])
    expected = {"zeta": "", "force.omega": "rad/s", "omega_n": "rad/s", "c": "N·s/m", "r": "", "X": "m",
                "phi": "rad", "F_T": "N", "magnification": "", "transmissibility": ""}
    assert {c: r["units"][c] for c in expected} == expected
    assert r["t"] == r["frame_t"] == [0.0, 0.5, 1.0, 3.0]


def test_the_plot_is_the_resonance_curves(executed):
    r = _report(executed)
    assert r["xlabel"] == "ω [rad/s]" and r["ylabel"] == "X [m]" and r["png"] > 1000
    assert [c[2] for c in r["curves"]] == ["ζ = 0.05", "ζ = 0.1", "ζ = 0.2"]
    m, k, f0 = 2.0, 800.0, 10.0
    wn = math.sqrt(k / m)
    for (xs, ys, _), zeta in zip(r["curves"], (0.05, 0.1, 0.2)):
        assert len(xs) == 141
        for w, x in zip(xs, ys):
            rr = w / wn
            assert x == pytest.approx(f0 / k / math.hypot(1 - rr * rr, 2 * zeta * rr), rel=1e-12)
