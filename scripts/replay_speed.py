#!/usr/bin/env python3
"""Headless speed of `cardemo replay` end to end, beside the whole-step benchmark.

For each lot size (default 1k and 100k parked cars) the script writes a scene laid out as
scripts/make_large_lot.py lays out the large lot (double rows of 2.6 m bays, 7 m aisles, jittered
headings; rows as long as the lot is tall), with a clearing in the middle where the player circles,
and a replay of FRAMES frames circling it (`4 UL` then `8 L`, repeated: about 10.6 m/s on a circle
of about 12.7 m radius, moving and turning every frame, no hit). These files are generated, never committed.

Each replay runs as a user runs it, the whole process (`cardemo replay FILE`), RUNS times; the
cost is the process's CPU time (user + system, from wait4: the machine is shared, and CPU time is
less disturbed by other processes than wall time), the minimum of the runs. The load (process
start, reading and parsing the scene, building the world) is the minimum over RUNS runs of a
1-frame replay of the same scene, and is subtracted. The step benchmark of the same lot size runs
once in each of the RUNS rounds too (1-frame replay, full replay, benchmark, interleaved so that
all three see the same load), minimum CPU time taken: `step/circling/N/cardemo` in cardemo_bench
is World::step alone on this very scene and circling input (bench/suite/circle_drive.cpp builds
them with this script's arithmetic), and the ratio end-to-end / step is printed against it. The
lot-drive row `step/lot/N/cardemo` (a different, cheaper drive) is printed beside it for reference.

    scripts/replay_speed.py --cardemo build/cardemo --bench build/bench/cardemo_bench
    scripts/replay_speed.py --frames 200000 --runs 3 --cars 1000        # quicker
    scripts/replay_speed.py --bench ''                                   # replay only
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_large_lot import Lcg  # noqa: E402  (the same generator as the bundled large lot)
from pathlib import Path

PITCH = 2.6  # metres between bay centres (scripts/make_large_lot.py)
CAR_LENGTH = 4.5
AISLE = 7.0
BLOCK_HEIGHT = 2 * (CAR_LENGTH + 0.1) + AISLE
CLEARING = 20.0  # radius of the empty circle in the middle of the lot, metres
CIRCLE = ("4 UL", "8 L")  # throttle a third of the time, steering left throughout


def lot_scene(cars):
    """Scene JSON with exactly `cars` parked cars around a clearing; the player circles in it."""
    rng = Lcg(20261125)
    # Square lot: bays per row * PITCH about equal to blocks * BLOCK_HEIGHT, plus the clearing.
    area = cars / 2 * PITCH * BLOCK_HEIGHT + math.pi * CLEARING**2
    side = math.sqrt(area)
    per_row = max(1, math.ceil(side / PITCH))
    centre = (per_row * PITCH / 2, side / 2)
    parked = []
    block = 0
    while len(parked) < cars:
        aisle_y = block * BLOCK_HEIGHT
        for side_sign, heading in ((1, 90), (-1, 270)):
            row_y = aisle_y + side_sign * (AISLE / 2 + CAR_LENGTH / 2 + 0.05)
            for k in range(per_row):
                jitter_heading = (rng.uniform() - 0.5) * 6.0
                jitter_x = (rng.uniform() - 0.5) * 0.3
                x = k * PITCH + jitter_x
                if len(parked) == cars or math.hypot(x - centre[0], row_y - centre[1]) < CLEARING:
                    continue
                parked.append({"id": f"{block:03d}{'N' if side_sign > 0 else 'S'}-{k + 1:04d}",
                               "x": round(x, 3), "y": round(row_y, 3),
                               "heading_deg": round(heading + jitter_heading, 2),
                               "length": 4.5, "width": 1.8})
        block += 1
    ys = [p["y"] for p in parked]
    scene = {
        "format": "cardemo-scene/1",
        "name": f"replay-speed-{cars}",
        "bounds": {"min": [-20.0, round(min(ys) - 20.0, 3)],
                   "max": [round(per_row * PITCH + 20.0, 3), round(max(ys) + 20.0, 3)]},
        # Heading east, turning left: the circle's centre is about 4 m north of the start.
        "player": {"x": round(centre[0], 3), "y": round(centre[1] - 4.0, 3), "heading_deg": 0,
                   "length": 4.5, "width": 1.8, "health": 100},
        "parked": parked,
    }
    return json.dumps(scene, separators=(",", ":")) + "\n"


def circling_replay(scene_path, frames):
    lines = ["cardemo-replay 1", f"scene {scene_path}", "hz 120"]
    pattern = [(int(c.split()[0]), c) for c in CIRCLE]
    period = sum(n for n, _ in pattern)
    lines += [c for _, c in pattern] * (frames // period)
    left = frames % period
    for n, c in pattern:
        if left > 0:
            lines.append(f"{min(n, left)} {c.split()[1]}")
            left -= min(n, left)
    return "\n".join(lines) + "\n"


def cpu(cmd):
    """CPU time (user + system, seconds) of one run of `cmd`, and its stdout."""
    # The child is reaped inside run(), so its usage is the increase of RUSAGE_CHILDREN.
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    proc = subprocess.run(cmd, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        sys.exit(f"{' '.join(cmd)} exited {proc.returncode}:\n{proc.stderr}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), proc.stdout


def step_ns(bench, cars):
    """CPU time per step (ns) of one run of the circling and lot-drive step rows for `cars` cars."""
    label = f"{cars // 1000}k" if cars % 1000 == 0 and cars < 1000000 else str(cars)
    if cars % 1000000 == 0:
        label = f"{cars // 1000000}M"
    names = {group: f"step/{group}/{label}/cardemo" for group in ("circling", "lot")}
    cmd = [bench, f"--benchmark_filter=^step/(circling|lot)/{label}/cardemo/",
           "--benchmark_format=json"]
    result = subprocess.run(cmd, check=True, capture_output=True, text=True)
    rows = [b for b in json.loads(result.stdout)["benchmarks"] if b.get("run_type") == "iteration"]
    out = {}
    for group, name in names.items():
        times = [b["cpu_time"] for b in rows if b["name"].startswith(name + "/")]
        if not times:
            sys.exit(f"{' '.join(cmd)}: no {name} rows")
        out[group] = min(times)
    return out, names


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cardemo", default="build/cardemo", help="cardemo binary")
    parser.add_argument("--bench", default="build/bench/cardemo_bench",
                        help="cardemo_bench binary ('' to skip the step benchmark)")
    parser.add_argument("--cars", default="1000,100000", help="lot sizes, comma separated")
    parser.add_argument("--frames", type=int, default=2_000_000, help="frames per replay")
    parser.add_argument("--runs", type=int, default=5, help="runs per measurement (minimum taken)")
    parser.add_argument("--dir", default=os.path.join(tempfile.gettempdir(), "cardemo-replay-speed"),
                        help="where the generated scenes and replays go")
    parser.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    args = parser.parse_args()

    work = Path(args.dir)
    work.mkdir(parents=True, exist_ok=True)
    rows = []
    for cars in (int(c) for c in args.cars.split(",")):
        scene = work / f"lot-{cars}.json"
        scene.write_text(lot_scene(cars))
        full = work / f"circle-{cars}-{args.frames}.replay"
        full.write_text(circling_replay(scene, args.frames))
        one = work / f"circle-{cars}-1.replay"
        one.write_text(circling_replay(scene, 1))
        load = total = math.inf
        summary = ""
        steps = {"circling": math.inf, "lot": math.inf}
        names = {}
        for _ in range(args.runs):
            load = min(load, cpu([args.cardemo, "replay", str(one)])[0])
            t, summary = cpu([args.cardemo, "replay", str(full)])
            total = min(total, t)
            if args.bench:
                run, names = step_ns(args.bench, cars)
                steps = {g: min(steps[g], run[g]) for g in steps}
        hits = next((line.split()[1] for line in summary.splitlines() if line.startswith("hits")), "?")
        ns = (total - load) / args.frames * 1e9
        row = {"cars": cars, "frames": args.frames, "load_s": load, "total_s": total,
               "replay_ns": ns, "hits": hits}
        if args.bench:
            row["step_ns"], row["lot_ns"] = steps["circling"], steps["lot"]
            row["bench_row"], row["lot_row"] = names["circling"], names["lot"]
        rows.append(row)
        print(f"{cars} cars: load {load:.3f} s, {args.frames} frames {total:.3f} s, "
              f"{ns:.1f} ns/frame ({1e9 / ns:,.0f} frames/s), hits {hits}"
              + (f"; {row['bench_row']} {row['step_ns']:.1f} ns/step, ratio {ns / row['step_ns']:.2f}x"
                 f"; for reference {row['lot_row']} {row['lot_ns']:.1f} ns/step"
                 if args.bench else ""), flush=True)

    if args.markdown:
        print("\n| parked cars | `cardemo replay`, end to end | frames/s | `World::step` on the same "
              "circle (`step/circling`) | steps/s | ratio | lot drive (`step/lot`), for reference |")
        print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
        for r in rows:
            step = (f"{r['step_ns']:.0f} ns | {1e9 / r['step_ns'] / 1e6:.1f} M | "
                    f"{r['replay_ns'] / r['step_ns']:.2f}x | {r['lot_ns']:.0f} ns"
                    if "step_ns" in r else " | | | ")
            print(f"| {r['cars']:,} | {r['replay_ns']:.0f} ns | {1e9 / r['replay_ns'] / 1e6:.1f} M | "
                  f"{step} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
