"""W_nc on the kinematics route (its quadrature of the drives' power, every piece's panels
integrated together: dyncli.quadrature.gauss_kronrod_many) against the crank's work in closed
form: with every load conservative (gravity), the work of the drive is the change of the
mechanism's energy, W_nc(t) = E(t) − E(0) (34.20), E = Σ ½ m v̄² + ½ Ī ω² + m g ȳ from the loop
closure by hand (slider-crank, refs_b.slider_crank_kinematics) or by mpmath findroot (four-bar,
refs_b.four_bar_state) at 30 digits — never from dyncli.

Tolerance 1e-10 of the energies' scale: the route's positions and rates are exact to rounding
times cond(J) (~1e-15 here) and each piece's quadrature is to 1e-12 of its integral (the
runner's estimate), summed over ~100 pieces: ~1e-10 at worst."""

from __future__ import annotations

from mpmath import mp, mpf

from tests.topics.scene import refs_b as R
from tests.topics.scene.common import gallery

TOL = 1e-10


def _energy(bodies, g) -> mpf:
    return sum(b["m"] * (b["v"][0] ** 2 + b["v"][1] ** 2) / 2 + b["I"] * b["omega"] ** 2 / 2 + b["m"] * g * b["x"][1]
               for b in bodies.values())


def _reported(rec) -> list[tuple[float, float]]:
    """(t, W_nc) at the requested times and at the find answers."""
    res = rec["results"]
    out = list(zip(res["t"], res["W_nc"]))
    out += [(f["t"], f["W_nc"]) for f in res.get("find", []) if f.get("reached")]
    return out


def _check(pairs, energy):
    with mp.workdps(30):
        E0 = energy(mpf(0))
        Es = {t: energy(mpf(t)) for t, _ in pairs}
        scale = max(abs(E) for E in list(Es.values()) + [E0])
        for t, W in pairs:
            ref = Es[t] - E0
            assert abs(W - ref) <= TOL * scale, (t, W, float(ref))


def test_slider_crank_work_is_the_crank_work():
    rec = gallery("slider-crank.yaml")
    assert rec["results"]["route"] == "kinematics"
    pairs = _reported(rec)
    assert len(pairs) == 6

    def energy(t):
        r, l, w, m1, m2, m3, g = (mpf(v) for v in ("0.1", "0.35", 10, "0.5", 1, 2, "9.81"))
        kin = R.slider_crank_kinematics(r, l, w, t)
        bodies = {nm: {"m": m, "I": m * L ** 2 / 12, "x": kin[f"x.{nm}"], "v": kin[f"v.{nm}"],
                       "omega": kin[f"omega.{nm}"]}
                  for nm, m, L in (("crank", m1, r), ("conrod", m2, l), ("slider", m3, 0))}
        return _energy(bodies, g)

    _check(pairs, energy)
    assert any(abs(t - float(mp.pi / 10)) < 1e-9 for t, _ in pairs)    # find.1: θ = π
    assert max(abs(W) for _, W in pairs) > 1.0                         # the crank does work


def test_four_bar_work_is_the_crank_work():
    rec = gallery("four-bar.yaml")
    assert rec["results"]["route"] == "kinematics"
    pairs = _reported(rec)
    assert len(pairs) == 5

    with mp.workdps(30):
        a, b, c, d, w, th20, g = (mpf("0.3"), mp.sqrt(mpf("0.26")), mpf("0.4"), mpf("0.5"), mpf(5), mp.pi / 2,
                                  mpf("9.81"))
        masses = (mpf("0.6"), mpf(1), mpf("0.8"))
        guess0 = (mp.atan(mpf("0.2")), mp.pi / 2)

    def energy(t):
        # the branch of the sketch continued in crank steps of at most 0.02 rad
        n = int(mp.ceil(w * t / mpf("0.02"))) + 1
        guess = R.four_bar_angles(a, b, c, d, th20, guess0)
        for j in range(1, n + 1):
            guess = R.four_bar_angles(a, b, c, d, th20 + w * t * j / n, guess)
        return _energy(R.four_bar_state(a, b, c, d, w, th20, masses, g, t, guess)["bodies"], g)

    _check(pairs, energy)
