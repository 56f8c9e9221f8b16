"""The notebook API (docs/api.md): ``Solution.units``, the time axis ``t`` in
the results, "did you mean" on a wrong result name, ``to_frame()`` of a
solution and of a sweep, and the NumericalError message.

Reference values: closed forms of the notes, independent of the code —
(17.15a) X = (F0/k)/|D|, D = 1 − r² + 2iζr (problems/vibration/
force-excitation.yaml: X = 1/37 m); ωₙ = √(k/m); and the work-per-force file's
(18.1)/(18.2) values U_gravity(2 s) = −m g x3 = −49.05 J."""

from __future__ import annotations

import math
import sys

import pytest

import dyncli
from tests.conftest import ROOT, run_cli

pd = pytest.importorskip("pandas", reason="pandas is in the test extra (pip install -e '.[test]')")

FORCED = str(ROOT / "problems/vibration/force-excitation.yaml")
SPRING = {"type": "vibration", "m": 1, "k": 400, "zeta": 0.05}
OVER_TIME = ["problems/vibration/underdamped.yaml", "problems/particle/work-per-force.yaml",
             "problems/gyroscopic/top-nutating.yaml", "problems/kinematics/rotating-slot.yaml",
             "problems/rigid-bodies/bearing-forces.yaml", "problems/particle/rotating-slot.yaml"]


@pytest.fixture(scope="module")
def forced():
    return dyncli.solve(FORCED)[0]


def test_units_from_the_declarations(forced):
    from dyncli.registry import TYPES

    spec = TYPES["vibration"]
    assert set(forced.units) == set(forced.results)
    for name, unit in forced.units.items():
        assert unit == ("s" if name == "t" else spec.spec_of(name).unit), name
    assert forced.units["X"] == "m" and forced.units["F_T"] == "N" and forced.units["zeta"] == ""


@pytest.mark.parametrize("path", OVER_TIME)
def test_time_axis_in_every_result_over_time(path):
    sol = dyncli.solve(str(ROOT / path))[0]
    at = [float(t) for t in sol._problem.model.at]
    assert "t" in sol.results and sol.units["t"] == "s"
    assert [float(t) for t in sol["t"]] == at
    series = [n for s in sol._result.series for n in s.names]
    assert series and all(len(sol[n]) == len(at) for n in series if isinstance(sol[n], list))
    assert "t" not in sol.to_dict()["results"] or "t" in sol._result.results    # the JSON record is unchanged


def test_did_you_mean_on_a_wrong_name(forced):
    with pytest.raises(KeyError) as info:
        forced["omega"]
    msg = str(info.value)
    assert msg.startswith("no result 'omega' in this vibration (did you mean 'omega_d', 'omega_n'?)")
    assert "its results: omega_n," in msg
    with pytest.raises(KeyError, match=r"\(did you mean 'F_T'\?\)"):
        forced.results["f_t"]
    with pytest.raises(KeyError) as info:
        forced["zzzz"]
    assert "did you mean" not in str(info.value)
    assert forced.results.get("omega") is None and "omega" not in forced.results


def test_solution_frame_one_row_per_time(forced):
    df = forced.to_frame()
    assert list(df["t"]) == [0.0, 0.5, 1.0, 3.0]
    assert df.columns[0] == "t" and set(df.attrs["units"]) == set(df.columns)
    assert df["x"].tolist() == pytest.approx([0.0, 0.0215438, 0.0217153, 0.0171283], abs=5e-7)
    assert (df["X"] == 1 / 37).all()                              # a closed form: repeated on each row
    assert df.attrs["units"]["x"] == "m" and df.attrs["units"]["v"] == "m/s" and df.attrs["units"]["t"] == "s"
    one = dyncli.solve(SPRING)[0].to_frame()                     # no result over time: one row
    assert len(one) == 1 and one["omega_n"][0] == 20.0


def test_vectors_by_component_and_mappings_by_key():
    sol = dyncli.solve(str(ROOT / "problems/particle/work-per-force.yaml"))[0]
    df = sol.to_frame()
    assert {"x.0", "x.1", "x.2", "work.gravity", "work.motor", "force_terms.motor.2"} <= set(df.columns)
    u = df.attrs["units"]
    assert (u["x.2"], u["work.gravity"], u["power.motor"], u["force_terms.motor.2"]) == ("m", "J", "W", "N")
    row = df[df["t"] == 2.0].iloc[0]
    assert row["work.gravity"] == pytest.approx(-5 * 9.81, rel=1e-9)
    assert row["x.2"] == pytest.approx(1.0, rel=1e-9)
    find = dyncli.solve(str(ROOT / "problems/rectilinear/case4-spring.yaml"))[0].to_frame()
    assert find.attrs["units"]["find.0.t"] == "s" and find.attrs["units"]["find.0.v"] == "m/s"


def test_sweep_is_a_list_with_a_frame():
    sols = dyncli.sweep(SPRING, {"k": [100, 400, 900], "m": [1, 4]})
    assert isinstance(sols, list) and len(sols) == 6 and sols[1:3] == [sols[1], sols[2]]
    df = sols.to_frame()
    assert list(df.columns[:2]) == ["k", "m"] and len(df) == 6
    assert df["omega_n"].tolist() == [math.sqrt(k / m) for k in (100, 400, 900) for m in (1, 4)]
    u = df.attrs["units"]
    assert (u["k"], u["m"], u["omega_n"], u["c"]) == ("N/m", "kg", "rad/s", "N·s/m")


def test_sweep_long_frame_and_several_problems():
    sols = dyncli.sweep(FORCED, {"zeta": [0.1, 0.2]})
    assert len(sols) == 4                                          # 2 problems x 2 points
    df = sols.to_frame()
    assert list(df.columns[:2]) == ["problem", "zeta"] and df["problem"].tolist() == [0, 0, 1, 1]
    long = sols.to_frame(long=True)
    assert len(long) == 2 * 4 + 2 * 3                              # the times of each problem's `at`
    assert list(long.columns[:3]) == ["problem", "zeta", "t"] and long.attrs["units"]["t"] == "s"
    m, k, f0, w = 2.0, 800.0, 10.0, 15.0
    r = w / math.sqrt(k / m)
    for zeta in (0.1, 0.2):
        rows = long[(long["problem"] == 0) & (long["zeta"] == zeta)]
        assert len(rows) == 4
        assert (rows["X"] == rows["X"].iloc[0]).all()
        assert rows["X"].iloc[0] == pytest.approx(f0 / k / math.hypot(1 - r * r, 2 * zeta * r), rel=1e-13)


def test_swept_paths_carry_their_field_units():
    sols = dyncli.sweep({"type": "particle", "m": 1, "v0": [1, 0, 0], "at": [0, 1]},
                        {"v0.1": [1, 2], "m": [1, 2]}, forces=[{"kind": "spring", "k": 4}])
    u = sols.to_frame().attrs["units"]
    assert (u["v0.1"], u["m"]) == ("m/s", "kg")
    u = dyncli.sweep(FORCED, {"force.omega": [10, 20]}).to_frame().attrs["units"]
    assert u["force.omega"] == "rad/s"


def test_no_pandas_is_an_import_error_naming_the_extra(monkeypatch, forced):
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=r"optional extra 'frames': pip install 'dyncli\[frames\]'"):
        forced.to_frame()
    with pytest.raises(ImportError, match="dyncli.frames"):
        dyncli.sweep(SPRING, {"k": [1]}).to_frame()


def test_numerical_error_names_the_source_once(tmp_path):
    spring = {"type": "particle", "m": 1, "v0": [1, 0, 0], "forces": [{"kind": "spring", "k": 100}],
              "t_end": 100, "accuracy": {"max_steps": 200}}
    import yaml

    text = yaml.safe_dump(spring)
    for source, start in ((spring, "<dict>: numerical step failed: "), (text, "<text>:1:1: numerical step failed: "),
                          ({**spring, "title": "Spring"}, "<dict>: Spring: numerical step failed: ")):
        with pytest.raises(dyncli.NumericalError) as info:
            dyncli.solve(source)
        assert str(info.value).startswith(start), str(info.value)
        assert "\n" not in str(info.value)
    path = tmp_path / "budget.yaml"
    path.write_text(text)
    rc, _, err = run_cli("solve", str(path))
    with pytest.raises(dyncli.NumericalError) as info:
        dyncli.solve(path)
    assert rc == 1 and err.strip() == str(info.value)             # the CLI's one line
    assert str(info.value).startswith(f"{path}:1:1: numerical step failed: the run to t = 100 s")


def test_xarray_of_a_sweep_over_time():
    pytest.importorskip("xarray", reason="xarray is in the test extra (pip install -e '.[test]')")
    omegas = [10.0, 15.0, 30.0]
    sols = dyncli.sweep(FORCED, {"zeta": [0.05, 0.1], "force.omega": omegas})
    with pytest.raises(dyncli.InputError, match=r"pick one with to_xarray\(problem=0\)"):
        sols.to_xarray()
    ds = sols.to_xarray(problem=0)
    assert dict(ds.sizes) == {"zeta": 2, "force.omega": 3, "t": 4}
    assert ds["x"].dims == ("zeta", "force.omega", "t") and ds["X"].dims == ("zeta", "force.omega")
    assert ds["t"].values.tolist() == [0.0, 0.5, 1.0, 3.0]
    assert (ds["x"].attrs["units"], ds["X"].attrs["units"], ds["force.omega"].attrs["units"]) == ("m", "m", "rad/s")
    assert "zeta" not in ds.data_vars                              # a swept input is the coordinate only
    m, k, f0 = 2.0, 800.0, 10.0
    for zeta in (0.05, 0.1):
        for w in omegas:
            r = w / math.sqrt(k / m)
            want = f0 / k / math.hypot(1 - r * r, 2 * zeta * r)        # (17.15a)
            assert float(ds["X"].sel(zeta=zeta, **{"force.omega": w})) == pytest.approx(want, rel=1e-13)
    one = next(s for s in sols if s.index == 0 and s.swept == {"zeta": 0.1, "force.omega": 15.0})
    assert ds["x"].sel(zeta=0.1, **{"force.omega": 15.0}).values.tolist() == one["x"]
    assert one["x"] == pytest.approx([0.0, 0.0215438, 0.0217153, 0.0171283], abs=5e-7)   # the file's values


def test_xarray_mapping_results_and_a_swept_param():
    pytest.importorskip("xarray")
    ds = dyncli.sweep(str(ROOT / "problems/particle/work-per-force.yaml"), {"params.mass": [1, 5]}).to_xarray(problem=0)
    u = ds["work.gravity"]
    assert u.dims == ("params.mass", "t") and u.attrs["units"] == "J"
    assert u.sel(t=2.0).values.tolist() == pytest.approx([-9.81, -49.05], rel=1e-9)   # −m g x3, x3(2 s) = 1 m


def test_a_scenes_motion_and_forces_are_rows_over_time():
    """A scene's results over the times of `at` — each body's position and angle, each joint's
    forces, the distance — are a frame's rows (one per time, the column t), as the energies
    always were; before, they were spread into a column per time copied onto every row (the row
    t = 0.25 carried the angle of t = 0).  The values are the result lists themselves; the units
    come with them (N for a wall's normal force, m for a position); the tables are unchanged."""
    pytest.importorskip("pandas")
    sol = dyncli.solve(str(ROOT / "problems" / "scenes" / "sliding-ladder.yaml"))[0]
    df = sol.to_frame()
    r = sol.results
    assert list(df["t"]) == r["t"]
    assert list(df["angle.rod"]) == r["angle"]["rod"]
    assert [row for row in df[["x.rod.0", "x.rod.1"]].itertuples(index=False, name=None)] == \
        [tuple(x[:2]) for x in r["x"]["rod"]]
    assert list(df["reaction.at_wall.N"]) == r["reaction"]["at_wall"]["N"]
    assert "angle.rod.1" not in df.columns
    assert df.attrs["units"]["reaction.at_wall.N"] == "N" and df.attrs["units"]["x.rod.0"] == "m"


def test_a_sweeps_index_is_numbers_its_peak_marks_are_the_tables():
    """A vibration's frequency sweep marks the point nearest each peak in its tables (◀ G max);
    the frame's column r holds the numbers themselves (before: '1 ◀ G max ◀ g max' in one cell,
    so the column could not be read as floats)."""
    pd = pytest.importorskip("pandas")
    sol = dyncli.solve(str(ROOT / "problems" / "vibration" / "sweep.yaml"))[0]
    df = sol.to_frame()
    assert pd.api.types.is_float_dtype(df["r"]), df["r"].tolist()
    assert list(df["r"]) == sol.results["sweep_r"]
    code, out, err = run_cli("solve", str(ROOT / "problems" / "vibration" / "sweep.yaml"))
    assert code == 0 and "◀ G max" in out, err
