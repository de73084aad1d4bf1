#!/usr/bin/env python3
"""Reproduces the tables of docs/box2d-comparison.md.

Usage: scripts/box2d_tables.py [path/to/cardemo] [--pairs N] [--seed S]

Runs `cardemo compare --all-exact --json -` on every bundled replay (the 10,100-car lot in full)
and `cardemo compare-sweep --all-exact`, and prints markdown. --all-exact: the GMP oracle judges
every pair (no shortcut from cardemo's own separation). --skip NAME leaves a replay out;
--radius NAME=R checks that replay's colliders within R m of the player only (`compare --radius`);
--csv FILE also keeps the sweep's CSV (for scripts/plot_box2d_offsets.py and
scripts/plot_cost_error.py --sweep-csv FILE, which then need not run the sweep again).
"""
import argparse
import glob
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
VERDICTS = ["ours", "box2d", "box2d_overlap", "box2d_skin", "box2d_skin_overlap"]


def hits_of(obj):
    return {(h["frame"], h["id"]) for h in obj}


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("binary", nargs="?", default=os.path.join(ROOT, "build", "cardemo"),
                    help="the cardemo executable")
    ap.add_argument("--pairs", default="1000000", help="compare-sweep pairs")
    ap.add_argument("--seed", default="1", help="compare-sweep seed")
    ap.add_argument("--skip", action="append", default=[], help="a bundled replay to leave out")
    ap.add_argument("--csv", help="where compare-sweep writes its per-pair CSV")
    ap.add_argument("--radius", action="append", default=[], metavar="REPLAY=R",
                    help="compare's --radius for one replay")
    args = ap.parse_args(argv)
    binary, pairs, seed, sweep_csv = args.binary, args.pairs, args.seed, args.csv
    skip = set(args.skip)
    radius = dict(r.split("=", 1) for r in args.radius)
    print("## Bundled replays (`cardemo compare REPLAY --all-exact --json -`)\n")
    print("Cells: disagree / borderline against the exact oracle; hits: first contacts implied "
          "(differing from the oracle's).\n")
    print("| replay | pairs | " + " | ".join(VERDICTS) + " | exact hits |")
    print("|---|---|" + "---|" * len(VERDICTS) + "---|")
    for replay in sorted(glob.glob(os.path.join(ROOT, "assets", "replays", "*.replay"))):
        if os.path.basename(replay) in skip:
            continue
        extra = ["--radius", radius[name]] if (name := os.path.basename(replay)) in radius else []
        run = subprocess.run([binary, "compare", replay, "--all-exact", "--json", "-"] + extra,
                             capture_output=True,
                             text=True, check=False)
        if run.returncode not in (0, 1):
            sys.exit(f"{replay}: cardemo compare exited {run.returncode}: {run.stderr}")
        j = json.loads(run.stdout)
        exact = hits_of(j["exact_hits"])
        cells = []
        for v in VERDICTS:
            o = j[v]
            mine = hits_of(o["hits"])
            cells.append(f'{o["disagree"]} / {o["borderline"]}; hits {len(mine)} '
                         f'({len(mine ^ exact)})')
        if name in radius:
            name += f" (`--radius {radius[name]}`)"
        print(f'| {name} | {j["pairs_checked"]} | ' + " | ".join(cells) + f" | {len(exact)} |")
    print(f"\n## Random box pairs (`cardemo compare-sweep --all-exact --pairs {pairs} "
          f"--seed {seed}`)\n")
    run = subprocess.run([binary, "compare-sweep", "--all-exact", "--pairs", pairs, "--seed", seed]
                         + (["--csv", sweep_csv] if sweep_csv else []),
                         capture_output=True, text=True, check=False)
    if run.returncode not in (0, 1):
        sys.exit(f"cardemo compare-sweep exited {run.returncode}: {run.stderr}")
    print(run.stdout)


if __name__ == "__main__":
    main(sys.argv[1:])
