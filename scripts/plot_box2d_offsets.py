#!/usr/bin/env python3
"""Draws docs/img/box2d-offsets.png: disagreement rate against world offset.

Usage: scripts/plot_box2d_offsets.py [path/to/cardemo] [--pairs N] [--seed S] [--out FILE]
                                    [--sweep-csv FILE]   (a saved `compare-sweep --all-exact --csv`)

Runs `cardemo compare-sweep --all-exact --csv` (the GMP oracle on every pair), sums every gap
bin (pairs within 1 m of touching) per offset, and plots the percentage of pairs on which each
verdict disagrees with the oracle outside the contract's |sep| <= 1e-6 m band. Verdicts that
differ inside the band (borderline) are allowed and not plotted; the script prints both.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from pyplot_loader import import_pyplot  # noqa: E402
ROOT = os.path.dirname(HERE)
LINES = [
    ("ours", "cardemo", "o-"),
    ("box2d", "Box2D b2CollidePolygons, skin 0", "s-"),
    ("box2d_overlap", "Box2D b2TestOverlap, skin 0", "^--"),
    ("box2d_skin", "Box2D b2CollidePolygons, default 0.01 m skin", "d-"),
]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("binary", nargs="?", default=os.path.join(ROOT, "build", "cardemo"),
                    help="the cardemo executable")
    ap.add_argument("--pairs", default="1000000", help="compare-sweep pairs")
    ap.add_argument("--seed", default="1", help="compare-sweep seed")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "img", "box2d-offsets.png"))
    ap.add_argument("--sweep-csv", help="a saved `compare-sweep --all-exact --csv` to plot")
    args = ap.parse_args(argv)
    binary, pairs, seed, out, given_csv = args.binary, args.pairs, args.seed, args.out, args.sweep_csv
    plt = import_pyplot(__file__, argv)

    with tempfile.TemporaryDirectory() as tmp:
        csv_path = given_csv or os.path.join(tmp, "sweep.csv")
        # Exit 1 would mean cardemo disagreed; the plot still shows it, so only 2 is fatal.
        if not given_csv:
            r = subprocess.run([binary, "compare-sweep", "--all-exact", "--pairs", pairs, "--seed",
                                seed, "--csv", csv_path], stdout=subprocess.DEVNULL)
            if r.returncode not in (0, 1):
                sys.exit(f"compare-sweep failed with exit {r.returncode}")
        with open(csv_path, newline="") as f:
            rows = list(csv.DictReader(f))

    offsets = sorted({float(r["offset_m"]) for r in rows})
    fig, ax = plt.subplots(figsize=(7, 4.2), dpi=120)
    for key, label, style in LINES:
        rates, borderline = [], []
        for o in offsets:
            cells = [r for r in rows if r["verdict"] == key and float(r["offset_m"]) == o]
            n = sum(int(r["pairs"]) for r in cells)
            wrong = sum(int(r["disagree"]) for r in cells)
            rates.append(100.0 * wrong / n if n else 0.0)
            borderline.append(100.0 * sum(int(r["borderline"]) for r in cells) / n if n else 0.0)
        print(f"{key}: disagree " + " / ".join(f"{x:.2f}" for x in rates) + " %, borderline " +
              " / ".join(f"{x:.2f}" for x in borderline) + " % at offsets " +
              " / ".join(f"{o:g}" for o in offsets) + " m")
        ax.plot(range(len(offsets)), rates, style, label=label)
    ax.set_xticks(range(len(offsets)))
    ax.set_xticklabels(["0" if o == 0 else f"1e{len(str(int(o))) - 1}" for o in offsets])
    ax.set_xlabel("distance of the pair from the world origin, m")
    ax.set_ylabel("pairs that disagree with the exact oracle, %\n(|sep| > 1e-6 m; borderline not counted)")
    ax.set_title(f"Box pairs within 1 m of touching ({int(pairs):,} pairs, seed {seed})")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(out), exist_ok=True)
    fig.savefig(out)
    print(out)


if __name__ == "__main__":
    main(sys.argv[1:])
