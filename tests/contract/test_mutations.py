"""Mutation tests: one small boundary-crossing edit of a safe program must not escape the prover.

Whether the mutant really leaves the allowed set is decided by the
independent brute force (tests/oracles/bruteforce.py), never by the prover.
"""

import re
from fractions import Fraction

from hypothesis import assume, event, given, settings
from hypothesis import strategies as st

from nczones.errors import GcodeError
from nczones.exact import format_decimal, parse_decimal
from nczones.prover import Verdict, verify_segments
from nczones.testing import machines, programs

from .contract import STATS, program_segments
from oracles.bruteforce import first_violation

MOTION = re.compile(r"\bG[0-3]\b")
AXIS_WORD = re.compile(r"\b([XYZ])(-?\d+(?:\.\d+)?)\b")


@st.composite
def mutants(draw, text: str, pulse: Fraction):
    """(kind, mutated text) or None when the mutation does not apply to this program."""
    lines = text.split("\n")
    idx = [i for i, ln in enumerate(lines) if MOTION.search(ln) and i > 1]
    kinds = ["shift", "G90/G91", "work offset"]
    kinds += ["flip arc"] if any(re.search(r"\bG[23]\b", lines[i]) for i in idx) else []
    kinds += ["drop G43"] if "G43" in text else []
    kind = draw(st.sampled_from(kinds))
    if kind == "shift":
        cands = [i for i in idx if AXIS_WORD.search(lines[i]) and not re.search(r"\bG[23]\b", lines[i])]
        if not cands:
            return None
        i = draw(st.sampled_from(cands))
        words = list(AXIS_WORD.finditer(lines[i]))
        w = draw(st.sampled_from(words))
        step = draw(st.sampled_from((pulse, 2 * pulse, 5 * pulse, Fraction(1, 10), Fraction(1), Fraction(10))))
        value = parse_decimal(w.group(2)) + draw(st.sampled_from((1, -1))) * step
        lines[i] = lines[i][: w.start()] + w.group(1) + format_decimal(value) + lines[i][w.end():]
    elif kind == "flip arc":
        cands = [i for i in idx if re.search(r"\bG[23]\b", lines[i])]
        if not cands:
            return None
        i = draw(st.sampled_from(cands))
        lines[i] = re.sub(r"\bG([23])\b", lambda m: "G3" if m.group(1) == "2" else "G2", lines[i], count=1)
    elif kind == "G90/G91":
        i = draw(st.sampled_from(idx)) if idx else None
        if i is None:
            return None
        if re.search(r"\bG9[01]\b", lines[i]):
            lines[i] = re.sub(r"\bG9([01])\b", lambda m: "G91" if m.group(1) == "0" else "G90", lines[i], count=1)
        else:
            lines[i] = draw(st.sampled_from(("G91 ", "G90 "))) + lines[i]
    elif kind == "drop G43":
        cands = [i for i, ln in enumerate(lines) if "G43" in ln]
        if not cands:
            return None
        i = draw(st.sampled_from(cands))
        lines[i] = re.sub(r"G43 H\d+ ?", "", lines[i])
    else:
        i = draw(st.sampled_from(idx)) if idx else None
        if i is None:
            return None
        if re.search(r"\bG5[45]\b", lines[i]):
            lines[i] = re.sub(r"\bG5([45])\b", lambda m: "G55" if m.group(1) == "4" else "G54", lines[i], count=1)
        else:
            lines[i] = "G55 " + lines[i]
    mutated = "\n".join(lines)
    return (kind, mutated) if mutated != text else None


@st.composite
def safe_programs_and_mutants(draw):
    machine = draw(machines(axes=draw(st.sampled_from([("X", "Y"), ("X", "Y", "Z")])),
                            allow_kinds=("stepped", "box", "polygon"), size=100, pulse="0.01"))
    text = draw(programs(machine, max_blocks=6, inside_bias=0.9, boundary_bias=0.8, subprograms=True))
    return machine, text


@settings()
@given(safe_programs_and_mutants(), st.data())
def test_prover_finds_every_mutation_that_really_leaves_the_allowed_set(case, data):
    machine, text = case
    segs = program_segments(text, machine)
    assume(verify_segments(segs, machine, max_violations=1).verdict is Verdict.SAFE)
    assume(first_violation(segs, machine) is None)
    mutant = data.draw(mutants(text, machine.axes[0].pulse))
    assume(mutant is not None)
    kind, mutated = mutant
    try:
        msegs = program_segments(mutated, machine)
    except GcodeError:  # e.g. G91 before an arc whose end is then off its circle
        event(f"mutation {kind}: invalid program")
        assume(False)
    hit = first_violation(msegs, machine)
    result = verify_segments(msegs, machine, max_violations=1)
    label = f"mutation {kind}: " + ("leaves the allowed set" if hit else "stays inside (brute force)")
    STATS[label] += 1
    event(label)
    if hit is not None:
        assert result.verdict is Verdict.UNSAFE, (
            f"mutation {kind!r} leaves the allowed set at {hit.point} (block {hit.block}, zones {hit.zones}) "
            f"but the prover says {result.verdict.label}:\n{mutated}")
        assert result.violations[0].block <= hit.block
    elif result.verdict is Verdict.UNSAFE:
        v = result.violations[0]
        seg = next(s for s in msegs if s.block == v.block)
        assert machine.allowed.violated_zones(dict(v.point), seg.tool_length)
        STATS[f"mutation {kind}: prover finds a violation the brute force's sampling missed"] += 1
