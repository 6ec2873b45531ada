"""``#4114``, the last sequence number (and ``#4113``, the last M), after blocks every lane of the Fanuc reader takes.

The control keeps the N of the last block it read (0i-MF "System variables": #4114, modal information of the
last block); a macro may read it (specs/fanuc.md lists it as modelled).  The general path keeps it
(``FanucInterpreter._record_block``); the plain-move lane, the expression lane, the lines kept as closures in a
loop and the box route's run reader (``gcode/fanuc/boxrun.py``) took numbered blocks without it, so a program
that moved by ``#4114`` after ``N20 G01 X2.`` was proved at X 0.5 while the control goes to X 20.5.  Each case
below reads ``#4114`` after a numbered block taken by one of them and moves to ``X[#4114 + 0.5]``: the move's end
is the N plus 0.5 (program X; the test mill's G54 adds 100), and ``verify`` finds it past a wall the other
moves stay inside.
"""

from __future__ import annotations

from fractions import Fraction

import pytest

from nczones.errors import GcodeError
from nczones.prover import verify_text
from tests.gcode.fanuc.helpers import ends, mill, probe_route

HEAD = "O6000\nG90 G17 G21 G54 F300.\n"
TAIL = "G01 X[#4114 + 0.5] Y2.\nM30\n"
#: (the program's middle, the N the read must give)
CASES = {
    "a plain line": ("N10 G01 X1. Y1.\nN20 G01 X2. Y1.\n", 20),
    "a plain line with a comment": ("N10 G01 X1. Y1.\nN20 G01 X2. Y1. (CUT)\n", 20),
    "a line with an expression": ("#1 = 1\nN10 G01 X1. Y1.\nN20 G01 X[#1 + 1] Y1.\n", 20),
    "an unnumbered line after the last numbered one": ("N10 G01 X1. Y1.\nN20 G01 X2. Y1.\nG01 X3. Y1.\n", 20),
    "a plain line in a loop (a closure)": ("#2 = 0\nWHILE [#2 LT 3] DO1\nN30 G01 X2. Y1.\n#2 = #2 + 1\nEND1\n", 30),
    "an expression line in a loop": ("#2 = 0\nWHILE [#2 LT 3] DO1\nN31 G01 X[#2] Y1.\n#2 = #2 + 1\nEND1\n", 31),
    # N40 runs as a kept closure from the third pass on (a plain line run a third time), N50 in the first two
    # passes only: N50 is the last N before it
    "a closure after another line's N": (
        "#2 = 0\nWHILE [#2 LT 4] DO1\nN40 G01 X1. Y1.\n#5 = FIX[#2 / 2]\nWHILE [#5 LT 1] DO2\n"
        "N50 G01 X2. Y1.\n#5 = 1\nEND2\n#2 = #2 + 1\nEND1\n", 40),
    "an expression closure after another line's N": (
        "#2 = 0\nWHILE [#2 LT 4] DO1\nN41 G01 X[#2] Y1.\n#5 = FIX[#2 / 2]\nWHILE [#5 LT 1] DO2\n"
        "N50 G01 X2. Y1.\n#5 = 1\nEND2\n#2 = #2 + 1\nEND1\n", 41),
    "a general block after a lane's": ("N10 G01 X1. Y1.\nN25 M08\n", 25),
    "a lane's block after a general one": ("N25 M08\nN10 G01 X1. Y1.\n", 10),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_the_read_gives_the_last_n(name):
    middle, n = CASES[name]
    got = ends(HEAD + middle + TAIL)
    assert got[-1][0] == Fraction(n) + Fraction(1, 2) + 100, (name, got[-1])


def _wall(x: int) -> object:
    return mill(tables=('\n[[zones]]\nname = "box"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-300" }\n'
                        f'max = {{ X = "{x}", Y = "90", Z = "0" }}\n'))


@pytest.mark.parametrize("tail", ["", "G01 X3. Y1.\nG00 X0. Y0.\n"])
def test_the_box_run_reader_keeps_the_last_n(monkeypatch, tail):
    """The box route's reader takes a plain program (no ``#``: a macro program's lines are the lanes'); a
    subprogram in another file may still read ``#4114`` after it, so the reader keeps the N of the last numbered
    line it took, as the lanes do (an unnumbered line after it leaves it)."""
    from nczones.gcode.fanuc import boxrun

    runners = []
    real = boxrun.read_box_run

    def read(runner, text, pos, lineno):
        runners.append(runner)
        return real(runner, text, pos, lineno)

    monkeypatch.setattr(boxrun, "read_box_run", read)
    body = "".join(f"N{10 * k} G01 X{k % 7}. Y{k % 5}.\n" for k in range(1, 13))
    result, _tested, taken = probe_route(HEAD + body + tail + "M30\n", _wall(150), "t.nc")
    assert result.verdict.label == "safe" and taken >= 10 and runners
    assert runners[-1].state.last.get("N") == 120


@pytest.mark.parametrize("runs", [True, False])
def test_a_box_run_keeps_the_last_n(runs):
    """``verify`` of a numbered run and a move by #4114, with the reader on or off (a ``#`` in the text: the lanes
    read it either way): the move leaves the box (machine X 100 + 120.5 past 150); with a later ``N2 M08`` (the
    general path's) it stays in it."""
    body = "".join(f"N{10 * k} G01 X{k % 7}. Y{k % 5}.\n" for k in range(1, 13))
    text = HEAD + body + TAIL
    result, _tested, _taken = probe_route(text, _wall(150), "t.nc", runs=runs)
    assert result.verdict.label == "unsafe", result.reasons
    assert verify_text(HEAD + body + "N2 M08\n" + TAIL, _wall(150), file="t.nc").verdict.label == "safe"


@pytest.mark.parametrize("fast", [True, False])
@pytest.mark.parametrize("tail", ["", "G01 X3. Y1.\n"])
def test_a_vectorized_run_keeps_the_last_n(fast, tail):
    """A numbered run long enough for the vectorized fast path (``fast``; its runs are the main text's plain
    lines between macro statements) and the full path give the same read: the last N written."""
    from nczones.gcode import interpret_text

    body = "".join(f"N{k} G01 X{k % 7}. Y{k % 5}.\n" for k in range(1, 1201))
    run = interpret_text(HEAD + "#1 = 0\n" + body + tail + TAIL, mill(), file="t.nc", fast=fast)
    assert list(run.segments())[-1].end[0] == Fraction(1200) + Fraction(1, 2) + 100


@pytest.mark.parametrize("fast", [True, False])
def test_a_vectorized_run_keeps_the_last_m(fast):
    """``#4113``, the last M code, after a run the vectorized fast path takes with an M word in it (it takes M3-M9)
    and the full path: M08 in the run, not the M09 before it."""
    from nczones.gcode import interpret_text

    body = "".join(f"G01 X{k % 7}. Y{k % 5}.{' M08' if k == 1100 else ''}\n" for k in range(1, 1201))
    text = HEAD + "M09\n#1 = 0\n" + body + TAIL.replace("#4114", "#4113")
    run = interpret_text(text, mill(), file="t.nc", fast=fast)
    assert list(run.segments())[-1].end[0] == Fraction(8) + Fraction(1, 2) + 100


#: the system variables the differential below reads (modal G groups, last D F H M N T, the G54.1 P number,
#: block end, machine and current positions)
_READS = [4001, 4002, 4003, 4005, 4006, 4007, 4008, 4009, 4010, 4012, 4014, 4015, 4016, 4017, 4107, 4109, 4111,
          4113, 4114, 4120, 4130, 5001, 5002, 5003, 5021, 5022, 5023, 5041, 5042, 5043]


def _random_blocks(r) -> str:
    """Plain blocks of every kind the lanes take or hand on (numbered or not, M, F, T, D, whole-circle arcs, G91,
    G43...); a block of axis words alone after an arc is written G01 (else it is an arc without a centre)."""
    lines, arc = [], False
    for _ in range(r.randint(1, 30)):
        w = [f"N{r.randint(1, 9999)}"] if r.random() < 0.3 else []
        kind = r.choice(["G00", "G01", "", "G02", "M", "F", "G91", "G90", "G18", "G17", "G43", "G49", "T", "D",
                         "G61", "G64"])
        if kind in ("G00", "G01", ""):
            w += [kind or ("G01" if arc else "")]
            w += [f"{a}{r.randint(-300, 300) / 10:.1f}" for a in r.sample("XYZ", r.randint(1, 3))]
            w += [f"F{r.randint(50, 900)}."] if r.random() < 0.3 else []
            w += [f"M0{r.choice([3, 5, 8, 9])}"] if r.random() < 0.2 else []
            arc = False
        elif kind == "G02":
            w += ["G17", r.choice(["G02", "G03"]), f"I{r.randint(1, 50)}."]  # a whole circle from where it is
            arc = True
        else:
            w.append({"M": f"M0{r.choice([3, 5, 8, 9])}", "F": f"F{r.randint(50, 900)}.", "G43": "G43 H1",
                      "G49": "G49", "T": f"T{r.randint(1, 9)}", "D": f"D{r.randint(1, 9)}"}.get(kind, kind))
        lines.append(" ".join(x for x in w if x))
        if r.random() < 0.1:
            lines.append("#1 = #1 + 1")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("seed", range(12))
def test_the_lanes_leave_what_the_general_path_leaves(monkeypatch, seed):
    """Differential: random blocks, then every variable of :data:`_READS` read into a move, with the lanes (and
    the vectorized path) and with the general path alone (no lane: ``Interpreter.run`` executes every block;
    its plain blocks through ``_plain``, which keeps the N as ``_record_block`` does): the same moves."""
    import random

    from nczones.gcode import interpret_text
    from nczones.gcode.interpreter import Interpreter

    def moves(text: str, lanes: bool) -> tuple | str:
        with monkeypatch.context() as m:
            if not lanes:
                m.setattr(Interpreter, "lane_for_blocks", lambda self: None)
            try:
                run = interpret_text(text, mill(), file="t.nc", fast=lanes)
                return tuple(s.end for s in run.segments())[-len(_READS):], run.status, run.unsupported
            except GcodeError as e:  # (the same error either way)
                return str(e)

    r = random.Random(seed)
    for _ in range(4):
        text = (HEAD + "#1 = 0\n" + _random_blocks(r) + "G90 G17 G49\n"
                + "".join(f"#7 = #{v}\nG01 X[#7 + 0.5] Y{k}. F100.\n" for k, v in enumerate(_READS)) + "M30\n")
        assert moves(text, True) == moves(text, False), text


#: (a program's middle, what the move by #4114 must be: a number, or None for ``unknown``).  A line of its N alone
#: (``N25``) is no block for nczones' reader, and no manual sentence at hand says whether the control's #4114 then
#: holds 25 or the N before it: where the two readings differ the read is ``unknown`` (VF203's system-variable
#: reason), where they agree it is modelled.
ALONE = {
    "an N alone after a numbered block": ("N10 G01 X1. Y1.\nN25\n", None),
    "an N alone with a comment": ("N10 G01 X1. Y1.\nN25 (NEXT)\n", None),
    "an N alone, the first N": ("G01 X1. Y1.\nN25\n", None),
    "an N alone, then a numbered block": ("N10 G01 X1. Y1.\nN25\nN30 G01 X2. Y1.\n", 30),
    "an N alone, then a block of the N before": ("N10 G01 X1. Y1.\nN25\nN10 G01 X2. Y1.\n", 10),
    "an N alone with the same number": ("N25 G01 X1. Y1.\nN25\n", 25),
    "an N alone in a loop": ("#2 = 0\nWHILE [#2 LT 3] DO1\nN30 G01 X2. Y1.\nN35\n#2 = #2 + 1\nEND1\n", None),
    # in a canned cycle's mode the reader hands the line on as a block without words (FanucInterpreter's
    # _record_block keeps its N apart)
    "an N alone in a canned cycle's mode": ("G00 Z1.\nG98 G81 X0. Y0. Z-3. R2.\nX1.\nN35\nG80\n", None),
    "a macro statement's label": ("N10 G01 X1. Y1.\nN25 #1 = 2\n", None),
    "a label, then a numbered block": ("N10 G01 X1. Y1.\nN25 #1 = 2\nN30 G01 X2. Y1.\n", 30),
    # the third pass runs N100 and N300 as kept closures (FanucRunner.make_op) after a block (N250) the passes
    # before did not run: the closures must record their N too
    "labels run as closures": ("#2 = 0\nN100 #2 = #2 + 1\nIF [#2 EQ 3] GOTO250\nN200 G01 X1. Y1.\nGOTO300\n"
                               "N250 G01 X2. Y1.\nN300 #3 = 1\nIF [#2 LT 3] GOTO100\n", None),
}


def alone_read(text: str, fast: bool, lanes: bool = True) -> Fraction | None:
    """The N the move by ``#4114`` reads (None: the read is unknown); ``lanes=False``: no block lanes."""
    from nczones.gcode import interpret_text
    from nczones.gcode.interpreter import Interpreter

    with pytest.MonkeyPatch.context() as mp:
        if not lanes:
            mp.setattr(Interpreter, "lane_for_blocks", lambda self: None)
        run = interpret_text(text, mill(), file="t.nc", fast=fast)
        ends = [s.end for s in run.segments()]
    if run.unsupported:
        assert run.unsupported[0].code == "#4114" and "not settled" in run.unsupported[0].reason, run.unsupported
        return None
    return ends[-1][0] - 100 - Fraction(1, 2)


@pytest.mark.parametrize("fast", [True, False])
@pytest.mark.parametrize("name", sorted(ALONE))
def test_a_line_of_its_n_alone_makes_the_read_unknown_where_it_matters(name, fast):
    middle, n = ALONE[name]
    assert alone_read(HEAD + middle + TAIL, fast) == n, name


@pytest.mark.parametrize("fast", [True, False])
@pytest.mark.parametrize("alone", [True, False])
def test_a_vectorized_run_with_an_n_alone(fast, alone):
    """A numbered run long enough for the vectorized fast path whose last numbered line is an N alone: the read is
    unknown on every path; with the N alone earlier in the run it is the last block's N."""
    body = "".join(f"N{k} G01 X{k % 7}. Y{k % 5}.\n" for k in range(1, 1201))
    text = HEAD + "#1 = 0\n" + (body + "N1500\n" if alone else "N1500\n" + body) + TAIL
    assert alone_read(text, fast) == (None if alone else 1200)


def test_a_block_without_words_keeps_its_n_apart():
    """A line of its N alone that the reader hands on as a block (no words) leaves ``#4114`` as the two readings
    allow, not as a block's N; a block's N (``keep_number``) then settles it."""
    from nczones.errors import SourceSpan
    from nczones.gcode.blocks import Block
    from nczones.gcode.fanuc.expr import SystemVariableUnknown
    from nczones.gcode.fanuc.interpreter import FanucInterpreter
    from nczones.gcode.fanuc.system import read

    it = FanucInterpreter(mill())
    it.execute(Block(words=(), span=SourceSpan("t.nc", 1, 1, 4, "N35"), index=0, number=Fraction(35)))
    with pytest.raises(SystemVariableUnknown, match="not settled"):
        read(it, 4114)
    it.keep_number(Fraction(40))
    assert read(it, 4114)[0] == 40
