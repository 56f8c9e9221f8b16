"""A bead's motion along its curve reported at given states (notes §16 problem II, §18, §20), for
every route that makes one: the energy quadrature (``quadrature.py``), the ODE (``solver.py``) and
the ``find`` queries (``find.py``).

:func:`assemble` turns the states (q, q̇, …) into the results named in :data:`SERIES` (the arc
length by :func:`arc_length`); :func:`equation_numbers` lists the notes' equations they use.
"""

from __future__ import annotations

import numpy as np

SERIES = ["q", "q_dot", "s", "s_dot", "x", "v", "a", "N", "N_vec", "friction", "kappa", "T", "V", "E", "W_nc", "W_N"]


def _vec(a) -> list[float]:
    return [float(c) + 0.0 for c in np.asarray(a, float)]


def _cols(a) -> list[list[float]]:
    """The columns of a (3, n) array as lists of floats (−0.0 as 0.0, as :func:`_vec`)."""
    return (np.asarray(a, float).T + 0.0).tolist()


def _dot3(a, b):
    """The dot products of the columns of two (3, n) arrays, each summed in order (a₁b₁ + a₂b₂) + a₃b₃:
    the doubles of ``a[:, j] @ b[:, j]``, all columns at once."""
    return (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2]


def arc_length(curve, q0, qs):
    """s(q) = ∫ |y'| dq from q0 to each q (QUADPACK to 1e-13 of each, the speed in plain floats)."""
    from dyncli.quadrature import quad

    sp = curve.speed
    return [quad(sp, q0, q, limit=200, epsabs=0, epsrel=1e-13)[0] + 0.0 if q != q0 else 0.0 for q in qs]


def assemble(p, model, times, Y, modes) -> dict:
    """The reported results at the states Y (one mode per state): q, q̇, φ, W̄, W_N and, when it
    is carried (the ODE route's 6th row), the arc length s, else s by :func:`arc_length`."""
    n = Y.shape[1]
    groups: dict = {}                       # the states of each mode, evaluated together
    for j, md in enumerate(modes):
        groups.setdefault(tuple(md), []).append(j)
    ts = np.asarray(times, float)
    cat: dict = {}
    Q = np.empty((n, 3, 3))
    for md, idx in groups.items():
        e = model.evaluate(ts[idx], Y[:, idx], md)
        for k in ("x", "v", "a", "N", "ft", "et", "speed", "y1", "y2"):
            if k not in cat:
                cat[k] = np.empty(np.shape(e[k])[:-1] + (n,))
            cat[k][..., idx] = e[k]
        Q[idx] = e["Q"]
    # where the curve is straight e_n is the documented fallback direction (no warning: nothing to act on)
    et, en, eb, kappa, _straight = model.curve.frenet(Y[0], Q, cat["y1"], cat["y2"])
    N = cat["N"]
    m = model.m
    T = 0.5 * m * np.sum(cat["v"] ** 2, axis=0)
    V = model.potential(cat["x"])
    qd = np.array([0.0 if md[0] == "stick" else Y[1, j] for j, md in enumerate(modes)])
    r = {
        "q": [float(v) + 0.0 for v in Y[0]],
        "q_dot": [float(v) + 0.0 for v in qd],
        "s": ([float(v) + 0.0 for v in Y[5]] if Y.shape[0] > 5 else
              arc_length(model.curve, float(p.q0), [float(v) for v in Y[0]])),
        "s_dot": [float(v) + 0.0 for v in cat["speed"] * qd],
        "x": _cols(cat["x"]), "v": _cols(cat["v"]), "a": _cols(cat["a"]),
        "N": [[0.0, a + 0.0, b + 0.0] for a, b in zip(_dot3(N, en).tolist(), _dot3(N, eb).tolist())],
        "N_vec": _cols(N + cat["ft"] * cat["et"]),
        "friction": [float(v) + 0.0 for v in cat["ft"]],
        "kappa": [float(v) for v in kappa],
        "T": [float(v) for v in T], "V": [float(v) + 0.0 for v in V], "E": [float(v) + 0.0 for v in T + V],
        "W_nc": [float(v) + 0.0 for v in Y[3]], "W_N": [float(v) + 0.0 for v in Y[4]],
    }
    return {"results": r}


def equation_numbers(model) -> list[str]:
    eq = ["16.7", "11.11", "18.4", "18.6"]
    if model.mu:
        eq.append("19.27")
    eq += ["20.3", "20.4", "20.5"]
    return eq
