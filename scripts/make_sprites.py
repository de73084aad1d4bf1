#!/usr/bin/env python3
"""Draws the game's sprites into assets/sprites/ (car.png, wheel.png, ground.png).

Standard library only: shapes are evaluated per sample (4x4 supersampling for the car and the tyre)
and written by a small zlib + struct PNG encoder. The output is the same on every run (fixed seeds).
Usage: scripts/make_sprites.py [OUTPUT_DIR]   (default: assets/sprites next to this script)
"""

import math
import os
import random
import struct
import sys
import zlib


def write_png(path, width, height, rgba_rows):
    """Writes 8-bit RGBA rows (each a bytes object of width * 4) as a PNG file, atomically."""

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + row for row in rgba_rows)  # filter type 0 on every row
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(png)
    os.replace(tmp, path)


def render(width, height, shade, samples=4):
    """Rows of RGBA bytes; shade(x, y) gives (r, g, b, a) floats 0..1 at a point in pixel units."""
    rows = []
    n = samples * samples
    for py in range(height):
        row = bytearray()
        for px in range(width):
            r = g = b = a = 0.0
            for sy in range(samples):
                for sx in range(samples):
                    cr, cg, cb, ca = shade(px + (sx + 0.5) / samples, py + (sy + 0.5) / samples)
                    r += cr * ca
                    g += cg * ca
                    b += cb * ca
                    a += ca
            if a > 0.0:
                r, g, b = r / a, g / a, b / a  # un-premultiply the average
            row += bytes(max(0, min(255, round(v * 255))) for v in (r, g, b, a / n))
        rows.append(bytes(row))
    return rows


def rounded_box(x, y, hx, hy, radius):
    """Signed distance to a rounded rectangle centred at the origin (negative inside)."""
    qx, qy = abs(x) - hx + radius, abs(y) - hy + radius
    outside = math.hypot(max(qx, 0.0), max(qy, 0.0))
    return outside + min(max(qx, qy), 0.0) - radius


def over(base, top, alpha):
    """`top` over `base` (both RGB) with coverage alpha."""
    return tuple(b + (t - b) * alpha for b, t in zip(base, top))


# The car: 4.5 m x 1.8 m, nose towards +x, seen from above. Light grey, so a colour mod paints it.
CAR_LENGTH, CAR_WIDTH = 4.5, 1.8
CAR_PPM = 56  # pixels per metre in the file


def car_shade(px, py):
    x = (px - CAR_LENGTH * CAR_PPM / 2) / CAR_PPM  # metres, forward
    y = (py - CAR_WIDTH * CAR_PPM / 2) / CAR_PPM   # metres, across (right side down)
    hx, hy = CAR_LENGTH / 2, CAR_WIDTH / 2
    radius = 0.42 if x > 0 else 0.3
    d = rounded_box(x, y, hx, hy, radius)
    if d > 0:
        return (0, 0, 0, 0)
    # Paint: brightest along the spine, darker towards the sides (a curved body in flat light).
    side = abs(y) / hy
    k = 0.9 - 0.18 * side ** 3
    col = (k, k, k)
    # Windscreen: a trapezoid from 0.27 m to 1.1 m ahead of the centre, narrowing to the front.
    if 0.27 < x < 1.1:
        t = (x - 0.27) / 0.83
        half = 0.78 - 0.14 * t
        if abs(y) < half:
            glass = (0.16, 0.19, 0.24)
            streak = 0.10 if abs((x - 0.5) - 0.45 * y) < 0.06 else 0.0
            col = tuple(c + streak for c in glass)
    # Rear window.
    if -1.62 < x < -1.2 and abs(y) < 0.66 - 0.12 * (-1.2 - x) / 0.42:
        col = (0.18, 0.21, 0.26)
    # Roof: slightly lighter, with a thin panel seam.
    if -1.2 <= x <= 0.27 and abs(y) < 0.72:
        col = (1.0 - 0.06 * (abs(y) / 0.72) ** 2,) * 3
        if abs(y) > 0.68 or abs(x + 1.2) < 0.03 or abs(x - 0.27) < 0.03:
            col = (0.72, 0.72, 0.72)
    # Bonnet creases.
    if 1.15 < x < 2.05 and abs(abs(y) - 0.38) < 0.018:
        col = over(col, (0.7, 0.7, 0.7), 0.6)
    # Lamps in neutral tones (the renderer lights them on top).
    if 1.92 < x < 2.2 and 0.42 < abs(y) < 0.78:
        col = (1.0, 0.98, 0.9)
    if -2.22 < x < -2.04 and 0.42 < abs(y) < 0.8:
        col = (0.62, 0.3, 0.3)
    # Side mirrors.
    if 0.2 < x < 0.42 and abs(y) > hy - 0.09:
        col = (0.6, 0.6, 0.6)
    # A dark rim along the body edge.
    if d > -0.035:
        col = over(col, (0.35, 0.35, 0.35), 0.8)
    return col + (1.0,)


# A tyre: 0.72 m x 0.26 m, rolling along +x.
TYRE_LENGTH, TYRE_WIDTH = 0.72, 0.26
TYRE_PPM = 120


def tyre_shade(px, py):
    x = (px - TYRE_LENGTH * TYRE_PPM / 2) / TYRE_PPM
    y = (py - TYRE_WIDTH * TYRE_PPM / 2) / TYRE_PPM
    d = rounded_box(x, y, TYRE_LENGTH / 2, TYRE_WIDTH / 2, 0.06)
    if d > 0:
        return (0, 0, 0, 0)
    k = 0.1
    if math.fmod(abs(x) + 0.5, 0.09) < 0.03 and abs(y) < 0.09:  # tread blocks across the tyre
        k = 0.13
    if d > -0.02:
        k = 0.05
    return (k, k, k * 1.1, 1.0)


# Asphalt: a seamless tile of periodic value noise plus grit.
GROUND_PX = 256


def ground_rows():
    rng = random.Random(20261124)
    octaves = []
    for cells in (4, 8, 16, 32):
        octaves.append((cells, [[rng.random() for _ in range(cells)] for _ in range(cells)]))

    def noise(u, v):
        total = 0.0
        amp = 1.0
        norm = 0.0
        for cells, grid in octaves:
            x, y = u * cells, v * cells
            x0, y0 = int(math.floor(x)), int(math.floor(y))
            fx, fy = x - x0, y - y0
            fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
            a = grid[y0 % cells][x0 % cells]
            b = grid[y0 % cells][(x0 + 1) % cells]
            c = grid[(y0 + 1) % cells][x0 % cells]
            d = grid[(y0 + 1) % cells][(x0 + 1) % cells]
            total += amp * ((a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy)
            norm += amp
            amp *= 0.55
        return total / norm

    rows = []
    for py in range(GROUND_PX):
        row = bytearray()
        for px in range(GROUND_PX):
            n = noise(px / GROUND_PX, py / GROUND_PX) - 0.5
            grit = rng.random()
            base = 42 + 16 * n
            if grit < 0.06:
                base += rng.uniform(-9, 4)
            elif grit > 0.985:
                base += rng.uniform(8, 18)
            r = base - 1
            g = base + 1
            b = base + 5
            row += bytes(max(0, min(255, round(v))) for v in (r, g, b)) + b"\xff"
        rows.append(bytes(row))
    return rows


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "assets", "sprites")
    os.makedirs(out, exist_ok=True)
    cw, ch = round(CAR_LENGTH * CAR_PPM), round(CAR_WIDTH * CAR_PPM)
    write_png(os.path.join(out, "car.png"), cw, ch, render(cw, ch, car_shade))
    tw, th = round(TYRE_LENGTH * TYRE_PPM), round(TYRE_WIDTH * TYRE_PPM)
    write_png(os.path.join(out, "wheel.png"), tw, th, render(tw, th, tyre_shade))
    write_png(os.path.join(out, "ground.png"), GROUND_PX, GROUND_PX, ground_rows())
    print("wrote car.png (%dx%d), wheel.png (%dx%d), ground.png (%dx%d) in %s"
          % (cw, ch, tw, th, GROUND_PX, GROUND_PX, os.path.normpath(out)))


if __name__ == "__main__":
    main()
