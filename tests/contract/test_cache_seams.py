"""Soundness hunt where features meet (hunt38): the machine-file parse cache × ``--param`` ranges × edited
machine files.

The parse cache (:mod:`nczones.machine_cache`, specs/machine-file.md "The parse cache") gives back what
``tomllib`` made of a machine file's very bytes.  Drawn here: the ranged programs, machines and ranges of
``tests/contract/test_range_seams.py``; the machine file's numbers written in a drawn form (decimal text,
padded or signed text, trailing zeros, TOML integer, TOML float, TOML float with an exponent); one byte of the
file then changed (a digit of a number, or a comment).  Relations:

1. **a warm cache is no cache**: the machine loaded from a hit (the parser made to fail, so it is a hit) equals
   the machine loaded with ``NCZONES_CACHE=off``, and the ranged verdict, witnesses (file, line, zone, values)
   and reason codes on it are the same;
2. **one byte changed is a miss**: after the edit the next load parses again (never the old entry), and gives
   what ``NCZONES_CACHE=off`` gives for the new bytes: the same machine or the same refusal (ZN codes and
   messages); a changed number gives another machine.

CI: ``EXAMPLES["ci"]`` examples per dialect (derandomized).  ``-m long``: ``NCZONES_CACHE_SEAMS`` examples per
dialect (default 150), randomized; the counts are printed (specs/contract.md, "Where features meet: hunt38").
"""

from __future__ import annotations

import json
import os
import random
import re
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path
from unittest import mock

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import nczones.machine as machine_module
from nczones import machine_cache as mc
from nczones.errors import NczonesError
from nczones.precompiled import replace
from nczones.prover import verify_text
from tests.contract.test_range_seams import Setup, _zone_text, dec, programs, ranges, setups
from tests.machines import machine_text

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = {"ci": 3, "long": int(os.environ.get("NCZONES_CACHE_SEAMS", "150"))}
OUTCOMES: Counter = Counter()
#: a quoted decimal value of the machine file (``X = "25"``, ``pulse = "0.001"``)
_QUOTED = re.compile(r'(=\s*)"(-?)(\d+)(?:\.(\d*))?"')
FORMS = ("text", "padded", "signed", "zeros", "toml", "exponent")


def _reform(match: re.Match, form: str) -> str:
    """One quoted decimal of the file in ``form`` (the same exact value)."""
    eq, sign, whole, frac = match.group(1), match.group(2), match.group(3), match.group(4) or ""
    text = f"{sign}{whole}" + (f".{frac}" if frac else "")
    if form == "padded":
        return f'{eq}" {text} "'
    if form == "signed":
        return f'{eq}"{sign or "+"}{whole}{"." + frac if frac else ""}"'
    if form == "zeros":
        return f'{eq}"{sign}{whole}.{frac}00"'
    if form == "toml":
        return f"{eq}{text}"
    if form == "exponent":
        digits = (whole + frac).lstrip("0") or "0"
        return f"{eq}{sign}{digits[0]}.{digits[1:] or '0'}e{len(whole.lstrip('0')) - 1 if whole.strip('0') else -(len(frac) - len(frac.lstrip('0')) + 1)}"
    return match.group(0)


def machine_file_text(setup: Setup, forms: list[str]) -> str:
    """The machine of ``setup`` (tests/machines/xyz_range_seams.toml, its zones added), each quoted number in the
    next of ``forms`` (cycled)."""
    zones = "".join(_zone_text(*z) for z in setup.zones)
    text = machine_text("xyz_range_seams", set={"machine.dialect": setup.dialect, "machine.path_mode": setup.path_mode,
                                                "machine.rapid_mode": setup.rapid_mode}, extra=zones)
    count = iter(range(10 ** 6))
    return _QUOTED.sub(lambda m: _reform(m, forms[next(count) % len(forms)]), text)


def _edit(text: str, rnd: random.Random) -> tuple[str, str]:
    """``text`` with one byte changed: a digit of a number (another digit) or a comment's letter; and which."""
    digits = [m.start() for m in re.finditer(r"\d", text) if not text[:m.start()].rsplit("\n", 1)[-1].startswith("#")]
    if rnd.random() < 0.2:
        at = text.index("#") + 2
        return text[:at] + ("Z" if text[at] != "Z" else "Y") + text[at + 1:], "comment"
    at = rnd.choice(digits)
    new = rnd.choice([d for d in "0123456789" if d != text[at]])
    return text[:at] + new + text[at + 1:], "digit"


class Loads:
    """``load_machine`` of one path under a cache folder, or with the cache off; counts the parses."""

    def __init__(self, path: Path, folder: Path):
        self.path, self.folder, self.parses = path, folder, 0

    def load(self, cache: bool, parse_fails: bool = False):
        """The machine, or ``("refused", diagnostics)``; ``parse_fails``: the parser raises (a hit is needed)."""
        real = machine_module._tomllib_loads

        def parse(*args):
            assert not parse_fails, "a hit was expected, the file was parsed"
            self.parses += 1
            return real(*args)

        env = {mc.DIR_ENV: str(self.folder), mc.SWITCH_ENV: "on" if cache else "off"}
        with mock.patch.dict(os.environ, env), mock.patch.object(machine_module, "_tomllib_loads", parse):
            try:
                return machine_module.load_machine(self.path)
            except NczonesError as e:
                return ("refused", tuple(d.render() for d in e.diagnostics))


def outcome(text: str, machine, params: list[str]):
    """What a ranged verify says: verdict, witnesses (file, line, zone, values), reason codes; or its error."""
    if isinstance(machine, tuple):
        return machine
    try:
        r = verify_text(text, machine, params=params, max_violations=100)
    except NczonesError as e:
        return ("error", e.code)
    if any("time backstop" in x.message for x in r.reasons):
        return ("solver time backstop",)  # wall time under load: not compared
    return (r.verdict.label, tuple((v.span.file if v.span else None, v.line, v.zone, v.params) for v in r.violations),
            tuple(sorted(x.code for x in r.reasons)))


def _agree(a, b) -> bool:
    return a == b or ("solver time backstop",) in (a, b)


def check(text: str, setup: Setup, rngs, forms: list[str], rnd: random.Random) -> None:
    """The two relations (the module's docstring) on one program, machine file and box of ranges."""
    params = [f"{n}={dec(lo).rstrip('.')}..{dec(hi).rstrip('.')}" for n, lo, hi in rngs]
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "machine.toml"
        source = machine_file_text(setup, forms)
        path.write_text(source)
        loads = Loads(path, Path(tmp) / "cache")
        off = loads.load(cache=False)
        cold = loads.load(cache=True)
        assert loads.parses == 2 and cold == off
        if isinstance(off, tuple):
            OUTCOMES[("machine", "refused")] += 1
            return
        warm = loads.load(cache=True, parse_fails=True)
        assert warm == off, f"a hit gives another machine ({forms}):\n{source}"
        a, b = outcome(text, off, params), outcome(text, warm, params)
        OUTCOMES[("warm = off", a[0])] += 1
        assert _agree(a, b), f"cache off {a}, warm {b}, ranges {params}:\n{text}"
        edited, where = _edit(source, rnd)
        path.write_text(edited)
        parses = loads.parses
        new = loads.load(cache=True)
        assert loads.parses == parses + 1, "one byte changed, and the old entry was used"
        new_off = loads.load(cache=False)
        assert new == new_off, f"after a one-byte edit ({where}) the cache gives another machine:\n{edited}"
        kind = "refused" if isinstance(new, tuple) else ("same" if new == replace_sha(off, new) else "changed")
        OUTCOMES[("edited " + where, kind)] += 1
        if where == "digit" and not isinstance(new, tuple):
            assert new != off
        if where == "comment":
            assert kind == "same", "a comment changed the machine"
        if kind == "changed" and rnd.random() < 0.5:
            c, d = outcome(text, new, params), outcome(text, new_off, params)
            OUTCOMES[("edited: warm = off", c[0])] += 1
            assert _agree(c, d), f"edited ({where}): cache {c}, off {d}, ranges {params}:\n{text}"


def replace_sha(old, new):
    """``old`` with ``new``'s file digest (a comment's edit changes only that)."""
    return replace(old, sha256=new.sha256)


def _run(dialect: str, n: int, derandomize: bool) -> None:
    @settings(max_examples=n, deadline=None, derandomize=derandomize, database=None,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(programs(dialect), setups(dialect), ranges(), st.lists(st.sampled_from(FORMS), min_size=1, max_size=4),
           st.integers(0, 2 ** 32))
    def run(text, setup, rngs, forms, seed):
        check(text, setup, rngs, forms, random.Random(seed))

    run()


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_cache_seams(dialect):
    _run(dialect, EXAMPLES["ci"], True)


@pytest.mark.long
@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_cache_seams_long(dialect):
    OUTCOMES.clear()
    _run(dialect, EXAMPLES["long"], False)
    print(f"\ncache seams, {dialect}:", dict(sorted(OUTCOMES.items())))


@pytest.mark.parametrize("form", FORMS)
def test_every_number_form_reads_as_the_text(form):
    """The forms are the same exact values (else relation 1 would compare different machines for nothing)."""
    setup = Setup("fanuc", "G61", "linear", ())
    with tempfile.TemporaryDirectory() as tmp:
        plain, formed = Path(tmp) / "a.toml", Path(tmp) / "b.toml"
        plain.write_text(machine_file_text(setup, ["text"]))
        formed.write_text(machine_file_text(setup, [form]))
        a, b = (Loads(p, Path(tmp) / "cache").load(cache=False) for p in (plain, formed))
    assert not isinstance(b, tuple), b
    assert replace(a, sha256=b.sha256, source=b.source, name=b.name) == b


def test_the_cli_reads_the_same_machine_warm_cold_off_and_after_an_edit(tmp_path):
    """``nczones verify --param`` with the cache cold, warm and off (JSON reports equal but for timings), then
    one byte of a zone's bound changed: the warm run follows the file."""
    setup = Setup("linuxcnc", "G61", "linear", (
        ("travel", (-80, -80, -30), (80, 80, 260), False, False),
        ("clamp", (25, 1, -30), (40, 9, 260), True, False)))
    machine = tmp_path / "m.toml"
    machine.write_text(machine_file_text(setup, ["toml", "exponent", "text"]))
    prog = tmp_path / "p.ngc"
    prog.write_text("G21 G90 G17 G54 F600.\nG0 X30. Y0.\nM30\n")

    def run(cache: str) -> dict:
        env = {**os.environ, mc.DIR_ENV: str(tmp_path / "cache"), mc.SWITCH_ENV: cache}
        p = subprocess.run([sys.executable, "-m", "nczones", "verify", str(prog), "--machine", str(machine),
                            "--param=G54.Y=-1..2", "--format", "json"], capture_output=True, text=True, env=env,
                           cwd=ROOT, timeout=120)
        report = json.loads(p.stdout)
        return {"exit": p.returncode, "verdict": report.get("verdict"), "violations": report.get("violations"),
                "machine_sha256": report["machine"]["sha256"]}

    cold, warm, off = run("on"), run("on"), run("off")
    assert cold == warm == off and cold["exit"] == 1, (cold, warm, off)
    # the clamp's min Y 1 -> 7 (one byte): the rapid along work Y0 misses it at every value of the range
    text = machine.read_text()
    at = text.index('name = "clamp"')
    lower = text.index("Y = ", at)
    edited = text[:lower + 4] + text[lower + 4:].replace("1", "7", 1)
    assert len(edited) == len(text) and edited != text
    machine.write_text(edited)
    warm2, off2 = run("on"), run("off")
    assert warm2 == off2 and warm2["exit"] == 0 and warm2["machine_sha256"] != warm["machine_sha256"], (warm2, off2)
