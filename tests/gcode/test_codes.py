"""Every code of the LinuxCNC and the Fanuc code tables (nczones/gcode/codes.py) crossed with every lane.

For each G and M code a tiny program uses it; each lane then either declines it as the table says or gives
the full interpreter's motion:

- plain lane (``Interpreter._lean``): the result with the lane on equals the result with it off, and the
  lane takes a block with the code only when the table says it claims the code;
- fast path: the code's block between two runs of simple lines (the fast path's size), the segments equal
  the full interpreter's (a lathe code turns the fast path off for the whole program); for a code the fast path claims, a run of that code is taken by the fast path;
- double pass (programs with ``#``): it raises ``Declined`` for a code it declines, and for a code it claims
  it either declines for another reason or its end points equal the full interpreter's.

A code the interpreter knows that is missing from the table, or a table code without a program here, fails.

The Fanuc rows (``FANUC_G``) are crossed the same way with the Fanuc lanes: the plain lane
(``FanucInterpreter.lane``, which hands what it does not take to ``Interpreter.lane``) with segments, the same
lane on the box route (``boxes``: its sink a ``columns.BoxSink``, where it takes arcs too, ``_arc_lane``), the
box route's run reader (``boxrun``: ``read_box_run``) and the fast path.  A claimed code's block is taken by the
lane (the lane moved by it); a declined one is handed on (the lane did not take its block); and the result is
the same with the lane on and off.
"""

from __future__ import annotations

import pytest

from nczones.errors import GcodeError
from nczones.gcode import fastpath, interpret_text
from nczones.gcode.codes import (
    FANUC_G,
    FANUC_HOLE_CYCLES,
    LANE_BOXES,
    LANE_BOXRUN,
    LANE_INTERPRETER,
    LANE_PLAIN,
    LATHE_REASON,
    LINUXCNC_G,
    LINUXCNC_M,
    claimed,
    decline_reason,
    gname,
)
from nczones.gcode.fastpath import CODES as FAST_CODES
from nczones.gcode.interpreter import GROUP_OF, PLAIN_CODES, Interpreter
from nczones.gcode.linuxcnc.doubles import CODES as DOUBLES_CODES
from nczones.gcode.linuxcnc.doubles import Declined, double_pass
from nczones.machine import parse_machine
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("mill_xyz", extra='[tool_lengths]\nH1 = "10"\n'))

#: A block using each G code (key: 10 * number); a code not listed here uses its name alone.
G_BLOCKS = {
    0: "G0 X1 Y1", 10: "G1 X1 Y1", 20: "G2 X1 Y0 I0.5 J0", 30: "G3 X1 Y0 I0.5 J0",
    40: "G4 P0.1", 100: "G10 L2 P1 X1", 520: "G52 X1", 530: "G53 G0 X1", 920: "G92 X1",
    330: "S100 M3\nG33 Z-1 K0.1", 331: "S100 M3\nG33.1 Z-1 K0.1",
    382: "G38.2 Z-1 F10", 383: "G38.3 Z-1 F10", 384: "G38.4 Z-1 F10", 385: "G38.5 Z-1 F10",
    730: "G73 X1 Y1 Z-1 R1 Q0.5", 760: "G76 P0.1 Z-1 I-0.1 J0.1 K0.1", 810: "G81 X1 Y1 Z-1 R1",
    820: "G82 X1 Y1 Z-1 R1 P0.1", 830: "G83 X1 Y1 Z-1 R1 Q0.5", 840: "S100 M3\nG84 X1 Y1 Z-1 R1",
    850: "G85 X1 Y1 Z-1 R1", 860: "S100 M3\nG86 X1 Y1 Z-1 R1 P0.1", 870: "G87 X1 Y1 Z-1 R1",
    880: "G88 X1 Y1 Z-1 R1 P0.1", 890: "G89 X1 Y1 Z-1 R1 P0.1",
    50: "G5 X1 Y1 I0.5 J0 P0.5 Q0", 51: "G5.1 X1 Y1 I0.5 J0", 52: "G5.2 X1 Y1 P1 L3\nX2 Y0\nG5.3",
    53: "G5.2 X1 Y1 P1 L3\nX2 Y0\nG5.3", 62: "G6.2 X1 Y1 P1 Q1", 930: "G93 G1 X1 F10",
    950: "S100 M3\nG95 G1 X1 F0.1", 430: "G43 H1", 431: "G43.1 Z1", 432: "G43.2 H1", 640: "G64 P0.01",
    960: "G96 S100 D1000", 410: "G41", 420: "G42", 411: "G41.1 D1", 421: "G42.1 D1",
}
M_BLOCKS = {6: "T1 M6", 61: "M61 Q1", 62: "M62 P0", 63: "M63 P0", 64: "M64 P0", 65: "M65 P0",
            66: "M66 P0 L0", 67: "M67 E0 Q0", 68: "M68 E0 Q0", 19: "S100 M3\nM19 R0", 50: "M50 P1",
            51: "M51 P1", 52: "M52 P1", 53: "M53 P1", 0: "M0", 1: "M1", 60: "M60"}
HEAD = "G21 G90 G17 G54 G94 F100\n"


def _block(kind: str, key: int) -> str:
    if kind == "G":
        return G_BLOCKS.get(key, gname(key))
    return M_BLOCKS.get(key, f"M{key}")


def _full(text: str):
    run = interpret_text(text, MACHINE, fast=False)
    try:
        return [(s.kind, s.start, s.end, s.line) for s in run.segments()], [str(u) for u in run.unsupported]
    except GcodeError as exc:
        return ("error", exc.diagnostics[0].code, str(exc.diagnostics[0].span)), []


CASES = [("G", k) for k in sorted(LINUXCNC_G)] + [("M", k) for k in sorted(LINUXCNC_M)]


def _ids(case):
    kind, key = case
    return gname(key) if kind == "G" else f"M{key}"


def test_every_code_the_interpreter_knows_is_in_the_table():
    from nczones.gcode.interpreter import _M_GROUP  # noqa: PLC2701 (the interpreter's own M groups)
    assert set(GROUP_OF) <= set(LINUXCNC_G)
    assert set(_M_GROUP) <= set(LINUXCNC_M)
    # every program above names a code of the table
    assert set(G_BLOCKS) <= set(LINUXCNC_G) and set(M_BLOCKS) <= set(LINUXCNC_M)


@pytest.mark.parametrize("case", CASES, ids=_ids)
def test_plain_lane_claims_or_declines_each_code(case, monkeypatch):
    kind, key = case
    text = HEAD + _block(kind, key) + "\nG1 X2 Y2\nM30\n"
    taken: list[tuple] = []
    lean = Interpreter._lean

    def spy(self, g, m, *args):
        ok = lean(self, g, m, *args)
        if ok:
            taken.append((g, m))
        return ok

    monkeypatch.setattr(Interpreter, "_lean", spy)
    on = _full(text)
    monkeypatch.setattr(Interpreter, "_lean", lambda self, *args: False)
    off = _full(text)
    assert on == off
    claims = PLAIN_CODES.claims_g(key) if kind == "G" else PLAIN_CODES.claims_m(key)
    used = [g for g, _m in taken] if kind == "G" else [m for _g, m in taken]
    if not claims:
        assert key not in used, PLAIN_CODES.decline_g(key) if kind == "G" else PLAIN_CODES.decline_m(key)
        return
    # a claimed code on a plain move is taken by the lane
    monkeypatch.setattr(Interpreter, "_lean", spy)
    taken.clear()
    move = f"G{key // 10} X3 Y3" if kind == "G" else f"G1 X3 Y3 M{key}"
    _full(HEAD + move + "\nM30\n")
    assert key in ([g for g, _m in taken] if kind == "G" else [m for _g, m in taken])


def _there_and_back(block: str, point: str, n: int) -> str:
    """``n`` blocks of the code from (0, 0) to (1, y) and back: an arc's I changes sign on the way back."""
    back = block.replace(f"X1{point}", f"X0{point}").replace(f"Y1{point}", f"Y0{point}")
    back = back.replace("I0.5", "I-0.5")
    return "".join((block if i % 2 == 0 else back) + "\n" for i in range(n))


def _lines(n: int, y: int) -> str:
    return "".join(f"G1 X{i % 7}.5 Y{y}\n" for i in range(n))


@pytest.mark.parametrize("case", CASES, ids=_ids)
def test_fast_path_claims_or_declines_each_code(case):
    kind, key = case
    n = fastpath.MIN_RUN + 8
    text = HEAD + _lines(n, 1) + _block(kind, key) + "\n" + _lines(n, 2) + "M30\n"
    want = _full(text)
    run = interpret_text(text, MACHINE)
    try:
        got = [(s.kind, s.start, s.end, s.line) for c in run for s in c.segments()], \
            [str(u) for u in run.unsupported]
    except GcodeError as exc:
        got = ("error", exc.diagnostics[0].code, str(exc.diagnostics[0].span)), []
    assert got == want
    if FAST_CODES.decline_g(key) == LATHE_REASON and kind == "G":
        assert not run.fast  # the program-wide decline the table names
    if want[0] and want[0][0] != "error" and kind == "G" and FAST_CODES.claims_g(key) and key not in (810, 820):
        # a run of the code itself is the fast path's (G0-G3: simple lines)
        body = _there_and_back(_block(kind, key), "", n)
        text = HEAD + "G0 X0 Y0\n" + body + "M30\n"
        run = interpret_text(text, MACHINE)
        segs = [(s.kind, s.start, s.end, s.line) for c in run for s in c.segments()]
        assert (segs, [str(u) for u in run.unsupported]) == _full(text)
        assert run.fast_lines >= n - 1


@pytest.mark.parametrize("case", CASES, ids=_ids)
def test_double_pass_claims_or_declines_each_code(case):
    kind, key = case
    text = HEAD + "#1 = 1\n" + _block(kind, key) + "\nG1 X[#1 + 1] Y2\nM30\n"
    claims = DOUBLES_CODES.claims_g(key) if kind == "G" else DOUBLES_CODES.claims_m(key)
    try:
        path = double_pass(text, MACHINE, max_iterations=100)
    except Declined as exc:
        if claims:
            assert (gname(key) if kind == "G" else f"M{key}") not in exc.reason.split()
        return
    assert claims, f"the double pass took {_ids(case)}, which the table says it declines"
    want = _full(text)
    assert want[0] == [] or want[0][0] != "error"  # M2/M30 first: no motion on either path
    ends = [float(v) for s in want[0] for v in s[2]]
    rows = [col[k] for k in range(1, path.motions + 1) for col in path.columns]
    assert len(rows) == len(ends) and rows == pytest.approx(ends, abs=1e-9)


FANUC_BLOCKS = {730: "G73 X1. Y1. Z-1. R1. Q0.5", 830: "G83 X1. Y1. Z-1. R1. Q0.5",
                740: "M4 S100\nG74 X1. Y1. Z-1. R1.",
                760: "M3 S100\nG76 X1. Y1. Z-1. R1. Q0.1", 842: "M3 S100\nG84.2 X1. Y1. Z-1. R1. F1.",
                843: "M4 S100\nG84.3 X1. Y1. Z-1. R1. F1.", 840: "M3 S100\nG84 X1. Y1. Z-1. R1.",
                860: "M3 S100\nG86 X1. Y1. Z-1. R1.", 870: "G87 X1. Y1. Z-1. R1.",
                20: "G2 X1. Y0. I0.5 J0.", 30: "G3 X1. Y0. I0.5 J0.", 0: "G0 X1. Y1.", 10: "G1 X1. Y1.",
                800: "G80"}


@pytest.mark.parametrize("key", sorted(FANUC_G), ids=gname)
def test_fanuc_fast_path_claims_or_declines_each_code(key):
    """Fanuc: the code's block between two runs of simple lines; the fast path gives the full path's result,
    and takes a run of a code it claims."""
    from tests.gcode.fanuc.helpers import mill

    machine = mill()
    n = fastpath.MIN_RUN + 8
    block = FANUC_BLOCKS.get(key, f"{gname(key)} X1. Y1. Z-1. R1.")
    lines = "".join(f"G1 X{i % 7}.5 Y1. F100.\n" for i in range(n))
    text = "%\nO1000\nG17 G40 G49 G80 G90 G21 G54\n" + lines + block + "\n" + lines + "M30\n%\n"

    def run(fast):
        it = interpret_text(text, machine, fast=fast)
        try:
            return [(s.kind, s.start, s.end, s.line) for s in it.segments()], [str(u) for u in it.unsupported]
        except GcodeError as exc:
            return ("error", exc.diagnostics[0].code), []

    assert run(True) == run(False)
    if FANUC_G[key].lanes["fastpath"] == "" and key in FANUC_HOLE_CYCLES:  # hole lines after the first block
        body = block.replace("X1.", "G98 X1.") + "\n" + "".join(f"X{i % 7}.5 Y{i % 3}.\n" for i in range(n))
        text = "%\nO1000\nG17 G40 G49 G80 G90 G21 G54 F100.\nG0 X0. Y0. Z5.\n" + body + "G80\nM30\n%\n"
        it = interpret_text(text, machine)
        list(it)
        assert it.fast_lines >= n - 1
    elif FANUC_G[key].lanes["fastpath"] == "" and key != 800:
        body = _there_and_back(block, ".", n)
        text = "%\nO1000\nG17 G40 G49 G80 G90 G21 G54 F100.\nG0 X0. Y0.\n" + body + "M30\n%\n"
        it = interpret_text(text, machine)
        list(it)
        assert it.fast_lines >= n - 1


# -- Fanuc: the plain lane, on the box route too, and the box route's run reader ---------------------------

#: the line of the code's block in :func:`_fanuc_text` (its last line when it has two)
_FANUC_HEAD = "%\nO1000\nG17 G40 G49 G80 G90 G21 G54 G94 F100.\nG0 X0. Y0. Z0.\nG1 X0.5 Y0.5\n"


def _fanuc_text(key: int) -> tuple[str, int]:
    """A program with the code's block between straight moves, and the line of that block."""
    block = FANUC_BLOCKS.get(key, f"{gname(key)} X1. Y1. Z-1. R1.")
    text = _FANUC_HEAD + block + "\nG1 X2. Y2.\nM30\n%\n"
    return text, _FANUC_HEAD.count("\n") + block.count("\n") + 1


def _lane_spy(monkeypatch) -> list[tuple[int, int]]:
    """``(line, motion mode after it)`` of every block ``FanucInterpreter.lane`` takes from now on."""
    from nczones.gcode.fanuc.interpreter import FanucInterpreter

    taken: list[tuple[int, int]] = []
    real = FanucInterpreter.lane

    def spy(self, letters, values, span, index):
        got = real(self, letters, values, span, index)
        if got:
            taken.append((span.line, self.motion))
        return got

    monkeypatch.setattr(FanucInterpreter, "lane", spy)
    return taken


def _lane_off(monkeypatch) -> None:
    from nczones.gcode.fanuc.interpreter import FanucInterpreter

    monkeypatch.setattr(FanucInterpreter, "lane", lambda self, *args: 0)


def _taken_as_claimed(table_lane: str, key: int, line: int, taken: list[tuple[int, int]]) -> None:
    """The code's block was taken by the lane, by the code's motion, exactly when ``table_lane`` claims it."""
    if decline_reason(FANUC_G, table_lane, key) is None:
        assert (line, key) in taken, (gname(key), taken)
    else:
        assert line not in [t[0] for t in taken], decline_reason(FANUC_G, table_lane, key)


@pytest.mark.parametrize("key", sorted(FANUC_G), ids=gname)
def test_fanuc_plain_lane_claims_or_declines_each_code(key, monkeypatch):
    """With segments (no box route): G0/G1 are the lane's, an arc and every other code are handed on."""
    from tests.gcode.fanuc.helpers import mill

    machine = mill()
    text, line = _fanuc_text(key)

    def run():
        it = interpret_text(text, machine, fast=False)
        try:
            return [(s.kind, s.start, s.end, s.line) for s in it.segments()], [str(u) for u in it.unsupported]
        except GcodeError as exc:
            return ("error", exc.diagnostics[0].code), []

    taken = _lane_spy(monkeypatch)
    on = run()
    assert taken, "the lane took no block at all: the crossing would be vacuous"
    _taken_as_claimed(LANE_PLAIN, key, line, taken)
    _lane_off(monkeypatch)
    assert run() == on


def _route_report(text: str, machine) -> tuple:
    from nczones.prover import verify_text

    try:
        r = verify_text(text, machine, file="t.nc")
    except GcodeError as exc:
        return ("error", exc.diagnostics[0].code)
    return (r.verdict.label, tuple(r.violations), tuple(r.reasons), tuple(r.notes), (r.extra or {}).get("counts"),
            "fanuc_boxes" in dict(r.stats))


@pytest.mark.parametrize("key", sorted(FANUC_G), ids=gname)
def test_fanuc_box_route_lanes_claim_or_decline_each_code(key, monkeypatch):
    """On the box route: the plain lane into a ``BoxSink`` (the reader off) takes G0-G3 and hands on the rest;
    the run reader takes the lines of G0-G3 and ends its run at any other; the report is the same with each of
    them on and off (and the route proves the program: the lanes were on the route)."""
    from nczones.gcode.fanuc import boxrun
    from tests.gcode.fanuc.helpers import mill

    machine = mill()
    text, line = _fanuc_text(key)
    monkeypatch.setattr(boxrun, "BOX_RUNS", False)
    taken = _lane_spy(monkeypatch)
    lanes = _route_report(text, machine)
    assert lanes[-1] is True, lanes
    assert (lanes[0] == "unknown") is (decline_reason(FANUC_G, LANE_INTERPRETER, key) is not None), lanes
    _taken_as_claimed(LANE_BOXES, key, line, taken)
    with monkeypatch.context() as m:
        _lane_off(m)
        assert _route_report(text, machine) == lanes
    read: list[int] = []
    real = boxrun.read_box_run

    def reader(runner, src, pos, lineno):
        got = real(runner, src, pos, lineno)
        if got is not None:
            read.extend(range(lineno, got[1]))
        return got

    monkeypatch.setattr(boxrun, "BOX_RUNS", True)
    monkeypatch.setattr(boxrun, "read_box_run", reader)
    assert _route_report(text, machine) == lanes
    assert read, "the reader took no line at all: the crossing would be vacuous"
    assert (line in read) is (decline_reason(FANUC_G, LANE_BOXRUN, key) is None), (gname(key), read)


def test_the_fanuc_full_column_is_the_interpreter_s():
    """The codes the full column declines are the Fanuc interpreter's unknown codes (of this table's rows)."""
    from nczones.gcode.fanuc.interpreter import UNKNOWN_G

    assert set(FANUC_G) - claimed(FANUC_G, LANE_INTERPRETER) == set(FANUC_G) & set(UNKNOWN_G)


def test_the_box_run_reader_s_codes_are_the_table_s():
    """The reader's G table (its fixed words G0 .. G03) names the codes the boxrun column claims, and the box
    lane's (``_arc_lane`` G2/G3 and ``lane`` G0/G1) are the same codes."""
    from nczones.gcode.fanuc import boxrun

    assert frozenset(boxrun._G.values()) == claimed(FANUC_G, LANE_BOXRUN) == claimed(FANUC_G, LANE_BOXES)
    assert claimed(FANUC_G, LANE_PLAIN) < claimed(FANUC_G, LANE_BOXES)
