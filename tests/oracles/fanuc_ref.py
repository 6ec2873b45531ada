"""An independent reference reader of Fanuc mill programs (issue 33, "Fanuc: an independent reference reader").

Deliberately small, slow and plain: a direct transcription of the manual rules, sharing NO code with
``nczones/gcode/fanuc/`` and none with ``nczones/gcode/lexer.py`` either (the tokenizer below is its own:
the nczones lexer builds ``Block`` objects and fast-lane tuples, more than a pure lexer, so using it would
share the number reading the reference is meant to check).  It produces the motion of a program as a list
of ``(kind, end)`` with ``kind`` in ``"rapid" "line" "arc" "dwell"`` and ``end`` the end point in machine
coordinates (X, Y, Z), exact ``Fraction``.

Sources (the sentences cited beside each rule):

* [0i]  FANUC Series 0i-MODEL D Operator's Manual B-64304EN (common to lathe and machining centre) and
  B-64304EN-1 (machining centre);
* [0i-MB] FANUC Series 0i-MB Operator's Manual B-63844EN/02, 14.1.2 "G53, G28, and G30 commands in tool
  length offset mode" and "independent specification of the H command"
  (http://cncmanuals.com/fanuc/346/series-0i-mb-operators-manual/page/228);
* [30i] FANUC Series 30i/31i/32i-MA Operator's Manual B-63944EN/02, 8.2 "Inch/metric conversion (G20,
  G21)" (http://cncmanuals.com/fanuc/773/.../page/226): "The unit systems for the following values are
  changed after inch/metric conversion: ... Positional command, Workpiece origin offset value, Tool
  compensation value";
* [15i] FANUC Series 15i-MA B-63324EN/03 17 "Custom macro", "Limitation": "The numeric data handled by
  custom macros are double-precision real data, as laid down in the applicable IEEE standard";
* [16i-PB] FANUC 16i/18i-PB Descriptions B-63682EN/01 7.3 "Decimal point input/pocket calculator type":
  "When calculator-type decimal notation is used, a value without decimal point is considered to be
  specified in millimeters, inch or deg. When standard decimal notation is used, such a value is considered
  to be specified in least input increments";
* [Sinha] S. K. Sinha, "CNC Programming Using Fanuc Custom Macro B", "Real versus integer values": "real
  numbers ... used in place of integer numbers are automatically rounded" (``S[1000.5]`` is S1001,
  ``M[3.4999999]`` is M03).

The reader models a Fanuc mill (G17, tool axis Z, the three axes X Y Z) with tool length compensation type
C on Z, TOS = 0 (parameter 5006#6: the tool axis moves at once by an offset change), IS-B increments.
Values in the machine description (offsets, tool lengths, reference positions) are millimetres.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from fractions import Fraction

F = Fraction
AXES = "XYZ"
LENGTH_LETTERS = set("XYZIJKRQ")  # K is the repeat count inside a canned cycle block
INTEGER_LETTERS = set("MSTHDPLN")
INCH = F(254, 10)
CYCLE_CODES = (73, 74, 76, 81, 82, 83, 84, 85, 86, 89, F(842, 10), F(843, 10))


class RefUnknown(Exception):
    """A construct this reader does not model (the caller skips the example; never a guess)."""


class RefError(Exception):
    """A program the control would reject (alarm)."""


# ---------------------------------------------------------------------------------------------- numbers

def round_half_away(q: Fraction, step: Fraction) -> Fraction:
    """``q`` rounded to a multiple of ``step``, halves away from zero ([0i] "ROUND": "rounded off";
    [Sinha]: 1000.5 -> 1001)."""
    n = q / step
    sign = -1 if n < 0 else 1
    n = abs(n)
    whole = n.numerator // n.denominator
    if n - whole >= F(1, 2):
        whole += 1
    return sign * whole * step


def exact_of_double(x: float) -> Fraction:
    """The value of a macro double as the control hands it to an address.

    [15i] 17 "Limitation": "The numeric data handled by custom macros are double-precision real data, as
    laid down in the applicable IEEE standard" and "Custom macro variables are decimal numbers with a
    precision of 15 digits": the double is read as its 15-significant-digit decimal (so ``-8.347 / 2`` is
    -4.1735, a half increment, not the double's -4.17349999999999976...)."""
    if x == 0 or not math.isfinite(x):
        return Fraction(0)
    return Fraction(format(x, ".15g"))


# ---------------------------------------------------------------------------------------------- lexing

_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)")


@dataclass
class Word:
    letter: str
    text: str | None = None  # a literal as written
    expr: object = None  # an expression tree (for #, [ ])
    neg: bool = False


@dataclass
class Line:
    lineno: int
    skip: int | None = None  # the block skip switch number (1 for '/')
    label: int | None = None  # N
    program: int | None = None  # O line
    kind: str = "nc"  # nc, assign, if_goto, if_then, while, end, goto, do, percent, empty
    words: list = field(default_factory=list)
    target: object = None
    value: object = None
    cond: object = None
    number: int | None = None


def cpython_libm(name: str, *args: float) -> float:
    """SIN/COS/TAN of degrees, ATAN of ``(y, x)`` in degrees, POW: CPython's library (``math.radians``,
    ``math.degrees``), the reference's own reading of the functions."""
    if name == "SIN":
        return math.sin(math.radians(args[0]))
    if name == "COS":
        return math.cos(math.radians(args[0]))
    if name == "TAN":
        return math.tan(math.radians(args[0]))
    if name == "ATAN":
        return math.degrees(math.atan2(args[0], args[1]))
    if name == "POW":
        return math.pow(args[0], args[1])
    raise RefError(f"function {name}")


def _strip(text: str) -> str:
    """Comments ``( )`` removed, blanks removed, upper case, the EOB ``;`` dropped ([0i] "Program
    configuration")."""
    out, depth = [], 0
    for ch in text:
        if ch == "(":
            depth = 1
            continue
        if ch == ")" and depth:
            depth = 0
            continue
        if depth:
            continue
        if ch in " \t\r":
            continue
        out.append(ch.upper())
    s = "".join(out)
    if s.endswith(";"):
        s = s[:-1]
    return s


class _Expr:
    """A recursive-descent reader of Macro B expressions ([0i] "Arithmetic and logic operation"):
    functions (``ATAN[a]/[b]`` of two arguments); ``* / AND MOD``; ``+ - OR XOR``; relations ``EQ NE GT GE LT LE``."""

    FUNCS = ("ROUND", "FIX", "FUP", "ABS", "SQRT", "SIN", "COS", "TAN")

    def __init__(self, s: str, i: int = 0):
        self.s, self.i = s, i

    def peek(self, t: str) -> bool:
        return self.s.startswith(t, self.i)

    def eat(self, t: str) -> None:
        if not self.peek(t):
            raise RefError(f"expected {t!r} at {self.s[self.i:]!r} in {self.s!r}")
        self.i += len(t)

    def relation(self):
        a = self.additive()
        for op in ("EQ", "NE", "GT", "GE", "LT", "LE"):
            if self.peek(op):
                self.i += 2
                return ("rel", op, a, self.additive())
        return a

    def condition(self):
        a = self.relation()
        while True:
            for op in ("AND", "OR"):
                if self.peek(op):
                    self.i += len(op)
                    a = ("cond", op, a, self.relation())
                    break
            else:
                return a

    def additive(self):
        a = self.term()
        while True:
            if self.peek("+") or self.peek("-"):
                op = self.s[self.i]
                self.i += 1
                a = ("bin", op, a, self.term())
            elif self.peek("OR") or self.peek("XOR"):
                op = "OR" if self.peek("OR") else "XOR"
                self.i += len(op)
                a = ("bin", op, a, self.term())
            else:
                return a

    def term(self):
        a = self.unary()
        while True:
            for op in ("*", "/", "AND", "MOD"):
                if self.peek(op):
                    self.i += len(op)
                    a = ("bin", op, a, self.unary())
                    break
            else:
                return a

    def unary(self):
        if self.peek("-"):
            self.i += 1
            return ("neg", self.unary())
        if self.peek("+"):
            self.i += 1
            return self.unary()
        return self.atom()

    def atom(self):
        if self.peek("["):
            self.i += 1
            e = self.condition()
            self.eat("]")
            return ("br", e)
        if self.peek("#"):
            self.i += 1
            if self.peek("["):
                self.i += 1
                e = self.additive()
                self.eat("]")
                return ("var", e)
            m = re.compile(r"\d+").match(self.s, self.i)
            if not m:
                raise RefError(f"bad variable in {self.s!r}")
            self.i = m.end()
            return ("var", ("num", float(m.group())))
        if self.peek("POW["):
            # [30i] "Arithmetic and logic operation": POW[a,b], a to the power b
            self.i += 4
            a = self.additive()
            self.eat(",")
            b = self.additive()
            self.eat("]")
            return ("pow", a, b)
        if self.peek("ATAN["):
            # [0i] "Arithmetic and logic operation": ``#i = ATAN[#j]/[#k]`` (also written ``ATAN[#j,#k]``), the
            # angle of the point (#k, #j) in degrees, 0 to 360 (parameter 6004#0 NAT = 0): ATAN[-1]/[-1] is 225
            self.i += 5
            a = self.additive()
            if self.peek(","):
                self.i += 1
                b = self.additive()
                self.eat("]")
            else:
                self.eat("]")
                if not self.peek("/["):
                    raise RefUnknown("ATAN of one argument")
                self.i += 2
                b = self.additive()
                self.eat("]")
            return ("atan", a, b)
        for f in self.FUNCS:
            if self.peek(f + "["):
                self.i += len(f) + 1
                e = self.additive()
                self.eat("]")
                return ("fn", f, e)
        m = _NUMBER.match(self.s, self.i)
        if m and self.s[self.i] not in "+-":
            self.i = m.end()
            return ("num", float(m.group()))
        raise RefError(f"cannot read {self.s[self.i:]!r} in {self.s!r}")


def _word_value(s: str, i: int) -> tuple[Word | None, int]:
    """One address value at ``s[i]``: a literal, ``#n``, ``-#n``, ``[e]`` or ``-[e]``."""
    neg = False
    j = i
    if s.startswith("-#", j) or s.startswith("-[", j):
        neg, j = True, j + 1
    if j < len(s) and s[j] in "#[":
        p = _Expr(s, j)
        e = p.atom()
        return Word("", expr=e, neg=neg), p.i
    m = _NUMBER.match(s, i)
    if not m:
        raise RefError(f"no value at {s[i:]!r}")
    return Word("", text=m.group()), m.end()


def lex_line(raw: str, lineno: int) -> Line:
    s = _strip(raw)
    line = Line(lineno)
    if not s:
        line.kind = "empty"
        return line
    if s.startswith("%"):
        line.kind = "percent"
        return line
    if s.startswith("/"):
        m = re.compile(r"/(\d)?").match(s)
        line.skip = int(m.group(1) or 1)
        s = s[m.end():]
    m = re.compile(r"[O:](\d+)").match(s)
    if m:
        line.program = int(m.group(1))
        line.kind = "o"
        return line
    m = re.compile(r"N(\d+)").match(s)
    if m:
        line.label = int(m.group(1))
        s = s[m.end():]
    if not s:
        line.kind = "empty"
        return line
    if s.startswith("#"):
        p = _Expr(s)
        p.eat("#")
        if p.peek("["):
            p.i += 1
            tgt = p.additive()
            p.eat("]")
        else:
            m = re.compile(r"\d+").match(s, p.i)
            tgt = ("num", float(m.group()))
            p.i = m.end()
        p.eat("=")
        line.kind, line.target, line.value = "assign", tgt, p.additive()
        if p.i != len(s):
            raise RefError(f"trailing text in {raw!r}")
        return line
    if s.startswith("IF["):
        p = _Expr(s, 2)
        p.eat("[")
        cond = p.condition()
        p.eat("]")
        line.cond = cond
        if p.peek("GOTO"):
            p.i += 4
            line.kind, line.value = "if_goto", p.additive()
        elif p.peek("THEN"):
            p.i += 4
            sub = lex_line(s[p.i:], lineno)
            if sub.kind != "assign":
                raise RefUnknown("IF THEN with something else than an assignment")
            line.kind, line.target, line.value = "if_then", sub.target, sub.value
        else:
            raise RefError(raw)
        return line
    if s.startswith("WHILE["):
        p = _Expr(s, 5)
        p.eat("[")
        line.cond = p.condition()
        p.eat("]")
        p.eat("DO")
        line.kind, line.number = "while", int(s[p.i:])
        return line
    m = re.compile(r"END(\d)$").match(s)
    if m:
        line.kind, line.number = "end", int(m.group(1))
        return line
    m = re.compile(r"DO(\d)$").match(s)
    if m:
        line.kind, line.number = "do", int(m.group(1))
        return line
    if s.startswith("GOTO"):
        p = _Expr(s, 4)
        line.kind, line.value = "goto", p.additive()
        return line
    i = 0
    while i < len(s):
        letter = s[i]
        if not letter.isalpha():
            raise RefError(f"unexpected {s[i:]!r} in {raw!r}")
        w, i = _word_value(s, i + 1)
        w.letter = letter
        line.words.append(w)
    return line


# ---------------------------------------------------------------------------------------------- machine

@dataclass
class RefMachine:
    """What the reader needs of the machine (millimetres, machine coordinates)."""

    work: dict  # "G54".."G59", "G54.1P<n>", "EXT" -> [x, y, z]
    lengths: dict  # H number -> geometry (mm)
    ref1: tuple = (F(0), F(0), F(0))
    ref2: tuple = (F(0), F(0), F(0))
    start: tuple = (F(0), F(0), F(0))
    g73_retract: Fraction = F(1, 2)
    g83_clearance: Fraction = F(1)
    boring_shift: str = "+X"
    decimal_point_input: str = "calculator"
    common: dict = field(default_factory=dict)  # "#500" -> value


VACANT = None


class Reader:
    """Run one program (text) and collect its motion."""

    MAX_STEPS = 200_000
    length_letters = LENGTH_LETTERS
    #: The control's library: ``libm(name, *args)`` the double SIN/COS/TAN (of degrees), ATAN (of y, x; degrees,
    #: before the range shift) or POW gives (:func:`cpython_libm`); a test may put another one in (a control whose
    #: library gives a neighbouring double, tests/gcode/fanuc/test_libm_spread.py).
    libm = staticmethod(lambda name, *args: cpython_libm(name, *args))
    round_step = F(1)

    def __init__(self, machine: RefMachine, *, block_delete=False):
        self.mc = machine
        # the optional block skip switches that are on: True is switch 1 alone ('/' is '/1'), a collection
        # names them (BDT1..BDT9)
        self.skip_on = {1} if block_delete is True else set(block_delete or ())
        self.work = {k: list(v) for k, v in machine.work.items()}
        self.work.setdefault("EXT", [F(0)] * 3)
        self.h_geom = {int(k): F(v) for k, v in machine.lengths.items()}
        self.h_wear: dict[int, Fraction] = {}
        self.pos = list(machine.start)  # machine position
        self.motions: list[tuple[str, tuple]] = []
        # modal state at power on ([0i] "G code list": G00 G17 G90 G21 G49 G80 G98 G54 are the defaults)
        self.motion = 0
        self.absolute = True
        self.inch = False
        self.wcs = "G54"
        self.local = [F(0)] * 3  # G52
        self.g92 = [F(0)] * 3
        self.tl_mode = 49
        self.tl_h = 0
        self.tl = F(0)  # the active tool length offset on Z
        self.cycle: int | None = None
        self.retract_initial = True  # G98
        self.cyc: dict = {}
        self.modal_call: dict | None = None
        self.common = {int(k.lstrip("#")): float(v) for k, v in machine.common.items()}
        self.locals: list[dict] = [{}]
        self.steps = 0
        self.plane = 17
        self.xf: tuple | None = None  # the active coordinate transform (G16, G51, G51.1, G68)
        self.polar = [F(0), F(0)]  # G16: the last radius and angle
        self.intermediate: dict = {}  # G28/G30 intermediate point per axis (machine), for G29
        self.ret_label: int | None = None  # M99 P n
        self.arcs: dict[int, tuple | None] = {}  # index of an arc in motions -> its circle (circle())
        self.lengths: list[Fraction] = []  # the tool length offset on Z in force at the end of each motion

    # -------------------------------------------------------------------------- units and offsets

    def unit(self) -> Fraction:
        return INCH if self.inch else F(1)

    def increment(self) -> Fraction:
        """The least input increment, IS-B: 0.001 mm / 0.0001 in ([0i] "Increment system")."""
        return F(1, 10000) if self.inch else F(1, 1000)

    def offset(self) -> list:
        """EXT + the workpiece system + G52 + G92, per axis ([0i] "Coordinate system": the workpiece
        coordinate system is shifted by the external offset; the local system G52 is set in every
        workpiece system; G92 shifts all workpiece systems by the same amount)."""
        w = self.work.get(self.wcs)
        if w is None:
            w = [F(0)] * 3
        return [self.work["EXT"][a] + w[a] + self.local[a] + self.g92[a] for a in range(3)]

    def tool(self) -> list:
        return [F(0), F(0), self.tl]

    def program_pos(self) -> list:
        """The current position in program units as the control reads it (#5001.., without the tool
        length): machine - offsets - tool length."""
        o, t = self.offset(), self.tool()
        return [(self.pos[a] - o[a] - t[a]) / self.unit() for a in range(3)]

    # -------------------------------------------------------------------------- macro values

    def read_var(self, n: int):
        if n == 0:
            return VACANT
        if 1 <= n <= 33:
            return self.locals[-1].get(n, VACANT)
        if 100 <= n <= 199 or 500 <= n <= 999:
            return self.common.get(n, VACANT)
        if 5001 <= n <= 5003:
            return float(self.program_pos()[n - 5001])
        if 5021 <= n <= 5023:
            return float(self.pos[n - 5021] / self.unit())
        if n == 4001:
            return float(self.motion if self.cycle is None else self.cycle)
        if n == 4003:
            return 90.0 if self.absolute else 91.0
        raise RefUnknown(f"#{n} not modelled by the reference")

    def write_var(self, n: int, v) -> None:
        if 1 <= n <= 33:
            self.locals[-1][n] = v
        elif 100 <= n <= 199 or 500 <= n <= 999:
            self.common[n] = v
        else:
            raise RefUnknown(f"write #{n}")

    def ev(self, e):
        """Evaluate an expression: a double, or VACANT (a bare vacant variable; [0i] "Vacant variables")."""
        k = e[0]
        if k == "num":
            return e[1]
        if k == "var":
            n = self.num(self.ev(e[1]))
            return self.read_var(int(round_half_away(exact_of_double(n), F(1))))
        if k == "br":
            return self.ev(e[1])
        if k == "neg":
            return -self.num(self.ev(e[1]))
        if k == "fn":
            x = self.num(self.ev(e[2]))
            f = e[1]
            if f == "ROUND":
                # inside an address ROUND rounds to the address's least increment ([Haas] 96-8000
                # "Notes on functions": "When round is used in an address expression, then the argument
                # of round is rounded to the addresses significant precision"; Machinery's Handbook 31st
                # ed. p. 1383: "#101 = 27/32; G91 G00 X[ROUND[#101]]: X0.8438 (inch) or X0.844 (metric)")
                return float(round_half_away(exact_of_double(x), self.round_step))
            if f == "FIX":
                return float(math.trunc(x))
            if f == "FUP":
                return float(math.trunc(x) + (0 if x == math.trunc(x) else (1 if x > 0 else -1)))
            if f == "ABS":
                return abs(x)
            if f == "SQRT":
                return math.sqrt(x)
            if f in ("SIN", "COS", "TAN"):
                return self.libm(f, x)
        if k == "atan":
            d = self.libm("ATAN", self.num(self.ev(e[1])), self.num(self.ev(e[2])))
            return d + 360.0 if d < 0 else d
        if k == "pow":
            return self.libm("POW", self.num(self.ev(e[1])), self.num(self.ev(e[2])))
        if k == "bin":
            op, a, b = e[1], self.num(self.ev(e[2])), self.num(self.ev(e[3]))
            if op == "+":
                return a + b
            if op == "-":
                return a - b
            if op == "*":
                return a * b
            if op == "/":
                if b == 0:
                    raise RefError("division by 0")
                return a / b
            if op == "MOD":
                ia, ib = int(round_half_away(F(a), F(1))), int(round_half_away(F(b), F(1)))
                return float(int(math.fmod(ia, ib)))
            ia, ib = int(a), int(b)
            return float({"AND": ia & ib, "OR": ia | ib, "XOR": ia ^ ib}[op])
        if k == "rel":
            a, b = self.ev(e[2]), self.ev(e[3])
            op = e[1]
            if op in ("EQ", "NE"):
                # [0i] "Vacant variables": in EQ/NE a vacant variable differs from 0
                same = (a is VACANT and b is VACANT) or (a is not VACANT and b is not VACANT and a == b)
                return same if op == "EQ" else not same
            a, b = self.num(a), self.num(b)
            return {"GT": a > b, "GE": a >= b, "LT": a < b, "LE": a <= b}[op]
        if k == "cond":
            a, b = self.ev(e[2]), self.ev(e[3])
            return (a and b) if e[1] == "AND" else (a or b)
        raise RefError(f"expression {e!r}")

    @staticmethod
    def num(v) -> float:
        return 0.0 if v is VACANT else float(v)

    def value(self, w: Word, *, in_cycle: bool = False):
        """The exact value of an address word in program units, or VACANT.

        A literal: as written; a length word without a decimal point is a count of least input increments
        when DPI = 0 ([16i-PB] 7.3).  A macro value: the double rounded as the control rounds it — a length
        to the least input increment, an integer address to an integer ([Sinha]), halves away from zero.
        A vacant variable drops the word ([0i] "Vacant variables": ``G90 X#1`` is ``G90``)."""
        is_length = w.letter in self.length_letters and not (w.letter == "K" and in_cycle)
        if w.text is not None:
            q = F(w.text)
            if is_length and "." not in w.text and self.mc.decimal_point_input == "increment":
                q = q * self.increment()
            return q
        self.round_step = self.increment() if is_length else F(1)
        try:
            v = self.ev(w.expr)
        finally:
            self.round_step = F(1)
        if v is VACANT:
            return VACANT
        q = exact_of_double(v)
        if w.neg:
            q = -q
        if w.letter == "G":
            return round_half_away(q, F(1, 10))
        if is_length:
            return round_half_away(q, self.increment())
        return round_half_away(q, F(1))

    # -------------------------------------------------------------------------- motion output

    def emit(self, kind: str, end) -> None:
        self.pos = list(end)
        self.motions.append((kind, tuple(end)))
        self.lengths.append(self.tl)

    def to_machine(self, prog) -> list:
        o, t = self.offset(), self.tool()
        return [prog[a] * self.unit() + o[a] + t[a] for a in range(3)]

    # -------------------------------------------------------------------------- running

    def run(self, text: str) -> list:
        lines = [lex_line(raw, i + 1) for i, raw in enumerate(text.splitlines())]
        # programs: the main program is the text up to the second O line (or the end); O<n> starts O<n>
        self.programs: dict[int, int] = {}
        self.lines = lines
        # [0i] "Program configuration": the first % starts the tape; the main program's number O line
        # comes first; a later O line starts another program (and ends the main program's text)
        main = 0
        while main < len(lines) and lines[main].kind in ("empty", "percent"):
            main += 1
        if main < len(lines) and lines[main].kind == "o":
            main += 1
        for i, ln in enumerate(lines):
            if ln.kind == "o" and i >= main:
                self.programs[ln.program] = i + 1
        self.exec_from(main, level_kind="main")
        return self.motions

    def find_label(self, start: int, n: int) -> int:
        """``GOTO n``: block N n of the current program, searched forward then from its start ([0i])."""
        lo = start
        while lo > 0 and self.lines[lo - 1].kind != "o":
            lo -= 1
        hi = start
        while hi < len(self.lines) and self.lines[hi].kind != "o":
            hi += 1
        for i in list(range(start, hi)) + list(range(lo, start)):
            if self.lines[i].label == n:
                return i
        raise RefError(f"N{n} not found")

    def exec_from(self, pc: int, level_kind: str) -> None:
        """Execute the lines from ``pc`` until M99 (in a subprogram/macro) or M30/M02/%/the next O line
        (main)."""
        loops: list[tuple[int, int]] = []  # (m, index of the WHILE line)
        while True:
            self.steps += 1
            if self.steps > self.MAX_STEPS:
                raise RefUnknown("step bound")
            if pc >= len(self.lines):
                return
            ln = self.lines[pc]
            if ln.kind == "o" or ln.kind == "percent":
                if level_kind == "main":
                    return
                raise RefError("a subprogram ran into the next program")
            # [0i] "Optional block skip": "When a slash followed by a number (/n, n = 1 to 9) is specified
            # at the head of a block, and optional block skip switch n on the machine operator panel is set
            # to on, the information contained in the block for which /n is specified is ignored"; "/1" may
            # be written "/".  A switch that is off: the block runs as if no slash were there.
            if ln.skip is not None and ln.skip in self.skip_on:
                pc += 1
                continue
            k = ln.kind
            if k == "empty":
                pc += 1
            elif k == "assign":
                self.write_var(self.target(ln.target), self.ev(ln.value))
                pc += 1
            elif k == "if_then":
                if self.ev(ln.cond):
                    self.write_var(self.target(ln.target), self.ev(ln.value))
                pc += 1
            elif k in ("if_goto", "goto"):
                if k == "goto" or self.ev(ln.cond):
                    n = int(round_half_away(exact_of_double(self.num(self.ev(ln.value))), F(1)))
                    tgt = self.find_label(pc + 1, n)
                    # [0i] "Branch and repetition": a GOTO out of a loop closes it
                    loops = [lp for lp in loops if lp[1] < tgt and self._loop_end(lp) > tgt]
                    pc = tgt
                else:
                    pc += 1
            elif k == "while":
                if self.ev(ln.cond):
                    if not loops or loops[-1][1] != pc:
                        loops.append((ln.number, pc))
                    pc += 1
                else:
                    if loops and loops[-1][1] == pc:
                        loops.pop()
                    pc = self._end_of(pc, ln.number) + 1
            elif k == "end":
                if not loops or loops[-1][0] != ln.number:
                    raise RefError(f"END{ln.number} without DO")
                pc = loops[-1][1]
            elif k == "do":
                raise RefUnknown("DO without WHILE")
            else:
                r = self.block(ln, pc)
                if isinstance(r, tuple):
                    pc = self.find_label(pc + 1, r[1])
                    continue
                if r == "end":
                    return
                if r == "return":
                    if level_kind == "main":
                        raise RefUnknown("M99 in the main program")
                    return
                pc += 1

    def _end_of(self, pc: int, m: int) -> int:
        depth = 0
        for i in range(pc + 1, len(self.lines)):
            ln = self.lines[i]
            if ln.kind == "while" and ln.number == m:
                depth += 1
            if ln.kind == "end" and ln.number == m:
                if depth == 0:
                    return i
                depth -= 1
        raise RefError(f"no END{m}")

    def _loop_end(self, lp) -> int:
        return self._end_of(lp[1], lp[0])

    def target(self, e) -> int:
        return int(round_half_away(exact_of_double(self.num(self.ev(e))), F(1)))

    # -------------------------------------------------------------------------- one NC block

    def block(self, ln: Line, pc: int):
        words = ln.words
        gs: list[Fraction] = []
        other: dict[str, Fraction] = {}
        letters = [w.letter for w in words]
        in_cycle_block = self.cycle is not None or any(
            w.letter == "G" and w.text is not None and F(w.text) in CYCLE_CODES for w in words)
        self._raw = {w.letter: w for w in words}
        for w in words:
            v = self.value(w, in_cycle=in_cycle_block)
            if v is VACANT:
                continue
            if w.letter == "G":
                gs.append(v)
            else:
                if w.letter in other and w.letter != "M":
                    raise RefError(f"address {w.letter} twice")
                other[w.letter] = v
        del letters
        g = set(gs)

        # ------------------------------------------------------------- calls (G65 first in its block)
        if F(65) in g:
            return self.call_macro(other, modal=False)
        if F(66) in g:
            self.modal_call = {"P": int(other.pop("P")), "L": int(other.pop("L", 1)), "args": dict(other)}
            return None
        if F(67) in g:
            self.modal_call = None
            g.discard(F(67))
        m = other.get("M")
        if m in (2, 30):
            return "end"  # [0i]: M02/M30 end the main program
        if m == 98:
            p = int(other["P"])
            if "L" in other:
                count = int(other["L"])
            elif p > 9999:
                count, p = p // 10000, p % 10000  # [0i] "Subprogram": M98 P30002 runs O0002 three times
            else:
                count = 1
            self.modal_state_only(g, other)
            for _ in range(count):
                self.call(p, new_level=False)
                if self.ret_label is not None:
                    label, self.ret_label = self.ret_label, None
                    return ("goto", label)
            return None
        if m == 97:
            # [Haas] M97 P n L: a local subprogram at block N n of the current program, to its M99
            tgt = self.find_label(pc, int(other["P"]))
            for _ in range(int(other.get("L", 1))):
                self.exec_from(tgt, level_kind="sub")
            return None
        if m == 99:
            # [0i] "Subprogram": M99 P n returns to block N n of the calling program
            self.ret_label = int(other["P"]) if "P" in other else None
            return "return"
        # M00 / M01 ([0i] "Program stop (M00)", "Optional stop (M01)"): automatic operation stops after
        # the block is executed and "the modal information remains unchanged"; cycle start resumes it.  No
        # motion of its own: the block runs as any other (and M01 the same whether its switch is on or off).

        # ------------------------------------------------------------- modal codes of the block
        self.modal_state_only(g, other)

        # ------------------------------------------------------------- group 00
        self.transform_codes(g, other)
        one_shot = [c for c in g if c in (4, 10, 27, 28, 29, 30, 52, 53, 92, F(921, 10))]
        axes = {a: other[a] for a in AXES if a in other}
        if one_shot:
            c = one_shot[0]
            if c == 4:
                self.emit("dwell", self.pos)
                return None
            if c == 10:
                self.g10(other)
                return None
            if c == 52:
                if not self.absolute:
                    raise RefUnknown("G52 in G91")
                for a, v in axes.items():
                    self.local[AXES.index(a)] = v * self.unit()
                return None
            if c == 92:
                self.g92_set(axes)
                return None
            if c == F(921, 10):
                self.g92 = [F(0)] * 3  # G92.1: the G92 shift is cancelled
                return None
            if c == 53:
                if not self.absolute:
                    raise RefUnknown("G53 in G91")
                # [0i] "Machine coordinate system": G53 IP_ moves at rapid to the machine coordinates;
                # [0i-MB] 14.1.2: the tool length offset vector is cancelled on the specified tool axis
                end = list(self.pos)
                for a, v in axes.items():
                    end[AXES.index(a)] = v * self.unit()
                self.emit("rapid", end)
                return None
            if c in (28, 30):
                self.reference_return(c, axes, other)
                return None
            if c == 27:
                # [0i] "Reference position return": G27 IP_ positions to IP_ at rapid (then checks)
                self.move(axes, other, None, kind="rapid")
                return None
            if c == 29:
                self.g29(axes)
                return None

        # ------------------------------------------------------------- canned cycle
        if self.cycle is not None:
            if any(a in other for a in "XYZR") and other.get("K", 1) != 0:
                self.drill(other)
            elif "K" in other and other["K"] == 0:
                self.cycle_data(other)
            return None

        # ------------------------------------------------------------- motion
        changed_tl = self._pending_tl
        if axes or changed_tl is not None:
            self.move(axes, other, changed_tl)
        self._pending_tl = None
        if self.modal_call is not None and axes:
            self.call_macro(dict(self.modal_call["args"], P=self.modal_call["P"], L=self.modal_call["L"]),
                            modal=True)
        return None

    _pending_tl = None
    _raw: dict = {}

    def modal_state_only(self, g: set, other: dict) -> None:
        """The modal codes of a block, in group order."""
        for c in sorted(g):
            if c == 20:
                self.inch = True
            elif c == 21:
                self.inch = False
            elif c == 90:
                self.absolute = True
            elif c == 91:
                self.absolute = False
            elif c in (17, 18, 19):
                self.plane = int(c)
            elif c in (54, 55, 56, 57, 58, 59):
                self.wcs = f"G{int(c)}"
            elif c == F(541, 10):
                self.wcs = f"G54.1P{int(other.pop('P'))}"
            elif c == 98:
                self.retract_initial = True
            elif c == 99:
                self.retract_initial = False
            elif c in (0, 1, 2, 3, 33):
                self.motion = int(c)
                self.cycle = None  # [0i]: a group 01 code cancels the canned cycle
            elif c == 80:
                self.cycle = None
            elif c in (73, 74, 76, 81, 82, 83, 84, 85, 86, 89, F(842, 10), F(843, 10)):
                if self.plane != 17:
                    raise RefUnknown("a canned cycle outside G17 (parameter 5101#0 FXY)")
                if self.cycle is None:
                    self.cyc = {"initial": self.pos[2]}
                self.cycle = c
            elif c in (43, 44, 49):
                self.tl_mode = int(c)
                self._pending_tl = "mode"
        if "H" in other and self._pending_tl is None and self.tl_mode in (43, 44):
            # [0i-MB] 14.1.2 "independent specification of the H command": an H word alone in G43/G44
            # mode changes the offset (B-64304EN's example cancels with N12 G00 Z57.0 H00)
            self._pending_tl = "H"
        if "H" in other and (self._pending_tl is not None):
            self.tl_h = int(other["H"])
        if self._pending_tl is not None:
            self._pending_tl = self.tool_length_value()

    def tool_length_value(self) -> Fraction:
        """G43: + (geometry + wear of H); G44: -; G49: 0 ([0i] "Tool length compensation"; memory C)."""
        if self.tl_mode == 49 or self.tl_h == 0:
            return F(0)
        v = self.h_geom.get(self.tl_h, F(0)) + self.h_wear.get(self.tl_h, F(0))
        return v if self.tl_mode == 43 else -v

    def move(self, axes: dict, other: dict, new_tl, kind: str | None = None) -> None:
        """A G00/G01/G02/G03/G33 block.  G90: the end is the commanded point plus the offsets; G91: the
        commanded increment from the current position; an axis not commanded keeps its program position.
        A tool length change: with TOS = 0 the tool axis moves by the change in the same block (B-64304EN
        example: H01 = -4.0, ``G91 G00 G43 Z-32.0 H01`` moves Z by -36)."""
        old_prog = self.program_pos()
        if new_tl is not None:
            self.tl = new_tl
        prog = list(old_prog)
        axes = dict(axes)
        if self.xf is not None and self.xf[0] == "polar":
            axes = self.polar_point(axes)
        for a, v in axes.items():
            i = AXES.index(a)
            prog[i] = v if self.absolute else old_prog[i] + v
        if self.xf is not None:
            prog = self.transformed(prog, axes)
        end = self.to_machine(prog)
        # the axes not commanded and not the tool axis stay where the machine is (a work system change
        # alone does not move, [0i] "Workpiece coordinate system")
        for i in range(2):
            if AXES[i] not in axes:
                end[i] = self.pos[i]
        if "Z" not in axes and new_tl is None:
            end[2] = self.pos[2]
        if kind is None:
            kind = {0: "rapid", 1: "line", 2: "arc", 3: "arc", 33: "line"}[self.motion]
            if kind == "arc" and not axes:
                kind = "line"
        if kind == "arc":
            self.arcs[len(self.motions)] = self.circle(other)
        self.emit(kind, end)

    #: the plane's axes in the order G02 turns clockwise in, viewed from the positive third axis ([0i]
    #: "Circular interpolation (G02, G03)": "the clockwise and counterclockwise directions ... viewed in the
    #: positive-to-negative direction of the Zp (Yp, Xp) axis" in the XpYp (ZpXp, YpZp) plane)
    PLANE_PAIRS = {17: (0, 1), 18: (2, 0), 19: (1, 2)}

    def circle(self, other: dict) -> tuple | None:
        """The circle of the G02/G03 block now moving from ``self.pos``: ``(ia, ib, clockwise, centre, r)``
        with ``(ia, ib)`` the plane's axes (:data:`PLANE_PAIRS`), and either ``centre`` the centre's machine
        coordinates on them (``r`` None) or ``r`` the signed radius (``centre`` None); None for an arc
        this reader gives no circle (under a transform, neither R nor a centre offset).  [0i] "Circular
        interpolation": "I_, J_, K_: distance from the start point to the center of an arc with sign"
        (incremental whatever G90/G91), "R_: arc radius (an arc of more than 180 degrees: a negative
        value)"; R takes precedence over I, J, K written with it."""
        if self.xf is not None:
            return None
        ia, ib = self.PLANE_PAIRS[self.plane]
        cw = self.motion == 2
        if "R" in other:
            return (ia, ib, cw, None, other["R"] * self.unit())
        la, lb = "IJK"[ia], "IJK"[ib]
        if la not in other and lb not in other:
            return None
        u = self.unit()
        centre = (self.pos[ia] + other.get(la, F(0)) * u, self.pos[ib] + other.get(lb, F(0)) * u)
        return (ia, ib, cw, centre, None)

    # -------------------------------------------------------------------------- coordinate transforms

    def transform_codes(self, g: set, other: dict) -> None:
        """G15/G16 polar coordinates, G50/G51 scaling, G50.1/G51.1 mirror image, G69/G68 rotation.

        [0i] "Scaling": ``G51 X_ Y_ Z_ P_``: scaling about (X, Y, Z) by P (P without a decimal point in
        units of 0.001, parameter 5400#7 SCR = 0), the centre omitted: the current position.
        [0i] "Programmable mirror image": ``G51.1 IP_``: a mirror image about the position IP_ of the named
        axes; ``G50.1 IP_`` cancels.  [0i] "Coordinate system rotation": ``G68 a_ b_ R_``: rotation by R
        degrees counter-clockwise about (a, b) in the plane.  [0i] "Polar coordinate command": under G16
        the first axis of the plane is the radius and the second the angle, measured from the workpiece
        zero (G90)."""
        raw = self._raw
        u = self.increment()
        for c in sorted(g):
            if c == 15:
                if self.xf is not None and self.xf[0] == "polar":
                    self.xf = None
            elif c == 16:
                self._one_transform()
                self.xf = ("polar",)
            elif c == 50:
                if self.xf is not None and self.xf[0] == "scale":
                    self.xf = None
            elif c == 51:
                self._one_transform()
                here = self.program_pos()
                cx = other.pop("X", here[0])
                cy = other.pop("Y", here[1])
                cz = other.pop("Z", here[2])
                w = raw.get("P")
                if w is None:
                    raise RefUnknown("G51 without P")
                p = other.pop("P")
                if w.text is not None and "." not in w.text:
                    p = p * F(1, 1000)  # parameter 5400#7 SCR = 0: P in units of 0.001
                if p == 0:
                    raise RefError("scale factor 0")
                self.xf = ("scale", cx, cy, p, cz)  # P scales X, Y and Z
            elif c == F(501, 10):
                if self.xf is not None and self.xf[0] == "mirror":
                    named = [a for a in "XY" if a in other]
                    for a in named:
                        other.pop(a)
                    left = {a: v for a, v in self.xf[1].items() if named and a not in named}
                    self.xf = ("mirror", left) if left else None
            elif c == F(511, 10):
                self._one_transform()
                centres = {a: other.pop(a) for a in "XY" if a in other}
                self.xf = ("mirror", centres)
            elif c == 69:
                if self.xf is not None and self.xf[0] == "rot":
                    self.xf = None
            elif c == 68:
                self._one_transform()
                here = self.program_pos()
                cx = other.pop("X", here[0])
                cy = other.pop("Y", here[1])
                if "R" not in other:
                    raise RefUnknown("G68 without R (parameter 5410)")
                self.xf = ("rot", cx, cy, other.pop("R"))
        del u

    def _one_transform(self) -> None:
        if self.xf is not None:
            raise RefUnknown("two transforms at once")
        if self.plane != 17:
            raise RefUnknown("a transform outside G17")

    @staticmethod
    def _cos_sin(deg: Fraction) -> tuple[Fraction, Fraction]:
        d = deg % 360
        table = {0: (1, 0), 90: (0, 1), 180: (-1, 0), 270: (0, -1)}
        if d not in table:
            raise RefUnknown(f"an angle of {deg} degrees (the reference computes quarter turns only)")
        c, s = table[d]
        return F(c), F(s)

    def polar_point(self, axes: dict) -> dict:
        if not self.absolute:
            raise RefUnknown("G91 in polar mode")
        if "X" in axes:
            self.polar[0] = axes.pop("X")
        if "Y" in axes:
            self.polar[1] = axes.pop("Y")
        c, s = self._cos_sin(self.polar[1])
        axes["X"] = self.polar[0] * c
        axes["Y"] = self.polar[0] * s
        return axes

    def transformed(self, prog: list, axes: dict) -> list:
        """The program point under the active transform, rounded to the least increment ([0i]
        "Increment system": positions are whole increments; halves away from zero)."""
        kind = self.xf[0]
        if kind == "polar":
            return prog
        if not self.absolute or not ("X" in axes and "Y" in axes):
            raise RefUnknown("a move under a transform that is not absolute on X and Y")
        x, y, z = prog
        if kind == "scale":
            _, cx, cy, p, cz = self.xf
            x, y = cx + p * (x - cx), cy + p * (y - cy)
            if "Z" in axes:
                z = cz + p * (z - cz)
        elif kind == "mirror":
            cs = self.xf[1]
            if "X" in cs:
                x = 2 * cs["X"] - x
            if "Y" in cs:
                y = 2 * cs["Y"] - y
        elif kind == "rot":
            _, cx, cy, r = self.xf
            c, s = self._cos_sin(r)
            x, y = cx + (x - cx) * c - (y - cy) * s, cy + (x - cx) * s + (y - cy) * c
        inc = self.increment()
        return [round_half_away(x, inc), round_half_away(y, inc), round_half_away(z, inc)]

    def g29(self, axes: dict) -> None:
        """[0i] "Reference position return": G29 IP_ moves the named axes from the reference position to
        the intermediate point of the last G28/G30, then to IP_."""
        if not self.absolute:
            raise RefUnknown("G29 in G91")
        mid = list(self.pos)
        for a in axes:
            i = AXES.index(a)
            if i not in self.intermediate:
                raise RefUnknown("G29 without an intermediate point on that axis")
            mid[i] = self.intermediate[i]
        self.emit("rapid", mid)
        self.move(axes, {}, None, kind="rapid")

    def g10(self, other: dict) -> None:
        """[0i] "Programmable data input": G10 L2 P0..P6 (EXT, G54..G59), L20 P1..P48 (G54.1), axis values
        absolute in G90, added in G91; L10/L11 P R: tool length geometry / wear (memory C).

        A changed length of the active H takes effect at the next G43/G44 (or H): this follows
        specs/fanuc.md — no manual sentence was found for it, so here the reader is not independent."""
        L, P = int(other["L"]), int(other.get("P", 0))
        u = self.unit()
        if L in (2, 20):
            key = ("EXT" if P == 0 else f"G{53 + P}") if L == 2 else f"G54.1P{P}"
            row = self.work.setdefault(key, [F(0)] * 3)
            for a in AXES:
                if a in other:
                    i = AXES.index(a)
                    row[i] = other[a] * u if self.absolute else row[i] + other[a] * u
        elif L in (10, 11):
            table = self.h_geom if L == 10 else self.h_wear
            r = other["R"] * u
            table[P] = r if self.absolute else table.get(P, F(0)) + r
        elif L in (12, 13):
            pass  # radius offsets: no motion depends on them (G41/G42 are not generated)
        else:
            raise RefUnknown(f"G10 L{L}")

    def g92_set(self, axes: dict) -> None:
        """[0i] "Workpiece coordinate system setting": G92 IP_ shifts the workpiece systems so that the
        current tool position reads IP_ (the programmed position, before the tool length offset).
        In G91: "If IP_ is an incremental command value, the workpiece coordinate system is defined so that
        the current tool position coincides with the result of adding the specified incremental value to
        the coordinates of the previous tool position" (B-64304EN "Setting a workpiece coordinate system",
        method using G92): the new reading is the old one plus the increment."""
        for a, v in axes.items():
            i = AXES.index(a)
            cur = self.program_pos()[i] * self.unit()
            new = v * self.unit() if self.absolute else cur + v * self.unit()
            self.g92[i] += cur - new

    def reference_return(self, c, axes: dict, other: dict) -> None:
        """[0i] "Reference position return": G28 IP_ moves the named axes at rapid to the intermediate
        point (G90/G91 like any positioning), then to the reference position; G30 P2.. to the 2nd.."""
        if not axes:
            raise RefUnknown("G28 without axes")
        p = int(other.get("P", 2)) if c == 30 else 1
        if c == 30 and p != 2:
            raise RefUnknown("G30 P3/P4")
        ref = self.mc.ref1 if c == 28 else self.mc.ref2
        old_prog = self.program_pos()
        mid_prog = list(old_prog)
        for a, v in axes.items():
            i = AXES.index(a)
            mid_prog[i] = v if self.absolute else old_prog[i] + v
        mid = self.to_machine(mid_prog)
        for i in range(3):
            if AXES[i] not in axes:
                mid[i] = self.pos[i]
            else:
                self.intermediate[i] = mid[i]
        self.emit("rapid", mid)
        end = list(mid)
        for a in axes:
            end[AXES.index(a)] = ref[AXES.index(a)]
        self.emit("rapid", end)
        if "Z" in axes and self.tl != 0:
            raise RefUnknown("tool axis returned with a tool length offset (nczones: unknown G28)")

    # -------------------------------------------------------------------------- canned cycles

    def cycle_data(self, other: dict) -> None:
        for key in ("R", "Z", "Q", "P"):
            if key in other:
                self.cyc[key] = other[key]
        self.cyc["abs"] = self.absolute

    def drill(self, other: dict) -> None:
        """[0i] "Canned cycle for drilling": operation 1 positioning of X and Y (rapid), 2 rapid to point R,
        3 the hole, 4 at the bottom, 5 back to point R, 6 rapid to the initial level (G98) or none (G99).
        G90: R and Z are the coordinates of point R and of the bottom; G91: R is the distance from the
        initial level to point R and Z the distance from point R to the bottom.  K repeats (each repeat
        moves by the increment in G91).  Not modelled: a cycle under a coordinate transform (the hole
        positions are rotated, scaled or mirrored; hunt42)."""
        if self.xf is not None:
            raise RefUnknown("a canned cycle under a coordinate transform")
        self.cycle_data(other)
        if "R" not in self.cyc or "Z" not in self.cyc:
            raise RefUnknown("a cycle without R or Z")
        k = int(other.get("K", 1))
        u = self.unit()
        for _ in range(k):
            prog = self.program_pos()
            xy = list(self.pos)
            for a in "XY":
                if a in other:
                    i = AXES.index(a)
                    xy[i] = (other[a] if self.absolute else prog[i] + other[a]) * u + self.offset()[i]
            self.emit("rapid", xy)
            init = self.cyc["initial"]
            zoff = self.offset()[2] + self.tl
            if self.absolute:
                r = self.cyc["R"] * u + zoff
                bottom = self.cyc["Z"] * u + zoff
            else:
                r = init + self.cyc["R"] * u
                bottom = r + self.cyc["Z"] * u
            at = lambda z: [self.pos[0], self.pos[1], z]  # noqa: E731
            back = init if self.retract_initial else r
            self.emit("rapid", at(r))
            c = self.cycle
            if c in (73, 83):
                q = abs(self.cyc["Q"]) * u
                d = (self.mc.g73_retract if c == 73 else self.mc.g83_clearance)
                depth = r
                while True:
                    nxt = max(depth - q, bottom)
                    if c == 73 or depth == r:
                        start_feed = depth
                    else:
                        start_feed = depth + d
                    if c == 83 and depth != r:
                        self.emit("rapid", at(start_feed))
                    self.emit("line", at(nxt))
                    depth = nxt
                    if depth == bottom:
                        break
                    if c == 73:
                        self.emit("rapid", at(depth + d))
                        # the next feed starts from there
                    else:
                        self.emit("rapid", at(r))
                self.emit("rapid", at(back))
            elif c in (81, 82):
                self.emit("line", at(bottom))
                if c == 82:
                    self.emit("dwell", self.pos)
                self.emit("rapid", at(back))
            elif c == 86:
                self.emit("line", at(bottom))
                self.emit("rapid", at(back))
            elif c in (74, 84, 85, 89, F(842, 10), F(843, 10)):
                self.emit("line", at(bottom))
                if c != 85:
                    self.emit("dwell", self.pos)
                self.emit("line", at(r))
                self.emit("rapid", at(back))
            elif c == 76:
                self.emit("line", at(bottom))
                self.emit("dwell", self.pos)
                q = abs(self.cyc["Q"]) * u
                sx = {"+X": (q, 0), "-X": (-q, 0), "+Y": (0, q), "-Y": (0, -q)}[self.mc.boring_shift]
                self.emit("rapid", [self.pos[0] + sx[0], self.pos[1] + sx[1], self.pos[2]])
                self.emit("rapid", at(back))
                self.emit("rapid", [self.pos[0] - sx[0], self.pos[1] - sx[1], self.pos[2]])
            else:
                raise RefUnknown(f"G{c}")

    # -------------------------------------------------------------------------- calls

    def call(self, p: int, new_level: bool) -> None:
        start = self.programs.get(p)
        if start is None:
            raise RefError(f"O{p} missing")
        self.exec_from(start, level_kind="sub")

    def call_macro(self, other: dict, modal: bool) -> None:
        """G65 P L <args> ([0i] "Macro call"): a new local level holding the arguments (specification I:
        A #1, B #2, C #3, I #4, J #5, K #6, D #7, E #8, F #9, H #11, M #13, Q #17, R #18, S #19, T #20,
        U #21, V #22, W #23, X #24, Y #25, Z #26), L times."""
        spec = {"A": 1, "B": 2, "C": 3, "I": 4, "J": 5, "K": 6, "D": 7, "E": 8, "F": 9, "H": 11, "M": 13,
                "Q": 17, "R": 18, "S": 19, "T": 20, "U": 21, "V": 22, "W": 23, "X": 24, "Y": 25, "Z": 26}
        p = int(other["P"])
        count = int(other.get("L", 1))
        args = {spec[a]: float(v) for a, v in other.items() if a in spec}
        for _ in range(count):
            self.locals.append(dict(args))
            saved_call = self.modal_call
            self.modal_call = None  # blocks of the macro are another call level: no modal call there
            try:
                self.call(p, new_level=True)
            finally:
                self.modal_call = saved_call
                self.locals.pop()
        return None


def reference_motion(text: str, machine: RefMachine, *, block_delete: bool = False) -> list:
    """The motion of ``text``: ``[(kind, (x, y, z)), ...]`` in machine coordinates (mm)."""
    return Reader(machine, block_delete=block_delete).run(text)


def reference_motion_with_circles(text: str, machine: RefMachine, *, block_delete: bool = False) -> tuple:
    """``(motion, circles, lengths)``: :func:`reference_motion`'s list, by the index of each arc in it its circle
    (``Reader.circle``: plane axes, direction, centre or signed radius; None where the reader gives none), and the
    tool length offset on Z in force at the end of each motion."""
    reader = Reader(machine, block_delete=block_delete)
    return reader.run(text), dict(reader.arcs), list(reader.lengths)


# ---------------------------------------------------------------------------------------------- lathe

@dataclass
class RefLathe:
    """A two-axis Fanuc lathe (G code system A): X a diameter axis, machine values radii (mm)."""

    work: dict  # "G54".. -> [x (radius), z]
    tool_offsets: dict  # offset number -> (x, z) geometry + wear (radius, mm)
    ref1: tuple = (F(240), F(650))
    start: tuple = (F(240), F(650))
    common: dict = field(default_factory=dict)
    decimal_point_input: str = "calculator"


class LatheReader(Reader):
    """The lathe rules of [0i-T] (FANUC 0i-TD B-64304EN, G code system A):

    * "Diameter and radius programming": on a diameter axis X and U are diameters (the machine moves half);
    * "Absolute and incremental programming": X Z absolute, U W incremental (system A);
    * "Tool offset": T xx yy selects tool xx and offset yy; the offset (geometry + wear) is added to the
      machine position so the tip reaches the programmed point; with parameter 5002#4 LGT = 0 the offset
      shifts the coordinate system: the T block itself does not move;
    * "Coordinate system setting (G50)": G50 X Z makes the current position read X (a diameter) Z;
    * "Canned cycle" G90 (outer diameter cutting: 1 rapid X, 2 feed Z, 3 feed X back, 4 rapid Z back),
      G94 (end face: 1 rapid Z, 2 feed X, 3 feed Z back, 4 rapid X back), G92 (threading: 1 rapid X,
      2 thread along Z, 3 rapid X back, 4 rapid Z back; thread chamfer 0); X (U), Z (W) are modal in the
      cycle: a block with X alone repeats it with the last Z.
    """

    length_letters = LENGTH_LETTERS | set("UW")

    def __init__(self, lathe: RefLathe, *, block_delete: bool = False):
        mc = RefMachine(work={k: [v[0], F(0), v[1]] for k, v in lathe.work.items()}, lengths={},
                        ref1=(lathe.ref1[0], F(0), lathe.ref1[1]), start=(lathe.start[0], F(0), lathe.start[1]),
                        common=lathe.common, decimal_point_input=lathe.decimal_point_input)
        super().__init__(mc, block_delete=block_delete)
        self.lathe = lathe
        self.toff = [F(0), F(0), F(0)]
        self.g50 = [F(0), F(0), F(0)]
        self.plane = 18
        self.lcycle: int | None = None
        self.cyc_xz: dict = {}

    def offset(self) -> list:
        w = self.work.get(self.wcs) or [F(0)] * 3
        return [w[a] + self.g50[a] + self.toff[a] for a in range(3)]

    def run(self, text: str) -> list:
        out = super().run(text)
        return [(k, (e[0], e[2])) for k, e in out]

    def lathe_axes(self, other: dict) -> dict:
        """Program targets (absolute, radius) of the axes named by X Z U W."""
        prog = self.program_pos()
        t = {}
        if "X" in other:
            t["X"] = other["X"] / 2
        elif "U" in other:
            t["X"] = prog[0] + other["U"] / 2
        if "Z" in other:
            t["Z"] = other["Z"]
        elif "W" in other:
            t["Z"] = prog[2] + other["W"]
        return t

    def block(self, ln: Line, pc: int):
        words = ln.words
        gs, other = [], {}
        self._raw = {w.letter: w for w in words}
        for w in words:
            v = self.value(w)
            if v is VACANT:
                continue
            if w.letter == "G":
                gs.append(v)
            else:
                other[w.letter] = v
        g = set(gs)
        if F(65) in g:
            return self.call_macro(other, modal=False)
        m = other.get("M")
        if m in (2, 30):
            return "end"
        if m == 98:
            p = int(other["P"])
            count = int(other.get("L", 1))
            for _ in range(count):
                self.call(p, new_level=False)
            return None
        if m == 99:
            self.ret_label = None
            return "return"
        for c in sorted(g):
            if c in (0, 1, 2, 3, 32):
                self.motion, self.lcycle = int(c), None
            elif c in (90, 92, 94):
                self.lcycle = int(c)
                self.cyc_xz = {}
            elif c in (54, 55, 56, 57, 58, 59):
                self.wcs = f"G{int(c)}"
            elif c in (18, 21, 40, 97, 98, 99, 96):
                pass
            elif c in (4, 50, 28):
                pass
            else:
                raise RefUnknown(f"lathe G{c}")
        if "T" in other:
            t = int(other["T"])
            off = t % 100
            if off == 0:
                raise RefUnknown("T xx00 (parameter 5002#5 LGC decides)")
            x, z = self.lathe.tool_offsets[off]
            self.toff = [x, F(0), z]  # LGT = 0: a shift, no motion in this block
        if F(4) in g:
            self.emit("dwell", self.pos)
            return None
        if F(50) in g:
            # [0i-T] G50 X Z: the current position reads X Z.  "If a coordinate system is set using G50
            # during offset, a coordinate system in which the position before offset matches the position
            # specified in G50 is set": the position before offset is the machine position less the work
            # system and G50 shift only (the tool offset not subtracted), on both axes alike:
            # pos - (work + g50') = value, so g50' = pos - work - value.
            w = self.work.get(self.wcs) or [F(0)] * 3
            for a, i in (("X", 0), ("Z", 2)):
                if a in other:
                    val = other[a] / 2 if a == "X" else other[a]
                    self.g50[i] = self.pos[i] - w[i] - val
            return None
        if F(28) in g:
            t = self.lathe_axes(other)
            mid = list(self.pos)
            for a in t:
                i = 0 if a == "X" else 2
                mid[i] = self.to_machine([t.get("X", F(0)), F(0), t.get("Z", F(0))])[i]
            self.emit("rapid", mid)
            end = list(mid)
            for a in t:
                i = 0 if a == "X" else 2
                end[i] = self.mc.ref1[i]
            self.emit("rapid", end)
            return None
        t = self.lathe_axes(other)
        if not t:
            return None
        if self.lcycle is not None:
            self.cyc_xz.update(t)
            if "X" not in self.cyc_xz or "Z" not in self.cyc_xz:
                raise RefUnknown("a lathe cycle without X or Z")
            self.box_cycle()
            return None
        prog = self.program_pos()
        target = [t.get("X", prog[0]), F(0), t.get("Z", prog[2])]
        end = self.to_machine(target)
        if "X" not in t:
            end[0] = self.pos[0]
        if "Z" not in t:
            end[2] = self.pos[2]
        kind = {0: "rapid", 1: "line", 2: "arc", 3: "arc", 32: "line"}[self.motion]
        self.emit(kind, end)
        return None

    def box_cycle(self) -> None:
        start = list(self.pos)
        tgt = self.to_machine([self.cyc_xz["X"], F(0), self.cyc_xz["Z"]])
        x, z = tgt[0], tgt[2]
        c = self.lcycle
        if c == 90:
            steps = [("rapid", x, start[2]), ("line", x, z), ("line", start[0], z), ("rapid", start[0], start[2])]
        elif c == 94:
            steps = [("rapid", start[0], z), ("line", x, z), ("line", x, start[2]), ("rapid", start[0], start[2])]
        else:
            steps = [("rapid", x, start[2]), ("line", x, z), ("rapid", start[0], z), ("rapid", start[0], start[2])]
        for kind, a, b in steps:
            self.emit(kind, [a, F(0), b])


def reference_lathe_motion(text: str, lathe: RefLathe, *, block_delete: bool = False) -> list:
    """The motion of a lathe program: ``[(kind, (x radius, z)), ...]`` in machine coordinates."""
    return LatheReader(lathe, block_delete=block_delete).run(text)
