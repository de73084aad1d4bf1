#!/usr/bin/env python3
"""Generates the game's sounds (assets/sounds/*.wav) from formulas; standard library only.

Usage: scripts/make_sounds.py [OUT_DIR]   (default: assets/sounds next to this script's parent)
       scripts/make_sounds.py --check [DIR]  (exit 1 unless DIR holds exactly what this makes)

Every sound is synthesised here, so the WAV files are our own work, released under CC0 1.0 (see
assets/sounds/README.md). The output is the same byte for byte on every run (seeded noise).

Loops (engine-1..4, screech) last LOOP_SECONDS and contain whole cycles of every partial, so they
repeat without a click: each frequency is a multiple of 1 / LOOP_SECONDS.
"""

import math
import os
import random
import struct
import sys
import wave

RATE = 22050  # Hz, mono, 16-bit
LOOP_SECONDS = 0.5  # loop partials must be multiples of 2 Hz
PEAK = 0.8  # of full scale

# Engine loops at rising pitch (firing frequency in Hz, each a multiple of 4 Hz so that f0 / 2
# is a whole number of cycles per loop too); the game
# cross-fades them by speed (src/play/sound_mix.cpp).
ENGINE_FREQUENCIES = [36, 60, 92, 136]


def normalise(samples, peak=PEAK):
    top = max(abs(s) for s in samples) or 1.0
    return [s * peak / top for s in samples]


def pcm(samples):
    return b"".join(struct.pack("<h", max(-32767, min(32767, round(s * 32767)))) for s in samples)


def write_wav(path, samples):
    tmp = path + ".tmp"
    with wave.open(tmp, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(RATE)
        w.writeframes(pcm(samples))
    os.replace(tmp, path)


def matches(path, samples):
    try:
        with wave.open(path, "rb") as w:
            same_format = (w.getnchannels(), w.getsampwidth(), w.getframerate()) == (1, 2, RATE)
            return same_format and w.readframes(w.getnframes()) == pcm(samples)
    except (OSError, wave.Error):
        return False


def engine(f0):
    """Harmonics of the firing frequency (falling as 1/k^1.3) with a lumpy half-rate pulse."""
    n = int(RATE * LOOP_SECONDS)
    phases = [0.0, 1.1, 2.3, 0.7, 1.9, 2.9, 0.3, 1.5]
    out = []
    for i in range(n):
        t = i / RATE
        s = sum(math.sin(2 * math.pi * k * f0 * t + phases[k - 1]) / k**1.3 for k in range(1, 9))
        s *= 1.0 + 0.35 * math.sin(2 * math.pi * (f0 / 2) * t)
        out.append(s)
    return normalise(out)


def screech():
    """A squealing tone: 1900 Hz frequency-modulated at 14 Hz, with a second partial and hiss."""
    n = int(RATE * LOOP_SECONDS)
    rng = random.Random(11)
    out = []
    for i in range(n):
        t = i / RATE
        wobble = 9.0 * math.sin(2 * math.pi * 14 * t)
        s = math.sin(2 * math.pi * 1900 * t + wobble)
        s += 0.4 * math.sin(2 * math.pi * 3800 * t + 2 * wobble)
        s += 0.15 * rng.uniform(-1.0, 1.0)
        out.append(s)
    return normalise(out, 0.6)


def impact():
    """A crunch: decaying noise, a falling low thump and a few inharmonic metal partials."""
    n = int(RATE * 0.6)
    rng = random.Random(7)
    out = []
    lowpassed = 0.0
    thump_phase = 0.0
    for i in range(n):
        t = i / RATE
        lowpassed += 0.35 * (rng.uniform(-1.0, 1.0) - lowpassed)
        noise = lowpassed * math.exp(-t / 0.06)
        thump_phase += 2 * math.pi * (45 + 70 * math.exp(-t / 0.05)) / RATE
        thump = 1.4 * math.sin(thump_phase) * math.exp(-t / 0.12)
        metal = sum(a * math.sin(2 * math.pi * f * t) * math.exp(-t / d)
                    for f, a, d in ((410, 0.35, 0.15), (1130, 0.25, 0.09), (2350, 0.15, 0.05)))
        attack = min(1.0, t / 0.002)
        out.append(attack * (noise + thump + metal))
    return normalise(out)


def chime():
    """Two bell notes (A5 then E6) with decaying partials: parked."""
    n = int(RATE * 1.2)
    out = [0.0] * n
    for start, f in ((0.0, 880.0), (0.16, 1318.5)):
        for i in range(int(start * RATE), n):
            t = i / RATE - start
            env = min(1.0, t / 0.004) * math.exp(-t / 0.35)
            out[i] += env * (math.sin(2 * math.pi * f * t) + 0.3 * math.sin(2 * math.pi * 2.76 * f * t)
                             * math.exp(-t / 0.1))
    return normalise(out, 0.7)


def main():
    args = sys.argv[1:]
    check = bool(args) and args[0] == "--check"
    if check:
        args = args[1:]
    here = os.path.dirname(os.path.abspath(__file__))
    out_dir = args[0] if args else os.path.join(here, "..", "assets", "sounds")
    sounds = {f"engine-{i + 1}.wav": engine(f) for i, f in enumerate(ENGINE_FREQUENCIES)}
    sounds["screech.wav"] = screech()
    sounds["impact.wav"] = impact()
    sounds["chime.wav"] = chime()
    if check:
        stale = [name for name, samples in sounds.items()
                 if not matches(os.path.join(out_dir, name), samples)]
        for name in stale:
            print(f"{os.path.join(out_dir, name)}: differs from what scripts/make_sounds.py makes; "
                  "run it to regenerate", file=sys.stderr)
        return 1 if stale else 0
    os.makedirs(out_dir, exist_ok=True)
    for name, samples in sounds.items():
        write_wav(os.path.join(out_dir, name), samples)
        print(f"{name}: {len(samples) / RATE:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
