"""The start of ``[[tools]]`` solids from a Fanuc tool offset listing (``import-machine --tool-table``, issue 39).

A Fanuc keeps offsets, not tools: ``G43 H<n>`` and ``G41 D<m>`` pick registers the program chooses, and a
lathe's ``T0211`` pairs tool 2 with offset 11.  What a listing (:mod:`.fanuc_offsets`) gives towards a tool
solid, and what is written (every solid **commented out**, as for a LinuxCNC tool table;
specs/machine-import.md, "Fanuc", "Tool solids from an offset listing"):

* a mill, memory C (``L12``/``L13`` blocks exist only there: cutter radius registers D apart from the length
  registers H): per D register with a positive radius geometry, a cutter part of diameter
  2 × max(geometry, geometry + wear), numbered by its **offset number** n, which is the machine file's
  ``[[tools]] number`` (active under ``G43 H<n>``), with H<n>'s length in the comment; the pairing D<n> with
  H<n> is the offset screen's row, not the control's (note ``IM205``);
* a mill, memory A (``L11`` only) or B (``L10``/``L11``): H and D share the registers and the program's words
  say which holds a radius, so no solid (note ``IM201``);
* a lathe (X and Z, no Y): an offset gives no body, only the nose: a part holding the nose circle, the
  square of half-width R (tip 0/9) or 2R (tips 1-8) about the imaginary tip (specs/turning.md, "Tool nose
  radius"), with ``number = "?"``: the listing does not say which turret tool selects the offset.
"""

from __future__ import annotations

import re
from fractions import Fraction

from ..exact.decimals import format_decimal
from .fanuc_offsets import FanucListing, read_fanuc_listing
from .model import Collector, ImportedMachine, read_source

__all__ = ["offset_solids", "with_offset_solids"]

Row = tuple[str, str]


def _d(v: Fraction) -> str:
    return format_decimal(v)


def with_offset_solids(imported: ImportedMachine, path: str, c: Collector) -> ImportedMachine:
    """``imported`` (a Fanuc parameter listing) with the solids the offset listing at ``path`` starts, and the
    notes on it.  The listing's unit, when it states none, is the input unit: ``G20`` in ``modal`` is
    0000 #2 INI = 1 (:func:`nczones.imports.fanuc.read_fanuc`), else mm."""
    from dataclasses import replace

    g20 = next((how for code, how in imported.modal if code == "G20"), None)
    inch_input = (True, g20) if g20 is not None else (False, "0000 #2 INI is 0 or not given: no G20 at start-up")
    lathe = any(key == "type" and value == '"lathe"' for key, value, _ in imported.extra)  # a DIA axis
    rows = offset_solids(path, imported.axes, inch_input, c, lathe)
    return replace(imported, tool_solids=rows, notes=tuple(c.notes))  # c holds the parameter notes too


def offset_solids(path: str, axes: tuple[str, ...], inch_input: tuple[bool, str] | None,
                  c: Collector, lathe_control: bool = False) -> tuple[Row, ...]:
    """The commented-out ``[[tools]]`` rows for the offset listing at ``path`` on a machine with ``axes``.

    ``inch_input`` is whether the input unit is inches and why (None: not known, mm); it gives the listing's
    unit when the listing states no ``G20``/``G21`` (note ``IM203``).  A malformed listing is ``VF111``, as
    for ``verify --tool-table``.  The listing is in the lathe format (``G10 P X Z R Q``) on a lathe control
    (``lathe_control``, a diameter axis) or a machine with X and Z but no Y, else in the mill format."""
    lathe = "X" in axes and "Z" in axes and "Y" not in axes
    mill = all(a in axes for a in "XYZ")
    if not (lathe or mill):
        c.note("IM201", f"the tool offset listing {path} is not read: tool solids need the axes X, Y and Z (a mill) "
               "or X and Z without Y (a lathe)", file=path)
        return ()
    text = read_source(path, "tool offset listing", "VF111")
    stated = _stated_units(text)
    units = stated
    if units is None:
        units = "inch" if inch_input is not None and inch_input[0] else "mm"
        why = inch_input[1] if inch_input is not None else "the control's default"
        c.note("IM203", f"the tool offset listing states no G20/G21: its values are taken in the input unit, {units} "
               f"by {why}", file=path)
    # X offsets of a lathe are not written (only R and Q are), so a diameter axis needs no ORC here
    listing = read_fanuc_listing(path, units, lathe or lathe_control, axes, (), None)
    lines = text.split("\n")
    if lathe:
        return _lathe(path, listing, lines, c)
    if lathe_control:
        c.note("IM201", f"no solid from the lathe tool offset listing {path}: this lathe has a Y axis, so its "
               "solids take the mill form (vertical cylinders about the tool axis), which an offset's nose is not",
               file=path)
        return ()
    return _mill(path, listing, lines, c)


def _stated_units(text: str) -> str | None:
    """``"inch"``/``"mm"`` when the listing states ``G20``/``G21`` (the reader checks they agree), else None."""
    body = re.sub(r"\([^)]*\)", "", text).upper().replace(" ", "")
    m = re.search(r"G(20|21)(?!\d)", body)
    return None if m is None else ("inch" if m.group(1) == "20" else "mm")


def _source(path: str, lines: list[str], line: int) -> str:
    return f"{path}:{line}: {' '.join(lines[line - 1].split())}"


def _mill(path: str, listing: FanucListing, lines: list[str], c: Collector) -> tuple[Row, ...]:
    levels = listing.levels
    if not levels & {12, 13}:
        memory = ("memory B (G10 L10 geometry and L11 wear of registers H and D share), or memory C without "
                  "cutter radius values" if 10 in levels else "memory A (G10 L11 only: one value per register, "
                  "shared by H and D)")
        c.note("IM201", f"no cutter solid from the tool offset listing: it holds {memory}; which registers hold "
               "a cutter radius is chosen by the program's D words, not by the listing", file=path)
        return ()
    inch = " (inch x 25.4)" if listing.units == "inch" else ""
    rows: list[Row] = [
        ("", "[[tools]] is not written: a tool solid also needs the cutter's length and the shank and holder, "
             "which a tool offset listing does not give."),
        ("", f"{path} holds tool compensation memory C: it has G10 L12/L13 blocks, the cutter radius registers D "
             "that only memory C keeps apart from the length registers H (L10/L11)."),
        ("", "Each solid is numbered by its offset number n: [[tools]] number = n is the assembly under G43 Hn, and "
             "its diameter is Dn's, paired by the offset screen's row. The control does not pair them (the "
             "program's H and D words choose the registers): check that the program uses Dn with Hn."),
        ("", "Dn's geometry is taken, 2 x max(geometry, geometry + wear): a wear that shrinks the radius leaves "
             "the cutter inside the geometry's cylinder, one that grows it is taken. A D register that holds a "
             "difference (CAM output for wear compensation) is not the cutter's size."),
        ("", "Replace each \"?\", add the shank and holder, remove the '#'s (specs/machine-file.md, \"Tools and "
             "fixtures as solids\"):"),
    ]
    skipped: list[str] = []
    written = 0
    for n in sorted(listing.diameters):
        geometry = listing.diameters[n] / 2
        wear = listing.radius_wear.get(n, Fraction(0))
        where = listing.lines.get((12, n)) or listing.lines[(13, n)]
        if geometry <= 0:
            skipped.append(f"D{n} ({path}:{where}: geometry {_d(geometry)})")
            continue
        radius = max(geometry, geometry + wear)
        worn = ("" if wear == 0 else f"; wear {_d(wear)} taken" if wear > 0 else
                f"; wear {_d(wear)} not taken (the cutter is inside the geometry)")
        rows.append(("[[tools]]", ""))
        rows.append((f"number = {n}", f"offset {n}: the assembly under G43 H{n}; " + _length(listing, n, path)))
        rows.append((f"parts = [{{ name = \"cutter\", diameter = \"{_d(2 * radius)}\", length = \"?\" }}]",
                     f"{_source(path, lines, where)}: D{n} radius {_d(geometry)}{inch} x 2{worn}"))
        written += 1
    if skipped:
        rows.append(("", "No solid for " + ", ".join(skipped) + ": a radius geometry of 0 or less is no "
                     "cutter's size."))
    if written:
        c.note("IM205", f"paired by offset number: each cutter solid written from {path} (commented out) takes "
               "its diameter from D<n> for the assembly under G43 H<n>; the control does not pair D<n> with H<n>, "
               "the program's D and H words do: check them before removing the '#'s", file=path)
    return tuple(rows) if written else ()


def _length(listing: FanucListing, n: int, path: str) -> str:
    if n not in listing.lengths:
        return f"the listing has no H{n} (G10 L10/L11 P{n})"
    geometry, wear = listing.lengths[n], listing.length_wear.get(n, Fraction(0))
    total = geometry + wear
    what = f"H{n} = {_d(geometry)}" + (f" + wear {_d(wear)} = {_d(total)}" if wear else "") + " mm"
    if total <= 0:
        return (f"{what} is no length from the gauge line (measured from the table or a master tool?): the parts' "
                "lengths must add up to the tip's real distance below the gauge line")
    return (f"{what}: the tip under G43 H{n}, below the gauge line when H is measured from it; the parts from "
            "the tip up to the gauge line add up to it")


def _lathe(path: str, listing: FanucListing, lines: list[str], c: Collector) -> tuple[Row, ...]:
    rows: list[Row] = [
        ("", "[[tools]] is not written: a turret tool's parts are rectangles relative to its tip (the insert, the "
             "bar, its holder; specs/turning.md, \"Tool and fixture solids\"), and a tool offset listing gives no "
             "body: its X and Z say where the tip is, R the nose radius, Q the tip direction."),
        ("", "What it gives is the nose: a part holding the nose circle, the square of half-width R (tip 0 or 9) or "
             "2R (tips 1-8) about the imaginary tip, whichever way the machine's tip numbers turn (R: max(geometry, "
             "geometry + wear))."),
        ("", "The listing holds offsets, not tools: give the turret tool whose T word selects the offset (T0101 "
             "pairs tool 1 with offset 1, T0111 tool 1 with offset 11), the nose's thickness across centre "
             "height, add the insert, bar and holder, and remove the '#'s:"),
    ]
    written = 0
    skipped: list[str] = []
    for n, offset in sorted(listing.offsets.items()):
        geometry, wear = offset.nose_radius, offset.wear_radius
        radius = max(geometry, geometry + wear)
        where = listing.lines.get((True, n))
        if where is None:
            skipped.append(f"offset {n} (a wear block only)")
            continue
        if geometry <= 0:
            skipped.append(f"offset {n} ({path}:{where}: R {_d(geometry)})")
            continue
        reach = radius if offset.tip in (0, 9) else 2 * radius
        rows.append(("[[tools]]", ""))
        rows.append(('number = "?"', f"the turret tool that selects offset {n}"))
        rows.append((f'parts = [{{ name = "nose", x = ["{_d(-reach)}", "{_d(reach)}"], '
                     f'z = ["{_d(-reach)}", "{_d(reach)}"], thickness = "?" }}]',
                     f"{_source(path, lines, where)}: nose radius {_d(geometry)}"
                     + (f", wear {_d(wear)}" if wear else "") + f", tip {offset.tip}"))
        written += 1
    if skipped:
        rows.append(("", "No nose for " + ", ".join(skipped) + ": no geometry nose radius above 0."))
    if not written:
        c.note("IM201", f"no nose solid from the tool offset listing {path}: no geometry offset (P10001..) has a "
               "nose radius R above 0", file=path)
        return ()
    return tuple(rows)
