"""--stats FILE: the viewer's frame rates and pass times as JSON, checked for form and plausible
counts only (no timing is asserted: machines are noisy)."""

import json
import os

from e2e_support import check


def test_stats(env):
    """A scripted run writes a well-formed --stats file whose counts fit the run; an unwritable
    --stats path fails at once, with one line and no window."""
    env.run_ok(env.raylab, ["--width", "200", "--height", "150", "--spp", "4", "--no-panel",
                            "--frames", "20", "--screenshot", "s.png", "--stats", "stats.json"])
    stats = json.load(open(env.path("stats.json")))
    for key in ["frames_shown", "seconds", "window_fps", "frame_ms", "frames_over_33ms",
                "minimised_seconds", "upload_ms", "passes", "pass_ms", "previews", "preview_ms",
                "cancelled_passes", "samples", "render_width", "render_height", "scene",
                "triangles"]:
        check(key in stats, f"--stats has no {key}: {stats}")
    check(stats["frames_shown"] >= 20, f"frames_shown {stats['frames_shown']} < 20")
    check(stats["seconds"] > 0 and stats["window_fps"] > 0, f"no frame rate: {stats}")
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
