"""Soundness hunt where features meet (task t7 "hunt", target 2): G64 corners × ``--param`` ranges × work
offsets (G10 L2, G10 L20, G92, G55, G53) × margins, by metamorphic relations.

1. **Range ⇒ values**: a range verdict ``safe`` is a proof for every value in it, so the same program on the
   machine file with the offset (or start position) set to a sampled value of the range, its ends included,
   must be ``safe`` too (a sampled value ``unsafe`` or ``unknown`` with the range ``safe`` is a wrong
   ``safe``: the concrete run proves less, so only ``unsafe`` counts as a finding; ``unknown`` is counted).
2. **Translation**: moving the machine's zones, reference, start and every work offset by one vector (and the
   machine coordinates the program writes: G53 moves, G10 L2 offsets) moves the whole motion by it; the
   verdict must be the same.
3. **Margin**: a verdict ``safe`` with a margin stays ``safe`` with a smaller one.

The programs draw from a vocabulary of motion and offset blocks on an XY machine that starts in G64 (so every
corner is proved by the blend enclosure), a table and a forbidden clamp.  CI size ``RANGE_EXAMPLES["ci"]``;
the ``long`` test runs ``RANGE_EXAMPLES["long"]`` (numbers in specs/contract.md).
"""

from __future__ import annotations

from decimal import Decimal
from unittest import mock

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.errors import NczonesError
from nczones.machine import parse_machine
from nczones.prover import verify_text
from tests.machines import box_zone, machine_text

RANGE_EXAMPLES = {"ci": 4, "long": 5_000}
#: (relation, outcome) counts of this session's runs (printed by the long profile)
OUTCOMES: dict[tuple[str, str], int] = {}

def _machine_text(mode: str, v: dict[str, str]) -> str:
    """tests/machines/xy_range_hunt.toml with the values ``v`` and its table and clamp."""
    keys = {"machine.path_mode": mode, "machine.reference.X": v["rx"], "machine.reference.Y": v["ry"],
            "machine.start.X": v["sx"], "machine.start.Y": v["sy"],
            "offsets.G54": {"X": v["g54x"], "Y": v["g54y"]}, "offsets.G55": {"X": v["g55x"], "Y": v["g55y"]}}
    zones = (box_zone("table", {"X": v["tx0"], "Y": v["ty0"]}, {"X": v["tx1"], "Y": v["ty1"]})
             + box_zone("clamp", {"X": v["cx0"], "Y": v["cy0"]}, {"X": v["cx1"], "Y": v["cy1"]}, forbid=True))
    return machine_text("xy_range_hunt", set=keys, extra=zones)


def machine(mode: str, shift=(0, 0), **values) -> object:
    base = dict(rx=0, ry=0, sx=5, sy=5, g54x=10, g54y=0, g55x=-20, g55y=15, tx0=-55, ty0=-55, tx1=55, ty1=55,
                cx0=15, cy0=15, cx1=30, cy1=30)
    base.update(values)
    dx, dy = shift
    out = {}
    for k, v in base.items():
        d = dx if k in ("rx", "sx", "g54x", "g55x", "tx0", "tx1", "cx0", "cx1") else dy
        out[k] = str(Decimal(str(v)) + d)
    return parse_machine(_machine_text(mode, out))


_C = st.integers(-50, 50)
_BLOCK = st.one_of(
    st.tuples(st.sampled_from(["G0", "G1"]), _C, _C).map(lambda t: f"{t[0]} X{t[1]} Y{t[2]}"),
    st.tuples(st.sampled_from(["G0", "G1"]), _C, _C).map(lambda t: f"{t[0]} X{t[1]} Y{t[2]}"),
    st.tuples(_C, _C).map(lambda t: f"G1 X{t[0]}.5 Y{t[1]}"),
    st.sampled_from(["G90", "G91", "G54", "G55", "G92.1", "G61", "G64", "G64 P0.5", "G4 P0"]),
    st.tuples(_C, _C).map(lambda t: f"G92 X{t[0]} Y{t[1]}"),
    st.tuples(_C, _C).map(lambda t: f"G10 L2 P2 X{t[0]} Y{t[1]}"),
    st.tuples(_C, _C).map(lambda t: f"G10 L20 P1 X{t[0]} Y{t[1]}"),
    st.tuples(_C, _C).map(lambda t: f"G53 G0 X{t[0]} Y{t[1]}"),
)
_RANGE = st.sampled_from(["G54.X", "G54.Y", "G55.X", "start.X", "start.Y"])


def _shifted(text: str, dx: Decimal, dy: Decimal) -> str:
    """``text`` with the machine-coordinate numbers (G53 moves, G10 L2 offsets) moved by (dx, dy)."""
    import re

    def move(line: str) -> str:
        if not (line.startswith("G53") or line.startswith("G10 L2 ")):
            return line
        line = re.sub(r"X(-?[0-9.]+)", lambda mo: f"X{Decimal(mo.group(1)) + dx}", line)
        return re.sub(r"Y(-?[0-9.]+)", lambda mo: f"Y{Decimal(mo.group(1)) + dy}", line)

    return "\n".join(move(line) for line in text.split("\n"))


def _program(blocks: list[str]) -> str:
    return "G21 G90 G54 F2000\n" + "\n".join(blocks) + "\nM2\n"


def _concrete(name: str, value: Decimal, mode: str) -> object:
    """The machine with range ``name``'s deviation ``value`` written into the file."""
    key = {"G54.X": "g54x", "G54.Y": "g54y", "G55.X": "g55x", "start.X": "sx", "start.Y": "sy"}[name]
    base = {"g54x": 10, "g54y": 0, "g55x": -20, "sx": 5, "sy": 5}[key]
    return machine(mode, **{key: Decimal(base) + value})


def _count(relation: str, outcome: str) -> None:
    OUTCOMES[(relation, outcome)] = OUTCOMES.get((relation, outcome), 0) + 1


def _examples() -> int:
    return RANGE_EXAMPLES["long" if settings.default.max_examples > 100 else "ci"]


def _check(blocks, name, lo, size, frac, mode):
    text = _program(blocks)
    hi = lo + size
    m = machine(mode)
    try:
        got = verify_text(text, m, params=[f"{name}={lo}..{hi}"])
    except NczonesError as e:  # a program the interpreter refuses (G53 in G91, ...): refused alike everywhere
        _count("error", e.code)
        with pytest.raises(NczonesError):
            verify_text(text, m)
        return
    _count("range", got.verdict.label)
    if got.verdict.label == "safe":
        for v in {Decimal(lo), Decimal(hi), Decimal(lo) + Decimal(size) * frac}:
            conc = verify_text(text, _concrete(name, v, mode)).verdict.label
            _count("range-sample", conc)
            assert conc != "unsafe", f"range {name}={lo}..{hi} safe, value {v} unsafe:\n{text}"
    plain = verify_text(text, m)
    moved = verify_text(_shifted(text, Decimal(7), Decimal(-3)), machine(mode, shift=(Decimal(7), Decimal(-3))))
    _count("translation", f"{plain.verdict.label}/{moved.verdict.label}")
    assert plain.verdict.label == moved.verdict.label, f"translation changed the verdict:\n{text}"
    wider = verify_text(text, m, margin="0.5")
    _count("margin", f"{wider.verdict.label}/{plain.verdict.label}")
    if wider.verdict.label == "safe":
        assert plain.verdict.label == "safe", f"safe with margin 0.5, {plain.verdict.label} without:\n{text}"


def test_range_hunt():
    @settings(max_examples=_examples(), deadline=None)
    @given(st.lists(_BLOCK, min_size=2, max_size=9), _RANGE, st.integers(-3, 0), st.integers(0, 4),
           st.sampled_from([Decimal("0.25"), Decimal("0.5"), Decimal("0.75")]), st.sampled_from(["G64", "G61"]))
    def run(blocks, name, lo, size, frac, mode):
        _check(blocks, name, lo, size, frac, mode)

    run()


@pytest.mark.long
def test_range_hunt_long():
    OUTCOMES.clear()
    with mock.patch.dict(RANGE_EXAMPLES, {"ci": RANGE_EXAMPLES["long"]}):
        test_range_hunt()
    print(f"range hunt: {sorted(OUTCOMES.items())}")
