"""Plots of ``scene`` problems (``dyncli solve --plot``).

* the mechanism drawn at each requested time (rods as lines, disks and rings as circles with
  a radius marking their turn, boxes as rectangles, points as markers, the surfaces as lines,
  a surface carried by a body with its body at each time, fixed pulleys as circles, the cords
  dashed from tangent point to tangent point, a string over round pegs with its wound arcs);
* the joint forces over time (each scalar force, each pin force's components), sampled from
  the solver's trajectory (``result.extra["scene_sample"]``: the exact motion, or the
  interpolants of the integration's own steps; nothing is solved again), with the events marked.
"""

from __future__ import annotations

import math

from dyncli.result import Line, Plot

SAMPLES = 400


def _outline(body: dict, x, angle) -> list[tuple[list, list]]:
    """Polylines of one body at one instant (fixed-basis coordinates)."""
    c, s = (math.cos(angle), math.sin(angle)) if angle is not None else (1.0, 0.0)

    def at(p1, p2):
        return x[0] + c * p1 - s * p2, x[1] + s * p1 + c * p2

    shape = body["shape"]
    if body.get("radius"):            # a round body (disk, ring, sphere, shell, cylinder) or I with a radius
        shape = "disk"
    if shape == "rod":
        h = body["length"] / 2
        (a1, a2), (b1, b2) = at(-h, 0), at(h, 0)
        return [([a1, b1], [a2, b2])]
    if shape in ("disk", "ring"):
        R = body["radius"]
        pts = [at(R * math.cos(2 * math.pi * k / 48), R * math.sin(2 * math.pi * k / 48)) for k in range(49)]
        e = at(R, 0)
        return [([p[0] for p in pts], [p[1] for p in pts]), ([x[0], e[0]], [x[1], e[1]])]
    if shape == "box":
        a, b = body["size"][0] / 2, body["size"][1] / 2
        pts = [at(*p) for p in ((-a, -b), (a, -b), (a, b), (-a, b), (-a, -b))]
        return [([p[0] for p in pts], [p[1] for p in pts])]
    return [([x[0]], [x[1]])]


def _mechanism(result, draw) -> Plot:
    r = result.results
    plot = Plot("the mechanism at the requested times", "x1 [m]", "x2 [m]", equal_aspect=True)
    span = draw["span"]
    for s in draw["surfaces"]:
        if "corner" in s:               # a corner: a marker, and a stroke along each face
            (c1, c2), h = s["corner"], 0.2 * span
            xs, ys = [c1], [c2]
            for i, (f1, f2) in enumerate(s["faces"]):
                xs, ys = ([c1 + h * f1, *xs], [c2 + h * f2, *ys]) if i == 0 else ([*xs, c1 + h * f1], [*ys, c2 + h * f2])
            plot.lines.append(Line(xs, ys, label=f"corner {s['name']}", style="-", marker="^" if not s["faces"] else None))
            continue
        if "points" in s:               # a curve: its polyline
            plot.lines.append(Line([p[0] for p in s["points"]], [p[1] for p in s["points"]],
                                   label=f"surface {s['name']}", style=":"))
            continue
        (o1, o2), (d1, d2) = s["origin"], s["d"]
        if s.get("length") is not None:     # from its `through` point to its end
            a, b = 0.0, float(s["length"])
        else:                               # ±span, and past every body drawn on it
            along = [(x[0] - o1) * d1 + (x[1] - o2) * d2 for xs in r.get("x", {}).values() for x in xs
                     if x is not None]
            a, b = min([-span, *along]) - 0.1 * span, max([span, *along]) + 0.1 * span
        plot.lines.append(Line([o1 + a * d1, o1 + b * d1], [o2 + a * d2, o2 + b * d2],
                               label=f"surface {s['name']}", style=":"))
    for (c1, c2), rad in draw["pulleys"]:
        k = range(33)
        plot.lines.append(Line([c1 + max(rad, span * 0.01) * math.cos(2 * math.pi * i / 32) for i in k],
                               [c2 + max(rad, span * 0.01) * math.sin(2 * math.pi * i / 32) for i in k], style="-"))
    cords = draw.get("cords") or []
    for j, t in enumerate(r.get("t", [])):
        first = True
        for n, pts in enumerate((cords[j] if j < len(cords) else None) or ()):     # the cords: dashed
            plot.lines.append(Line([p[0] for p in pts], [p[1] for p in pts],
                                   label="cords" if j == 0 and n == 0 else None, style="--", marker=""))
        for sf in draw.get("carried", ()):           # a carried line or curve, placed with its body
            x = r["x"][sf["carrier"]][j]
            if x is None:
                continue
            ang = r["angle"].get(sf["carrier"], [None] * (j + 1))[j] or 0.0
            c, s = math.cos(ang), math.sin(ang)
            plot.lines.append(Line([x[0] + c * p1 - s * p2 for p1, p2 in sf["points"]],
                                   [x[1] + s * p1 + c * p2 for p1, p2 in sf["points"]],
                                   label=f"t = {t:g} s" if first else None, style=":"))
            first = False
        for name, body in draw["bodies"].items():
            x = r["x"][name][j]
            if x is None:
                continue
            ang = r["angle"].get(name, [None] * (j + 1))[j]
            for xs, ys in _outline(body, x, ang):
                point = len(xs) == 1
                plot.lines.append(Line(xs, ys, label=f"t = {t:g} s" if first else None,
                                       style="" if point else "-", marker="o" if point else None))
                first = False
    return plot


def _forces(result, sample) -> Plot | None:
    r = result.results
    t_end = result.extra.get("scene_t_end", 0.0)
    if not t_end > 0:
        return None
    ts = [t_end * k / (SAMPLES - 1) for k in range(SAMPLES)]
    series: dict[str, list] = {}
    for t in ts:
        st = sample(t)
        for j, rep in (st or {}).get("reaction", {}).items():
            for name, v in rep.items():
                comps = [("", v)] if not isinstance(v, list) else (
                    [(f"[{i}]", c) for i, c in enumerate(v)] if name == "T" else [(".1", v[0]), (".2", v[1])])
                for suffix, c in comps:
                    series.setdefault(f"{j} {name}{suffix}", []).append((t, c))
    if not series:
        return None
    plot = Plot("joint forces over time", "t [s]", "force [N]")
    for label, pts in series.items():
        plot.lines.append(Line([p[0] for p in pts], [p[1] for p in pts], label=label))
    plot.vlines = [(ev["t"], f"{ev['joint']} {ev['what']}") for ev in r.get("events", [])]
    return plot


def plots(problem, result) -> list[Plot]:
    draw = result.extra.get("scene_draw")
    if draw is None:
        return []
    out = [_mechanism(result, draw)]
    sample = result.extra.get("scene_sample")
    if sample is not None:
        f = _forces(result, sample)
        if f is not None:
            out.append(f)
    return out
