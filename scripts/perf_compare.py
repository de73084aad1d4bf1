#!/usr/bin/env python3
"""Prints, as markdown, a few benchmark rows side by side across saved runs of the suite.

Each FILE is the Google Benchmark JSON of one run (scripts/perf_report.py keeps the last one as
BUILD/bench.json; copy it aside to keep it). For each run the script prints its command and commit
(when scripts/perf_report.py recorded them), the machine (MHz as reported, widest batch path), its
repetitions and load average, and the fastest repetition of a few sentinel rows. Rows whose code did
not change between two runs show how much a run on a shared machine moves by itself.

Usage: scripts/perf_compare.py FILE [FILE ...] [--rows ROW ...]
       (ROW: a benchmark name without /iterations:..., e.g. narrow/collidePolygons/1k/box2d)
"""
import argparse
import json
import sys

SENTINELS = [
    "narrow/collidePolygons/1k/box2d",
    "narrow/collidePolygons/1k/cardemo",
    "narrow/overlapObb3/1k/cardemo",
    "broad/query/lot/1M/cardemo",
    "step/lot/1k/cardemo",
    "step/lot/1M/cardemo",
    "replay/demo/cardemo",
]


def fastest(data):
    """Per benchmark name (without /iterations:N), the fastest repetition in ns per item."""
    out = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration" or b.get("error_occurred"):
            continue
        name = b["run_name"].split("/iterations:")[0]
        ns = 1e9 / b["items_per_second"] if b.get("items_per_second") else b["cpu_time"]
        out[name] = min(ns, out.get(name, ns))
    return out


def repetitions(data):
    counts = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "iteration":
            counts[b["run_name"]] = counts.get(b["run_name"], 0) + 1
    return max(counts.values()) if counts else 0


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("files", nargs="+", help="saved runs (Google Benchmark JSON)")
    ap.add_argument("--rows", nargs="+", default=SENTINELS, help="benchmark names")
    args = ap.parse_args(argv)
    print("Fastest repetition of each row, ns per item (pair, query, step or frame).\n")
    header = ["run", "commit", "machine", "reps", "load avg"] + [f"`{r}`" for r in args.rows]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for path in args.files:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        ctx = data.get("context", {})
        load = ctx.get("load_avg") or []
        times = fastest(data)
        machine = f"{ctx.get('mhz_per_cpu', '?')} MHz, {ctx.get('batch_path', '?')}"
        cells = [path, ctx.get("git_commit", "?"), machine, str(repetitions(data)),
                 f"{load[0]:.2f}" if load else "?"]
        cells += [f"{times[r]:,.1f}" if r in times else "-" for r in args.rows]
        print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
