"""The code cache (:mod:`nczones.code_cache`) at the seams (hunt42): a generated program verified with the cache
cold (an empty folder), warm (the folder the cold run filled, the process's memo emptied) and off
(``NCZONES_CACHE=off``) gives the same report (``to_json_dict(..., deterministic=True)``: verdict, violations,
witnesses, reasons, notes, stats).

The programs: hunt42's LinuxCNC mill programs (compensated arcs, plane-mix arcs under G64 P Q, cycles in G20 and
G91; the double pass writes and compiles their plans) and Fanuc programs under G68/G51 (line shapes).  The warm run
is checked to read every stored source back: it compiles no source of ``MIN_STORED`` characters or more that the
cold run compiled.

CI: 2 examples (derandomized); ``-m long``: ``NCZONES_SEAMS42`` examples (default 300).
"""

from __future__ import annotations

import builtins
import os
import tempfile

import pytest
from hypothesis import event, given, settings
from hypothesis import strategies as st

from nczones import code_cache as cc
from nczones import machine_cache as mc
from nczones.errors import NczonesError
from nczones.machine import parse_machine
from nczones.prover import verify_text
from nczones.prover.render import to_json_dict
from tests.contract.fanuc_seams41 import program
from tests.contract.fanuc_seams42 import fanuc_programs42
from tests.contract.test_double_pass_seams40 import _mill, _text
from tests.contract.test_double_pass_seams42 import seam42_programs
from tests.contract.test_fanuc_seams41 import _SETTINGS
from tests.gcode.fanuc.helpers import mill
from tests.machines import box_zone, machine_text

LONG_EXAMPLES = int(os.environ.get("NCZONES_SEAMS42", "300"))


def _report(text: str, machine, env: dict) -> tuple[object, set]:
    """(the deterministic JSON report or the error's text, the long sources compiled) of one verify under
    ``env``, the memo emptied first."""
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    inner = builtins.compile
    count: set = set()

    def counting(source, *args, **kwargs):
        if isinstance(source, str) and cc.MIN_STORED <= len(source) <= cc.MAX_STORED:
            count.add(source)
        return inner(source, *args, **kwargs)

    cc.forget()
    builtins.compile = counting
    try:
        return to_json_dict(verify_text(text, machine, file="t.nc"), deterministic=True), count
    except NczonesError as exc:
        return f"{type(exc).__name__}: {exc}", count
    finally:
        builtins.compile = inner
        cc.forget()
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def check_cache(text: str, machine) -> str:
    """Cold, warm and off give the same report; the warm run compiles no long source the cold run compiled
    (``shapes.py`` compiles a line shape's run lazily, after uses this process counts: the warm run may compile
    a source the cold one did not)."""
    with tempfile.TemporaryDirectory() as folder:
        on = {mc.DIR_ENV: os.path.join(folder, "cache"), mc.SWITCH_ENV: "on"}
        cold, compiled_cold = _report(text, machine, on)
        warm, compiled_warm = _report(text, machine, on)
        off, _ = _report(text, machine, {**on, mc.SWITCH_ENV: "off"})
    assert cold == warm == off, f"cold, warm and off differ\n{text}\ncold {cold}\nwarm {warm}\noff {off}"
    again = compiled_warm & compiled_cold
    assert not again, f"the warm run compiled {len(again)} long sources again\n{text}"
    verdict = cold["verdict"] if isinstance(cold, dict) else "error"
    return f"{verdict}, {'stored' if compiled_cold else 'nothing stored'}"


def _linuxcnc(data) -> tuple[str, object]:
    draw = data.draw
    template = draw(seam42_programs(comp=draw(st.booleans())))
    values = _mill(draw, template)
    values = {**values, "machine.cutter_compensation": "linuxcnc",
              "machine.modal": [g for g in values.get("machine.modal", ()) if g not in ("G20", "G91")]}
    zone = box_zone("bounds", {a: "-150" for a in "XYZ"}, {a: "150" for a in "XYZ"})
    return _text(template, "G21"), parse_machine(machine_text("xyz_range_seams", set=values) + zone)


def _fanuc(data) -> tuple[str, object]:
    zone = box_zone("bounds", {"X": "-100", "Y": "-100", "Z": "-400"}, {"X": "450", "Y": "200", "Z": "100"})
    return program(data.draw(fanuc_programs42())), mill(tables=zone)


def check(data) -> None:
    text, machine = (_fanuc if data.draw(st.booleans()) else _linuxcnc)(data)
    event(check_cache(text, machine))


_COMP = ("G21 G90 G17 F300\n#1 = 2\nG0 X0 Y0\nG41 D1 G1 X10 Y0\nG2 X20 Y0 R5\nG3 X30 Y0 I5 J0\n"
         "G1 X[30 + #1] Y2\nG40 G0 X0 Y-30\nG20\nG0 Z0.5\nG99 G83 X1 Y1 Z-0.2 R[0.25 + 0.25] Q0.1\nG80\nG21\nM2\n")


def test_a_compensated_program_reads_its_plans_back():
    """Compensated arcs and an inch cycle: their plans are long sources (stored cold, read back warm), and the
    three reports are the same (``check_cache``)."""
    values = {"machine.cutter_compensation": "linuxcnc"}
    zone = box_zone("bounds", {a: "-150" for a in "XYZ"}, {a: "150" for a in "XYZ"})
    got = check_cache(_COMP, parse_machine(machine_text("xyz_range_seams", set=values) + zone))
    assert got.endswith(", stored"), got


@settings(max_examples=2, derandomize=True, **_SETTINGS)
@given(st.data())
def test_cold_warm_and_off_caches_give_the_same_report(data):
    check(data)


@pytest.mark.long
@settings(max_examples=LONG_EXAMPLES, **_SETTINGS)
@given(st.data())
def test_cache_seams42_long(data):
    check(data)
