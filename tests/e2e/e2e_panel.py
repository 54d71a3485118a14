"""The panel beside the picture (src/viewer/view_layout.h), drawn from its cached pixels
(src/viewer/panel_cache.h): the window (--readback) is the panel's column at the left and, right
of it, raylab-render's picture of the same scene and size, pixel for pixel: the panel covers
nothing. Hovering the panel's button shows at once; F1 hides the panel and the picture then fills
the whole window; at UI scale 2 (--ui-scale, or the monitor's content scale) the column is twice
as wide and the picture still whole; dragging
the column's edge gives the picture what the panel gives up; a dropped screenshot restores its
picture's size beside the panel."""

import json
import shutil
import subprocess
import time

from e2e_support import PANEL_BUTTON, PANEL_COLUMN, Failure, Viewer, check, same_pixels
from pngread import read_png

WIDTH, HEIGHT = 480, 360
SIZE = ["--width", str(WIDTH), "--height", str(HEIGHT)]
BUTTON_BACKGROUND = (20, 17)  # inside the screenshot button, left of its text (UI scale 1)
BUTTON_HOVERED = (66, 150, 250)  # Dear ImGui's dark style, ButtonHovered (opaque)


def near(a, b, tolerance=3):
    return all(abs(x - y) <= tolerance for x, y in zip(a, b))


class Crop:
    """The part of an image right of column x0, as an image of its own (for same_pixels)."""

    def __init__(self, png, x0, width):
        self.width, self.height = width, png.height
        self.rgba = b"".join(png.rgba[4 * (y * png.width + x0):4 * (y * png.width + x0 + width)]
                             for y in range(png.height))


def render(env, name, flags):
    env.run_ok(env.render, flags + ["-o", name])
    return read_png(env.path(name))


def check_beside(window, picture, column, what):
    """The window is the panel's column of `column` pixels and, right of it, exactly `picture`;
    the column shows the panel (hardly a pixel of it is black)."""
    check((window.width, window.height) == (column + picture.width, picture.height),
          f"{what}: the window is {window.width}x{window.height}, expected the "
          f"{picture.width}x{picture.height} picture beside a {column}-pixel column")
    same_pixels(Crop(window, column, picture.width), picture, f"{what}: the picture's area")
    black = sum(window.pixel(x, y)[:3] == (0, 0, 0) for y in range(window.height)
                for x in range(column - 1))
    check(black < 0.1 * (column - 1) * window.height,
          f"{what}: {black} pixels of the panel's column are black: no panel drawn there")


def test_panel(env):
    """Scripted run with the panel: left of the picture its column, right of it raylab-render's
    picture of the same size, pixel for pixel. Then a real window: the mouse on the screenshot
    button highlights it in the very frames that follow. Last, F1 three times (hide, show,
    hide): the picture then fills the whole window and is raylab-render's at that size."""
    flags = SIZE + ["--spp", "2"]
    expected = render(env, "expected.png", flags)
    env.run_ok(env.raylab, flags + ["--frames", "5", "--screenshot", "s.png", "--readback",
                                    "r.png"])
    window, shot = read_png(env.path("r.png")), read_png(env.path("s.png"))
    same_pixels(shot, expected, "the screenshot vs raylab-render")
    check_beside(window, expected, PANEL_COLUMN, "with the panel")
    idle_button = window.pixel(*BUTTON_BACKGROUND)[:3]
    check(not near(idle_button, BUTTON_HOVERED),
          f"the button looks hovered with no mouse over it: {idle_button}")

    # 240 frames take 4 s: the mouse reaches the button well before the last one, read back.
    viewer = Viewer(env, SIZE + ["--spp", "4", "--frames", "240", "--readback", "hover.png"])
    try:
        viewer.xdotool("mousemove", "--window", viewer.window, str(PANEL_BUTTON[0]),
                       str(PANEL_BUTTON[1]))
        start = time.monotonic()
        code = viewer.proc.wait(timeout=60)
        check(code == 0, f"the viewer exited {code}: {viewer.output()}")
        check(time.monotonic() - start > 0.5, "the run ended too soon after the mouse moved")
    finally:
        viewer.kill()
    hovered = read_png(env.path("hover.png"))
    button = hovered.pixel(*BUTTON_BACKGROUND)[:3]
    check(near(button, BUTTON_HOVERED),
          f"the mouse on the button: pixel {BUTTON_BACKGROUND} = {button}, expected the hovered "
          f"colour {BUTTON_HOVERED}")

    viewer = Viewer(env, SIZE + ["--spp", "4", "--frames", "240", "--screenshot", "f1.png",
                                 "--readback", "f1-window.png"])
    try:
        for _ in range(3):
            viewer.xdotool("key", "F1")
            time.sleep(0.3)
        code = viewer.proc.wait(timeout=60)
        check(code == 0, f"the viewer exited {code}: {viewer.output()}")
    finally:
        viewer.kill()
    image, window = read_png(env.path("f1.png")), read_png(env.path("f1-window.png"))
    check((image.width, image.height) == (PANEL_COLUMN + WIDTH, HEIGHT),
          f"without the panel the picture is {image.width}x{image.height}, not the whole "
          f"{PANEL_COLUMN + WIDTH}x{HEIGHT} window")
    same_pixels(window, image, "after F1 hid the panel, the window vs its screenshot")
    same_pixels(image, render(env, "whole.png", ["--width", str(PANEL_COLUMN + WIDTH),
                                                 "--height", str(HEIGHT), "--spp", "4"]),
                "the picture filling the window vs raylab-render")


def set_content_scale(scale):
    """Gives this test's X server the content scale `scale`, as a desktop does: Xft.dpi =
    96 * scale in the root window's resources, which GLFW reads when it starts."""
    if shutil.which("xprop") is None:
        raise Failure("xprop is not installed: run scripts/install-deps.sh (x11-utils)")
    result = subprocess.run(["xprop", "-root", "-f", "RESOURCE_MANAGER", "8s", "-set",
                             "RESOURCE_MANAGER", f"Xft.dpi:\t{round(96 * scale)}\n"],
                            capture_output=True, text=True, timeout=30)
    check(result.returncode == 0, f"xprop could not set Xft.dpi: {result.stderr.strip()}")


def test_panel_scale(env):
    """--ui-scale 2 (Xvfb's own content scale is 1): the panel's column is twice as wide, its
    widgets twice as large (the screenshot button's background where scale 1 has it, doubled),
    and the picture beside it is still raylab-render's, whole. Then a monitor of content scale 2
    (Xft.dpi 192) without --ui-scale: the panel scales the same, and the window opens at twice
    the size asked for (GLFW's scaling to the monitor), the picture beside the panel whole."""
    flags = SIZE + ["--spp", "2"]
    expected = render(env, "expected.png", flags)
    env.run_ok(env.raylab, flags + ["--frames", "5", "--readback", "one.png"])
    env.run_ok(env.raylab, flags + ["--ui-scale", "2", "--frames", "5", "--readback", "two.png"])
    one, two = read_png(env.path("one.png")), read_png(env.path("two.png"))
    check_beside(one, expected, PANEL_COLUMN, "at UI scale 1")
    check_beside(two, expected, 2 * PANEL_COLUMN, "at UI scale 2")
    x, y = BUTTON_BACKGROUND
    button = one.pixel(x, y)[:3]
    for point in ((2 * x, 2 * y), (2 * x, 2 * y + 14), (2 * PANEL_COLUMN - 60, 2 * y)):
        check(two.pixel(*point)[:3] == button,
              f"at UI scale 2, pixel {point} = {two.pixel(*point)[:3]}: not the screenshot "
              f"button's {button} (the button is not twice as large)")
    check(one.pixel(x, 2 * y + 14)[:3] != button,
          "at UI scale 1 the button reaches as low as at scale 2")

    set_content_scale(2)
    env.run_ok(env.raylab, flags + ["--frames", "5", "--readback", "monitor.png"])
    monitor = read_png(env.path("monitor.png"))
    check_beside(monitor, render(env, "double.png", ["--width", str(2 * WIDTH), "--height",
                                                     str(2 * HEIGHT), "--spp", "2"]),
                 2 * PANEL_COLUMN, "on a monitor of content scale 2")
    check(monitor.pixel(2 * x, 2 * y)[:3] == button,
          "on a monitor of content scale 2 the screenshot button is not twice as large")


def test_panel_edge(env):
    """Dragging the panel's right edge 40 pixels to the right makes the picture 40 pixels
    narrower (the render follows), and a Ctrl+click still inspects the pixel under the cursor
    in the picture's own coordinates; a screenshot dropped on a window with the panel restores
    its picture's size exactly (the window grows by the column)."""
    viewer = Viewer(env, SIZE + ["--spp", "2"])
    try:
        first, _ = viewer.key_shot()
        check((first.width, first.height) == (WIDTH, HEIGHT),
              f"first screenshot {first.width}x{first.height}")
        w = viewer.window
        viewer.xdotool("mousemove", "--window", w, str(PANEL_COLUMN - 1), "200", "mousedown", "1")
        time.sleep(0.3)
        viewer.xdotool("mousemove", "--window", w, str(PANEL_COLUMN + 19), "200")
        time.sleep(0.3)
        viewer.xdotool("mousemove", "--window", w, str(PANEL_COLUMN + 39), "200")
        time.sleep(0.3)
        viewer.xdotool("mouseup", "1")
        narrow, settings = viewer.shot_when(lambda png, s: png.width == WIDTH - 40,
                                            "dragging the panel's edge did not narrow the picture")
        check(narrow.height == HEIGHT and settings["camera"] == json.load(
            open(viewer.screenshots()[0][:-4] + ".json"))["camera"],
              "dragging the panel's edge moved the camera")
        # The picture now starts 40 pixels further right.
        viewer.xdotool("mousemove", "--window", w, str(PANEL_COLUMN + 40 + 200), "150")
        viewer.xdotool("keydown", "ctrl", "click", "1", "keyup", "ctrl")
        time.sleep(0.5)
        viewer.quit()
    finally:
        viewer.kill()
    lines = [line for line in viewer.output().splitlines() if line.startswith("{")]
    check(len(lines) == 1, f"expected one inspection printed, got {lines}")
    check(json.loads(lines[0])["pixel"] == [200, 150],
          f"Ctrl+click at the picture's (200, 150) inspected {json.loads(lines[0])['pixel']}")

    env.run_ok(env.raylab, ["--width", "200", "--height", "150", "--yaw", "10", "--spp", "2",
                            "--no-panel", "--frames", "5", "--screenshot", "a.png"])
    env.run_ok(env.raylab, SIZE + ["--spp", "2", "--drop", env.path("a.json"), "--frames", "30",
                                   "--screenshot", "b.png", "--readback", "b-window.png"])
    original, restored = read_png(env.path("a.png")), read_png(env.path("b.png"))
    same_pixels(restored, original, "the screenshot restored beside the panel")
    check_beside(read_png(env.path("b-window.png")), original, PANEL_COLUMN,
                 "the restored screenshot's window")
