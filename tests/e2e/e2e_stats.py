"""--stats FILE: the viewer's frame rates and pass times as JSON, checked for form and plausible
counts only (no timing is asserted: machines are noisy), and what it tells about redrawing: an
idle window draws (almost) nothing."""

import json
import os
import time

from e2e_support import Viewer, check, close

STEP = 0.1  # core's navigationStep for the lab's box


def test_stats(env):
    """A scripted run writes a well-formed --stats file whose counts fit the run; an unwritable
    --stats path fails at once, with one line and no window."""
    env.run_ok(env.raylab, ["--width", "200", "--height", "150", "--spp", "4", "--no-panel",
                            "--frames", "20", "--screenshot", "s.png", "--stats", "stats.json"])
    stats = json.load(open(env.path("stats.json")))
    for key in ["redraw", "frames_shown", "seconds", "window_fps", "pictures_shown",
                "pictures_per_second", "views_shown", "views_per_second", "frame_ms", "frames_over_33ms", "draw_ms",
                "minimised_seconds", "upload_ms", "passes", "pass_ms", "previews", "preview_ms",
                "cancelled_passes", "samples", "render_width", "render_height", "scene",
                "triangles"]:
        check(key in stats, f"--stats has no {key}: {stats}")
    check(stats["redraw"] == "continuous", f"a scripted run redraws {stats['redraw']}")
    check(stats["frames_shown"] >= 20, f"frames_shown {stats['frames_shown']} < 20")
    check(1 <= stats["pictures_shown"] <= stats["frames_shown"],
          f"pictures_shown {stats['pictures_shown']}, frames_shown {stats['frames_shown']}")
    check(stats["seconds"] > 0 and stats["window_fps"] > 0, f"no frame rate: {stats}")
    check(stats["views_shown"] == 1, f"views_shown {stats['views_shown']} for one view: {stats}")
    check(stats["passes"] >= 4 and stats["samples"] == 4, f"passes or samples: {stats}")
    check((stats["render_width"], stats["render_height"]) == (200, 150),
          f"render size {stats['render_width']}x{stats['render_height']}")
    passes = stats["pass_ms"]
    check(0 < passes["min"] <= passes["mean"] <= passes["max"], f"pass_ms {passes}")
    check(stats["upload_ms"]["count"] >= 1, f"no upload counted: {stats['upload_ms']}")
    check(stats["scene"] == "cornell" and stats["triangles"] == 30, f"scene: {stats}")
    check(stats["minimised_seconds"] == 0, f"minimised without a window manager: {stats}")

    result = env.run(env.raylab, ["--frames", "1", "--stats", env.path("no/such/dir/x.json")])
    check(result.returncode == 1, f"unwritable --stats: exit {result.returncode}, expected 1")
    check(len(result.stderr.strip().splitlines()) == 1,
          f"unwritable --stats: expected one line, got {result.stderr!r}")
    check(sorted(os.listdir(env.workdir)) == ["s.json", "s.png", "stats.json"],
          f"files: {os.listdir(env.workdir)}")


# Frames an idle window may draw beyond the pictures it shows: those after the events of the test
# (focus, cursor, the keys) and Dear ImGui's frames after each. Drawing continuously at 60 frames
# per second, the run below would draw more than 300.
EVENT_FRAMES = 60


def test_idle(env):
    """An interactive window draws a frame when something changed (a new picture, an event), not
    60 identical frames a second: after the picture reaches its sample cap, 4 s of idling add
    (almost) no frames; a key after the idle time still wakes it and moves the camera."""
    stats_path = env.path("stats.json")
    viewer = Viewer(env, ["--width", "320", "--height", "240", "--spp", "4",
                          "--stats", stats_path])
    try:
        time.sleep(4.0)  # 4 samples of 320 x 240 take well under a second
        viewer.check_running()
        _, before = viewer.key_shot()
        check(before["image"]["samples"] == 4, f"after 4 s the picture has {before['image']}")
        time.sleep(4.0)
        _, after = viewer.key_shot("Up")
        z0, z1 = before["camera"]["position"][2], after["camera"]["position"][2]
        check(close(z1 - z0, STEP), f"Up after idling moved the camera from z {z0} to {z1}")
        viewer.quit()
    finally:
        viewer.kill()
    stats = json.load(open(stats_path))
    check(stats["redraw"] == "on demand", f"an interactive run redraws {stats['redraw']}")
    check(stats["seconds"] > 7.0, f"the window was shown only {stats['seconds']} s")
    check(stats["pictures_shown"] >= 2, f"pictures_shown {stats['pictures_shown']}: {stats}")
    check(stats["views_shown"] == 2, f"views_shown {stats['views_shown']} for two views: {stats}")
    check(stats["frames_shown"] <= stats["pictures_shown"] + EVENT_FRAMES,
          f"{stats['frames_shown']} frames for {stats['pictures_shown']} pictures in "
          f"{stats['seconds']:.1f} s: the idle window kept redrawing ({stats})")
