"""Shared fixtures of the Python module's tests: the curves every test
file uses, and the tool of the same build (CURVEFIG_TOOL, set by
python/tests/meson.build) for comparisons with the C library through the
language."""

import os
import subprocess

import numpy as np
import pytest

import curvefig

QUARTIC = [[0, 5], [1, -1], [3, 0], [4, 3], [6, 10]]
KNOTS = [0, 0, 0, 0, 0.2, 0.5, 0.5, 0.7, 1, 1, 1, 1]
CUBIC_P = [[0, 0], [1, 2], [2, -1], [3, 3], [4, 0], [5, 2], [6, 1], [7, 0]]


@pytest.fixture
def quartic():
    return curvefig.Bezier(QUARTIC)


@pytest.fixture
def spline():
    return curvefig.BSpline(3, KNOTS, CUBIC_P)


def tool():
    t = os.environ.get("CURVEFIG_TOOL")
    if not t or not os.path.exists(t):
        pytest.skip("CURVEFIG_TOOL is not set (run through meson test)")
    return t


def run_lua(code, tmp_path):
    """What `curvefig run` prints for a script: the C library through the
    language, for comparison."""
    p = tmp_path / "check.lua"
    p.write_text(code)
    r = subprocess.run([tool(), "run", str(p)], capture_output=True,
                       text=True, check=True)
    return r.stdout


def exact_values(text):
    """Numbers printed with %a (hexadecimal: exact) back to doubles."""
    return np.array([float.fromhex(x) for x in text.split()])
