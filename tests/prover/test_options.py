"""VerifyOptions (issue 34): one value for every setting of a verification, read from the keywords, the
command line, a report's and a fleet job's settings, written back as the report's settings.

The expected values come from what the user wrote (``--margin 0.50`` is one half, ``--budget none`` no
budget) and from the old paths these replace: a report's settings must survive a round trip (``nczones
replay`` re-reads them), and a fleet job's settings must give the options the old keyword mapping
(``nczones.fleet.project.verify_kwargs`` + ``verify(**kwargs)``) gave.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones.cli import build_parser
from nczones.errors import InputError
from nczones.fleet.project import SETTINGS, verify_kwargs
from nczones.gcode import interpret_text
from nczones.machine import parse_machine
from nczones.prover import VerifyOptions, verify_text
from nczones.prover.core import prove
from nczones.prover.limits import DEFAULT_BUDGET_S
from nczones.prover.result import ParamRange
from tests.machines import machine_text

MACHINE = parse_machine(machine_text("options_mill_h1"))

PROGRAM = "G90 G21\n/G1 X30 F100\nG1 X10 Y10 F100\nG2 X10 Y10 I5 J0\nM2\n"


def parse(*argv: str):
    return build_parser("verify").parse_args(["verify", "p.ngc", "--machine", "m.toml", *argv])


def test_the_command_line_is_read_as_written():
    args = parse("--margin", "0.50", "--param", "G54.X=-1..1", "--param", "H1=99..101", "--budget", "none",
                 "--block-delete", "1=on", "--arc-tolerance", "0.01", "--max-iterations", "7",
                 "--max-violations", "3", "--engine", "z3", "--recovery", "start", "--dialect", "fanuc")
    o = VerifyOptions.from_args(args, MACHINE)
    assert o.margin == Fraction(1, 2) and o.budget_s is None and o.block_delete == "1=on"  # the other switches: both
    assert o.arc_tolerance == Fraction(1, 100) and (o.max_iterations, o.max_violations) == (7, 3)
    assert (o.engine, o.recovery, o.dialect) == ("z3", "start", "fanuc")
    # a tool length range is absolute as written, a deviation from the machine file's H1 = 100 inside
    assert o.params == (ParamRange("G54.X", Fraction(-1), Fraction(1), (Fraction(-1), Fraction(1))),
                        ParamRange("H1", Fraction(-1), Fraction(1), (Fraction(99), Fraction(101)), absolute=True))
    assert VerifyOptions.from_args(parse(), MACHINE) == VerifyOptions()  # no option: verify()'s defaults
    assert VerifyOptions().budget_s == DEFAULT_BUDGET_S


def test_every_bad_value_is_one_diagnostic_of_one_error():
    with pytest.raises(InputError) as e:
        VerifyOptions.from_args(parse("--margin", "-.5", "--max-violations", "0", "--budget", "0",
                                      "--block-delete", "7=up"), MACHINE)
    assert [d.code for d in e.value.diagnostics] == ["VF102", "VF103", "VF110", "VF109"]
    assert e.value.diagnostics[0].message == "--margin -.5: must not be negative"  # the text as written
    assert VerifyOptions().validate() == ()
    assert [d.code for d in VerifyOptions(max_iterations=0, arc_tolerance=Fraction(-1)).validate()] == \
        ["VF105", "VF104"]


def test_a_reports_settings_survive_the_round_trip():
    r = verify_text(PROGRAM, MACHINE, margin="0.25", params=["G54.X=-1..1"], block_delete="off",
                    max_violations=5, budget_s=30)
    settings_ = dict(r.settings)
    assert settings_["margin"] == "0.25" and settings_["params"] == ("G54.X=-1..1",)
    assert settings_["block_delete"] == "off" and settings_["budget_s"] == 30
    again = VerifyOptions.from_settings(settings_)
    assert again.to_settings(MACHINE) == r.settings
    assert again.margin == Fraction(1, 4) and again.max_violations == 5


def test_prove_takes_motion_not_text():
    """The prover's entry point proves the interpreter's motion with the options; the text's verdict is
    the same through the pipeline (the arc of line 4 bulges to X = 20 + margin 0.25 > 20: unsafe)."""
    options = VerifyOptions(margin=Fraction(1, 4), block_delete="on")
    motion = interpret_text(PROGRAM, MACHINE, block_delete=True).segments()
    direct = prove(motion, MACHINE, options)
    piped = verify_text(PROGRAM, MACHINE, margin="0.25", block_delete="on")
    assert direct.verdict == piped.verdict
    assert [(v.line, v.zone) for v in direct.violations] == [(v.line, v.zone) for v in piped.violations] == \
        [(4, "travel")]


FLEET_VALUES = {
    "margin": st.sampled_from(["0", "0.5", "1.25"]),
    "params": st.lists(st.sampled_from(["G54.X=-1..1", "H1=99..101", "start.Z=-2..0"]), max_size=2,
                       unique=True),
    "recovery": st.sampled_from(["start", "breakpoint"]),
    "engine": st.sampled_from(["auto", "z3"]),
    "arc_tolerance": st.sampled_from(["0.002", "linuxcnc", "grbl"]),
    "max_iterations": st.integers(1, 10_000),
    "max_violations": st.integers(1, 50),
    "block_delete": st.sampled_from(["both", "off", "on", "1=on,2=off"]),
    "dialect": st.sampled_from(["linuxcnc", "fanuc"]),
    "library": st.sampled_from(["lib", "sub/progs"]),
    "budget": st.floats(0.5, 1000),
}


@settings(max_examples=60, deadline=None)
@given(st.fixed_dictionaries({}, optional=FLEET_VALUES))
def test_a_fleet_jobs_settings_give_the_old_keywords(raw):
    assert set(FLEET_VALUES) == set(SETTINGS)  # every fleet setting is drawn
    normalized = sorted((k, SETTINGS[k].normalize(v)) for k, v in raw.items())
    assert VerifyOptions.from_settings(normalized, root="/proj") == \
        VerifyOptions.from_keywords(**verify_kwargs(normalized, "/proj"))
