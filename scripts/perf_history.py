#!/usr/bin/env python3
"""Prints, as markdown, how a few benchmark rows moved across the committed runs of the suite.

Every version of docs/perf/bench.json that git holds is one run of scripts/perf_report.py. For the
newest N of them (default 6) the script prints the run's start (from the benchmark's own context),
the commit that saved it, the machine (its MHz as reported and its widest batch path: the sessions
do not all run on the same CPU), its repetitions and load average, and the fastest repetition of a few
sentinel rows. Rows that did not change between two runs show how much a run on a shared machine
moves by itself.

Usage: scripts/perf_history.py [--runs N] [ROW ...]     (ROW: a benchmark name without
       /iterations:..., e.g. narrow/collidePolygons/1k/box2d)
"""
import argparse
import json
import subprocess
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
PATH = "docs/perf/bench.json"


def git(*args):
    return subprocess.run(["git", *args], capture_output=True, text=True, check=True).stdout


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
    ap.add_argument("--runs", type=int, default=6, help="how many of the newest runs")
    ap.add_argument("rows", nargs="*", default=SENTINELS, help="benchmark names")
    args = ap.parse_args(argv)
    commits = git("log", f"-{args.runs}", "--format=%h", "--", PATH).split()
    runs = []
    for commit in commits:
        data = json.loads(git("show", f"{commit}:{PATH}"))
        runs.append((commit, data))
    print("Fastest repetition of each row, ns per item (pair, query, step or frame).\n")
    header = ["run (start)", "saved in", "machine", "reps", "load avg"] + [f"`{r}`" for r in args.rows]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for commit, data in runs:
        ctx = data["context"]
        load = ctx.get("load_avg") or []
        times = fastest(data)
        machine = f"{ctx.get('mhz_per_cpu', '?')} MHz, {ctx.get('batch_path', '?')}"
        cells = [ctx.get("date", "?")[:16].replace("T", " "), commit, machine, str(repetitions(data)),
                 f"{load[0]:.2f}" if load else "?"]
        cells += [f"{times[r]:,.1f}" if r in times else "-" for r in args.rows]
        print("| " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
