"""The path integrator in the real window: "the lab's N for this scene" (the N key sets the
constant N to the path-traced picture's mean N, which raylab-render's indirect view confirms)."""

import struct

from e2e_support import Viewer, check

SIZE = ["--width", "200", "--height", "200"]  # square: every ray of the lab's camera hits the box


def read_pfm(path):
    """(width, height, rows of (r, g, b)) of a little-endian colour PFM, top row first."""
    with open(path, "rb") as f:
        data = f.read()
    header, rest = data.split(b"\n", 1)
    check(header == b"PF", f"{path}: not a colour PFM")
    size, rest = rest.split(b"\n", 1)
    scale, rest = rest.split(b"\n", 1)
    width, height = (int(v) for v in size.split())
    check(float(scale) < 0, f"{path}: not little-endian")
    values = struct.unpack(f"<{3 * width * height}f", rest[:12 * width * height])
    rows = [[values[3 * (y * width + x):3 * (y * width + x) + 3] for x in range(width)]
            for y in range(height)]
    return width, height, rows[::-1]


def test_mean_n(env):
    """With the path integrator at its sample cap, N makes the lab's constant the picture's mean
    N; the screenshot's settings hold it, and it equals the mean of raylab-render's indirect view
    of the same settings (the same estimates: every pixel's N of every sample)."""
    flags = SIZE + ["--integrator", "path", "--spp", "8"]
    viewer = Viewer(env, flags)
    try:
        viewer.shot_when(lambda png, s: s["image"]["samples"] == 8, "no picture at the cap")
        png, settings = viewer.key_shot("n")
        viewer.quit()
    finally:
        viewer.kill()
    indirect = settings["indirect"]
    check(indirect["enabled"], "N did not turn the indirect term on")
    n = [c * indirect["intensity"] for c in indirect["color"]]
    check(max(n) < 0.45, f"the mean N {n} is still the lab's 0.5")

    env.run_ok(env.render, flags + ["--view", "indirect", "-o", "n.pfm"])
    width, height, rows = read_pfm(env.path("n.pfm"))
    for c in range(3):
        mean = sum(row[x][c] for row in rows for x in range(width)) / (width * height)
        check(abs(mean - n[c]) <= 1e-3 * max(mean, 1e-3),
              f"channel {c}: the viewer's N {n[c]} but the indirect view's mean is {mean}")
