#!/usr/bin/env python3
"""End-to-end tests of the viewer `raylab`: the real binary in a real window, under Xvfb with
Mesa's software OpenGL (llvmpipe), driven with xdotool.

    viewer_e2e.py TEST --raylab PATH --render PATH

runs one test (see TESTS) and exits 0 when it passes, 1 when it fails, and 77 (ctest's skip code
here) when it needs a window and Xvfb is not installed. Tests that need a window run on an Xvfb
display of their own (e2e_display.py).
"""

import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from e2e_display import Display, DisplayError  # noqa: E402
from e2e_import import test_import_cancel, test_import_failures, test_import_quit  # noqa: E402
from pngread import read_png  # noqa: E402
from e2e_minimise import test_minimise  # noqa: E402
from e2e_observer import test_observer  # noqa: E402
from e2e_panel import test_panel, test_panel_edge, test_panel_scale  # noqa: E402
from e2e_record import test_record  # noqa: E402
from e2e_path import (test_bookmarks, test_drop, test_inspect, test_mean_n,  # noqa: E402
                      test_orbit, test_snapshot, test_split, test_undo)
from e2e_scene_path import test_browse, test_scene_path  # noqa: E402
from e2e_stats import test_idle, test_stats  # noqa: E402
from e2e_teach import test_difference, test_hover_readout, test_ray_overlay  # noqa: E402
from e2e_support import (PANEL_BUTTON, PANEL_COLUMN, Env, Failure, Viewer, check,  # noqa: E402
                         close, distinct_colours, same_pixels, vec)

SKIP = 77
STEP = 0.1  # core's navigationStep for the lab's box
TURN_DEGREES = 5.0  # the viewer's kTurnStepDegrees
HOLD_DELAY = 0.25  # the viewer's kHoldDelaySeconds: a held key moves smoothly from then on
HELD_STEPS_PER_SECOND = 25.0  # the viewer's kHeldStepsPerSecond


# --- tests without a window -----------------------------------------------------------------

def test_bad_input(env):
    """Unknown flag: one line, exit 2. Missing or broken scene: one line, exit 1. No files."""
    result = env.run(env.raylab, ["--no-such-flag"])
    check(result.returncode == 2, f"unknown flag: exit {result.returncode}, expected 2")
    check(len(result.stderr.strip().splitlines()) == 1,
          f"unknown flag: expected one line, got {result.stderr!r}")
    result = env.run(env.raylab, ["--fov", "nan", "--frames", "1"])
    check(result.returncode == 2, f"--fov nan: exit {result.returncode}, expected 2")
    result = env.run(env.raylab, ["--readback"])
    check(result.returncode == 2, f"--readback without file: exit {result.returncode}")
    for scale in (["nan"], ["inf"], ["0.4"], ["4.5"], ["2x"], []):
        result = env.run(env.raylab, ["--ui-scale"] + scale + ["--frames", "1"])
        check(result.returncode == 2 and len(result.stderr.strip().splitlines()) == 1 and
              "--ui-scale" in result.stderr,
              f"--ui-scale {scale}: exit {result.returncode}, {result.stderr!r}; expected one "
              f"line and exit 2")
    result = env.run(env.raylab, [env.path("missing.obj"), "--frames", "1"])
    check(result.returncode == 1, f"missing scene: exit {result.returncode}, expected 1")
    check(len(result.stderr.strip().splitlines()) == 1,
          f"missing scene: expected one line, got {result.stderr!r}")
    garbage = env.path("garbage.obj")
    with open(garbage, "wb") as f:
        f.write(bytes(range(256)) * 8)
    result = env.run(env.raylab, [garbage, "--frames", "1", "--screenshot", "x.png"])
    check(result.returncode == 1, f"garbage scene: exit {result.returncode}, expected 1")
    check(len(result.stderr.strip().splitlines()) == 1,
          f"garbage scene: expected one line, got {result.stderr!r}")
    check(not os.path.exists(env.path("x.png")), "a failed start left a screenshot behind")
    result = env.run(env.raylab, ["--help"])
    check(result.returncode == 0 and "--frames" in result.stdout and "--readback" in result.stdout,
          "--help does not list the viewer's options")


# --- tests in a window, scripted by --frames ------------------------------------------------

def test_screenshot_matches_render(env):
    """`raylab --frames N --screenshot a.png` equals raylab-render with the same settings."""
    cases = [
        ["--width", "320", "--height", "240", "--spp", "4"],
        ["--width", "200", "--height", "160", "--spp", "1", "--yaw", "12", "--pitch", "-5",
         "--light-pos", "0.3,0.6,-0.5", "--light-power", "20,14,10", "--display", "srgb",
         "--exposure", "0.5", "--shadow-eps", "0"],
        ["--width", "160", "--height", "120", "--spp", "6", "--integrator", "path",
         "--light-radius", "0.1", "--max-bounces", "3"],
    ]
    for n, flags in enumerate(cases):
        shot, again, from_json = f"a{n}.png", f"b{n}.png", f"c{n}.png"
        env.run_ok(env.raylab, flags + ["--no-panel", "--frames", "5", "--screenshot", shot])
        env.run_ok(env.render, flags + ["-o", again])
        a, b = read_png(env.path(shot)), read_png(env.path(again))
        same_pixels(a, b, f"viewer screenshot vs raylab-render {' '.join(flags)}")
        check(distinct_colours(a) > 5, f"{shot} is nearly blank")
        settings = json.load(open(env.path(f"a{n}.json")))
        spp = int(flags[flags.index("--spp") + 1])
        check(settings["image"]["samples"] == spp, f"{shot}: JSON samples "
              f"{settings['image']['samples']}, expected {spp}")
        check(settings["image"]["width"] == a.width and settings["image"]["height"] == a.height,
              f"{shot}: JSON size differs from the image")
        check(json.loads(a.texts.get("raylab-settings", "null")) == settings,
              f"{shot}: the PNG's raylab-settings chunk differs from a{n}.json")
        env.run_ok(env.render, ["--settings", f"a{n}.json", "-o", from_json])
        same_pixels(a, read_png(env.path(from_json)), f"raylab-render --settings a{n}.json")


def test_readback_matches_cpu(env):
    """What the window shows (glReadPixels) is the CPU image: nothing lost, nothing flipped."""
    for scale in ["1", "0.5", "0.37"]:
        shot, back = f"s{scale}.png", f"r{scale}.png"
        env.run_ok(env.raylab, ["--width", "320", "--height", "240", "--spp", "2", "--no-panel",
                                "--resolution-scale", scale, "--frames", "3",
                                "--screenshot", shot, "--readback", back])
        image, window = read_png(env.path(shot)), read_png(env.path(back))
        check((window.width, window.height) == (320, 240),
              f"readback is {window.width}x{window.height}, expected the 320x240 window")
        check(distinct_colours(image) > 5, f"{shot} is nearly blank")
        if scale == "1":
            same_pixels(window, image, "GL readback vs CPU image")
            continue
        check(image.width == round(320 * float(scale)), f"{shot}: width {image.width}")
        # Nearest texel with an exact mapping: pixel x shows texel floor((x + .5) * W / w).
        for y in range(window.height):
            ty = ((2 * y + 1) * image.height) // (2 * window.height)
            for x in range(window.width):
                tx = ((2 * x + 1) * image.width) // (2 * window.width)
                if window.pixel(x, y) != image.pixel(tx, ty):
                    raise Failure(f"scale {scale}: window pixel ({x}, {y}) = "
                                  f"{window.pixel(x, y)}, texel ({tx}, {ty}) = "
                                  f"{image.pixel(tx, ty)}")


def test_frames_quit(env):
    """--frames N without a screenshot quits by itself, leaving no file."""
    start = time.monotonic()
    env.run_ok(env.raylab, ["--width", "200", "--height", "150", "--frames", "3"], timeout=60)
    check(time.monotonic() - start < 30, "--frames 3 took more than 30 s")
    check(os.listdir(env.workdir) == [], f"files left behind: {os.listdir(env.workdir)}")


# --- interactive tests with xdotool ---------------------------------------------------------

def test_keys_and_buttons(env):
    """Up, W, Q, Left do what the keys say (checked in the saved settings); F12 and the panel's
    button write screenshots, numbered, never overwriting; Escape quits."""
    viewer = Viewer(env, ["--width", "400", "--height", "300", "--spp", "1"])
    try:
        _, s0 = viewer.key_shot()
        check(vec(s0, "camera") == [0.0, 0.0, -3.0] and s0["camera"]["yaw"] == 0.0,
              f"unexpected start camera {s0['camera']}")
        _, s1 = viewer.key_shot("Up")
        c0, c1 = vec(s0, "camera"), vec(s1, "camera")
        check(close(c1[2] - c0[2], STEP) and close(c1[0], c0[0]) and close(c1[1], c0[1]),
              f"Up moved the camera from {c0} to {c1}, expected +{STEP} along z")
        _, s2 = viewer.key_shot("w")
        l1, l2 = vec(s1, "light"), vec(s2, "light")
        check(close(l2[2] - l1[2], STEP) and close(l2[0], l1[0]) and close(l2[1], l1[1]),
              f"W moved the light from {l1} to {l2}, expected +{STEP} along z")
        _, s3 = viewer.key_shot("q")
        l3 = vec(s3, "light")
        check(close(l3[1] - l2[1], -STEP) and close(l3[0], l2[0]) and close(l3[2], l2[2]),
              f"Q moved the light from {l2} to {l3}, expected -{STEP} along y")
        _, s4 = viewer.key_shot("Left")
        check(close(s4["camera"]["yaw"], TURN_DEGREES) and vec(s4, "camera") == vec(s3, "camera"),
              f"Left gave camera {s4['camera']}, expected yaw {TURN_DEGREES} and no move")
        check(s4["light"] == s3["light"], "Left moved the light")
        png, s5 = viewer.shot_after("mousemove", "--window", viewer.window,
                                    str(PANEL_BUTTON[0]), str(PANEL_BUTTON[1]), "click", "1")
        check(s5 == s4, "clicking the screenshot button changed the settings")
        check((png.width, png.height) == (400, 300), "the button's screenshot is not 400x300")
        names = [os.path.basename(p) for p in viewer.screenshots()]
        check(names == [f"raylab-{n:04d}.png" for n in range(1, 7)],
              f"screenshot names {names}")
        viewer.quit()
    finally:
        viewer.kill()
    leftovers = [f for f in os.listdir(viewer.shots) if not f.startswith("raylab-")]
    check(leftovers == [], f"files left beside the screenshots: {leftovers}")


def test_held_key(env):
    """Holding Up moves the camera smoothly: one step at the press, then HELD_STEPS_PER_SECOND
    from HOLD_DELAY after it until the release, whatever X's key repeat does (it starts after
    660 ms, 25 a second; the viewer ignores it), and nothing after the release."""
    viewer = Viewer(env, ["--width", "400", "--height", "300", "--spp", "1"])
    try:
        _, s0 = viewer.key_shot()
        before_press = time.monotonic()
        viewer.xdotool("keydown", "Up")
        after_press = time.monotonic()
        time.sleep(1.0)
        before_release = time.monotonic()
        viewer.xdotool("keyup", "Up")
        after_release = time.monotonic()
        time.sleep(0.3)
        _, s1 = viewer.key_shot()
        c0, c1 = vec(s0, "camera"), vec(s1, "camera")
        check(close(c1[0], c0[0]) and close(c1[1], c0[1]) and s1["camera"] == {
            **s0["camera"], "position": c1}, f"holding Up moved the camera {c0} -> {c1} off +z")
        steps = (c1[2] - c0[2]) / STEP
        # The hold as X saw it lies between these two; the viewer's frames add a little either way.
        shortest = before_release - after_press
        longest = after_release - before_press
        least = 1 + HELD_STEPS_PER_SECOND * (shortest - HOLD_DELAY)
        most = 1 + HELD_STEPS_PER_SECOND * (longest - HOLD_DELAY)
        print(f"held Up for {shortest:.3f}..{longest:.3f} s: {steps:.2f} steps, "
              f"expected {least:.2f}..{most:.2f}")
        # Slack for a loaded machine: a quarter of a second either way (a stall counts at most
        # 0.1 s). A tap would give 1 step; X's repeats alone about 9; repeats on top of the
        # smooth motion about 9 more than expected.
        slack = HELD_STEPS_PER_SECOND * 0.25
        check(least - slack <= steps <= most + slack,
              f"holding Up for {shortest:.2f}..{longest:.2f} s moved {steps:.2f} steps, expected "
              f"{least:.1f}..{most:.1f} (1 step, then {HELD_STEPS_PER_SECOND:g} a second from "
              f"{HOLD_DELAY} s after the press)")
        time.sleep(0.5)
        _, s2 = viewer.key_shot()
        check(s2["camera"] == s1["camera"],
              f"the camera kept moving after the release: {s1['camera']} -> {s2['camera']}")
        viewer.quit()
    finally:
        viewer.kill()


def test_mouse(env):
    """A drag outside the panel turns the camera (right: yaw up, the view turns left; down: pitch
    up); the wheel moves it forward; a drag that starts on the panel does not turn it."""
    viewer = Viewer(env, ["--width", "800", "--height", "600", "--spp", "1"])
    w = viewer.window
    try:
        _, s0 = viewer.key_shot()
        viewer.xdotool("mousemove", "--window", w, "500", "300", "mousedown", "1")
        time.sleep(0.3)
        viewer.xdotool("mousemove", "--window", w, "560", "330")
        time.sleep(0.3)
        viewer.xdotool("mouseup", "1")
        time.sleep(0.2)
        _, s1 = viewer.key_shot()
        degrees_per_pixel = s0["camera"]["fov"] / 600
        check(close(s1["camera"]["yaw"], 60 * degrees_per_pixel, 0.05) and
              close(s1["camera"]["pitch"], 30 * degrees_per_pixel, 0.05),
              f"dragging by (60, 30) px gave camera {s1['camera']}")
        check(vec(s1, "camera") == vec(s0, "camera"), "the drag moved the camera")
        _, s2 = viewer.shot_after("mousemove", "--window", w, "500", "300", "click", "4",
                                  "sleep", "0.3", "key", "F12")
        c1, c2 = vec(s1, "camera"), vec(s2, "camera")
        moved = math.dist(c1, c2)
        check(close(moved, STEP) and c2[2] > c1[2], f"the wheel moved the camera {c1} -> {c2}")
        viewer.xdotool("mousemove", "--window", w, "100", "200", "mousedown", "1")
        time.sleep(0.3)
        viewer.xdotool("mousemove", "--window", w, "100", "260")
        time.sleep(0.3)
        viewer.xdotool("mouseup", "1")
        time.sleep(0.2)
        _, s3 = viewer.key_shot()
        check(s3["camera"]["yaw"] == s2["camera"]["yaw"] and
              s3["camera"]["pitch"] == s2["camera"]["pitch"],
              "a drag on the panel turned the camera")
        viewer.quit()
    finally:
        viewer.kill()


def test_resize(env):
    """Resizing the window to 1 x 1 and back leaves it rendering at the new sizes: the picture
    is the window less the panel's column (at 1 x 1 there is no room for the panel and the
    picture is the window's one pixel)."""
    viewer = Viewer(env, ["--width", "400", "--height", "300", "--spp", "2"])
    try:
        first, _ = viewer.key_shot()
        check((first.width, first.height) == (400, 300), "first screenshot is not 400x300")
        viewer.xdotool("windowsize", viewer.window, "1", "1")
        tiny, s = viewer.shot_when(lambda png, s: (png.width, png.height) == (1, 1),
                                   "no 1 x 1 screenshot after resizing to 1 x 1")
        check(s["image"]["width"] == 1, f"at 1 x 1 the JSON says {s['image']}")
        viewer.xdotool("windowsize", viewer.window, str(PANEL_COLUMN + 360), "280")
        back, s = viewer.shot_when(lambda png, s: (png.width, png.height) == (360, 280),
                                   "no 360 x 280 screenshot after resizing back")
        check(s["image"]["height"] == 280, f"after resizing back the JSON says {s['image']}")
        check(distinct_colours(back) > 5, "after resizing back the picture is blank")
        env.run_ok(env.render, ["--settings", viewer.screenshots()[-1][:-4] + ".json",
                                "-o", "again.png"])
        same_pixels(back, read_png(env.path("again.png")), "resized screenshot vs raylab-render")
        viewer.quit()
    finally:
        viewer.kill()


def test_close_in_flight(env):
    """Escape while a long pass is in flight cancels it and quits promptly, leaving no file."""
    viewer = Viewer(env, ["--width", "1200", "--height", "780", "--spp", "4096"])
    try:
        time.sleep(1.5)
        start = time.monotonic()
        viewer.quit()
        check(time.monotonic() - start < 10, "quitting took more than 10 s")
    finally:
        viewer.kill()
    check(os.listdir(viewer.shots) == [], f"files left: {os.listdir(viewer.shots)}")
    check(sorted(os.listdir(env.workdir)) == ["shots"], f"files left: {os.listdir(env.workdir)}")


TESTS = {
    "bad_input": (test_bad_input, False),
    "screenshot_matches_render": (test_screenshot_matches_render, True),
    "readback_matches_cpu": (test_readback_matches_cpu, True),
    "frames_quit": (test_frames_quit, True),
    "keys_and_buttons": (test_keys_and_buttons, True),
    "held_key": (test_held_key, True),
    "mouse": (test_mouse, True),
    "resize": (test_resize, True),
    "close_in_flight": (test_close_in_flight, True),
    "minimise": (test_minimise, True),
    "scene_path": (test_scene_path, True),
    "browse": (test_browse, True),
    "stats": (test_stats, True),
    "idle": (test_idle, True),
    "panel": (test_panel, True),
    "panel_scale": (test_panel_scale, True),
    "panel_edge": (test_panel_edge, True),
    "mean_n": (test_mean_n, True),
    "split": (test_split, True),
    "inspect": (test_inspect, True),
    "snapshot": (test_snapshot, True),
    "undo": (test_undo, True),
    "orbit": (test_orbit, True),
    "bookmarks": (test_bookmarks, True),
    "drop": (test_drop, True),
    "ray_overlay": (test_ray_overlay, True),
    "hover_readout": (test_hover_readout, True),
    "difference": (test_difference, True),
    "observer": (test_observer, True),
    "import_failures": (test_import_failures, True),
    "import_cancel": (test_import_cancel, True),
    "import_quit": (test_import_quit, True),
    "record": (test_record, True),
}


def run_test(function, name, raylab, render):
    os.environ["LIBGL_ALWAYS_SOFTWARE"] = "1"
    with tempfile.TemporaryDirectory(prefix=f"raylab-e2e-{name}-") as workdir:
        env = Env(os.path.abspath(raylab), os.path.abspath(render), workdir)
        try:
            function(env)
        except Failure as failure:
            print(f"FAIL {name}: {failure}")
            return 1
    print(f"PASS {name}")
    return 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("test", choices=sorted(TESTS))
    parser.add_argument("--raylab", required=True)
    parser.add_argument("--render", required=True)
    args = parser.parse_args()
    function, needs_window = TESTS[args.test]
    if not needs_window:
        return run_test(function, args.test, args.raylab, args.render)
    if shutil.which("Xvfb") is None:
        print(f"SKIP {args.test}: Xvfb is not installed")
        return SKIP
    try:
        with Display() as display:
            result = run_test(function, args.test, args.raylab, args.render)
            if result != 0 and not display.alive():
                print(f"{args.test}: the X server ended during the test")
            return result
    except DisplayError as error:
        print(f"FAIL {args.test}: {error}")
        return 1


if __name__ == "__main__":
    sys.exit(main())
