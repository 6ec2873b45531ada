"""Zone kinds x per-kind tables (issue 34): every consumer dispatches on the zone kind through a
:class:`nczones.zones.kinds.KindTable`, never through ``isinstance``, and every kind has an entry in every table.

A new kind (a class in nczones/zones/model.py, listed in ``ZONE_KINDS``) fails
:func:`test_every_kind_has_an_entry_in_every_table` until each table has an entry for it: the tables without a
fallback must get one (the kind is not modelled there otherwise); where a table's declared fallback is right
for the kind, add ``(table, kind)`` to ``ON_FALLBACK`` below, on purpose.
"""

from __future__ import annotations

import ast
import importlib
import re
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from nczones.zones import BoxZone, ZonePoint
from nczones.zones.kinds import TABLES, ZONE_KINDS, KindTable, coverage

PACKAGE = Path(__file__).resolve().parents[2] / "nczones"
DESIGN = PACKAGE.parent / "docs" / "design.md"

#: (table, kind) pairs that knowingly ride the table's fallback (none today: every kind has its own entry).
ON_FALLBACK: frozenset[tuple[str, str]] = frozenset()


def _modules_making_tables() -> list[str]:
    """The modules whose source makes a ``KindTable(...)`` (found by reading, not by importing)."""
    out = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if path.parent.name == "zones" and path.name == "kinds.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        if any(isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id == "KindTable"
               for n in ast.walk(tree)):
            rel = path.relative_to(PACKAGE.parent).with_suffix("")
            out.append(".".join(rel.parts))
    return out


@pytest.fixture(scope="module")
def tables() -> list[KindTable]:
    for module in _modules_making_tables():
        importlib.import_module(module)
    return list(TABLES)


def test_every_module_that_makes_a_table_is_seen(tables):
    """Each module that makes tables has at least one in ``TABLES`` under its own name (a table's name starts
    with its module's path below nczones)."""
    made = {t.name.rsplit(".", 1)[0] for t in tables}
    for module in _modules_making_tables():
        assert module.removeprefix("nczones.") in made, module


def test_every_kind_has_an_entry_in_every_table(tables):
    got = coverage(ZONE_KINDS, tables)
    assert got.missing == ()
    assert set(got.on_fallback) == ON_FALLBACK


def test_a_new_kind_is_reported_until_registered(tables, monkeypatch):
    """A throw-away kind: the coverage check names every table without fallback as missing it and every table
    with one as riding its fallback; registered in one table, that table drops out of the list."""

    @dataclass(frozen=True)
    class CylinderZone:
        name: str
        forbid: bool = False
        point: ZonePoint = ZonePoint.MACHINE
        kind = "cylinder"

    got = coverage((CylinderZone,), tables)
    required = sorted(t.name for t in tables if not t.has_fallback)
    optional = sorted(t.name for t in tables if t.has_fallback)
    assert sorted(name for name, _ in got.missing) == required
    assert sorted(name for name, _ in got.on_fallback) == optional
    assert {kind for _, kind in got.missing + got.on_fallback} == {"CylinderZone"}
    assert "prover.exact.line_violation" in required and "prover.smt.zone_violation" in required

    line = next(t for t in tables if t.name == "prover.exact.line_violation")
    monkeypatch.setitem(line._entries, CylinderZone, lambda zone, ln, d: [])
    again = coverage((CylinderZone,), tables)
    assert sorted(name for name, _ in again.missing) == [n for n in required if n != line.name]


def test_lookup_is_by_the_exact_class():
    """A subclass does not silently take its parent's entry; a table without fallback says which kind it lacks."""
    t: KindTable[str] = KindTable("test.exact_class", register_globally=False)
    t.set(BoxZone, "box")

    @dataclass(frozen=True)
    class Sub(BoxZone):
        pass

    zone = BoxZone("b", (("X", Fraction(0), Fraction(1)),))
    assert t.of(zone) == "box"
    with pytest.raises(Exception, match="no entry for zone kind Sub"):
        t.of(Sub("s", zone.limits))
    with pytest.raises(Exception, match="registered twice"):
        t.set(BoxZone, "again")


def test_the_fallbacks_of_the_prover_are_conservative(tables):
    """What a kind without its own entry gets where the verdict depends on it: nothing proved (the screen
    shows no row, the box test shows no fit, no arc enclosure, a depth only as a lower bound, no certificate)
    or ``unknown`` with a reason (the nose)."""
    from nczones.prover import core, exact, nose, screen

    @dataclass(frozen=True)
    class Odd:
        name: str = "odd"
        forbid: bool = False
        point: ZonePoint = ZonePoint.TIP
        kind = "odd"

    z = Odd()
    ok = np.ones(4, dtype=bool)
    screen.ZONE_ROWS(z, None, None, ok, 9, [])
    assert not ok.any()
    assert exact.BOX_FITS(z, lambda a: (Fraction(0), Fraction(0)), {}) is False
    assert exact.CERTAIN_CELLS(z, None, {}, {}, Fraction(0), Fraction(0)) is False
    assert exact.LINE_DEPTH_EXACT.of(z) is False
    assert exact.OUTSIDE_POINT_MORE(z, None, {}, Fraction(0), Fraction(0), {}, [], []) is None
    assert exact.decidable(z) is False  # the SMT tier decides it (or says unknown)
    assert core.ARC_ENCLOSURES(z) is False
    assert "is not modelled" in nose.NOSE_GROWN(z, Fraction(1, 2))


ZONE_CLASS_NAMES = {k.__name__ for k in ZONE_KINDS} | {"Zone"}


def _zone_isinstance_sites(root: Path = PACKAGE) -> list[str]:
    """``file:line`` of every ``isinstance(x, <zone class>)`` outside nczones/zones/."""
    found = []
    for path in sorted(root.rglob("*.py")):
        if path.parent.name == "zones":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "isinstance" \
                    and len(node.args) == 2:
                names = {n.id for n in ast.walk(node.args[1]) if isinstance(n, ast.Name)}
                names |= {n.attr for n in ast.walk(node.args[1]) if isinstance(n, ast.Attribute)}
                if names & ZONE_CLASS_NAMES:
                    found.append(f"{path.relative_to(root.parent)}:{node.lineno}")
    return found


def test_no_isinstance_dispatch_on_zone_kinds_outside_the_zone_package():
    assert _zone_isinstance_sites() == []


def test_the_isinstance_scan_is_not_blind(tmp_path):
    pkg = tmp_path / "nczones"
    (pkg / "report").mkdir(parents=True)
    (pkg / "zones").mkdir()
    (pkg / "report" / "a.py").write_text("def f(z):\n    return isinstance(z, (BoxZone, int))\n")
    (pkg / "report" / "b.py").write_text("def f(z):\n    return isinstance(z, model.PolygonZone)\n")
    (pkg / "zones" / "c.py").write_text("def f(z):\n    return isinstance(z, BoxZone)\n")
    assert _zone_isinstance_sites(pkg) == ["nczones/report/a.py:2", "nczones/report/b.py:2"]


def test_design_lists_every_table(tables):
    """docs/design.md "How to add a zone kind" names every table (in backticks) and the files that hold the
    tables without fallback, which are the places a new kind must touch."""
    text = DESIGN.read_text(encoding="utf-8")
    section = text.split("### How to add a zone kind", 1)[1].split("\n#", 1)[0]
    named = set(re.findall(r"`([a-z0-9_]+(?:\.[a-z0-9_]+)+)`", section))
    assert {t.name for t in tables} <= named
    for t in tables:
        if not t.has_fallback:
            module = "nczones/" + "/".join(t.name.split(".")[:-1]) + ".py"
            assert module in section, module
