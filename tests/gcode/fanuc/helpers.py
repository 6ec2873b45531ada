"""A Fanuc mill for the tests and small runners around the dialect's language layer."""

from __future__ import annotations

from fractions import Fraction

from nczones.gcode import interpret_text
from nczones.gcode.fanuc.expr import FanucVariables
from nczones.gcode.fanuc.program import iter_blocks
from nczones.machine import parse_machine

MILL = """
[machine]
name = "fanuc test mill"
dialect = "fanuc"
axes = ["X", "Y", "Z"]
[machine.rapid]
X = "10000"
Y = "10000"
Z = "10000"
[machine.reference]
X = "0"
Y = "0"
Z = "0"
[machine.reference_2]
X = "-100"
Y = "-50"
Z = "-10"
[offsets]
G54 = { X = "100", Y = "50", Z = "-200" }
G55 = { X = "300", Y = "50", Z = "-200" }
EXT = { Z = "1" }
"G54.1P3" = { X = "500", Y = "20", Z = "-210" }
[tool_lengths]
H1 = "100"
H2 = "150.5"
[fanuc]
g73_retract = "0.5"
g83_clearance = "1"
boring_shift = "+X"
{fanuc_extra}
[variables]
"#500" = "2.5"
{tables}
"""


def mill(fanuc_extra: str = "", tables: str = ""):
    """The test mill: G54 = (100, 50, -200), EXT Z = 1, H1 = 100, H2 = 150.5, G30 P2 at (-100, -50, -10)."""
    return parse_machine(MILL.replace("{fanuc_extra}", fanuc_extra).replace("{tables}", tables), "mill.toml")


def blocks(text: str, **kw):
    """``(blocks as [(letter, value), ...] lists, variables, runner)`` of the language layer alone."""
    variables = kw.pop("variables", None) or FanucVariables(kw.pop("initial", None))
    out: list = []
    got = [[(w.letter, w.value) for w in b.words] for b in iter_blocks(text, "t.nc", variables=variables,
                                                                       runner_out=out, **kw)]
    return got, variables, out[0]


def var(variables: FanucVariables, n: int):
    """The exact value of a variable (None if vacant)."""
    from nczones.gcode.fanuc.expr import VACANT

    v = variables.read(n)
    if v is VACANT:
        return None
    return v[1] if v[1] is not None else Fraction(v[0])


def ends(text: str, machine=None, **kw) -> list[tuple]:
    """The end points of every segment (machine coordinates) of a program on the test mill."""
    run = interpret_text(text, machine or mill(), file="t.nc", **kw)
    out = [tuple(s.end) for s in run.segments()]
    assert run.status == "complete", run.unsupported
    return out


def F(x) -> Fraction:
    return Fraction(str(x))


def probe_route(text: str, machine, file: str, *, runs: bool = True, route: bool = True) -> tuple:
    """``verify`` on ``text`` with the box route watched.

    Returns ``(result, tested, taken)``: the result, or the GcodeError verify raised; the boxes the route
    tested, each ``(lo, hi, tool length)`` with ``lo``/``hi`` the ``(axis, value)`` pairs sorted by axis name;
    the lines the box run reader took.  ``runs``: the reader on (``boxrun.BOX_RUNS``); ``route``: the route
    on (``fanucboxes.ROUTE``).
    """
    import pytest

    from nczones.errors import GcodeError
    from nczones.gcode.fanuc import boxrun
    from nczones.prover import fanucboxes, verify_text

    tested: list = []
    taken = [0]
    real_fits, real_read = fanucboxes.box_fits, boxrun.read_box_run

    def fits(allowed, lo, hi, margin, tl):
        tested.append((tuple(sorted(lo.items())), tuple(sorted(hi.items())), tl))
        return real_fits(allowed, lo, hi, margin, tl)

    def read(runner, text, pos, lineno):
        got = real_read(runner, text, pos, lineno)
        if got is not None:
            taken[0] += got[1] - lineno
        return got

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(boxrun, "BOX_RUNS", runs)
        mp.setattr(boxrun, "read_box_run", read)
        mp.setattr(fanucboxes, "ROUTE", route)
        mp.setattr(fanucboxes, "box_fits", fits)
        try:
            result = verify_text(text, machine, file=file)
        except GcodeError as e:
            result = e
    return result, tested, taken[0]


#: The box route tests' zone on :func:`mill`: machine X -10..150, Y -10..90, Z -201..0 (at G54 and EXT Z = 1:
#: program X -110..50, Y -60..40, Z -2..199).
BOX_ZONE = ('\n[[zones]]\nname = "box"\nkind = "box"\nmin = { X = "-10", Y = "-10", Z = "-201" }\n'
            'max = { X = "150", Y = "90", Z = "0" }\n')


def final_state(text: str, machine, *, runs: bool) -> tuple:
    """The interpreter's and the runner's state once the box route (``fanucboxes.prove_boxes``) read ``text``,
    the box run reader on or off (``runs``: ``boxrun.BOX_RUNS``); ``()`` when the route did not run.

    The state: the machine and program points, motion, feed, blocks, motion count and counts by kind, block index
    and span, the cycle's initial level, the pending rotation start, the modes noted as assumed, whether a
    transform was just cancelled, and the runner's block index.
    """
    import pytest

    from nczones.gcode.fanuc import boxrun
    from nczones.prover import fanucboxes, verify_text

    got: list = []
    real = fanucboxes.prove_boxes

    def prove(run, *a, **k):
        result = real(run, *a, **k)
        it = run.interpreter
        runner = next(iter(run.runners), None)
        got.append((tuple(it.pos), tuple(it.prog or ()), it.motion, it.feed, it.blocks, it.segment_count,
                    sorted(it.kind_counts.items()), it.block_index, it.span, it.cycle_il, it.prerotation_xy_next,
                    dict(it.assumed), it.transform_just_cancelled, getattr(runner, "index", None)))
        return result

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(boxrun, "BOX_RUNS", runs)
        mp.setattr(fanucboxes, "prove_boxes", prove)
        verify_text(text, machine, file="t.nc")
    return got[0] if got else ()


def assert_state_handed_back(text: str, machine) -> None:
    """The box run reader leaves :func:`final_state` as the path without it does, or raises the GcodeError (code
    and message) that path raises (a drawn program the interpreter refuses)."""
    import pytest

    from nczones.errors import GcodeError

    try:
        without = final_state(text, machine, runs=False)
    except GcodeError as exc:
        with pytest.raises(GcodeError) as read:
            final_state(text, machine, runs=True)
        assert (read.value.code, str(read.value)) == (exc.code, str(exc))
        return
    assert final_state(text, machine, runs=True) == without
