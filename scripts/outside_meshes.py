#!/usr/bin/env python3
"""Writes the meshes of PERFORMANCE.md's "Meshes outside the bench" as OBJ files.

usage: python3 scripts/outside_meshes.py OUT_DIR [ASSETS_DIR]

- terrain.obj: a 700 x 700 height field of sines over [-10, 10]^2, two triangles a cell
  (980,000 triangles): a large, smooth, evenly tessellated surface.
- sticks.obj: 60,000 long thin triangles (2 to 8 units long, 0.02 wide, in random directions,
  both ends in a 10-unit cube), stored in random order: every triangle crosses many
  nodes, the worst case for spatial splits and for the build's partition.
- bunny_shuffled.obj: the assets' Stanford bunny (ASSETS_DIR/bunny/bun_zipper.ply, default
  ../shared/assets) with its triangles in random order.

The meshes depend only on this script and the bunny (fixed seeds): every run writes the same
files.
"""

import math
import os
import random
import sys


def write_obj(path, vertices, faces):
    """vertices: (x, y, z) tuples; faces: 0-based index triples. Written whole or not at all."""
    partial = path + ".partial"
    with open(partial, "w", encoding="ascii") as out:
        out.writelines(f"v {x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in vertices)
        out.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    os.replace(partial, path)


def terrain(cells=700, half=10.0):
    step = 2.0 * half / cells
    vertices = []
    for j in range(cells + 1):
        z = -half + j * step
        for i in range(cells + 1):
            x = -half + i * step
            y = (0.6 * math.sin(0.7 * x) * math.cos(0.5 * z)
                 + 0.25 * math.sin(2.3 * x + 1.7 * z)
                 + 0.1 * math.sin(5.1 * z - 3.7 * x))
            vertices.append((x, y, z))
    faces = []
    row = cells + 1
    for j in range(cells):
        for i in range(cells):
            a = j * row + i
            faces.append((a, a + row, a + 1))
            faces.append((a + 1, a + row, a + row + 1))
    return vertices, faces


def sticks(count=60000, seed=1):
    rng = random.Random(seed)
    vertices, faces = [], []
    while len(faces) < count:
        d = [rng.gauss(0.0, 1.0) for _ in range(3)]
        norm = math.sqrt(sum(c * c for c in d)) or 1.0
        d = [c / norm for c in d]
        length = rng.uniform(2.0, 8.0)
        a = [rng.uniform(-5.0, 5.0) for _ in range(3)]
        b = [a[k] + length * d[k] for k in range(3)]
        if any(abs(c) > 5.0 for c in b):
            continue  # both ends in the cube
        # A unit vector across the stick: d crossed with the axis it is least along.
        axis = min(range(3), key=lambda k: abs(d[k]))
        e = [0.0, 0.0, 0.0]
        e[axis] = 1.0
        w = [d[1] * e[2] - d[2] * e[1], d[2] * e[0] - d[0] * e[2], d[0] * e[1] - d[1] * e[0]]
        wn = math.sqrt(sum(c * c for c in w))
        c = [0.5 * (a[k] + b[k]) + 0.02 * w[k] / wn for k in range(3)]
        n = len(vertices)
        vertices += [tuple(a), tuple(b), tuple(c)]
        faces.append((n, n + 1, n + 2))
    return vertices, faces


def read_ascii_ply(path):
    with open(path, encoding="ascii") as f:
        header = []
        for line in f:
            header.append(line.split())
            if line.strip() == "end_header":
                break
        counts = {h[1]: int(h[2]) for h in header if h[0] == "element"}
        vertices = []
        for _ in range(counts["vertex"]):
            x, y, z = f.readline().split()[:3]
            vertices.append((float(x), float(y), float(z)))
        faces = []
        for _ in range(counts["face"]):
            fields = f.readline().split()
            corners = [int(v) for v in fields[1:1 + int(fields[0])]]
            faces += [(corners[0], corners[k], corners[k + 1]) for k in range(1, len(corners) - 1)]
    return vertices, faces


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: outside_meshes.py OUT_DIR [ASSETS_DIR]")
    out_dir = sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    default_assets = os.path.join(here, "..", "..", "shared", "assets")
    assets = sys.argv[2] if len(sys.argv) == 3 else default_assets
    try:
        vertices, faces = read_ascii_ply(os.path.join(assets, "bunny", "bun_zipper.ply"))
        random.Random(2).shuffle(faces)
        os.makedirs(out_dir, exist_ok=True)
        write_obj(os.path.join(out_dir, "bunny_shuffled.obj"), vertices, faces)
        write_obj(os.path.join(out_dir, "terrain.obj"), *terrain())
        write_obj(os.path.join(out_dir, "sticks.obj"), *sticks())
    except (OSError, ValueError, KeyError, IndexError) as error:
        sys.exit(f"outside_meshes.py: {error}")

if __name__ == "__main__":
    main()
