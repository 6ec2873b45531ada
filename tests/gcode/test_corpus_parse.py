"""The language layer over the external corpus: no traceback, LinuxCNC control-flow oracles."""

from __future__ import annotations

import collections
import csv
import re
from pathlib import Path

import pytest

from nczones.errors import GcodeError
from nczones.gcode.program import UnsupportedGcode, read_program
from tests.corpus import CORPUS

pytestmark = [pytest.mark.corpus, pytest.mark.skipif(not CORPUS.is_dir(), reason="corpus folder missing")]
LOCATION = re.compile(r"^.+:\d+:\d+: error\[GC\d{3}\]: ")


def programs() -> list[str]:
    with open(CORPUS / "MANIFEST.tsv", newline="") as f:
        return [row["path"] for row in csv.DictReader(f, delimiter="\t") if row["role"] == "program"]


def run(path: Path, **kw):
    return list(read_program(path, **kw))


def test_every_corpus_program_runs_or_is_diagnosed(capsys):
    outcomes: collections.Counter = collections.Counter()
    for rel in programs():
        path = CORPUS / rel
        try:
            run(path, max_loop_iterations=2000)
            outcomes["blocks"] += 1
        except GcodeError as e:
            assert LOCATION.match(e.diagnostics[0].render()), rel
            outcomes["GcodeError"] += 1
        except UnsupportedGcode as e:
            assert LOCATION.match(e.diagnostic.render()), rel
            outcomes["unsupported " + e.code] += 1
    with capsys.disabled():
        print("\nlanguage layer over the corpus:", dict(sorted(outcomes.items())))
    assert outcomes["blocks"] >= 650


# Of tests/interp/bad, these are language errors and rejected here; the rest (arc radius, canned-cycle
# axes, cutter compensation, feed rate, missing IJR, G64/M19 R words, probe without axes) are the
# interpreter's: a-in-canned-cycle*, bad-arc.*, ccomp-*, g64-*, no-feed-rate, no-ijr, probe-no-axes.
LANGUAGE_BAD = ["exists-1", "exists-2", "exists-3", "exists-4", "exists-5", "exists-6", "exists-7", "nested"]


@pytest.mark.parametrize("name", LANGUAGE_BAD)
def test_linuxcnc_bad_language_programs_are_rejected(name):
    with pytest.raises(GcodeError) as e:
        run(CORPUS / "linuxcnc/tests/interp/bad" / f"{name}.ngc")
    assert e.value.diagnostics[0].span.line >= 2  # line 1 holds LinuxCNC's message


def test_bad_interpreter_programs_pass_the_language_layer():
    bad = CORPUS / "linuxcnc/tests/interp/bad"
    for path in sorted(bad.glob("*.ngc")):
        if path.stem not in LANGUAGE_BAD:
            assert run(path), path.name


def expected_messages(expected: Path, awk: bool) -> list[str]:
    """MESSAGE("..") calls and bare PRINT lines of an rs274 canon log, in order."""
    out = []
    for line in expected.read_text().splitlines():
        m = re.search(r'MESSAGE\("(.*)"\)$', line)
        if m:
            out.append(" ".join(m.group(1).split()))
        elif line.strip() and "N....." not in line and not re.match(r"\s*\d*\s*N\d", line):
            out.append(" ".join(line.split()))
    return out


def our_messages(path: Path, awk: bool) -> list[str]:
    out = []
    for block in read_program(path):
        for msg in block.messages:
            kind, _, text = msg.partition(",")
            if kind == "PRINT":
                fields = text.split()
                out.append(" ".join(fields[1:] if awk else fields))  # awk '{$1=""}' drops the first field
            elif kind == "DEBUG":
                out.append(" ".join(text.split()))
    return out


@pytest.mark.parametrize(
    "test_dir, program, awk",
    [("interp/do-while-break", "test.ngc", True), ("interp/m98m99/02-variables", "test.ngc", True),
     ("interp/m98m99/05-M98-loops", "test.ngc", True), ("interp/m98m99/07-nested-subs", "test.ngc", True),
     ("interp/m98m99/08-sub-follows-main", "test.ngc", True), ("interp/m98m99/10-M98-P001", "test.ngc", True),
     ("interp/m98m99/14-o-expression-call", "test.ngc", False)],
)
def test_linuxcnc_control_flow_messages_match(test_dir, program, awk):
    d = CORPUS / "linuxcnc/tests" / test_dir
    expected = expected_messages(d / "expected", awk)
    assert expected, "oracle has messages"
    assert our_messages(d / program, awk) == expected


@pytest.mark.parametrize(
    "test_dir", ["oword/while.0", "oword/sub.0", "interp/oword-bug315", "interp/oword-bug315-p2",
                 "interp/m98m99/01-basics", "interp/m98m99/09-disable-fanuc-subs", "interp/flowsnake",
                 "interp/namedparam-bug424", "interp/exists"])
def test_linuxcnc_language_tests_run(test_dir):
    d = CORPUS / "linuxcnc/tests" / test_dir
    for path in sorted(d.glob("*.ngc")):
        blocks = run(path)
        assert [b.index for b in blocks] == list(range(len(blocks)))


def test_exists_program_matches_canon_log():
    (first, *_rest) = run(CORPUS / "linuxcnc/tests/interp/exists/test.ngc")
    assert [(w.letter, w.value) for w in first.words][1:] == [("X", 1), ("Y", 0), ("Z", 1), ("A", 0)]


@pytest.mark.parametrize(
    "test_dir, program, code",
    [("interp/m98m99/03-error-M98-no-P-word", "test.ngc", "GC317"),
     ("interp/m98m99/04-M98-but-no-sub", "test.ngc", "GC317"),
     ("interp/m98m99/06-error-mixed-sub-styles", "O...-called-with-O..._call.ngc", "GC313"),
     ("interp/m98m99/06-error-mixed-sub-styles", "O...-ended-with-O..._endsub.ngc", "GC315"),
     ("interp/m98m99/06-error-mixed-sub-styles", "O...-sub-called-with-M98.ngc", "GC317"),
     ("interp/m98m99/06-error-mixed-sub-styles", "O...-sub-ended-with-M99.ngc", "GC315")],
)
def test_linuxcnc_error_tests_are_rejected(test_dir, program, code):
    with pytest.raises(GcodeError) as e:
        run(CORPUS / "linuxcnc/tests" / test_dir / program)
    assert e.value.code == code
