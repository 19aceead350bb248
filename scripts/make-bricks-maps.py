#!/usr/bin/env python3
"""make-bricks-maps.py: writes scenes/textures/bricks-512-depth.png and
bricks-512-colour.png, the maps of the parallax benchmark scenes
(scenes/conformance-parallax-*.json, issue 30): a tileable running bond of
4 x 8 bricks on 512 x 512 texels, deterministic (an integer hash, no random
module), so the files can be made again byte for byte.

Depth (grey, 0 = the top of a brick, 1 = the bottom of a joint): each brick a
flat face with grain, rounded over a bevel of 10 texels down into joints of
8 texels. Colour (RGB): a tone per brick, grain, pale joints.
"""
import struct
import sys
import zlib

N = 512
COLS, ROWS = 4, 8
BW, BH = N // COLS, N // ROWS
JOINT, BEVEL = 8, 10


def hash32(*xs):
    h = 2166136261
    for x in xs:
        h ^= x & 0xFFFFFFFF
        h = (h * 16777619) & 0xFFFFFFFF
        h ^= h >> 13
        h = (h * 0x5BD1E995) & 0xFFFFFFFF
        h ^= h >> 15
    return h


def unit(*xs):
    return hash32(*xs) / 4294967296.0


def grain(x, y):
    # Value noise on a 4-texel lattice, bilinear, tileable.
    gx, gy = x // 4, y // 4
    fx, fy = (x % 4) / 4.0, (y % 4) / 4.0
    n = N // 4

    def g(i, j):
        return unit(7, i % n, j % n)
    a = g(gx, gy) * (1 - fx) + g(gx + 1, gy) * fx
    b = g(gx, gy + 1) * (1 - fx) + g(gx + 1, gy + 1) * fx
    return a * (1 - fy) + b * fy


def brick_at(x, y):
    row = y // BH
    shift = (BW // 2) * (row % 2)
    xs = (x + shift) % N
    col = xs // BW
    # Distance in texels to the nearest joint centre line.
    dx = min(xs % BW, BW - xs % BW)
    dy = min(y % BH, BH - y % BH)
    return row, col, min(dx, dy)


def smoothstep(e0, e1, v):
    t = min(max((v - e0) / (e1 - e0), 0.0), 1.0)
    return t * t * (3 - 2 * t)


def png(path, width, height, channels, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    colour_type = {1: 0, 3: 2}[channels]

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(raw, 9)))
        f.write(chunk(b"IEND", b""))


def main(out):
    depth_rows, colour_rows = [], []
    for y in range(N):
        d_row, c_row = [], []
        for x in range(N):
            row, col, edge = brick_at(x, y)
            g = grain(x, y)
            # 0 in the joint, 1 on the face past the bevel.
            face = smoothstep(JOINT / 2, JOINT / 2 + BEVEL, edge)
            depth = 1.0 - face * (0.9 - 0.12 * g - 0.06 * unit(3, row, col))
            d_row.append(min(255, max(0, int(round(depth * 255)))))
            tone = unit(5, row, col)
            brick = (0.55 + 0.2 * tone + 0.15 * g, 0.25 + 0.1 * tone + 0.1 * g, 0.18 + 0.06 * tone + 0.08 * g)
            joint = (0.62 + 0.1 * g, 0.6 + 0.1 * g, 0.56 + 0.1 * g)
            c = [j * (1 - face) + b * face for j, b in zip(joint, brick)]
            c_row.extend(min(255, max(0, int(round(v * 255)))) for v in c)
        depth_rows.append(d_row)
        colour_rows.append(c_row)
    png(f"{out}/bricks-512-depth.png", N, N, 1, depth_rows)
    png(f"{out}/bricks-512-colour.png", N, N, 3, colour_rows)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "scenes/textures")
