"""Minimising and restoring the viewer's window under a real window manager.

Xvfb has no window manager, so nothing there honours an iconify request. This test runs openbox
(Debian's openbox package; scripts/install-deps.sh installs it) on the test's own Xvfb display,
and only in this test, so the other tests keep undecorated windows at known places."""

import json
import os
import shutil
import subprocess
import tempfile
import time

from e2e_display import end_process
from e2e_support import Failure, Viewer, check, distinct_colours, same_pixels, vec
from pngread import read_png

WINDOW_MANAGER = "openbox"
STEP = 0.1  # core's navigationStep for the lab's box


class WindowManager:
    """openbox on the current display, with its configuration and cache in a folder of its own."""

    def __init__(self):
        program = shutil.which(WINDOW_MANAGER)
        if program is None:
            raise Failure(f"{WINDOW_MANAGER} is not installed: run scripts/install-deps.sh")
        self.home = tempfile.TemporaryDirectory(prefix="raylab-e2e-wm-")
        env = dict(os.environ, XDG_CONFIG_HOME=self.home.name, XDG_CACHE_HOME=self.home.name,
                   XDG_DATA_HOME=self.home.name)
        self.log = tempfile.TemporaryFile(mode="w+")
        # --startup runs its command once openbox manages the screen.
        ready = os.path.join(self.home.name, "ready")
        self.proc = subprocess.Popen([program, "--sm-disable", "--startup", f"touch {ready}"],
                                     env=env, stdout=self.log, stderr=subprocess.STDOUT,
                                     text=True)
        deadline = time.monotonic() + 15
        while not os.path.exists(ready):
            if self.proc.poll() is not None or time.monotonic() > deadline:
                self.stop()
                self.log.seek(0)
                raise Failure(f"{WINDOW_MANAGER} did not start within 15 s: "
                              f"{self.log.read().strip()}")
            time.sleep(0.1)

    def stop(self):
        end_process(self.proc)
        self.home.cleanup()


def visible(window):
    """Whether the window is mapped (an iconified window is not)."""
    found = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", "^raylab"],
                           capture_output=True, text=True, timeout=10)
    return window in found.stdout.split()


def wait_until(condition, seconds, what):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(0.1)
    raise Failure(f"{what} within {seconds} s")


def test_minimise(env):
    """Minimised (xdotool windowminimize, honoured by openbox) while a long render runs, and
    restored: the viewer lives, knew it was minimised (--stats), and its screenshot after restoring
    equals raylab-render with the same settings; a key afterwards still renders a new picture."""
    flags = ["--width", "240", "--height", "180", "--spp", "4096"]
    stats = env.path("stats.json")
    wm = WindowManager()
    try:
        viewer = Viewer(env, flags + ["--stats", stats])
        try:
            time.sleep(1.0)  # a render in flight: 4096 samples take far longer than this
            viewer.check_running()
            viewer.xdotool("windowminimize", viewer.window)
            wait_until(lambda: not visible(viewer.window), 10,
                       f"{WINDOW_MANAGER} did not minimise the window")
            time.sleep(2.0)
            viewer.check_running()
            viewer.xdotool("windowactivate", viewer.window)
            wait_until(lambda: visible(viewer.window), 10,
                       f"{WINDOW_MANAGER} did not restore the window")
            viewer.xdotool("windowfocus", viewer.window)
            time.sleep(0.5)

            png, settings = viewer.key_shot()
            check((png.width, png.height) == (240, 180),
                  f"after restoring, the screenshot is {png.width}x{png.height}, not 240x180")
            check(distinct_colours(png) > 5, "after restoring, the picture is blank")
            samples = settings["image"]["samples"]
            same_flags = flags[:-1] + [str(samples)]
            env.run_ok(env.render, same_flags + ["-o", "same.png"])
            same_pixels(png, read_png(env.path("same.png")),
                        f"screenshot after restoring vs raylab-render {' '.join(same_flags)}")

            moved, after = viewer.key_shot("Up")
            c0, c1 = vec(settings, "camera"), vec(after, "camera")
            check(abs(c1[2] - c0[2] - STEP) < 1e-4, f"Up after restoring moved {c0} to {c1}")
            env.run_ok(env.render, ["--settings", viewer.screenshots()[-1][:-4] + ".json",
                                    "-o", "moved.png"])
            same_pixels(moved, read_png(env.path("moved.png")),
                        "the screenshot after Up vs raylab-render --settings")
            viewer.quit()
        finally:
            viewer.kill()
    finally:
        wm.stop()
    measured = json.load(open(stats))
    check(measured["minimised_seconds"] > 0.0,
          f"the viewer did not notice it was minimised: {measured}")
    check(measured["frames_shown"] > 0 and measured["passes"] > 0, f"implausible stats {measured}")
