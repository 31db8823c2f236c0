#!/usr/bin/env python3
"""Writes the texture images of stage 07's scenes (stages/07-textures/scenes/textures/), made
from code so that they can be re-made and reviewed: a test card whose orientation is plain to
see, bricks, a normal map of round bumps, a fine checkerboard for the filtering demo and a
latitude-longitude map of a made-up planet for a globe.

    python3 tools/make_textures.py [OUT_DIR]

Plain Python (zlib only), 8-bit RGB PNG. Colour images hold sRGB-encoded values; the normal map
holds data (docs/conventions.md#textures)."""
import math
import os
import struct
import sys
import zlib


def write_png(path, width, height, pixel):
    """pixel(x, y) -> (r, g, b) in 0..255; row 0 is the top of the image."""
    rows = b"".join(b"\x00" + bytes(c for x in range(width) for c in pixel(x, y))
                    for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(rows, 9)))
        f.write(chunk(b"IEND", b""))


def test_card(x, y):
    """64 x 64: quadrants red (top left), green (top right), blue (bottom left), yellow (bottom
    right), a white grid every 8 texels, and a black 'F' in the top-left quadrant that reads
    correctly only when the image is neither mirrored nor upside down."""
    if x % 8 == 0 or y % 8 == 0:
        return (255, 255, 255)
    if 6 <= x < 10 and 6 <= y < 26 or 6 <= y < 10 and 6 <= x < 22 or 14 <= y < 18 and 6 <= x < 18:
        return (0, 0, 0)
    top, left = y < 32, x < 32
    return {(True, True): (220, 40, 40), (True, False): (40, 180, 60),
            (False, True): (40, 80, 220), (False, False): (240, 210, 40)}[(top, left)]


def bricks(x, y):
    """64 x 64: four courses of bricks 32 x 16 with mortar, alternate courses shifted by half."""
    course = y // 16
    shifted = (x + (16 if course % 2 else 0)) % 32
    if y % 16 < 2 or shifted < 2:
        return (200, 195, 185)
    shade = 150 + ((x // 32 * 7 + course * 13) % 5) * 12
    return (shade, 70 + (course * 17) % 30, 50)


def bumps_normal(x, y):
    """64 x 64: a tangent-space normal map (OpenGL style, +y towards the image top) of four by
    four round bumps; flat (128, 128, 255) between them."""
    cx, cy = (x % 16) + 0.5 - 8, (y % 16) + 0.5 - 8
    r = math.hypot(cx, cy)
    if r >= 6:
        return (128, 128, 255)
    # A spherical cap: the normal tilts outwards. Image y grows downwards, tangent-space y up.
    nx, ny = cx / 6.5, -cy / 6.5
    nz = math.sqrt(max(0.0, 1 - nx * nx - ny * ny))
    return tuple(int(round((c * 0.5 + 0.5) * 255)) for c in (nx, ny, nz))


def fine_checks(x, y):
    """64 x 64: black and white squares of 4 texels."""
    return (235, 235, 235) if (x // 4 + y // 4) % 2 == 0 else (20, 20, 20)


def _hash(ix, iy):
    h = (ix * 374761393 + iy * 668265263) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 65535.0


def _value_noise(x, y, period):
    """Smooth value noise, periodic in x with `period` cells (so the globe has no seam)."""
    ix, iy = math.floor(x), math.floor(y)
    fx, fy = x - ix, y - iy
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
    def at(i, j):
        return _hash(i % period, j)
    top = at(ix, iy) * (1 - sx) + at(ix + 1, iy) * sx
    bottom = at(ix, iy + 1) * (1 - sx) + at(ix + 1, iy + 1) * sx
    return top * (1 - sy) + bottom * sy


def globe(x, y):
    """128 x 64 latitude-longitude map of a made-up planet: oceans and continents from periodic
    value noise, ice caps, a grid about every 30 degrees and a red meridian at u = 0 (the seam)."""
    u, v = (x + 0.5) / 128, (y + 0.5) / 64
    if x == 0 or x == 127:
        return (200, 30, 30)
    if x % 11 == 0 and x < 121 or y % 11 == 0 and 0 < y < 60:
        grid = True
    else:
        grid = False
    if v < 0.08 or v > 0.92:
        return (235, 240, 245)
    land = (_value_noise(u * 8, v * 4, 8) * 0.65 + _value_noise(u * 16, v * 8, 16) * 0.35) > 0.55
    colour = (70, 140, 60) if land else (30, 70, 150)
    if grid:
        colour = tuple(min(255, c + 60) for c in colour)
    return colour


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "stages", "07-textures", "scenes",
        "textures")
    os.makedirs(out, exist_ok=True)
    for name, fn in (("test_card", test_card), ("bricks", bricks),
                     ("bumps_normal", bumps_normal), ("fine_checks", fine_checks),
                     ("globe", globe)):
        width = 128 if name == "globe" else 64
        write_png(os.path.join(out, name + ".png"), width, 64, fn)
        print(os.path.join(out, name + ".png"))


if __name__ == "__main__":
    main()
