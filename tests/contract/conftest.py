"""Hypothesis profiles for the differential suite, and its statistics.

``ci`` (the default) is derandomized and sized so that all of tests/contract
runs in a few minutes on 2 cores; ``HYPOTHESIS_PROFILE=long`` runs at least
20,000 examples per property, randomized.  Set ``NCZONES_CONTRACT_STATS`` to
a file name to get the outcome counts as JSON at the end of the session.
"""

import json
import os
import sys
from pathlib import Path

from hypothesis import HealthCheck, settings

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tests/: the shared `oracles` package

settings.register_profile(
    "ci",
    derandomize=True,
    deadline=None,
    max_examples=60,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.data_too_large],
)
settings.register_profile(
    "long",
    derandomize=False,
    deadline=None,
    max_examples=20_000,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.data_too_large],
)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_terminal_summary(terminalreporter):
    from .contract import STATS

    if not STATS:
        return
    terminalreporter.write_sep("-", "prover <-> controller contract: outcome counts")
    for label, n in sorted(STATS.items()):
        terminalreporter.write_line(f"{n:8d}  {label}")
    out = os.environ.get("NCZONES_CONTRACT_STATS")
    if out:
        Path(out).write_text(json.dumps(dict(STATS), indent=2, sort_keys=True) + "\n")
