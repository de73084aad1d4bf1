#!/usr/bin/env python3
"""Writes the large-lot scene: >= 10,000 parked cars in double rows with aisles between them.

Deterministic (a fixed linear congruential generator), so the committed file can be checked:
    scripts/make_large_lot.py assets/scenes/large-lot.json          # write
    scripts/make_large_lot.py --check assets/scenes/large-lot.json  # exit 1 if it differs
    scripts/make_large_lot.py --blocks 496 /tmp/lot100k.json        # 100,025 cars, 10.5 MB
"""
import argparse
import json
import sys

BLOCKS = 50          # double rows; each block is two back-to-back rows and one aisle
CARS_PER_ROW = 104
PITCH = 2.6          # metres between bay centres
CAR_LENGTH = 4.5
AISLE = 7.0          # aisle width, metres
BLOCK_HEIGHT = 2 * (CAR_LENGTH + 0.1) + AISLE


class Lcg:
    """Numerical Recipes' 32-bit LCG: portable and reproducible across Python versions."""

    def __init__(self, seed):
        self.state = seed & 0xFFFFFFFF

    def uniform(self):
        self.state = (1664525 * self.state + 1013904223) & 0xFFFFFFFF
        return self.state / 2**32


def scene_text(blocks=BLOCKS):
    rng = Lcg(20261122)
    parked = []
    for block in range(blocks):
        aisle_y = block * BLOCK_HEIGHT
        for side, heading in ((1, 90), (-1, 270)):
            row_y = aisle_y + side * (AISLE / 2 + CAR_LENGTH / 2 + 0.05)
            for k in range(CARS_PER_ROW):
                empty = rng.uniform() < 0.03
                jitter_heading = (rng.uniform() - 0.5) * 6.0
                jitter_x = (rng.uniform() - 0.5) * 0.3
                length = 4.2 + 0.6 * rng.uniform()
                width = 1.7 + 0.2 * rng.uniform()
                if empty:
                    continue
                row_name = f"{block:02d}{'N' if side > 0 else 'S'}"
                parked.append({
                    "id": f"{row_name}-{k + 1:03d}",
                    "x": round(k * PITCH + jitter_x, 3),
                    "y": round(row_y, 3),
                    "heading_deg": round(heading + jitter_heading, 2),
                    "length": round(length, 3),
                    "width": round(width, 3),
                })
    width = CARS_PER_ROW * PITCH
    height = blocks * BLOCK_HEIGHT
    header = {
        "format": "cardemo-scene/1",
        "name": "large-lot",
        "bounds": {"min": [-40.0, -BLOCK_HEIGHT], "max": [round(width + 40.0, 3), round(height, 3)]},
        "player": {"x": -20.0, "y": round(25 * BLOCK_HEIGHT, 3), "heading_deg": 0, "length": 4.5,
                   "width": 1.8, "health": 100},
    }
    lines = ["{"]
    for key, value in header.items():
        lines.append(f'  "{key}": {json.dumps(value, separators=(", ", ": "))},')
    lines.append('  "parked": [')
    for i, car in enumerate(parked):
        lines.append("    " + json.dumps(car, separators=(", ", ": ")) + ("," if i + 1 < len(parked) else ""))
    lines.append("  ]")
    lines.append("}")
    return "\n".join(lines) + "\n", len(parked)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true", help="compare with OUT instead of writing it")
    parser.add_argument("--blocks", type=int, default=BLOCKS,
                        help=f"double rows of {2 * CARS_PER_ROW} bays (default {BLOCKS}, the bundled lot)")
    parser.add_argument("out")
    args = parser.parse_args()
    text, count = scene_text(args.blocks)
    if args.check:
        with open(args.out, encoding="utf-8") as f:
            same = f.read() == text
        print(f"{args.out}: {'matches' if same else 'DIFFERS from'} the generator ({count} cars)")
        return 0 if same else 1
    with open(args.out, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {args.out}: {count} parked cars")
    return 0


if __name__ == "__main__":
    sys.exit(main())
