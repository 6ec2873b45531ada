"""A second reading of the G68/G51 column lane (nczones/gcode/fanuc/transform_columns.py, review42).

* ``test_huge_numbers_decline_and_never_wrap`` — a centre or a work offset near the ``int64`` limit: the lane
  declines (the general path decides), where it raised ``OverflowError`` or wrapped a machine coordinate
  (a G54 X of 9223372036854775 mm rotated by 30 degrees came out at -9.2e15 mm).
"""

from __future__ import annotations

import pytest

from nczones.gcode import interpret_text
from nczones.gcode.fastpath import MIN_RUN

from .helpers import mill

_MILL = mill()
_BODY = [f"X{k % 50}.5 Y{k % 30}.25" for k in range(MIN_RUN + 8)]


def _program(pre: list[str], transform: str) -> str:
    return "\n".join(["%", "O1000", *pre, "G00 G17 G90 G21 G54 X0. Y0.", "G43 H1 Z25.", "G01 Z-1. F800.",
                      transform, "G01 X1. Y1.", *_BODY, "G69" if "G68" in transform else "G50", "G00 X0. Y0.",
                      "M30", "%"]) + "\n"


def _outcome(text: str, fast: bool) -> tuple:
    run = interpret_text(text, _MILL, fast=fast, file="xf.nc")
    return [(s.kind, s.start, s.end, s.centre) for s in run.segments()], run.status, \
        [(u.code, u.reason) for u in run.unsupported]


@pytest.mark.parametrize(("pre", "transform"), [
    ([], "G68 X9999999999999999. Y0 R30."),                      # a centre beyond int64 (scaled)
    ([], "G68 X-9223372036854775. Y0 R30."),                     # one at its edge
    (["G10 L2 P1 X9223372036854775."], "G68 X0 Y0 R30."),        # an offset the machine point wrapped past
    (["G10 L2 P1 X-9223372036854775."], "G68 X0 Y0 R30."),
    (["G10 L2 P1 X9223372036854775."], "G51 X0 Y0 Z-1. P2."),    # the machine start beyond int64
    ([], "G51 X9999999999999999. Y0 Z-1. P2."),
    ([], "G51 X9223372036854775. Y0 Z-1. P-2."),
])
def test_huge_numbers_decline_and_never_wrap(pre, transform):
    text = _program(pre, transform)
    assert _outcome(text, True) == _outcome(text, False)
