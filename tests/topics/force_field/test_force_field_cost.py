"""force-field without a path needs no scipy; the straight-segment work behind the
single-valuedness check of V (composite Gauss-Legendre) against closed forms."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from dyncli.expr import parse
from dyncli.topics.force_field.path import segment_work
from dyncli.topics.force_field.solver import Field

ROOT = Path(__file__).resolve().parents[3]
VARS = ("x1", "x2", "x3")


def _field(*F):
    return Field([parse(f, VARS) for f in F])


def _heavy_imports_of(text: str) -> tuple[dict, list[str]]:
    """(results, heavy top-level packages imported, numpy included) of solving ``text`` in a fresh interpreter."""
    code = ("import json, sys; from tests.conftest import solve_one_text\n"
            f"r = solve_one_text({text!r})['results']\n"
            "print(json.dumps([r, sorted({m.split('.')[0] for m in sys.modules} & {'numpy', 'scipy', 'sympy', 'matplotlib'})]))")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True).stdout
    results, mods = json.loads(out.splitlines()[-1])
    return results, mods


def test_no_path_does_not_import_scipy():
    results, mods = _heavy_imports_of(
        "type: force-field\nF: ['2*x1*x2 + x3**3', 'x1**2', '3*x1*x3**2']\npoints: [[1, 2, 3]]\n")
    assert results["potential"] == "-x1**2*x2 - x1*x3**3"
    assert mods == []                 # a conservative polynomial field: exact without sympy, nor even numpy
    results, mods = _heavy_imports_of("type: force-field\nF: ['-x2', 'x1', '0']\n")
    assert results["curl_formula"] == ["0", "0", "2"]
    assert mods == ["numpy"]          # not conservative: numpy's random test points name a counterexample
    results, mods = _heavy_imports_of("type: force-field\nF: ['x2*cos(x1)', 'sin(x1)', '0']\n")
    assert results["potential"] == "-x2*sin(x1)"
    assert mods == ["numpy", "sympy"]          # any other field: sympy's exact curl and potential


def test_polynomial_field_along_a_path_imports_no_sympy():
    # the work of a polynomial field along a path: the quadrature runner (dyncli/quadrature.py, no
    # scipy), x'(t) exact without sympy
    results, mods = _heavy_imports_of("type: force-field\nF: ['2*x1*x2 + x3**3', 'x1**2', '3*x1*x3**2']\n"
                                      "path: {x1: t, x2: 't**2', x3: 't**3', t_span: [0, 1]}\n")
    assert results["work"] == pytest.approx(2.0, rel=1e-14)       # V(0) - V(1, 1, 1) = 0 - (-2) (19.8)
    assert mods == ["numpy"]
    results, mods = _heavy_imports_of("type: force-field\nF: ['-x2', 'x1', '0']\n"
                                      "path: {x1: 'cos(t)', x2: 'sin(t)', x3: 0, t_span: [0, pi]}\n")
    assert results["work"] == pytest.approx(math.pi, rel=1e-13)   # twice the half disc's area (Stokes)
    assert mods == ["numpy"]                                        # x'(t) by the IR's rules, not sympy


@pytest.mark.parametrize("a, b", [([0, 0, 0], [1, 1, 1]), ([-1.5, 0.3, 2], [0.7, -1.1, -0.4])])
def test_segment_work_of_a_conservative_field_is_the_potential_drop(a, b):
    # F = (2 x1 x2 + x3³, x1², 3 x1 x3²) = −∇V, V = −x1² x2 − x1 x3³ (19.7): U = V(a) − V(b) (19.8)
    fld = _field("2*x1*x2 + x3**3", "x1**2", "3*x1*x3**2")
    a, b = np.array(a, float), np.array(b, float)

    def V(x):
        return -x[0] ** 2 * x[1] - x[0] * x[2] ** 3

    U, err = segment_work(fld, a, b)
    exact = V(a) - V(b)
    # a polynomial of degree 4 in s: 16-point Gauss-Legendre is exact up to rounding of ~100 terms
    assert abs(U - exact) <= 1e-13 * (1 + abs(exact))
    assert err <= 1e-13 * (1 + abs(exact))


def test_segment_work_of_the_vortex_across_the_cut():
    # F = (−x2, x1, 0)/(x1² + x2²): the work from a to b is the angle swept about the x3 axis (19.6)
    fld = _field("-x2/(x1**2 + x2**2)", "x1/(x1**2 + x2**2)", "0")
    a, b = np.array([-1.0, -0.05, 0.0]), np.array([-1.0, 0.05, 0.0])
    U, err = segment_work(fld, a, b, panels=32)
    exact = -2 * math.atan(0.05)           # clockwise past the negative x1 axis
    assert abs(U - exact) <= 1e-12
    assert err <= 1e-12


def test_segment_work_is_nan_through_a_singularity():
    fld = _field("-x2/(x1**2 + x2**2)", "x1/(x1**2 + x2**2)", "0")
    U, _ = segment_work(fld, np.array([-1.0, 0.0, 0.0]), np.array([1.0, 0.0, 0.0]), panels=1, order=1)
    assert math.isnan(U)
