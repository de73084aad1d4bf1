#!/usr/bin/env python3
"""Generates the game's sounds (assets/sounds/*.wav) from formulas; standard library only.

Usage: scripts/make_sounds.py [OUT_DIR]   (default: assets/sounds next to this script's parent)
       scripts/make_sounds.py --check [DIR]  (exit 1 unless DIR holds exactly what this makes)

Every sound is synthesised here, so the WAV files are our own work, released under CC0 1.0 (see
assets/sounds/README.md). The output is the same byte for byte on every run (seeded noise).

Loops (engine-1..4, screech) last LOOP_SECONDS and repeat without a click: every partial is a
multiple of 1 / LOOP_SECONDS, each firing's ring wraps round the loop, and filters run in their
steady state over the repeating loop.

Laptop speakers play little below about 150 Hz, so engine, screech and impact keep most of their
energy between 150 and 2,000 Hz: the engine's firing rate (36 to 136 Hz) is heard from its
harmonics, as a missing fundamental. tests/play/sound_spectrum_test.cpp measures the files.
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

# Engine loops at rising pitch (firing frequency in Hz, each a multiple of 4 Hz so that a loop
# holds an even number of firings, strong and weak in turn); the game cross-fades them by speed
# (src/play/sound_mix.cpp).
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


def biquad(kind, f, q):
    """Coefficients (b0, b1, b2, a1, a2) of a 2nd-order filter, after R. Bristow-Johnson's
    "Audio EQ Cookbook": kind "low" or "high" pass, or "band" (band pass, 0 dB at f)."""
    w = 2 * math.pi * f / RATE
    cw = math.cos(w)
    alpha = math.sin(w) / (2 * q)
    b = {"low": ((1 - cw) / 2, 1 - cw, (1 - cw) / 2),
         "high": ((1 + cw) / 2, -(1 + cw), (1 + cw) / 2),
         "band": (alpha, 0.0, -alpha)}[kind]
    a0 = 1 + alpha
    return (b[0] / a0, b[1] / a0, b[2] / a0, -2 * cw / a0, (1 - alpha) / a0)


def filtered(samples, stages, loop=False):
    """`samples` through each biquad of `stages` in turn. With `loop`, each stage first runs once
    over the loop to settle, so the output is the steady state of the repeating loop and still
    joins without a click (the filters ring for milliseconds, the loop lasts LOOP_SECONDS)."""
    for b0, b1, b2, a1, a2 in stages:
        x1 = x2 = y1 = y2 = 0.0
        for _ in range(2 if loop else 1):
            out = []
            for x in samples:
                y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2
                x2, x1, y2, y1 = x1, x, y1, y
                out.append(y)
        samples = out
    return samples


# What a firing rings: the exhaust's resonances (Hz, amplitude, decay in s). Then two 2nd-order
# high-pass stages (24 dB per octave below 190 Hz) take out what laptop speakers cannot play.
KNOCK_RESONANCES = ((300, 1.0, 0.0035), (650, 0.6, 0.0025), (1250, 0.3, 0.0015))
ENGINE_HIGHPASS = [biquad("high", 190, 0.71), biquad("high", 190, 0.71)]


def engine(f0):
    """A loop of firings at f0 per second: each a short knock of the exhaust's resonances (near
    300, 650, 1250 Hz), every other one weaker, with seeded jitter in time and strength; a steep
    high-pass at 190 Hz leaves the firing rate to be heard from its harmonics."""
    n = int(RATE * LOOP_SECONDS)
    rng = random.Random(f0)
    out = [0.0] * n
    knock_samples = int(0.03 * RATE)
    for j in range(round(f0 * LOOP_SECONDS)):
        start = j / f0 + rng.uniform(-0.0002, 0.0002)
        strength = (1.0 if j % 2 == 0 else 0.75) * rng.uniform(0.92, 1.08)
        first = math.ceil(start * RATE)
        for i in range(first, first + knock_samples):
            t = i / RATE - start
            # The last firings ring on into the loop's first samples, so the loop joins seamlessly.
            out[i % n] += strength * sum(a * math.exp(-t / d) * math.sin(2 * math.pi * f * t)
                                         for f, a, d in KNOCK_RESONANCES)
    return normalise(filtered(out, ENGINE_HIGHPASS, loop=True))


def screech():
    """A tyre squeal: 1150 Hz wavering at 4 and 14 Hz and chattering at 22 Hz, a weaker second
    harmonic, and hiss around the squeal."""
    n = int(RATE * LOOP_SECONDS)
    rng = random.Random(11)
    hiss = filtered([rng.uniform(-1.0, 1.0) for _ in range(n)],
                    [biquad("band", 1200, 1.2), biquad("band", 1200, 1.2)], loop=True)
    out = []
    for i in range(n):
        t = i / RATE
        wobble = 3.0 * math.sin(2 * math.pi * 14 * t) + 8.0 * math.sin(2 * math.pi * 4 * t)
        chatter = 1.0 + 0.25 * math.sin(2 * math.pi * 22 * t)
        s = math.sin(2 * math.pi * 1150 * t + wobble)
        s += 0.25 * math.sin(2 * math.pi * 2300 * t + 2 * wobble + 0.8)
        out.append(chatter * s + 0.5 * hiss[i])
    return normalise(out, 0.6)


def impact():
    """A thud and crunch: a body resonance falling from 330 to 170 Hz with its second harmonic,
    band-passed crackle and a few inharmonic metal partials, all decaying within half a second."""
    n = int(RATE * 0.6)
    rng = random.Random(7)
    crackle = [rng.uniform(-1.0, 1.0) * (1.0 if rng.random() < 0.3 else 0.2) for _ in range(n)]
    crackle = filtered(crackle, [biquad("high", 350, 0.71), biquad("low", 1700, 0.71)])
    out = []
    body_phase = 0.0
    for i in range(n):
        t = i / RATE
        body_phase += 2 * math.pi * (170 + 160 * math.exp(-t / 0.04)) / RATE
        body = math.exp(-t / 0.09) * (math.sin(body_phase) + 0.45 * math.sin(2 * body_phase))
        noise = 4.0 * crackle[i] * math.exp(-t / 0.06)
        metal = sum(a * math.sin(2 * math.pi * f * t) * math.exp(-t / d)
                    for f, a, d in ((410, 0.35, 0.15), (1130, 0.25, 0.09), (1720, 0.15, 0.05)))
        attack = min(1.0, t / 0.002)
        release = min(1.0, (n - 1 - i) / (0.03 * RATE))  # no click where the file ends
        out.append(attack * release * (body + noise + metal))
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
