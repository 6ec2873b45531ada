"""What a CI job sees (issue 38, "CI traps"): an empty fleet selection fails, SIGTERM stops a run the way
Ctrl-C does, ``--output`` still shows the verdicts, fleet text is not cut inside a word."""

from __future__ import annotations

import signal
import subprocess
import sys
import time
from pathlib import Path

from nczones.cli import main
from tests.machines import machine_text
from tests.processes import cpu_seconds, interrupt

ROOT = Path(__file__).resolve().parents[2]
GRINDER = str(ROOT / "specs/machines/grinder.toml")


def _project(root: Path, globs: str = '["*.ngc"]') -> Path:
    (root / "m.toml").write_text(machine_text("x_travel_10"), encoding="utf-8")
    (root / "nczones.toml").write_text(f'[machines.m]\nfile = "m.toml"\nprograms = {globs}\n', encoding="utf-8")
    return root


def test_an_empty_fleet_selection_fails_naming_the_glob(tmp_path, capsys):
    # Before: "0 cells ...; 0 jobs ran", exit 0 -- a CI job checking nothing passed.
    project = _project(tmp_path, '["programs/**/*.ngc"]')
    assert main(["fleet", "check", str(project), "--serial"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "error[FL112]: no program selected" in err
    assert "programs = ['programs/**/*.ngc']" in err and str(project) in err
    (tmp_path / "programs").mkdir()
    (tmp_path / "programs" / "a.ngc").write_text("G0 X5\nM2\n", encoding="utf-8")
    assert main(["fleet", "check", str(project), "--serial", "--program", "other/*.nc"]) == 2
    out, err = capsys.readouterr()
    assert "error[FL112]" in err and "--program 'other/*.nc' matches none" in err
    assert main(["fleet", "check", str(project), "--serial", "--machine", "lathe"]) == 2
    assert "--machine lathe: no such machine" in capsys.readouterr().err
    assert main(["fleet", "check", str(project), "--serial"]) == 0  # the program is there now: it runs


def test_fleet_findings_are_cut_at_a_word():
    from nczones.fleet.status import FINDING_CHARS, cut_at_word

    message = ("G41: cutter radius compensation (G41) offsets the path by the tool radius, and controls differ "
               "in how; if this machine is LinuxCNC, set cutter_compensation")
    cut = cut_at_word(message)
    assert len(cut) <= FINDING_CHARS and cut.endswith("…")
    kept = cut[:-1]
    # the cut ends a word of the message: what follows it there is a space (or a comma before one)
    assert message.startswith(kept) and message[len(kept)] in " ,;:"
    assert cut_at_word(message[:FINDING_CHARS]) == message[:FINDING_CHARS]


def test_output_still_prints_each_summary_line(tmp_path, capsys):
    report = tmp_path / "r.json"
    dip, over = (str(ROOT / "specs/examples/programs" / n) for n in ("notch_dip.ngc", "notch_over.ngc"))
    assert main(["verify", dip, over, "--machine", GRINDER, "--format", "json", "--output", str(report)]) == 1
    out, _ = capsys.readouterr()
    lines = out.splitlines()
    assert lines[0].startswith(f"{dip}: unsafe: 1 violating block, the first at line 5")
    assert lines[1].startswith(f"{over}: safe: every motion stays inside the allowed set")
    assert lines[2] == f"report written to {report}" and len(lines) == 3
    assert report.read_text(encoding="utf-8").lstrip().startswith("[")


def test_sigterm_stops_a_running_verify_like_ctrl_c_with_its_own_exit_code(tmp_path):
    from tests.prover.test_limits import hard_program

    prog = tmp_path / "hard.ngc"
    prog.write_text(hard_program(repeats=6))
    # Before: SIGTERM's default disposition killed the process: exit -15 (143 in a shell), no report.
    proc = subprocess.Popen([sys.executable, "-m", "nczones", "verify", str(prog), "--machine",
                             str(ROOT / "specs" / "machines" / "mill.toml"), "--engine", "z3"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT,
                            preexec_fn=lambda: signal.signal(signal.SIGTERM, signal.SIG_DFL))
    deadline = time.monotonic() + 120
    while cpu_seconds(proc.pid) < 1.5 and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    assert proc.poll() is None, proc.communicate()
    stopped = interrupt(proc, sig=signal.SIGTERM)
    out, err = stopped.out, stopped.err
    assert proc.returncode == 143, (out, err)
    assert stopped.cpu_after_signal_s < 1.0 and stopped.wall_after_signal_s < 20, stopped
    assert "unknown[VF204]: interrupted" in out, out
    assert "(interrupted: a partial report)" in out.splitlines()[-1]
    assert "stopped by SIGTERM" in err and "Traceback" not in err
