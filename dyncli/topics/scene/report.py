"""The results of a scene at one instant, and over the requested times (docs/types/scene.md).

Per body x, v, a (3-vectors on e_i) and, for a rigid body, angle, ω, α (ω and α as
[0, 0, ·]); per named point its x, v, a; per joint its forces in the joint's own terms; per
drive the force or couple of the driver; per named load its force; T, V, E, W_nc and the
energy residual E − E₁ − W_nc (34.20, with the work of the non-conservative loads integrated
along the motion).
"""

from __future__ import annotations
from dyncli.motion_find import flatten  # noqa: F401 (the one flattening of an instant's results)


def _v3(a) -> list:
    return [float(a[0]) + 0.0, float(a[1]) + 0.0, 0.0]


def _w3(w) -> list:
    return [0.0, 0.0, float(w) + 0.0]


def instant(system, q, v, W, t, E1: float, skip_points: bool = False, solved=None) -> dict:
    a, lam, _ = solved if solved is not None else system.solve(q, v, t)
    out: dict = {"x": {}, "v": {}, "a": {}, "angle": {}, "omega": {}, "alpha": {}, "point": {},
                 "reaction": {}, "drive": {}, "force": {}}
    from .system import Point

    for b in system.bodies:
        i = b.index
        out["x"][b.name] = _v3((q[i[0]], q[i[1]]))
        out["v"][b.name] = _v3((v[i[0]], v[i[1]]))
        out["a"][b.name] = _v3((a[i[0]], a[i[1]]))
        if b.rigid:
            out["angle"][b.name] = float(q[i[2]]) + 0.0
            out["omega"][b.name] = _w3(v[i[2]])
            out["alpha"][b.name] = _w3(a[i[2]])
            pts = {}
            for pname, p in b.points.items():
                if pname == "center":
                    continue
                P = Point(pname, b, p)
                acc = P.jac(q, system.n) @ a + P.bias(q, v)
                pts[pname] = {"x": _v3(P.pos(q)), "v": _v3(P.vel(q, v)), "a": _v3(acc)}
            if pts:
                out["point"][b.name] = pts
    for k, e in enumerate(system.elements):
        if e.kind == "guide":
            continue
        rep = e.report(system.lam_of(lam, k), q, v, t)
        if e.kind == "drive":
            out["drive"][e.name] = rep["drive"]
        else:
            out["reaction"][e.name] = rep
    for ld in system.loads:
        if ld.name:
            out["force"][ld.name] = ld.generalized(q, v, t, system.n)[2]
    T, V = system.kinetic(v), system.potential(q)
    E = T + V
    out.update({"T": T, "V": V, "E": E, "W_nc": float(W), "energy_residual": E - E1 - float(W)})
    return out


PER_TIME = ("x", "v", "a", "angle", "omega", "alpha", "point", "reaction", "drive", "force",
            "T", "V", "E", "W_nc", "energy_residual")


def collect(instants: list, shape: dict | None = None) -> dict:
    """Instants (dicts, or None after a stopping event) -> the same nesting with a list over
    the times at every leaf (a vector or a segment list is a leaf); ``shape``: an instant whose
    nesting to use when every time asked is past the stop (its leaves all None then)."""
    template = next((s for s in instants if s is not None), shape)
    if template is None:
        return {}

    def build(node, getter):
        if isinstance(node, dict):
            return {k: build(v, lambda s, k=k, g=getter: None if g(s) is None else g(s).get(k)) for k, v in node.items()}
        return [getter(s) for s in instants]

    return {k: build(template[k], lambda s, k=k: None if s is None else s.get(k)) for k in PER_TIME}


