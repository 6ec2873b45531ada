"""Fleet verification: every program of a library against every machine, incrementally, serial or on Dask.

A library is a folder with a project file ``nczones.toml``
(:mod:`nczones.fleet.project`): its machines, which programs run on which
(globs) and the settings of each program.  Every (program, machine) pair is
a cell; the cells' jobs are keyed by the SHA-256 of the program, the
machine file, the settings and the nczones version
(:mod:`nczones.fleet.jobs`), and their results live in an SQLite store
(:mod:`nczones.fleet.store`, ``.nczones/results.sqlite``).  ``fleet check``
(:func:`run_check`) verifies only the jobs the store does not have, in this
process or on a Dask cluster (:mod:`nczones.fleet.execute`); a long program
may be split into chunks verified on several workers where that is sound
(:mod:`nczones.fleet.split`).  ``fleet status`` and ``fleet diff``
(:mod:`nczones.fleet.status`) read the store.  The format and the store's
schema: ``specs/fleet.md``.

Public API
----------
:func:`load_project`, :class:`Project`, :func:`run_check`,
:class:`CheckOptions`, :class:`Store`, :func:`code_version`.

>>> from nczones.fleet import load_project
>>> project = load_project("specs/examples/library")
>>> len(project.machines), len({c.program for c in project.cells()}) >= 30
(14, True)
"""

from __future__ import annotations

from .check import CheckOptions, CheckSummary, run_check
from .jobs import code_version
from .project import Project, load_project
from .store import Store

__all__ = ["load_project", "Project", "run_check", "CheckOptions", "CheckSummary", "Store", "code_version"]
