"""The version of the Z3 library a report names, read without loading Z3 (issue 36).

Its own module, of no import beyond the standard library's ``os`` and ``sys``: the double pass and the Fanuc box
route name the solver in their ``safe`` results without importing :mod:`nczones.prover.smt` (some 1.3 million
instructions of a 10,000-line verify, boot44), which re-exports :func:`z3_version`.
"""

from __future__ import annotations

# not typing's (start-up, issue 36): a type checker takes any TYPE_CHECKING for true
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

__all__ = ["z3_version", "find_spec", "wheel_infos"]


def z3_version() -> str:
    """The version of the Z3 library (``major.minor.build``), without loading Z3 when it is not loaded yet.

    >>> import z3
    >>> z3_version() == z3.get_version_string()
    True
    """
    import sys

    loaded = sys.modules.get("z3")
    if loaded is not None:
        return str(loaded.get_version_string())
    found = _wheel_version()
    if found is not None:  # the wheel's version is the library's, with a fourth (revision) number
        return ".".join(found.split(".")[:3])
    import z3  # a Z3 installed without its metadata (a system package)

    return str(z3.get_version_string())


def find_spec(name: str) -> Any:
    """``importlib.util.find_spec(name)`` for a top-level module not imported yet: the first spec a finder of
    ``sys.meta_path`` gives (None if none does), without importing :mod:`importlib.util` (with
    :mod:`contextlib`, some 1.5 ms of a small verify, issue 36)."""
    import sys

    for finder in sys.meta_path:
        find = getattr(finder, "find_spec", None)
        spec = find(name, None) if find is not None else None
        if spec is not None:
            return spec
    return None


def wheel_infos(names: list[str]) -> list[str]:
    """The names of ``z3-solver``'s ``.dist-info`` folders among the entries ``names`` of a folder: those whose
    lower case starts with ``z3_solver-`` and that end with ``.dist-info``.

    Only a name that starts with ``z3`` or ``Z3`` can: no other character's lower case starts with ``z`` or is
    ``3`` (``tests/prover/test_lazy_solver.py`` checks every code point), so the few such names are the only
    ones lowered (a site-packages of 200 entries: 0.35 million instructions to lower every name, boot44).

    >>> wheel_infos(["numpy", "Z3_Solver-4.12.2.0.dist-info", "z3", "z3_solver-1.pth", "zz3_solver-1.dist-info"])
    ['Z3_Solver-4.12.2.0.dist-info']
    """
    return [n for n in names if n.startswith(("z3", "Z3")) and n.lower().startswith("z3_solver-")
            and n.endswith(".dist-info")]


def _wheel_version() -> str | None:
    """The version of the ``z3-solver`` wheel that holds the ``z3`` package an import would load, from the
    ``METADATA`` of its ``.dist-info`` folder beside it; None unless there is exactly one such folder.

    Read directly: :mod:`importlib.metadata` costs about 10 ms of start-up to import.
    """
    import os

    try:
        spec = find_spec("z3")
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.submodule_search_locations:
        return None
    folder = os.path.dirname(os.path.abspath(next(iter(spec.submodule_search_locations))))
    try:
        infos = wheel_infos(os.listdir(folder))
        if len(infos) != 1:
            return None
        with open(os.path.join(folder, infos[0], "METADATA"), encoding="utf-8") as fh:
            for line in fh:
                if line.startswith("Version:"):
                    return line.split(":", 1)[1].strip() or None
                if not line.strip():  # the headers end at the first blank line
                    break
    except OSError:
        return None
    return None
