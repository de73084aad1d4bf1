#!/usr/bin/env python3
"""Draws docs/img/cost-vs-error.png: cost per pair against misclassification rate, cardemo and
Box2D on one plot, one point per world offset (0, 1e3, 1e5, 1e7 m).

Usage: scripts/plot_cost_error.py [BUILD] [--pairs N] [--seed S] [--repetitions R] [--out FILE]
                                  [--sweep-csv FILE]   (a saved `compare-sweep --all-exact --csv`)

Runs, from BUILD (default build/):
  bench/cardemo_bench --benchmark_filter='^offset/' --benchmark_repetitions=R (cost: CPU ns per
      pair, the fastest repetition; 1k random car pairs, 45 % overlapping, moved to the offset);
  cardemo compare-sweep --all-exact --pairs N --seed S --csv FILE (error: pairs whose verdict
      differs from the GMP oracle outside the contract's |sep| <= 1e-6 m band, over all pairs at
      the offset; pairs drawn in equal numbers per |gap| bin 1e-9..1e-6..1e-4..1e-2..0.1..1 m).
Prints the numbers it plots, as a markdown table.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from pyplot_loader import import_pyplot  # noqa: E402
ROOT = os.path.dirname(HERE)
# (bench query, bench engine, compare-sweep verdict, label, style). Like for like: the booleans
# together, the manifolds together. cardemo's three queries share the sweep's `ours` verdict:
# overlapObb2's verdict is collideObb2's (SatObb2Random.*), and manifoldObb2's is the exact one
# outside the 1e-6 m band at every sweep offset (Manifold2Random.VerdictIsExactNearTouchingFarOut).
ENGINES = [
    ("overlapObb2", "cardemo", "ours", "cardemo overlapObb2 (boolean)", "o-"),
    ("overlapObb2", "box2d", "box2d_overlap", "Box2D b2TestOverlap (boolean), skin 0", "^--"),
    ("manifoldObb2", "cardemo", "ours", "cardemo manifoldObb2 (manifold)", "D-"),
    ("manifoldObb2", "box2d", "box2d", "Box2D b2CollidePolygons (manifold), skin 0", "s--"),
    ("collideObb2", "cardemo", "ours", "cardemo collideObb2 (depth and normal; no Box2D twin)", "x:"),
]
OFFSETS = ["0", "1000", "100000", "1e+07"]


def offset_label(offset):
    """'0', '1e3', '1e5', '1e7' for the offsets' strings."""
    return "0" if offset == "0" else f"{float(offset):.0e}".replace("+0", "")


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"), help="build folder")
    ap.add_argument("--pairs", default="1000000", help="compare-sweep pairs")
    ap.add_argument("--seed", default="1", help="compare-sweep seed")
    ap.add_argument("--repetitions", default="5", help="benchmark repetitions (the fastest counts)")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "img", "cost-vs-error.png"))
    ap.add_argument("--sweep-csv", help="a saved `compare-sweep --all-exact --csv` to plot")
    args = ap.parse_args(argv)
    build, pairs, seed, reps = args.build, args.pairs, args.seed, args.repetitions
    out, given_csv = args.out, args.sweep_csv
    plt = import_pyplot(__file__, argv)

    with tempfile.TemporaryDirectory() as tmp:
        bench_json = os.path.join(tmp, "offset.json")
        subprocess.run([os.path.join(build, "bench", "cardemo_bench"), "--benchmark_filter=^offset/",
                        f"--benchmark_repetitions={reps}", "--benchmark_min_time=0.2",
                        f"--benchmark_out={bench_json}", "--benchmark_out_format=json"],
                       check=True, stdout=subprocess.DEVNULL)
        with open(bench_json) as f:
            data = json.load(f)
        sweep_csv = given_csv or os.path.join(tmp, "sweep.csv")
        if not given_csv:
            r = subprocess.run([os.path.join(build, "cardemo"), "compare-sweep", "--all-exact",
                                "--pairs", pairs, "--seed", seed, "--csv", sweep_csv],
                               stdout=subprocess.DEVNULL)
            if r.returncode not in (0, 1):
                sys.exit(f"compare-sweep failed with exit {r.returncode}")
        with open(sweep_csv, newline="") as f:
            rows = list(csv.DictReader(f))

    cost = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" or b.get("error_occurred"):
            continue
        _, query, offset, engine = b["run_name"].split("/")[:4]
        ns = 1e9 / b["items_per_second"]
        key = (query, engine, offset)
        cost[key] = min(ns, cost.get(key, ns))
    error = {}
    for verdict in {e[2] for e in ENGINES}:
        for offset in OFFSETS:
            cells = [x for x in rows if x["verdict"] == verdict and float(x["offset_m"]) == float(offset)]
            n = sum(int(x["pairs"]) for x in cells)
            error[(verdict, offset)] = 100.0 * sum(int(x["disagree"]) for x in cells) / n

    print("| engine | " + " | ".join(f"{o} m: ns, misclassified" for o in OFFSETS) + " |")
    print("|---|" + "---|" * len(OFFSETS))
    fig, ax = plt.subplots(figsize=(7.5, 4.5), dpi=120)
    for query, engine, verdict, label, style in ENGINES:
        xs = [error[(verdict, o)] for o in OFFSETS]
        ys = [cost[(query, engine, o)] for o in OFFSETS]
        print(f"| {label} | " + " | ".join(f"{y:.1f} ns, {x:.2f} %" for x, y in zip(xs, ys)) + " |")
        # Offsets with the same error share one label, placed at the group's highest point; a
        # series whose offsets all share one error (cardemo's, all at 0 %) says so in the legend
        # instead, since labels of several such series would print over each other.
        groups = {}
        for x, y, o in zip(xs, ys, OFFSETS):
            groups.setdefault(x, []).append((y, offset_label(o)))
        if len(groups) == 1:
            label += ", at " + ", ".join(offset_label(o) for o in OFFSETS) + " m"
        ax.plot(xs, ys, style, label=label)
        if len(groups) == 1:
            continue
        for x, points in groups.items():
            text = ", ".join(label for _, label in points) + " m"
            ax.annotate(text, (x, max(y for y, _ in points)), textcoords="offset points",
                        xytext=(4, 4), fontsize=7)
    ax.set_xscale("symlog", linthresh=0.1)
    ax.set_xlim(left=-0.02)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("misclassified pairs, % (verdict differs from the GMP oracle, |sep| > 1e-6 m)")
    ax.set_ylabel("CPU ns per pair (fastest of the repetitions)")
    ax.set_title(f"Cost against error at 0 to 1e7 m from the origin ({int(pairs):,} sweep pairs)",
                 fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(out), exist_ok=True)
    fig.savefig(out)
    print(out)


if __name__ == "__main__":
    main(sys.argv[1:])
