"""The long profile of the grammar-driven differential against ``rs274 -g``, in chunks that are kept.

    nice -n 10 python -m tests.tools.rs274_long run --out runs/rs274 --start 100000 --count 50000 --chunk 500
    python -m tests.tools.rs274_long summary --out runs/rs274

Each chunk of ``--chunk`` seeds is written to ``OUT/chunk-<first seed>.json`` when it ends (counts, CPU time,
the commit, every mismatch with its seed and class); a chunk already there is skipped, so a stopped run
goes on where it stopped. A mismatch is run a second time before it is kept (a transient failure of the
host, e.g. rs274 not finding its tool table while packages are reinstalled, is counted as ``flaky``).
``summary`` adds the chunks up and groups the mismatches by class (``classify``).
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from tests.oracles.rs274 import compare
from tests.tools.rs274_diff import generate, machine_of, run_rs274

#: (class, why) by a pattern of the outcome's detail or of the program: the first that matches names it
CLASSES: tuple[tuple[str, str, str], ...] = (
    ("detail", r"GC32\d", "finding-comp-concave: nczones refuses a concave corner LinuxCNC 2.9 runs (comp)"),
    ("both", r"(?s)(zero feed rate|[Ss]pindle|feed per rev).*\x00.*M7[023]",
     "lcnc-modal-restore: feed (G93 -> G94) or spindle after an M72/M73 restore (class 11)"),
    ("text", r"(?s)o\d+ (break|continue)\n.*o\d+ (do|repeat)", "finding-loop-after-jump: after a break/continue "
                                                               "LinuxCNC 2.9 runs a later do/repeat loop a "
                                                               "different number of times"),
    ("detail", r"F word missing with inverse time", "finding-g93-spline-f: G5/G5.1 in G93 without F (LinuxCNC "
                                                 "refuses, nczones runs)"),
    ("text", r"(?s)G10 L2 P\d[^\n]* R-?\d.*G(28|30) [XYZA]", "finding-rot-g28: G28/G30 with axis words in a "
                                                          "rotated system (G10 L2 R)"),
    ("text", r"(?s)M61 Q\d.*(#5400|_current_tool|\nG4[12]\n)", "oracle-m61-tool: the standalone rs274 keeps "
                                                              "tool 0 after M61 (its #5400, G41's diameter)"),
    ("text", r"M7[23]", "lcnc-modal-restore: after an M72/M73 restore (class 11)"),
    ("text", r"_value", "lcnc-value: #<_value> (class 13)"),
    ("detail", r"rs274 timed out", "rs274-timeout"),
)


def classify(status: str, detail: str, text: str) -> str:
    for where, pattern, name in CLASSES:
        subject = {"detail": detail, "text": text, "both": detail + "\x00" + text}[where]
        if re.search(pattern, subject):
            return name.split(":")[0].split(" (")[0]
    return "unclassified"


def one(seed: int, work: Path) -> tuple[str, str, bool, bool]:
    """(status, detail, rs274 accepted, nczones unknown) of one seed."""
    text, setup = generate(seed)
    moves, error, _ = run_rs274(text, setup, work)
    try:
        o = compare(text, machine_of(setup), moves, error)
    except Exception as exc:  # noqa: BLE001 - an internal error of nczones is a finding too
        return "crash", f"{type(exc).__name__}: {exc}", error is None, False
    return o.status, o.detail, error is None, o.status == "unknown"


def run_chunk(first: int, count: int, work: Path) -> dict:
    t0 = time.process_time()
    c0 = _children_cpu()
    counts: Counter = Counter()
    accepted = unknown = flaky = 0
    mismatches = []
    for seed in range(first, first + count):
        status, detail, ok, unk = one(seed, work)
        if status not in ("match", "unknown"):
            again = one(seed, work)
            if again[0] in ("match", "unknown"):
                flaky += 1
                status, detail, ok, unk = again
        counts[status] += 1
        accepted += ok
        unknown += unk
        if status not in ("match", "unknown"):
            text, _ = generate(seed)
            mismatches.append({"seed": seed, "status": status, "detail": detail[:300],
                               "class": classify(status, detail, text)})
    return {"first": first, "count": count, "outcomes": dict(counts), "rs274_accepted": accepted,
            "nczones_unknown": unknown, "flaky": flaky, "mismatches": mismatches,
            "cpu_s": round(time.process_time() - t0 + _children_cpu() - c0, 1), "commit": COMMIT}


def _children_cpu() -> float:
    import resource

    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _commit() -> str:
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              cwd=Path(__file__).parent).stdout.strip()
    except OSError:
        return "?"


COMMIT = _commit()  # the code this process loaded


def cmd_run(args) -> int:
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        for first in range(args.start, args.start + args.count, args.chunk):
            path = out / f"chunk-{first}.json"
            if path.exists():
                continue
            res = run_chunk(first, min(args.chunk, args.start + args.count - first), Path(tmp))
            path.write_text(json.dumps(res, indent=1) + "\n")
            print(f"chunk {first}: {res['outcomes']} cpu {res['cpu_s']} s", flush=True)
    return 0


def summary(out: Path, recheck: bool = False) -> dict:
    """Totals of the chunks; with ``recheck`` every kept mismatch is run again with the code of now (the
    generator must be the run's: its programs are regenerated from the seed) and counted where it lands."""
    total: Counter = Counter()
    classes: Counter = Counter()
    examples: dict[str, list[int]] = {}
    n = accepted = unknown = flaky = 0
    cpu = 0.0
    commits = set()
    for path in sorted(out.glob("chunk-*.json")):
        res = json.loads(path.read_text())
        n += res["count"]
        accepted += res["rs274_accepted"]
        unknown += res["nczones_unknown"]
        flaky += res["flaky"]
        cpu += res["cpu_s"]
        commits.add(res["commit"])
        total.update(res["outcomes"])
        for m in res["mismatches"]:
            if recheck:
                with tempfile.TemporaryDirectory() as tmp:
                    status, detail, _ok, _unk = one(m["seed"], Path(tmp))
                if status in ("match", "unknown"):
                    total[m["status"]] -= 1
                    total[status] += 1
                    classes["fixed in the oracle since (re-run: " + status + ")"] += 1
                    continue
                m["status"], m["detail"] = status, detail
            m["class"] = classify(m["status"], m["detail"], generate(m["seed"])[0])  # the classes of now
            classes[m["class"]] += 1
            examples.setdefault(m["class"], []).append(m["seed"])
    return {"programs": n, "rs274_accepted": accepted, "nczones_unknown": unknown, "flaky": flaky,
            "outcomes": dict(total), "classes": dict(classes),
            "examples": {k: v[:10] for k, v in examples.items()}, "cpu_s": round(cpu), "commits": sorted(commits)}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    run = sub.add_parser("run")
    run.add_argument("--out", required=True)
    run.add_argument("--start", type=int, default=100000)
    run.add_argument("--count", type=int, default=50000)
    run.add_argument("--chunk", type=int, default=500)
    s = sub.add_parser("summary")
    s.add_argument("--out", required=True)
    s.add_argument("--recheck", action="store_true")
    args = ap.parse_args(argv)
    if args.cmd == "run":
        return cmd_run(args)
    print(json.dumps(summary(Path(args.out), args.recheck), indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
