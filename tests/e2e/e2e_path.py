"""The path integrator in the real window: "the lab's N for this scene" (the N key sets the
constant N to the path-traced picture's mean N, which raylab-render's indirect view confirms)."""

import json
import os
import struct
import time

from e2e_support import PANEL_COLUMN, Viewer, check, same_pixels
from pngread import read_png

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

    # F12 wrote the linear picture beside the PNG: raylab-render with the screenshot's settings
    # measures it as exactly its own picture (relative RMSE 0 at the last sample).
    shot = viewer.screenshots()[-1]
    exr = shot[:-4] + ".exr"
    check(os.path.exists(exr), f"no linear picture beside {shot}")
    lines = env.run_ok(env.render, ["--settings", shot[:-4] + ".json", "--reference", exr,
                                    "-o", "again.pfm"]).stdout.strip().splitlines()
    check(lines and "relative RMSE 0.000000" in lines[-1],
          f"the .exr beside the screenshot is not its picture: {lines[-1:]}")

    env.run_ok(env.render, flags + ["--view", "indirect", "-o", "n.pfm"])
    width, height, rows = read_pfm(env.path("n.pfm"))
    for c in range(3):
        mean = sum(row[x][c] for row in rows for x in range(width)) / (width * height)
        check(abs(mean - n[c]) <= 1e-3 * max(mean, 1e-3),
              f"channel {c}: the viewer's N {n[c]} but the indirect view's mean is {mean}")


def test_split(env):
    """The A/B split: left of the divider the lab's integrator, right of it the path tracer, each
    converging on its own; the screenshot records both sides, and raylab-render reproduces each
    side's columns from that side's settings file, pixel for pixel."""
    env.run_ok(env.raylab, ["--width", "240", "--height", "180", "--spp", "4", "--split", "0.4",
                            "--no-panel", "--frames", "5", "--screenshot", "s.png"])
    left_settings = json.load(open(env.path("s.json")))
    right_settings = json.load(open(env.path("s-right.json")))
    check(left_settings["integrator"]["kind"] == "lab", "the left side is not the lab's")
    check(right_settings["integrator"]["kind"] == "path", "the right side is not path traced")
    check(left_settings["split"] == {"divider": 0.4, "side": "left", "other": "s-right.json"},
          f"left split record {left_settings['split']}")
    check(right_settings["split"]["other"] == "s.json", "the right side does not name the left")
    env.run_ok(env.render, ["--settings", "s.json", "-o", "left.png"])
    env.run_ok(env.render, ["--settings", "s-right.json", "-o", "right.png"])
    shot, left, right = (read_png(env.path(n)) for n in ("s.png", "left.png", "right.png"))
    column = round(0.4 * shot.width)
    differ = 0
    for y in range(shot.height):
        for x in range(shot.width):
            side = left if x < column else right
            if shot.pixel(x, y) != side.pixel(x, y):
                check(False, f"pixel ({x}, {y}) of the split is {shot.pixel(x, y)}, its side "
                      f"renders {side.pixel(x, y)}")
            differ += left.pixel(x, y) != right.pixel(x, y)
    # The two integrators differ (the path tracer's shadows and walls are not the constant's).
    check(differ > shot.width * shot.height // 2,
          f"only {differ} pixels differ between the lab's and the path tracer's pictures")

    # In a real window: B turns the split off, and the screenshot is then the lab's alone.
    viewer = Viewer(env, ["--width", "240", "--height", "180", "--spp", "2", "--split", "0.5"])
    try:
        png, settings = viewer.key_shot()
        check("split" in settings, "the split's screenshot has no split record")
        viewer.xdotool("key", "b")
        png, settings = viewer.shot_when(lambda p, s: "split" not in s, "B did not end the split")
        viewer.quit()
    finally:
        viewer.kill()


def test_inspect(env):
    """Ctrl+click looks inside a pixel: the viewer prints the pixel's equation as raylab-render
    --inspect does (the same numbers), and shows it in its panel; V steps through the views of
    one term, Shift+V back."""
    size = ["--width", "480", "--height", "360"]
    viewer = Viewer(env, size + ["--spp", "2"])
    try:
        # The picture's pixel (390, 200), right of the panel's column.
        viewer.xdotool("mousemove", "--window", viewer.window, str(PANEL_COLUMN + 390), "200")
        viewer.xdotool("keydown", "ctrl", "click", "1", "keyup", "ctrl")
        _, settings = viewer.key_shot("v")
        check(settings["display"]["view"] == "albedo", f"V gave the view {settings['display']}")
        _, settings = viewer.key_shot("shift+v")
        check(settings["display"]["view"] == "beauty", f"Shift+V gave {settings['display']}")
        viewer.quit()
    finally:
        viewer.kill()
    lines = [line for line in viewer.output().splitlines() if line.startswith("{")]
    check(len(lines) == 1, f"expected one inspection printed, got {lines}")
    seen = json.loads(lines[0])
    check(seen["pixel"] == [390, 200], f"inspected pixel {seen['pixel']}")
    result = env.run_ok(env.render, size + ["--inspect", "390,200"])
    expected = json.loads(result.stdout)
    check(seen == expected, f"the viewer's inspection {seen} differs from raylab-render's "
          f"{expected}")
    check(seen["hit"], "the inspected pixel misses the box")


def test_snapshot(env):
    """K keeps the settings as A and splits the picture, live on the left, A on the right; a change
    after it shows on the left only, and the screenshot's two files record both."""
    viewer = Viewer(env, ["--width", "240", "--height", "180", "--spp", "2"])
    try:
        viewer.xdotool("key", "k")
        _, settings = viewer.key_shot("w")  # the light forward, after A was kept
        viewer.quit()
    finally:
        viewer.kill()
    shot = viewer.screenshots()[-1]
    left = json.load(open(shot[:-4] + ".json"))
    right = json.load(open(shot[:-4] + "-right.json"))
    check(left["split"]["side"] == "left" and right["split"]["side"] == "right",
          "the snapshot's screenshot is not a split")
    check(right["light"]["position"] == [0, 0.5, -0.7],
          f"A's light moved: {right['light']['position']}")
    check(left["light"]["position"] != right["light"]["position"],
          "the live side's light did not move")
    check(left["integrator"] == right["integrator"], "A compares another integrator")


def test_undo(env):
    """Ctrl+Z undoes a change once it has settled, Ctrl+Shift+Z (or Ctrl+Y) redoes it."""
    viewer = Viewer(env, ["--width", "240", "--height", "180", "--spp", "2"])
    try:
        _, moved = viewer.key_shot("w")
        start = [0, 0.5, -0.7]
        check(moved["light"]["position"] != start, "W did not move the light")
        time.sleep(0.8)  # the change settles into a step
        _, undone = viewer.key_shot("ctrl+z")
        check(undone["light"]["position"] == start,
              f"Ctrl+Z left the light at {undone['light']['position']}")
        _, redone = viewer.key_shot("ctrl+shift+z")
        check(redone["light"]["position"] == moved["light"]["position"],
              f"Ctrl+Shift+Z put the light at {redone['light']['position']}")
        _, again = viewer.key_shot("ctrl+z")
        _, redone = viewer.key_shot("ctrl+y")
        check(again["light"]["position"] == start and
              redone["light"]["position"] == moved["light"]["position"], "Ctrl+Y did not redo")
        viewer.quit()
    finally:
        viewer.kill()


def test_orbit(env):
    """A right drag orbits about the point under the cursor (the distance to it is kept, the camera
    turns to keep looking at it); a middle drag pans (the camera moves, its direction stays)."""
    size = ["--width", "480", "--height", "360"]
    pivot = json.loads(env.run_ok(env.render, size + ["--inspect", "390,200"]).stdout)["point"]
    viewer = Viewer(env, size + ["--spp", "2"])
    try:
        w = viewer.window
        x = PANEL_COLUMN  # the picture's left edge in the window
        viewer.xdotool("mousemove", "--window", w, str(x + 390), "200", "mousedown", "3")
        time.sleep(0.2)
        viewer.xdotool("mousemove", "--window", w, str(x + 430), "180")
        time.sleep(0.2)
        viewer.xdotool("mouseup", "3")
        time.sleep(0.3)
        _, orbited = viewer.key_shot()
        viewer.xdotool("mousemove", "--window", w, str(x + 400), "200", "mousedown", "2")
        time.sleep(0.2)
        viewer.xdotool("mousemove", "--window", w, str(x + 420), "220")
        time.sleep(0.2)
        viewer.xdotool("mouseup", "2")
        time.sleep(0.3)
        _, panned = viewer.key_shot()
        viewer.quit()
    finally:
        viewer.kill()
    start = [0, 0, -3]
    position = orbited["camera"]["position"]
    check(position != start, "the right drag did not move the camera")

    def distance(a, b):
        return sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5

    check(abs(distance(position, pivot) - distance(start, pivot)) < 1e-3,
          f"the orbit changed the distance to the pivot {pivot}: {distance(start, pivot)} -> "
          f"{distance(position, pivot)}")
    check(orbited["camera"]["yaw"] != 0, "the orbit did not turn the camera")
    check(panned["camera"]["position"] != position, "the middle drag did not pan")
    check((panned["camera"]["yaw"], panned["camera"]["pitch"]) ==
          (orbited["camera"]["yaw"], orbited["camera"]["pitch"]), "the pan turned the camera")


def test_bookmarks(env):
    """Ctrl+1 keeps the camera in slot 1 and 1 returns to it; the screenshot's settings keep the
    bookmarks, and a viewer started with those settings has them."""
    viewer = Viewer(env, ["--width", "240", "--height", "180", "--spp", "2"])
    try:
        viewer.xdotool("key", "--delay", "80", "ctrl+1")
        _, moved = viewer.key_shot("Up", "Up")
        check(moved["camera"]["position"] != [0, 0, -3], "Up did not move the camera")
        _, back = viewer.key_shot("1")
        check(back["camera"]["position"] == [0, 0, -3],
              f"1 did not return to the bookmark: {back['camera']['position']}")
        check(back["bookmarks"][0]["position"] == [0, 0, -3] and back["bookmarks"][1] is None,
              f"the screenshot's bookmarks: {back.get('bookmarks')}")
        viewer.quit()
    finally:
        viewer.kill()
    saved = viewer.screenshots()[-1][:-4] + ".json"
    viewer = Viewer(env, ["--settings", saved, "--spp", "2"])
    try:
        viewer.key_shot("Up", "Up")
        _, back = viewer.key_shot("1")
        check(back["camera"]["position"] == [0, 0, -3], "the loaded bookmark did not work")
        viewer.quit()
    finally:
        viewer.kill()


def test_drop(env):
    """Dropping a raylab screenshot (its PNG or its JSON) restores its scene, settings and size
    exactly; dropping a mesh opens it; a PNG that is no raylab screenshot is refused in the panel
    and the viewer goes on (drops driven by --drop, which feeds the window's drop handling)."""
    env.run_ok(env.raylab, ["--width", "200", "--height", "150", "--yaw", "10", "--light-power",
                            "9", "--spp", "2", "--no-panel", "--frames", "5", "--screenshot",
                            "a.png"])
    original = json.load(open(env.path("a.json")))
    for dropped in ("a.png", "a.json"):
        shot = f"b-{dropped}.png"
        env.run_ok(env.raylab, ["--width", "320", "--height", "240", "--spp", "2", "--no-panel",
                                "--drop", env.path(dropped), "--frames", "30", "--screenshot",
                                shot])
        restored = json.load(open(env.path(shot[:-4] + ".json")))
        for part in ("camera", "light", "image", "indirect", "shadows"):
            check(restored[part] == original[part],
                  f"dropping {dropped}: {part} {restored[part]} != {original[part]}")
        same_pixels(read_png(env.path("a.png")), read_png(env.path(shot)),
                    f"the picture restored from {dropped}")
    with open(env.path("tri.obj"), "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    env.run_ok(env.raylab, ["--width", "160", "--height", "120", "--spp", "1", "--no-panel",
                            "--drop", env.path("tri.obj"), "--frames", "30", "--screenshot",
                            "c.png"])
    opened = json.load(open(env.path("c.json")))
    check(opened["scene"] == env.path("tri.obj"), f"the dropped mesh was not opened: {opened}")
    with open(env.path("plain.png"), "wb") as f:
        f.write(open(env.path("a.png"), "rb").read()[:8] + b"garbage")
    result = env.run(env.raylab, ["--width", "160", "--height", "120", "--spp", "1", "--no-panel",
                                  "--drop", env.path("plain.png"), "--frames", "20",
                                  "--screenshot", "d.png"])
    check(result.returncode == 0, f"a bad drop ended the viewer: {result.stderr}")
    check("plain.png" in result.stderr, f"no message about the bad drop: {result.stderr}")
    check(json.load(open(env.path("d.json")))["scene"] == "cornell", "a bad drop changed the scene")
