"""What the viewer's end-to-end tests share: failures, the temporary folder with the programs,
pixel comparisons, and a running viewer driven with xdotool. Standard library only."""

import glob
import json
import os
import subprocess
import tempfile
import time

from pngread import read_png

# The panel's column at the window's left edge (src/viewer/view_layout.h, kPanelColumnWidth at UI
# scale 1): with the panel shown, the picture's pixel (x, y) is at window point (PANEL_COLUMN + x,
# y), and the window is PANEL_COLUMN wider than --width.
PANEL_COLUMN = 360
PANEL_BUTTON = (100, 17)  # window coordinates inside the panel's "Save screenshot" button
PATH_FIELD = (120, 40)  # window coordinates inside the panel's scene path field


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def close(a, b, tolerance=1e-4):
    return abs(a - b) <= tolerance


class Env:
    def __init__(self, raylab, render, workdir):
        self.raylab = raylab
        self.render = render
        self.workdir = workdir

    def run(self, program, args, timeout=120):
        result = subprocess.run([program] + args, cwd=self.workdir, capture_output=True,
                                text=True, timeout=timeout)
        return result

    def run_ok(self, program, args, timeout=120):
        result = self.run(program, args, timeout)
        check(result.returncode == 0,
              f"{os.path.basename(program)} {' '.join(args)} exited {result.returncode}: "
              f"{result.stderr.strip()}")
        return result

    def path(self, name):
        return os.path.join(self.workdir, name)


def same_pixels(a, b, what):
    check((a.width, a.height) == (b.width, b.height),
          f"{what}: sizes differ, {a.width}x{a.height} vs {b.width}x{b.height}")
    if a.rgba != b.rgba:
        for i in range(0, len(a.rgba), 4):
            if a.rgba[i:i + 4] != b.rgba[i:i + 4]:
                p = i // 4
                raise Failure(f"{what}: pixel ({p % a.width}, {p // a.width}) differs: "
                              f"{tuple(a.rgba[i:i + 4])} vs {tuple(b.rgba[i:i + 4])}")


def distinct_colours(png):
    return len({png.rgba[i:i + 3] for i in range(0, len(png.rgba), 4)})


class Viewer:
    """A running viewer whose screenshots go to workdir/shots."""

    def __init__(self, env, args):
        self.env = env
        self.shots = env.path("shots")
        os.makedirs(self.shots, exist_ok=True)
        self.log = tempfile.TemporaryFile(mode="w+")  # stdout and stderr, outside workdir
        self.proc = subprocess.Popen([env.raylab, "--screenshot-dir", self.shots] + args,
                                     cwd=env.workdir, stdout=self.log, stderr=subprocess.STDOUT,
                                     text=True)
        self.window = self.find_window()
        self.xdotool("windowfocus", self.window)  # keys go to the focused window
        self.xdotool("mousemove", "--window", self.window, "300", "200")
        time.sleep(0.5)

    def output(self):
        self.log.seek(0)
        return self.log.read().strip()

    def check_running(self):
        if self.proc.poll() is not None:
            raise Failure(f"raylab ended ({self.proc.returncode}): {self.output()}")

    def xdotool(self, *args):
        result = subprocess.run(["xdotool"] + list(args), capture_output=True, text=True,
                                timeout=30)
        check(result.returncode == 0, f"xdotool {' '.join(args)}: {result.stderr.strip()}")
        return result.stdout.strip()

    def find_window(self):
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            self.check_running()
            result = subprocess.run(["xdotool", "search", "--onlyvisible", "--name", "^raylab"],
                                    capture_output=True, text=True, timeout=10)
            if result.returncode == 0 and result.stdout.strip():
                return result.stdout.split()[0]
            time.sleep(0.2)
        raise Failure("the viewer's window did not appear within 30 s")

    def screenshots(self):
        return sorted(glob.glob(os.path.join(self.shots, "raylab-*.png")))

    def shot_after(self, *action):
        """Runs the xdotool action; returns (png, settings) of the one new screenshot."""
        before = self.screenshots()
        self.xdotool(*action)
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            self.check_running()
            new = [p for p in self.screenshots() if p not in before]
            if new and os.path.exists(new[0][:-4] + ".json"):
                check(len(new) == 1, f"one action wrote {len(new)} screenshots")
                return read_png(new[0]), json.load(open(new[0][:-4] + ".json"))
            time.sleep(0.1)
        raise Failure(f"no screenshot after xdotool {' '.join(action)}")

    def key_shot(self, *keys):
        return self.shot_after("key", "--delay", "80", *keys, "F12")

    def shot_when(self, wanted, what, seconds=20):
        """F12 until wanted(png, settings) holds (a change the viewer has not drawn yet, on a busy
        machine); returns (png, settings) of that screenshot."""
        deadline = time.monotonic() + seconds
        while True:
            png, settings = self.key_shot()
            if wanted(png, settings):
                return png, settings
            if time.monotonic() > deadline:
                raise Failure(f"{what} within {seconds} s (last screenshot "
                              f"{png.width}x{png.height}, scene {settings.get('scene')})")
            time.sleep(0.3)

    def quit(self):
        self.xdotool("key", "Escape")
        try:
            code = self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise Failure("Escape did not end the viewer within 20 s")
        check(code == 0, f"the viewer exited {code}: {self.output()}")

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()


def vec(settings, part):
    return settings[part]["position"]
