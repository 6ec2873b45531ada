"""Runs of plain Fanuc lines read straight into the box of the numpy-free route (issue 36).

On the box route (:mod:`nczones.prover.fanucboxes`) the interpreter's plain lane writes each straight move and
arc of a run into a :class:`~nczones.gcode.fanuc.columns.BoxRows` box; reading a line through the language
layer (``FanucRunner.read_plain`` -> ``scan_plain`` -> ``plain_first`` -> ``FanucInterpreter.lane`` /
``_arc_lane``) costs 15-20 us, most of it making Fractions the box never keeps.  :func:`read_box_run` reads a
run of such lines from the text itself: each line is keyed on its layout (its digits zeroed, as the LinuxCNC
double pass keys its lines, ``gcode/shapes.py``), the layout read once into where its numbers are and what they
are (the text is cut into lines once, by :class:`_Lines`, when its first line is in the subset), and the line
then updates the interpreter's state kept as scaled integers (``10**SCALE``, as the box's):
the position (program value plus the offset, ``FanucInterpreter.lane``), the motion mode and the feed.  Each
motion widens the box as the lane's would: a straight move by its end, an arc by
:func:`~nczones.gcode.fanuc.columns.r_arc_box` / :func:`~nczones.gcode.fanuc.columns.centre_arc_box` and the ends
of its other axes (``BoxRows.add_arc``), on the same integers.  An arc that cannot widen the run's box is not
boxed: every point of an R arc lies within ``2|R|`` of both its ends (a diameter; ``r_arc_box`` rounds a unit
outward at most, :data:`_SLACK` covers it), every point of an I/J arc whose ends lie on one circle in that circle's
box (``centre_arc_box`` rounds its root up by a unit); when that box is inside the run's, the run's box is the same
either way (only for arcs the box functions take: a chord of at most ``sqrt(3)|R|``, equal radii).

The subset, taken only in the state both lanes take (``FanucInterpreter.lane`` and ``_arc_lane``'s tests: no
cycle, compensation, transform, tool length shift, inch input, incremental input, G93/G95, tracked ranges,
assumed modes still to be noted ...): a line of upper-case words with blanks between them, at most a leading
integer N, one G of 0-3 (G0 .. G03), axis words of the machine's X, Y and Z, F, and for G2/G3 the plane's R or centre
offsets (not both), each letter once; every length a decimal with a point and at most the increment system's
decimals (as ``FanucRunner.plain_ok`` lets the plain lane take it: a length without a point is read by the
decimal point rule on the general path), F positive.  Anything else ends the run: that line and the ones after
it go the way they went before, the state handed back as the lanes leave it (position, motion, feed, the counts
of blocks and motions, the block index and span, the run's box and tool length).  An arc the box functions leave
to the interpreter (equal ends of an R arc, a half circle within the tolerance, a spiral past it) ends the run
the same way.  The runner asks for a run only on the box route, in the main text outside loops and calls, when the
text holds no ``#`` (``FanucRunner.box_reader`` / ``box_run``).  ``tests/gcode/fanuc/test_box_run.py`` holds the
reader to the lanes and to the fast path.

Under one G68 rotation or G51 scaling (:func:`_read_transformed`, issue 36) the same lines are read as
``FanucInterpreter._transformed_motion`` moves them: the program point kept beside the machine point, each point
mapped as ``_transform_target`` maps it (``transform_points``), I/J arcs boxed on their mapped ends and centre;
``tests/gcode/fanuc/test_box_transforms.py`` holds it to the general path.
"""

from __future__ import annotations

import re
from fractions import Fraction

from ...motion import PLANE_AXES, SegmentKind
from .columns import SCALE, BoxRows, BoxSink, centre_arc_box, r_arc_box, widen_plane

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["read_box_run", "BOX_RUNS"]

#: Whether the runner reads plain runs on the box route with :func:`read_box_run` (tests turn it off).
BOX_RUNS = True

_UNIT = 10**SCALE
_ZERO_DIGITS = str.maketrans("123456789", "000000000")
#: a line after the first that starts with an N word (the layouts take N first only; ``"\n"`` first, not
#: ``^`` under ``re.M``: the search then looks for the newline, not a match at every offset), and its number
_NUMBERED = re.compile(r"\n[ \t]*N")
_FIRST_N = re.compile(r"[ \t]*N")
_N_WORD = re.compile(r"[ \t]*N[ \t]*(\d+)")
_WORD = re.compile(r"([A-Z])[ \t]*(-?0*)(\.?)(0*)[ \t]*")
#: integer digits of a length at most (coordinates stay far below the lanes' ``2**57`` at the scale)
_MAX_DIGITS = 7
_LINE, _RAPID, _ARC = SegmentKind.LINE, SegmentKind.RAPID, SegmentKind.ARC
_CENTRE = {"X": "I", "Y": "J", "Z": "K"}
_MAX_LAYOUTS = 4096
#: where a plane's layouts keep the axis words of each hole line's layout (:func:`_holes`)
_HOLE_WORDS = ("hole words",)
#: an arc inside the run's box (read_box_run: its box is not made) and the units its bounds may be rounded outward
_INSIDE = (0, 0, 0, 0)
_SLACK = 4
#: the motion of a G word's text the reader takes (G0-G3 with at most one leading zero)
_G = {"0": 0, "00": 0, "1": 10, "01": 10, "2": 20, "02": 20, "3": 30, "03": 30}


def _layout(key: str, index: dict[str, int], digits: int, plane: tuple[int, int, str, str]) -> tuple | None:
    """What a line of layout ``key`` holds in the plane ``(ia, ib, centre letter a, centre letter b)``, its
    numbers as slices of the line with its points removed: ``(g, f, straight, arc, r_arc)`` with ``g`` the slice of the
    G number (None: no G), ``f`` ``(slice, multiplier)`` of F or None, ``straight`` the axis words ``((slice,
    multiplier, axis index), ...)`` (None when the line has R, I, J or K: not a straight move), ``arc``
    ``(R's slice, its multiplier, centre a, centre b, word a's slice, its multiplier, word b's, its multiplier,
    the other axes' words)`` (a centre offset as F, None when absent; ``arc`` None when the line is no arc the lane
    takes in the plane) and ``r_arc``, the same arc's ``(R's slice, its multiplier, word a's slice, its
    multiplier, word b's, its multiplier)`` when it is an R arc with both words of the plane and no other axis
    (the form :func:`_lines` reads itself), else None; None for a line out of the subset (module docstring)."""
    pos, n = 0, len(key)
    if key[-1:] == "\r":  # a CR LF line end
        n -= 1
    while pos < n and key[pos] in " \t":
        pos += 1
    seen: set[str] = set()
    g = None
    axes = []
    other: dict[str, tuple[slice, int]] = {}
    first = True
    dots = 0  # points before pos
    while pos < n:
        m = _WORD.match(key, pos)
        if m is None:
            return None
        letter, whole, point, frac = m.groups()
        if letter in seen:
            return None
        seen.add(letter)
        a = m.start(2) - dots  # in the line without its points
        dots += len(point)
        b = m.end(4) - dots
        if len(whole.lstrip("-")) + len(frac) == 0:
            return None
        if letter == "N":
            if not first or point or frac or whole.startswith("-"):
                return None
        elif letter == "G":
            if point or frac or whole.startswith("-") or len(whole) > 2:
                return None
            g = slice(a, b)
        elif letter == "F":
            if whole.startswith("-") or len(frac) > SCALE or len(whole) > 9:
                return None
            other["F"] = (slice(a, b), 10 ** (SCALE - len(frac)))
        else:
            if not point or len(frac) > digits or len(whole.lstrip("-")) > _MAX_DIGITS:
                return None
            mult = 10 ** (SCALE - len(frac))
            i = index.get(letter)
            if i is not None:
                axes.append((slice(a, b), mult, i))
            elif letter in "RIJK":
                other[letter] = (slice(a, b), mult)
            else:
                return None
        first = False
        pos = m.end()
    if not axes:
        return None
    ia, ib, la, lb = plane
    words = tuple(axes)
    rijk = [c for c in "RIJK" if c in other]
    arc = r_arc = None
    if rijk and all(c in ("R", la, lb) for c in rijk) and ("R" in other) != (la in other or lb in other) \
            and any(i == ia or i == ib for _s, _m, i in words):
        wa = next(((sl, m) for sl, m, i in words if i == ia), (None, 0))
        wb = next(((sl, m) for sl, m, i in words if i == ib), (None, 0))
        r = other.get("R", (None, 0))
        helix = tuple(w for w in words if w[2] != ia and w[2] != ib)
        arc = (r[0], r[1], other.get(la), other.get(lb), wa[0], wa[1], wb[0], wb[1], helix)
        if r[0] is not None and wa[0] is not None and wb[0] is not None and not helix:
            r_arc = (r[0], r[1], wa[0], wa[1], wb[0], wb[1])
    return (g, other.get("F"), None if rijk else words, arc, r_arc)


def _takes(interp: Any, runner: Any) -> tuple[bool, bool] | None:
    """Whether the runner and the interpreter are in a state both plain lanes take lines in
    (``FanucInterpreter.box_lane_modes``): (straight moves, arcs) or None."""
    if not _runner_takes(interp, runner):
        return None
    modes: tuple[bool, bool] | None = interp.box_lane_modes()
    return modes


def _runner_takes(interp: Any, runner: Any) -> bool:
    """Whether the runner and the interpreter's sink let the reader take lines (:func:`_takes`)."""
    sink = interp.row_sink
    return not (type(sink) is not BoxSink or runner.modal_call is not None or runner.lane is None
                or runner.shape_codes or (runner.custom_g and not runner.custom_g.isdisjoint((0, 1, 2, 3)))
                or interp.segment_count < sink.start)


def _scaled(x: Any) -> int | None:
    x = Fraction(x)
    q, rem = divmod(x.numerator * _UNIT, x.denominator)
    return None if rem else q


class _Run:
    """The interpreter's state the reader keeps as integers at the scale (:func:`_start`), and its counts."""

    __slots__ = ("rows", "fresh", "p", "lo", "hi", "off", "tl", "feed", "feed0", "tol", "motion", "room", "plane",
                 "index", "layouts", "digits", "straight_ok", "arc_ok", "kinds", "g_seen", "taken", "last", "ctx")

    rows: Any
    fresh: bool
    p: list[int]
    lo: list[int]
    hi: list[int]
    off: list[int]
    tl: int
    feed: int
    feed0: int
    tol: int | None
    motion: int
    room: int
    plane: tuple[int, int, str, str]
    index: dict[str, int]
    layouts: dict[str, Any]
    digits: int
    straight_ok: bool
    arc_ok: bool
    kinds: list[int]
    g_seen: int
    taken: int
    last: tuple[int, int]
    ctx: tuple[list[int], list[int], list[int], list[int], int, int]  # p, lo, hi, off, ia, ib (for _arc)


def _start(runner: Any) -> _Run | None:
    """The state at the start of a run, None when the reader does not take it (module docstring)."""
    interp = runner.state
    modes = _takes(interp, runner)
    if modes is None:
        return None
    st = _Run()
    st.straight_ok, st.arc_ok = modes
    return st if _state(runner, interp, st) else None


def _state(runner: Any, interp: Any, st: _Run) -> bool:
    """``st`` filled with the interpreter's state at the scale (False: a number not at the scale, or too large)."""
    st.index = index = {name: i for i, name in enumerate(interp.axes) if name in "XYZ"}
    a_name, b_name, _n = PLANE_AXES[interp.plane]
    ia, ib = index.get(a_name), index.get(b_name)
    if ia is None or ib is None:
        return False
    st.plane = plane = (ia, ib, _CENTRE[a_name], _CENTRE[b_name])
    p: Any = [_scaled(v) for v in interp.pos]
    off: Any = [_scaled(v) for v in interp.off]
    tl, feed = _scaled(interp.tlo), _scaled(interp.feed) if interp.feed is not None else None
    tol = _scaled(interp.arc_tolerance) if interp.arc_rule == "fixed" else 0
    if None in p or None in off or tl is None or feed is None or tol is None or any(abs(o) >= 2**56 for o in off):
        return False
    st.p, st.off, st.tl, st.feed, st.feed0 = p, off, tl, feed, feed
    st.tol = tol if interp.arc_rule == "fixed" else None
    emitted = interp.emitted
    rows: Any = emitted[-1] if emitted else None
    st.rows = rows
    st.fresh = type(rows) is not BoxRows or rows.prev_end is not interp.pos or rows.full
    if st.fresh:
        st.lo, st.hi, st.room = p[:], p[:], interp.row_sink.max_rows
    else:
        st.lo, st.hi, st.room = rows.lo[:], rows.hi[:], rows.max_rows - rows.count
    st.ctx = (p, st.lo, st.hi, off, plane[0], plane[1])
    st.digits = runner.box_digits
    st.layouts = runner.box_layouts.setdefault(plane, {})
    st.motion = interp.motion
    st.kinds = [0, 0, 0, 0]  # motions by motion // 10 (G0, G1, G2, G3)
    st.g_seen = st.taken = 0
    st.last = (0, 0)
    return True


def read_box_run(runner: Any, text: str, pos: int, lineno: int) -> tuple[int, int, bool] | None:
    """Read the plain lines of ``text`` from offset ``pos`` (line ``lineno``) into the box of the interpreter's
    run, as the plain lanes would (module docstring): ``(next offset, next line number, whether the chunk is
    full)``, or None when the first line is not taken (nothing changed)."""
    if pos and text[pos - 1:pos] != "\n":
        # not a line's start (never asked so), or past the text's end: after a last line without a newline the
        # next offset is the text's length + 1, as ``StringSource.line_at`` gives it, and no line is left
        return None
    st = _start(runner)
    if st is None:
        if runner.state.prog is not None:  # a programmable transform is active
            return _read_transformed(runner, text, pos, lineno)
        return _read_holes(runner, text, pos, lineno)
    lines = runner.box_keys
    if lines is None or lines.text is not text:
        end = text.find("\n", pos)
        key = text[pos:end if end >= 0 else len(text)].translate(_ZERO_DIGITS)
        if not (st.layouts.get(key) or _miss(st, key)) and key.strip(" \t\r"):
            return None  # the first line is out of the subset: the text is not cut (a program it declines)
        lines = runner.box_keys = _Lines(text)
    first = lines.index(pos)
    pos, lineno, index = _lines(st, lines.keys, lines.dotless, pos, lineno, first)
    if not _close_run(runner, st, lines, first, pos, index):
        return None
    return _hand_back(runner, runner.state, st, pos, lineno)


def _cut(runner: Any, text: str) -> _Lines:
    """The runner's :class:`_Lines` of ``text``, cut now when it holds none of that text."""
    lines = runner.box_keys
    if lines is None or lines.text is not text:
        lines = runner.box_keys = _Lines(text)
    return lines  # type: ignore[no-any-return]


def _close_run(runner: Any, st: _Run, lines: _Lines, first: int, pos: int, index: int) -> bool:
    """After a run read lines of index ``first`` .. ``index - 1`` (``pos``: the next line's offset): where the next
    run starts looking (``_Lines.index``), and the last sequence number a macro reads (#4114), as the general path
    keeps it; False when the run took no line."""
    lines.pos, lines.at = pos, index
    if not st.taken:
        return False
    number = lines.last_number(first, index)
    if number is not None:
        runner.lane_number(number)
    return True


def _read_holes(runner: Any, text: str, pos: int, lineno: int) -> tuple[int, int, bool] | None:
    """Hole lines under a drilling cycle (a line of X and Y words, a leading N) read into the run's box, each hole
    the rows of :func:`~nczones.gcode.fanuc.holes.fanuc_holes` (the interpreter's ``_fanuc_cycle``): ``(next
    offset, next line number, whether the chunk is full)``, or None when the first line is not taken.

    Every row of a hole is a straight move (a rapid: each axis monotone) or a dwell, from the hole's X and Y at
    the template's levels: its motion lies in the box of the hole's X, Y and the least and greatest level, and
    the move to the next hole (at the top, the level the last row ends at) in the box of the two holes'.  The
    lines are :func:`_layout`'s with only X and Y words; inch input, another plane or any state
    ``fanuc_holes`` does not mirror is not taken."""
    from .holes import fanuc_holes

    interp = runner.state
    sink = interp.row_sink
    if type(sink) is not BoxSink or runner.modal_call is not None or runner.lane is None or runner.shape_codes \
            or interp.segment_count < sink.start or interp.ended or interp.inch or not interp.fused_lane:
        return None
    plan = fanuc_holes(interp)
    if plan is None:
        return None
    st = _Run()
    st.straight_ok = st.arc_ok = False
    scaled = [_scaled(z) for z in plan[1].values()]
    levels = [z for z in scaled if z is not None and abs(z) < 2**56]
    if len(levels) != len(scaled) or not _state(runner, interp, st):
        return None
    lines = _cut(runner, text)
    first = lines.index(pos)
    holes, pos, lineno = _holes(st, lines, len(plan[2]), pos, lineno, first)
    st.taken = holes
    if not _close_run(runner, st, lines, first, pos, first + holes):
        return None
    iz = st.index["Z"]
    st.lo[iz] = min(st.lo[iz], *levels)
    st.hi[iz] = max(st.hi[iz], *levels)
    interp.note_assumed(plan[5])
    counts = interp.kind_counts
    for kind, *_rest in plan[2]:
        counts[kind] += holes
    return _hand_back(runner, interp, st, pos, lineno, holes * len(plan[2]))


def _holes(st: _Run, lines: _Lines, per: int, pos: int, lineno: int, i: int) -> tuple[int, int, int]:
    """Read hole lines of ``per`` rows each from ``pos`` (line index ``i``) into ``st``'s position and box, as many
    as the chunk has room for: (holes, next offset, next line number)."""
    keys, dotless = lines.keys, lines.dotless
    ix, iy = st.index["X"], st.index["Y"]
    p, lo, hi, off = st.p, st.lo, st.hi, st.off
    layouts: Any = st.layouts
    cache = layouts.setdefault(_HOLE_WORDS, {})  # (a tuple: never a line's key)
    most = min(st.room // per, len(keys) - i)
    holes = last_pos = last_no = 0
    while holes < most:
        key = keys[i]
        words = cache.get(key)
        if words is None:
            got = _miss(st, key)
            ok = got and got[0] is None and got[1] is None and got[2] is not None \
                and all(a == ix or a == iy for _s, _m, a in got[2])
            words = got[2] if ok else ()
            if len(cache) < _MAX_LAYOUTS:
                cache[key] = words
        if not words:
            break
        line = dotless[i]
        for sl, m, a in words:
            v = int(line[sl]) * m + off[a]
            p[a] = v
            if v < lo[a]:
                lo[a] = v
            elif v > hi[a]:
                hi[a] = v
        holes += 1
        last_pos, last_no = pos, lineno
        pos, lineno, i = pos + len(key) + 1, lineno + 1, i + 1
    st.last = (last_pos, last_no)
    return holes, pos, lineno


#: :data:`_ZERO_DIGITS` for bytes
_ZERO_BYTES = bytes.maketrans(b"123456789", b"000000000")


def _keys_dotless(text: str) -> tuple[list[str], list[str]]:
    r"""The lines of ``text`` with their digits zeroed (the layouts' keys) and without their points: an ASCII text
    (most) by the bytes' ``translate`` and ``replace``, which give the same lines (the digits and the point are
    ASCII) for a quarter of ``str.translate``'s work and half of ``str.replace``'s (line44: some 3M instructions
    on 10,000 R arcs).

    >>> _keys_dotless("G2 X1.5 R2.\nM30"), _keys_dotless("(é) X9.")
    ((['G0 X0.0 R0.', 'M00'], ['G2 X15 R2', 'M30']), (['(é) X0.'], ['(é) X9']))
    """
    if text.isascii():
        raw = text.encode("ascii")
        return (raw.translate(_ZERO_BYTES).decode("ascii").split("\n"),
                raw.replace(b".", b"").decode("ascii").split("\n"))
    return text.translate(_ZERO_DIGITS).split("\n"), text.replace(".", "").split("\n")


class _Lines:
    """The main text cut into its lines once (``str.split``, not a slice a line): each line's layout (its digits
    zeroed, :func:`_layout`'s key) and the line with its points removed (where the layout's slices read), and
    the index of the line at offset :attr:`pos` (where the last run ended: the next usually starts there)."""

    __slots__ = ("text", "keys", "dotless", "pos", "at", "numbered")

    def __init__(self, text: str) -> None:
        self.text = text
        self.keys, self.dotless = _keys_dotless(text)
        self.pos = self.at = 0
        # a line may start with an N word (the first line, or another)
        self.numbered = "N" in text and (_FIRST_N.match(text) is not None or _NUMBERED.search(text) is not None)

    def last_number(self, first: int, end: int) -> Fraction | None:
        """The N of the last line of index ``first`` .. ``end - 1`` that has one (the layout's N word comes
        first, a whole number: :func:`_layout`), None when none has."""
        if self.numbered:
            keys = self.keys
            for j in range(end - 1, first - 1, -1):
                if keys[j].lstrip(" \t")[:1] == "N":
                    m = _N_WORD.match(self.dotless[j])
                    if m is not None:
                        return Fraction(int(m.group(1)))
        return None

    def index(self, pos: int) -> int:
        """The index of the line starting at offset ``pos``: counted from the last run's end (runs read forward)."""
        if pos >= self.pos:
            return self.at + self.text.count("\n", self.pos, pos)
        return self.at - self.text.count("\n", pos, self.pos)


def _miss(st: _Run, key: str) -> tuple:
    """The layout of ``key`` not met before in this plane (kept), or kept as ``()``: a line out of the subset."""
    got = st.layouts.get(key)
    if got is not None:
        return got  # type: ignore[no-any-return]
    got = None if key.startswith("\ufeff") else _layout(key, st.index, st.digits, st.plane)
    got = got or ()
    if len(st.layouts) < _MAX_LAYOUTS:
        st.layouts[key] = got
    return got


def _lines(st: _Run, keys: list[str], dotless: list[str], pos: int, lineno: int, i: int) -> tuple[int, int, int]:
    """Read lines from ``pos`` (the line of index ``i`` in ``keys``, the lines' layouts, and ``dotless``, the
    lines without their points: :class:`_Lines`) while they are in the subset (module docstring): the next offset,
    line number and index; the state, box and counts in ``st``.

    The loop counts lines by their index only (the offsets and line numbers are summed once after it,
    :func:`_ended`).  It is a ``while True``: the loop's back edge is a JUMP_BACKWARD, which counts towards
    CPython 3.11's warm-up of the code (``while cond:`` ends in POP_JUMP_BACKWARD_IF_TRUE, which does not): the
    loop is specialized after 8 lines, not after 8 calls (a 10,000-line run is 10 calls).

    An R arc with both words of the plane and no other axis (its layout's ``r_arc``) is read here, not by
    :func:`_arc`: the same steps written out (the per-line cost of the R-arc programs, issue 36), its inside test
    tighter for a minor arc (``R > 0``) than :func:`_arc`'s diameter test, which a major arc keeps.
    A minor arc lies within half its chord ``h`` of the chord's midpoint ``M``: for a point ``P`` of the circle
    (centre at distance ``d`` from ``M``, angle ``t`` between ``CP`` and ``CM``), ``|PM|**2 = r**2 + d**2 - 2 r d
    cos t``, and the minor arc has ``cos t >= d / r`` (its ends have equality), so ``|PM|**2 <= r**2 - d**2 =
    h**2``; with ``h <= (|dx| + |dy|) / 2`` its ``a`` lies in ``[min a - |dy| / 2, max a + |dy| / 2]``, and
    ``r_arc_box``'s bounds (outward by at most a unit) within :data:`_SLACK` of that: fewer arcs need their box.
    An offset 0 is not added to an end (a sum of large integers is a new object)."""
    p, lo, hi, off, layouts, gvalues = st.p, st.lo, st.hi, st.off, st.layouts, _G
    motion, feed, kinds, straight_ok, arc_ok = st.motion, st.feed, st.kinds, st.straight_ok, st.arc_ok
    ia, ib = st.plane[0], st.plane[1]
    oa, ob = off[ia], off[ib]
    first, g_seen, blanks = i, 0, 0
    if feed < 0:
        return pos, lineno, i  # (the lanes' decline of a negative feed; an F word read here is never negative)
    lim = len(keys) - (not keys[-1])  # past the lines (an empty last line starts at the text's end: none)
    stop = min(i + st.room, lim)  # and past the room
    while True:  # (not ``while cond:``, docstring)
        if i >= stop:
            break
        key = keys[i]
        got = layouts.get(key) or _miss(st, key)
        if not got:  # out of the subset
            if key.strip(" \t\r"):
                break
            i += 1  # a blank line: no block (plain_first), no room taken
            blanks += 1
            stop = min(stop + 1, lim)
            continue
        g, f, words, arc, r_arc = got
        line = dotless[i]
        mo = motion if g is None else gvalues.get(line[g], -1)
        if f is None:
            fv = feed
        else:
            fv = int(line[f[0]]) * f[1]  # (never negative: the layout has no sign in F)
            if not fv:
                break  # F 0 (the lanes' decline)
        if mo < 0:
            break  # another G
        if mo < 20:
            if words is None or not straight_ok or (mo == 10 and fv == 0):
                break  # R, I, J, K in G0/G1; G1 without a feed (check_feed): the general path
            _straight(line, words, p, lo, hi, off)
        elif r_arc is not None and fv and arc_ok:  # _arc's steps for an R arc in the plane, written out
            r, rm, wa, am, wb, bm = r_arc
            sa, sb = p[ia], p[ib]
            ea = int(line[wa]) * am + oa if oa else int(line[wa]) * am
            eb = int(line[wb]) * bm + ob if ob else int(line[wb]) * bm
            rv = int(line[r]) * rm
            if ea >= sa:  # the ends' least and greatest (statements: no tuple is made)
                a0, a1 = sa, ea
            else:
                a0, a1 = ea, sa
            if eb >= sb:
                b0, b1 = sb, eb
            else:
                b0, b1 = eb, sb
            adx, ady = a1 - a0, b1 - b0
            if rv > 0:  # a minor arc lies within half its chord of the chord's midpoint: |dy| / 2 of the ends in a
                ar = rv
                w = (ady >> 1) + _SLACK
                la, ua = a0 - w, a1 + w
                w = (adx >> 1) + _SLACK
                lb, ub = b0 - w, b1 + w
            else:  # any arc lies within 2|R| (a diameter) of both its ends
                ar = -rv
                w = 2 * ar + _SLACK
                la, ua, lb, ub = a1 - w, a0 + w, b1 - w, b0 + w
            # inside the run's box, for an arc r_arc_box takes (a chord of at most sqrt(3)|R|, _arc's test; |dx|,
            # |dy| <= |R| and not both 0 gives 0 < l2 <= 2 R**2): the box stays as it is (module docstring)
            if not (la >= lo[ia] and ua <= hi[ia] and lb >= lo[ib] and ub <= hi[ib] and (
                    (adx <= ar and ady <= ar and (adx or ady)) or 0 < adx * adx + ady * ady <= 3 * ar * ar)) \
                    and not widen_plane(lo, hi, ia, ib, r_arc_box(sa, sb, ea, eb, rv, mo == 20)):
                break
            p[ia], p[ib] = ea, eb
        elif arc is None or fv == 0 or not arc_ok or not _arc(st, line, arc, mo == 20):
            break
        kinds[mo // 10] += 1
        motion, feed = mo, fv
        if g is not None:
            g_seen += 1
        i += 1
    st.motion, st.feed, st.g_seen = motion, feed, g_seen
    return _ended(st, keys, first, i, blanks, pos, lineno)


def _ended(st: _Run, keys: list[str], first: int, i: int, blanks: int, pos: int,
           lineno: int) -> tuple[int, int, int]:
    """After :func:`_lines` read from the line of index ``first`` (offset ``pos``, number ``lineno``) to index
    ``i``, ``blanks`` of them blank: the lines taken and the last one's offset and number into ``st``; the next
    offset, number and index.  A line after the last taken is blank (a taken line has an axis word)."""
    nxt = pos + len("\n".join(keys[first:i])) + 1 if i > first else pos  # (C loops, not one a line)
    st.taken = taken = i - first - blanks
    if taken:
        j = i - 1
        at = nxt - len(keys[j]) - 1
        while not keys[j].strip(" \t\r"):
            j -= 1
            at -= len(keys[j]) + 1
        st.last = (at, lineno + j - first)
    return nxt, lineno + i - first, i


def _straight(line: str, words: tuple, p: list[int], lo: list[int], hi: list[int], off: list[int]) -> None:
    """A straight move's end into the position and the box (``BoxRows.add``)."""
    for sl, m, i in words:
        v = int(line[sl]) * m + off[i]
        p[i] = v
        if v < lo[i]:
            lo[i] = v
        elif v > hi[i]:
            hi[i] = v


def _arc(st: _Run, line: str, arc: tuple, cw: bool) -> bool:
    """An arc into the position and the box as ``BoxRows.add_arc`` (True), or False (nothing changed) when the
    box functions leave it to the interpreter."""
    r, rm, ca, cb, wa, am, wb, bm, helix = arc
    p, lo, hi, off, ia, ib = st.ctx
    sa = p[ia]
    sb = p[ib]
    ea = int(line[wa]) * am + off[ia] if wa is not None else sa
    eb = int(line[wb]) * bm + off[ib] if wb is not None else sb
    box: Any
    if r is not None:
        rv = int(line[r]) * rm
        dx = ea - sa
        dy = eb - sb
        l2 = dx * dx + dy * dy
        # an arc r_arc_box takes (far from a half circle): every point of it (and its box, rounded outward) lies
        # within 2|R| of both ends; inside the run's box, it leaves the box as it is
        w = 2 * (rv if rv > 0 else -rv) + _SLACK
        if 0 < l2 and l2 <= 3 * rv * rv and (sa if sa > ea else ea) - w >= lo[ia] \
                and (sa if sa < ea else ea) + w <= hi[ia] and (sb if sb > eb else eb) - w >= lo[ib] \
                and (sb if sb < eb else eb) + w <= hi[ib]:
            box = _INSIDE
        else:
            box = r_arc_box(sa, sb, ea, eb, rv, cw)
    else:
        box = _centre_box(st, line, ca, cb, sa, sb, ea, eb, cw)
    if box is None:
        return False
    p[ia], p[ib] = ea, eb
    if helix:
        _straight(line, helix, p, lo, hi, off)
    if box is not _INSIDE:
        widen_plane(lo, hi, ia, ib, box)
    return True


def _centre_box(st: _Run, line: str, ca: Any, cb: Any, sa: int, sb: int, ea: int, eb: int, cw: bool) -> Any:
    """The box of an I/J/K arc (``centre_arc_box``), :data:`_INSIDE` when the circle's box is inside the run's."""
    _p, lo, hi, _off, ia, ib = st.ctx
    xa = sa + int(line[ca[0]]) * ca[1] if ca is not None else sa
    xb = sb + int(line[cb[0]]) * cb[1] if cb is not None else sb
    dx = sa - xa
    dy = sb - xb
    l2 = dx * dx + dy * dy  # the radius squared, at the start
    dx = ea - xa
    dy = eb - xb
    # ends at one distance from the centre: the arc lies in the circle's box, the one centre_arc_box takes its
    # extremes from (the root rounded up: one unit); inside the run's box, nothing to add
    w = min(xa - lo[ia], hi[ia] - xa, xb - lo[ib], hi[ib] - xb) - 1
    if 0 < l2 and l2 == dx * dx + dy * dy and w >= 0 and w * w >= l2:
        return _INSIDE
    return centre_arc_box(sa, sb, ea, eb, xa, xb, cw, st.tol)


def _hand_back(runner: Any, interp: Any, st: _Run, pos: int, lineno: int,
               motions: int | None = None) -> tuple[int, int, bool]:
    """The state after the run, as the lanes leave it (module docstring); ``motions``: the run's motions when a
    line is not one (:func:`_read_holes`)."""
    from ..lexer import make_span

    end = tuple(Fraction(v, _UNIT) for v in st.p)
    rows = st.rows
    if st.fresh:
        rows = BoxRows(interp.pos, st.lo, interp.file, interp.row_sink.max_rows)
        interp.emitted.append(rows)
    rows.lo, rows.hi = st.lo, st.hi
    if interp.tlo is not rows.tl:
        rows.tl = interp.tlo
        rows.tls.add(st.tl)
    taken = st.taken
    rows.count += taken if motions is None else motions
    if rows.count >= rows.max_rows:
        rows.full = True
    rows.prev_end = end
    last_pos, last_no = st.last
    text = runner.main.src.text
    line = text[last_pos:text.find("\n", last_pos) % (len(text) + 1)].removesuffix("\r")
    index = runner.index + taken - 1
    runner.index = index + 1
    runner.started = runner.ran = True
    interp.block_index = index
    interp.span = make_span(interp.file, last_no, 1, len(line) + 1, line)
    interp.blocks += taken
    if st.g_seen:
        interp.cycle_il = None
        interp.last_cycle = None
    interp.motion = st.motion
    if st.feed != st.feed0:
        interp.feed = Fraction(st.feed, _UNIT)
    counts = interp.kind_counts
    g0, g1, g2, g3 = st.kinds
    for kind, k in ((_RAPID, g0), (_LINE, g1), (_ARC, g2 + g3)):
        if k:
            counts[kind] += k
    interp.segment_count += taken if motions is None else motions
    interp.pos = end
    interp.prerotation_xy_next = None
    return pos, lineno, rows.full or len(interp.emitted) >= interp.chunk_size


def _read_transformed(runner: Any, text: str, pos: int, lineno: int) -> tuple[int, int, bool] | None:
    """Plain lines under one G68 rotation or G51 scaling read into the run's box as
    ``FanucInterpreter._transformed_motion`` moves them: ``(next offset, next line number, whether the chunk is
    full)``, or None when the first line is not taken (nothing changed).

    The state is the one ``FanucInterpreter.box_transform`` gives (the straight lane's but the transform: G90, metric,
    no cycle, compensation or tool length shift, not the first move after a transform's block, no tracked ranges,
    no mode left to note as assumed).  The program point is kept as scaled integers beside the machine point; each
    line's words set the program point and the axes they move are mapped by
    :class:`~nczones.gcode.fanuc.transform_points.PointMap` (both plane axes of the rotation when either is
    named), plus the offsets, as ``_transform_target`` maps them.  An axis a line does not name keeps its program
    and machine values: the run starts only where the machine point is the transform of the program point plus
    the offsets (computed exactly by ``transforms.scale`` / ``rotate``), so the general path's
    ``_unnamed_axis_moves`` finds nothing to move there.  A straight move widens the box by its end; an I/J arc in
    the plane (``_transformed_arc``: the rotation's plane, equal scale factors on the plane's axes, ends at one
    distance from the centre in the program) maps its end and centre and is boxed by ``centre_arc_box`` on the
    machine integers (the rounding's spiral: the larger radius and twice the roots' difference, as the arc's
    segment is boxed), its direction reversed by an odd count of negative factors.  A point the rotation finds
    uncertain, an R arc, and every line :func:`_lines` would leave end the run: the general path decides them."""
    from .transform_points import PointMap

    interp = runner.state
    if not _runner_takes(interp, runner):
        return None
    xf = interp.box_transform()
    if xf is None:
        return None
    pm = PointMap.of(xf, SCALE)
    st = _Run()
    st.straight_ok = st.arc_ok = True
    if pm is None or not _state(runner, interp, st) or st.feed < 0:
        return None  # (a negative feed: the lanes' decline, as _lines)
    prog: Any = [_scaled(v) for v in interp.prog]
    if None in prog or not _mapped_here(interp, xf):
        return None
    lines = _cut(runner, text)
    first = lines.index(pos)
    pos, lineno, index = _xlines(st, pm, prog, lines, pos, lineno, first)
    if not _close_run(runner, st, lines, first, pos, index):
        return None
    interp.prog = [Fraction(v, _UNIT) for v in prog]
    return _hand_back(runner, interp, st, pos, lineno)


def _mapped_here(interp: Any, xf: tuple) -> bool:
    """Whether the machine point is the program point transformed (exactly: ``transforms``) plus the offsets."""
    from .transforms import PointNotCertain, rotate, scale

    rotation, scaling, step = xf
    try:
        q = rotate(rotation, list(interp.prog), step) if rotation is not None else scale(scaling, interp.prog, step)
    except PointNotCertain:
        return False
    return all(q[i] + o == v for i, (o, v) in enumerate(zip(interp.off, interp.pos)))


def _xlines(st: _Run, pm: Any, prog: list[int], lines: _Lines, pos: int, lineno: int,
            i: int) -> tuple[int, int, int]:
    """:func:`_lines` for :func:`_read_transformed`: lines read while they are taken; the next offset, line number
    and index; the state, box and counts in ``st``, the program point in ``prog``.  A straight move is the
    transform's mover's (:func:`_rotation_mover`, :func:`_scaling_mover`: the map written out, per-line cost)."""
    keys, dotless, n = lines.keys, lines.dotless, len(lines.text)
    layouts, gvalues = st.layouts, _G
    motion, feed, room, kinds = st.motion, st.feed, st.room, st.kinds
    arcs = _arc_flip(pm, st.plane[0], st.plane[1])
    plans: Any = None
    plan_of: Any = _rotation_plan
    if pm.rot is not None:
        move = _rotation_mover(st, pm, prog)
        plans = layouts.setdefault(("rotation", pm.ia, pm.ib), {})  # type: ignore[call-overload]  # (a tuple key)
    else:
        move = _scaling_mover(st, pm, prog)
    taken = g_seen = last_pos = last_no = 0
    while True:
        if taken >= room or pos >= n:
            break
        key = keys[i]
        end = pos + len(key)
        got = layouts.get(key) or _miss(st, key)
        if not got:
            if key.strip(" \t\r"):
                break
            pos, lineno, i = end + 1, lineno + 1, i + 1  # a blank line: no block
            continue
        g, f, words, arc, _r_arc = got
        line = dotless[i]
        mo = motion if g is None else gvalues.get(line[g], -1)
        fv = feed if f is None else int(line[f[0]]) * f[1]
        if mo < 0 or (f is not None and not fv):
            break  # another G; F 0
        if mo < 20:
            if words is None or (mo == 10 and fv == 0):
                break
            if plans is not None:
                words = plans.get(key) or plan_of(plans, key, words, pm)
            if not move(line, words):
                break
        elif arc is None or arc[0] is not None or fv == 0 or arcs is None \
                or not _xarc(st, pm, prog, line, arc, (mo == 20) != arcs):
            break  # an R arc, a plane or factors the lane does not map, an arc the general path decides
        kinds[mo // 10] += 1
        motion, feed = mo, fv
        if g is not None:
            g_seen += 1
        last_pos, last_no = pos, lineno
        taken += 1
        pos, lineno, i = end + 1, lineno + 1, i + 1
    st.motion, st.feed, st.taken, st.g_seen = motion, feed, taken, g_seen
    if taken:
        st.last = (last_pos, last_no)
    return pos, lineno, i


def _rotation_plan(plans: dict, key: str, words: tuple, pm: Any) -> tuple:
    """How :func:`_rotation_mover` reads a straight layout's ``words``: ``(slice of the rotation's first axis,
    its multiplier, the second's, its multiplier, the other axes' words)`` (a slice None: not named); kept."""
    wa = next(((sl, m) for sl, m, k in words if k == pm.ia), (None, 0))
    wb = next(((sl, m) for sl, m, k in words if k == pm.ib), (None, 0))
    plan = (wa[0], wa[1], wb[0], wb[1], tuple(w for w in words if w[2] != pm.ia and w[2] != pm.ib))
    if len(plans) < _MAX_LAYOUTS:
        plans[key] = plan
    return plan


def _rotation_mover(st: _Run, pm: Any, prog: list[int]) -> Any:
    """``move(line, plan)``: a straight move's words (:func:`_rotation_plan`) into the program point, the machine
    point and the box, False (nothing changed) when the rotated point is uncertain (``PointMap.rotated``)."""
    p, lo, hi, off = st.p, st.lo, st.hi, st.off
    ia, ib, rotated = pm.ia, pm.ib, pm.rotated
    oa, ob = off[ia], off[ib]

    def move(line: str, plan: tuple) -> bool:
        wa, ma, wb, mb, others = plan
        if wa is not None or wb is not None:
            a = int(line[wa]) * ma if wa is not None else prog[ia]
            b = int(line[wb]) * mb if wb is not None else prog[ib]
            got = rotated(a, b)
            if got is None:
                return False
            ma, mb = got
            ma += oa
            mb += ob
            prog[ia] = a
            prog[ib] = b
            p[ia] = ma
            if ma < lo[ia]:
                lo[ia] = ma
            elif ma > hi[ia]:
                hi[ia] = ma
            p[ib] = mb
            if mb < lo[ib]:
                lo[ib] = mb
            elif mb > hi[ib]:
                hi[ib] = mb
        if others:
            for sl, m, k in others:
                w = int(line[sl]) * m
                prog[k] = w
                _box_at(p, lo, hi, k, w + off[k])
        return True

    return move


def _box_at(p: list[int], lo: list[int], hi: list[int], k: int, v: int) -> None:
    """Axis ``k`` of the machine point to ``v``, the box widened to it."""
    p[k] = v
    if v < lo[k]:
        lo[k] = v
    elif v > hi[k]:
        hi[k] = v


def _scaling_mover(st: _Run, pm: Any, prog: list[int]) -> Any:
    """``move(line, words)``: a straight move's layout words into the program point, the machine point and the
    box; ``PointMap.scaled``'s steps written out (exact integers: never uncertain)."""
    p, lo, hi, off, step = st.p, st.lo, st.hi, st.off, pm.st
    # (centre, c (fd - fn), 2 fd st, fd st, fn) by axis: N = c fd + fn (v - c) = fn v + c (fd - fn)
    axes = [None if a is None else (a[0], a[0] * (a[2] - a[1]), 2 * a[3], a[3], a[1]) for a in pm.axes]

    def move(line: str, words: tuple) -> bool:
        for sl, m, k in words:
            v = int(line[sl]) * m
            prog[k] = v
            ax = axes[k]
            if ax is not None and v != ax[0]:
                _c, base, den2, den, fn = ax
                nv = fn * v + base
                v = ((2 * nv + den) // den2 if nv >= 0 else -((den - 2 * nv) // den2)) * step
            v += off[k]
            p[k] = v
            if v < lo[k]:
                lo[k] = v
            elif v > hi[k]:
                hi[k] = v
        return True

    return move


def _arc_flip(pm: Any, ia: int, ib: int) -> bool | None:
    """Whether arcs in the plane ``ia``, ``ib`` change direction under ``pm`` (an odd count of negative factors),
    None when ``_transformed_arc`` leaves them (another plane than the rotation's, unequal factors: an ellipse)."""
    if pm.rot is not None:
        return False if {pm.rot.ia, pm.rot.ib} == {ia, ib} else None
    fa: Fraction = pm.factor(ia)
    fb: Fraction = pm.factor(ib)
    if abs(fa) != abs(fb):
        return None
    return (fa < 0) != (fb < 0)


def _xpoint(pm: Any, prog: list[int], new: dict[int, int], off: list[int]) -> dict[int, int] | None:
    """The machine coordinates (by axis index) the program point ``prog`` with the words ``new`` moves: each
    named axis, and both plane axes of a rotation when either is named; None when the point is uncertain."""
    rot = pm.rot
    out = {}
    for k, v in new.items():
        out[k] = pm.scaled(k, v) + off[k]
    if rot is not None and (rot.ia in new or rot.ib in new):
        ia, ib = rot.ia, rot.ib
        got = pm.rotated(new.get(ia, prog[ia]), new.get(ib, prog[ib]))
        if got is None:
            return None
        out[ia], out[ib] = got[0] + off[ia], got[1] + off[ib]
    return out


def _xarc(st: _Run, pm: Any, prog: list[int], line: str, arc: tuple, cw: bool) -> bool:
    """An I/J arc under the transform (its machine direction ``cw``) into the program point, the position and the
    box (:func:`_read_transformed`), False (nothing changed) when the general path must decide it."""
    _r, _rm, ca, cb, wa, am, wb, bm, helix = arc
    p, lo, hi, off, ia, ib = st.ctx
    sa, sb = prog[ia], prog[ib]
    new = {i: int(line[sl]) * m for sl, m, i in helix}
    ea = new[ia] = int(line[wa]) * am if wa is not None else sa
    eb = new[ib] = int(line[wb]) * bm if wb is not None else sb
    xa = sa + int(line[ca[0]]) * ca[1] if ca is not None else sa
    xb = sb + int(line[cb[0]]) * cb[1] if cb is not None else sb
    r0 = (sa - xa) ** 2 + (sb - xb) ** 2
    if r0 == 0 or r0 != (ea - xa) ** 2 + (eb - xb) ** 2:
        return False  # a zero radius (GC304), a spiral in the program (the tolerance's test): the general path
    moved = _xpoint(pm, prog, new, off)
    centre = _xpoint(pm, prog, {ia: xa, ib: xb}, off)
    if moved is None or centre is None:
        return False
    box = centre_arc_box(p[ia], p[ib], moved[ia], moved[ib], centre[ia], centre[ib], cw, 4 * pm.st)
    if box is None:
        return False
    widen_plane(lo, hi, ia, ib, box)
    for k, v in new.items():
        prog[k] = v
    for k, v in moved.items():
        _box_at(p, lo, hi, k, v)
    return True
