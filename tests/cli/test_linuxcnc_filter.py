"""``nczones linuxcnc-filter`` run the way LinuxCNC's AXIS runs a [FILTER] program (issue 38).

The reference is AXIS's own code: ``filter_program`` of the installed ``/usr/bin/axis`` (Debian's
linuxcnc-uspace 2.9.0~pre1), taken out of the script with :mod:`ast` and run with stand-ins for the Tk
progress bar and text widget only.  Where LinuxCNC is not installed, the transcription below (the same
function, from src/emc/usr_intf/axis/scripts/axis.py of LinuxCNC 2.9) runs instead, and where it is
installed a test checks that the transcription is the installed function, statement for statement.

What AXIS does with a filter (read from that code): it runs ``sh -c "<INI [FILTER] ext value> '<path>'"``
(a ``'`` in the path written ``'\\''``) with standard input closed and standard output going to the
file it will load; a standard-error line matching ``^FILTER_PROGRESS=(\\d*)$`` moves the progress bar,
every other line is kept; a non-zero exit code makes AXIS show the kept lines and load nothing
(``open_file_guts``: ``if exitcode: ... nf_dialog(...); return``).

A real LinuxCNC session cannot run here: see docs/linuxcnc-filter.md, "Testing".
"""

from __future__ import annotations

import ast
import io
import os
import re
import select
import shlex
import sys
import types
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
AXIS = Path("/usr/bin/axis")

TRANSCRIPTION = r'''
progress_re = re.compile("^FILTER_PROGRESS=(\\d*)$")
def filter_program(program_filter, infilename, outfilename):
    import subprocess
    outfile = open(outfilename, "w")
    infilename_q = infilename.replace("'", "'\\''")
    env = dict(os.environ)
    env['AXIS_PROGRESS_BAR'] = '1'
    p = subprocess.Popen(["sh", "-c", "%s '%s'" % (program_filter, infilename_q)],
                          stdin=subprocess.PIPE,
                          stdout=outfile,
                          stderr=subprocess.PIPE,
                          env=env)
    p.stdin.close()  # No input for you
    progress = Progress(1, 100)
    progress.set_text(_("Filtering..."))
    stderr_text = []
    try:
        while p.poll() is None: # XXX add checking for abort
            t.update()
            r,w,x = select.select([p.stderr], [], [], 0.100)
            if r:
                stderr_line = p.stderr.readline().decode()
                m = progress_re.match(stderr_line)
                if m:
                    progress.update(int(m.group(1)), 1)
                else:
                    stderr_text.append(stderr_line)
                    sys.stderr.write(stderr_line)
        # .. might be something left on stderr
        for line in p.stderr:
            stderr_line = line.decode()
            m = progress_re.match(stderr_line)
            if not m:
                stderr_text.append(stderr_line)
                sys.stderr.write(stderr_line)
        return p.returncode, "".join(stderr_text)
    finally:
        progress.done()
'''


def _installed_source() -> str | None:
    """``progress_re`` and ``filter_program`` as the installed AXIS script has them (None without LinuxCNC)."""
    if not AXIS.is_file():
        return None
    text = AXIS.read_text(encoding="utf-8")
    tree = ast.parse(text)
    wanted = [node for node in tree.body
              if (isinstance(node, ast.FunctionDef) and node.name == "filter_program")
              or (isinstance(node, ast.Assign) and any(getattr(t, "id", "") == "progress_re" for t in node.targets))]
    assert len(wanted) == 2, "axis no longer defines progress_re and filter_program at top level"
    return "\n".join(ast.get_source_segment(text, node) or "" for node in wanted) + "\n"


class _Progress:
    """AXIS's Tk progress bar: records the updates."""

    def __init__(self, phases: int, total: int) -> None:
        self.updates: list[int] = []
        self.done_called = False
        _Progress.last = self

    def set_text(self, text: str) -> None:
        pass

    def update(self, value: int, force: int = 0) -> None:
        self.updates.append(value)

    def done(self) -> None:
        self.done_called = True


def axis_filter_program(source: str):
    """``filter_program`` compiled from ``source`` with AXIS's globals (the Tk parts stood in)."""
    fake_sys = types.SimpleNamespace(stderr=io.StringIO())
    namespace = {"os": os, "re": re, "select": select, "sys": fake_sys, "Progress": _Progress,
                 "t": types.SimpleNamespace(update=lambda: None), "_": lambda s: s}
    exec(compile(source, "axis.py", "exec"), namespace)
    return namespace["filter_program"], fake_sys


@pytest.fixture
def run_filter(tmp_path, monkeypatch):
    """Run the filter the way AXIS does: (exit code, kept stderr text, output bytes, progress updates).

    The installed AXIS's code when LinuxCNC is installed, else the transcription (which
    test_transcription_is_the_installed_axis_code keeps equal to it)."""
    source = _installed_source() or TRANSCRIPTION
    filter_program, fake_sys = axis_filter_program(source)
    monkeypatch.setenv("PYTHONPATH", str(ROOT))
    ini = tmp_path / "grinder.ini"
    # The INI as docs/linuxcnc-filter.md shows it; the [FILTER] value is the command AXIS's sh runs.
    command = f"{shlex.quote(sys.executable)} -m nczones linuxcnc-filter"
    ini.write_text("[FILTER]\nPROGRAM_EXTENSION = .ngc nczones: prove before loading\n"
                   f"ngc = {command}\n\n[NCZONES]\nMACHINE = {ROOT / 'specs/machines/grinder.toml'}\n",
                   encoding="utf-8")
    monkeypatch.setenv("INI_FILE_NAME", str(ini))  # the linuxcnc launcher exports it to the GUI

    def run(program: Path) -> tuple[int, str, bytes, list[int]]:
        out = tmp_path / ("filtered-" + program.name)
        code, stderr = filter_program(command, str(program), str(out))
        assert fake_sys.stderr.getvalue().endswith(stderr)  # AXIS echoes the kept lines to its terminal
        return code, stderr, out.read_bytes(), _Progress.last.updates

    return run


def test_safe_program_passes_through_byte_for_byte(run_filter, tmp_path):
    # A name with a space and a quote: AXIS single-quotes the path and writes ' as '\''.
    program = tmp_path / "it's notch over.ngc"
    text = (ROOT / "specs/examples/programs/notch_over.ngc").read_bytes() + b"(\xc2\xb0 kept as written)\r\n"
    program.write_bytes(text)
    code, stderr, output, updates = run_filter(program)
    assert (code, stderr) == (0, "")  # every stderr line was a FILTER_PROGRESS line
    assert output == text  # what AXIS loads is the program, unchanged
    # While the filter runs AXIS moves its bar with each FILTER_PROGRESS line; those read after the exit are
    # dropped (axis.py's last loop), so the values seen are a rising run of percentages, possibly empty.
    assert updates == sorted(updates) and all(0 <= u <= 100 for u in updates)
    assert not list(tmp_path.glob("*.nczones.*"))  # no report for a safe program


def test_unsafe_program_is_refused_with_line_zone_and_depth(run_filter, tmp_path):
    program = tmp_path / "notch_dip.ngc"
    program.write_bytes((ROOT / "specs/examples/programs/notch_dip.ngc").read_bytes())
    code, stderr, output, updates = run_filter(program)
    # Non-zero: AXIS shows `stderr` in its "Filter failed" dialog and loads nothing.
    assert code == 1 and output == b""
    # Derivation: G54 shifts X by +400, so line 5 (G1 X50 at Y130) runs from machine X150 to X450 at Y130;
    # over the work head (200 < X <= 380) grinder.toml's stepped zone allows Y >= 220: 220 - 130 = 90 mm.
    assert "notch_dip.ngc is UNSAFE and was not loaded" in stderr
    assert "line 5: leaves the allowed zone 'wheel area' by 90 mm" in stderr
    report = tmp_path / "notch_dip.ngc.nczones.html"
    assert f"full report: {report}" in stderr
    assert updates == sorted(updates)
    pytest.importorskip("matplotlib")
    assert report.read_text(encoding="utf-8").lstrip().lower().startswith("<!doctype html")


def test_no_machine_file_refuses_with_its_code(run_filter, tmp_path, monkeypatch):
    ini = tmp_path / "bare.ini"
    ini.write_text("[EMC]\nMACHINE = bare\n", encoding="utf-8")
    monkeypatch.setenv("INI_FILE_NAME", str(ini))
    program = tmp_path / "p.ngc"
    program.write_text("G0 X0\nM2\n", encoding="utf-8")
    code, stderr, output, _ = run_filter(program)
    assert code == 2 and output == b""
    assert "error[LF101]" in stderr and "bare.toml does not exist" in stderr


def test_machine_file_beside_the_ini(tmp_path):
    from nczones.commands.linuxcnc_filter import find_machine

    ini = tmp_path / "mill.ini"
    ini.write_text("[EMC]\nMACHINE = mill\n", encoding="utf-8")
    (tmp_path / "mill.toml").write_text("", encoding="utf-8")
    assert find_machine(None, str(ini)) == str(tmp_path / "mill.toml")
    assert find_machine("given.toml", str(ini)) == "given.toml"


@pytest.mark.skipif(not AXIS.is_file(), reason="LinuxCNC (AXIS) is not installed")
def test_transcription_is_the_installed_axis_code():
    assert ast.dump(ast.parse(TRANSCRIPTION)) == ast.dump(ast.parse(_installed_source()))


SIM = Path("/usr/share/doc/linuxcnc/examples/sample-configs/sim")


def _linuxcnc_session_possible() -> str:
    """Why a real LinuxCNC session cannot run here ("" when it can)."""
    import shutil
    import subprocess

    if not (shutil.which("linuxcnc") and AXIS.is_file() and (SIM / "axis/axis_mm.ini").is_file()):
        return "LinuxCNC (linuxcnc-uspace with its sample configurations) is not installed"
    probe = subprocess.run(["/usr/bin/python3", "-c", "import linuxcnc"], capture_output=True)
    return "" if probe.returncode == 0 else "the system Python has no linuxcnc module"


@pytest.mark.skipif(bool(_linuxcnc_session_possible()), reason=_linuxcnc_session_possible() or "-")
def test_real_linuxcnc_session_loads_the_safe_program_and_refuses_the_unsafe(tmp_path):
    """The sim config axis_mm.ini run by the real `linuxcnc` launcher (milltask, iocontrol, the uspace HAL),
    with tests/cli/linuxcnc/frontend.py as its display: AXIS's filter code opens both programs through the
    [FILTER] entry, the safe one is loaded by LinuxCNC's task, the unsafe one is refused with the message."""
    import shutil
    import subprocess
    import tempfile

    config = tmp_path / "config"
    config.mkdir()
    ini = (SIM / "axis/axis_mm.ini").read_text(encoding="utf-8")
    frontend = config / "frontend"  # the launcher runs DISPLAY's first word with -ini FILE: an executable
    frontend.write_text("#!/usr/bin/python3\n" + (ROOT / "tests/cli/linuxcnc/frontend.py").read_text("utf-8"), "utf-8")
    frontend.chmod(0o755)
    filter_command = f"env PYTHONPATH={shlex.quote(str(ROOT))} {shlex.quote(sys.executable)} -m nczones linuxcnc-filter"
    # Headless: no AXIS, no Tk tool-change dialog, no halui; the [FILTER] entry and [NCZONES] MACHINE added.
    ini = ini.replace("DISPLAY = axis\n", f"DISPLAY = {frontend}\n")
    ini = ini.replace("HALFILE = axis_manualtoolchange.hal\n", "").replace("HALUI = halui\n", "")
    ini = ini.replace("[FILTER]\n", f"[FILTER]\nPROGRAM_EXTENSION = .ngc nczones\nngc = {filter_command}\n", 1)
    ini += f"\n[NCZONES]\nMACHINE = {ROOT / 'specs/machines/grinder.toml'}\n"
    assert ini.count("nczones linuxcnc-filter") == 1 and f"DISPLAY = {frontend}" in ini
    (config / "axis_mm.ini").write_text(ini, encoding="utf-8")
    (config / "sim_mm.tbl").write_bytes((SIM / "sim_mm.tbl").read_bytes())
    safe, unsafe = tmp_path / "notch_over.ngc", tmp_path / "notch_dip.ngc"
    for p in (safe, unsafe):
        p.write_bytes((ROOT / "specs/examples/programs" / p.name).read_bytes())
    log = tmp_path / "frontend.log"
    # rtapi_app binds its socket as the real uid (RTAPI_UID below when root): a folder that uid can reach
    fifo = Path(tempfile.mkdtemp(prefix="nczones-rtapi-"))
    os.chmod(fifo, 0o777)
    env = dict(os.environ, HOME=str(tmp_path), NCZONES_FRONTEND_LOG=str(log),
               NCZONES_FRONTEND_PROGRAMS=f"{safe}\n{unsafe}", RTAPI_FIFO_PATH=str(fifo / "rtapi_fifo"))
    env.pop("DISPLAY", None)
    if os.getuid() == 0:  # the uspace rtapi_app refuses to run as root without a fallback uid
        env["RTAPI_UID"] = "65534"
    try:
        run = subprocess.run(["linuxcnc", str(config / "axis_mm.ini")], env=env, capture_output=True, text=True,
                             timeout=180, cwd=config)
    finally:
        shutil.rmtree(fifo, ignore_errors=True)
    assert log.is_file(), f"the front end did not run (exit {run.returncode}); see {tmp_path}/linuxcnc_debug.txt"
    lines = log.read_text(encoding="utf-8").splitlines()
    # AXIS reads FILTER_PROGRESS lines only while the filter runs (its last loop, after the exit, keeps the
    # other lines only), so the last value it shows may be below 100: any seen value is a percentage.
    assert re.fullmatch(f"LOADED {re.escape(str(safe))} file {re.escape(str(config / 'filtered-notch_over.ngc'))} "
                        r"progress \[(\d|[1-9]\d|100)?\]", lines[0]), lines[0]
    assert (config / "filtered-notch_over.ngc").read_bytes() == safe.read_bytes()
    assert lines[1].startswith(f"REFUSED {unsafe} exit 1 progress "), lines[1]
    assert "line 5: leaves the allowed zone 'wheel area' by 90 mm" in lines[1]
    assert run.returncode == 0, run.stdout + run.stderr


def test_progress_lines_are_what_axis_matches(tmp_path, capsys):
    """Every standard-error line of a safe run is a FILTER_PROGRESS line by AXIS's own pattern, rising
    from 0 to 100 (the pattern as AXIS compiles it: ^FILTER_PROGRESS=(\\d*)$ on the decoded line)."""
    from nczones.cli import main

    progress_re = re.compile("^FILTER_PROGRESS=(\\d*)$")
    program = tmp_path / "p.ngc"
    program.write_bytes((ROOT / "specs/examples/programs/notch_over.ngc").read_bytes())
    code = main(["linuxcnc-filter", str(program), "--machine", str(ROOT / "specs/machines/grinder.toml")])
    out, err = capsys.readouterr()
    assert code == 0 and out == program.read_text(encoding="utf-8")
    values = [int(progress_re.match(line + "\n").group(1)) for line in err.splitlines()]
    assert values[0] == 0 and values[-1] == 100 and values == sorted(set(values))


def test_import_machine_writes_the_ini_snippet_the_filter_reads(tmp_path, capsys):
    """import-machine --linuxcnc-filter: the snippet appended to the INI makes the filter find the machine
    file just written (MACHINE relative to the INI's folder), and the [FILTER] lines name the filter."""
    from nczones.cli import main
    from nczones.commands.linuxcnc_filter import find_machine

    ini = tmp_path / "cfg" / "mill.ini"
    ini.parent.mkdir()
    ini.write_text("[TRAJ]\nCOORDINATES = X Y Z\nLINEAR_UNITS = mm\n[AXIS_X]\nMIN_LIMIT = 0\nMAX_LIMIT = 10\n",
                   encoding="utf-8")
    machine = tmp_path / "machines" / "mill.toml"
    machine.parent.mkdir()
    snippet = tmp_path / "snippet.ini"
    assert main(["import-machine", str(ini), "-o", str(machine), "--linuxcnc-filter", str(snippet)]) == 0
    out, err = capsys.readouterr()
    assert f"{snippet}: the [FILTER] and [NCZONES] lines" in out and err == ""
    text = snippet.read_text(encoding="utf-8")
    assert "\nngc = nczones linuxcnc-filter\n" in text and "\nMACHINE = ../machines/mill.toml\n" in text
    ini.write_text(ini.read_text(encoding="utf-8") + text, encoding="utf-8")
    assert os.path.samefile(find_machine(None, str(ini)), machine)
    # Without -o there is no machine file path to name: refused before anything is written.
    assert main(["import-machine", str(ini), "--linuxcnc-filter", str(tmp_path / "s2.ini")]) == 2
    out, err = capsys.readouterr()
    assert "error[LF103]" in err and out == "" and not (tmp_path / "s2.ini").exists()


def test_unknown_program_is_refused_with_the_reason(tmp_path, capsys):
    """A call of a subroutine file (SUBROUTINE_PATH is not read) is unknown: exit 3, nothing on standard
    output, the line and code for the operator (once), the report beside the program."""
    from nczones.cli import main

    program = tmp_path / "sub.ngc"
    program.write_text("G21 G90\nG0 X-250 Y300\no<foo> call\nM2\n", encoding="utf-8")
    assert main(["linuxcnc-filter", str(program), "--machine", str(ROOT / "specs/machines/grinder.toml")]) == 3
    out, err = capsys.readouterr()
    assert out == "" and "sub.ngc could NOT be proved safe and was not loaded (verdict unknown)" in err
    assert "  line 3 [GC393]: subroutine o<foo> is not defined" in err and "GC393: GC393" not in err
    assert list(tmp_path.glob("sub.ngc.nczones.*"))
