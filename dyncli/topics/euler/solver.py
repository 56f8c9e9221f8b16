"""Euler's equations (39.5) and the torque-free body (notes §39) — the adapter: the validated
model as plain inputs (:class:`dyncli.topics.euler.motion.Body`), solved by
:func:`dyncli.topics.euler.motion.solve` (the exact torque-free solution, :mod:`.free`, or the
integration of :mod:`.integrated`)."""

from __future__ import annotations

from dyncli.result import Result, SolveOptions
from dyncli.topics.euler import motion


def plain(pb) -> motion.Body:
    """The body's principal moments (given, or the coin's, 39.10), ω'₀, M, the times and the
    accuracy controls as plain values."""
    a = pb.accuracy
    return motion.Body(tuple(float(v) for v in pb.moments()), tuple(float(v) for v in pb.omega0),
                       None if pb.M is None else tuple(pb.M), tuple(float(t) for t in pb.at), a.method,
                       a.rtol, a.atol, a.max_steps, a.estimate, pb.coin is not None)


def solve(pb, options: SolveOptions | None = None) -> Result:
    end = None
    if pb.find:
        from dyncli.motion_find import find_end

        end = find_end(pb)
    return motion.solve(plain(pb), options, search_end=end)
