"""The program's SHA-256 is computed only for the reports that carry it (issue 36, boot43).

A text report never names the digest, so ``verify`` leaves it for later (:class:`nczones.digest.LaterDigest`);
JSON and SARIF ask for it and get the SHA-256 of the file's bytes, as before.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import pickle
from pathlib import Path

import pytest

from nczones import cli, digest
from nczones.digest import LaterDigest
from nczones.gcode.source import load_program, program_text

MILL = str(Path(__file__).resolve().parents[2] / "specs" / "machines" / "mill.toml")
#: A program whose bytes no other digest of a verify has (the machine file's, the caches' keys are other sizes).
LINES = ["G90 G21", "(lazy digest)", *(f"G1 X{i % 17} Y{i % 13} F100" for i in range(300)), "M2"]


def _verify(tmp_path, monkeypatch, fmt: str) -> tuple[str, list[int], bytes]:
    """The report of a verify in format ``fmt``, the sizes of the data hashed meanwhile, the program's bytes."""
    program = tmp_path / "p.ngc"
    program.write_text("\n".join(LINES) + "\n")
    data = program.read_bytes()
    sizes: list[int] = []
    real = digest.sha256

    def counting(payload: bytes | None = None):  # noqa: ANN202
        sizes.append(len(payload or b""))
        return real(payload)

    monkeypatch.setattr(digest, "sha256", counting)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert cli.main(["verify", str(program), "--machine", MILL, "--format", fmt]) == 0
    return out.getvalue(), sizes, data


def test_a_text_report_never_hashes_the_program(tmp_path, monkeypatch):
    report, sizes, data = _verify(tmp_path, monkeypatch, "text")
    assert "safe" in report
    assert len(data) not in sizes


@pytest.mark.parametrize("fmt", ["json", "sarif"])
def test_json_and_sarif_still_carry_the_digest_of_the_bytes(tmp_path, monkeypatch, fmt):
    report, sizes, data = _verify(tmp_path, monkeypatch, fmt)
    assert sizes.count(len(data)) == 1  # hashed once, when the report asked
    want = hashlib.sha256(data).hexdigest()
    doc = json.loads(report)
    if fmt == "json":
        assert doc["program_sha256"] == want
    else:
        assert doc["runs"][0]["artifacts"][0]["hashes"]["sha-256"] == want


def test_a_later_digest_is_the_digest_of_its_bytes_once_computed():
    data = b"G1 X1\n" * 50
    later = LaterDigest(data)
    assert not later.known
    assert later.hex == hashlib.sha256(data).hexdigest() and later.known
    assert later == hashlib.sha256(data).hexdigest() == later  # both ways round
    assert later == LaterDigest(data) and hash(later) == hash(later.hex)
    assert later != LaterDigest(data + b"M2\n")
    assert pickle.loads(pickle.dumps(LaterDigest(data))) == later.hex  # sent as its digest, not its bytes


def test_the_sources_digest_is_what_it_was(tmp_path):
    path = tmp_path / "c.ngc"
    raw = "G1 X1 (caf\u00e9)\n".encode("cp1252")  # a comment byte read as CP1252: the digest is of the bytes
    path.write_bytes(raw)
    assert load_program(path).sha256 == hashlib.sha256(raw).hexdigest()
    assert program_text("G1 X1\n").sha256 == hashlib.sha256(b"G1 X1\n").hexdigest()
