"""The machine-file parse cache (nczones/machine_cache.py): a hit is exactly tomllib's table of the same bytes,
anything else is a miss, and the cache never fails a load."""

from __future__ import annotations

import decimal
import json
import marshal
import os
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nczones import machine_cache as mc
from nczones.machine import load_machine

ROOT = Path(__file__).resolve().parents[2]
MACHINE_FILES = sorted([*(ROOT / "tests" / "machines").glob("*.toml"), *(ROOT / "specs" / "machines").glob("*.toml"),
                        *(ROOT / "specs" / "examples" / "machines").glob("*.toml")])


def shape(value):
    """``value`` with every leaf's exact type (and a Decimal's text: 1.50 is not 1.5): what equal tables share."""
    if type(value) is dict:
        return ("dict", [(k, shape(v)) for k, v in value.items()])
    if type(value) is list:
        return ("list", [shape(v) for v in value])
    return (type(value).__name__, str(value) if type(value) is decimal.Decimal else value)


def tomllib_table(source: bytes):
    text = source.decode("utf-8").replace("\r\n", "\n").replace("\r", "\n")
    return tomllib.loads(text, parse_float=decimal.Decimal)


class Parses:
    """A ``parse`` for :func:`cached_table` that counts its calls."""

    def __init__(self, source: bytes):
        self.source, self.calls = source, 0

    def __call__(self):
        self.calls += 1
        return tomllib_table(self.source)


@pytest.fixture
def cache(tmp_path, monkeypatch):
    """A private, empty cache folder (not made yet) for this test."""
    folder = tmp_path / "cache"
    monkeypatch.setenv(mc.DIR_ENV, str(folder))
    monkeypatch.delenv(mc.SWITCH_ENV, raising=False)
    return folder


def cold_then_warm(path: Path, source: bytes):
    """The table of a miss (parsed) and of the hit after it (not parsed)."""
    first, second = Parses(source), Parses(source)
    cold = mc.cached_table(str(path), source, first)
    warm = mc.cached_table(str(path), source, second)
    assert (first.calls, second.calls) == (1, 0), "the second load of the same bytes is a hit"
    return cold, warm


def test_there_are_machine_files():
    assert len(MACHINE_FILES) > 50


def test_a_hit_equals_tomllib_on_every_machine_file(cache):
    for path in MACHINE_FILES:
        source = path.read_bytes()
        cold, warm = cold_then_warm(path, source)
        assert shape(warm) == shape(cold) == shape(tomllib_table(source)), path


def test_loaded_machines_equal_with_and_without_the_cache(cache, monkeypatch):
    for path in MACHINE_FILES:
        cold, warm = load_machine(path), load_machine(path)
        monkeypatch.setenv(mc.SWITCH_ENV, "off")
        off = load_machine(path)
        monkeypatch.delenv(mc.SWITCH_ENV)
        assert cold == warm == off and cold.sha256 == off.sha256, path


# TOML text drawn from a small grammar: tomllib reads it, the table goes through an entry and back.
_KEYS = st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=6)
_STRINGS = st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=12)
_FLOATS = st.one_of(
    st.sampled_from(["inf", "-inf", "+inf", "nan", "-nan", "+nan", "0.0", "-0.0", "1e-400", "1E+400"]),
    st.builds(lambda s, i, f, e: f"{s}{i}.{f}{e}", st.sampled_from(["", "-", "+"]), st.integers(0, 10 ** 30),
              st.from_regex(r"[0-9]{1,25}", fullmatch=True), st.sampled_from(["", "e5", "E-12", "e+0", "e-0999"])),
)
_SCALARS = st.one_of(st.booleans(), st.integers(-(2 ** 63), 2 ** 63 - 1), _STRINGS.map(lambda s: ("s", s)),
                     _FLOATS.map(lambda f: ("f", f)))
_VALUES = st.recursive(_SCALARS, lambda inner: st.one_of(st.lists(inner, max_size=4),
                                                         st.dictionaries(_KEYS, inner, max_size=4)), max_leaves=20)


def _quote(s: str) -> str:
    return '"' + "".join(f"\\u{ord(c):04x}" if c in '"\\' or ord(c) < 0x20 or ord(c) == 0x7F else c for c in s) + '"'


def _toml(value) -> str:
    """TOML text of a drawn value (inline tables and arrays)."""
    if type(value) is bool:
        return "true" if value else "false"
    if type(value) is int:
        return str(value)
    if type(value) is tuple:
        return _quote(value[1]) if value[0] == "s" else value[1]
    if type(value) is list:
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return "{" + ", ".join(f"{_quote(k)} = {_toml(v)}" for k, v in value.items()) + "}"


@settings(max_examples=60, deadline=None)
@given(st.dictionaries(_KEYS, _VALUES, max_size=5))
def test_a_hit_equals_tomllib_on_drawn_toml(table):
    source = "".join(f"{_quote(k)} = {_toml(v)}\n" for k, v in table.items()).encode("utf-8")
    expected = tomllib_table(source)
    assert shape(mc.decode(mc.encode(expected))) == shape(expected)
    with tempfile.TemporaryDirectory() as folder:
        os.environ[mc.DIR_ENV], saved = folder, os.environ.get(mc.DIR_ENV)
        try:
            _, warm = cold_then_warm(Path(folder) / "m.toml", source)
        finally:
            os.environ[mc.DIR_ENV] = saved if saved is not None else os.environ.pop(mc.DIR_ENV)
    assert shape(warm) == shape(expected)


def _filled(cache: Path, source: bytes = b'a = "1.50"\nb = 1.50\n') -> tuple[Path, bytes, Path]:
    path = cache.parent / "m.toml"
    mc.cached_table(str(path), source, Parses(source))
    entry = Path(mc.entry_path(str(cache), str(path)))
    assert entry.is_file() and (entry.stat().st_mode & 0o777) == 0o600
    assert (cache.stat().st_mode & 0o777) == 0o700
    return path, source, entry


def _is_miss(path: Path, source: bytes) -> bool:
    parse = Parses(source)
    table = mc.cached_table(str(path), source, parse)
    assert shape(table) == shape(tomllib_table(source))
    return parse.calls == 1


def test_the_entry_is_a_hit_for_the_same_bytes_only(cache):
    path, source, _ = _filled(cache, b'x = 1.50\ny = "ab"\nz = [1, 2]\n')
    assert not _is_miss(path, source)
    for i in range(len(source)):  # every one-byte change (same length) is a miss, then a hit again
        for new in {source[i] ^ 1, source[i] ^ 0x40} - {source[i]}:
            changed = source[:i] + bytes([new]) + source[i + 1:]
            try:
                tomllib_table(changed)
            except (tomllib.TOMLDecodeError, UnicodeDecodeError):
                continue
            assert _is_miss(path, changed), (i, changed)
            assert mc._read(mc.entry_path(str(cache), str(path)), source) is None
            _filled(cache, source)


@pytest.mark.parametrize("spoil", ["group_writable_entry", "other_writable_entry", "group_writable_dir",
                                   "foreign_owner", "truncated", "garbage", "empty", "other_python", "code_object",
                                   "float_leaf", "symlink"])
def test_a_spoiled_entry_is_a_miss(cache, monkeypatch, spoil):
    path, source, entry = _filled(cache)
    blob = entry.read_bytes()
    if spoil == "group_writable_entry":
        entry.chmod(0o620)
    elif spoil == "other_writable_entry":
        entry.chmod(0o602)
    elif spoil == "group_writable_dir":
        cache.chmod(0o770)
    elif spoil == "foreign_owner":
        monkeypatch.setattr(mc.os, "getuid", lambda: os.stat(entry).st_uid + 1)
    elif spoil in ("truncated", "garbage", "empty"):
        entry.write_bytes({"truncated": blob[: len(blob) // 2], "garbage": os.urandom(len(blob)),
                           "empty": b""}[spoil])
    elif spoil == "symlink":
        real = cache / "real"
        entry.rename(real)
        entry.symlink_to(real)
    else:
        stored = list(marshal.loads(blob))
        if spoil == "other_python":
            stored[2] = stored[2] + " "
        elif spoil == "code_object":
            stored[-1] = compile("1", "x", "eval")
        else:
            stored[-1] = {"a": 1.5}
        entry.write_bytes(marshal.dumps(tuple(stored)))
    assert _is_miss(path, source)


def test_each_truncation_is_a_miss(cache):
    path, source, entry = _filled(cache)
    blob = entry.read_bytes()
    for n in range(len(blob)):
        entry.write_bytes(blob[:n])
        entry.chmod(0o600)
        assert mc._read(str(entry), source) is None, n


def test_a_group_writable_dir_is_not_written(cache):
    cache.mkdir(mode=0o700)
    cache.chmod(0o770)
    path = cache.parent / "m.toml"
    assert _is_miss(path, b"a = 1\n") and _is_miss(path, b"a = 1\n")
    assert not list(cache.iterdir())


def test_a_read_only_dir_still_gives_hits(cache):
    path, source, _ = _filled(cache)
    cache.chmod(0o500)
    try:
        assert not _is_miss(path, source)
        assert _is_miss(path, source + b"c = 2\n")  # cannot be stored (unless root): still no error
    finally:
        cache.chmod(0o700)


def test_an_unusable_dir_means_no_cache(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("")
    monkeypatch.setenv(mc.DIR_ENV, str(blocker / "cache"))
    assert _is_miss(tmp_path / "m.toml", b"a = 1\n") and _is_miss(tmp_path / "m.toml", b"a = 1\n")


def test_off_reads_and_writes_nothing(cache, monkeypatch):
    path, source, entry = _filled(cache)
    monkeypatch.setenv(mc.SWITCH_ENV, "off")
    assert _is_miss(path, source)
    entry.unlink()
    assert _is_miss(path, source) and not entry.exists()


def test_what_is_not_stored(cache):
    path = cache.parent / "m.toml"
    dated = b"when = 1979-05-27T07:32:00Z\n"
    assert _is_miss(path, dated) and _is_miss(path, dated)  # a TOML date is not cached
    big = b"a = 1\n" + b"#" * mc.MAX_SOURCE
    assert _is_miss(path, big) and _is_miss(path, big)
    bad = b"a = \n"
    for _ in range(2):
        with pytest.raises(tomllib.TOMLDecodeError):
            mc.cached_table(str(path), bad, Parses(bad))


def test_where_the_cache_is(monkeypatch, tmp_path):
    for name in (mc.DIR_ENV, mc.SWITCH_ENV, "XDG_CACHE_HOME"):
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("HOME", str(tmp_path))
    assert mc.cache_dir() == str(tmp_path / ".cache" / "nczones")
    monkeypatch.setenv("XDG_CACHE_HOME", "relative")  # not absolute: ignored (XDG base directory spec)
    assert mc.cache_dir() == str(tmp_path / ".cache" / "nczones")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "x"))
    assert mc.cache_dir() == str(tmp_path / "x" / "nczones")
    monkeypatch.setenv(mc.DIR_ENV, str(tmp_path / "d"))
    assert mc.cache_dir() == str(tmp_path / "d")
    monkeypatch.setenv(mc.SWITCH_ENV, "off")
    assert mc.cache_dir() is None


_PROBE = """
import sys
from nczones import cli
try:
    cli.main(["verify", sys.argv[1], "--machine", sys.argv[2]])
except SystemExit:
    pass
print("MODULES", *sorted(m for m in ("tomllib", "datetime", "typing") if m in sys.modules))
"""


@pytest.mark.parametrize("dialect", ["linuxcnc", "fanuc"])
def test_a_verify_that_hits_the_cache_imports_no_toml_parser_nor_typing(cache, tmp_path, machine_file, dialect):
    program = tmp_path / "p.nc"
    program.write_text("G0 X1. Y1.\nG1 X2. F100.\nM30\n")
    machine = machine_file("box_5000", set={"machine.dialect": dialect})
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    seen = []
    for _ in range(2):
        r = subprocess.run([sys.executable, "-c", _PROBE, str(program), str(machine)], capture_output=True, text=True,
                           env=env, cwd=tmp_path, timeout=120)
        seen.append((r.stdout.split("MODULES")[-1].split(), ": safe:" in r.stdout + r.stderr))
    assert seen == [(["datetime", "tomllib", "typing"], True), ([], True)], seen


def test_verdicts_equal_with_and_without_the_cache(cache, monkeypatch):
    from nczones.prover import verify

    ex = ROOT / "specs" / "examples"
    cases = tomllib.loads((ex / "examples.toml").read_text())["example"][:6]
    for case in cases:
        got = []
        for switch in ("off", "on", "on"):
            monkeypatch.setenv(mc.SWITCH_ENV, switch)
            r = verify(str(ex / case["program"]), load_machine(ex / case["machine"]), margin=case.get("margin", "0"),
                       params=case.get("params", []), recovery=case.get("recovery"))
            got.append(json.dumps([r.verdict.label, [(v.line, v.zone, str(v.point)) for v in r.violations]]))
        assert got[0] == got[1] == got[2], case["name"]


def test_decode_reads_the_stored_table_in_place():
    """The stored containers are reused (a region list of thousands of tables is not built again), each
    Decimal's 1-tuple replaced by the Decimal, written as it was (issue 36, table45)."""
    stored = mc.encode({"a": [{"x": decimal.Decimal("1.50"), "y": "t"}, 2, True], "b": {"c": decimal.Decimal("-0")}})
    rows, row = stored["a"], stored["a"][0]
    got = mc.decode(stored)
    assert got is stored and got["a"] is rows and got["a"][0] is row
    assert shape(got) == shape({"a": [{"x": decimal.Decimal("1.50"), "y": "t"}, 2, True],
                                "b": {"c": decimal.Decimal("-0")}})
    assert str(got["a"][0]["x"]) == "1.50" and str(got["b"]["c"]) == "-0"


def test_a_stored_table_sharing_a_container_is_read_right_or_missed(cache):
    """An entry whose table holds one container twice (no entry nczones writes does: a foreign one) decodes the
    container once; the second visit meets a Decimal, a value encode never stores, and the entry is a miss."""
    path, source, entry = _filled(cache, b'a = { x = 1.50 }\nb = { x = 1.50 }\n')
    stored = list(marshal.loads(entry.read_bytes()))
    shared = {"x": ("1.50",)}
    stored[-1] = {"a": shared, "b": shared}
    entry.write_bytes(marshal.dumps(tuple(stored)))
    assert _is_miss(path, source)


def test_equal_strings_are_stored_once():
    """encode makes equal strings one object, which marshal writes once: read back, the keys and repeated values
    of a long region list are one object each (fewer strings to make at every start, issue 36)."""
    rows = [{"upto": str(k + 1), "max": "300"} for k in range(3)]
    rows.append({"upto": "".join(["30", "0"]), "max": "".join(["30", "0"])})  # equal texts, distinct objects
    stored = mc.encode({"regions": rows})
    back = marshal.loads(marshal.dumps(stored))
    keys = [k for row in back["regions"] for k in row]
    assert len({id(k) for k in keys if k == "upto"}) == 1
    assert len({id(row["max"]) for row in back["regions"]}) == 1
    assert back["regions"][3]["upto"] is back["regions"][3]["max"]
    assert mc.decode(back) == {"regions": rows}
