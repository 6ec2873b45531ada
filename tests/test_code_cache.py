"""The cache of run-time code objects (nczones/code_cache.py): a hit is the code ``compile`` gives for the very
same text, anything else compiles, and the cache never fails."""

from __future__ import annotations

import builtins
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones import code_cache as cc
from nczones import machine_cache as mc

ROOT = Path(__file__).resolve().parents[1]


def source(n: int, tag: str = "x") -> str:
    """A source of at least :data:`MIN_STORED` characters that sets ``tag`` to ``n``."""
    pad = "".join(f"_{tag}{k} = {k}\n" for k in range(cc.MIN_STORED // 8))
    return pad + f"{tag} = {n}\n"


def run(code) -> dict:
    scope: dict = {}
    exec(code, scope)  # noqa: S102  # the tests' own sources
    return scope


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """A private, empty cache folder for this test, and an empty memo."""
    folder = tmp_path / "cache"
    monkeypatch.setenv(mc.DIR_ENV, str(folder))
    monkeypatch.delenv(mc.SWITCH_ENV, raising=False)
    cc.forget()
    yield folder
    cc.forget()


def entries(folder: Path) -> list[Path]:
    return sorted(folder.glob("code-*.marshal")) if folder.is_dir() else []


def test_a_stored_source_is_read_back_without_compiling(cache, monkeypatch):
    text = source(42)
    first = cc.compiled(text, "<test>")
    assert run(first)["x"] == 42 and len(entries(cache)) == 1
    cc.forget()

    def refuse(*args, **kwargs):
        raise AssertionError("compiled again")

    monkeypatch.setattr(builtins, "compile", refuse)
    again = cc.compiled(text, "<test>")
    assert again is not first and again == first and run(again)["x"] == 42


def test_the_memo_gives_the_same_object(cache, monkeypatch):
    text = source(7)
    code = cc.compiled(text, "<test>")
    monkeypatch.setenv(mc.SWITCH_ENV, "off")  # no folder: only the memo can answer

    def refuse(*args, **kwargs):
        raise AssertionError("compiled again")

    monkeypatch.setattr(builtins, "compile", refuse)
    assert cc.compiled(text, "<test>") is code


def test_a_full_memo_starts_again_and_keeps_memoizing(cache, monkeypatch):
    # the memo is bounded (MAX_MEMO) but never stops answering: a process past the bound (a fleet, a test run of
    # thousands of plans) empties it and goes on keeping what it compiles
    monkeypatch.setattr(cc, "MAX_MEMO", 3)
    monkeypatch.setenv(mc.SWITCH_ENV, "off")
    codes = [cc.compiled(f"x = {k}\n", "<test>") for k in range(3)]
    assert all(cc.compiled(f"x = {k}\n", "<test>") is c for k, c in enumerate(codes))
    late = cc.compiled("x = 99\n", "<test>")  # the memo was full: emptied, then this one kept
    assert cc.compiled("x = 99\n", "<test>") is late
    assert cc.compiled("x = 0\n", "<test>") is not codes[0]  # (forgotten with the rest: compiled again)


def test_another_text_in_the_same_entry_is_a_miss(cache, monkeypatch):
    monkeypatch.setattr(cc, "SLOTS_HEX", 0)  # every source in one entry: each the other's collision
    a, b = source(1, "a"), source(2, "b")
    assert run(cc.compiled(a, "<test>"))["a"] == 1
    assert run(cc.compiled(b, "<test>"))["b"] == 2
    cc.forget()
    assert run(cc.compiled(a, "<test>"))["a"] == 1  # b's entry was read and refused: compiled, stored again
    assert len(entries(cache)) == 1


def test_another_file_name_is_a_miss(cache):
    text = source(3)
    code = cc.compiled(text, "<one>")
    cc.forget()
    other = cc.compiled(text, "<two>")
    assert other.co_filename == "<two>" and code.co_filename == "<one>"


@pytest.mark.parametrize("damage", ["truncated", "garbage", "group-writable", "foreign header"])
def test_a_damaged_entry_compiles(cache, damage, monkeypatch):
    text = source(5)
    cc.compiled(text, "<test>")
    (entry,) = entries(cache)
    blob = entry.read_bytes()
    if damage == "truncated":
        entry.write_bytes(blob[: len(blob) // 2])
    elif damage == "garbage":
        entry.write_bytes(b"\x00" * 100)
    elif damage == "group-writable":
        entry.chmod(0o620)
    else:  # a well-formed entry of another Python
        import marshal

        stored = marshal.loads(blob)
        entry.write_bytes(marshal.dumps((stored[0], stored[1], "another python", *stored[3:])))
    cc.forget()
    calls = []
    real = builtins.compile

    def counting(*args, **kwargs):
        calls.append(args[1])
        return real(*args, **kwargs)

    monkeypatch.setattr(builtins, "compile", counting)
    assert run(cc.compiled(text, "<test>"))["x"] == 5
    assert calls == ["<test>"]


def test_off_and_short_sources_store_nothing(cache, monkeypatch):
    cc.compiled("y = 1\n", "<test>")
    assert entries(cache) == []
    monkeypatch.setenv(mc.SWITCH_ENV, "off")
    assert run(cc.compiled(source(9), "<test>"))["x"] == 9
    assert entries(cache) == []


def test_an_unwritable_folder_still_compiles(tmp_path, monkeypatch):
    folder = tmp_path / "ro"
    folder.mkdir(mode=0o500)
    monkeypatch.setenv(mc.DIR_ENV, str(folder / "inner"))
    cc.forget()
    assert run(cc.compiled(source(11), "<test>"))["x"] == 11
    cc.forget()


@settings(max_examples=30, deadline=None)
@given(st.lists(st.integers(-10**30, 10**30), min_size=1, max_size=40), st.integers(0, 3))
def test_a_hit_runs_as_the_compiled_text(values, slot_digits):
    """Any text: the code read back computes what ``compile`` of the text computes."""
    body = "".join(f"v{k} = {v!r}\n" for k, v in enumerate(values))
    text = body + "total = " + " + ".join(f"v{k}" for k in range(len(values))) + "\n"
    text += "#" * max(0, cc.MIN_STORED - len(text)) + "\n"
    folder = os.environ[mc.DIR_ENV]  # the test session's private folder (tests/conftest.py)
    assert folder
    cc.forget()
    first = run(cc.compiled(text, "<hypothesis>"))
    cc.forget()
    second = run(cc.compiled(text, "<hypothesis>"))
    assert first["total"] == second["total"] == sum(values) == run(compile(text, "<h>", "exec"))["total"]


def _verify(program: Path, machine: Path, env: dict) -> dict:
    out = subprocess.run([sys.executable, "-m", "nczones", "verify", str(program), "--machine", str(machine),
                          "--format", "json"], capture_output=True, text=True, env=env, check=False, cwd=ROOT)
    assert out.returncode in (0, 1), out.stderr
    doc = json.loads(out.stdout)
    doc.pop("timings")  # seconds differ from run to run
    doc["stats"].pop("profile")
    return doc


def test_a_verify_reads_its_plans_back_and_says_the_same(tmp_path, machine_file):
    """The double pass's plans come from the folder on a second run (entries made by the first), and the
    report is the same as with the cache off."""
    sys.path.insert(0, str(ROOT / "bench"))
    try:
        import bench_gcode
    finally:
        sys.path.pop(0)
    program = tmp_path / "arcs.ngc"
    program.write_text(bench_gcode.rarc_program(1500))
    machine = machine_file("box_5000")
    folder = tmp_path / "cache"
    env = dict(os.environ, **{mc.DIR_ENV: str(folder)})
    env.pop(mc.SWITCH_ENV, None)
    first = _verify(program, machine, env)
    stored = entries(folder)
    assert stored, "the plans of R arcs are long sources: stored"
    stamps = {p: p.stat().st_mtime_ns for p in stored}
    second = _verify(program, machine, env)
    assert {p: p.stat().st_mtime_ns for p in entries(folder)} == stamps  # read, not written again
    off = _verify(program, machine, dict(env, **{mc.SWITCH_ENV: "off"}))
    assert first == second == off
    assert first["verdict"] in ("safe", "unsafe")
