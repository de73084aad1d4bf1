#!/usr/bin/env python3
"""Builds each level's human-tempo golden replay, assets/replays/<level>.human.replay: a drive a
person could key in, where every input line holds its keys for at least 30 frames (0.25 s at
120 Hz), and the car parks without a scratch. The level's par is that replay's parked time rounded
up to whole seconds: scripts/make_levels.py reads it from these replays.

The search starts from the level's scripted manoeuvre (scripts/make_levels.py), keyed at a
person's tempo: the one-frame pedal releases last 30 frames, the quick pulses of the scripted drive
are slowed until the shorter press lasts 30 frames, and each step that runs until a condition (a
heading reached, the car stopped) is cut at the nearest QUANTUM (1/8 s) to where it first holds,
driven in the level itself. Then two hill climbs, each keeping the first change that brings the
car nearer to a clean park (cost()): over the lengths of the manoeuvre's fixed steps, planning
again after each change (tune()), and, if that is not enough, over the drive's lines themselves:
lengths, boundaries, a line left out, a tap of steering added (mend()). Every run is
`cardemo replay --json`; the first clean parking drive is kept. The search is deterministic.

Run after scripts/make_levels.py (which makes the levels), then run make_levels.py again so that the
pars follow the new replays:

  scripts/make_levels.py BUILD/cardemo && scripts/make_human_replays.py BUILD/cardemo &&
  scripts/make_levels.py BUILD/cardemo

usage: scripts/make_human_replays.py CARDEMO_BINARY [LEVEL_NUMBER...]
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import make_levels

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LEVELS = os.path.join(ROOT, "assets", "scenes", "levels")
REPLAYS = os.path.join(ROOT, "assets", "replays")
MIN_FRAMES = 30  # the shortest a person holds or releases keys: 0.25 s at 120 Hz
QUANTUM = 15     # line lengths move in steps of 1/8 s: nobody keys to the frame
TAIL = 120       # frames standing at the end, longer than the goal's hold
CARDEMO = None
TMP = None


def human_path(level_file):
    return os.path.join(REPLAYS, level_file + ".human.replay")


def write_replay(path, scene_rel, lines, comment=None):
    with open(path, "w") as f:
        if comment:
            f.write("cardemo-replay 1\n# %s\nscene %s\nhz 120\n" % (comment, scene_rel))
        else:
            f.write("cardemo-replay 1\nscene %s\nhz 120\n" % scene_rel)
        f.write("".join("%d %s\n" % (n, k) for n, k in lines))


def trace(scene, lines):
    path = os.path.join(TMP, "t.replay")
    write_replay(path, scene, lines)
    out = os.path.join(TMP, "t.csv")
    subprocess.run([CARDEMO, "replay", path, "--trace", out], capture_output=True, check=True)
    with open(out) as f:
        return list(csv.DictReader(f))


def summary(scene, lines):
    path = os.path.join(TMP, "s.replay")
    write_replay(path, scene, lines)
    out = subprocess.run([CARDEMO, "replay", path, "--json", "-"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("make_human_replays: cardemo replay failed: %s" % out.stderr)
    return json.loads(out.stdout)


def quantized(frames):
    """`frames` to the nearest multiple of QUANTUM, at least MIN_FRAMES."""
    return max(MIN_FRAMES, QUANTUM * int(math.floor(frames / QUANTUM + 0.5)))


def relative(rows, start):
    """Trace rows with x and y from the player's start, as make_levels' conditions read them."""
    out = []
    for row in rows:
        q = dict(row)
        q["x"] = str(float(row["x"]) - start[0])
        q["y"] = str(float(row["y"]) - start[1])
        out.append(q)
    return out


def at_tempo(steps):
    """A scripted manoeuvre keyed at a person's tempo: fixed counts of at least MIN_FRAMES, and
    pulses slowed down until the shorter of the two lasts MIN_FRAMES (the same share of each)."""
    out = []
    for step in steps:
        if len(step) == 3:
            (a, na), (b, nb), until = step
            scale = MIN_FRAMES / min(na, nb)
            out.append(((a, round(na * scale)), (b, round(nb * scale)), until))
        elif isinstance(step[1], int):
            out.append((step[0], max(MIN_FRAMES, step[1])))
        else:
            out.append(step)
    return out


def plan(scene, start, steps):
    """Input lines for `steps` driven in the level itself, each condition cut at the nearest
    QUANTUM after it first holds (a condition that holds sooner still gets MIN_FRAMES)."""
    lines = []

    def first(keys, limit, until):
        rows = relative(trace(scene, lines + [(limit, keys)]), start)
        n = sum(c for c, _ in lines)
        return next((i - n for i in range(n + 1, len(rows)) if until(rows[i])), None)

    for step in steps:
        if len(step) == 3:
            (a, na), (b, nb), until = step
            for _ in range(200):
                k = first(a, na, until)
                if k is not None:
                    lines.append((quantized(k), a))
                    break
                lines.append((na, a))
                k = first(b, nb, until)
                if k is not None:
                    lines.append((quantized(k), b))
                    break
                lines.append((nb, b))
            else:
                return None
            continue
        keys, until = step
        if isinstance(until, int):
            lines.append((until, keys))
            continue
        k = first(keys, 3000, until)
        if k is None:
            return None
        lines.append((quantized(k), keys))
    lines.append((TAIL, "."))
    return merged(lines)


def merged(lines):
    """Neighbouring lines with the same keys as one."""
    out = []
    for n, k in lines:
        if out and out[-1][1] == k:
            out[-1] = (out[-1][0] + n, k)
        else:
            out.append((n, k))
    return out


def heading_error(a, b, either):
    d = (a - b + 180.0) % 360.0 - 180.0
    if either and abs(d) > 90.0:
        d = d - 180.0 if d > 0 else d + 180.0
    return abs(d)


def cost(goal, s):
    """0 for a clean parked drive; else how far it is from one (lower is nearer)."""
    damage = 100 * len(s["hits"]) + (100 - s["health"]) if s["hits"] or s["health"] < 100 else 0
    if s["parked"] is not None and damage == 0:
        return 0.0
    bays = [goal["bay"]] + goal.get("next_bays", [])
    parked = s["bays"]["parked"]
    bay = bays[min(parked, len(bays) - 1)]
    f = s["final"]
    far = math.hypot(f["x"] - bay["x"], f["y"] - bay["y"]) / goal.get("position_tolerance", 0.5)
    turn = heading_error(f["heading_deg"], bay["heading_deg"], goal.get("either_direction", False))
    turn /= goal.get("heading_tolerance_deg", 8.0)
    gates = s["gates"]["total"] - s["gates"]["passed"]
    return 1.0 + 1000.0 * damage + 100.0 * gates + 100.0 * (len(bays) - parked) + far + turn


def neighbours(lines):
    """Drives one change away from `lines` (its standing tail kept): one line longer or shorter by
    1, 3 or 6 QUANTUM, the boundary between two lines moved by as much, or one line left out."""
    m = len(lines) - 1
    for step in (QUANTUM, 3 * QUANTUM, 6 * QUANTUM):
        for i in range(m):
            for d in (step, -step):
                if lines[i][0] + d >= MIN_FRAMES:
                    yield lines[:i] + [(lines[i][0] + d, lines[i][1])] + lines[i + 1:]
        for i in range(m - 1):
            for d in (step, -step):
                a, b = lines[i][0] + d, lines[i + 1][0] - d
                if a >= MIN_FRAMES and b >= MIN_FRAMES:
                    yield lines[:i] + [(a, lines[i][1]), (b, lines[i + 1][1])] + lines[i + 2:]
    for i in range(m):
        yield merged(lines[:i] + lines[i + 1:])
    # A correction a person makes on the way: a tap of steering inside a line that has none.
    for i in range(m):
        n, keys = lines[i]
        if "L" in keys or "R" in keys or n < 3 * MIN_FRAMES:
            continue
        for side in "LR":
            tapped = "".join(k for k in "UDLRH" if k in keys + side)
            for at in range(MIN_FRAMES, n - 2 * MIN_FRAMES + 1, MIN_FRAMES):
                yield (lines[:i] + [(at, keys), (MIN_FRAMES, tapped), (n - at - MIN_FRAMES, keys)] +
                       lines[i + 1:])


def mend(scene, goal, lines, budget=5000):
    """A clean parking drive near `lines`, by first-improvement hill climbing over neighbours();
    None when it gets stuck or runs out of `budget` evaluations."""
    best = cost(goal, summary(scene, lines))
    evaluations = 0
    while best > 0.0:
        for trial in neighbours(lines):
            evaluations += 1
            if evaluations > budget:
                return None
            c = cost(goal, summary(scene, trial))
            if c < best:
                best, lines = c, trial
                break
        else:
            return None
    return lines


def tune(scene, start, goal, steps, passes=3):
    """The manoeuvre's fixed-length steps lengthened or shortened (by 1 to 3 QUANTUM, never below
    MIN_FRAMES), each trial planned again so that its conditions still cut the other steps:
    first-improvement hill climbing. Returns the best plan's lines and their cost."""
    lines = plan(scene, start, steps)
    best = cost(goal, summary(scene, lines)) if lines else math.inf
    for _ in range(passes):
        improved = False
        for j, step in enumerate(steps):
            if best == 0.0:
                return lines, best
            if len(step) == 3 or not isinstance(step[1], int):
                continue
            for d in (QUANTUM, -QUANTUM, 2 * QUANTUM, -2 * QUANTUM, 3 * QUANTUM, -3 * QUANTUM):
                if step[1] + d < MIN_FRAMES:
                    continue
                trial = steps[:j] + [(step[0], step[1] + d)] + steps[j + 1:]
                trial_lines = plan(scene, start, trial)
                c = cost(goal, summary(scene, trial_lines)) if trial_lines else math.inf
                if c < best:
                    best, lines, steps, improved = c, trial_lines, trial, True
                    break
        if not improved:
            break
    return lines, best


def build(level):
    name = level["file"]
    scene_path = os.path.join(LEVELS, name + ".json")
    with open(scene_path) as f:
        scene_json = json.load(f)
    player = scene_json["player"]
    start = (player["x"], player["y"])
    lines, best = tune(scene_path, start, scene_json["goal"], at_tempo(level["steps"]))
    if lines is None:
        sys.exit("make_human_replays: %s: a condition of its manoeuvre never holds" % name)
    if best > 0.0:
        lines = mend(scene_path, scene_json["goal"], lines)
    if lines is None:
        sys.exit("make_human_replays: %s: no clean parking drive found near its manoeuvre" % name)
    assert all(n >= MIN_FRAMES for n, _ in lines)
    path = human_path(name)
    rel = "../scenes/levels/%s.json" % name
    comment = ("Level %s at a person's tempo: every line holds its keys for at least %d frames "
               "(made by scripts/make_human_replays.py)." % (name.split("-")[1], MIN_FRAMES))
    write_replay(path, rel, lines, comment)
    out = subprocess.run([CARDEMO, "replay", path, "--print-expect"], capture_output=True,
                         text=True, check=True)
    expect = [l for l in out.stdout.splitlines() if l.startswith("expect")]
    with open(path, "a") as f:
        f.write("# Expectations (regenerate with: cardemo replay THIS --print-expect)\n")
        f.write("\n".join(expect) + "\n")
    print(out.stdout.strip())
    print("%s: %d lines, par %d s" % (path, len(lines), par_of(path)))


def par_of(replay_path):
    """The par a human replay gives its level: its parked time rounded up to whole seconds."""
    out = subprocess.run([CARDEMO, "replay", replay_path, "--json", "-"], capture_output=True,
                         text=True)
    score = json.loads(out.stdout)["score"] if out.returncode == 0 else None
    if score is None:
        sys.exit("make_human_replays: %s does not park" % replay_path)
    return math.ceil(score["seconds"])


def main():
    global CARDEMO, TMP
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    CARDEMO = os.path.abspath(sys.argv[1])
    only = sys.argv[2:]
    TMP = tempfile.mkdtemp(prefix="cardemo-human-")
    try:
        for level in make_levels.ALL_LEVELS:
            if only and level["file"].split("-")[1] not in only:
                continue
            build(level)
    finally:
        shutil.rmtree(TMP, ignore_errors=True)


if __name__ == "__main__":
    main()
