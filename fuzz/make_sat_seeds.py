#!/usr/bin/env python3
"""Writes the hand-made seeds of the SAT fuzz targets (fuzz/corpus/sat2, fuzz/corpus/sat3).

Each seed spells out, byte by byte, the choices that the decoders in shapes2.hpp and shapes3.hpp
read (same order), so that the fuzzer starts from the named edge cases: exact touching far from
the origin, nearly and exactly parallel edges, containment, coincident shapes, the size extremes,
and the "wild" domain. A few seeded random inputs are added. Rerun after changing a decoder:
    python3 fuzz/make_sat_seeds.py
"""
import math
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


class Seed:
    """Byte writer mirroring ByteReader (fuzz/byte_reader.hpp)."""

    def __init__(self):
        self.out = bytearray()

    def byte(self, v):
        self.out.append(v & 0xFF)
        return self

    pick = byte

    def sign(self, s):
        return self.byte(1 if s < 0 else 0)

    def unit(self, x):
        x = min(1.0, max(0.0, x))
        self.out += struct.pack("<Q", round(x * (2**53 - 1)) << 11)
        return self

    def range(self, lo, hi, v):
        return self.unit((v - lo) / (hi - lo))

    def log_range(self, lo, hi, v):
        return self.unit((math.log(v) - math.log(lo)) / (math.log(hi) - math.log(lo)))

    def signed_log(self, lo, hi, v):
        self.sign(v)
        return self.log_range(lo, hi, abs(v))

    def dyadic(self, lo, hi, v):
        self.sign(v)
        return self.range(lo, hi, abs(v))


# --- 2D (shapes2.hpp) ---------------------------------------------------------------------------

def center2(s, mode, x=0.0, y=0.0):
    s.pick(mode)
    if mode == 0:
        s.range(-100, 100, x).range(-100, 100, y)
    elif mode == 1:
        s.range(-math.pi, math.pi, math.atan2(y, x)).log_range(1.0, 1e7, math.hypot(x, y))
    else:
        s.dyadic(4e6, 8e6, x).dyadic(4e6, 8e6, y)


def axis2(s, quarter, mode, value=0.0):
    s.pick(quarter).pick(mode)
    if mode == 1:
        s.range(-180, 180, value)
    elif mode == 2:
        s.signed_log(1e-15, 1e-3, value)


def half2(s, v):
    if v == 0.005:
        s.pick(0)
    elif v == 50.0:
        s.pick(1)
    else:
        s.pick(2).log_range(0.005, 50.0, v)


def box2(s, quarter, axis_mode, axis_value, hx, hy):
    axis2(s, quarter, axis_mode, axis_value)
    half2(s, hx)
    half2(s, hy)


def regular_polygon2(s, n, rx, ry, start, quarter=0, reverse=False):
    s.pick(n - 3).pick(1)
    half2(s, rx)
    half2(s, ry)
    axis2(s, quarter, 0)
    s.range(0.0, 2 * math.pi, start)
    s.byte(1 if reverse else 0)


def place2(s, mode, normal=0, gap=0.0, lateral=0.5, offset=(0.0, 0.0)):
    s.pick(mode)
    if mode == 0:
        s.range(-150, 150, offset[0]).range(-150, 150, offset[1])
        return
    if mode in (1, 2):
        s.pick(normal)
    else:
        s.range(-math.pi, math.pi, normal)
    if gap == 0.0:
        s.pick(0)
    else:
        s.pick(1).signed_log(1e-12, 10.0, gap)
    s.unit(lateral)


def sat2_seeds():
    seeds = {}
    s = Seed().byte(0)  # box/box, exactly touching face to face at 6e6 m on a dyadic grid
    center2(s, 2, 6e6, -5e6)
    box2(s, 0, 0, 0, 2.25, 0.9)
    box2(s, 1, 0, 0, 2.25, 0.9)
    place2(s, 1, normal=0, gap=0.0)
    seeds["box-touching-far"] = s
    s = Seed().byte(0)  # box/box, 1e-13 rad off a quarter turn, 1e-9 m apart
    center2(s, 1, 3e5, 2e5)
    box2(s, 0, 0, 0, 50.0, 0.005)
    box2(s, 1, 2, 1e-13, 50.0, 0.005)
    place2(s, 1, normal=1, gap=1e-9, lateral=0.9)
    seeds["box-near-parallel-far"] = s
    s = Seed().byte(0)  # box/box, B inside A
    center2(s, 0, 1.0, 2.0)
    box2(s, 0, 1, 30.0, 10.0, 10.0)
    box2(s, 0, 1, -45.0, 0.005, 0.005)
    place2(s, 0, offset=(0.5, -0.25))
    seeds["box-containment"] = s
    s = Seed().byte(0)  # box/box, coincident
    center2(s, 1, -7e6, 7e6)
    box2(s, 0, 1, 12.5, 2.25, 0.9)
    box2(s, 0, 1, 12.5, 2.25, 0.9)
    place2(s, 0, offset=(0.0, 0.0))
    seeds["box-coincident"] = s
    s = Seed().byte(0)  # box/box, corner against corner at 45 degrees, overlapping by 1e-7 m
    center2(s, 0, 0.0, 0.0)
    box2(s, 0, 1, 45.0, 1.0, 1.0)
    box2(s, 0, 1, 45.0, 1.0, 1.0)
    place2(s, 3, normal=0.0, gap=-1e-7, lateral=0.5)
    seeds["box-corners"] = s
    s = Seed().byte(1)  # polygon/polygon: regular hexagons with parallel edges, exactly touching
    center2(s, 2, -4.5e6, 4.5e6)
    regular_polygon2(s, 6, 3.0, 3.0, 0.0)
    regular_polygon2(s, 6, 3.0, 3.0, 0.0, reverse=True)
    place2(s, 1, normal=2, gap=0.0)
    seeds["polygon-hexagons-touching"] = s
    s = Seed().byte(1)  # polygon/polygon: 16-gon against a triangle, 2e-6 m apart, far out
    center2(s, 1, 9e6, -1e6)
    regular_polygon2(s, 16, 50.0, 0.5, 0.3)
    regular_polygon2(s, 3, 0.005, 0.005, 1.0)
    place2(s, 2, normal=1, gap=2e-6, lateral=0.1)
    seeds["polygon-sliver-far"] = s
    s = Seed().byte(2)  # box/polygon at 1e7 m, 1e-12 m overlap
    center2(s, 1, 7e6, 7e6)
    box2(s, 0, 1, 90.0, 2.25, 0.9)
    regular_polygon2(s, 5, 1.0, 2.0, 0.7)
    place2(s, 1, normal=3, gap=-1e-12)
    seeds["box-polygon-far"] = s
    s = Seed().byte(3)  # polygon/box, B's normal
    center2(s, 0, 10.0, -10.0)
    regular_polygon2(s, 4, 2.0, 2.0, 0.25)
    box2(s, 2, 2, 1e-15, 0.005, 50.0)
    place2(s, 2, normal=2, gap=1e-6)
    seeds["polygon-box-thin"] = s
    for routine in range(4):  # wild: tiny, huge and denormal values
        s = Seed().byte(0x80 | routine)
        s.out += bytes(random.Random(routine).randrange(256) for _ in range(160))
        seeds[f"wild-{routine}"] = s
    for k in range(4):
        s = Seed()
        s.out += bytes(random.Random(100 + k).randrange(256) for _ in range(200))
        seeds[f"random-{k}"] = s
    return seeds


# --- 3D (shapes3.hpp) ---------------------------------------------------------------------------

def center3(s, mode, c):
    s.pick(mode)
    for v in c:
        if mode == 0:
            s.range(-100, 100, v)
        elif mode == 1:
            s.signed_log(1.0, 5.7e6, v)
        else:
            s.dyadic(2e6, 4e6, v)


def quarter_turns(s, first, second):
    s.pick(first).pick(second)


def direction3(s, z, t):
    s.range(-1, 1, z).range(-math.pi, math.pi, t)


def size3(s, sizes):
    for v in sizes:
        if v == 0.01:
            s.pick(0)
        elif v == 100.0:
            s.pick(1)
        else:
            s.pick(2).log_range(0.01, 100.0, v)


def place3_axis(s, k, sign, gap, lateral=0.0):
    s.pick(1)
    direction3(s, 0.3, 0.4)  # the random direction read first (unused when the axis exists)
    s.pick(k).sign(sign)
    if gap == 0.0:
        s.pick(0)
    else:
        s.pick(1).signed_log(1e-12, 10.0, gap)
    direction3(s, 0.1, 1.0)
    s.unit(lateral)


def sat3_seeds():
    seeds = {}
    s = Seed().byte(0)  # axis-aligned dyadic boxes touching face to face far out, same rotation
    center3(s, 2, (3e6, -3e6, 2.5e6))
    s.pick(0)
    quarter_turns(s, 0, 0)
    size3(s, (4.5, 1.8, 1.5))
    s.pick(2).pick(0)
    size3(s, (4.5, 1.8, 1.5))
    place3_axis(s, 0, +1, 0.0)
    seeds["touching-far"] = s
    s = Seed().byte(0)  # long boxes with edges 1e-14 rad from parallel, 1e-9 m apart on their edge axis
    center3(s, 1, (5e5, -2e5, 1e6))
    s.pick(3).range(-math.pi, math.pi, 0.7)
    direction3(s, 0.2, 2.0)
    size3(s, (100.0, 0.01, 0.5))
    s.pick(1)
    quarter_turns(s, 1, 0)
    s.signed_log(1e-15, 1e-3, 1e-14)
    direction3(s, -0.5, 0.1)
    size3(s, (0.01, 100.0, 0.3))
    place3_axis(s, 6 + 3 * 0 + 1, -1, 1e-9)
    seeds["near-parallel-edges"] = s
    s = Seed().byte(0)  # exactly parallel, quaternion scaled by -1, overlapping by 1e-7 m on a face
    center3(s, 0, (1.0, 2.0, 3.0))
    s.pick(1)
    for v in (0.3, -0.5, 0.2, 0.7):
        s.range(-1, 1, v)
    size3(s, (2.0, 3.0, 4.0))
    s.pick(2).pick(1)
    size3(s, (1.0, 1.0, 1.0))
    place3_axis(s, 4, +1, -1e-7, lateral=0.3)
    seeds["parallel-negated"] = s
    s = Seed().byte(0)  # B inside A
    center3(s, 1, (-9e5, 9e5, 1.0))
    s.pick(2)
    quarter_turns(s, 2, 3)
    s.signed_log(1e-15, 1e-3, 1e-5)
    direction3(s, 0.9, -2.0)
    size3(s, (100.0, 100.0, 100.0))
    s.pick(0)
    s.pick(0)
    quarter_turns(s, 3, 1)
    size3(s, (0.01, 0.01, 0.01))
    s.pick(3).range(-1, 1, 0.2).range(-1, 1, -0.3).range(-1, 1, 0.1)
    seeds["containment"] = s
    for k in range(3):
        s = Seed().byte(0x80)
        s.out += bytes(random.Random(200 + k).randrange(256) for _ in range(200))
        seeds[f"wild-{k}"] = s
    for k in range(4):
        s = Seed()
        s.out += bytes(random.Random(300 + k).randrange(256) for _ in range(240))
        seeds[f"random-{k}"] = s
    return seeds


def main():
    for target, seeds in (("sat2", sat2_seeds()), ("sat3", sat3_seeds())):
        folder = os.path.join(HERE, "corpus", target)
        os.makedirs(folder, exist_ok=True)
        for name, seed in seeds.items():
            with open(os.path.join(folder, name), "wb") as f:
                f.write(bytes(seed.out))


if __name__ == "__main__":
    main()
