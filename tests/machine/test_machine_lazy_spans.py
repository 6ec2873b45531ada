"""A machine file's diagnostics keep their spans where the spans are found only when a diagnostic needs them
(issue 36, boot44: the per-axis tables, the register tables and a box zone's limits no longer search the text for
every key of a file that loads)."""

from __future__ import annotations

from pathlib import Path

import pytest

from nczones.errors import MachineFileError
from nczones.machine import parse_machine

#: a machine file wrong in each of those tables (a golden file: its check-machine output is pinned there too)
BAD = Path(__file__).resolve().parents[1] / "golden" / "machine" / "lazy_spans.toml"


def test_each_diagnostic_points_at_its_key():
    # the spans main (8aeb531) gave, every one found the eager way (a [zones.max] sub-table's keys have none)
    with pytest.raises(MachineFileError) as err:
        parse_machine(BAD.read_text(encoding="utf-8"), "bad.toml")
    found = [(d.code, d.span.line, d.span.column) if d.span is not None else (d.code, None, None)
             for d in err.value.diagnostics]
    assert found == [("ZN106", 6, 1), ("ZN110", 8, 1), ("ZN102", 5, 1), ("ZN103", 11, 1), ("ZN105", 14, 1),
                     ("ZN101", 15, 1), ("ZN105", 20, 9), ("ZN103", 19, 24), ("ZN103", None, None),
                     ("ZN105", None, None)]


def test_the_machine_table_s_numbers_point_at_their_keys():
    text = ('[machine]\nname = "bad3"\naxes = ["X", "Y", "Z"]\npulse = "-0.001"\nmax_feed = "0"\n'
            'monitor_period_ms = "100000"\narc_tolerance = "-1"\npath_tolerance = "99"\n[machine.rapid]\nX = "1"\n'
            'Y = "1"\nZ = "1"\n[machine.reference]\nX = "0"\nY = "0"\nZ = "0"\n')
    with pytest.raises(MachineFileError) as err:
        parse_machine(text, "bad3.toml")
    found = [(d.code, d.span.line, d.span.column) for d in err.value.diagnostics]
    assert found == [("ZN106", 4, 1), ("ZN106", 5, 1), ("ZN105", 6, 1), ("ZN106", 7, 1), ("ZN105", 8, 1)]
