"""The progress bar: drawn on a terminal, silent otherwise; the prover and controller report their lines."""

import io
import subprocess
import sys

from nczones.gcode import interpret_text
from nczones.machine import load_machine
from nczones.prover import verify_text
from nczones.report.progress import ProgressBar, progress_for

from .helpers import EX, MACHINES


class FakeTTY(io.StringIO):
    def isatty(self):
        return True


def _long_program(n=400):
    return "G21 G90 G54\nG0 X-250 Y300\nG1 Y150 F500\n" + "".join(f"G1 X{-250 + (k % 2) * 10}\n" for k in range(n))


def test_bar_draws_on_a_terminal(monkeypatch):
    monkeypatch.setenv("TERM", "xterm")
    stream = FakeTTY()
    bar = progress_for(stream, "verify")
    assert bar is not None
    bar.min_interval = 0
    m = load_machine(MACHINES / "grinder.toml")
    prog = _long_program()
    result = verify_text(prog, m, progress=bar)
    bar.close()
    assert result.verdict.label == "safe"
    out = stream.getvalue()
    last = out.rstrip("\r ").split("\r")[-1]
    assert last.startswith("verify 402 motions, 403 blocks (line 403/403) ") and "motions/s" in last, last
    assert out.endswith("\r")  # erased at the end, the terminal is left clean


def test_loops_count_as_they_run(monkeypatch):
    # three lines run 3,000 motions: the bar counts executed motions and blocks, not source lines
    monkeypatch.setenv("TERM", "xterm")
    stream = FakeTTY()
    bar = progress_for(stream, "verify")
    bar.min_interval = 0
    m = load_machine(MACHINES / "grinder.toml")
    prog = ("G21 G90 G54\nG0 X-250 Y300\nG1 Y150 F500\n#1 = 0\no100 while [#1 LT 1500]\n"
            "G1 X-240\nG1 X-250\n#1 = [#1 + 1]\no100 endwhile\nM2\n")
    assert verify_text(prog, m, progress=bar).verdict.label == "safe"
    frames = [f for f in stream.getvalue().split("\r") if f.strip()]
    counts = [int(f.split()[1].replace(",", "")) for f in frames]
    assert counts == sorted(counts) and counts[-1] == 3002, frames[-1]
    assert all("(line " in f for f in frames)


def test_silent_when_not_a_terminal():
    stream = io.StringIO()
    assert progress_for(stream, "verify") is None
    bar = ProgressBar(stream, "verify", min_interval=0)  # even if built by hand, it stays quiet
    bar(5, 10)
    bar.close()
    assert stream.getvalue() == "" and bar.calls == 1


def test_dumb_terminal_is_silent(monkeypatch):
    monkeypatch.setenv("TERM", "dumb")
    assert progress_for(FakeTTY(), "verify") is None


def test_verify_reports_increasing_lines_up_to_the_last():
    m = load_machine(MACHINES / "grinder.toml")
    seen = []
    verify_text(_long_program(), m, progress=lambda line, total: seen.append((line, total)))
    lines = [s[0] for s in seen]
    assert lines == sorted(lines) and lines[-1] == 403 and {s[1] for s in seen} == {403}


def test_simulate_reports_lines():
    from nczones.controller import simulate

    m = load_machine(MACHINES / "grinder.toml")
    seen = []
    run = interpret_text("G21 G90 G54\nG0 X-250 Y300\nG1 Y150 F5000\nG1 X-240\nG1 X-250\n", m)
    res = simulate(run, m, progress=lambda line, total: seen.append((line, total)))
    assert not res.alarms
    assert [s[0] for s in seen] == [2, 3, 4, 5] and seen[-1][1] == 5


def test_cli_stderr_is_quiet_on_a_pipe():
    for cmd in (["verify", "programs/notch_over.ngc"], ["simulate", "programs/notch_over.ngc"]):
        r = subprocess.run([sys.executable, "-m", "nczones", *cmd, "--machine", "../machines/grinder.toml"],
                           capture_output=True, text=True, cwd=EX)
        assert r.returncode == 0, r.stderr
        assert r.stderr == ""


class _Closed(io.StringIO):
    def isatty(self):
        raise ValueError("I/O operation on closed file")


def test_verify_asks_for_a_bar_as_progress_for_answers(monkeypatch):
    # issue 36 (boot44): nczones verify imports the progress module for a terminal only; its answer is
    # progress_for's for every kind of stream (a terminal, TERM=dumb, a file, one that cannot be asked, none)
    from nczones.commands.verify import _progress_bar

    for term in ("xterm", "dumb"):
        monkeypatch.setenv("TERM", term)
        for stream in (FakeTTY(), io.StringIO(), _Closed(), object(), None):
            ours, theirs = _progress_bar(stream), progress_for(stream if stream is not None else io.StringIO(),
                                                                "verify")
            assert (ours is None) == (theirs is None), (term, stream)
            assert ours is None or (type(ours), ours.label) == (type(theirs), theirs.label)


def test_a_verify_without_a_terminal_loads_no_progress_module(tmp_path):
    # a JSON report (a text report asks the module whether to colour)
    program = tmp_path / "small.ngc"
    program.write_text("G90 G21\nG1 X10 Y10 F100\nM2\n")
    code = (f"import sys\nfrom nczones.cli import main\nassert main(['verify', {str(program)!r}, '--machine', "
            f"{str(MACHINES / 'grinder.toml')!r}, '--format', 'json']) in (0, 1, 3)\n"
            "print('nczones.report.progress' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == "False"
