"""The text-wide scans that choose a route or set a pass's flags, rewritten for speed (line44, issue 36), against
the scans they replace: each must give the very same answer on every text.

- ``pipeline.verification._fanuc_plain_piece`` (the box route's test for calls and G68/G51 with G20/G91): the old
  scan upper-cased the text and searched it; the new one searches the text as written, the lower-case letter's
  pattern only when the text holds it.  That rests on a property of ``str.upper`` checked here for every code
  point, and the two scans are compared on texts of the characters that matter (and some that upper-case oddly).
"""

from __future__ import annotations

import re
import sys

from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.pipeline.verification import _fanuc_plain_piece

#: the characters the Fanuc code patterns read besides their letter (digits, the point, blanks)
_PATTERN_CHARS = set("0123456789. \t")
_DIGIT_OR_POINT = re.compile(r"[\d.]")


def test_only_g_and_m_upper_case_into_a_pattern_s_characters():
    """No character but ``g`` and ``m`` upper-cases to a string that holds G, M, a digit, a point, a space or a
    tab unless it is that character itself; a character's upper case starts with a digit or a point (``\\d``:
    any Unicode decimal) exactly when the character is one.  So a pattern ``L[ \\t]*0*DD(?![\\d.])`` matches
    ``text.upper()`` exactly where ``L...`` or its lower-case letter's pattern matches ``text``."""
    odd = []
    for cp in range(sys.maxunicode + 1):
        c = chr(cp)
        up = c.upper()
        if up == c:  # (most characters)
            continue
        if c not in "gm" and (set(up) & (_PATTERN_CHARS | {"G", "M"}) or _DIGIT_OR_POINT.search(up)):
            odd.append(c)
        if (_DIGIT_OR_POINT.match(c) is None) != (_DIGIT_OR_POINT.match(up) is None):
            odd.append(c)
    assert odd == []


def _old_plain_piece(p: str) -> bool:
    """The scan before line44: the piece upper-cased, then five searches."""
    m98, g65 = re.compile(r"M[ \t]*0*98(?![\d.])"), re.compile(r"G[ \t]*0*6[56](?![\d])")
    turns, inch, incremental = (re.compile(r"G[ \t]*0*(?:68|51)(?![\d.])"), re.compile(r"G[ \t]*0*20(?![\d.])"),
                                re.compile(r"G[ \t]*0*91(?![\d.])"))
    up = p.upper()
    return not (m98.search(up) is not None or g65.search(up) is not None or (
        turns.search(up) is not None and (inch.search(up) is not None or incremental.search(up) is not None)))


_CODES = ["G", "g", "M", "m", "0", "00", "98", "65", "66", "68", "51", "20", "91", "6", "5", "9", "8", "1", "2",
          ".", " ", "\t", "\n", "X", "x", "ß", "ſ", "ﬀ", "ǆ", "٣", "ｇ", "Ｍ", "İ", "ŉ"]


@settings(max_examples=600, deadline=None)
@given(st.lists(st.sampled_from(_CODES), max_size=24).map("".join))
def test_the_fanuc_scan_agrees_with_the_upper_cased_one(text):
    assert _fanuc_plain_piece(text) == _old_plain_piece(text)


def test_the_fanuc_scan_on_codes_of_every_kind():
    """Examples each way, both cases (a mutant that drops the lower-case scan, or reads a G65 as a code, fails)."""
    for text in ("G1 X1.\nM30", "G651", "G65.", "g 0 20\ng68", "X1. M980", "M98.", "G6 8\nG20", "N1 G68.1\nG91"):
        assert _fanuc_plain_piece(text) == _old_plain_piece(text), text
    for text in ("m98 p1", "M 098", "g65 p2", "G066", "g68\ng91", "G51 x0\ng20", "G0051\nG091", "ǆ\tg65"):
        assert not _fanuc_plain_piece(text), text
        assert not _old_plain_piece(text), text
    for text in ("G68\nG21", "g51\ng90", "G0 X65. Y98.", "G65.1", "M198"):
        assert _fanuc_plain_piece(text) == _old_plain_piece(text), text


_TEXT = st.text(alphabet=st.sampled_from(list("Gg0123456789.7381 \tXxRrJjKkN\n") + ["é", "ß", "\r"]), max_size=40)


@settings(max_examples=300, deadline=None)
@given(_TEXT)
def test_the_box_reader_s_lines_are_the_str_ones(text):
    """``boxrun._keys_dotless`` (bytes for an ASCII text) gives the lines ``str.translate`` and ``str.replace``
    gave."""
    from nczones.gcode.fanuc.boxrun import _ZERO_DIGITS, _keys_dotless

    assert _keys_dotless(text) == (text.translate(_ZERO_DIGITS).split("\n"), text.replace(".", "").split("\n"))


@settings(max_examples=300, deadline=None)
@given(_TEXT)
def test_the_letter_counts_and_the_g_scans_are_the_old_ones(text):
    """``_letter_count`` is both cases' ``count``; ``may_cycle`` and ``_may_compensate`` search "g" only in a text
    that holds one: the answer of both letters' searches."""
    from nczones.gcode.linuxcnc.double_cycles import may_cycle
    from nczones.gcode.linuxcnc.doubles import _may_compensate
    from nczones.pipeline.verification import _letter_count

    for letter in "RJK":
        assert _letter_count(text, letter) == text.count(letter) + text.count(letter.lower())
    assert may_cycle(text) == any(re.search(g + r"[ \t]*0*(?:73|8[1-9])(?![0-9])", text) for g in "Gg")
    assert _may_compensate(text) == any(re.search(g + r"[ \t]*0*4[12](?![0-9])", text) for g in "Gg")


def test_lower_case_codes_are_still_found():
    """A text in lower case (the g scan is the one that finds them; a mutant that drops it fails here)."""
    from nczones.gcode.linuxcnc.double_cycles import may_cycle
    from nczones.gcode.linuxcnc.doubles import _may_compensate

    assert may_cycle("g0 z2\ng98 g 081 x1 r2") and not may_cycle("g0 x81 y73")
    assert _may_compensate("g1 x1\ng041 d1") and not _may_compensate("g1 x41 y42")


@settings(max_examples=100, deadline=None)
@given(st.lists(_TEXT, min_size=1, max_size=4))
def test_the_kept_line_count_is_each_text_s(texts):
    """``_line_count`` keeps the last text's count: asked for texts in turn (some the same object again), each
    count is the text's own."""
    from nczones.pipeline.verification import _line_count

    for text in texts + texts[:1] + texts[::-1]:
        assert _line_count(text) == text.count("\n") + (1 if text and not text.endswith("\n") else 0)
