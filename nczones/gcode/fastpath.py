"""Vectorized fast path for CAM-style G-code (DESIGN §9).

CAM output is mostly runs of lines such as ``G1 X12.5 Y-3.25 F800`` or
``X12.6 Y-3.2`` (modal words) or ``G2 X.. Y.. I.. J..``.  This module reads
such runs with numpy at the byte level, straight into column
:class:`~nczones.motion.MotionChunk` values of scaled ``int64``; every other
line (and any run it cannot prove it handles exactly like the full
interpreter) goes through the language layer and the full
:class:`~nczones.gcode.interpreter.Interpreter`, which keeps the modal state
across both paths.

A line is *simple* when, outside comments and blanks, it holds only words
``G0``-``G3`` (at most one), axis words of the machine, ``I J K`` (with an
arc), ``F`` and a leading ``N``, each with a plain decimal literal, and its
comments are not magic comments.  A program with ``#``, ``[``, ``O`` words
or ``/`` anywhere is run entirely by the full path (its control flow needs
the language layer); so are runs shorter than :data:`MIN_RUN` lines.

Invariants
----------
* Identical segments: the fast path produces the same segments (kinds,
  exact coordinates, centres, feeds, line and block numbers) as the full
  path; ``tests/gcode/test_fastpath.py`` checks this on the corpus.
* Exact: numbers are parsed digit by digit into integers; the common scale
  ``10**s`` is the largest number of decimals in the run (plus one for
  inches, 25.4 = 254/10).  Magnitudes are checked before any product so no
  ``int64`` ever wraps; a run that could overflow goes to the full path.
* Arc radius tolerance: a float64 screen decides only with a margin far
  above its rounding error; undecided arcs are checked with exact Python
  integers, and a run with a bad arc goes to the full path, which raises
  the diagnostic.
"""

from __future__ import annotations

import re
from dataclasses import replace
from fractions import Fraction

import numpy as np

from ..errors import GcodeError, InputError
from ..motion import PLANE_AXES, MotionChunk, Plane, SegmentKind

__all__ = ["run_with_fastpath", "MIN_RUN"]

#: Shorter runs of simple lines are left to the full interpreter.
MIN_RUN = 64
_MAX_SCALE = 9
_LIMIT = 2**62

_NL, _CR, _SP, _TAB = 10, 13, 32, 9
_LP, _RP, _SEMI = ord("("), ord(")"), ord(";")
_MAGIC = re.compile(r"\(\s*(MSG|DEBUG|PRINT|LOG|PROBE|ABORT)", re.I)


def run_with_fastpath(interp):
    """Yield the chunks of ``interp`` (an Interpretation), fast where possible."""
    from . import _blocks

    it = interp.interpreter
    text = interp.text
    text = _truncate_at_percent(text)
    data = text.encode("utf-8", errors="surrogateescape")
    lines_info = _classify(data, it)
    if lines_info is None:
        yield from it.run(_blocks(text, interp.file, interp.block_delete, it))
        return
    simple, starts, ends_, code = lines_info
    nlines = len(starts)
    i = 0
    block_counter = [0]
    while i < nlines and not it.ended:
        if simple[i]:
            j = i
            while j < nlines and simple[j]:
                j += 1
            if j - i >= MIN_RUN and _state_ok(it):
                chunk = _fast_run(interp, data, starts, ends_, code, i, j, block_counter)
                if chunk is not None:
                    if len(chunk):
                        yield chunk
                    i = j
                    continue
            # fall through: full path for this run
        j = i + 1
        while j < nlines and not (simple[j] and _run_len(simple, j) >= MIN_RUN):
            j += 1
        yield from _full_piece(interp, data, starts, ends_, i, j, block_counter)
        i = j


def _truncate_at_percent(text: str) -> str:
    """A ``%`` line after the first line with code ends the program."""
    if "%" not in text:
        return text
    seen_code = False
    pos = 0
    for line in text.splitlines(keepends=True):
        body = re.sub(r"\([^)]*\)|;.*", "", line).strip()
        if body.startswith("%"):
            if seen_code:
                return text[:pos]
        elif body:
            seen_code = True
        pos += len(line)
    return text


def _run_len(simple, j):
    k = j
    n = len(simple)
    while k < n and simple[k] and k - j < MIN_RUN:
        k += 1
    return k - j


def _state_ok(it) -> bool:
    return (not it.unsupported and it.motion in (None, 0, 10, 20, 30) and not it.comp_just_off
            and not it.comp_on and not it.track)


def _full_piece(interp, data, starts, ends_, i, j, block_counter):
    """Run lines i..j-1 through the language layer and the interpreter."""
    from . import _blocks

    it = interp.interpreter
    piece = data[starts[i]:ends_[j - 1]].decode("utf-8", errors="surrogateescape")
    offset = i  # line numbers inside the piece start at 1

    from .interpreter import Unsupported
    from .expr import Parameters
    from .program import UnsupportedGcode, iter_blocks

    params = Parameters()
    it.bind_parameters(params)

    def shifted():
        try:
            for b in iter_blocks(piece, file=interp.file, params=params, block_delete=interp.block_delete):
                span = replace(b.span, line=b.span.line + offset)
                words = tuple(replace(w, span=replace(w.span, line=w.span.line + offset)) for w in b.words)
                nb = replace(b, words=words, span=span, index=block_counter[0])
                block_counter[0] += 1
                yield nb
        except UnsupportedGcode as exc:
            d = exc.diagnostic
            span = replace(d.span, line=d.span.line + offset) if d.span is not None else None
            it.unsupported.append(Unsupported(d.code, d.message, span))

    try:
        yield from it.run(shifted())
    except InputError as exc:
        diags = [replace(d, span=replace(d.span, line=d.span.line + offset)) if d.span is not None else d
                 for d in exc.diagnostics]
        raise GcodeError(diags) from None


# --------------------------------------------------------------------------- classification


def _classify(data: bytes, it):
    """Per line: simple or not; line byte ranges; the code bytes (comments/blanks removed)."""
    b = np.frombuffer(data, dtype=np.uint8)
    if b.size == 0:
        return None
    nl = np.flatnonzero(b == _NL)
    starts = np.concatenate(([0], nl + 1))
    ends_ = np.concatenate((nl, [b.size]))
    if starts[-1] >= b.size:
        starts, ends_ = starts[:-1], ends_[:-1]
    nlines = len(starts)
    line_of = np.zeros(b.size, dtype=np.int64)
    line_of[nl[nl + 1 < b.size] + 1] = 1
    line_of = np.cumsum(line_of, dtype=np.int64)
    # parentheses: depth relative to the line start
    op = (b == _LP).astype(np.int32)
    cl = (b == _RP).astype(np.int32)
    if not op.any():
        op = cl = None
    bad = np.zeros(nlines, dtype=bool)
    if op is not None:
        depth = np.cumsum(op - cl, dtype=np.int32)
        base = np.concatenate(([0], depth))[starts]
        rel = depth - base[line_of]
        in_paren = (rel > 0) | (cl == 1)
        # nesting or unbalanced: not simple
        bad[line_of[(rel > 1) | (rel < 0)]] = True
        bad |= (ends_ > starts) & (rel[np.maximum(ends_ - 1, 0)] > 0)
    else:
        in_paren = np.zeros(b.size, dtype=bool)
    semi = (b == _SEMI) & ~in_paren
    if semi.any():
        sc = np.cumsum(semi, dtype=np.int32)
        sbase = np.concatenate(([0], sc))[starts]
        in_semi = (sc - sbase[line_of]) > 0
        comment = in_paren | in_semi
    else:
        comment = in_paren
    blank = (b == _SP) | (b == _TAB) | (b == _CR) | (b == _NL)
    keep = ~comment & ~blank
    c = b[keep].copy()
    cl_line = line_of[keep]
    # lower -> upper case
    low = (c >= 97) & (c <= 122)
    c[low] -= 32
    letters = set(b"GXYZIJKFN") | {ord(a) for a in it.axes if a in "XYZABCUVW"}
    allowed = np.zeros(256, dtype=bool)
    for ch in letters | set(b"0123456789.+-"):
        allowed[ch] = True
    bad[cl_line[~allowed[c]]] = True
    # control flow, parameters, subprograms: the whole program needs the language layer
    cb = c.tobytes()
    if any(t in cb for t in (b"#", b"[", b"O", b"/", b"M98", b"M99")):
        return None
    # magic comments: rare; check by regex on lines with '('
    paren_lines = np.unique(line_of[op == 1]) if op is not None else np.zeros(0, np.int64)
    for ln in paren_lines.tolist():
        if not bad[ln] and _MAGIC.search(data[starts[ln]:ends_[ln]].decode("latin-1")):
            bad[ln] = True
    return ~bad, starts, ends_, (c, cl_line)


# --------------------------------------------------------------------------- one run


def _parse_words(c, cl_line, lo_line, hi_line):
    """Words of lines [lo, hi): (line, letter, int value, decimals) arrays, or None if malformed."""
    sel_lo = np.searchsorted(cl_line, lo_line)
    sel_hi = np.searchsorted(cl_line, hi_line)
    cc = c[sel_lo:sel_hi]
    ln = cl_line[sel_lo:sel_hi]
    if cc.size == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.uint8), np.zeros(0, np.int64), np.zeros(0, np.int64)
    is_letter = (cc >= 65) & (cc <= 90)
    # every line's first code byte must be a letter
    first = np.ones(cc.size, dtype=bool)
    first[1:] = ln[1:] != ln[:-1]
    if np.any(first & ~is_letter):
        return None
    wstart = np.flatnonzero(is_letter)
    wend = np.concatenate((wstart[1:], [cc.size]))
    # a word ends at the next letter or at the end of its line
    nwords = wstart.size
    word_id = np.cumsum(is_letter) - 1
    nstart = wstart + 1
    nlen = wend - nstart
    if np.any(nlen <= 0):
        return None
    # numbers: sign only first, at most one '.', at least one digit, at most 18 digits
    isdigit = (cc >= 48) & (cc <= 57)
    isdot = cc == 46
    issign = (cc == 43) | (cc == 45)
    pos_in_word = np.arange(cc.size) - wstart[word_id]
    if np.any(issign & (pos_in_word != 1)):
        return None
    ndots = np.bincount(word_id[isdot], minlength=nwords)
    ndig = np.bincount(word_id[isdigit], minlength=nwords)
    if np.any(ndots > 1) or np.any(ndig == 0) or np.any(ndig > 18):
        return None
    # decimals: digits after the dot
    dotpos = np.full(nwords, -1, dtype=np.int64)
    dotpos[word_id[isdot]] = np.flatnonzero(isdot)
    after = isdigit & (dotpos[word_id] >= 0) & (np.arange(cc.size) > dotpos[word_id])
    decimals = np.bincount(word_id[after], minlength=nwords).astype(np.int64)
    # integer value of the digit string: sum digit * 10**(digits to its right)
    d = (cc - 48).astype(np.int64)
    d[~isdigit] = 0
    dig_cum = np.cumsum(isdigit[::-1])[::-1]  # digits at or after each position, whole array
    wend_cum = np.concatenate((dig_cum, [0]))[wend]
    right = dig_cum - wend_cum[word_id] - 1
    right[~isdigit] = 0
    pow10 = 10 ** np.arange(19, dtype=np.int64)
    contrib = d * pow10[np.clip(right, 0, 18)]
    value = np.add.reduceat(contrib, wstart) if nwords else contrib[:0]
    neg = np.zeros(nwords, dtype=bool)
    neg[word_id[cc == 45]] = True
    value = np.where(neg, -value, value)
    return ln[wstart], cc[wstart], value, decimals


def _fast_run(interp, data, starts, ends_, code, lo, hi, block_counter):
    """Interpret simple lines lo..hi-1 in columns; None to send them to the full path."""
    it = interp.interpreter
    c, cl_line = code
    parsed = _parse_words(c, cl_line, lo, hi)
    if parsed is None:
        return None
    wl, wletter, wval, wdec = parsed
    n = hi - lo
    axes = it.axes
    na = len(axes)
    letter_codes = {ord(a): k for k, a in enumerate(axes)}
    # N only as the first word of its line; drop N words
    isN = wletter == ord("N")
    if isN.any():
        firstw = np.ones(wl.size, dtype=bool)
        firstw[1:] = wl[1:] != wl[:-1]
        if np.any(isN & ~firstw):
            return None
        keep = ~isN
        wl, wletter, wval, wdec = wl[keep], wletter[keep], wval[keep], wdec[keep]
    rel = wl - lo
    # duplicates of a letter in a line
    if rel.size:
        bits = np.left_shift(np.int64(1), (wletter.astype(np.int64) - 65))
        lstart = np.flatnonzero(np.concatenate(([True], rel[1:] != rel[:-1])))
        if np.any(np.add.reduceat(bits, lstart) != np.bitwise_or.reduceat(bits, lstart)):
            return None
    # G words: values 0..3 without decimals
    isG = wletter == ord("G")
    gval = wval[isG]
    gdec = wdec[isG]
    if np.any(gdec > 0) or np.any((gval < 0) | (gval > 3)):
        return None
    # scale
    inch = it.inch
    numeric = ~isG
    s = int(wdec[numeric].max()) if numeric.any() else 0
    s_units = s + (1 if inch else 0)
    need = [it.tlo, it.feed * (Fraction(254, 10) if inch else 1)] + list(it.pos) + list(it.off)
    for q in need:
        dd = _decimals(q)
        if dd is None:
            return None
        s_units = max(s_units, dd)
    if s_units > _MAX_SCALE:
        return None
    S = s_units
    if np.any(np.abs(wval[numeric]).astype(np.float64) * 10.0 ** (S - wdec[numeric]) * 25.4 > 2.0**59):
        return None
    # per line: has word?  blocks are lines with at least one word (after N)
    has_word = np.zeros(n, dtype=bool)
    has_word[rel] = True
    # motion mode per line (forward filled)
    gline = np.full(n, -1, dtype=np.int64)
    gline[rel[isG]] = gval
    mode0 = -1 if it.motion is None else it.motion // 10
    idx = np.where(gline >= 0, np.arange(n), -1)
    idx = np.maximum.accumulate(idx)
    mode = np.where(idx >= 0, gline[np.maximum(idx, 0)], mode0)
    # values scaled to S (mm) per letter per line
    def scaled(mask):
        v = wval[mask]
        e = S - wdec[mask] - (1 if inch else 0)
        out = v * (10 ** e)
        if inch:
            out = out * 254
        return out

    axis_present = np.zeros((n, na), dtype=bool)
    axis_val = np.zeros((n, na), dtype=np.int64)
    for letter, k in letter_codes.items():
        m = wletter == letter
        if not m.any():
            continue
        rows = rel[m]
        axis_present[rows, k] = True
        if it.rotary[k]:
            e = S - wdec[m]
            axis_val[rows, k] = wval[m] * (10 ** e)
        else:
            axis_val[rows, k] = scaled(m)
    moving = axis_present.any(axis=1)
    # I J K
    ijk = {}
    for letter in "IJK":
        m = wletter == ord(letter)
        if m.any():
            col = np.zeros(n, dtype=np.int64)
            pres = np.zeros(n, dtype=bool)
            col[rel[m]] = scaled(m)
            pres[rel[m]] = True
            ijk[letter] = (col, pres)
    any_ijk = np.zeros(n, dtype=bool)
    for col, pres in ijk.values():
        any_ijk |= pres
    is_arc_line = (mode == 2) | (mode == 3)
    if np.any(any_ijk & ~is_arc_line):
        return None
    if np.any((mode < 0) & moving):
        return None
    arc_rows = is_arc_line & (moving | (gline >= 2))
    if np.any(is_arc_line & (gline >= 2) & ~moving & ~any_ijk):
        return None
    if np.any(any_ijk & ~arc_rows):
        return None
    # feed
    fmask = wletter == ord("F")
    feed = np.zeros(n, dtype=np.int64)
    fpres = np.zeros(n, dtype=bool)
    if fmask.any():
        if np.any(wval[fmask] < 0):
            return None
        feed[rel[fmask]] = scaled(fmask)
        fpres[rel[fmask]] = True
    f0 = _scaled_int(it.feed * (Fraction(254, 10) if inch else 1), S)
    fidx = np.maximum.accumulate(np.where(fpres, np.arange(n), -1))
    feed_line = np.where(fidx >= 0, feed[np.maximum(fidx, 0)], f0)
    feedmove = (arc_rows | (moving & (mode == 1)))
    if it.feed_mode == 94 and np.any(feedmove & (feed_line == 0)):
        return None
    # positions
    pos0 = np.array([_scaled_int(p, S) for p in it.pos], dtype=np.int64)
    off = np.array([_scaled_int(o, S) for o in it.off], dtype=np.int64)
    if it.absolute:
        target = np.where(axis_present, axis_val + off, 0)
        pidx = np.where(axis_present, np.arange(n)[:, None], -1)
        pidx = np.maximum.accumulate(pidx, axis=0)
        end = np.where(pidx >= 0, target[np.maximum(pidx, 0), np.arange(na)], pos0)
    else:
        if np.sum(np.abs(axis_val).astype(np.float64), axis=0).max(initial=0) + np.abs(pos0).max(initial=0) > 2.0**60:
            return None
        end = pos0 + np.cumsum(axis_val, axis=0)
    start = np.vstack((pos0[None, :], end[:-1]))
    emit = moving | arc_rows
    rows = np.flatnonzero(emit)
    m = rows.size
    kind = np.where(mode[rows] == 0, SegmentKind.RAPID, np.where(mode[rows] == 1, SegmentKind.LINE, SegmentKind.ARC)).astype(np.int8)
    st = start[rows]
    en = end[rows]
    centre = plane_col = cw = turns = None
    arcs = kind == SegmentKind.ARC
    if arcs.any():
        plane = it.plane
        a_name, b_name, n_name = PLANE_AXES[plane]
        ia, ib = it.index.get(a_name), it.index.get(b_name)
        if ia is None or ib is None:
            return None
        offs = {"X": "I", "Y": "J", "Z": "K"}
        la, lb, ln_ = offs[a_name], offs[b_name], offs[n_name]
        if ln_ in ijk and np.any(ijk[ln_][1][rows[arcs]]):
            return None
        arow = rows[arcs]
        ia_col = ijk.get(la, (np.zeros(n, np.int64), np.zeros(n, bool)))
        ib_col = ijk.get(lb, (np.zeros(n, np.int64), np.zeros(n, bool)))
        if np.any(~(ia_col[1][arow] | ib_col[1][arow])):
            return None  # R format or missing centre: full path
        if it.arc_absolute:
            ca = np.where(ia_col[1][arow], ia_col[0][arow] + off[ia], off[ia])
            cb = np.where(ib_col[1][arow], ib_col[0][arow] + off[ib], off[ib])
        else:
            ca = start[arow, ia] + ia_col[0][arow]
            cb = start[arow, ib] + ib_col[0][arow]
        if not _arcs_ok(start[arow, ia], start[arow, ib], end[arow, ia], end[arow, ib], ca, cb,
                        it.arc_tolerance, S):
            return None
        centre = np.zeros((m, 2), dtype=np.int64)
        centre[arcs, 0] = ca
        centre[arcs, 1] = cb
        plane_col = np.where(arcs, int(plane), 0).astype(np.int8)
        cw = arcs & (mode[rows] == 2)
        turns = np.zeros(m, dtype=np.int32)
    # blocks and lines
    block_of_line = np.cumsum(has_word) - 1 + block_counter[0]
    block_counter[0] += int(has_word.sum())
    tl = _scaled_int(it.tlo, S)
    chunk = MotionChunk(
        axes, S, kind=kind, start=st, end=en, line=(rows + lo + 1).astype(np.int64),
        block=block_of_line[rows].astype(np.int64), tool_length=np.full(m, tl, dtype=np.int64),
        centre=centre, plane=plane_col, clockwise=cw, turns=turns,
        feed=(feed_line[rows] if it.feed_mode == 94 else None), file=interp.file,
    )
    # hand the state back to the interpreter
    den = 10**S
    it.pos = [Fraction(int(v), den) for v in end[-1]]
    last_mode = int(mode[-1])
    it.motion = None if last_mode < 0 else last_mode * 10
    if fpres.any():
        last_f = Fraction(int(feed_line[-1]), den)
        it.feed = last_f / Fraction(254, 10) if inch else last_f
    if m:
        it._note_assumed(("units", "distance", "offset", "plane") if arcs.any() else ("units", "distance", "offset"))
    it.blocks += int(has_word.sum())
    it.segment_count += m
    for k in (SegmentKind.RAPID, SegmentKind.LINE, SegmentKind.ARC):
        it.kind_counts[k] += int(np.count_nonzero(kind == k))
    interp.fast_lines += n
    return chunk


def _decimals(q: Fraction) -> int | None:
    from ..exact import decimal_places

    return decimal_places(q)


def _scaled_int(q: Fraction, S: int) -> int:
    v = q * 10**S
    if v.denominator != 1:
        raise ValueError("not representable")
    return int(v)


def _arcs_ok(sa, sb, ea, eb, ca, cb, tol: Fraction, S: int) -> bool:
    """Every arc: both radii non-zero and |r0 - r1| <= tol (exactly)."""
    r0f = (sa - ca).astype(np.float64) ** 2 + (sb - cb).astype(np.float64) ** 2
    r1f = (ea - ca).astype(np.float64) ** 2 + (eb - cb).astype(np.float64) ** 2
    if np.any(((sa == ca) & (sb == cb)) | ((ea == ca) & (eb == cb))):
        return False
    t = float(tol * 10**S)
    diff = np.abs(np.sqrt(r0f) - np.sqrt(r1f))
    rad = np.sqrt(np.maximum(r0f, r1f))
    margin = rad * 1e-9 + 1.0
    clear_ok = diff + margin < t
    unsure = ~clear_ok
    if not unsure.any():
        return True
    from .interpreter import _sqrt_diff_exceeds

    tt = tol * 10**S
    for k in np.flatnonzero(unsure).tolist():
        a0 = (int(sa[k]) - int(ca[k])) ** 2 + (int(sb[k]) - int(cb[k])) ** 2
        a1 = (int(ea[k]) - int(ca[k])) ** 2 + (int(eb[k]) - int(cb[k])) ** 2
        if a0 != a1 and _sqrt_diff_exceeds(Fraction(a0), Fraction(a1), tt):
            return False
    return True
