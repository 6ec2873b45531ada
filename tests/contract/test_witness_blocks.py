"""A ranged witness replays as its block's motion, not as its ``(file, line)`` (:mod:`nczones.pipeline.witnesses`).

The programs run a loop (LinuxCNC ``o100 while``, an ``o200 sub`` called in a loop, Fanuc ``WHILE``, a Fanuc
``G65`` macro called in a loop, Fanuc ``M98 P.. L..``) of 140 passes, two rapids a pass (more motions than a chunk holds, so the replay hands out
the first passes before it meets anything): the last pass's rapids reach the clamp when ``G54.Y`` is 0.5 or
more, and the pass before it runs an arc from machine zero that the control refuses once ``|G54.Y|`` is
past its tolerance (LinuxCNC GC301, Fanuc GC302).  At every value where the clamp is reached the control
stops at that arc: the witnesses name motions it never makes.  Matched by ``(file, line)`` they were kept
(the rapids' lines run on the first pass): a false ``unsafe`` whose witness does not replay.  Matched by
block, they are dropped and the verdict is ``unknown`` (VF232).

The relation (Hypothesis, both dialects, :func:`test_every_reported_witness_replays_at_its_values`): every
witness of a ranged ``unsafe``, its values written into the machine, verifies ``unsafe`` there with a
violation of its zone on its line, and its path point lies on the motion of its block there (an exact check
written here, not the pipeline's) with its point in that zone.
"""

from __future__ import annotations

import os
from collections import Counter
from fractions import Fraction
from unittest import mock

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from nczones.errors import InputError
from nczones.gcode import interpret_text
from nczones.motion import SegmentKind
from nczones.pipeline import witnesses
from nczones.prover import verify_text
from tests.contract.test_range_seams import Setup, machine_for

F = Fraction
_Z = (F(-80), F(-80), F(-30)), (F(80), F(80), F(260))
#: a clamp the rapids along work Y0 meet only when G54.Y is 0.5 or more (and they pass X 25)
_CLAMP = ("clamp", (F(25), F(1, 2), F(-30)), (F(40), F(5), F(260)), True, False)
RANGE = ["G54.Y=-1..1"]
N = 140  # passes: 2 rapids each, past the interpreter's chunk of 128 motions

#: the arc the control refuses away from G54.Y = 0 (from machine zero to a work position), by dialect
_ARC = {"linuxcnc": "G53 G0 X0 Y0\nG3 X0 Y10. I0 J5.", "fanuc": "G90 G53 G0 X0 Y0\nG2 X-10. Y0. R5."}
#: the same two blocks with an arc the control runs at every value (the same block count)
_RUNS = {"linuxcnc": "G53 G0 X0 Y0\nG0 X0. Y10.", "fanuc": "G90 G53 G0 X0 Y0\nG0 X0. Y10."}

PROGRAMS = {
    "linuxcnc while": ("linuxcnc", f"""G21 G90 G17 G54 F600.
#1 = 1
o100 while [#1 LE {N}]
o110 if [#1 EQ {N - 1}]
{{arc}}
o110 endif
#2 = 10
o120 if [#1 EQ {N}]
#2 = 30
o120 endif
G0 X#2 Y0
G0 X5. Y0
#1 = [#1 + 1]
o100 endwhile
M30
"""),
    "linuxcnc sub": ("linuxcnc", f"""o200 sub
G0 X#1 Y0
G0 X5. Y0
o200 endsub
G21 G90 G17 G54 F600.
#3 = 1
o300 while [#3 LT {N}]
o200 call [10]
#3 = [#3 + 1]
o300 endwhile
{{arc}}
G0 X5. Y0
o200 call [30]
M30
"""),
    "fanuc while": ("fanuc", f"""G21 G90 G17 G54 F600.
#1=1
WHILE[#1LE{N}]DO1
IF[#1NE{N - 1}]GOTO10
{{arc}}
N10 #2=10.
IF[#1NE{N}]GOTO20
#2=30.
N20 G0 X#2 Y0
G0 X5. Y0
#1=#1+1
END1
M30
"""),
    "fanuc g65": ("fanuc", f"""O1000
G21 G90 G17 G54 F600.
#1=1
WHILE[#1LT{N}]DO1
G65 P1002 X10.
#1=#1+1
END1
{{arc}}
G0 X5. Y0
G65 P1002 X30.
M30
O1002
G0 X#24 Y0
G0 X5. Y0
M99
"""),
    "fanuc m98": ("fanuc", f"""O1000
G21 G90 G17 G54 F600.
#100=0
M98 P1001 L{N}
M30
O1001
#100=#100+1
IF[#100NE{N - 1}]GOTO10
{{arc}}
N10 #2=10.
IF[#100NE{N}]GOTO20
#2=30.
N20 G0 X#2 Y0
G0 X5. Y0
M99
"""),
}


def _setup(dialect: str) -> Setup:
    return Setup(dialect, "G61", "linear", (("travel", *_Z, False, False), _CLAMP))


def _program(form: str, arc: dict[str, str] = _ARC) -> tuple[str, str]:
    dialect, text = PROGRAMS[form]
    return dialect, text.format(arc=arc[dialect])


def _rapid_lines(text: str) -> set[int]:
    """The lines of the two rapids the last pass (or call) violates on."""
    return {n for n, line in enumerate(text.splitlines(), start=1)
            if line.endswith(("X#2 Y0", "X#1 Y0", "X#24 Y0", "X5. Y0"))}


@pytest.mark.parametrize("form", sorted(PROGRAMS))
def test_a_later_pass_the_control_never_makes_is_not_a_witness(form):
    """The clamp is reached only on the last pass, and only where the control refuses the arc before it: no
    witness is reported, each is a VF232 reason on its rapid's line naming the refused arc.  The (file, line)
    rule kept them: the replay at their values makes the first passes through those lines (checked here)."""
    dialect, text = _program(form)
    machine = machine_for(_setup(dialect))
    got = verify_text(text, machine, params=RANGE)
    assert got.verdict.label == "unknown" and not got.violations, [(v.line, v.block) for v in got.violations]
    refused = [r for r in got.reasons if r.code == "VF232"]
    assert refused and {r.span.line for r in refused} <= _rapid_lines(text)
    assert all("refuses an earlier block" in r.message and ("GC301" in r.message or "GC302" in r.message)
               for r in refused), [r.message for r in refused]
    # at a value of the witnesses the control runs the rapids' lines (first passes), then refuses the arc
    at = machine_for(_setup(dialect), {"G54.Y": F(3, 4)})
    run, lines = interpret_text(text, at, dialect=dialect), set()
    with pytest.raises(InputError):
        lines.update(s.span.line for s in run.segments() if s.span is not None)
    assert {r.span.line for r in refused} <= lines


@pytest.mark.parametrize("form", sorted(PROGRAMS))
def test_a_later_pass_the_control_makes_stays_a_witness(form):
    """The same loop with a move the control always runs in place of the arc: the last pass's witnesses
    replay (their blocks run at their values), so the verdict stays ``unsafe``, each on its block (the last
    pass's, not the first's)."""
    dialect, text = _program(form, _RUNS)
    machine = machine_for(_setup(dialect))
    got = verify_text(text, machine, params=RANGE)
    assert got.verdict.label == "unsafe" and not [r for r in got.reasons if r.code in ("VF231", "VF232")]
    assert {v.line for v in got.violations} <= _rapid_lines(text)
    first = {s.span.line: s.block for s in reversed(list(interpret_text(text, machine, dialect=dialect).segments()))
             if s.span is not None}
    assert all(v.block > first[v.line] for v in got.violations)
    for v in got.violations:
        _assert_replays(text, _setup(dialect), v)


@pytest.mark.parametrize("form", ["linuxcnc while", "fanuc m98"])
def test_nczones_replay_confirms_every_later_pass_witness(tmp_path, form, capsys):
    """End to end: ``nczones verify --param`` of the loop whose last pass always runs reports its witnesses on
    their blocks (the last pass's), and ``nczones replay`` of that JSON report confirms every one."""
    import json

    from nczones.cli import main
    from nczones.replay import replay_file
    from tests.contract.test_witness_budget import _machine_file

    dialect, text = _program(form, _RUNS)
    prog = tmp_path / ("p.ngc" if dialect == "linuxcnc" else "p.nc")
    prog.write_text(text)
    report = tmp_path / "report.json"
    main(["verify", str(prog), "--machine", str(_machine_file(tmp_path, dialect)), *(f"--param={p}" for p in RANGE),
          "--format", "json", "--output", str(report)])
    capsys.readouterr()
    doc = json.loads(report.read_text())
    assert doc["verdict"] == "unsafe" and all(v["block"] > N for v in doc["violations"])
    checks = replay_file(str(report))
    assert checks and all(c.confirmed and c.exact for c in checks), [c.render() for c in checks]


def _by_line(interpret, at_values, params, at_line, shift, margin):
    """The (file, line) rule of witness37 behind the new interface: a witness whose line the replay moves on
    before it stops is kept (the mutation :func:`test_the_block_rule_has_teeth` puts back)."""
    run, todo = interpret(at_values), set(at_line)
    try:
        for seg in run.segments():
            if seg.span is not None:
                todo.discard((seg.span.file, seg.span.line))
    except InputError:
        pass
    return {id(v): ("refused", "stops before its line") for k in todo for v in at_line[k]}


@pytest.mark.parametrize("form", ["linuxcnc while", "fanuc m98"])
def test_the_block_rule_has_teeth(form):
    """Matched by (file, line) again, the later passes' witnesses are reported (``unsafe``), and they do not
    replay: at their values the control refuses the arc (the relation below fails on them)."""
    dialect, text = _program(form)
    with mock.patch.object(witnesses, "_unreached", _by_line):
        got = verify_text(text, machine_for(_setup(dialect)), params=RANGE)
    assert got.verdict.label == "unsafe" and got.violations
    with pytest.raises(AssertionError, match="refused at its values"):
        _assert_replays(text, _setup(dialect), got.violations[0])


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_a_block_refused_after_the_witness_drops_it(dialect):
    """The rapids of lines 2 and 3 meet the clamp from ``G54.Y = 0.5``; the arc of line 4 is refused there.  The
    control stops at the error and need not make the motions it has read ahead (LinuxCNC drops the commands
    it queued past the machine), and ``nczones verify`` at those values is that error: the witness is not
    shown to replay, so it is dropped (VF232, "a later block"), though its motion was made before the arc
    (the interpreter's motions not yet handed out in a chunk count as made)."""
    text = f"G21 G90 G17 G54 F600.\nG0 X30. Y0.\n{_ARC[dialect]}\nM30\n"
    machine = machine_for(_setup(dialect))
    got = verify_text(text, machine, params=RANGE)
    assert got.verdict.label == "unknown" and not got.violations
    # line 2's rapid and line 3's way back to machine zero, both made before the arc
    refused = [r for r in got.reasons if r.code == "VF232"]
    assert sorted(r.span.line for r in refused) == [2, 3]
    assert all("refuses a later block, line 4" in r.message for r in refused), [r.message for r in refused]
    with pytest.raises(InputError):
        verify_text(text, machine_for(_setup(dialect), {"G54.Y": F(3, 4)}))


def test_a_witness_the_prover_moved_does_not_replay():
    """A prover that names values off by one (the witness's point found at other values) is caught here: the
    block runs at the named values without the point, so the witness is dropped (VF231), never reported."""
    from nczones.prover.core import Prover

    written = Prover.written_params
    text = "G21 G90 G17 G54 F600.\nG1 X10. Y0. Z100.\nM30\n"
    setup = Setup("linuxcnc", "G61", "linear", (("travel", *_Z, False, False), (
        "clamp", (F(11), F(-5), F(0)), (F(20), F(5), F(200)), True, False)))
    assert verify_text(text, machine_for(setup), params=["G54.X=0..2"]).verdict.label == "unsafe"
    with mock.patch.object(Prover, "written_params", lambda self, values: tuple(
            (n, v - 1) for n, v in written(self, values))):
        got = verify_text(text, machine_for(setup), params=["G54.X=0..2"])
    assert got.verdict.label == "unknown" and not got.violations
    (why,) = [r for r in got.reasons if r.code == "VF231"]
    assert "is not on the line of block" in why.message and "does not replay" in why.message, why.message


# -- the relation: every reported witness replays at its values ---------------------------------------------------

def _on(p: tuple[Fraction, ...], seg) -> bool:
    """``p`` on the straight move or circular arc ``seg`` (exact; an arc: on its circle in its plane)."""
    a, b = seg.start, seg.end
    if seg.kind is SegmentKind.ARC and seg.centre is not None:
        i, j, k = seg.plane_indices()
        c = seg.centre
        r2 = (a[i] - c[0]) ** 2 + (a[j] - c[1]) ** 2
        return (p[i] - c[0]) ** 2 + (p[j] - c[1]) ** 2 == r2 and min(a[k], b[k]) <= p[k] <= max(a[k], b[k])
    d = [y - x for x, y in zip(a, b)]
    n = next((n for n in range(len(d)) if d[n]), None)
    if n is None:
        return tuple(p) == tuple(a)
    t = (p[n] - a[n]) / d[n]
    return 0 <= t <= 1 and all(p[m] == a[m] + t * d[m] for m in range(len(d)))


def _assert_replays(text: str, setup: Setup, v) -> None:
    """Witness ``v`` at its values: ``unsafe`` with a violation of its zone on its line, its path point on the
    motion of its block and its point in its zone there."""
    values = dict(v.params)
    machine = machine_for(setup, values)
    try:
        at = verify_text(text, machine, max_violations=100)
    except InputError as exc:
        raise AssertionError(f"witness of line {v.line} at {values} refused at its values: {exc}") from None
    assert at.verdict.label == "unsafe", (values, at.verdict.label, text)
    assert (v.line, v.zone) in {(w.line, w.zone) for w in at.violations} or at.truncated, (v.line, v.zone, values)
    mine = [s for s in interpret_text(text, machine, dialect=setup.dialect).segments() if s.block == v.block]
    path = tuple(x for _, x in v.path_point)
    hits = [s for s in mine if _on(path, s)]
    assert hits, f"witness of line {v.line} (block {v.block}) at {values}: path point on none of {mine}"
    named = {z.name for s in hits for z in machine.allowed.violated_zones(dict(v.point), s.tool_length)}
    assert v.zone in named, (v.zone, named, values)


def _loop(dialect: str, k: int, n: int, gate: int, x: str, arc: str) -> str:
    """Loop ``k`` (counter ``#1k``) of ``n`` passes: the arc on pass ``gate`` (none when 0), then a rapid to
    ``X`` (an expression of the counter ``#``) and back to X5."""
    c = f"#{k + 10}"
    x = x.replace("#", c)
    if dialect == "linuxcnc":
        return (f"{c} = 1\no{k + 1}00 while [{c} LE {n}]\no{k + 1}10 if [{c} EQ {gate}]\n{arc}\no{k + 1}10 endif\n"
                f"G0 X{x} Y0\nG0 X5. Y0\n{c} = [{c} + 1]\no{k + 1}00 endwhile")
    return (f"{c}=1\nWHILE[{c}LE{n}]DO1\nIF[{c}NE{gate}]GOTO{k + 1}0\n{arc}\nN{k + 1}0 G0 X{x} Y0\nG0 X5. Y0\n"
            f"{c}={c}+1\nEND1")


def _short_loop(dialect: str, k: int, draw) -> str:
    """A loop of 1 to 4 passes whose rapid steps 10 mm a pass (the clamp from the third), an arc on one pass."""
    gate = draw(st.integers(0, 4))
    return _loop(dialect, k, draw(st.integers(1, 4)), gate, "[# * 10]", _ARC[dialect] if gate else "")


def _long_loop(dialect: str, k: int, draw) -> str:
    """A loop of 60 to 70 passes (more motions than a chunk) to X10, its last pass to X30 (the clamp), the arc
    (or not) on the pass before: a witness on a later pass, the line's first passes handed out before the
    replay meets the arc (what the (file, line) rule took for the witness's)."""
    n = draw(st.integers(60, 70))
    x = f"[10 + 20 * FIX[# / {n}]]"  # 30 on the last pass only
    return _loop(dialect, k, n, n - 1, x, _ARC[dialect] if draw(st.booleans()) else "G0 X0. Y10.")


#: the pieces a program is made of: (dialect, k, draw) -> lines
_PIECES = {
    "rapid": lambda dialect, k, draw: f"G0 X{draw(st.sampled_from([5, 20, 30, 45]))}. "
                                      f"Y{draw(st.sampled_from(['0', '0.3', '1.']))}",
    "arc": lambda dialect, k, draw: _ARC[dialect],
    "loop": _short_loop,
    "long loop": _long_loop,
    "call": lambda dialect, k, draw: (f"o900 call [{draw(st.sampled_from([5, 20, 30, 45]))}]" if dialect == "linuxcnc"
                                      else f"M98 P9000 L{draw(st.integers(1, 4))}"),
}


@st.composite
def _programs(draw, dialect: str) -> str:
    """One to four pieces of :data:`_PIECES`: rapids, counted loops (short, or long with the clamp on the last
    pass), a subprogram called or repeated (its rapid steps 10 mm a pass on Fanuc), the arc the control
    refuses away from ``G54.Y = 0``."""
    kinds = draw(st.lists(st.sampled_from(["rapid", "arc", "loop", "loop", "long loop", "call"]), min_size=1,
                          max_size=4))
    return _wrapped(dialect, "\n".join(_PIECES[kind](dialect, k, draw) for k, kind in enumerate(kinds)))


def _wrapped(dialect: str, body: str) -> str:
    """The program of ``body``: its header, its end, and the subprogram its calls name."""
    if dialect == "linuxcnc":
        return f"o900 sub\nG0 X#1 Y0\nG0 X5. Y0\no900 endsub\nG21 G90 G17 G54 F600.\n{body}\nM30\n"
    return f"O1000\nG21 G90 G17 G54 F600.\n{body}\nM30\nO9000\nG91 G0 X10.\nG90 G0 X5. Y0\nM99\n"


#: an example every run tries: a long loop whose last pass meets the clamp past the arc refused before it
_LATE = {d: _wrapped(d, _loop(d, 0, 66, 65, "[10 + 20 * FIX[# / 66]]", _ARC[d])) for d in _ARC}


EXAMPLES = {"ci": 4, "long": int(os.environ.get("NCZONES_WITNESS_BLOCKS", "150"))}
#: verdicts, reason codes and replayed witnesses of this session's relation runs (printed by the long tests)
OUTCOMES: Counter = Counter()


def _relation(dialect: str, n: int, derandomize: bool) -> None:
    @settings(max_examples=n, deadline=None, derandomize=derandomize, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(_programs(dialect), st.sampled_from([["G54.Y=-1..1"], ["G54.Y=-1..1", "G54.X=-3..3"], ["G54.Y=0..1"]]))
    @example(_LATE[dialect], ["G54.Y=-1..1"])
    def run(text, params):
        setup = _setup(dialect)
        try:
            got = verify_text(text, machine_for(setup), params=params, max_violations=4)
        except InputError:
            OUTCOMES["refused at the nominal values"] += 1
            return
        OUTCOMES[got.verdict.label] += 1
        OUTCOMES.update(r.code for r in got.reasons if r.code in ("VF231", "VF232"))
        for v in got.violations:
            _assert_replays(text, setup, v)
            OUTCOMES["witness replayed"] += 1

    run()


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_every_reported_witness_replays_at_its_values(dialect):
    _relation(dialect, EXAMPLES["ci"], True)


@pytest.mark.long
@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_every_reported_witness_replays_at_its_values_long(dialect):
    OUTCOMES.clear()
    _relation(dialect, EXAMPLES["long"], False)
    print(f"witness blocks ({dialect}): {sorted(OUTCOMES.items())}")
