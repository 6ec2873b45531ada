"""Soundness hunt where features meet (hunt38): Fanuc offsets written by macro × G20/G21 × G10 G91 increments ×
G43/G44 H × M98/G65 frames.

Drawn programs write work offsets (EXT, G54, G55: ``#5201``.., ``#5221``.., ``#5241``..; G54.1 P3: ``#7041``..) and
tool lengths (geometry ``#11001``/``#2201``.., wear ``#10001``/``#2001``..), absolute or added to (the macro
``#v = #v + d`` beside ``G91 G10``), written in the main program, in an ``M98`` subprogram or in a ``G65``
macro from its argument ``X`` (``#24``), in inches or millimetres, between moves in G54/G55/G54.1 P3 with
G43/G44 H1/H2 and G49, G90 and G91.  Every write has a ``G10`` twin (L2, L20, L10, L11).  Relations:

1. **a macro write and its G10 twin give the same motion** (nczones): kind and exact end of every motion, and
   the same unsupported codes; the macro form may alone be ``unknown`` (GC399) where a written value has more
   digits than the increment and its double's readings round apart (tests/gcode/fanuc/test_offset_writes.py);
2. **the reference reader gives the same motion** for the G10 form (tests/oracles/fanuc_ref.py models G10
   but not the offset variables): ``same``, or ``skip`` where it does not model a construct, never ``differ``;
   only where every written value is on the increment's grid (the reference takes a literal as written,
   nczones rounds it to the increment as the control does, specs/fanuc.md "length words").

The machine is tests/gcode/fanuc/helpers.py's mill, as the differential tests use it.  CI: ``EXAMPLES["ci"]``
examples (derandomized); ``-m long``: ``NCZONES_OFFSET_SEAMS`` (default 1500), randomized, counts printed
(specs/contract.md, "Where features meet: hunt38").
"""

from __future__ import annotations

import os
from collections import Counter
from dataclasses import dataclass, field
from decimal import Decimal
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError

from .ref_differential import compare, first_difference, nczones_motion

EXAMPLES = {"ci": 40, "long": int(os.environ.get("NCZONES_OFFSET_SEAMS", "1500"))}
OUTCOMES: Counter = Counter()
AXES = "XYZ"


@dataclass
class Twins:
    """The two programs being built: the macro form and the G10 form; subprograms after the main one."""

    inch: bool
    macro: list = field(default_factory=list)
    g10: list = field(default_factory=list)
    subs_macro: list = field(default_factory=list)
    subs_g10: list = field(default_factory=list)
    off_grid: bool = False  # a written value with more digits than the increment (GC399 possible)
    written: set = field(default_factory=set)  # the G10 targets written absolutely so far (in these units)

    def both(self, line: str) -> None:
        self.macro.append(line)
        self.g10.append(line)

    def text(self, form: str) -> str:
        main, subs = (self.macro, self.subs_macro) if form == "macro" else (self.g10, self.subs_g10)
        head = ["%", "O0001", "G20" if self.inch else "G21", "G90 G17 G40 G49 G80 G94 G54 F500."]
        return "\n".join(head + main + ["M30"] + subs + ["%"]) + "\n"


def _value(draw, inch: bool, on_grid: bool, scale: int = 40) -> str:
    """A decimal value in program units: on the increment's grid, or with up to two digits more."""
    places = (4 if inch else 3) + (0 if on_grid else draw(st.integers(1, 2)))
    span = scale * 10 ** places // (25 if inch else 1)
    n = draw(st.integers(-span, span))
    return format(Decimal(n).scaleb(-places), "f")


def _target(draw) -> tuple[str, str, str]:
    """(variable number, the G10 words before the value, what it is): an offset axis or a tool length."""
    kind = draw(st.sampled_from(["EXT", "G54", "G55", "G54.1", "geometry", "wear"]))
    if kind in ("geometry", "wear"):
        h = draw(st.sampled_from([1, 2]))
        first, second, L = (11000, 2200, 10) if kind == "geometry" else (10000, 2000, 11)
        var = draw(st.sampled_from([first, second])) + h
        return str(var), f"G10 L{L} P{h} R", f"{kind} H{h}"
    a = draw(st.sampled_from(range(3)))
    if kind == "G54.1":
        return str(7041 + a), f"G10 L20 P3 {AXES[a]}", f"G54.1 P3 {AXES[a]}"
    p = {"EXT": 0, "G54": 1, "G55": 2}[kind]
    return str(5201 + 20 * p + a), f"G10 L2 P{p} {AXES[a]}", f"{kind} {AXES[a]}"


def _write(draw, tw: Twins, n_subs: list) -> None:
    """One offset write and its twin, in the main program, an M98 subprogram or a G65 macro."""
    var, g10, _what = _target(draw)
    # added to in inches only once written in inches: a value the machine file sets in millimetres is off the
    # inch grid, and the macro's read and write re-rounds it to the inch increment (up to 0.00127 mm) where
    # G91 G10 adds to it as stored (specs/contract.md, "Where features meet: hunt38")
    added = draw(st.booleans()) and (not tw.inch or g10 in tw.written)
    on_grid = added or draw(st.sampled_from([True, True, False]))
    v = _value(draw, tw.inch, on_grid, 5 if added else 40)
    tw.off_grid |= not on_grid
    if not added:
        tw.written.add(g10)
    frame = draw(st.sampled_from(["main", "main", "M98", "G65"]))
    # the argument X (#24): a length word, rounded to the value's own grid (A would round to 0.001 deg in G20)
    arg = "#24" if frame == "G65" else v
    macro = f"#{var} = #{var} + {arg}" if added else f"#{var} = {arg}"
    twin = f"{g10}{arg}"
    # G10 adds in G91 and sets in G90 (a move may have left either): the mode is written in both forms
    mode, after = (["G91"], ["G90"]) if added else (["G90"], [])
    if frame == "main":
        tw.macro += mode + [macro] + after
        tw.g10 += mode + [twin] + after
        return
    n_subs[0] += 1
    num = 9000 + n_subs[0]
    tw.subs_macro += [f"O{num}", *mode, macro, *after, "M99"]
    tw.subs_g10 += [f"O{num}", *mode, twin, *after, "M99"]
    tw.both(f"M98 P{num}" if frame == "M98" else f"G65 P{num} X{v}")


def _move(draw, tw: Twins) -> None:
    wcs = draw(st.sampled_from(["", "", "G54", "G55", "G54.1 P3"]))
    if wcs:
        tw.both(wcs)
    tl = draw(st.sampled_from(["", "", "G43 H1", "G43 H2", "G44 H1", "G49", "H2"]))
    inc = draw(st.sampled_from(["G90", "G90", "G91"]))
    kind = draw(st.sampled_from(["G00", "G01"]))
    scale = 10 if inc == "G91" else 60
    words = " ".join(f"{a}{_value(draw, tw.inch, True, scale)}" for a in AXES if draw(st.booleans())) or "Z0."
    tw.both(f"{inc} {kind} {tl} {words}".replace("  ", " ") + (" F500." if kind == "G01" else ""))


@st.composite
def twins(draw) -> Twins:
    tw = Twins(inch=draw(st.booleans()))
    n_subs = [0]
    for _ in range(draw(st.integers(2, 8))):
        if draw(st.booleans()):
            _write(draw, tw, n_subs)
        else:
            _move(draw, tw)
    _move(draw, tw)  # a motion after the last write
    return tw


def _motion(text: str):
    try:
        run, segs = nczones_motion(text, "calculator", False)
    except GcodeError as e:
        return ("error", e.diagnostics[0].code), ()
    return segs, tuple(u.code for u in run.unsupported)


def check(tw: Twins) -> None:
    by_macro, by_g10 = tw.text("macro"), tw.text("g10")
    (m_segs, m_unsupported), (g_segs, g_unsupported) = _motion(by_macro), _motion(by_g10)
    if m_unsupported != g_unsupported and tw.off_grid and set(m_unsupported) - set(g_unsupported) == {"GC399"}:
        OUTCOMES[("macro = G10", "macro unknown GC399 (a value off the increment)")] += 1
    else:
        OUTCOMES[("macro = G10", "compared" + (" (unknown)" if g_unsupported else ""))] += 1
        assert (m_segs, m_unsupported) == (g_segs, g_unsupported), f"macro form:\n{by_macro}\nG10 form:\n{by_g10}"
    if tw.off_grid:  # the reference takes a literal as written, nczones rounds it (specs/fanuc.md): not compared
        OUTCOMES[("G10 = reference", "not compared: a literal off the increment")] += 1
        return
    ref = compare(by_g10)
    OUTCOMES[("G10 = reference", ref.status)] += 1
    assert ref.status != "differ", f"{first_difference(ref)}\n{by_g10}"


def _run(n: int, derandomize: bool) -> None:
    @settings(max_examples=n, deadline=None, derandomize=derandomize, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(twins())
    def run(tw):
        check(tw)

    run()


def test_offset_seams():
    _run(EXAMPLES["ci"], True)


@pytest.mark.long
def test_offset_seams_long():
    OUTCOMES.clear()
    _run(EXAMPLES["long"], False)
    print("\noffset seams:", dict(sorted(OUTCOMES.items())))


def test_the_relations_have_teeth():
    """A twin that writes another value, and a G10 form the reference would read otherwise, are caught."""
    tw = Twins(inch=False, macro=["#5221 = 1.5", "G90 G00 X0. Y0."], g10=["G10 L2 P1 X1.6", "G90 G00 X0. Y0."])
    with pytest.raises(AssertionError):
        check(tw)
    ok = Twins(inch=True, macro=["#5221 = 4.", "G91", "#5221 = #5221 + 0.5", "G90", "G90 G00 X0. Y0."],
               g10=["G10 L2 P1 X4.", "G91", "G10 L2 P1 X0.5", "G90", "G90 G00 X0. Y0."])
    check(ok)


def test_a_millimetre_offset_read_and_written_in_inches_is_re_rounded():
    """The one twin the hunt leaves out, pinned: in G20, ``#5203 = #5203 + 0`` re-rounds EXT Z (1 mm in the
    machine file, 0.03937.. in) to 0.0394 in, while ``G91 G10 L2 P0 Z0`` leaves it at 1 mm.  Both follow
    specs/fanuc.md (an offset written in program units, rounded to their increment); whether a control keeps
    offsets in millimetres and rounds the write there is not modelled (the reference reader has no offset
    variables)."""
    tw = Twins(inch=True, macro=["G91", "#5203 = #5203 + 0.", "G90", "G90 G00 Z0."],
               g10=["G91", "G10 L2 P0 Z0.", "G90", "G90 G00 Z0."])
    (m, _), (g, _) = _motion(tw.text("macro")), _motion(tw.text("g10"))
    assert g[-1][1][2] == -200 + 1 and m[-1][1][2] == -200 + Fraction("0.0394") * Fraction("25.4")
