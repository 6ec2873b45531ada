"""What differs between the dialects, seen from outside: cross-dialect hints (a Fanuc run's report notes are
:func:`nczones.gcode.fanuc.program.fanuc_notes`, beside the runners they read).

A diagnostic that only one dialect gives says so: when a line the program was
rejected for would be read by the other dialect (it parses there, and its G
codes exist there without two of one modal group), the message names it,
``valid in the fanuc dialect: set dialect = "fanuc" in [machine] (or pass
--dialect fanuc)``.  The same goes for ``unknown`` reasons of codes the
other dialect models (:func:`unknown_hint`).

>>> from nczones.errors import Diagnostic, GcodeError, SourceSpan
>>> e = GcodeError(Diagnostic("GC201", "G0 and G1 are in the same modal group",
...                SourceSpan("p.nc", 1, 1, 3, "G00 G17 G01 X5")))
>>> print(with_hints(e, "linuxcnc").diagnostics[0].message)
G0 and G1 are in the same modal group; valid in the fanuc dialect: set dialect = "fanuc" in [machine] (or pass --dialect fanuc)
"""

from __future__ import annotations

from ..errors import GcodeError
from ..precompiled import replace  # dataclasses.replace without importing dataclasses (start-up)

__all__ = ["with_hints", "accepts", "unknown_hint", "HINTED_CODES"]

#: Diagnostic codes a line alone decides (syntax, unknown codes, modal group conflicts, letters).
HINTED_CODES = ("GC101", "GC102", "GC104", "GC105", "GC106", "GC107", "GC201", "GC202", "GC203", "GC204")


def _hint(dialect: str) -> str:
    return f"valid in the {dialect} dialect: set dialect = \"{dialect}\" in [machine] (or pass --dialect {dialect})"


def accepts(line: str, dialect: str) -> bool:
    """Whether ``dialect`` reads ``line`` as one block: it parses, its literal G codes exist in that
    dialect, and no two of them are in one modal group (what one line decides).

    >>> accepts("G00 G17 G40 G49 G80 G90", "fanuc"), accepts("G00 G17 G40 G49 G80 G90", "linuxcnc")
    (True, True)
    >>> accepts("G00 G01 X1", "fanuc"), accepts("G00 G01 X1", "linuxcnc")
    (True, False)
    >>> accepts("o100 while [#1 lt 3]", "linuxcnc"), accepts("WHILE [#1 LT 3] DO1", "linuxcnc")
    (True, False)
    """
    from ..errors import GcodeError as _E
    from .interpreter import GROUP_OF, UNSUPPORTED_G, gkey

    try:
        if dialect == "fanuc":
            from .fanuc.interpreter import GROUPS
            from .fanuc.parser import LITERAL
            from .fanuc.parser import parse_line as parse_fanuc

            fl = parse_fanuc(line, 1, "<line>")
            codes = [w[2][0] for w in fl.words if w[0] == "G" and w[1] == LITERAL]
            table, unknown = GROUPS, {}
        else:
            from .parser import NUM
            from .parser import parse_line as parse_linuxcnc

            pl = parse_linuxcnc(line, 1, "<line>")
            if pl.unsupported is not None:
                return False
            codes = [w[1][2] for w in pl.words if w[0] == "G" and w[1][0] == NUM]
            table, unknown = GROUP_OF, UNSUPPORTED_G
    except _E:
        return False
    seen: set = set()
    motion: set = set()
    for q in codes:
        k = gkey(q)
        if k is None:
            return False
        g = table.get(k)
        if g is None:
            if k in unknown:
                continue
            return False
        if g in seen and not (dialect == "fanuc" and g != 0) and not (dialect == "linuxcnc" and g == 1 and
                                                                       (k == 800 or 800 in motion)):
            return False  # LinuxCNC drops a G80 beside another motion code
        seen.add(g)
        if g == 1:
            motion.add(k)
    return True


def with_hints(exc: GcodeError, dialect: str) -> GcodeError:
    """``exc`` with the other dialect named in the diagnostics it would not give."""
    other = "fanuc" if dialect == "linuxcnc" else "linuxcnc"
    out = []
    changed = False
    for d in exc.diagnostics:
        if d.code in HINTED_CODES and d.span is not None and d.span.text and "valid in the" not in d.message \
                and accepts(d.span.text, other):
            d = replace(d, message=f"{d.message}; {_hint(other)}")
            changed = True
        out.append(d)
    return GcodeError(out) if changed else exc


def unknown_hint(code: str, line: str, dialect: str) -> str:
    """A sentence for an ``unknown`` reason when the other dialect models the line's code, else ``""``."""
    if dialect == "linuxcnc" and (code == "GC391" or code.startswith(("G68", "G65", "G66", "G51", "G50", "G15",
                                                                      "G16", "G54.1", "M97", "M99"))):
        if accepts(line, "fanuc"):
            return "; " + _hint("fanuc")
    return ""
