"""The double pass on a lathe: what a LinuxCNC lathe changes for the motion's doubles, and what the pass declines.

The full path runs a lathe program with :class:`~nczones.gcode.linuxcnc.lathe.LatheInterpreter` (a machine with
``diameter_axes``, or a text that mentions G7, G8 or G70-G72: :func:`~nczones.gcode.mentions.uses_lathe`), which
is the mill's interpreter with three changes:

* **Diameter mode** (G7; G8 is radius mode): every X word is a diameter, halved before it is used
  (``Interp::read_x``: ``block->x_number = value / 2``; G7 or G8 in a block re-scales that block's X,
  ``convert_lathe_diameter_mode``, before the block's motion: the block's X is halved exactly when the mode
  *after* its G7/G8 is diameter).  So is an incremental X (G91: the increment is the word, halved), an arc's X
  end; not I, J, K (radii: only G76 halves them), nor R.  A machine with ``diameter_axes = ["X"]`` starts in
  G7 (LinuxCNC's ``RS274NGC_STARTUP_CODE``), any other in G8.
* **G70-G72** (the profile cycles, :mod:`.g7x`): declined here, with G76, G33 and G33.1 (spindle-synchronised
  motion) and G95 (feed per revolution): none is in the pass's code table (:data:`nczones.gcode.codes.LINUXCNC_G`).
  G96 (constant surface speed, ``D`` its speed limit) and G97 move nothing (LinuxCNC's
  ``convert_spindle_mode`` only sets the spindle's mode, and the pass reads no feed rate but its sign): the pass
  takes them, but G96 without S (LinuxCNC's error "S word missing with G96", which the full path does not
  raise) and a D word in a block without G96 (the full path's GC204) decline (:func:`spindle_mode`).
* **Nothing else**: the plane (a lathe's machine file starts in G18, but the pass takes arcs only after the
  program sets the plane, as on a mill), the work offsets, ``G43 H<n>`` on the tool axis (Z on an X-Z lathe) and
  the zones are the mill's; the machine coordinates and zones are radii (``Machine.diameter_axes``), so the rows
  are radii and a report's diameters are the prover's business, not the pass's.

What the prover reads of a lathe's tool (the pass leaves those machines to the full path): tool solids
(``[[tools]]``, ``[spindle]``: an insert, a boring bar, :mod:`nczones.lathe_solids`) are declined here before
the pass runs (``prover/doubles.py`` would refuse its boxes anyway); a tool tip zone (``point = "tip"``) is
proved with the tool length the boxes leave out, so ``G43`` declines on such a machine (``_Pass._tools``, as on a
mill); the nose radius of ``[tool_offsets]`` enlarges the tip zones before the pass sees the machine
(:func:`nczones.prover.nose.nose_zones`, the same machine for both paths).

Why the halved double keeps the pass's bound: the word's exact value ``w`` (its shadow or its double ``d``) is
within half an ulp of ``d``; the full path's coordinate word is ``w / 2`` (exact), the pass's ``d * 0.5``, which
is ``d / 2`` exactly (a power of two: only the exponent changes) unless ``d / 2`` is subnormal, and then the
correctly rounded ``d / 2`` as LinuxCNC's ``value / 2`` (the same real number rounded once: ``x * 0.5`` and
``x / 2.0`` are the same double).  So ``|d/2 - w/2| = |d - w| / 2`` is within half an ulp of ``d / 2``: the
module's bound (``doubles.py``, "Why the bound holds") holds for the halved word as for any word; a subnormal's
rounding (at most ``2**-1075`` a word, however many words a G91 chain adds up) is far below the ``2**-60`` mm
every row is widened by (``doubles._TINY``).  A G8 block in G7 is not halved (LinuxCNC halves then doubles:
the same double but for a subnormal, covered alike).
"""

from __future__ import annotations

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["DIAMETER", "SPINDLE_MODE", "diameter_start", "diameter_body", "lathe_reason", "spindle_mode"]

#: The modal groups of G7/G8 (LinuxCNC's group 15) and of G96/G97 (14) as the pass names them
#: (``doubles._GROUP_NAMES``).
DIAMETER = "diameter"
SPINDLE_MODE = "spindle mode"
#: ``st.half``: the factor of an X word in diameter mode (G7) and in radius mode (G8).
_HALF = {7: 0.5, 8: 1.0}


def lathe_reason(machine: Any) -> str | None:
    """Why the pass declines ``machine`` as a lathe (None: it takes it): diameter axes other than X (the full
    path halves X only), and tool solids on a lathe (the prover checks them on the full path)."""
    dia = tuple(getattr(machine, "diameter_axes", ()) or ())
    if dia not in ((), ("X",)):
        return "a lathe whose diameter axes are not X alone"
    lathe = getattr(machine, "machine_type", "mill") == "lathe" or bool(dia)
    sections = getattr(machine, "sections", {}) or {}
    if lathe and (sections.get("tools") or sections.get("spindle")):
        return "a lathe with tool or spindle solids (the full path checks them)"
    return None


def diameter_start(machine: Any) -> tuple[float, bool]:
    """``(half, possible)``: the factor of an X word at the start (0.5: G7, the machine's ``diameter_axes``
    holds X; 1.0: G8), and whether X words are compiled with the factor from the start (a lathe; on another
    machine a G7 turns it on, :func:`diameter_body`)."""
    dia = "X" in (getattr(machine, "diameter_axes", ()) or ())
    lathe = getattr(machine, "machine_type", "mill") == "lathe"
    return (0.5 if dia else 1.0), (dia or lathe)


def diameter_body(st: Any, groups: dict[str, int]) -> list[str] | str:
    """The code of a block's G7 or G8 (``st.half``, before the block's motion: the block's X takes the mode it
    sets, as LinuxCNC's ``convert_lathe_diameter_mode``), or why the pass declines it (a ``str``, as
    :mod:`.double_arcs` says why).  On a machine whose X words were compiled without the factor
    (``st.diameter`` false: not a lathe), a G7 turns the factor on for the lines compiled after it, and
    declines when a line with an X word was compiled before it (its step would not halve)."""
    code = groups.get(DIAMETER)
    if code is None:
        return []
    if code == 7 and not st.diameter:
        if st.x_compiled:
            return "G7 after a line with an X word (on a machine that is not a lathe)"
        if getattr(st, "g20_compiled", False):  # the inch code does not halve (doubles._Pass.units)
            return "G7 after a G20 (on a machine that is not a lathe)"
        st.diameter = True
    return [f"st.half = {_HALF[code]!r}"]


def spindle_mode(groups: dict[str, int], others: list[str]) -> str | None:
    """Why the pass declines a block's G96 or D word (None: it does not): G96 without an S word (LinuxCNC
    refuses it: ``interp_check.cc``, "S word missing with G96"; the full path takes it), a D word without G96 in
    its block (LinuxCNC's and the full path's error, GC204: the pass follows no cutter compensation nor cycle
    that reads D).  G96 and G97 themselves move nothing."""
    mode = groups.get(SPINDLE_MODE)
    if mode == 96 and "S" not in others:
        return "G96 without an S word (LinuxCNC's error)"
    if "D" in others and mode != 96:
        return "a D word without G96"
    return None
