"""What the LinuxCNC seam hunts share (hunt42's :mod:`tests.contract.test_double_pass_seams42`, hunt43's
``test_double_pass_seams43``, dup44): a drawn mill case for hunt40's relations 1-3, relation 4 (rs274) on a drawn
program, and the four tests each hunt runs with its own generator (``programs(one_unit=..., comp=...)``, a
strategy of templates) and checks."""

from __future__ import annotations

from collections.abc import Callable

import pytest
from hypothesis import event, given, settings
from hypothesis import strategies as st

from tests.contract.test_double_pass_seams40 import _SETTINGS, _mill, check_rs274
from tests.gcode.rs274_pass import NEEDS_RS274

TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any


def mill_case(data: Any, programs: Callable[..., Any], units: str | None = None) -> tuple[str, dict, str]:
    """``(template, values, units)`` of a drawn mill program: in one unit a quarter of the time, else compensated
    half the time (the machine then has LinuxCNC's compensation and no G20 or G91 among its modal codes);
    ``units`` drawn unless given."""
    draw = data.draw
    one_unit = draw(st.integers(0, 3)) == 0
    units = units or draw(st.sampled_from(("G20", "G21")))
    comp = not one_unit and draw(st.booleans())
    template = draw(programs(one_unit=one_unit, comp=comp))
    values = _mill(draw, template)
    if comp:
        modal = [g for g in values.get("machine.modal", ()) if g not in ("G20", "G91")]
        values = {**values, "machine.cutter_compensation": "linuxcnc", "machine.modal": modal}
    return template, values, units


def check_rs274_drawn(data: Any, workdir: Any, programs: Callable[..., Any]) -> None:
    """Relation 4 on a drawn program without compensation; one with a motion below the resolution of rs274's log
    (``(tiny)``: ``tests.oracles.rs274.compare`` drops rs274's moves that do not move in the log, the full path's
    stay: hunt42's H3) is counted, not compared."""
    units = data.draw(st.sampled_from(("G20", "G21")))
    template = data.draw(programs(one_unit=data.draw(st.booleans())))
    if "(tiny)" in template:
        event("rs274's own (a motion below its log's resolution)")
        return
    event(check_rs274(template, units, workdir))


def seam_tests(check_any: Callable[[Any], None], check_rs274_any: Callable[[Any, Any], None], ci: int,
               long: int) -> tuple[Callable[..., None], ...]:
    """A hunt's four tests: relations 1-3 (``check_any(data)``) and 4 (``check_rs274_any(data, workdir)``), each
    in CI (``ci`` examples, derandomized; rs274 one less) and under ``-m long`` (``long`` examples)."""

    @settings(max_examples=ci, derandomize=True, **_SETTINGS)
    @given(st.data())
    def agree(data):
        check_any(data)

    @NEEDS_RS274
    @settings(max_examples=ci - 1, derandomize=True, **_SETTINGS)
    @given(st.data())
    def rs274(tmp_path_factory, data):
        check_rs274_any(data, tmp_path_factory.mktemp("rs274"))

    @pytest.mark.long
    @settings(max_examples=long, **_SETTINGS)
    @given(st.data())
    def agree_long(data):
        check_any(data)

    @pytest.mark.long
    @NEEDS_RS274
    @settings(max_examples=long, **_SETTINGS)
    @given(st.data())
    def rs274_long(tmp_path_factory, data):
        check_rs274_any(data, tmp_path_factory.mktemp("rs274"))

    return agree, rs274, agree_long, rs274_long
