"""``nczones verify`` over the LinuxCNC corpus: no internal error (exit 4), no hang (issue 33, classes 6, 7).

Every MANIFEST program written for LinuxCNC (648: LinuxCNC's own, CAMotics, Vectric .tap) runs through the
command line in process (``tests/corpus_verify.py``: ``--budget 10``, a hang alarm after 300 s) on a
9-axis mill with a travel box and a forbidden block.  Exits 0 to 3 are all fine here (the programs were not
written for this machine); 4 and a hang are not.  The default run takes a fixed sample of 40 programs spread
over the list; ``-m long`` runs them all (measured numbers in specs/gcode-support.md, "Reading a program").
"""

from __future__ import annotations

import pytest

from tests.corpus import MANIFEST
from tests.corpus_verify import LINUXCNC_MACHINE, linuxcnc_programs, run, sample

pytestmark = [pytest.mark.corpus, pytest.mark.skipif(not MANIFEST.is_file(), reason="corpus not available")]


def _check(programs, tmp_path, capsys):
    machine = tmp_path / "linuxcnc.toml"
    machine.write_text(LINUXCNC_MACHINE)
    counts, bad, slowest = run(programs, lambda _rel: machine)
    with capsys.disabled():
        print(f"\nverify over {len(programs)} LinuxCNC corpus programs: exits {dict(counts)}, slowest {slowest:.1f} s")
    assert not bad, bad
    assert sum(counts.values()) == len(programs) and counts[0] > len(programs) // 2, counts


def test_linuxcnc_corpus_sample_has_no_internal_error_and_no_hang(tmp_path, capsys):
    _check(sample(linuxcnc_programs(), 40), tmp_path, capsys)


@pytest.mark.long
def test_whole_linuxcnc_corpus_has_no_internal_error_and_no_hang(tmp_path, capsys):
    programs = linuxcnc_programs()
    assert len(programs) >= 600
    _check(programs, tmp_path, capsys)
