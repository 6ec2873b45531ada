"""Start-up stays light (issue 26): what ``nczones --help`` and ``import nczones`` load, not how long they take.

The CPU time of start-up is measured in ``bench/bench_startup.py``; these tests pin down why it is small:
the heavy libraries and stages are not imported until a command needs them.  Each case runs in a fresh
interpreter, since this test process has imported everything already.
"""

from __future__ import annotations

import contextlib
import io
import json
import subprocess
import sys
from pathlib import Path

import pytest

from nczones import cli
from nczones.commands import COMMANDS

ROOT = Path(__file__).resolve().parents[2]
MILL = str(ROOT / "specs" / "machines" / "mill.toml")

#: What a light start must not load: the numeric and drawing libraries, the solver, and the two witnesses.
HEAVY = ("numpy", "z3", "shapely", "matplotlib", "nczones.controller", "nczones.prover", "nczones.report",
         "nczones.gcode", "nczones.fleet", "nczones.imports", "nczones.plans.homing", "nczones.plans.recovery", "nczones.solids")


def loaded_after(code: str) -> set[str]:
    """The top-level modules of HEAVY that a fresh interpreter has loaded after running ``code``."""
    probe = (f"import sys\n{code}\n"
             f"import json; print(json.dumps(sorted(m for m in {HEAVY!r} if m in sys.modules)))")
    r = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    return set(json.loads(r.stdout.splitlines()[-1]))


@pytest.mark.parametrize("code", [
    "import nczones",
    "import nczones.cli",
    "from nczones.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit as e:\n    assert e.code == 0",
    "from nczones.cli import main\ntry:\n    main(['--version'])\nexcept SystemExit as e:\n    assert e.code == 0",
    f"from nczones.cli import main\nassert main(['check-machine', {MILL!r}]) == 0",
])
def test_a_light_start_loads_no_heavy_module(code):
    assert loaded_after(code) == set()


#: What a small verify must not load: numpy (the fast path and the column screen), the solver (nothing needs a
#: query), the package metadata (the solver's version is read from its wheel), the drawing libraries and the
#: other witness.
NOT_FOR_A_SMALL_VERIFY = ("numpy", "z3", "shapely", "matplotlib", "importlib.metadata", "nczones.controller",
                          "nczones.fleet", "nczones.imports", "nczones.gcode.fastpath", "nczones.prover.screen",
                          "nczones.prover.polygon", "nczones.plans.homing", "nczones.plans.recovery", "nczones.solids",
                          "nczones.gcode.linuxcnc.lathe", "nczones.geometry.cylinder", "nczones.gcode.linuxcnc.g7x",
                          "nczones.prover.blend", "nczones.prover.hull2d", "socket", "nczones.geometry.nurbs",
                          # issue 36: OpenSSL (hashlib: the digests are CPython's own, nczones.digest), ctypes (the
                          # x87 functions load at the first SIN/COS/TAN), shutil (argparse's terminal width)
                          "_hashlib", "ctypes", "shutil", "nczones.lathe_solids",
                          # issue 36 (startup36c): dataclasses imports inspect, ast, dis, tokenize (some 10 ms); the
                          # classes, field(), replace() and field names come from nczones.precompiled
                          "dataclasses", "inspect", "ast", "dis", "tokenize",
                          # issue 36 (startup36d): the signal module (its enums), threading and select: SIGTERM's
                          # handler goes through _signal, the limits' watchdog starts with the first solver query
                          "signal", "threading", "select",
                          # struct (the x87 functions' packing: with ctypes), heapq (a run profile's slowest
                          # motions: once its list is full); each a C extension to load
                          "struct", "heapq",
                          # issue 36 (boot43): the replay of witnesses at parameter values (none here)
                          "nczones.pipeline.witnesses",
                          # issue 36 (boot44): the hints of unsupported codes (none here), the nose radius (no lathe)
                          "nczones.gcode.dialects", "nczones.prover.nose",
                          # (boot44) the spline motions' module (no G5 here), the parameter ranges' cases (none)
                          "nczones.gcode.linuxcnc.splines", "nczones.prover.cases")


def loaded_by_verify(tmp_path, lines: list[str]) -> set[str]:
    program = tmp_path / "small.ngc"
    program.write_text("\n".join(lines) + "\n")
    code = (f"from nczones.cli import main\nassert main(['verify', {str(program)!r}, '--machine', {MILL!r}]) == 0\n"
            f"import json; print(json.dumps(sorted(m for m in {NOT_FOR_A_SMALL_VERIFY!r} if m in sys.modules)))")
    r = subprocess.run([sys.executable, "-c", "import sys\n" + code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    return set(json.loads(r.stdout.splitlines()[-1]))


def test_a_small_verify_loads_neither_numpy_nor_the_solver(tmp_path):
    assert loaded_by_verify(tmp_path, ["G90 G21", "G1 X10 Y10 F100", "M2"]) == set()


def test_a_small_program_with_parameters_loads_neither_solids_nor_ctypes(tmp_path):
    # the double pass (a LinuxCNC program with '#') asks whether the machine declares solids without
    # importing nczones.solids; ctypes (and struct) wait for the first SIN, COS or TAN
    assert loaded_by_verify(tmp_path, ["G90 G21 F100", "#1 = 2.5", "G1 X[#1 * 2] Y[#1 + 1]", "M2"]) == set()
    loaded = loaded_by_verify(tmp_path, ["G90 G21 F100", "#1 = 30", "G1 X[10 * SIN[#1]] Y[10 * COS[#1]]", "M2"])
    assert loaded == {"ctypes", "struct"}


def test_a_small_verify_loads_no_pathlib(tmp_path):
    # pathlib (with urllib.parse and ipaddress, ~3 ms): a development environment's site
    # imports pathlib for its editable-install hook, so the interpreter starts without site here, as an
    # installed wheel's would not need it; the hook imports importlib.util too, which a small verify does not
    # (issue 36, startup36e: the solver's wheel is found through sys.meta_path), nor locale where gettext has
    # no folder of catalogues (argparse's messages are then not passed through gettext)
    import gettext
    import os

    # contextlib (18 classes, issue 36, boot43): the run's watch is a class, the solver's query imports it
    names = ("pathlib", "urllib.parse", "ipaddress", "importlib.util", "contextlib",
             *(() if os.path.isdir(gettext._default_localedir) else ("locale",)))
    program = tmp_path / "small.ngc"
    program.write_text("G90 G21\nG1 X10 Y10 F100\nM2\n")
    code = (f"import sys\nsys.path[:0] = {[p for p in sys.path if p]!r}\nfrom nczones.cli import main\n"
            f"assert main(['verify', {str(program)!r}, '--machine', {MILL!r}]) == 0\n"
            f"print(sorted(m for m in {names!r} if m in sys.modules))")
    r = subprocess.run([sys.executable, "-S", "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == "[]"


def test_help_loads_neither_typing_nor_contextlib():
    # issue 36 (startup36e): the command line's own modules take TYPE_CHECKING as a local False and SIGTERM's
    # block is a class; started without site (a development environment's editable-install hook imports
    # contextlib), as in the test above
    code = (f"import sys\nsys.path[:0] = {[p for p in sys.path if p]!r}\nfrom nczones.cli import main\n"
            "try:\n    main(['--help'])\nexcept SystemExit as e:\n    assert e.code == 0\n"
            "print(sorted(m for m in ('typing', 'contextlib') if m in sys.modules))")
    r = subprocess.run([sys.executable, "-S", "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == "[]"


def _run_program(tmp_path, lines: list[str]) -> dict:
    """``nczones.cli.run`` (the console script) on a program: whether ctypes and numpy were loaded, the hook left."""
    program = tmp_path / "run.ngc"
    program.write_text("\n".join(lines) + "\n")
    code = (f"import sys, json, atexit\nsys.argv = ['nczones', 'verify', {str(program)!r}, '--machine', {MILL!r}]\n"
            "from nczones import cli\n"
            "called = []\nkeep = cli._keep_freed_memory\ncli._keep_freed_memory = lambda: (called.append(1), keep())\n"
            "atexit.register(lambda: print(json.dumps({'ctypes': 'ctypes' in sys.modules, 'numpy': 'numpy' in "
            "sys.modules, 'called': len(called), 'hook': any(type(m).__name__ == '_BeforeNumpy' for m in "
            "sys.meta_path)})))\ncli.run()")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout.splitlines()[-1])


def test_the_allocator_is_tuned_when_numpy_loads_and_only_then(tmp_path):
    # glibc is asked to keep freed memory (ctypes, mallopt) once numpy is imported: a small program never pays
    assert _run_program(tmp_path, ["G90 G21", "G1 X10 Y10 F100", "M2"]) == {
        "ctypes": False, "numpy": False, "called": 0, "hook": True}
    assert _run_program(tmp_path, ["G90 G21", *_vectorized_lines(), "M2"]) == {"ctypes": True, "numpy": True,
                                                                               "called": 1, "hook": False}


def _vectorized_lines() -> list[str]:
    """A plain program's lines the vectorized path reads: more than the double pass is tried first for
    (``PLAIN_PASS_SIZE``; a smaller plain one goes to the pass, which needs no numpy, and only one it declines
    reaches the vectorized path; since the pass takes a program that leaves its work offset to the machine
    file, this program's ``G90 G21`` head no longer makes it decline)."""
    from nczones.pipeline.verification import PLAIN_PASS_SIZE

    return [f"G1 X{10 + k % 50}.{k % 10} Y{20 + k % 30}.5 F100" for k in range(PLAIN_PASS_SIZE + 1)]


def test_a_large_program_takes_the_vectorized_path(tmp_path):
    loaded = loaded_by_verify(tmp_path, ["G90 G21", *_vectorized_lines(), "M2"])
    assert {"numpy", "nczones.gcode.fastpath", "nczones.prover.screen"} <= loaded and "z3" not in loaded


def test_a_machine_file_section_imports_its_parser_when_it_appears():
    """Issue 34: no module is imported for its side effects; the extra sections of a machine file are an explicit
    table (section -> "module:function"), and a section's module is imported when a file has the section."""
    homing_mill = str(ROOT / "specs" / "machines" / "homing_mill.toml")
    solids_mill = str(ROOT / "specs" / "machines" / "mill_solids.toml")
    probe = "import sys\nfrom nczones import load_machine\nm = load_machine({!r})\n" \
            "print(sorted(m.sections), sorted(x for x in ('nczones.plans.homing', 'nczones.plans.recovery', 'nczones.solids') " \
            "if x in sys.modules))"
    for machine, sections, modules in ((MILL, [], []), (homing_mill, ["homing"], ["nczones.plans.homing"]),
                                       (solids_mill, ["fixtures", "spindle", "tools"], ["nczones.solids"])):
        r = subprocess.run([sys.executable, "-c", probe.format(machine)], capture_output=True, text=True, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        assert r.stdout.split("\n")[0] == f"{sections} {modules}"
    from nczones.machine import SECTION_PARSERS, section_parser

    for name, where in SECTION_PARSERS.items():
        module, _, function = where.partition(":")
        assert callable(section_parser(name)) and section_parser(name).__module__ == module
        assert section_parser(name).__name__ == function


def test_the_public_api_still_reaches_every_stage():
    """A heavy stage is loaded when it is used, and the package's names stay importable."""
    loaded = loaded_after("import nczones\nfrom nczones import Machine, load_machine, Segment, AllowedSet\n"
                          "import nczones.controller\nfrom nczones.prover import verify")
    assert {"numpy", "nczones.controller", "nczones.prover"} <= loaded
    import nczones

    assert set(nczones.__all__) <= set(dir(nczones))


def test_a_command_loads_its_own_module_and_not_the_others():
    assert loaded_after("from nczones.cli import build_parser\nbuild_parser('check-machine')") == set()
    loaded = loaded_after("from nczones.cli import build_parser\nbuild_parser('simulate')")
    assert "nczones.prover" not in loaded and "z3" not in loaded and "nczones.fleet" not in loaded
    loaded = loaded_after("from nczones.cli import build_parser\nbuild_parser('verify')")
    assert "nczones.prover" in loaded and "nczones.controller" not in loaded and "matplotlib" not in loaded


def test_the_lazy_parser_lists_what_the_full_parser_lists():
    """``nczones --help`` (each command by its summary) says what the fully built parser says."""
    import argparse

    def commands(parser: argparse.ArgumentParser) -> list[tuple[str, str | None]]:
        sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        return [(a.dest, a.help) for a in sub._choices_actions]

    full = cli.build_parser()
    assert commands(cli.build_parser("")) == commands(full) == [(n, c.summary) for n, c in COMMANDS.items()]
    assert full.format_help() == cli.build_parser("").format_help()


@pytest.mark.parametrize("argv, command", [
    ([], ""), (["--help"], ""), (["-h", "verify"], "verify"), (["verify", "--help"], "verify"),
    (["fleet", "check", "lib"], "fleet"), (["--version"], ""),
])
def test_the_chosen_command_is_the_first_word_that_is_no_option(argv, command):
    assert cli.chosen_command(argv) == command


def test_a_command_built_alone_parses_as_in_the_full_parser():
    argv = ["verify", "p.ngc", "--machine", "m.toml", "--margin", "0.5", "--engine", "z3"]
    assert vars(cli.build_parser("verify").parse_args(argv)) == vars(cli.build_parser().parse_args(argv))
    # without the other commands' parsers (main's `nczones verify ...`): the same arguments, help and errors
    alone = cli.build_parser("verify", alone=True)
    assert vars(alone.parse_args(argv)) == vars(cli.build_parser().parse_args(argv))

    def shown(parser, args):
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), pytest.raises(SystemExit) as stop:
            parser.parse_args(args)
        return stop.value.code, out.getvalue(), err.getvalue()

    for args in (["verify", "--help"], ["verify"], ["verify", "p.ngc", "--margin"]):
        assert shown(alone, args) == shown(cli.build_parser(), args), args


def test_the_program_exits_with_the_status_main_returns(tmp_path):
    # nczones.cli.run (the console script, python -m nczones) tunes the process, runs main and exits with its status
    program = tmp_path / "out.ngc"
    program.write_text("G90 G21\nG1 X900 Y10 F100\nM2\n")  # X beyond the mill's travel
    code = (f"import sys\nsys.argv = ['nczones', 'verify', {str(program)!r}, '--machine', {MILL!r}]\n"
            "from nczones.cli import run\nrun()")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 1 and "unsafe" in r.stdout, r.stderr
    r = subprocess.run([sys.executable, "-m", "nczones", "--version"], capture_output=True, text=True, cwd=ROOT)
    from nczones import __version__

    assert r.returncode == 0 and __version__ in r.stdout


def test_a_small_fanuc_verify_loads_neither_dataclasses_nor_pathlib(tmp_path):
    # issue 36 (startup36c): the Fanuc modules make their classes through nczones.precompiled too, and pathlib
    # (urllib.parse, ipaddress) is imported only for a library folder; site is left out as in the test above.
    # fanucfix38: nor the LinuxCNC language layer (its runner and line shapes: what the two runners share is in
    # nczones.gcode.runner_common), nor the multi-path reader (a text without "$" has no path header)
    program = tmp_path / "small.nc"
    program.write_text("G21 G90\nG0 X1. Y1.\nG1 X2. Y2. F100.\nM30\n")
    machine = ROOT / "specs" / "machines" / "fanuc_mill.toml"
    names = ("dataclasses", "inspect", "ast", "pathlib", "urllib.parse", "ipaddress", "numpy", "z3", "signal", "threading",
             "nczones.gcode.program", "nczones.gcode.shapes", "nczones.gcode.linuxcnc.doubles", "nczones.gcode.mentions",
             "nczones.gcode.fanuc.paths")
    code = (f"import sys\nsys.path[:0] = {[p for p in sys.path if p]!r}\nfrom nczones.cli import main\n"
            f"assert main(['verify', {str(program)!r}, '--machine', {str(machine)!r}]) == 0\n"
            f"print(sorted(m for m in {names!r} if m in sys.modules))")
    r = subprocess.run([sys.executable, "-S", "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == "[]"


def test_the_package_imports_its_public_names_at_their_first_use():
    # issue 36 (startup36d): `import nczones` loads none of the modules behind its public names, nor typing, so
    # that `python -m nczones` sets the collector's threshold before they make their objects
    behind = ("nczones.machine", "nczones.motion", "nczones.zones", "typing", "nczones.exact.elementary")
    probe = (f"import sys, nczones\nbefore = sorted(m for m in {behind!r} if m in sys.modules)\n"
             "from nczones import Machine, load_machine\nfrom nczones.machine import Machine as M, load_machine as L\n"
             "assert (Machine, load_machine) == (M, L) and nczones.SegmentKind.LINE is not None\n"
             # exact() has its subpackage's name: still the function once the subpackage is imported
             "import nczones.exact.decimals\nfrom nczones import exact\nfrom nczones.exact import exact as E\n"
             "assert exact is E and nczones.exact is E and callable(exact)\n"
             # boot44: nczones.exact's enclosures of pi and the trigonometric functions at their first use too
             "from nczones.exact import atan_interval, pi_interval\nel = sys.modules['nczones.exact.elementary']\n"
             "assert (atan_interval, pi_interval) == (el.atan_interval, el.pi_interval)\n"
             "ex = sys.modules['nczones.exact']\nassert all(getattr(ex, n) is not None for n in ex.__all__)\n"
             "try:\n    ex.no_such_name\nexcept AttributeError as e:\n    assert 'no_such_name' in str(e)\n"
             # every name of __all__ is reachable (a new public name needs its row in nczones._MODULE_OF)
             "assert all(getattr(nczones, n) is not None for n in nczones.__all__)\n"
             "try:\n    nczones.no_such_name\nexcept AttributeError as e:\n    assert 'no_such_name' in str(e)\n"
             "print(before)")
    r = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == "[]"


def test_the_program_runs_with_the_collectors_threshold_raised(tmp_path):
    # python -m nczones and the console script (cli.run): the first threshold is cli.YOUNG_OBJECTS while the
    # command runs (a small verify then sets off no collection after its start), the others Python's
    program = tmp_path / "small.ngc"
    program.write_text("G90 G21\nG1 X10 Y10 F100\nM2\n")
    seen = ("import atexit, gc, sys\natexit.register(lambda: print(gc.get_threshold(), file=sys.stderr))\n")
    for start in ("import runpy\nrunpy.run_module('nczones', run_name='__main__')", "from nczones import cli\ncli.run()"):
        code = f"{seen}sys.argv = ['nczones', 'verify', {str(program)!r}, '--machine', {MILL!r}]\n{start}"
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        assert r.stderr.splitlines()[-1] == str((cli.YOUNG_OBJECTS, 10, 10))


def test_a_small_verify_with_a_text_report_loads_no_json(tmp_path):
    # issue 36 (startup36d): json (with its decoder, scanner and C accelerator) only for a JSON report; the machine
    # file's zone labels are quoted without it (tests/machine: the quoting is json's)
    program = tmp_path / "small.ngc"
    program.write_text("G90 G21\nG1 X10 Y10 F100\nM2\n")
    for fmt, loaded in (("text", False), ("json", True)):
        code = (f"import sys\nfrom nczones.cli import main\nassert main(['verify', {str(program)!r}, '--machine', "
                f"{MILL!r}, '--format', {fmt!r}]) == 0\nprint('json' in sys.modules)")
        r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
        assert r.returncode == 0, r.stderr
        assert r.stdout.splitlines()[-1] == str(loaded), fmt


def _parse_messages(argv: list[str]) -> tuple[object, str, str]:
    """What ``main`` prints and exits with when argparse stops at ``argv`` (help or an error)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), pytest.raises(SystemExit) as stop:
        cli.main(argv)
    return stop.value.code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("argv", [["verify"], ["verify", "--help"], ["--help"], ["no-such-command"],
                                  ["verify", "p.ngc", "--machine", "m.toml", "--margin"], ["verify", "a", "b", "--x"]])
def test_argparse_says_without_gettext_what_it_says_with_it(argv, monkeypatch, tmp_path):
    # issue 36 (startup36e): where gettext's folder of catalogues does not exist, argparse's messages skip gettext
    # (and its import of locale) while the command line is parsed; with a folder (no catalogue in it) gettext is
    # asked as always: the same words, and argparse gets gettext's functions back either way
    import argparse
    import gettext

    def asked(folder: Path) -> tuple[tuple[object, str, str], bool]:
        monkeypatch.setattr(gettext, "_default_localedir", str(folder))
        calls = []
        real = gettext.dgettext
        monkeypatch.setattr(gettext, "dgettext", lambda *a: (calls.append(a), real(*a))[1])
        said = _parse_messages(argv)
        monkeypatch.setattr(gettext, "dgettext", real)
        assert vars(argparse)["_"] is gettext.gettext and vars(argparse)["ngettext"] is gettext.ngettext
        return said, bool(calls)

    with_gettext, asked_it = asked(tmp_path)
    without, asked_none = asked(tmp_path / "absent")
    assert asked_it and not asked_none
    assert with_gettext == without and with_gettext[0] in (0, 2) and (with_gettext[1] or with_gettext[2])


@pytest.mark.parametrize("n", [0, 1, 2, 7])
def test_the_plural_stand_in_is_gettexts_without_a_catalogue(n):
    import gettext

    assert cli._same_plural("an argument", "arguments", n) == gettext.NullTranslations().ngettext(
        "an argument", "arguments", n)
    assert cli._same_message("usage: ") == gettext.NullTranslations().gettext("usage: ")


#: Python's finalization calls ``threading._shutdown`` first thing (to join the threads): this one says so
_FINALIZED = ("import os, sys, threading\n_shutdown = threading._shutdown\n"
              "threading._shutdown = lambda: (os.write(2, b' finalized'), _shutdown())\n")


def _untimed(report):
    """A JSON report without its measurements (``stats``, ``*_s``, ``seconds*``), which differ from run to run."""
    if isinstance(report, dict):
        return {k: _untimed(v) for k, v in report.items()
                if not (k == "stats" or k.endswith("_s") or k.startswith("seconds"))}
    if isinstance(report, list):
        return [_untimed(v) for v in report]
    return report


@pytest.mark.parametrize("handler", [False, True])
def test_the_program_skips_finalization_only_when_nothing_waits_for_it(tmp_path, handler):
    # issue 36 (boot42): cli.run ends with os._exit once the streams are flushed when no exit handler is
    # registered and no other thread runs (Python's finalization then never starts); with a handler, Python's
    # usual exit runs it and finalizes.  Either way the report and the status are main()'s.
    program = tmp_path / "out.ngc"
    program.write_text("G90 G21\n" + "".join(f"G1 X{k} Y10 F100\n" for k in range(300)) + "M2\n")
    argv = ["verify", str(program), "--machine", MILL, "--format", "json"]
    register = "import atexit\natexit.register(lambda: os.write(2, b' handler'))\n" if handler else ""
    code = f"{_FINALIZED}{register}sys.argv = ['nczones', *{argv!r}]\nfrom nczones.cli import run\nrun()"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = cli.main(argv)
    assert r.returncode == status == 0  # (safe by the double pass: z3, which registers an exit handler, not loaded)
    assert _untimed(json.loads(r.stdout)) == _untimed(json.loads(out.getvalue()))
    assert json.loads(r.stdout)["verdict"] == "safe" and r.stdout.endswith("}\n")
    assert r.stderr.split() == (["finalized", "handler"] if handler else []), r.stderr


def test_the_program_finalizes_when_its_streams_are_not_its_own():
    # a caller that replaced sys.stdout (a capture) gets Python's usual exit, which flushes and finalizes
    code = (f"{_FINALIZED}import io\nsys.stdout = io.StringIO()\n"
            "sys.argv = ['nczones', '--version']\nfrom nczones.cli import run\nrun()")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0 and r.stderr.split() == ["finalized"], r.stderr


@pytest.mark.parametrize("script, raised", [("nczones", True), ("not_nczones.py", False)])
def test_the_console_script_raises_the_threshold_before_the_imports(tmp_path, script, raised):
    # issue 36 (boot43): the console script (a file named nczones whose __main__ imports nczones.cli) raises the
    # collector's first threshold when nczones is imported, so the start's imports set off no collection; any
    # other program that imports nczones keeps its own threshold
    path = tmp_path / script
    path.write_text("import gc, sys\ngc.set_threshold(700, 10, 10)\nbefore = gc.get_stats()[0]['collections']\n"
                    "from nczones.cli import run\n"
                    "print(gc.get_threshold()[0], gc.get_stats()[0]['collections'] - before)\n")
    r = subprocess.run([sys.executable, str(path)], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    threshold, collections = map(int, r.stdout.split())
    assert threshold == (cli.YOUNG_OBJECTS if raised else 700)
    # raised: at most the one collection finding the package may set off; else one every few modules
    assert collections <= 1 if raised else collections >= 5


def test_a_polygon_zone_through_the_double_pass_loads_no_numpy(tmp_path):
    # issue 36 (poly45): a plain program of 1,000 short moves inside a 200-vertex outline is proved by the double
    # pass; the simple-polygon check and the exact polygon tier (prover/polygon.py) run in Python integers, so
    # numpy (only the vectorized screen's) is not imported
    import math
    import random

    verts = []
    for i in range(200):
        th = 2 * math.pi * i / 200
        r = 100 + 3 * math.sin(37 * th)
        verts.append(f'["{r * math.cos(th):.4f}", "{r * math.sin(th):.4f}"]')
    machine = tmp_path / "poly.toml"
    machine.write_text('[machine]\naxes = ["X", "Y"]\nrapid_mode = "linear"\n[machine.rapid]\nX = "10000"\n'
                       'Y = "10000"\n[machine.reference]\nX = "80"\nY = "0"\n[[zones]]\nname = "outline"\n'
                       'kind = "polygon"\nplane = ["X", "Y"]\nvertices = [' + ", ".join(verts) + "]\n")
    rnd = random.Random(0)
    lines = ["G21 G90 G17", "G1 F1000", "X80 Y0"]
    x, y = 80.0, 0.0
    while len(lines) < 1003:  # a walk of short moves between radius 60 and 95 (each motion's box fits)
        nx, ny = x + rnd.uniform(-2, 2), y + rnd.uniform(-2, 2)
        if 60 < math.hypot(nx, ny) < 95:
            x, y = nx, ny
            lines.append(f"X{x:.3f} Y{y:.3f}")
    program = tmp_path / "walk.ngc"
    program.write_text("\n".join(lines) + "\nM2\n")
    code = (f"import sys, json\nfrom nczones.cli import main\n"
            f"code = main(['verify', {str(program)!r}, '--machine', {str(machine)!r}, '--format', 'json'])\n"
            "print(json.dumps([code, 'numpy' in sys.modules, 'nczones.prover.polygon' in sys.modules]))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    report = json.loads(r.stdout[:r.stdout.rindex("\n[")])
    assert report["verdict"] == "safe", report["stats"]
    assert report["stats"].get("double_pass_boxes", 0) > 0, report["stats"]
    assert json.loads(r.stdout.splitlines()[-1]) == [0, False, True]
