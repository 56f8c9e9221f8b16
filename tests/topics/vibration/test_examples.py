"""Every example in problems/vibration/ against independent 50-digit references."""

from __future__ import annotations

import math

import mpmath as mp
import pytest

from tests.conftest import PROBLEMS, solve_path
from tests.topics.vibration import notes_formulas as nf
from tests.topics.vibration.reference import max_rel_err, reference

TOL = 1e-13

# The inputs of each example problem, written out here (not read from the files).
EXAMPLES = {
    ("undamped.yaml", 0): dict(m=1, k=4, zeta=0, L=0.5, x0=0.6, v0=0.2, at=[math.pi / 8, 1, 2.5]),
    ("underdamped.yaml", 0): dict(m=2, k=200, zeta=0.1, L=0.3, x0=0.35, v0=0, at=[0, 0.1, 0.3157, 1, 3]),
    ("critical.yaml", 0): dict(m=1, k=100, c=20, L=0, x0=0.1, v0=-3, at=[0, 0.05, 0.1, 0.2, 0.5]),
    ("overdamped.yaml", 0): dict(m=1, k=1, zeta=1.25, L=0, x0=0.1, v0=0.2, at=[0, 1, 2, 5]),
    ("overdamped.yaml", 1): dict(m=1, k=1, zeta=1.25, L=0, x0=0.1, v0=-0.125, at=[0, 1, 2, 5]),
    ("base-excitation.yaml", 0): dict(m=1, k=400, zeta=0.05, L=0.2, x0=0.2, v0=0, s0=0.002, Omega=30,
                                      at=[0, 0.1, 0.5, 1, 5, 20]),
    ("resonance.yaml", 0): dict(m=1, k=25, zeta=0, L=0, x0=0, v0=0, s0=0.01, Omega=5, at=[0, 1, 2, 5, 10]),
    ("sweep.yaml", 0): dict(m=1, k=1, zeta=0.2, L=0, x0=0, v0=0, at=[], sweep=(0.0, 3.0, 31)),
    ("near-critical.yaml", 0): dict(m=1, k=1, zeta=0.999999999999, L=0, x0=1, v0=0, at=[0, 1, 5]),
    ("near-critical.yaml", 1): dict(m=1, k=1, zeta=1, L=0, x0=1, v0=0, at=[0, 1, 5]),
    ("near-critical.yaml", 2): dict(m=1, k=1, zeta=1.000000000001, L=0, x0=1, v0=0, at=[0, 1, 5]),
}


def close(got, want, tol=TOL):
    with mp.workdps(50):
        want = mp.mpf(want)
        return abs(mp.mpf(got) - want) <= tol * max(abs(want), mp.mpf("1e-300"))


def test_every_example_file_is_covered():
    files = {p.name for p in (PROBLEMS / "vibration").glob("*.yaml")} - {"force-excitation.yaml",     # test_force.py
                                                                     "rotating-unbalance.yaml"}  # test_unbalance.py
    assert files == {f for f, _ in EXAMPLES}


@pytest.mark.parametrize("key", list(EXAMPLES), ids=lambda k: f"{k[0]}#{k[1]}")
def test_example(key):
    fname, idx = key
    ex = EXAMPLES[key]
    rec = solve_path(PROBLEMS / "vibration" / fname)[idx]
    assert rec.get("error") is None
    R = rec["results"]
    assert rec["method"] == "closed-form"
    with mp.workdps(50):
        m, k = mp.mpf(ex["m"]), mp.mpf(ex["k"])
        wn = mp.sqrt(k / m)
        zeta = mp.mpf(ex["zeta"]) if "zeta" in ex else mp.mpf(ex["c"]) / (2 * mp.sqrt(k * m))
        c = 2 * m * zeta * wn
        assert close(R["omega_n"], wn)
        assert close(R["zeta"], zeta)
        assert close(R["c"], c)
        regime = "undamped" if zeta == 0 else "underdamped" if zeta < 1 else "critical" if zeta == 1 else "overdamped"
        assert R["regime"] == regime
        wd = wn * mp.sqrt(abs(1 - zeta ** 2))
        assert close(R["omega_d"], wd) if wd else R["omega_d"] == 0.0
    for name in ("omega_n", "zeta", "c", "omega_d"):
        assert isinstance(R[name], float)

    if "s0" not in ex:
        A, phi = nf.free_A_phi(ex["x0"] - ex["L"], ex["v0"], float(wn), float(zeta))
        if A is None:
            assert R["A"] is None and R["phi"] is None
            assert any("A and phi are null" in w for w in rec["warnings"])
        else:
            assert close(R["A"], A)
            if phi is None:
                assert R["phi"] is None and rec["warnings"]
            else:
                assert close(R["phi"], phi)
                assert -math.pi < R["phi"] <= math.pi
        assert "G" not in R and "r" not in R
    else:
        r = ex["Omega"] / float(wn)
        assert close(R["r"], mp.mpf(ex["Omega"]) / wn)
        if zeta == 0 and r == 1:
            assert R["G"] is None and R["g"] is None
            assert any("resonance" in w for w in rec["warnings"])
            assert R["phi"] == pytest.approx(-math.pi / 2, abs=1e-15)
        else:
            G, phi, g, Phi = nf.amplification(r, float(zeta))
            for name, want in (("G", G), ("phi", phi), ("g", g), ("Phi", Phi)):
                assert close(R[name], want), (name, R[name], want)
        assert "A" not in R

    if ex["at"]:
        rx, rv, rw = reference(ex["at"], m=ex["m"], k=ex["k"], zeta=float(zeta), L=ex["L"], x0=ex["x0"], v0=ex["v0"],
                               s0=ex.get("s0", 0.0), Omega=ex.get("Omega", 0.0))
        assert len(R["x"]) == len(ex["at"])
        assert max_rel_err(R["x"], rx) <= TOL
        assert max_rel_err(R["v"], rv) <= TOL
        assert max_rel_err(R["w"], rw) <= TOL
    else:
        assert "x" not in R

    if "sweep" in ex:
        lo, hi, n = ex["sweep"]
        rs = [lo + (hi - lo) * i / (n - 1) for i in range(n)]
        assert R["sweep_r"] == pytest.approx(rs, rel=1e-15, abs=1e-15)
        for i, ri in enumerate(R["sweep_r"]):
            G, phi, g, Phi = nf.amplification(ri, float(zeta))
            assert close(R["sweep_G"][i], G, 1e-13) or (G == 0 and R["sweep_G"][i] == 0)
            assert close(R["sweep_g"][i], g, 1e-13)
            assert abs(R["sweep_phi"][i] - float(phi)) <= 1e-13
            assert abs(R["sweep_Phi"][i] - float(Phi)) <= 1e-13
        rG, Gm = nf.peak(nf.G_of(float(zeta)), 0.5, 2.0)
        rg, gm = nf.peak(nf.g_of(float(zeta)), 0.5, 1.0)
        assert close(R["peak_G_r"], rG, 1e-14) and close(R["peak_G"], Gm, 1e-14)
        assert close(R["peak_g_r"], rg, 1e-14) and close(R["peak_g"], gm, 1e-14)


def test_near_critical_examples_are_continuous():
    recs = solve_path(PROBLEMS / "vibration" / "near-critical.yaml")
    xs = [r["results"]["x"] for r in recs]
    for a, b in zip(xs[0], xs[2]):
        assert a == pytest.approx(b, rel=1e-11)
    assert [r["results"]["regime"] for r in recs] == ["underdamped", "critical", "overdamped"]


def test_sweep_table_marks_the_peaks(cli):
    rc, out, err = cli("solve", "problems/vibration/sweep.yaml")
    assert rc == 0, err
    assert "◀ G max" in out and "◀ g max" in out
    assert "Resonance peaks (exact)" in out
