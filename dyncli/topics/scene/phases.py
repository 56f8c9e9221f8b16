"""What happens at an event: the joint set changes and the motion goes on (docs/types/scene.md).

* ``separates``, ``leaves``: the contact (or rolling body) is released; its point is watched
  for its return to the surface;
* ``slack``: the cord's run has no row; its length is watched for the instant it is taut again;
* ``slips``: a sticking contact slides (a rolling body slips) opposite to the friction it
  would have needed, with kinetic friction μ_k N;
* ``sticks``: a sliding contact (a slipping rolling body) whose slip speed reached 0 is held
  and the static test |F| ≤ μ_s N decides: it sticks (rolls), or slides back (no event);
* ``impact``: a released contact, a stop or a rolling body reaches its surface, ``taut``: a
  slack cord is jerked taut (restitution 0, an inextensible cord): the velocities jump
  (impulse.py); a contact with e = 0 stays made, one with e > 0 rebounds;
* simultaneous impacts: the released contacts and stops whose gap is 0 at the located impact's
  instant (within 1e-9 of the scene's size) and that approach their surfaces strike together:
  one impulse solve with Newton's law on every striking row (impulse.strike), each listed in
  ``impacts`` (the energy lost, the impact's whole, on the located one's entry);
* ``wraps``, ``unwraps``: a string catches a peg (from then on it swings about the peg with the
  length left) or swings back straight off it (elements.PeggedString); a crossing of a peg's
  watch that is not a wrap (the line passing it beyond the string's end, a whole half turn about
  the peg) only turns the watch's sign: a phase boundary with no event;
* ``rests``: the accumulation rule of a bouncing point (Zeno: infinitely many impacts in a
  finite time): when the rebound speed falls below √rtol × the first impact speed on that
  joint (the bounce height below rtol × the first one), the remaining bounces are summed as
  the geometric series of flight times, exact for a constant normal acceleration a_n:
  t_rest = t + 2 v⁺ / (|a_n| (1 − e)), and the point is made to rest on the surface at once
  (a plastic impact for the remaining normal speed).

After each change the new joint set is made consistent at the same instant: a made contact
that would pull is released, a cord that would push goes slack, friction past μ_s N slips.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from dyncli.errors import NumericalError

from . import assembly, motion
from .contacts import Contact, Rolls
from .elements import Cord

EPS = float(np.finfo(float).eps)
#: the most phases one solve follows; the motion stops there with a warning
MAX_PHASES = 2000
#: the most changes at one instant (phases of no length) before the solve gives up (exit 1)
MAX_INSTANT = 50


@dataclass
class Phase:
    t_start: float
    t_end: float
    joints: list
    route: str

    def as_dict(self) -> dict:
        return {"t_start": self.t_start, "t_end": self.t_end, "joints": list(self.joints), "route": self.route}


@dataclass
class Impact:
    t: float
    joint: str
    e: float
    impulse: float                  # the normal impulse (N̂ ≥ 0), or a cord's impulsive tension
    energy_loss: float              # T⁻ − T⁺
    friction: float = 0.0           # the tangential impulse of a rough impact
    v_normal: tuple = (0.0, 0.0)    # the normal speed of the point before and after
    slip: tuple = (None, None)      # the point's slip speed along d̂ before and after (a cord: None)
    course: str | None = None       # the slip through the impact (routh.py): smooth, sticks, slides, ...

    def as_dict(self) -> dict:
        return {"t": self.t, "joint": self.joint, "e": self.e, "impulse": self.impulse,
                "energy_loss": self.energy_loss, "impulse_F": self.friction,
                "v_n_before": self.v_normal[0], "v_n_after": self.v_normal[1],
                "slip_before": self.slip[0], "slip_after": self.slip[1], "course": self.course}


def lost(T1: float, T2: float) -> float:
    """The kinetic energy an impact takes, T⁻ − T⁺ ≥ 0: a difference below the rounding of T
    (64 ε T⁻, an elastic or nearly elastic impact) is 0, never a gain."""
    d = T1 - T2
    return 0.0 if d < 0 and -d <= 64 * EPS * max(T1, T2) else d


def joints_of(s) -> list[str]:
    """The joints made in the current phase (a cord with at least one taut run)."""
    return [e.name for e in s.elements if e.kind != "guide" and e.rows > 0]


def element(s, name):
    """The joint element called ``name``."""
    return next((e for e in s.elements if e.name == name), None)


class Transitions:
    """The changes at the events of one solve (keeps the first impact speed of each joint for
    the accumulation rule)."""

    def __init__(self, system, traj, rtol: float):
        self.s, self.traj, self.rtol = system, traj, rtol
        self.first: dict[str, float] = {}
        self.behind: set[str] = set()   # the joints a point has passed behind (warned once)

    def event(self, t, joint, what) -> None:
        self.traj.events.append(motion.Event(t, joint, what))

    def after(self, t, q, v, hit):
        """(q, v) after the event ``hit`` = (t, joint, what) and the changes it entails."""
        s = self.s
        _, joint, what = hit
        if what != "switch":
            v = self._change(t, q, v, element(s, joint), what)
        s.refresh()
        v = self.settle(t, q, v)
        if self._land(t, q, v, joint):
            v = self.settle(t, q, v)
        if why := self._locked(t, q):
            raise NumericalError(why)
        q = s.project_position(q, t)
        for e in s.elements:            # a new phase: the cords' turning segments measured from here
            if e.kind == "cord":
                e.mark(q)
        return q, s.project_velocity(q, v, t)

    def _change(self, t, q, v, e, what):
        from . import impulse           # (the impacts' module: imported by a motion that has one)

        s = self.s
        if what == "reverses":                  # a two-sided guide's N changes sign: so does its friction
            e.nsign = -e.nsign
        elif what in ("separates", "leaves"):
            together = self._separating_with(t, q, v, e) if what == "separates" else []
            impulse.release(e)
            self.event(t, e.name, what)
            for el in together:
                impulse.release(el)
                self.event(t, el.name, "separates")
        elif what == "slack":
            T = e.tensions(s.lam_of(s.solve(q, v, t)[1], s.elements.index(e)))
            e.slack = e.slack | {min(e.taut, key=lambda r: T[r])}
            self.event(t, e.name, what)
        elif what == "slips":
            lm = s.lam_of(s.solve(q, v, t)[1], s.elements.index(e))
            F = e.grip(lm)[1]
            held = [x.name for x in s.elements if isinstance(x, Contact) and x.mode == "shared" and x.holder == e.name]
            e.mode = "slip" if isinstance(e, Rolls) else "slide"
            e.sign = -math.copysign(1.0, F)
            self.event(t, e.name, what)
            for name in held:                   # the contacts held with it slide with it (SceneSystem._groups)
                self.event(t, name, what)
        elif what == "sticks":
            sliding = {x.name for x in s.elements if isinstance(x, Contact) and x.mode == "slide"}
            holds, sign = motion.stick_test(s, e, q, v, t)
            if holds:
                self.event(t, e.name, what)
                for x in s.elements:            # the contacts held with it (motion.join_held)
                    if isinstance(x, Contact) and x.mode == "shared" and x.holder == e.name and x.name in sliding:
                        self.event(t, x.name, what)
                self.note_groups()
            else:
                e.mode, e.sign = ("slip" if isinstance(e, Rolls) else "slide"), sign
        elif what == "taut":
            gaps = np.array(e.consts) - e.lengths(q)
            run = min(e.slack, key=lambda r: abs(gaps[r]))
            v = self._strike(t, q, v, e, 0.0, run, "taut")
        elif what == "impact":
            if not self._from_behind(t, q, v, e):
                v = self._strike(t, q, v, e, e.e, None, "impact")
        elif what in ("wraps", "unwraps"):
            done = e.turn(q, v, what)
            if done is not None:
                self.event(t, e.name, done)
        # "turns" (a cord's arc three eighths of a turn on): no event; after() marks its new branch
        return v

    def note_groups(self) -> None:
        """A warning, once a group, for the contacts held together (motion.held_groups)."""
        for names in motion.held_groups(self.s):
            w = motion.indeterminate_warning(names)
            if w not in self.traj.warnings:
                self.traj.warnings.append(w)

    def _from_behind(self, t, q, v, e) -> bool:
        """A point that comes over a surface's extent past one of its ends on the far side (the
        side away from its normal) has not crossed it: no impact, the point passes behind (a
        stop is one-sided).  Its gap there is well below the rounding a crossing is located to.
        Where it heads for the surface from behind (a surface drawn the wrong way round: the
        user expects it to strike), a warning, once a joint, names the normal; a point the
        extent sweeps over as it moves away (a surface carried round by a turning body) passes
        without one."""
        gap = float(e.gap(q))
        if not gap < -1e-8 * max(1.0, float(np.max(np.abs(q), initial=0.0))):
            return False
        if e.name not in self.behind and e.normal_speed(q, v) > 0:
            self.behind.add(e.name)
            n = [0.0 if abs(c) < 1e-12 else float(c) for c in (e.normal(q) if hasattr(e, "normal") else e.surface.n)]
            self.traj.warnings.append(
                f"{e.name}: at t = {t:.6g} s the point came over the surface {e.surface.name!r} past its end on "
                f"its far side ({-gap:.6g} m behind it): a {'stop' if getattr(e, 'stop', False) else 'contact'} "
                f"acts only on the side of its normal n = [{n[0]:.4g}, {n[1]:.4g}] (to the left of the "
                "direction), so the point passes behind it; if it should strike there, reverse the surface's "
                "direction")
        return True

    def _strike(self, t, q, v, e, rest, run, what):
        from . import impulse

        s = self.s
        T1 = s.kinetic(v)
        speed = (lambda w: -float(e.run_rate(q, w, run))) if isinstance(e, Cord) else (lambda w: e.normal_speed(q, w))
        vn = speed(v)
        others = [] if isinstance(e, Cord) else self._together(t, q, v, e)
        vns = [el.normal_speed(q, v) for el, _ in others]
        slips = {el.name: el.slip_speed(q, v) for el, _ in [(e, 0)] + others if not isinstance(el, Cord)}
        vp, N, F, released, more, courses = impulse.strike(s, q, v, t, e, rest, run, others)
        vn2 = speed(vp)

        def slip(el):
            return (None, None) if isinstance(el, Cord) else (slips[el.name], el.slip_speed(q, vp))
        hit = Impact(t, e.name, rest, N, 0.0, F, (vn, vn2), slip(e), courses.get(e.name))
        hits = [(hit, what)] if N > 0 or not more else []      # a point struck with no impulse: none
        for (el, N_o, F_o), vn_o in zip(more, vns):
            if N_o > 0:
                hits.append((Impact(t, el.name, el.e, N_o, 0.0, F_o, (vn_o, el.normal_speed(q, vp)), slip(el),
                                    courses.get(el.name)), "impact"))
        hits = hits or [(hit, what)]
        hits[0][0].energy_loss = lost(T1, s.kinetic(vp))   # the whole impact's, on its first entry
        for h, w in hits:
            self.event(t, h.joint, w)
            self.traj.impacts.append(h)
        rebound = []
        for el, _N, _F in more:
            if el.rows and el.e > 0 and el.normal_speed(q, vp) > 0:
                impulse.release(el)                     # it rebounds with the located point
                rebound.append((el, 0.0))
        for el, _r in released:
            self.event(t, el.name, "slack" if isinstance(el, Cord) else "separates")
        if isinstance(e, Cord) or rest == 0:
            return vp
        first = self.first.setdefault(e.name, abs(vn))
        if vn2 > math.sqrt(self.rtol) * first:
            impulse.release(e)                          # it rebounds: the contact is open again
            return vp
        impulse.release(e)
        s.refresh()
        a_n = impulse.normal_acceleration(s, q, vp, t, e)
        if not a_n < 0:                                 # not pressed back: it flies off slowly
            return vp
        t_rest = t + 2.0 * vn2 / (-a_n * (1.0 - rest)) if rest < 1 else math.inf
        T2 = s.kinetic(vp)
        vr, N2, F2, released, more, _ = impulse.strike(s, q, vp, t, e, 0.0, None, rebound, hold=True)
        hit.impulse += N2
        hit.friction += F2
        hit.energy_loss += lost(T2, s.kinetic(vr))
        self.event(t_rest, e.name, "rests")
        for el, _N, _F in more:                         # those that struck with it rest with it
            self.event(t_rest, el.name, "rests")
        return vr

    def _together(self, t, q, v, e) -> list:
        """[(element, e)] of the released contacts and stops other than ``e`` that reach their
        surfaces at this instant too (gap within 1e-9 of the scene's size, over the surface's
        extent) approaching it."""
        s = self.s
        tol = 1e-9 * assembly.length_scale(q, s)
        out = []
        for el in s.elements:
            if el is e or not isinstance(el, (Contact, Rolls)) or el.mode != "off":
                continue
            if abs(el.watch((), q, v, t)[0][1]) <= tol and el.normal_speed(q, v) < 0:
                out.append((el, el.e))
        return out

    def _separating_with(self, t, q, v, e) -> list:
        """The other contacts whose N reaches 0 at the instant ``e``'s does (within 1e-9 of the
        multipliers' scale, solved with them all still made): they separate together.  A
        symmetric scene — a cylinder resting on two others, a rod lifted off two ledges — loses
        both at one instant; releasing one of them first would leave the other's N at its
        rounding and the motion lopsided."""
        s = self.s
        _, lam, _ = s.solve(q, v, t)
        scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
        out = []
        for i, el in enumerate(s.elements):
            if el is e or el.rows == 0 or not isinstance(el, (Contact, Rolls)) or getattr(el, "two_sided", False):
                continue
            if any(what == "separates" and abs(g) <= 1e-9 * scale for what, g in el.watch(s.lam_of(lam, i), q, v, t)):
                out.append(el)
        return out

    def locked_with(self, t, q, joint: str) -> str | None:
        """Why the instant t cannot be passed when the joint that chatters there (made and
        released again at every event) would lock with the joints made if it were made too (a
        hoop bouncing ever faster between a floor and a curb's edge comes to rest wedged between
        them): the refusal of :meth:`_locked`, else None."""
        from . import impulse

        e = element(self.s, joint)
        if not isinstance(e, (Contact, Rolls)) or e.mode != "off":
            return None
        impulse.make(e, q)
        self.s.refresh()
        try:
            return self._locked(t, q)
        finally:
            impulse.release(e)
            self.s.refresh()

    def _locked(self, t, q) -> str | None:
        """Why the joints made after an event cannot be followed past it, when their rows are
        dependent (a wheel wedged between a floor and a curb's edge, rolling on both: held there,
        its friction is not determined): the refusal names the joints, not a singular matrix."""
        s = self.s
        J = s.jac(q)
        if J.shape[0] and assembly.rank(J) < J.shape[0]:
            names = ", ".join(joints_of(s))
            return (f"at t = {t:.6g} s the joints made ({names}) lock each other: their rows are dependent "
                    "(a wheel wedged between two surfaces and rolling on both: held there, the friction of each "
                    "is not determined); this release does not follow the motion past that instant: make one of "
                    "them smooth or give it a smaller mu_s, or end the motion before (t_end)")
        return None

    def _land(self, t, q, v, left: str) -> bool:
        """After an event, a body that touches a surface without approaching it while free flight
        takes it in (a wheel passing over a curb's corner onto its top, its centre over the
        corner, moving along the top; a box's corner on the floor when the obstacle it pivoted on
        lets go) is made on it at once — not struck an instant later after a fall of the event's
        rounding.  Each released contact or stop at that instant with a gap within 1e-9 of the
        scene's size, a normal speed within 1e-9 of the scene's speeds and free flight taking it
        into the surface beyond 1e-9 of the scene's accelerations is made (settle then releases
        it if it would pull; a contact whose N reached 0 at this instant has no such
        acceleration, to rounding: it stays off), sliding on if it arrives slipping, and left
        off where its rows would repeat the made ones'; the joint ``left`` (the event's own)
        stays as the event left it.  Returns whether one was made."""
        from . import impulse

        s = self.s
        tol = 1e-9 * assembly.length_scale(q, s)
        vtol = 1e-9 * max(float(np.max(np.abs(v), initial=0.0)), 1e-300)
        made = False
        ascale = None
        for el in s.elements:
            if not isinstance(el, (Contact, Rolls)) or el.mode != "off" or el.name == left:
                continue
            if abs(el.watch((), q, v, t)[0][1]) > tol or abs(el.normal_speed(q, v)) > vtol:
                continue
            if ascale is None:
                ascale = max(float(np.max(np.abs(s.solve(q, v, t)[0]), initial=0.0)), abs(s.g), 1e-300)
            if impulse.normal_acceleration(s, q, v, t, el) < -1e-9 * ascale:
                impulse.make(el, q)
                slip = el.slip_speed(q, v)
                if el.rows == 2 and abs(slip) > vtol:       # it arrives slipping: it slides on (no jump of its slip)
                    el.mode, el.sign = ("slip" if isinstance(el, Rolls) else "slide"), math.copysign(1.0, slip)
                s.refresh()
                J = s.jac(q)
                if assembly.rank(J) < J.shape[0]:           # its rows repeat the made ones' (a wheel wedged
                    impulse.release(el)                     # between a floor and a curb's edge): left to its
                    s.refresh()                             # impact, which shares what is not determined
                    continue
                made = True
        return made

    def settle(self, t, q, v):
        """Make the joint set consistent at t: release, slacken or slip what the new set would
        make pull, push or exceed μ_s N (each an event), until nothing changes."""
        s = self.s

        def loads() -> float:
            return float(np.max(np.abs(s.applied(q, v, t)[0]), initial=0.0))

        for _ in range(4 * len(s.elements) + 4):
            _, lam, _ = s.solve(q, v, t)
            scale = max(float(np.max(np.abs(lam), initial=0.0)), 1e-300)
            bad = None
            for i, e in enumerate(s.elements):
                if e.rows == 0 or not isinstance(e, (Contact, Rolls, Cord)):
                    continue
                for what, g in e.watch(s.lam_of(lam, i), q, v, t):
                    if what in ("separates", "slack", "slips") and g < -1e-9 * scale:
                        bad = (e, what)
                        break
                    # a two-sided guide's N the other way than its friction assumes: by more than the
                    # rounding of the loads (at its reversal N is 0 to rounding, and so is every λ)
                    if what == "reverses" and g < -1e-9 * max(scale, loads()):
                        bad = (e, what)
                        break
                if bad:
                    break
            if bad is None:
                return v
            v = self._change(t, q, v, *bad)
            s.refresh()
            v = s.project_velocity(q, v, t)
        return v
