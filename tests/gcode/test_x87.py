"""LinuxCNC's trigonometry in x87 long double (nczones/gcode/linuxcnc/x87.py) against numpy's 80-bit longdouble.

numpy's ``longdouble`` is the x87 format on x86-64 and its ``sin`` calls the same ``sinl``: an independent
computation of the same formulas (``sin((x * M_PIl) / 180.0)``, ``(r * 180.0) / M_PIl``), rounded to double
once at the end.  The values ``rs274`` computes are in tests/gcode/test_language.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.gcode.linuxcnc import x87

pytestmark = pytest.mark.skipif(not x87.AVAILABLE or np.finfo(np.longdouble).nmant != 63,
                                reason="no x87 long double on this host")

LD = np.longdouble
PI_L = LD("3.141592653589793238462643383279502884")


def oracle(name: str, x: float) -> float:
    fn = {"sin": np.sin, "cos": np.cos, "tan": np.tan}[name]
    return float(fn((LD(x) * PI_L) / LD(180.0)))


def test_pi_is_m_pil():
    assert LD(x87.PI64) * LD(2.0) ** -62 == PI_L


degrees = st.one_of(
    st.floats(-720, 720, allow_nan=False),
    st.integers(-100_000, 100_000).map(lambda k: k * 0.1),
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e300, max_value=1e300),
    st.floats(allow_nan=False, allow_infinity=False, min_value=-1e-300, max_value=1e-300),
    st.sampled_from([0.0, -0.0, 30.0, 45.0, 60.0, 90.0, 180.0, 270.0, 360.0, 5e-324, -5e-324, 1e308]),
)


@settings(max_examples=2000, deadline=None, derandomize=True)
@given(degrees, st.sampled_from(["sin", "cos", "tan"]))
def test_trigonometry_is_the_80_bit_formula(x, name):
    got = {"sin": x87.sin_degrees, "cos": x87.cos_degrees, "tan": x87.tan_degrees}[name](x)
    want = oracle(name, x)
    assert got == want and math.copysign(1.0, got) == math.copysign(1.0, want), (x, got, want)


@settings(max_examples=2000, deadline=None, derandomize=True)
@given(st.one_of(st.floats(-4, 4, allow_nan=False), st.floats(allow_nan=False, allow_infinity=False,
                                                                min_value=-1e300, max_value=1e300)))
def test_degrees_from_radians_is_the_80_bit_quotient(r):
    want = float(LD(r * 180.0) / PI_L)
    assert x87.degrees_from_radians(r) == want


def test_the_angles_a_loop_computes():
    # arguments a program computes (#1 * 0.9), where the double formula often differs from the controller
    for k in range(-2000, 2001):
        x = k * 0.9
        for name, fn in (("sin", x87.sin_degrees), ("cos", x87.cos_degrees), ("tan", x87.tan_degrees)):
            assert fn(x) == oracle(name, x), (name, x)


def _argument_by_round64(x: float) -> tuple[int, int]:
    """``(x * M_PIl) / 180.0`` by the generic rounding :func:`x87._round64`, twice (the unrolled one's reference)."""
    m, e = math.frexp(abs(x))
    sig, exp = x87._round64(int(m * 2.0**53) * x87.PI64, e - 53 - 62, False)
    quotient, remainder = divmod(sig << 72, 180)
    return x87._round64(quotient, exp - 72, remainder != 0)


@settings(max_examples=400, deadline=None, derandomize=True)
@given(degrees.filter(lambda x: x != 0.0))
def test_the_unrolled_argument_rounds_as_round64(x):
    assert x87._argument(x) == _argument_by_round64(x)


def test_no_quotient_is_half_way():
    # the quotient's low 64 (or 65) bits depend on q mod 45 only, and none is exactly one half (x87._argument)
    for b in range(45):
        low = (b << 70) // 45
        for extra in (64, 65):
            assert low & ((1 << extra) - 1) != 1 << (extra - 1), b
    for m in (1 << 52, 3 << 51):  # the significands with 51 or 52 trailing zeros: the product is not half way
        p = m * x87.PI64
        extra = 53 if p >> 116 else 52
        assert p & ((1 << extra) - 1) != 1 << (extra - 1)


def test_the_argument_of_whole_degrees_and_tenths():
    for k in range(1, 20001):
        for x in (k * 1.0, k * 0.1, -k * 0.25):
            assert x87._argument(x) == _argument_by_round64(x), x
