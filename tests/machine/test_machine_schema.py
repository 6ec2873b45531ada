"""specs/machine.schema.json accepts every example machine and rejects what it can express."""

from __future__ import annotations

import decimal
import json
import tomllib
from pathlib import Path

import jsonschema
import pytest

ROOT = Path(__file__).resolve().parents[2]
SCHEMA = json.loads((ROOT / "specs" / "machine.schema.json").read_text(encoding="utf-8"))
VALIDATOR = jsonschema.Draft202012Validator(SCHEMA)
GOLDEN = ROOT / "tests" / "golden" / "machine"

#: Malformed files whose problem JSON Schema cannot express (checked by the
#: loader only); keep in step with the list in specs/machine-file.md.
NOT_EXPRESSIBLE = {
    "bad_toml_syntax": "not TOML at all (no document to validate)",
    "duplicate_toml_key": "duplicate keys are refused by the TOML parser",
    "upto_not_increasing": "order between array elements",
    "from_not_below_first_upto": "order between from and the first upto",
    "region_min_greater_than_max": "order between two values",
    "box_min_greater_than_max": "order between two values",
    "polygon_limits_after_multiline_vertices": "order between two values",
    "self_intersecting_polygon": "geometry",
    "bad_solids_axes": "tool solids need the axes X, Y and Z (a relation between sections)",
    "bad_lathe_solids": "order between two values (x = [8, -8], an inner radius above the radius) and a part's "
                        "form against the machine's axes (a mill part on a lathe)",
    "degenerate_polygon": "geometry",
    "duplicate_zone_names": "uniqueness of one field across array elements",
    "start_outside": "membership of the start position in the allowed set",
    "reference_outside_as_start": "membership of the start position in the allowed set",
}


def to_json(value):
    """TOML data read exactly -> JSON data: finite decimals become numbers, inf/nan text."""
    if isinstance(value, decimal.Decimal):
        if not value.is_finite():
            return str(value).lower().replace("infinity", "inf")
        return float(value)  # only for the validator's range checks, never for geometry
    if isinstance(value, dict):
        return {k: to_json(v) for k, v in value.items()}
    if isinstance(value, list):
        return [to_json(v) for v in value]
    return value


def load(path: Path):
    with path.open("rb") as f:
        return to_json(tomllib.load(f, parse_float=decimal.Decimal))


VALID = sorted((ROOT / "specs" / "machines").glob("*.toml")) + sorted((GOLDEN / "ok").glob("*.toml"))
BAD = sorted(GOLDEN.glob("*.toml"))


@pytest.mark.parametrize("path", VALID, ids=[p.stem for p in VALID])
def test_schema_accepts_valid_machines(path):
    errors = [e.message for e in VALIDATOR.iter_errors(load(path))]
    assert errors == []


@pytest.mark.parametrize("path", BAD, ids=[p.stem for p in BAD])
def test_schema_rejects_malformed_machines(path):
    if path.stem in ("bad_toml_syntax", "duplicate_toml_key"):
        with pytest.raises(tomllib.TOMLDecodeError):
            load(path)
        return
    valid = VALIDATOR.is_valid(load(path))
    if path.stem in NOT_EXPRESSIBLE:
        assert valid, f"{path.stem} is now caught by the schema: drop it from NOT_EXPRESSIBLE"
    else:
        assert not valid


def test_not_expressible_list_names_real_files():
    assert {p.stem for p in BAD} >= set(NOT_EXPRESSIBLE)


@pytest.mark.parametrize(
    "edit, ok",
    [
        (lambda d: d["machine"].update(pulse="0.0005"), True),
        (lambda d: d["machine"].update(pulse=0.5), True),
        (lambda d: d["machine"].update(pulse="1.5"), False),
        (lambda d: d["machine"].update(pulse={"X": "0.001", "Y": "0.0001"}), True),
        (lambda d: d["machine"].update(pulse={"X": "0.001"}), False),  # Y missing
        (lambda d: d["machine"]["rapid"].update(Z="100"), False),  # not an axis of this machine
        (lambda d: d["machine"].update(modal=["G90", "g21", "G18"]), True),
        (lambda d: d["machine"].update(modal=["G90", "G91"]), False),
        (lambda d: d["machine"].update(tool_axis="Z"), False),
        (lambda d: d["zones"][0]["regions"][0].update(upto=500.1), True),
        (lambda d: d["zones"][0]["regions"][0].update(upto="1000000.0"), True),
        (lambda d: d["zones"][0]["regions"][0].update(upto="1000000.1"), False),
        (lambda d: d["zones"][0]["regions"][0].update(upto="1e3"), False),
        (lambda d: d.update(homing={"X": {"direction": "+"}}), True),
        (lambda d: d.update(homing={"Q": {}}), False),
        (lambda d: d.update(tool_change={"position": {"X": "0", "Y": "300"}, "clearance": "300",
                                         "approach_distance": "5", "approach_feed": "200"}), True),
        (lambda d: d.update(tool_change={"X": "0"}), False),  # not a [tool_change] key
        (lambda d: d.update(tool_change={"position": {"X": "0"}, "retract_distance": "-5",
                                         "approach_distance": "5", "approach_feed": "200"}), False),
        (lambda d: d.update(tool_change={"position": {"X": "0"}, "clearance": "1", "variant": "halfway",
                                         "approach_distance": "5", "approach_feed": "200"}), False),
        (lambda d: d["offsets"].update({"G59.3": {"X": "1"}}), True),
        (lambda d: d.update(tool_lengths={"H12": "100", "T1": "5"}), False),
    ],
)
def test_schema_details_on_the_grinder(edit, ok):
    data = load(ROOT / "specs" / "machines" / "grinder.toml")
    edit(data)
    assert VALIDATOR.is_valid(data) is ok
