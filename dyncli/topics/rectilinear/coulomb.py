"""Coulomb friction written by hand, ``a: "-k*s - mu*g*sign(v)"``, on the ODE route.

sign(v) jumps at v = 0: the body stops there, and sticks while the other forces
are smaller than the friction.  A step-by-step integrator cannot pass that
point: on reaching v = 0 it chatters between the two signs with ever shorter
steps (DOP853 projects some 1e10 steps, Radau gives up at the stop), and more
steps never help.  So the ODE route refuses it before integrating and names
what does answer it: ``particle`` with ``{kind: friction}`` (the stop and the
sticking located as events, notes §19), or — when a depends on v alone — the
quadrature of case 3, which reaches the stop and stays there.
"""

from __future__ import annotations


from dyncli.errors import InputError
from dyncli.expr.evaluate import uses


def _zero_at_rest(ir: tuple) -> bool:
    """Whether a sign() argument in v alone vanishes at v = 0 (sign(v), sign(-2*v), sign(v*abs(v)))."""
    from dyncli.expr.evaluate import compile_ir

    try:
        return compile_ir(ir)({"v": 0.0}) == 0.0
    except (ArithmeticError, ValueError, KeyError):
        return False


def _sign_of_v(ir: tuple) -> bool:
    kind = ir[0]
    if kind in ("num", "param", "var"):
        return False
    if kind == "call":
        args = ir[2]
        if ir[1] == "sign" and len(args) == 1 and uses(args[0], "v") \
                and not any(uses(args[0], x) for x in ("t", "s")) and _zero_at_rest(args[0]):
            return True
        return any(_sign_of_v(a) for a in args)
    return any(_sign_of_v(a) for a in ir[1:])


def by_hand(a) -> bool:
    """Whether the expression ``a`` holds a sign() of v that jumps at v = 0."""
    return "v" in a.variables and _sign_of_v(a.ir)


def refuse(a, case) -> InputError:
    """The refusal of ``a`` on an ODE route, pointing to what answers it."""
    alone = ("; or, since a depends on v alone, use accuracy.method auto (the quadrature of case 3 "
             "reaches the stop and stays there)") if case == 3 else ""
    return InputError(
        f"sign(v) in {a.text!r} jumps at v = 0 (Coulomb friction written by hand): the body stops there and may "
        "stick, which a step-by-step integration cannot pass (more steps do not help); write the friction as "
        "type particle with forces [{kind: friction, mu: MU, N: NORMAL_FORCE}] and the other forces as force "
        f"terms (it finds the stop and the sticking){alone}", "a")


