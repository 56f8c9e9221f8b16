"""dyncli's own DOP853 stepper: scipy's ``DOP853`` step for step, without importing scipy.

A student's script that integrates one problem pays ``import scipy.integrate`` (about 0.3 s of
CPU: it loads ``scipy.special``, ``scipy.optimize`` and more); dyncli's explicit routes use only
the DOP853 stepper, its dense output and a piecewise interpolant.  This module is those three,
the same algorithm as scipy's ``scipy/integrate/_ivp`` (``rk.py``, ``base.py``, ``common.py``;
BSD-3-Clause, Copyright (c) the SciPy Developers) written with the same floating-point
operations in the same order, so that a run is bit-identical to scipy's (``tests/
test_dop853.py`` compares every step, state and interpolated value with the installed scipy):

* :class:`DOP853` — the explicit Runge-Kutta 8(5,3) pair of Dormand and Prince with Hairer's
  error estimator and step-size control (safety 0.9, factors 0.2 … 10, exponent −1/8), the
  starting step of Hairer, Nørsett & Wanner (II.4) capped by the interval and ``max_step``;
  the public interface of scipy's ``OdeSolver`` that :mod:`dyncli.ode` steps (``step``,
  ``dense_output``, ``t``, ``y``, ``t_old``, ``f``, ``status``, ``nfev``, ``direction``, ``n``).
* :class:`DenseOutput` — the 7th-degree interpolant of one step (3 extra stages).
* :class:`OdeSolution` — consecutive steps' interpolants as one function of t.

Only scipy's ``solve_ivp`` driver (event location, used by routes that ask it for events) still
takes scipy's own classes (:func:`dyncli.integrators.solver_class` with ``scipy=True``).
"""

from __future__ import annotations

import math

import numpy as np

from dyncli import dop853_coefficients as dc

SAFETY = 0.9        # multiplies the step size the error's asymptotics suggest
MIN_FACTOR = 0.2    # the smallest decrease of a step size
MAX_FACTOR = 10     # the largest increase
EPS = np.finfo(float).eps


def norm(x):
    """The RMS norm of the step-size control."""
    return np.linalg.norm(x) / x.size ** 0.5


def select_initial_step(fun, t0, y0, t_bound, max_step, f0, direction, order, rtol, atol, controlled=None):
    """The starting step (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.4), no longer than the
    interval or ``max_step``; ``controlled``: the norms over the first that many components only
    (None: all, as scipy)."""
    interval_length = abs(t_bound - t0)
    if interval_length == 0.0:
        return 0.0
    c = slice(controlled)
    scale = atol + np.abs(y0[c]) * rtol
    d0 = norm(y0[c] / scale)
    d1 = norm(f0[c] / scale)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, interval_length)
    y1 = y0 + h0 * direction * f0
    f1 = fun(t0 + h0 * direction, y1)
    d2 = norm((f1[c] - f0[c]) / scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1 / (order + 1))
    return min(100 * h0, h1, interval_length, max_step)


class DOP853:
    """Explicit Runge-Kutta 8(5,3) of Dormand and Prince (scipy's ``DOP853``, same steps).

    ``controlled`` (dyncli's, not scipy's; None by default: scipy's steps): only the first that
    many components of the state enter the error norm of the step-size control and of the
    starting step.  The rest are carried by the same stages without steering the steps: for
    integrals of the motion's own quantities such as a work ∫ P dt or an arc length ∫ ṡ dt,
    which are quadratures of the controlled state (their error is of the order of the
    controlled components' own), so that carrying them costs no extra steps (and a component
    that is exact, such as φ = ω t, does not dilute the norm)."""

    n_stages = dc.N_STAGES
    order = 8
    error_estimator_order = 7
    A = dc.A[:n_stages, :n_stages]
    B = dc.B
    C = dc.C[:n_stages]
    E3 = dc.E3
    E5 = dc.E5
    D = dc.D
    A_EXTRA = dc.A[n_stages + 1:]
    C_EXTRA = dc.C[n_stages + 1:]
    TOO_SMALL_STEP = "Required step size is less than spacing between numbers."

    def __init__(self, fun, t0, y0, t_bound, max_step=np.inf, rtol=1e-3, atol=1e-6,
                 vectorized=False, first_step=None, controlled=None):
        if vectorized:
            raise ValueError("dyncli's DOP853 steps one state at a time (vectorized=False)")
        y0 = np.asarray(y0).astype(float, copy=False)
        if y0.ndim != 1:
            raise ValueError("`y0` must be 1-dimensional.")
        if not np.isfinite(y0).all():
            raise ValueError("All components of the initial state `y0` must be finite.")
        self.t_old, self.t, self.y, self.t_bound = None, t0, y0, t_bound
        self.fun_single = lambda t, y: np.asarray(fun(t, y), dtype=float)
        self._fun_raw = fun         # a stage's rate is written into K directly (the same doubles)
        self.direction = np.sign(t_bound - t0) if t_bound != t0 else 1
        self.n, self.status, self.nfev, self.njev, self.nlu = y0.size, "running", 0, 0, 0
        self.y_old = None
        if max_step <= 0:
            raise ValueError("`max_step` must be positive.")
        self.max_step = max_step
        self.rtol, self.atol = np.maximum(rtol, 100 * EPS) if np.any(rtol < 100 * EPS) else rtol, np.asarray(atol)
        if self.atol.ndim > 0 and self.atol.shape != (self.n,):
            raise ValueError("`atol` has wrong shape.")
        if np.any(self.atol < 0):
            raise ValueError("`atol` must be positive.")
        self.controlled = None if controlled is None or controlled >= self.n else int(controlled)
        self.f = self.fun(self.t, self.y)
        if first_step is None:
            self.h_abs = select_initial_step(self.fun, self.t, self.y, t_bound, max_step, self.f, self.direction,
                                             self.error_estimator_order, self.rtol, self.atol, self.controlled)
        elif first_step <= 0 or first_step > np.abs(t_bound - t0):
            raise ValueError("`first_step` must be positive and within the interval.")
        else:
            self.h_abs = first_step
        self.error_exponent = -1 / (self.error_estimator_order + 1)
        self.h_previous = None
        self.K_extended = np.empty((dc.N_STAGES_EXTENDED, self.n), dtype=self.y.dtype)
        self.K = self.K_extended[:self.n_stages + 1]
        # the stage loop's operands made once (views of K: the same arrays scipy's loop slices per stage)
        self._stages = [(self.K[:s].T, a[:s], float(c), self.K[s]) for s, (a, c) in
                        enumerate(zip(self.A[1:], self.C[1:]), start=1)]
        self._KB = self.K[:-1].T

    def fun(self, t, y):
        """The right-hand side, each call counted (``nfev``)."""
        self.nfev += 1
        return self.fun_single(t, y)

    @property
    def step_size(self):
        return None if self.t_old is None else np.abs(self.t - self.t_old)

    def step(self):
        """One accepted step (or the solver fails: ``status`` "failed" and the message)."""
        if self.status != "running":
            raise RuntimeError("Attempt to step on a failed or finished solver.")
        if self.n == 0 or self.t == self.t_bound:
            self.t_old, self.t, self.status = self.t, self.t_bound, "finished"
            return None
        t = self.t
        success, message = self._step_impl()
        if not success:
            self.status = "failed"
        else:
            self.t_old = t
            if self.direction * (self.t - self.t_bound) >= 0:
                self.status = "finished"
        return message

    def _rk_step(self, t, y, h):
        """The stages of one step and its 8th-order result (scipy's ``rk_step``)."""
        K, fun, dot = self.K, self._fun_raw, np.dot
        K[0] = self.f
        for KT, a, c, row in self._stages:
            row[...] = fun(t + c * h, y + dot(KT, a) * h)
        y_new = y + h * dot(self._KB, self.B)
        f_new = self.fun_single(t + h, y_new)
        K[-1] = f_new
        self.nfev += self.n_stages
        return y_new, f_new

    def _error_norm(self, h, scale):
        """Hairer's error norm of DOP853 (the 5th-order estimate corrected by the 3rd)."""
        K = self.K
        if self.controlled is not None:
            K, scale = K[:, :self.controlled], scale[:self.controlled]
        err5 = np.dot(K.T, self.E5) / scale
        err3 = np.dot(K.T, self.E3) / scale
        err5_norm_2 = np.sqrt(err5.dot(err5)) ** 2      # np.linalg.norm of a vector, without its checks
        err3_norm_2 = np.sqrt(err3.dot(err3)) ** 2
        if err5_norm_2 == 0 and err3_norm_2 == 0:
            return 0.0
        denom = err5_norm_2 + 0.01 * err3_norm_2
        return np.abs(h) * err5_norm_2 / np.sqrt(denom * len(scale))

    def _step_impl(self):
        t, y, rtol, atol = self.t, self.y, self.rtol, self.atol
        min_step = 10 * abs(math.nextafter(t, self.direction * math.inf) - t)   # (numpy's, in floats)
        if self.h_abs > self.max_step:
            h_abs = self.max_step
        elif self.h_abs < min_step:
            h_abs = min_step
        else:
            h_abs = self.h_abs
        accepted = rejected = False
        while not accepted:
            if h_abs < min_step:
                return False, self.TOO_SMALL_STEP
            h = h_abs * self.direction
            t_new = t + h
            if self.direction * (t_new - self.t_bound) > 0:
                t_new = self.t_bound
            h = t_new - t
            h_abs = abs(h)
            y_new, f_new = self._rk_step(t, y, h)
            scale = atol + np.maximum(np.abs(y), np.abs(y_new)) * rtol
            error_norm = self._error_norm(h, scale)
            if error_norm < 1:
                factor = MAX_FACTOR if error_norm == 0 else min(MAX_FACTOR, SAFETY * error_norm ** self.error_exponent)
                h_abs *= min(1, factor) if rejected else factor
                accepted = True
            else:
                h_abs *= max(MIN_FACTOR, SAFETY * error_norm ** self.error_exponent)
                rejected = True
        self.h_previous, self.y_old = h, y
        self.t, self.y, self.h_abs, self.f = t_new, y_new, h_abs, f_new
        return True, None

    def dense_output(self):
        """The interpolant of the last accepted step."""
        if self.t_old is None:
            raise RuntimeError("Dense output is available after a successful step was made.")
        if self.n == 0 or self.t == self.t_old:
            return ConstantOutput(self.t_old, self.t, self.y)
        return _interpolant(self.fun, self.K_extended, self.t_old, self.t, self.y_old, self.y, self.f, self.h_previous)

    def dense_later(self):
        """The interpolant of the last accepted step, built on its first call (its three extra
        stages evaluated then, the same values as :meth:`dense_output`'s): a run that keeps every
        step's interpolant pays only for the steps it reads."""
        if self.t_old is None:
            raise RuntimeError("Dense output is available after a successful step was made.")
        if self.n == 0 or self.t == self.t_old:
            return ConstantOutput(self.t_old, self.t, self.y)
        K = np.empty_like(self.K_extended)
        K[:self.n_stages + 1] = self.K
        return LazyDense(self.fun, K, self.t_old, self.t, self.y_old, self.y, self.f, self.h_previous)


def _interpolant(fun, K, t_old, t, y_old, y, f, h):
    """The :class:`DenseOutput` of a step from its stages ``K`` (the three extra ones filled in)."""
    n = y_old.size
    for s, (a, c) in enumerate(zip(DOP853.A_EXTRA, DOP853.C_EXTRA), start=DOP853.n_stages + 1):
        dy = np.dot(K[:s].T, a[:s]) * h
        K[s] = fun(t_old + c * h, y_old + dy)
    F = np.empty((dc.INTERPOLATOR_POWER, n), dtype=y_old.dtype)
    f_old = K[0]
    delta_y = y - y_old
    F[0] = delta_y
    F[1] = h * f_old - delta_y
    F[2] = 2 * delta_y - h * (f + f_old)
    F[3:] = h * np.dot(DOP853.D, K)
    return DenseOutput(t_old, t, y_old, F)


class _Interpolant:
    """What every step's interpolant shares: its interval, and a scalar or 1-D array of times."""

    def __init__(self, t_old, t):
        self.t_old, self.t = t_old, t
        self.t_min, self.t_max = min(t, t_old), max(t, t_old)

    def __call__(self, t):
        t = np.asarray(t)
        if t.ndim > 1:
            raise ValueError("`t` must be a float or a 1-D array.")
        return self._call_impl(t)


class DenseOutput(_Interpolant):
    """DOP853's 7th-degree interpolant of one step (scipy's ``Dop853DenseOutput``)."""

    def __init__(self, t_old, t, y_old, F):
        super().__init__(t_old, t)
        self.h, self.F, self.y_old = t - t_old, F, y_old

    def _call_impl(self, t):
        x = (t - self.t_old) / self.h
        if t.ndim == 0:
            y = np.zeros_like(self.y_old)
        else:
            x = x[:, None]
            y = np.zeros((len(x), len(self.y_old)), dtype=self.y_old.dtype)
        for i, f in enumerate(reversed(self.F)):
            y += f
            if i % 2 == 0:
                y *= x
            else:
                y *= 1 - x
        y += self.y_old
        return y.T

    def component(self, i: int):
        """``t -> float``: the ``i``-th component at one float t in plain floats (a root search's
        many scalar calls): the operations of :meth:`_call_impl` on that component alone, the same
        double (each is elementwise)."""
        cs = [float(c) for c in reversed(self.F[:, i])]
        y0, t_old, h = float(self.y_old[i]), self.t_old, self.h

        def value(t: float) -> float:
            x = (t - t_old) / h
            y = 0.0
            for k, c in enumerate(cs):
                y += c
                if k % 2 == 0:
                    y *= x
                else:
                    y *= 1 - x
            return y + y0
        return value


class LazyDense(_Interpolant):
    """A step's :class:`DenseOutput` made on its first call (:meth:`DOP853.dense_later`)."""

    def __init__(self, fun, K, t_old, t, y_old, y, f, h):
        super().__init__(t_old, t)
        self._args, self._dense = (fun, K, t_old, t, y_old, y, f, h), None

    def made(self) -> DenseOutput:
        """The step's :class:`DenseOutput` (made now if it was not yet)."""
        if self._dense is None:
            self._dense = _interpolant(*self._args)
            self._args = None
        return self._dense

    def _call_impl(self, t):
        return self.made()._call_impl(t)

    def component(self, i: int):
        """:meth:`DenseOutput.component` of the step's interpolant (made now)."""
        return self.made().component(i)


def _bernstein_matrix():
    """The matrix taking (y_old, F0, …, F6) of a :class:`DenseOutput` to the Bernstein coefficients
    of degree 7 of its polynomial on the step (x = (t − t_old)/h in [0, 1]).  Its nested form is
    y_old + x (F0 + (1 − x)(F1 + x (F2 + …))): F_j multiplies x^i (1 − x)^l with i = ⌈(j + 1)/2⌉,
    l = ⌊(j + 1)/2⌋, whose Bernstein coefficients of degree 7 are C(7 − i − l, k − i) / C(7, k)
    (k = i … 7 − l); the constant 1 has every coefficient 1."""
    from math import comb

    M = np.zeros((8, 8))
    M[:, 0] = 1.0
    for j in range(7):
        i, l = (j + 2) // 2, (j + 1) // 2
        for k in range(i, 8 - l):
            M[k, j + 1] = comb(7 - i - l, k - i) / comb(7, k)
    return M


BERNSTEIN = _bernstein_matrix()


def one_sign(outputs, row: int):
    """For each step's interpolant of ``outputs`` (:class:`DenseOutput` or :class:`LazyDense`;
    anything else: False), whether its component ``row`` keeps one strict sign over the whole
    step, decided exactly, never by samples: every Bernstein coefficient of that degree-7
    polynomial (:data:`BERNSTEIN`) has the same sign and exceeds 64 ε times the sum of the
    magnitudes of its terms (so that neither the coefficients' rounding nor the interpolant's own
    evaluation can change a sign); the polynomial is a convex combination of those coefficients on
    the step.  False says only that the test cannot exclude a root (the caller looks closer).
    All steps in a few array operations."""
    dense = [o.made() if type(o) is LazyDense else o for o in outputs]
    ok = np.array([type(d) is DenseOutput and d.F.shape[0] == 7 for d in dense], dtype=bool)
    out = np.zeros(len(dense), dtype=bool)
    if not ok.any():
        return out
    coef = np.array([np.concatenate(([d.y_old[row]], d.F[:, row])) for d, g in zip(dense, ok) if g], dtype=float)
    with np.errstate(all="ignore"):
        b = coef @ BERNSTEIN.T
        tol = 64 * EPS * np.sum(np.abs(coef), axis=1)[:, None]
        good = np.all(b > tol, axis=1) | np.all(b < -tol, axis=1)
    out[ok] = good
    return out


class ConstantOutput(_Interpolant):
    """The interpolant of a step of zero length."""

    def __init__(self, t_old, t, value):
        super().__init__(t_old, t)
        self.value = value

    def _call_impl(self, t):
        if t.ndim == 0:
            return self.value
        ret = np.empty((self.value.shape[0], t.shape[0]))
        ret[:] = self.value[:, None]
        return ret


class OdeSolution:
    """Consecutive steps' interpolants as one function of t (scipy's ``OdeSolution``): at a step's
    end the earlier step is used (in the direction of integration)."""

    def __init__(self, ts, interpolants):
        ts = np.asarray(ts)
        d = np.diff(ts)
        if not ((ts.size == 2 and ts[0] == ts[-1]) or np.all(d > 0) or np.all(d < 0)):
            raise ValueError("`ts` must be strictly increasing or decreasing.")
        self.n_segments = len(interpolants)
        if ts.shape != (self.n_segments + 1,):
            raise ValueError("Numbers of time stamps and interpolants don't match.")
        self.ts, self.interpolants = ts, interpolants
        self.ascending = bool(ts[-1] >= ts[0])
        self.t_min, self.t_max = (ts[0], ts[-1]) if self.ascending else (ts[-1], ts[0])
        self.side = "left" if self.ascending else "right"
        self.ts_sorted = ts if self.ascending else ts[::-1]

    def _segment(self, ind):
        segment = min(max(ind - 1, 0), self.n_segments - 1)
        return segment if self.ascending else self.n_segments - 1 - segment

    def __call__(self, t, rows: slice | None = None):
        """The states at ``t`` (a time or a 1-D array of times); ``rows``: only those components
        (the same values as the whole state's rows: every operation is element by element)."""
        t = np.asarray(t)
        if t.ndim == 0:
            y = self.interpolants[self._segment(np.searchsorted(self.ts_sorted, t, side=self.side))](t)
            return y if rows is None else y[rows]
        # each time's step, found by a sorted search of the time itself (whatever the order of the
        # others); the times are put in order only when their steps are not already grouped in
        # order (the nodes of many pieces, one piece after the other, are: no sort, no copy back)
        segments = self._segments(t)
        grouped = segments.size < 2 or bool((segments[1:] >= segments[:-1]).all())
        if grouped:
            reverse, t_sorted = None, t
        else:
            order = np.argsort(t, kind="stable")     # (linear on times already in order)
            reverse = np.empty_like(order)
            reverse[order] = np.arange(order.shape[0])
            t_sorted = t[order]
            segments = segments[order]
        cuts = np.flatnonzero(np.diff(segments)) + 1
        stack = self._stacked() if cuts.size and t.size < 32 * (cuts.size + 1) else None
        if stack is not None:               # many steps, few times in each: every step's polynomial at once
            y = _evaluate(stack, segments, t_sorted, rows)
            return y if reverse is None else y[:, reverse]
        bounds = [0] + cuts.tolist() + [t.size]
        ys = [self.interpolants[int(segments[i])](t_sorted[i:j]) for i, j in zip(bounds[:-1], bounds[1:])]
        if rows is not None:
            ys = [y[rows] for y in ys]
        y = ys[0] if len(ys) == 1 else np.hstack(ys)
        return y if reverse is None else y[:, reverse]

    def _segments(self, t):
        """The step of each time (an array, in any order), as scipy's OdeSolution picks it."""
        segments = np.searchsorted(self.ts_sorted, t, side=self.side) - 1
        segments[segments < 0] = 0
        segments[segments > self.n_segments - 1] = self.n_segments - 1
        if not self.ascending:
            segments = self.n_segments - 1 - segments
        return segments

    def _stacked(self):
        """(t_old, h, F, y_old) of every step stacked, when every step is a :class:`DenseOutput`
        (a :class:`LazyDense` already made by then counts as its DenseOutput; else None); made once,
        on the first call over many steps."""
        if not hasattr(self, "_stack"):
            its = [i._dense if type(i) is LazyDense and i._dense is not None else i for i in self.interpolants]
            ok = all(type(i) is DenseOutput for i in its) and len({i.F.shape for i in its}) == 1
            self._stack = (np.array([i.t_old for i in its], float), np.array([i.h for i in its], float),
                           np.stack([i.F for i in its]), np.stack([i.y_old for i in its])) if ok else None
        return self._stack


def _evaluate(stack, segments, t, rows: slice | None = None):
    """:meth:`DenseOutput._call_impl` of the steps ``segments`` at the times ``t`` in one
    vectorised pass: the same operations on the same doubles, so the same values (``rows``: of
    those components only)."""
    t_old, h, F, y_old = stack
    if rows is not None:
        F, y_old = F[:, :, rows], y_old[:, rows]
    x = ((t - t_old[segments]) / h[segments])[:, None]
    y = np.zeros((t.size, y_old.shape[1]), dtype=y_old.dtype)
    for i in range(F.shape[1]):
        y += F[segments, F.shape[1] - 1 - i]
        if i % 2 == 0:
            y *= x
        else:
            y *= 1 - x
    y += y_old[segments]
    return y.T


class DenseStack:
    """Many steps' :class:`DenseOutput` evaluated together: ``stack(which, t)`` is
    ``outputs[which[i]](t[i])`` for every i, as rows (len(t), dim), by the same arithmetic as each
    one's own call (equal to it bit for bit) in a few array operations over all the times."""

    def __init__(self, outputs):
        self.t_old = np.array([o.t_old for o in outputs], dtype=float)
        self.h = np.array([o.h for o in outputs], dtype=float)
        self.F = np.stack([o.F for o in outputs])            # (steps, power, dim)
        self.y_old = np.stack([o.y_old for o in outputs])

    def __call__(self, which, t):
        x = ((t - self.t_old[which]) / self.h[which])[:, None]
        y = np.zeros((len(t), self.y_old.shape[1]), dtype=self.y_old.dtype)
        power = self.F.shape[1]
        for i in range(power):
            y += self.F[which, power - 1 - i]
            if i % 2 == 0:
                y *= x
            else:
                y *= 1 - x
        y += self.y_old[which]
        return y
