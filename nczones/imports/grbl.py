"""Grbl: a ``$$`` settings dump, optionally with the ``$#`` parameters.

Grbl keeps its machine space negative: homing sets the switch corner to 0 (less
the pull-off) and the travel runs from ``-$130`` to 0 on every axis, whichever
way the axis homes (``system_check_travel_limits`` in Grbl 1.1 without
``HOMING_FORCE_SET_ORIGIN``).  So ``$130``–``$132`` become the box
``[-max travel, 0]``, and the home position is ``-pull-off`` (or
``-max travel + pull-off`` for an axis that homes towards minus), on the step
grid.  All settings are in mm whatever ``$13`` says (``$13`` only changes
reports, including the ``$#`` offsets).

Two layouts are read: Grbl 0.9 and 1.1 (``$100``–``$132`` per axis, up to six
axes X Y Z A B C as grblHAL and the 4/5/6-axis forks number them) and the
Grbl 0.9 development layout of 2013–2014 (``$0``–``$11`` per axis), told
apart by the ``$100`` settings or, without them, by the comments Grbl prints.
``specs/machine-import.md`` lists every setting.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from fractions import Fraction
from pathlib import Path

from ..errors import SourceSpan
from ..exact import format_decimal
from ..machine import WORK_OFFSETS
from .linuxcnc import modal_changes, startup_modal
from .model import (
    INCH,
    Collector,
    HomingDraft,
    ImportedMachine,
    Sourced,
    ZoneDraft,
    frozen,
    in_range,
    line_span,
    rounded_decimal,
)

__all__ = ["read_grbl", "LAYOUTS"]

_AXES = "XYZABC"

#: Setting numbers per layout: per-axis bases (axis i adds i) and single settings.
LAYOUTS = {
    "1.1": {"steps": 100, "rate": 110, "accel": 120, "travel": 130, "axes": 6,
            "report_inches": 13, "soft": 20, "hard": 21, "homing": 22, "homing_dir": 23,
            "homing_feed": 24, "homing_seek": 25, "pulloff": 27},
    "0.9-dev": {"steps": 0, "rate": 3, "accel": 6, "travel": 9, "axes": 3,
                "report_inches": 19, "soft": 23, "hard": 24, "homing": 25, "homing_dir": 26,
                "homing_feed": 27, "homing_seek": 28, "pulloff": 30},
}
#: A setting as read: its value, the text written, the description Grbl printed beside it, where it stands.
Setting = tuple[Fraction, str, str | None, SourceSpan]

_LAYOUT_NAMES = {"1.1": "Grbl 0.9/1.1 ($100-$132)",
                 "0.9-dev": "Grbl 0.9 development layout of 2013-2014 ($0-$11 per axis)"}

_SETTING = re.compile(r"\s*\$(\d+)\s*=\s*(\S*)\s*(?:\((.*)\))?\s*$")
_STARTUP = re.compile(r"\s*\$N(\d)\s*=(.*)$", re.I)
_PARAM = re.compile(r"\s*\[(G5[4-9]|G28|G30|G92|TLO|PRB)\s*:([^\]]*)\]\s*$")
_IGNORED = re.compile(r"\s*(?:$|ok\b|error:|alarm:|>|\[[A-Z]+:.*\]|<.*>|Grbl\b|\(.*\)\s*$|;)", re.I)


def _lround(q: Fraction) -> Fraction:
    """C's ``lround``: to the nearest integer, halves away from zero (Grbl puts the homed axis on a step).

    >>> _lround(Fraction(5, 2)), _lround(Fraction(-5, 2)), _lround(Fraction(-7, 3))
    (Fraction(3, 1), Fraction(-3, 1), Fraction(-2, 1))
    """
    n = (abs(q.numerator) * 2 + q.denominator) // (2 * q.denominator)
    return Fraction(n if q >= 0 else -n)


def _setting_how(n: int, raw: str, comment: str | None) -> str:
    return f"${n}={raw}" + (f" ({comment.strip()})" if comment else "")


def read_grbl(path: str, text: str, c: Collector) -> ImportedMachine:
    """Read a Grbl ``$$`` dump (and ``$#`` lines when present); see the module docstring."""
    settings: dict[int, Setting] = {}
    params: dict[str, tuple[list[Fraction], SourceSpan]] = {}
    startup: list[tuple[str, SourceSpan]] = []
    for i, line in enumerate(text.lstrip("\ufeff").split("\n"), 1):
        body = line.rstrip("\r")
        m = _SETTING.match(body)
        if m:
            n = int(m.group(1))
            span = line_span(path, i, body, m.start(2), m.end(2))
            q = c.real(m.group(2), f"${n}", span)
            if q is None:
                continue
            if n in settings:
                c.error("IM108", f"${n} is set twice (first at line {settings[n][3].line})",
                        line_span(path, i, body, body.index("$")))
                continue
            settings[n] = (q, m.group(2), m.group(3), span)
            continue
        m = _STARTUP.match(body)
        if m:
            if m.group(2).strip():
                startup.append((m.group(2).strip(), line_span(path, i, body, m.start(2))))
            continue
        m = _PARAM.match(body)
        if m:
            span = line_span(path, i, body, m.start(2), m.end(2))
            fields = m.group(2).split(":")[0].split(",")
            values = [c.real(f, f"[{m.group(1)}:...]", span) for f in fields]
            if all(v is not None for v in values):
                params[m.group(1)] = ([v for v in values if v is not None], span)
            continue
        if _IGNORED.match(body):
            continue
        stripped = body.strip()
        c.error("IM102", f"{stripped!r} is not a Grbl setting: expected $<number>=<value> lines (as $$ prints "
                "them), $N startup lines or [G54:...] parameter lines (as $# prints them)",
                line_span(path, i, body, len(body) - len(body.lstrip())))
    c.raise_if_failed()

    layout = _layout(path, settings, c)
    c.raise_if_failed()
    lay = LAYOUTS[layout]

    def get(key: str, axis: int = 0) -> Setting | None:
        return settings.get(lay[key] + axis)

    def need(key: str, axis: int = 0) -> Setting:
        """A setting the checks above have made sure of."""
        return settings[lay[key] + axis]

    def how(key: str, axis: int = 0) -> str:
        q, raw, comment, _ = settings[lay[key] + axis]
        return _setting_how(lay[key] + axis, raw, comment)

    axes = tuple(_AXES[i] for i in range(lay["axes"]) if get("travel", i) is not None or get("rate", i) is not None)
    if not axes:
        c.error("IM107", "no axis: the dump has no max travel or max rate setting "
                f"(${lay['travel']}, ${lay['rate']} and up)", file=path)
        c.raise_if_failed()
    for i, a in enumerate(axes):
        for key in ("travel", "rate"):
            if get(key, i) is None:
                c.error("IM107", f"axis {a}: ${lay[key] + i} ({'max travel' if key == 'travel' else 'max rate'}) "
                        "is missing; a $$ dump lists it for every axis", file=path)
    c.raise_if_failed()

    def flag(key: str) -> bool:
        setting = get(key)
        if setting is None:
            return False
        if setting[0] not in (0, 1):
            c.error("IM105", f"{how(key)}: a boolean setting is 0 or 1", setting[3])
        return bool(setting[0] == 1)

    soft, homing = flag("soft"), flag("homing")
    mask_s = get("homing_dir")
    mask = int(mask_s[0]) if mask_s is not None and mask_s[0].denominator == 1 and 0 <= mask_s[0] < 256 else 0
    if mask_s is not None and Fraction(mask) != mask_s[0]:
        c.error("IM105", f"{how('homing_dir')}: the homing direction mask is a whole number 0..255", mask_s[3])
    pulloff = get("pulloff")

    rapid: dict[str, Sourced] = {}
    pulse: dict[str, Sourced] = {}
    lo: dict[str, Sourced] = {}
    hi: dict[str, Sourced] = {}
    home: dict[str, Sourced] = {}
    steps: dict[str, Fraction] = {}
    for i, a in enumerate(axes):
        q, _, _, span = need("rate", i)
        if q <= 0:
            c.error("IM108", f"{how('rate', i)}: the max rate must be greater than 0", span)
        elif in_range(c, q, how("rate", i), span):
            rapid[a] = Sourced(q, how("rate", i), span)
        st = get("steps", i)
        if st is not None:
            if st[0] <= 0:
                c.error("IM108", f"{how('steps', i)}: steps per mm must be greater than 0", st[3])
            else:
                steps[a] = st[0]
                exact = 1 / st[0]
                p, was_rounded = rounded_decimal(exact)
                text_how = f"1 / {how('steps', i)}"
                if was_rounded:
                    text_how += f"; exactly {exact.numerator}/{exact.denominator}, rounded"
                    c.note("IM202", f"{how('steps', i)}: the step length {exact.numerator}/{exact.denominator} "
                           f"{'deg' if a in 'ABC' else 'mm'} is "
                           f"not a finite decimal; the pulse is written rounded to {format_decimal(p)} (the prover "
                           "does not use the pulse)", st[3])
                if p > 1:
                    c.note("IM201", f"{how('steps', i)}: a step of {format_decimal(exact, 6)} mm is beyond the "
                           "machine file's pulse range (at most 1)", st[3])
                else:
                    pulse[a] = Sourced(p, text_how, st[3])
        travel, _, _, span = need("travel", i)
        if travel < 0:
            c.error("IM108", f"{how('travel', i)}: max travel is a length, not negative (Grbl stores it negated "
                     "itself)", span)
            continue
        if not in_range(c, travel, how("travel", i), span):
            continue
        lo[a] = Sourced(-travel, f"minus {how('travel', i)}: Grbl's machine space is negative", span)
        hi[a] = Sourced(Fraction(0), f"0: Grbl's machine zero is at the homing corner ({how('travel', i)})", span)
        inverted = bool(mask >> i & 1)
        if homing:
            pull = pulloff[0] if pulloff is not None else Fraction(0)
            target = -travel + pull if inverted else -pull
            exact = _lround(target * steps[a]) / steps[a] if a in steps else target
            value, was_rounded = rounded_decimal(exact)
            why = (f"minus {how('travel', i)} plus {how('pulloff')}: homes towards minus" if inverted
                   else f"minus {how('pulloff')}: homes towards plus" if pulloff is not None
                   else "0: homes towards plus")
            if exact != target:
                why += ", on the step grid"
            if was_rounded:
                c.note("IM202", f"axis {a}: the homed position {exact.numerator}/{exact.denominator} "
                       f"{'deg' if a in 'ABC' else 'mm'} (on the "
                       f"step grid) is not a finite decimal; written rounded to {format_decimal(value)}", span)
            home[a] = Sourced(value, why, pulloff[3] if pulloff is not None else span)
        else:
            home[a] = Sourced(Fraction(0), "homing off: Grbl starts at machine zero where it stands")
    c.raise_if_failed()

    if not homing:
        s_h = get("homing")
        c.note("IM203", f"homing is off ({how('homing') if s_h else 'no homing setting'}): Grbl's machine "
               "coordinates start where the machine stands at power-on, so the travel box is placed as Grbl "
               "places it after homing, [-max travel, 0] on every axis", s_h[3] if s_h else None, file=path)
    if not soft:
        s_s = get("soft")
        c.note("IM203", f"soft limits are off ({how('soft') if s_s else 'no soft-limit setting'}): Grbl "
               "does not stop at the travel box; it is written as the machine's travel all the same",
               s_s[3] if s_s else None, file=path)

    # $# parameters: work offsets and the stored G28/G30 positions (in inches when $13=1)
    inch = flag("report_inches")
    factor = INCH if inch else Fraction(1)
    unit_how = f", in, x 25.4 ({how('report_inches')})" if inch else ""
    offsets: dict[str, dict[str, Sourced]] = {}
    reference: dict[str, Sourced] = {}

    def point(key: str) -> dict[str, Sourced] | None:
        if key not in params:
            return None
        values, span = params[key]
        if len(values) < len(axes):
            c.error("IM102", f"[{key}:...] gives {len(values)} coordinates for {len(axes)} axes", span)
            return None
        return {a: Sourced(values[i] * factor, f"[{key}:...] {a}{format_decimal(values[i])}{unit_how}", span)
                for i, a in enumerate(axes)}

    for name in WORK_OFFSETS[:6]:
        work = point(name)
        if work is not None and any(v.value for v in work.values()):
            offsets[name] = {a: v for a, v in work.items() if v.value}
    g28 = point("G28")
    if g28 is not None:
        reference = g28
    else:
        reference = {a: Sourced(Fraction(0), "no $# output: Grbl's G28 position defaults to machine zero")
                     for a in axes}
        if "G28" not in params:
            c.note("IM203", "no $# output ([G28:...]): the reference (where G28 goes) is taken as machine zero, "
                   "Grbl's default; add the $# lines to take the stored G28 position", file=path)
    start = home if any(home[a].value != reference[a].value for a in axes) else {}
    g30 = point("G30")
    if g30 is not None and any(g30[a].value != reference[a].value for a in axes):
        c.note("IM201", "the G30 position differs from the G28 position; the machine file has one reference "
               "position, used by both", params["G30"][1])
    g92 = point("G92")
    if g92 is not None and any(v.value for v in g92.values()):
        c.note("IM201", "a G92 offset is in effect; the machine file has none (Grbl forgets it at reset unless "
               "a program sets it again)", params["G92"][1])
    if "TLO" in params and any(params["TLO"][0]):
        c.note("IM201", "a tool length offset (G43.1) is in effect; the machine file's tool lengths are registers "
               "(G43 H), so it is not taken", params["TLO"][1])
    for positions in [reference, start, *offsets.values()]:
        for v in positions.values():
            in_range(c, v.value, v.how, v.span)
    c.raise_if_failed()

    modal = _startup_modal(startup, c)
    zone = ZoneDraft("soft limits" if soft else "travel", False, frozen(lo), frozen(hi),
                     (f"Grbl's travel, {_LAYOUT_NAMES[layout]}: [-max travel, 0] on every axis "
                      f"({'soft limits on' if soft else 'soft limits off: Grbl does not stop here'})",))
    homing_drafts = _homing(axes, homing, mask, lay, settings, how, lo)
    if homing_drafts:
        c.note("IM201", f"homing ({' '.join(h.axis for h in homing_drafts)}): not taken; the machine file's "
               f"[homing.<axis>] also needs {', '.join(homing_drafts[0].missing)} (Grbl homes to the limit "
               "switch alone); written commented out", need("homing")[3], file=path)
    name = Path(path).stem
    return ImportedMachine(
        kind="grbl", source=path, name=name, name_how="the file name",
        axes=axes, axes_how=f"the axes with settings, {_LAYOUT_NAMES[layout]}",
        rapid=frozen(rapid), reference=frozen(reference), start=frozen(start), pulse=frozen(pulse),
        rapid_mode=("linear", "Grbl moves G0 on a straight line"),
        extra=(("dialect", '"linuxcnc"', "Grbl reads the RS-274/NGC subset LinuxCNC's dialect describes"),
               ("arc_tolerance", '"grbl"', "Grbl's arc check (gcode.c): an I/J arc's end radius may differ from "
                "its start radius by 0.005 mm (nczones does not take Grbl's wider 0.1 %, up to 0.5 mm), an R arc "
                "not at all")),
        modal=modal,
        offsets=frozen({k: frozen(v) for k, v in offsets.items()}),
        zones=(zone,) if lo else (), homing=homing_drafts, notes=tuple(c.notes),
    )


def _layout(path: str, settings: dict[int, Setting], c: Collector) -> str:
    if any(n >= 100 for n in settings):
        return "1.1"
    comments = {n: (s[2] or "").lower() for n, s in settings.items()}
    if "travel" in comments.get(9, "") or "step/mm" in comments.get(0, ""):
        if not any("travel" in comments.get(n, "") for n in (9, 10, 11)):
            c.error("IM107", "this looks like Grbl 0.8 ($0-$2 are steps per mm, and there is no max travel): "
                    "Grbl 0.8 has no travel settings to take zones from", file=path)
        return "0.9-dev"
    c.error("IM107", "no $100-$132 settings: Grbl 0.9 and 1.1 print them for every axis, and without the comments "
            "Grbl prints beside each setting the older layouts cannot be told apart; give the complete $$ output",
            file=path)
    return "1.1"


def _startup_modal(startup: list[tuple[str, SourceSpan]], c: Collector) -> tuple[tuple[str, str], ...]:
    chosen: dict[str, tuple[str, str]] = {}
    for block, span in startup:
        startup_modal(block, f"startup block {block!r}", f"startup block $N={block} ({span.file}:{span.line})",
                      span, chosen, c)
    return modal_changes(chosen)


def _homing(axes: tuple[str, ...], homing: bool, mask: int, lay: dict[str, int], settings: dict[int, Setting],
            how: Callable[..., str], lo: dict[str, Sourced]) -> tuple[HomingDraft, ...]:
    if not homing:
        return ()
    out = []
    for i, a in enumerate(axes):
        inverted = bool(mask >> i & 1)
        fields: list[tuple[str, Sourced | str, str]] = [
            ("direction", '"negative"' if inverted else '"positive"',
             f"{how('homing_dir')}: bit {i} {'set' if inverted else 'clear'}" if lay["homing_dir"] in settings
             else "no homing direction mask: towards plus"),
        ]
        for key, name in (("homing_seek", "search_speed"), ("homing_feed", "latch_speed")):
            n = lay[key]
            if n in settings and settings[n][0] > 0:
                fields.append((name, Sourced(settings[n][0], how(key), settings[n][3]), ""))
        edge = lo[a].value if inverted else Fraction(0)
        fields.append(("dog_position", Sourced(edge, "the limit switch trips at the end of the travel", lo[a].span),
                       ""))
        out.append(HomingDraft(a, tuple(fields), ("dog_length", "grid_pitch", "detector_phase")))
    return tuple(out)
