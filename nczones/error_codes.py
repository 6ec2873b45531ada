"""The one catalogue of nczones's codes: every code, its kind and meaning, where it is documented.

A code (``GC101``, ``ZN103``, ``VF203`` ...) names one problem or one reason,
stably: tests, CI annotations and filters key on it.  :data:`CATALOGUE` is
the single source: ``specs/errors.md`` is generated from it
(``python -m nczones.error_codes --write``), and
``tests/packaging/test_error_catalogue.py`` fails when a code in the package
source is not here, a code here is used nowhere (unless reserved or retired),
a code is listed twice, a code is raised as another kind than listed here (an
error code as a reason for unknown: a second meaning), the page is stale, or
a spec names a code that is not here.

The kinds:

* ``error``: an input error (:class:`nczones.errors.InputError`, exit 2);
* ``warning`` / ``note``: a diagnostic that stops nothing;
* ``unknown``: the code of a reason for the verdict ``unknown``
  (:class:`nczones.prover.result.Reason`);
* ``rule``: a SARIF rule id of ``nczones verify --format sarif``.

This module is imported by the tests and the page generator only, never on
the command line's start-up path.
"""

from __future__ import annotations

import re
import sys
from dataclasses import dataclass

__all__ = ["Code", "Family", "CATALOGUE", "FAMILIES", "KINDS", "CODE_PATTERN", "TWO_MEANINGS", "PAGE",
           "by_code", "family_of", "render_page", "main"]

#: What a code looks like: two or three capital letters and three digits.
CODE_PATTERN = re.compile(r"\b([A-Z]{2,3})(\d{3})\b")

#: The kinds a code can have (see the module docstring).
KINDS = ("error", "warning", "note", "unknown", "rule")

#: Where :func:`render_page` is written, relative to the repository root.
PAGE = "specs/errors.md"


@dataclass(frozen=True, slots=True)
class Family:
    """A range of codes with one subject: ``prefix`` and the hundreds digit(s) ``first``..``last``."""

    prefix: str
    first: int
    last: int
    title: str

    def holds(self, code: str) -> bool:
        m = CODE_PATTERN.fullmatch(code)
        return m is not None and m.group(1) == self.prefix and self.first <= int(m.group(2)) <= self.last


@dataclass(frozen=True, slots=True)
class Code:
    """One code.

    ``kind`` is one of :data:`KINDS`, or two joined by ``" / "`` when one code
    is raised both ways (an error at one site, a reason for ``unknown`` at
    another; see :data:`TWO_MEANINGS`).  ``doc`` is the file that documents it
    in detail (it must name the code), or ``""`` when this catalogue and
    ``specs/errors.md`` are its only documentation.  ``status`` is ``used``,
    ``reserved`` (not raised yet) or ``retired`` (raised no more, never reused).
    """

    code: str
    kind: str
    doc: str
    meaning: str
    status: str = "used"


FAMILIES: tuple[Family, ...] = (
    Family("GC", 100, 199, "G-code text: reading the file, lexical errors"),
    Family("GC", 200, 299, "G-code blocks: words, modal groups, what a block may hold"),
    Family("GC", 300, 399, "G-code interpretation: run-time errors and reasons for unknown"),
    Family("ZN", 0, 199, "Machine file"),
    Family("IM", 100, 199, "import-machine: a controller configuration it cannot read (errors)"),
    Family("IM", 200, 299, "import-machine: what it did not take as written (notes)"),
    Family("EX", 100, 199, "export-zones: what the control's settings cannot hold (notes)"),
    Family("VF", 100, 199, "verify: the command line and its input files"),
    Family("VF", 200, 299, "verify: reasons for unknown from the proof"),
    Family("RC", 200, 299, "Recovery (tool-change restart) proofs: reasons for unknown"),
    Family("SM", 100, 199, "simulate"),
    Family("PL", 100, 199, "plot"),
    Family("RP", 100, 199, "replay"),
    Family("FL", 100, 199, "fleet: the project file and the command line"),
    Family("FL", 200, 299, "fleet: a run"),
    Family("FL", 300, 399, "fleet: the result store"),
    Family("LF", 100, 199, "LinuxCNC filter (linuxcnc-filter, import-machine --linuxcnc-filter)"),
    Family("PK", 100, 199, "Optional packages (extras)"),
    Family("NCZ", 0, 99, "SARIF rules of verify --format sarif"),
)

_E, _W, _N, _U, _R = KINDS

_GS = "specs/gcode-support.md"
_FA = "specs/fanuc.md"
_TU = "specs/turning.md"
_CY = "specs/cylindrical.md"
_MF = "specs/machine-file.md"
_MI = "specs/machine-import.md"
_HO = "specs/homing.md"
_RE = "specs/recovery.md"
_FL = "specs/fleet.md"
_LF = "docs/linuxcnc-filter.md"
_CI = "docs/ci.md"
_RM = "README.md"

#: Codes that still mean two things (one code, two unrelated problems): each is a debt, to be split by giving
#: one meaning a new code.  Empty since issue 34 split VF105 (VF112) and GC301-GC305, GC311 (GC391-GC395,
#: GC326).  The test fails when a code here is no longer doubly used (remove it then) and
#: when a code not here is marked ``" / "`` in its kind.
TWO_MEANINGS: frozenset[str] = frozenset()

CATALOGUE: tuple[Code, ...] = (
    # -- GC1xx: reading the program, lexical
    Code("GC100", _E, _GS, "the program file cannot be read (no such file, a directory, no permission)"),
    Code("GC101", _E, _FA, "an unexpected character or a malformed block (a character no word starts with, "
                           "text after ';' in the fanuc dialect, '/0', a comment inside a word, a wrong path header)"),
    Code("GC102", _E, "", "a comment not closed: missing ')'"),
    Code("GC103", _E, "", "a nested comment: '(' inside a comment (LinuxCNC)"),
    Code("GC104", _E, "", "a number expected and not found, or a number too large "
                          "(a letter without a value, a bad sequence number)"),
    Code("GC105", _E, _FA, "a malformed expression: brackets not closed or nested too deep, a function "
                           "without its bracketed arguments"),
    Code("GC106", _E, "", "an unknown function name in an expression (the message lists the known ones)"),
    Code("GC107", _E, "", "a malformed parameter (variable) reference after '#': no number, '[expression]' "
                          "or '<name>', an unterminated or empty name, '##n' or '#_name' in the fanuc dialect"),
    Code("GC108", _E, _GS, "the bytes are not text: not UTF-8 outside comments, a bad UTF-16 file, a NUL byte"),
    Code("GC109", _E, _GS, "the program is empty or only whitespace"),
    Code("GC110", _E, _GS, "a line longer than 65,536 characters"),
    # -- GC2xx: blocks, words, modal groups
    Code("GC201", _E, _GS, "two codes of one modal group in a block (or a word out of its place: N not first, "
                           "G65/G66/G67 together)"),
    Code("GC202", _E, _GS, "an unknown or unsupported G/M code or statement, or one out of its place "
                           "(an O-word not first, a malformed macro statement)"),
    Code("GC203", _E, _GS, "an axis word for an axis the machine does not have; '=' missing in an assignment"),
    Code("GC204", _E, _GS, "a word written twice, a word no code of the block uses, or words that do not go "
                           "together (R and I/J/K in one arc, a canned cycle with comp or G93 ...)"),
    Code("GC205", _E, _GS, "two G codes that use axis words, axis words with G80, polar words out of place; "
                           "a parameter/variable number that does not exist or is read-only"),
    Code("GC206", _E, "", "too many M words in one block (LinuxCNC: 4, Fanuc: 3)"),
    Code("GC207", _E, _GS, "G53 misused: without G0/G1, in G91, with an arc, a cycle or polar words"),
    Code("GC208", _E, _GS, "a word a code needs is missing (G10 without L, G4 without P, G5 without I/J, "
                           "G92/G52 without an axis word ...)"),
    Code("GC209", _E, _GS, "a word's value out of its allowed range (negative F or S, a non-integer or negative "
                           "tool, register or P number, L not among G10's ...)"),
    Code("GC210", _E, "", "an axis word a canned cycle (or a lathe cycle) cannot take"),
    Code("GC230", _E, _CY, "cylindrical interpolation (G07.1): a G code the mode does not allow"),
    Code("GC231", _E, _CY, "cylindrical interpolation: I/J/K, an arc without R, H, an arc with another axis"),
    Code("GC232", _E, _CY, "cylindrical interpolation: G07.1 not alone in its block, without exactly one rotary "
                           "axis word, or on a machine without the parallel linear axis"),
    Code("GC233", _E, _CY, "cylindrical interpolation: a negative cylinder radius"),
    Code("GC234", _E, _TU, "polar coordinate interpolation (G12.1): a G code the mode does not allow"),
    Code("GC235", _E, _TU, "polar coordinate interpolation: a word a motion block cannot hold, an arc without "
                           "I/J or R, or with both"),
    Code("GC236", _E, _TU, "polar coordinate interpolation on a machine without the linear axis X and rotary "
                           "axis C"),
    # -- GC3xx: interpretation
    Code("GC301", _E, _GS, "an arc's end point off its circle by more than the arc tolerance"),
    Code("GC302", _E, _MF, "an R arc's radius too small to reach its end point"),
    Code("GC303", _E, "", "an R arc whose end point equals its start point: the centre is undefined"),
    Code("GC304", _E, "", "a zero-radius arc (R0, or the centre at the start or end point; LinuxCNC: an I/J/K "
                          "radius below its 0.00005 inch, \"Zero-radius arc\")"),
    Code("GC305", _E, _GS, "a block the control refuses in its run-time state: feed 0, the spindle not turning "
                           "for G33/G84/G95, an (ABORT, ...), polar words at the origin, G93 without F"),
    Code("GC306", _E, "", "a canned cycle's retract plane R below its bottom"),
    Code("GC308", _E, "", "a plane, arc, cycle, spline or rotation needs axes this machine does not have"),
    Code("GC310", _E, _MF, "a tool register or named parameter the program uses is not defined (H not in "
                           "[tool_lengths], a lathe tool offset, #<name> never set)"),
    Code("GC311", _E, _FA, "division or MOD by zero"),
    Code("GC312", _E, _FA, "a computation that cannot be done: a function's domain, overflow, infinity or "
                           "not a number, an expression nested too deep"),
    Code("GC313", _E, _GS, "a subroutine called but not defined where it must be (skipped definition, a folder "
                           "file without its sub, a lathe-cycle profile missing)"),
    Code("GC314", _E, _GS, "a misplaced or unmatched control statement: o-word sub/loop/if structure, DO/END, "
                           "GOTO to a missing N, a definition met twice"),
    Code("GC315", _E, "", "a subroutine ending wrongly: M99 inside an o-word sub, endsub/return outside a "
                          "subroutine, a lathe-cycle profile without endsub"),
    Code("GC316", _E, _GS, "subroutine or macro calls nested too deep"),
    Code("GC317", _E, _FA, "a bad M98/M97/G65 call: no P, a bad program number or repeat count, no such "
                           "subprogram"),
    Code("GC318", _E, _GS, "an assignment to a read-only named parameter (#<_value> ...)"),
    Code("GC320", _E, _GS, "cutter compensation turned on in a wrong state (G19, already on, a bad D word)"),
    Code("GC321", _E, _GS, "cutter compensation: no diameter for the tool"),
    Code("GC322", _E, _GS, "cutter compensation: the entry move or arc not longer than the radius"),
    Code("GC323", _E, _GS, "cutter compensation: the tool radius not less than an inside arc's radius"),
    Code("GC324", _E, _GS, "cutter compensation: a concave corner the tool cannot reach without gouging"),
    Code("GC325", _E, _GS, "cutter compensation: an operation LinuxCNC refuses while it is on"),
    Code("GC326", _E, _GS, "cutter compensation: the move right after G40 is an arc (LinuxCNC requires a "
                           "straight one; GC311 until issue 34)"),
    Code("GC329", _E, _GS, "cutter compensation: LinuxCNC's internal consistency checks"),
    Code("GC330", _E, _CY, "an arc that cannot be drawn in cylindrical or polar coordinate interpolation (R0, "
                           "equal start and end, a chord longer than 2|R|)"),
    Code("GC390", _U, _GS, "a construct nczones does not model; the message starts with the construct"),
    Code("GC391", _U, _GS, "a Fanuc or Haas construct in a LinuxCNC program: a macro statement (IF, GOTO, "
                           "WHILE), M97, G65-type calls, #3000, M99 P (GC301 until issue 34)"),
    Code("GC392", _U, _GS, "a loop, an M98 L repeat or a lathe-cycle profile past max_iterations "
                           "(GC302 until issue 34)"),
    Code("GC393", _U, _GS, "a subroutine called but found in no file or folder; --library or the machine "
                           "file's subroutine_path names where (GC303 until issue 34)"),
    Code("GC394", _U, _GS, "M99 in the main program, which restarts it forever (GC304 until issue 34)"),
    Code("GC395", _U, _GS, "controller state nczones does not know: a state parameter, HAL pin or INI value "
                           "read, or a state parameter assigned (GC305 until issue 34)"),
    Code("GC396", _U, _FA, "a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW whose one-ulp neighbours give a "
                           "different integer, comparison, domain or alarm (a control's library may give them)"),
    Code("GC397", _U, _FA, "a result of SIN/COS/TAN/ATAN/ASIN/ACOS/LN/EXP/POW whose one-ulp neighbours round to "
                           "different increments at an address, or that an address takes as it is (F, G51)"),
    Code("GC398", _U, _FA, "a Fanuc macro value whose readings (the double as it is, its 15-digit decimal, the "
                           "exact value) give different results for FIX/FUP/ROUND/MOD/AND/OR/XOR/BIN/BCD, a "
                           "comparison or a variable number"),
    Code("GC399", _U, _FA, "a Fanuc macro value at half an increment whose readings (its 15-digit decimal, the "
                           "double scaled in doubles, the exact value) round to different increments"),
    # -- ZN: machine file
    Code("ZN099", _E, _MF, "the machine file cannot be read (missing, a directory, no permission, not UTF-8)"),
    Code("ZN100", _E, _MF, "not valid TOML (or a controller configuration given as the machine file)"),
    Code("ZN101", _E, _MF, "unknown key, section, work offset or tool register"),
    Code("ZN102", _E, _MF, "something required is missing"),
    Code("ZN103", _E, _MF, "wrong type, or text that is not a decimal"),
    Code("ZN104", _E, _MF, "a number that is not finite"),
    Code("ZN105", _E, _MF, "a number out of range"),
    Code("ZN106", _E, _MF, "a value that must be greater than 0 (or not negative)"),
    Code("ZN107", _E, _MF, "a value not among the allowed choices (units, rapid_mode, modal, zone kind, point)"),
    Code("ZN108", _E, _MF, "two modal codes of the same group"),
    Code("ZN110", _E, _MF, "unknown axis"),
    Code("ZN111", _E, _MF, "an axis named twice"),
    Code("ZN112", _E, _MF, "two zones with the same name"),
    Code("ZN113", _E, _MF, "a tip zone on a machine without a tool axis"),
    Code("ZN114", _E, _MF, "a setting not among its choices (type, dialect, cutter_compensation, arc_tolerance, "
                           "block_delete, control_units, path_mode, [fanuc] keys)"),
    Code("ZN115", _W, _MF, "a section or key this machine's dialect or type does not read (ignored)"),
    Code("ZN120", _E, _MF, "an empty zone"),
    Code("ZN121", _E, _MF, "upto not strictly increasing"),
    Code("ZN122", _E, _MF, "min greater than max"),
    Code("ZN123", _E, _MF, "polygon vertices malformed"),
    Code("ZN124", _E, _MF, "polygon not simple"),
    Code("ZN130", _E, _MF, "the start position is outside the allowed set"),
    Code("ZN131", _W, _MF, "the reference position is outside the allowed set"),
    Code("ZN140", _E, _HO, "[homing]: unknown key"),
    Code("ZN141", _E, _HO, "[homing] is not a table of axis tables, or names an axis the machine does not have"),
    Code("ZN142", _E, _HO, "[homing]: a required key is missing"),
    Code("ZN143", _E, _HO, "[homing]: direction is not one of the accepted words or signs"),
    Code("ZN144", _E, _HO, "[homing]: search_speed or latch_speed not greater than 0"),
    Code("ZN145", _E, _HO, "[homing]: detector_phase outside [0, grid_pitch)"),
    Code("ZN146", _E, _HO, "[homing]: grid_pitch or dog_length not > 0, switch_jitter or servo_lag_ms negative"),
    Code("ZN147", _E, _HO, "[homing]: 2 * switch_jitter >= grid_pitch"),
    Code("ZN148", _E, _HO, "[homing]: a position not a whole number of the axis' pulses"),
    Code("ZN150", _E, _RE, "[tool_change]: unknown key"),
    Code("ZN151", _E, _RE, "[tool_change] is not a table, or a required key or axis is missing"),
    Code("ZN152", _E, _RE, "[tool_change]: unknown axis, or a rotary retract_axis"),
    Code("ZN153", _E, _RE, "[tool_change]: not a number, not finite or out of range"),
    Code("ZN154", _E, _RE, "[tool_change]: a negative distance or a non-positive feed"),
    Code("ZN155", _E, _RE, "[tool_change]: variant other than start / breakpoint"),
    Code("ZN156", _E, _RE, "[tool_change]: both or neither of clearance and retract_distance"),
    Code("ZN157", _E, _RE, "[tool_change]: length_register is not H<n>, or not in [tool_lengths]"),
    Code("ZN160", _E, _MF, "[[tools]], [spindle], [[fixtures]]: unknown key"),
    Code("ZN161", _E, _MF, "[[tools]], [spindle], [[fixtures]]: not a table or list, a missing key or name"),
    Code("ZN162", _E, _MF, "[[tools]]: number not a tool number 0..9999, or a tool described twice"),
    Code("ZN163", _E, _MF, "[[fixtures]]: kind not box / cylinder, or an empty box or cylinder"),
    Code("ZN164", _E, _MF, "tool or fixture solids on a machine without the axes X, Y and Z"),
    Code("ZN165", _E, _MF, "a lathe tool part: x or z not a [low, high] pair with low below high"),
    Code("ZN166", _E, _MF, "a lathe fixture: kind not chuck / cylinder, or an empty ring or height range"),
    Code("ZN170", _E, _MF, "[[fixtures]]: frame not a work offset (G54..G59.3, G54.1 Pn)"),
    # -- IM: import-machine
    Code("IM100", _E, _MI, "the configuration cannot be read (missing, a directory, no permission, not UTF-8, "
                           "binary)"),
    Code("IM101", _E, _MI, "the kind of configuration cannot be told, or cannot be imported; give --kind"),
    Code("IM102", _E, _MI, "a malformed line"),
    Code("IM103", _E, _MI, "not a number where one is needed"),
    Code("IM104", _E, _MI, "a number out of range"),
    Code("IM105", _E, _MI, "a word or code the control does not accept"),
    Code("IM106", _E, _MI, "units the machine file cannot express exactly, or an axis type that disagrees with "
                           "its letter"),
    Code("IM107", _E, _MI, "something required is missing, or a Grbl dump whose layout cannot be told"),
    Code("IM108", _E, _MI, "a contradiction the control refuses too (min above max, a setting given twice, an "
                           "include loop ...)"),
    Code("IM109", _E, _MI, "a file the configuration names exists but cannot be read"),
    Code("IM110", _E, _MI, "the configuration gives a machine the machine file refuses"),
    Code("IM111", _E, _MI, "LinuxCNC TOOL_CHANGE_AT_G30 with a G30 position other than the G28 position"),
    Code("IM201", _N, _MI, "not taken: the source sets something the machine file has no place for"),
    Code("IM202", _N, _MI, "rounded: an exact value that is not a finite decimal"),
    Code("IM203", _N, _MI, "assumed: the source leaves something to the control's default, and the import "
                           "takes that default"),
    Code("IM204", _N, _MI, "skipped: a tool-table line LinuxCNC skips too"),
    Code("IM205", _N, _MI, "paired by offset number: a cutter solid started from a Fanuc offset listing takes D<n> "
         "for the assembly under G43 H<n>, which the control does not tie together"),
    # -- EX: export-zones
    Code("EX101", _N, _MI, "a zone the control cannot hold"),
    Code("EX102", _N, _MI, "a value rounded to what the control can write"),
    Code("EX103", _N, _MI, "a bound the control cannot write"),
    # -- VF1xx: verify's command line and input files
    Code("VF101", _E, "", "--param: malformed (not NAME=VALUE or NAME=LOW..HIGH, a bad number)"),
    Code("VF102", _E, "", "--margin: not a decimal number of mm, or negative"),
    Code("VF103", _E, "", "--max-violations below 1"),
    Code("VF104", _E, "", "--arc-tolerance: not a non-negative decimal, linuxcnc or grbl"),
    Code("VF105", _E, "", "--max-iterations below 1"),
    Code("VF106", _E, "", "programs that cannot go together: standard input given twice, --format html with "
                          "more than one program"),
    Code("VF107", _E, "", "--output: the report cannot be written"),
    Code("VF108", _E, "", "--sarif-root: not a directory"),
    Code("VF109", _E, "", "--budget: not a positive number of seconds or none"),
    Code("VF110", _E, "", "--block-delete: not a valid switch setting"),
    Code("VF111", _E, _MF, "--tool-table: the file cannot be read, is neither format, lacks its units, or a "
                           "line of a Fanuc offset listing is wrong (verify; import-machine reads a listing so too)"),
    Code("VF112", _E, "", "--library: not a folder of subprogram files (VF105 until issue 34)"),
    # -- VF2xx: reasons for unknown
    Code("VF201", _U, _RM, "the solver's resource limit, or a ranged path with too many cases"),
    Code("VF202", _U, _RM, "the solver's time backstop"),
    Code("VF203", _U, _RM, "the run's --budget is spent"),
    Code("VF204", _U, _RM, "interrupted (Ctrl-C, SIGTERM): the rest was not checked"),
    Code("VF205", _U, "", "the solver could not decide (incomplete)"),
    Code("VF206", _U, _RM, "block-delete switch positions: the program is verified in some of them only"),
    Code("VF207", _U, _RM, "a lathe tool's nose radius with a zone the nose cannot be checked against"),
    Code("VF208", _U, "specs/path-modes.md", "a corner the control may round (G64, Fanuc cutting mode) may leave "
                                               "the allowed set"),
    Code("VF210", _U, _MF, "tool solids: an arc near a fixture its enclosure cannot decide, a motion kind "
                           "the solids proof does not model"),
    Code("VF211", _U, _MF, "tool solids: a motion under G49 (no H register names the tool in the spindle)"),
    Code("VF212", _U, _MF, "a lathe's tool solids with parameter ranges or tool-break recovery were not checked; "
                           "both are proved now, as a mill's (VF218/VF220)", "retired"),
    Code("VF218", _U, _MF, "tool solids (a mill's or a lathe's): a part may meet a fixture somewhere in the "
                           "parameter ranges, not at their nominal values"),
    Code("VF219", _U, _MF, "tool solids: a fixture in a work offset at a motion whose frame does not give "
                           "that offset (another work offset active, a rotated frame)"),
    Code("VF220", _U, _MF, "tool solids (a mill's or a lathe's): tool-break recovery legs near a fixture the proof "
                           "cannot decide"),
    Code("VF231", _U, "", "a witness over parameter ranges whose block runs at its values without its point in "
                          "its zone (its motion there misses the point): it does not replay, and no other is left"),
    Code("VF232", _U, "", "a witness over parameter ranges at values where the control refuses a block (before "
                          "its block, or after it) or the program stops before its block: it does not replay, and "
                          "no other is left"),
    Code("VF233", _U, _MF, "tool solids: a part may meet a fixture within the G64 P (or path_tolerance) bound of "
                           "the programmed path, which itself clears it"),
    Code("VF234", _U, _MF, "tool solids: a part may meet a fixture in a corner region the control may round "
                           "without tolerance (G64), while the programmed path clears it"),
    Code("VF235", _U, _MF, "tool solids: a path mode whose rounded corners the solids proof does not model "
                           "(G64 Q without P, Fanuc cutting mode without path_tolerance, a lathe without a tolerance)"),
    # -- RC: recovery
    Code("RC201", _U, _RE, "a recovery (break) motion nczones does not encode"),
    Code("RC202", _U, _RE, "recovery: the solver's limit"),
    Code("RC203", _U, _RE, "recovery: a thin set the proof cannot decide"),
    Code("RC204", _U, _RE, "recovery over parameter ranges is not modelled"),
    # -- SM: simulate
    Code("SM101", _E, "", "--accdec-before-ms / --accdec-after-ms: not a non-negative decimal number of ms"),
    Code("SM102", _E, "", "simulate --max-iterations below 1"),
    Code("SM110", _E, _RE, "--break-at: the line has no cutting motion that ran"),
    Code("SM111", _E, _RE, "--break-at: malformed (not LINE[:FRACTION])"),
    # -- PL: plot
    Code("PL101", _E, "", "--plane: not two different axes of the machine"),
    Code("PL102", _E, "", "a plot needs a machine with two axes or more"),
    Code("PL103", _E, "", "-o: the file name must end in .png, .svg or .pdf"),
    Code("PL104", _E, "", "-o: the file cannot be written"),
    # -- RP: replay
    Code("RP100", _E, "", "the report cannot be read"),
    Code("RP101", _E, "", "not a JSON report of nczones verify"),
    Code("RP102", _E, "", "the program or machine file is not the one the report was made from (SHA-256)"),
    Code("RP103", _E, "", "the report names no machine file or program file (pass --machine / --program), "
                          "or --base is not a directory"),
    Code("RP104", _E, "", "a value in the report is malformed (parameters, margin, params_exact)"),
    Code("RP105", _E, "", "a solid violation (kind = \"solid\") on a machine file without tool or spindle solids"),
    Code("RP106", _E, "", "a solid violation that does not name its tool part (zones = [part])"),
    # -- FL: fleet
    Code("FL100", _E, _FL, "no project file"),
    Code("FL101", _E, _FL, "the project file is not UTF-8 or not TOML"),
    Code("FL102", _E, _FL, "an unknown or malformed table in the project file"),
    Code("FL103", _E, _FL, "a bad machine entry or glob list"),
    Code("FL104", _E, _FL, "an unknown or unsupported setting"),
    Code("FL105", _E, _FL, "a bad setting value"),
    Code("FL110", _E, "", "fleet's command line: --split-lines or --workers below 1, --format html without "
                          "--output"),
    Code("FL111", _E, "", "the Dask scheduler cannot be reached"),
    Code("FL112", _E, _FL, "no program selected"),
    Code("FL201", _E, _FL, "a program changed while the fleet ran"),
    Code("FL300", _E, "", "no result store, or no run (or no two runs for a diff) in it yet"),
    Code("FL301", _E, _FL, "not a result store this nczones can read"),
    # -- LF: LinuxCNC filter
    Code("LF101", _E, _LF, "no machine file"),
    Code("LF102", _E, _LF, "the INI file cannot be read"),
    Code("LF103", _E, _LF, "import-machine --linuxcnc-filter without a LinuxCNC INI or without -o"),
    # -- PK: extras
    Code("PK101", _E, _RM, "a command needs an optional package (extra) that is not installed"),
    # -- NCZ: SARIF rules
    Code("NCZ001", _R, _CI, "a motion leaves the allowed set"),
    Code("NCZ002", _R, _RM, "a recovery motion leaves the allowed set"),
    Code("NCZ003", _R, _CI, "not proved: the verdict is unknown"),
)


def by_code() -> dict[str, Code]:
    """The catalogue as a mapping code → entry."""
    return {c.code: c for c in CATALOGUE}


def family_of(code: str) -> Family | None:
    """The family a code belongs to, or None."""
    return next((f for f in FAMILIES if f.holds(code)), None)


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def render_page() -> str:
    """``specs/errors.md``: every code once, by family."""
    out = [
        "# Error codes",
        "",
        "<!-- Generated from nczones/error_codes.py by `python -m nczones.error_codes --write`; do not edit. -->",
        "",
        "Every code nczones reports, once: a diagnostic (`error`: exit 2; `warning`, `note`: nothing stops), the",
        "code of a reason for the verdict `unknown`, or a SARIF rule. A code is stable: it keeps its meaning and",
        "is never reused. \"Documented in\" names the page that says more; an empty cell: this page is its",
        "documentation. A kind such as `error / unknown` would mark a code raised both ways for two problems, a",
        "debt listed in `TWO_MEANINGS` of the catalogue (none is left).",
        "",
    ]
    entries = by_code()
    for fam in FAMILIES:
        rows = sorted(c for c in entries if fam.holds(c))
        if not rows:
            continue
        lo, hi = (f"{fam.prefix}{n:03d}" for n in (fam.first, fam.last))
        out += [f"## {fam.prefix}: {fam.title} ({lo}-{hi})", "",
                "| code | kind | meaning | documented in |", "|---|---|---|---|"]
        for code in rows:
            c = entries[code]
            status = "" if c.status == "used" else f" ({c.status})"
            doc = f"`{c.doc}`" if c.doc else ""
            out.append(f"| {c.code} | {c.kind}{status} | {_cell(c.meaning)} | {doc} |")
        out.append("")
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    """``python -m nczones.error_codes [--write | --check]`` (run from the repository root)."""
    from pathlib import Path

    args = sys.argv[1:] if argv is None else argv
    page = render_page()
    if not args:
        sys.stdout.write(page)
        return 0
    path = Path(PAGE)
    if args == ["--write"]:
        path.write_text(page, encoding="utf-8")
        return 0
    if args == ["--check"]:
        current = path.read_text(encoding="utf-8") if path.exists() else ""
        if current != page:
            print(f"{PAGE} is stale: run python -m nczones.error_codes --write", file=sys.stderr)
            return 1
        return 0
    print("usage: python -m nczones.error_codes [--write | --check]", file=sys.stderr)
    return 2


if __name__ == "__main__":
    raise SystemExit(main())
