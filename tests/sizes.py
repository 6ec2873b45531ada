"""Example counts of the default run and of the long run, for tests outside tests/contract (whose conftest has
the Hypothesis profiles).

The default run keeps each draw small (the project's rule: the whole run well under 15 minutes on 2 cores);
``HYPOTHESIS_PROFILE=long`` (with ``-m long`` or without) gives each test its long count, at least the count it
had before the default run was trimmed (specs/performance.md, "The default test run").
"""

from __future__ import annotations

import os

#: the long run: ``HYPOTHESIS_PROFILE=long``
LONG = os.environ.get("HYPOTHESIS_PROFILE") == "long"


def examples(ci: int, long: int) -> int:
    """``long`` in the long run, else ``ci``.

    >>> examples(10, 400) == (400 if LONG else 10)
    True
    """
    return long if LONG else ci
