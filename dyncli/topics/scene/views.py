"""The tables a student reads next to the notes: views that only read a scene's results.

One row per requested time and body (centre x, v, a; angle, ω, α), per named point, per joint
force (in the joint's own terms), per drive and named load; the events with the coordinates at
their instant; the ``find`` answers with the quantity each query asked about.  The raw nested
results stay in JSON, YAML and CSV.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from dyncli.result import Table

COVERED = ["x", "v", "a", "angle", "omega", "alpha", "point", "reaction", "drive", "force", "events", "phases",
           "impacts", "find"]


def _xy(v):
    return None if v is None else [v[0], v[1]]


def _z(v):
    return None if v is None else v[2]


def views(res) -> list[Table]:
    r = res.results
    times = r.get("t", [])
    out = [_bodies(r, times)]
    pts = _points(r, times)
    if pts.rows:
        out.append(pts)
    forces = _forces(r, times)
    if forces.rows:
        out.append(forces)
    if r.get("events"):
        out.append(_events(r))
    if len(r.get("phases") or []) > 1:
        out.append(_phases(r))
    if r.get("impacts"):
        out.append(_impacts(r))
    if r.get("find"):
        out.append(_find(r))
    return out


def _bodies(r, times) -> Table:
    rows = []
    for k, t in enumerate(times):
        for b in r["x"]:
            rigid = b in r["angle"]
            rows.append([t, b, _xy(r["x"][b][k]), _xy(r["v"][b][k]), _xy(r["a"][b][k]),
                         r["angle"][b][k] if rigid else "", _z(r["omega"][b][k]) if rigid else "",
                         _z(r["alpha"][b][k]) if rigid else ""])
    return Table("bodies (centres on e1, e2)", ["t [s]", "body", "x̄ [m]", "v̄ [m/s]", "ā [m/s²]", "θ [rad]",
                                                "ω [rad/s]", "α [rad/s²]"], rows)


def _points(r, times) -> Table:
    rows = []
    for k, t in enumerate(times):
        for b, pts in r["point"].items():
            for p, d in pts.items():
                rows.append([t, f"{b}.{p}", _xy(d["x"][k]), _xy(d["v"][k]), _xy(d["a"][k])])
    return Table("points", ["t [s]", "point", "x [m]", "v [m/s]", "a [m/s²]"], rows)


def _forces(r, times) -> Table:
    cols: list[str] = []
    getters: list[Callable[..., Any]] = []          # k -> the column's value at times[k]
    for j, rep in r["reaction"].items():
        for name in rep:
            unit = "N·m" if name == "M" else "N"
            cols.append(f"{j} {name} [{unit}]")
            conv = _xy if name == "R" else _z if name == "M" else (lambda v: v)
            getters.append(lambda k, j=j, name=name, conv=conv: conv(r["reaction"][j][name][k]))
    for d in r["drive"]:
        cols.append(f"drive {d}")
        getters.append(lambda k, d=d: r["drive"][d][k])
    for f in r["force"]:
        cols.append(f"force {f}")
        getters.append(lambda k, f=f: (lambda v: _xy(v) if isinstance(v, list) else v)(r["force"][f][k]))
    rows = [[t] + [g(k) for g in getters] for k, t in enumerate(times)] if cols else []
    return Table("joint forces (on the first-named body, by the second) and loads", ["t [s]"] + cols, rows,
                 note="pin R on e1, e2; a cord's T per straight segment, in order; drive: the driver's force [N] "
                      "or couple [N·m]")


def _coords(state) -> list:
    out = []
    for b, x in state["x"].items():
        out.append(f"{b}: x̄ = {_fmt(_xy(x))}")
        if b in state["angle"]:
            out.append(f"θ = {_fmt(state['angle'][b])}")
    return out


def _fmt(v) -> str:
    if isinstance(v, list):
        return "[" + ", ".join(_fmt(x) for x in v) + "]"
    return f"{v + 0.0:.6g}"


def _events(r) -> Table:
    rows = [[e["t"], e["joint"], e["what"], ", ".join(_coords(e["state"]))] for e in r["events"]]
    return Table("events", ["t [s]", "joint", "what", "state (events.N.state holds every result)"], rows)


def _phases(r) -> Table:
    rows = [[p["t_start"], p["t_end"], ", ".join(p["joints"]) or "—", p["route"]] for p in r["phases"]]
    return Table("phases (the joints made in each)", ["from [s]", "to [s]", "joints", "route"], rows)


def _impacts(r) -> Table:
    rows = [[i["t"], i["joint"], i["e"], i["impulse"], i["impulse_F"], i["v_n_before"], i["v_n_after"],
             i["energy_loss"], i.get("course") or "—"] for i in r["impacts"]]
    return Table("impacts (28.7, 28.16, 33.2)", ["t [s]", "joint", "e", "impulse [N·s]", "friction [N·s]",
                                                 "v_n before [m/s]", "v_n after [m/s]", "energy lost [J]",
                                                 "slip"], rows)


def _find(r) -> Table:
    rows = []
    for i, f in enumerate(r["find"]):
        rows.append([i, f.get("t"), f.get("reached"), f.get("at_end"), ", ".join(_coords(f)) if f.get("reached") else "—"])
    return Table("find", ["#", "t [s]", "reached", "at end", "state (find.N holds every result)"], rows)


def equilibria(eqs) -> list[Table]:
    """One row per equilibrium (its coordinates, stability, ω² and frequencies) and one per mode."""
    rows, mrows = [], []
    for i, e in enumerate(eqs):
        coords = ", ".join(f"{c} = {_fmt(v)}" for c, v in zip(e["coordinates"], e["values"]))
        rows.append([i, coords, e["stability"], _fmt(e["omega2"]),
                     "—" if e["frequencies"] is None else _fmt(e["frequencies"]),
                     "—" if e["frequencies_hz"] is None else _fmt(e["frequencies_hz"])])
        for r, u in enumerate(e["modes"]):
            mrows.append([i, r + 1, "—" if e["frequencies"] is None else e["frequencies"][r],
                          ", ".join(f"{c}: {_fmt(x)}" for c, x in zip(e["coordinates"], u))])
    out = [Table("equilibria (rest configurations; stability from the reduced stiffness)",
                 ["#", "coordinates", "stability", "ω² [1/s²]", "ω [rad/s]", "f [Hz]"], rows)]
    if mrows:
        out.append(Table("mode shapes (first non-zero component 1)", ["equilibrium", "mode", "ω [rad/s]", "shape"],
                         mrows))
    drows = [[i, f"{z[0]:.6g} {'+' if z[1] >= 0 else '−'} {abs(z[1]):.6g} i", wd, zeta]
             for i, e in enumerate(eqs) if e.get("damped")
             for z, wd, zeta in zip(e["damped"]["eigenvalues"], e["damped"]["frequencies"], e["damped"]["damping_ratios"])]
    if drows:
        out.append(Table("damped (complex) modes: λ = −ζω ± iω_d", ["equilibrium", "λ [1/s]", "ω_d [rad/s]", "ζ"],
                         drows))
    return out
