"""Optional block skip (block delete): the operator's switches, which a proof covers, and where a program
uses them (``specs/machine-file.md`` ``block_delete``, ``specs/fanuc.md``, ``specs/gcode-support.md``).

A Fanuc control has nine switches, BDT1 .. BDT9: a block starting with ``/n`` is skipped while switch
``n`` is on, ``/`` alone is ``/1``.  LinuxCNC has one switch, number 1 here: every line starting with
``/`` follows it (with the switch on the rest of the line is not read at all, so ``/1 G0 X4`` and
``//G0 X4`` are skipped; with it off they are errors, as ``rs274`` reports them).

A setting says, per switch, ``both`` (the proof covers the switch off and on), ``off`` or ``on``
(fixed).  It is written as one word for all nine switches (``both``, ``off``, ``on``: the form of
earlier versions), as ``N=POS`` items for single switches (``1=on,2=off``; the others ``both``), or as
a word followed by items (``off,2=both``: all off but switch 2).

>>> parse_block_delete("off,2=both")[2], parse_block_delete("off,2=both")[3]
('both', 'off')
>>> format_block_delete(parse_block_delete("2=off,1=on"))
'1=on,2=off'
>>> format_block_delete(parse_block_delete("on"))
'on'
>>> sorted(used_switches("G0 X1\\n/2 G0 X2\\n/ G0 X3\\n /3G1 X4\\n", "fanuc").items())
[(1, [3]), (2, [2]), (3, [4])]
>>> used_switches("/1 G0 X4\\n//G0 X4\\n", "linuxcnc")
{1: [1, 2]}
"""

from __future__ import annotations

import re
from collections.abc import Collection, Mapping

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

#: The switches: Fanuc BDT1 .. BDT9 (LinuxCNC's one switch is number 1).
SWITCHES = tuple(range(1, 10))
POSITIONS = ("both", "off", "on")
_ITEM = re.compile(r"^\s*(?:/?([1-9])\s*=\s*)?([A-Za-z]+)\s*$")
_LINE = re.compile(r"(?m)^[ \t]*/([1-9]?)")


def parse_block_delete(value: str | Mapping[str, str] | Mapping[int, str]) -> dict[int, str]:
    """The position setting of every switch 1..9 from its written form; ``ValueError`` says what is allowed."""
    if isinstance(value, Mapping):
        items = [f"{k}={v}" for k, v in value.items()]
    elif isinstance(value, str):
        items = value.split(",")
    else:
        raise ValueError(f"expected a string, not {value!r}")
    default, single, seen = None, {}, set()
    for k, item in enumerate(items):
        m = _ITEM.match(item)
        if m is None or m.group(2).lower() not in POSITIONS:
            raise ValueError(f"{item.strip()!r} is not a switch position; use \"both\" (verify the switches off: "
                             "lines starting with / run, and on: they are skipped), \"off\" or \"on\" for every "
                             "switch, or N=both|off|on for switch N (1 to 9, Fanuc /1 .. /9), comma-separated after "
                             "an optional position for the others (e.g. \"1=on,2=off\", \"off,2=both\")")
        pos = m.group(2).lower()
        if m.group(1) is None:
            if k != 0 or isinstance(value, Mapping):
                raise ValueError(f"{item.strip()!r}: a position for every switch comes first (e.g. off,2=both)")
            default = pos
            continue
        n = int(m.group(1))
        if n in seen:
            raise ValueError(f"switch {n} is given twice")
        seen.add(n)
        single[n] = pos
    return {n: single.get(n, default or "both") for n in SWITCHES}


def format_block_delete(modes: Mapping[int, str]) -> str:
    """The canonical written form of a setting (``both``/``off``/``on`` when all switches agree)."""
    values = [modes.get(n, "both") for n in SWITCHES]
    default = max(POSITIONS, key=lambda p: (values.count(p), p == "both"))
    rest = ",".join(f"{n}={modes.get(n, 'both')}" for n in SWITCHES if modes.get(n, "both") != default)
    if default == "both" and rest:
        return rest
    return default + ("," + rest if rest else "")


def skipped_switches(block_delete: bool | Collection[int]) -> frozenset[int]:
    """The switches that are on (their lines skipped): ``True`` is all, ``False`` none."""
    if block_delete is True:
        return frozenset(SWITCHES)
    if block_delete is False:
        return frozenset()
    return frozenset(block_delete)


def used_switches(text: Any, dialect: str) -> dict[int, list[int]]:
    """The switches a program's lines start with and their line numbers (1-based): ``/`` is switch 1;
    LinuxCNC has only switch 1 (``/2`` there is a line its one switch skips).  ``text`` is a ``str`` or a
    streamed file (:class:`~nczones.gcode.source.FileText`), read a piece at a time, each cut after a newline
    (so every piece starts a line, as ``^`` needs)."""
    used: dict[int, list[int]] = {}
    if "/" not in text:
        return used
    line = 1
    for piece in (text,) if isinstance(text, str) else text.pieces(1 << 20):
        at = 0
        for m in _LINE.finditer(piece):
            n = int(m.group(1)) if m.group(1) and dialect == "fanuc" else 1
            line += piece.count("\n", at, m.start())
            at = m.start()
            lines = used.setdefault(n, [])
            if not lines or lines[-1] != line:
                lines.append(line)
        line += piece.count("\n", at)
    return used
