"""Evaluated blocks: what the G-code language layer hands the interpreter.

The language layer (lexer, parser, parameters, expressions, O-word control
flow, M98/M99 subprograms) runs the program's *control* and yields one
:class:`Block` per executed block, in execution order, with every word's
value already evaluated to an exact rational.  The interpreter
(:mod:`nczones.gcode.interpreter`) gives the blocks their *machine* meaning
(modal state, offsets, motion).
"""

from __future__ import annotations

from fractions import Fraction

from ..errors import SourceSpan
from ..precompiled import dataclass  # dataclasses.dataclass, its methods precompiled (start-up)

__all__ = ["Word", "Block", "ShapeBlock", "LANE_FULL"]


@dataclass(frozen=True, slots=True, eq=False)
class Word:
    """One word: an upper-case letter and its exact value.

    ``text`` is the word as written (``"x-1.5"``, ``"X[#1+2]"``).  For G and
    M codes the value is the code number (``Fraction(591, 10)`` for G59.1).
    """

    letter: str
    value: Fraction
    span: SourceSpan
    text: str = ""

    # Equality by value, not by class: the lexer and the fast path build
    # subclasses whose span is computed on first read.
    def __eq__(self, other):
        if isinstance(other, Word):
            return (self.letter, self.value, self.span, self.text) == (other.letter, other.value, other.span, other.text)
        return NotImplemented

    def __hash__(self):
        return hash((self.letter, self.value, self.span, self.text))


@dataclass(frozen=True, slots=True, eq=False)
class Block:
    """One executed block.

    Attributes
    ----------
    words : tuple of Word
        The words in source order, after parameter and expression evaluation
        (parameter assignments and O-words are consumed by the language layer).
    span : SourceSpan
        The whole source line.
    index : int
        Position in execution order (0-based; repeats and calls count anew).
    number : Fraction or None
        The N word, if any.
    messages : tuple of str
        ``(MSG, ...)``/``(DEBUG, ...)``-style comments, for reports only.
    """

    words: tuple[Word, ...]
    span: SourceSpan
    index: int
    number: Fraction | None = None
    messages: tuple[str, ...] = ()

    # Equality by value, not by class: the language layer builds a subclass whose
    # words are made only when read (nczones.gcode.lexer.PlainBlock).
    def __eq__(self, other):
        if isinstance(other, Block):
            return (self.words, self.span, self.index, self.number, self.messages) == (
                other.words, other.span, other.index, other.number, other.messages)
        return NotImplemented

    def __hash__(self):
        return hash((self.words, self.span, self.index, self.number, self.messages))

    def get(self, letter: str) -> Word | None:
        """The first word with this letter, or None."""
        for w in self.words:
            if w.letter == letter:
                return w
        return None

    def all(self, letter: str) -> tuple[Word, ...]:
        return tuple(w for w in self.words if w.letter == letter)


@dataclass(frozen=True, slots=True, eq=False)
class ShapeBlock(Block):
    """A lathe cycle block together with the finishing shape it reads (Fanuc G70-G73 ``P``/``Q``, LinuxCNC
    G70-G72 ``Q``): ``shape`` holds the shape's blocks, evaluated but not executed, in program order."""

    shape: tuple[Block, ...] = ()

    @classmethod
    def of(cls, values: list, span: SourceSpan, index: int, number: Fraction | None,
           shape: tuple[Block, ...]) -> ShapeBlock:
        """The block of evaluated words ``(letter, value, column, end column, text)``."""
        words = tuple(Word(v[0], v[1], SourceSpan(span.file, span.line, v[2], v[3], span.text), v[4])
                      for v in values)
        return cls(words, span, index, number, (), shape)


#: What the language layer yields, in place of a block, when the interpreter's lane it hands plain blocks
#: to (``iter_blocks(..., lane=...)``) has a full chunk: the interpreter then hands the chunk on.
LANE_FULL = object()
