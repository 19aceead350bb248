#!/usr/bin/env python3
"""Writes the built-in scenes/triangles-*.json (the plain interpolating kind).

Each scene aims at one rasterization rule that the CPU pipeline must share
with llvmpipe. The files are committed; rerun this after editing it.
Deterministic: a fixed-seed generator, no wall-clock input.
"""
import json
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "scenes")


def write(name, scene):
    path = os.path.join(OUT, name + ".json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


def colour(rng):
    return [round(rng.random(), 6) for _ in range(3)] + [1.0]


def main():
    rng = random.Random(20261125)

    write("triangles-basic", {
        "kind": "triangles",
        "description": "Two triangles with per-vertex colours at arbitrary sub-pixel positions.",
        "width": 64, "height": 64, "coordinates": "pixels",
        "triangles": [
            {"positions": [[4.3, 5.1], [58.7, 9.9], [20.2, 60.6]],
             "colours": [[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]]},
            {"positions": [[40, 40], [63, 62], [30, 63]], "colour": [0.25, 0.5, 0.75, 1]},
        ],
    })

    # A jittered grid of shared vertices: every interior edge is shared by two
    # triangles. Additive blending (GL_ONE, GL_SRC_ALPHA with alpha 1 adds the
    # destination) makes a pixel covered twice come out brighter.
    n, size = 8, 128
    verts = [[[(i + (rng.random() - 0.5) * 0.8 * (0 < i < n)) * size / n,
               (j + (rng.random() - 0.5) * 0.8 * (0 < j < n)) * size / n] for i in range(n + 1)]
             for j in range(n + 1)]
    tris = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = verts[j][i], verts[j][i + 1], verts[j + 1][i + 1], verts[j + 1][i]
            for t in ([a, b, c], [a, c, d]) if (i + j) % 2 else ([a, b, d], [b, c, d]):
                tris.append({"positions": [[round(x, 4), round(y, 4)] for x, y in t],
                             "colour": [0.25, 0.25, 0.25, 1.0]})
    write("triangles-shared-edges", {
        "kind": "triangles",
        "description": "A jittered 8x8 grid of shared edges drawn additively: double coverage shows as 0.5, a gap as 0.",
        "width": size, "height": size, "coordinates": "pixels", "blend": "one_src_alpha",
        "triangles": tris,
    })

    # Vertices exactly on pixel centres (k + 0.5): edges run through centres,
    # so the fill rule alone decides.
    tris = []
    for k in range(12):
        x0, y0 = 2 + (k % 4) * 15, 2 + (k // 4) * 20
        pts = [[x0 + 0.5, y0 + 0.5], [x0 + 12.5, y0 + 0.5 + (k % 3)], [x0 + 0.5 + (k % 5), y0 + 16.5]]
        if k % 2:
            pts = [pts[0], pts[2], pts[1]]  # clockwise half of them
        tris.append({"positions": pts, "colours": [colour(rng) for _ in range(3)]})
    write("triangles-pixel-centres", {
        "kind": "triangles",
        "description": "Vertices on pixel centres, edges through centres, both windings.",
        "width": 64, "height": 64, "coordinates": "pixels", "triangles": tris,
    })

    # Integer and half-pixel vertex positions, and offsets of exactly half a
    # sub-pixel step (1/512) where the snap's round-half-to-even decides.
    tris = []
    for k in range(16):
        x0, y0 = (k % 4) * 16 + 1, (k // 4) * 16 + 1
        e = (k % 4) / 512.0
        pts = [[x0 + e, y0 + 0.5], [x0 + 13 + 0.5, y0 + e * 3], [x0 + 6 - e, y0 + 14 + 0.5 + e]]
        tris.append({"positions": pts, "colours": [colour(rng) for _ in range(3)]})
    write("triangles-half-pixel", {
        "kind": "triangles",
        "description": "Integer, half-pixel and half-sub-pixel (1/512) vertex positions.",
        "width": 64, "height": 64, "coordinates": "pixels", "triangles": tris,
    })

    # Slivers: long, thin triangles, many narrower than a pixel.
    tris = []
    for k in range(24):
        ang = k * math.pi / 24 + 0.01
        cx, cy = 64 + 3.3 * math.cos(ang * 7), 64 + 3.1 * math.sin(ang * 5)
        dx, dy = math.cos(ang) * 60, math.sin(ang) * 60
        w = 0.05 + 0.1 * (k % 6)
        px, py = -math.sin(ang) * w, math.cos(ang) * w
        pts = [[cx - dx, cy - dy], [cx + dx, cy + dy], [cx + dx * 0.3 + px, cy + dy * 0.3 + py]]
        tris.append({"positions": [[round(x, 5), round(y, 5)] for x, y in pts],
                     "colours": [colour(rng) for _ in range(3)]})
    write("triangles-slivers", {
        "kind": "triangles",
        "description": "24 slivers through the centre, 0.05 to 0.55 pixels wide, drawn additively.",
        "width": 128, "height": 128, "coordinates": "pixels", "blend": "one_src_alpha",
        "triangles": tris,
    })

    # Larger than the screen, in clip space, with w != 1 (perspective-correct
    # colours), inside llvmpipe's guard band so nothing is clipped in x/y.
    write("triangles-large", {
        "kind": "triangles",
        "description": "Triangles reaching far beyond the target, with per-vertex w from 0.3 to 11.5.",
        "width": 96, "height": 80, "coordinates": "clip",
        "triangles": [
            {"positions": [[-30, -20, 0, 1], [25, -3, 0.2, 1], [-2, 40, -0.5, 1]],
             "colours": [[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]]},
            {"positions": [[-3.3, -2.1, 0.1, 3], [80.5, 5.75, 1.0, 11.5], [0.6, 0.9, 0.1, 0.3]],
             "colours": [[1, 1, 0, 0.5], [0, 1, 1, 1], [1, 0, 1, 0.25]]},
        ],
        "blend": "alpha",
    })

    # Overlapping triangles with the depth test on, in an order where a later
    # triangle is hidden in part.
    tris = []
    for k in range(10):
        cx, cy = 20 + rng.random() * 60, 20 + rng.random() * 60
        r = 15 + rng.random() * 20
        pts = []
        for v in range(3):
            a = rng.random() * 2 * math.pi
            pts.append([round(cx + r * math.cos(a), 4), round(cy + r * math.sin(a), 4),
                        round(rng.random(), 4)])
        tris.append({"positions": pts, "colours": [colour(rng) for _ in range(3)]})
    write("triangles-depth", {
        "kind": "triangles",
        "description": "Ten overlapping triangles with sloped depth, GL_LESS depth test.",
        "width": 100, "height": 100, "coordinates": "pixels", "depth_test": True,
        "clear_colour": [0.1, 0.1, 0.1, 1], "triangles": tris,
    })

    # Alpha blending of translucent triangles over each other.
    tris = []
    for k in range(8):
        cx, cy = 10 + rng.random() * 44, 10 + rng.random() * 44
        pts = [[round(cx + 20 * math.cos(a), 4), round(cy + 20 * math.sin(a), 4)]
               for a in (k, k + 2.1, k + 4.2)]
        tris.append({"positions": pts,
                     "colours": [colour(rng)[:3] + [round(rng.random(), 4)] for _ in range(3)]})
    write("triangles-alpha-blend", {
        "kind": "triangles",
        "description": "Translucent triangles with ordinary alpha blending over a grey clear colour.",
        "width": 64, "height": 64, "coordinates": "pixels", "blend": "alpha",
        "clear_colour": [0.5, 0.5, 0.5, 1], "triangles": tris,
    })

    # A size that is no multiple of the tile or quad size.
    tris = []
    for k in range(20):
        pts = [[round(rng.uniform(-10, 107), 3), round(rng.uniform(-10, 71), 3)] for _ in range(3)]
        tris.append({"positions": pts, "colours": [colour(rng) for _ in range(3)]})
    write("triangles-odd-size", {
        "kind": "triangles",
        "description": "97x61 target (partial tiles and quads), triangles crossing its borders.",
        "width": 97, "height": 61, "coordinates": "pixels", "triangles": tris,
    })

    # Triangles crossing the near and far planes: clipped geometrically.
    write("triangles-near-far", {
        "kind": "triangles",
        "description": "Triangles crossing the near and the far plane (clipped), perspective w.",
        "width": 64, "height": 64, "coordinates": "clip",
        "triangles": [
            {"positions": [[-0.8, -0.8, -1.5, 1], [0.9, -0.6, 0.5, 1], [0.1, 0.9, 0.2, 1]],
             "colours": [[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 1, 1]]},
            {"positions": [[-1.2, 0.5, 1.9, 2], [1.5, 1.2, 2.5, 1.5], [0.3, -1.4, 0.1, 1.2]],
             "colours": [[1, 1, 0, 1], [0, 1, 1, 1], [1, 0, 1, 1]]},
        ],
    })

    # Textured triangles: bilinear and nearest filtering, repeat and clamp
    # wrapping, float and 8-bit texels, magnified and minified, with texture
    # coordinates beyond [0, 1].
    for fmt in ("rgba32f", "rgba8"):
        for filt in ("linear", "nearest"):
            tris = []
            for k, wrap_uv in enumerate((1.0, 3.7)):
                x0 = 2 + k * 48
                tris.append({"positions": [[x0, 2], [x0 + 44, 5], [x0 + 5, 60]],
                             "colours": [[1, 1, 1, 1], [1, 1, 1, 1], [1, 1, 1, 1]],
                             "uvs": [[-0.3, -0.2], [wrap_uv, 0.1], [0.2, wrap_uv]]})
                tris.append({"positions": [[x0 + 44, 5], [x0 + 47, 62], [x0 + 5, 60]],
                             "colours": [[1, 0.5, 1, 1], [0.5, 1, 1, 1], [1, 1, 0.5, 1]],
                             "uvs": [[wrap_uv, 0.1], [wrap_uv * 0.9, wrap_uv * 1.1], [0.2, wrap_uv]]})
            # Power-of-two and other sizes take different wrap code in llvmpipe.
            for (tw, th), size_name in (((13, 9), "npot"), ((16, 8), "pot")):
                for wrap in ("repeat", "clamp"):
                    write(f"triangles-texture-{fmt}-{filt}-{wrap}-{size_name}", {
                        "kind": "triangles",
                        "description": f"Two quads sampling a {tw}x{th} {fmt} noise texture, {filt} filter, {wrap} wrap, magnified and minified.",
                        "width": 100, "height": 64, "coordinates": "pixels",
                        "texture": {"format": fmt, "filter": filt, "wrap": wrap, "width": tw, "height": th,
                                    "pattern": "noise", "seed": 7},
                        "triangles": tris,
                    })


if __name__ == "__main__":
    main()
