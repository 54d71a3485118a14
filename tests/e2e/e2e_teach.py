"""The viewer as a teaching instrument, in the real window: the inspected pixel's rays drawn over
the picture (never into it), the pixel under the cursor and a rectangle's mean, and the compare's
signed difference."""

import json
import math
import struct
import time

from e2e_path import read_pfm
from e2e_support import Failure, Viewer, check, same_pixels
from pngread import read_png

STEP = 0.1  # core's navigationStep for the lab's box: one Up moves the camera this far along +z
LAB_CAMERA = (0.0, 0.0, -3.0)
SHADOW_CLEAR = (255, 255, 0)  # ray_overlay_geometry.h's overlayColour
SHADOW_BLOCKED = (255, 0, 0)
CAMERA_RAY = (0, 255, 0)
PATH = (255, 0, 255)
FOREVER = ["--frames", "1000000"]  # --readback needs --frames; Escape ends the run before


def project(point, camera, width, height):
    """Where the lab's camera (yaw = pitch = 0, focal length = height) at `camera` sees `point`:
    (x, y) in pixels, y down, and the depth. Its right axis is -x, up +y, forward +z."""
    cx = -(point[0] - camera[0])
    cy = point[1] - camera[1]
    cz = point[2] - camera[2]
    return (width / 2 + height * cx / cz, height / 2 - height * cy / cz), cz


def lerp(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


def has_colour_near(png, x, y, colour, reach=2):
    for dy in range(-reach, reach + 1):
        for dx in range(-reach, reach + 1):
            px, py = round(x) + dx, round(y) + dy
            if 0 <= px < png.width and 0 <= py < png.height and png.pixel(px, py)[:3] == colour:
                return True
    return False


def count_colour(png, colour):
    return sum(1 for i in range(0, len(png.rgba), 4) if tuple(png.rgba[i:i + 3]) == colour)


def inspect_with_render(env, flags, pixel):
    """raylab-render --inspect's JSON of `pixel`."""
    result = env.run_ok(env.render, flags + ["--inspect", f"{pixel[0]},{pixel[1]}"])
    return json.loads(result.stdout)


def inspect_in_window(env, flags, readback, pixel):
    """A viewer with `flags` whose picture reached 2 samples, after a Ctrl+click on `pixel`; its
    window is read back to `readback` when it quits."""
    viewer = Viewer(env, flags + ["--no-panel", "--readback", readback] + FOREVER)
    try:
        viewer.shot_when(lambda png, s: s["image"]["samples"] == 2, "no picture at the cap")
        viewer.xdotool("mousemove", "--window", viewer.window, str(pixel[0]), str(pixel[1]))
        viewer.xdotool("keydown", "ctrl", "click", "1", "keyup", "ctrl")
        time.sleep(0.5)
    except Failure:
        viewer.kill()
        raise
    return viewer


def test_ray_overlay(env):
    """Ctrl+click draws the pixel's rays over the picture: the shadow ray from the hit towards
    the light (yellow, or red up to its blocker when blocked), not in the screenshot (which is
    still raylab-render's picture). The rays stay where they are in the world: after the camera
    moves forward, the window shows the shadow ray and the camera ray (green, from where the
    camera was) where the moved camera projects them. With the path tracer the inspected path's
    surfaces are joined by magenta lines."""
    width, height = 480, 360
    pixel = (241, 343)  # a floor pixel that sees the light
    size = ["--width", str(width), "--height", str(height), "--spp", "2"]
    seen = inspect_with_render(env, size, pixel)
    check(seen["hit"], f"pixel {pixel} misses the box")
    env.run_ok(env.render, size + ["-o", "expected.png"])
    viewer = inspect_in_window(env, size, "back.png", pixel)
    try:
        shot, _ = viewer.key_shot()
        same_pixels(shot, read_png(env.path("expected.png")),
                    "the screenshot with the rays drawn vs raylab-render")
        viewer.xdotool("key", "Up")
        viewer.shot_when(lambda png, s: s["camera"]["position"][2] > -2.95,
                         "Up did not move the camera")
        time.sleep(0.5)
        viewer.quit()
    finally:
        viewer.kill()
    back = read_png(env.path("back.png"))
    camera = (0.0, 0.0, -3.0 + STEP)
    point = seen["point"]
    if seen["shadowed"]:
        r = seen["to_light"]
        length = math.sqrt(sum(c * c for c in r))
        end = [p + c / length * seen["blocker"]["t"] for p, c in zip(point, r)]
        colour = SHADOW_BLOCKED
    else:
        end = [p + c for p, c in zip(point, seen["to_light"])]
        colour = SHADOW_CLEAR
    check(count_colour(back, colour) > 10, f"no {colour} line in the window")
    for t in (0.25, 0.5, 0.75):
        (x, y), _ = project(lerp(point, end, t), camera, width, height)
        check(has_colour_near(back, x, y, colour),
              f"the shadow ray's point at {t} of its length projects to ({x:.1f}, {y:.1f}) but "
              f"the window has no {colour} there")
    # The camera ray from the old camera position: its points in front of the moved camera.
    drawn = 0
    for t in (0.6, 0.7, 0.8, 0.9):
        (x, y), depth = project(lerp(LAB_CAMERA, point, t), camera, width, height)
        if depth > 0.05 and 0 <= x < width and 0 <= y < height:
            check(has_colour_near(back, x, y, CAMERA_RAY),
                  f"the camera ray's point at {t} projects to ({x:.1f}, {y:.1f}) but the window "
                  f"has no camera-ray colour there")
            drawn += 1
    check(drawn >= 2, "the moved camera sees too little of the camera ray to check it")

    # With the path tracer, the inspected path is drawn from surface to surface.
    pixel = (200, 200)
    flags = size + ["--integrator", "path"]
    seen = inspect_with_render(env, flags, pixel)
    path = [v["point"] for v in seen.get("path", [])]
    check(len(path) >= 3, f"pixel {pixel}'s path has only {len(path)} surfaces")
    viewer = inspect_in_window(env, flags, "path.png", pixel)
    try:
        viewer.quit()
    finally:
        viewer.kill()
    back = read_png(env.path("path.png"))
    for a, b in zip(path, path[1:]):
        for t in (0.3, 0.5, 0.7):
            (x, y), _ = project(lerp(a, b, t), LAB_CAMERA, width, height)
            if 0 <= x < width and 0 <= y < height:
                check(has_colour_near(back, x, y, PATH),
                      f"the path's point at {t} of {a} -> {b} projects to ({x:.1f}, {y:.1f}) but "
                      f"the window has no path colour there")


def test_hover_readout(env):
    """The pixel under the cursor and a Shift + drag rectangle: the viewer's --stats record the
    pixel's linear R (raylab-render's PFM value, exactly), its displayed bytes (raylab-render's
    PNG) and the rectangle's mean R (the PFM's mean over it)."""
    size = ["--width", "240", "--height", "180", "--spp", "4"]
    env.run_ok(env.render, size + ["-o", "expected.pfm"])
    env.run_ok(env.render, size + ["-o", "expected.png"])
    viewer = Viewer(env, size + ["--no-panel", "--stats", "stats.json"])
    w = viewer.window
    try:
        viewer.shot_when(lambda png, s: s["image"]["samples"] == 4, "no picture at the cap")
        viewer.xdotool("mousemove", "--window", w, "40", "30", "keydown", "shift", "mousedown",
                       "1")
        time.sleep(0.2)
        viewer.xdotool("mousemove", "--window", w, "60", "45")
        time.sleep(0.2)
        viewer.xdotool("mousemove", "--window", w, "80", "60")
        time.sleep(0.2)
        viewer.xdotool("mouseup", "1", "keyup", "shift")
        time.sleep(0.2)
        viewer.xdotool("mousemove", "--window", w, "150", "90")
        time.sleep(0.5)
        _, settings = viewer.key_shot()
        viewer.quit()
    finally:
        viewer.kill()
    check(settings["camera"]["yaw"] == 0 and settings["camera"]["pitch"] == 0,
          f"the Shift + drag turned the camera: {settings['camera']}")
    stats = json.load(open(env.path("stats.json")))
    check("hover" in stats and "rectangle" in stats, f"no readouts in --stats: {stats.keys()}")
    _, _, rows = read_pfm(env.path("expected.pfm"))
    png = read_png(env.path("expected.png"))
    hover = stats["hover"]
    check(hover["pixel"] == [150, 90], f"the pixel under the cursor is {hover['pixel']}")
    linear = [struct.unpack("<f", struct.pack("<f", v))[0] for v in rows[90][150]]
    check(hover["linear"] == linear, f"hover R {hover['linear']}, raylab-render's {linear}")
    check(hover["display"] == list(png.pixel(150, 90)[:3]),
          f"hover shows {hover['display']}, raylab-render's PNG {png.pixel(150, 90)[:3]}")
    rectangle = stats["rectangle"]
    check(rectangle["from"] == [40, 30] and rectangle["to"] == [80, 60],
          f"the rectangle is {rectangle['from']} - {rectangle['to']}")
    check(rectangle["pixels"] == 41 * 31, f"the rectangle has {rectangle['pixels']} pixels")
    for c in range(3):
        mean = sum(rows[y][x][c] for y in range(30, 61) for x in range(40, 81)) / (41 * 31)
        check(abs(rectangle["mean"][c] - mean) <= 1e-6 * max(abs(mean), 1e-6),
              f"channel {c}: the rectangle's mean {rectangle['mean'][c]}, the PFM's {mean}")


def difference_colour(d, scale):
    """difference_view.h's colour of the value d at scale."""
    t = max(-1.0, min(1.0, d / scale))
    level = math.floor(255 * abs(t) + 0.5)
    return (level, 0, 0) if t >= 0 else (0, 0, level)


def test_difference(env):
    """K keeps A, M shows the signed difference live - A: black everywhere while nothing
    differs; after the light moves, the screenshot (what the window shows, read back) is the
    colour scale of the difference of the two sides' raylab-render PFMs, with both colours."""
    size = ["--width", "160", "--height", "120", "--spp", "2"]
    viewer = Viewer(env, size + ["--no-panel", "--readback", "back.png"] + FOREVER)

    def difference_at_cap(png, settings):
        split = settings.get("split", {})
        return "difference" in split and settings["image"]["samples"] == 2

    try:
        viewer.shot_when(lambda png, s: s["image"]["samples"] == 2, "no picture at the cap")
        viewer.xdotool("key", "--delay", "80", "k", "m")
        same, settings = viewer.shot_when(difference_at_cap, "M did not show the difference")
        check(settings["split"]["difference"] == 0.1,
              f"the default scale is {settings['split']['difference']}")
        check(same.rgba == bytes([0, 0, 0, 255]) * (same.width * same.height),
              "live and A are the same but the difference is not black everywhere")
        viewer.xdotool("key", "w")
        shot, settings = viewer.shot_when(
            lambda png, s: difference_at_cap(png, s) and s["light"]["position"][2] > -0.65,
            "W did not move the light in the difference")
        time.sleep(0.5)
        viewer.quit()
    finally:
        viewer.kill()
    name = viewer.screenshots()[-1][:-4]
    right = json.load(open(name + "-right.json"))
    check(right["split"]["difference"] == 0.1 and right["image"]["samples"] == 2,
          f"A's record {right['split']}, samples {right['image']['samples']}")
    env.run_ok(env.render, ["--settings", name + ".json", "-o", "live.pfm"])
    env.run_ok(env.render, ["--settings", name + "-right.json", "-o", "a.pfm"])
    width, height, live = read_pfm(env.path("live.pfm"))
    _, _, a = read_pfm(env.path("a.pfm"))
    red = blue = 0
    for y in range(height):
        for x in range(width):
            d = sum(live[y][x][c] - a[y][x][c] for c in range(3)) / 3
            expected = difference_colour(d, 0.1)
            got = shot.pixel(x, y)[:3]
            if any(abs(g - e) > 1 for g, e in zip(got, expected)):
                raise Failure(f"pixel ({x}, {y}): live - A = {d}, shown {got}, expected "
                              f"{expected}")
            red += got[0] > 8
            blue += got[2] > 8
    check(red > 100 and blue > 100, f"the moved light gave {red} red and {blue} blue pixels")
    same_pixels(read_png(env.path("back.png")), shot, "the window vs the difference's screenshot")
